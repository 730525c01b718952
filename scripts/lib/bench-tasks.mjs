// The tasks of ../shared/BENCH.md that `npm run bench` must produce, and the reference
// figures of other libraries measured there (for orientation: compare within one run).
// scripts/bench.mjs checks every (task, build) below appears in the results and lists what
// is missing in its report instead of silently printing a shorter table.

export const expectedTasks = [
  ...['mesh_build', 'mesh_ring', 'mesh_normals', 'mesh_memory'].flatMap((task) =>
    ['native', 'wasm'].map((build) => ({ task, build }))),
  ...['curve_bezier3_eval', 'curve_bspline_eval', 'curve_bspline_eval_d1', 'curve_nurbs_eval', 'curve_nurbs_eval_d1']
    .flatMap((task) => ['native', 'wasm'].map((build) => ({ task, build }))),
  ...['ui_load', 'ui_drag', 'ui_traversal_step'].map((task) => ({ task, build: 'browser' })),
];

// BENCH.md "Reference figures" (min ns per unit; mesh_memory in bytes per face). Mesh
// figures are for the 100,000-face inputs. Curve figures: [Node library, native library].
export const references = {
  mesh_build: { input: /_100000$/, native: 242, label: 'OpenMesh 9' },
  mesh_ring: { input: /_100000$/, native: 3.0, label: 'OpenMesh 9' },
  mesh_normals: { input: /_100000$/, native: 94, label: 'OpenMesh 9' },
  mesh_memory: { input: /_100000$/, native: 61, label: 'OpenMesh 9 (B/face)' },
  curve_bezier3_eval: { wasm: 31, native: 57, label: 'bezier-js 6.1 / SISL 4.6' },
  curve_bspline_eval: { wasm: 174, native: 54, label: 'verb-nurbs 3.0 / SISL 4.6' },
  curve_bspline_eval_d1: { native: 98, label: 'SISL 4.6' },
  curve_nurbs_eval: { wasm: 200, native: 94, label: 'verb-nurbs 3.0 / SISL 4.6' },
  curve_nurbs_eval_d1: { wasm: 829, native: 129, label: 'verb-nurbs 3.0 / SISL 4.6' },
};

// The reference figure for a result row, or null. Wasm rows of mesh tasks compare with the
// native reference too (the goal: wasm within 1.6x of native).
export function referenceFor(row) {
  const ref = references[row.task];
  if (!ref) return null;
  if (ref.input && !ref.input.test(String(row.input ?? ''))) return null;
  const value = ref[row.build] ?? (row.task.startsWith('mesh_') ? ref.native : null);
  return value == null ? null : { value, label: ref.label };
}

export function missingTasks(rows) {
  return expectedTasks.filter(({ task, build }) => !rows.some((r) => r.task === task && r.build === build));
}
