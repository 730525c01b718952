// The tasks of docs/benchmarks.md that `npm run bench` must produce, and the reference
// figures of other libraries measured there (for orientation: compare within one run).
// scripts/bench.mjs checks every (task, build) below appears in the results and lists what
// is missing in its report instead of silently printing a shorter table.

export const expectedTasks = [
  ...['mesh_build', 'mesh_ring', 'mesh_normals', 'mesh_memory', 'mesh_edit_flip', 'mesh_edit_split',
    'mesh_subdivide_loop', 'mesh_subdivide_cc'].flatMap((task) =>
    ['native', 'wasm'].map((build) => ({ task, build }))),
  ...['curve_bezier3_eval', 'curve_bspline_eval', 'curve_bspline_eval_d1', 'curve_nurbs_eval', 'curve_nurbs_eval_d1']
    .flatMap((task) => ['native', 'wasm'].map((build) => ({ task, build }))),
  ...['ui_load', 'ui_drag'].map((task) => ({ task, build: 'browser' })),
  { task: 'ui_walk_step', build: 'browser' }, // tests/bench/browser/walk.bench.mjs
  { task: 'ui_edit', build: 'browser' }, // tests/bench/browser/edit.bench.mjs
  { task: 'ui_hover', build: 'browser' }, // tests/bench/browser/hover.bench.mjs
  { task: 'ui_pick', build: 'browser' }, // tests/bench/browser/hover.bench.mjs
  { task: 'ui_tab_switch', build: 'browser' }, // tests/bench/browser/tabs.bench.mjs
  { task: 'ui_import', build: 'browser' }, // tests/bench/browser/import.bench.mjs
  { task: 'ui_rotate', build: 'browser' }, // tests/bench/browser/rotate.bench.mjs
];

// docs/benchmarks.md "Reference figures" (min ns per unit; mesh_memory in bytes per face), per build:
// [figure, library]. Mesh figures are native, for the 100,000-face inputs; the wasm mesh
// goal is a ratio to our own native figure (the "wasm / native" column), not to OpenMesh.
export const references = {
  mesh_build: { input: /_100000$/, native: [242, 'OpenMesh 9'] },
  mesh_ring: { input: /_100000$/, native: [3.0, 'OpenMesh 9'] },
  mesh_normals: { input: /_100000$/, native: [94, 'OpenMesh 9'] },
  mesh_memory: { input: /_100000$/, native: [61, 'OpenMesh 9, B/face'] },
  mesh_edit_flip: { input: /_100000$/, native: [183, 'OpenMesh 9 TriMesh is_flip_ok + flip'] },
  mesh_edit_split: { input: /_100000$/, native: [405, 'OpenMesh 9 TriMesh split'] },
  mesh_subdivide_loop: { input: /^sphere_100000$/, native: [829, 'OpenMesh 9 LoopT, one step'] },
  mesh_subdivide_cc: { input: /^sphere_100000$/, native: [1046, 'OpenMesh 9 CatmullClarkT (PolyMesh), one step'] },
  curve_bezier3_eval: { wasm: [31, 'bezier-js 6.1'], native: [57, 'SISL 4.6'] },
  curve_bspline_eval: { wasm: [174, 'verb-nurbs 3.0'], native: [54, 'SISL 4.6'] },
  curve_bspline_eval_d1: { native: [98, 'SISL 4.6'] },
  curve_nurbs_eval: { wasm: [200, 'verb-nurbs 3.0'], native: [94, 'SISL 4.6'] },
  curve_nurbs_eval_d1: { wasm: [829, 'verb-nurbs 3.0'], native: [129, 'SISL 4.6'] },
};

// The reference figure for a result row, or null.
export function referenceFor(row) {
  const ref = references[row.task];
  if (!ref || !ref[row.build]) return null;
  if (ref.input && !ref.input.test(String(row.input ?? ''))) return null;
  const [value, label] = ref[row.build];
  return { value, label };
}

// For a wasm row, the native row of the same task and input (the issues' "within 1.6x").
export function nativeTwin(row, rows) {
  if (row.build !== 'wasm') return null;
  const task = row.task.replace(/_core$/, '');
  return rows.find((r) => r.build === 'native' && r.task === task && r.input === row.input) ?? null;
}

export function missingTasks(rows) {
  return expectedTasks.filter(({ task, build }) => !rows.some((r) => r.task === task && r.build === build));
}
