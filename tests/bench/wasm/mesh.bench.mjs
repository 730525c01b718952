// docs/benchmarks.md mesh tasks in wasm under Node, through the public API (one call per mesh); the
// in-module timers and the ring walk through the bench hooks (not part of the student API).
import { loadBenchCore } from './bench-core.mjs';
import { wants, timeRuns, report } from './harness.mjs';

// The API over the bench module: the shipped module's bindings and flags, plus its hooks.
const { api, hooks } = await loadBenchCore();
// Repetitions: 7, or 31 for the 10k-face inputs (well under a millisecond each, so more
// repetitions keep the minimum out of the noise); the same rule as the native benchmark.
const repetitionsFor = (faces) => (faces <= 10000 ? 31 : 7);
const inputs = [
  ['sphere_10000', 'sphere', { slices: 100, stacks: 51 }], ['grid_10000', 'grid', { nx: 100, ny: 50 }],
  ['sphere_100000', 'sphere', { slices: 250, stacks: 201 }], ['grid_100000', 'grid', { nx: 250, ny: 200 }],
  ['sphere_1000000', 'sphere', { slices: 1000, stacks: 501 }], ['grid_1000000', 'grid', { nx: 1000, ny: 500 }],
];

if (['mesh_memory', 'mesh_build', 'mesh_ring', 'mesh_normals'].some(wants)) {
  for (const [name, kind, options] of inputs) {
    const input = api.generateMesh(kind, { ...options, layout: 'csr' });
    const F = input.faceOffsets.length - 1;
    const R = repetitionsFor(F);
    if (wants('mesh_memory')) {
      const before = api.memoryUsage();
      const mesh = api.buildMesh(input);
      const after = api.memoryUsage();
      report({ task: 'mesh_memory', input: name, n: F, seconds: [after.heapInUse - before.heapInUse], unit: 'B',
        checksum: mesh.counts().edges, structure_bytes_per_face: mesh.bytes() / F,
        linear_memory_growth_per_face: (after.linearBytes - before.linearBytes) / F });
      mesh.dispose();
    }
    if (wants('mesh_build')) {
      let checksum = 0;
      const seconds = timeRuns(R, (r) => {
        const mesh = api.buildMesh(input);
        if (r >= 0) checksum += mesh.bytes(); // timed repetitions only, not the warm-up
        mesh.dispose();
      });
      report({ task: 'mesh_build', input: name, n: F, seconds, checksum });
      // The same build timed inside the module, without the boundary (as native times it).
      const core = hooks.timeBuildInCore(input, R);
      report({ task: 'mesh_build_core', input: name, n: F, seconds: Array.from(core.seconds), checksum: core.checksum });
    }
    const mesh = api.buildMesh(input);
    try {
      if (wants('mesh_ring')) {
        let walk;
        const seconds = timeRuns(R, () => { walk = hooks.ringWalk(mesh); });
        report({ task: 'mesh_ring', input: name, n: walk.visited, seconds, checksum: walk.checksum });
      }
      if (wants('mesh_normals')) {
        let checksum = 0;
        // Into one reused array, as the native benchmark reuses its vector; still one copy out.
        const into = new Float64Array(3 * F);
        const seconds = timeRuns(R, (r) => { const n = mesh.normals({ into }); if (r >= 0) checksum += n[0] + n[n.length - 1]; });
        report({ task: 'mesh_normals', input: name, n: F, seconds, checksum });
      const core = hooks.timeNormalsInCore(mesh, R);
      report({ task: 'mesh_normals_core', input: name, n: F, seconds: Array.from(core.seconds), checksum: core.checksum });
      }
    } finally {
      mesh.dispose();
    }
  }
}

// The editing tasks, inside the module (each repetition on a fresh copy of the
// built mesh, the copy untimed, as natively); the 10k and 100k inputs.
for (const task of ['mesh_edit_flip', 'mesh_edit_split'].filter(wants)) {
  for (const [name, kind, options] of inputs.filter(([n]) => !n.endsWith('_1000000'))) {
    const mesh = api.buildMesh(api.generateMesh(kind, { ...options, layout: 'csr' }));
    try {
      const r = hooks.timeEditInCore(mesh, task, repetitionsFor(mesh.counts().faces));
      report({ task, input: name, n: r.n, seconds: Array.from(r.seconds), checksum: r.checksum });
    } finally {
      mesh.dispose();
    }
  }
}

// One subdivision step inside the module on the 10k and 100k inputs; memory: the
// result's own bytes and the heap growth while one result is held, per input face.
for (const task of ['mesh_subdivide_loop', 'mesh_subdivide_cc'].filter(wants)) {
  for (const [name, kind, options] of inputs.filter(([n]) => !n.endsWith('_1000000'))) {
    const mesh = api.buildMesh(api.generateMesh(kind, { ...options, layout: 'csr' }));
    try {
      const R = repetitionsFor(mesh.counts().faces);
      hooks.timeSubdivideInCore(mesh, task, 3); // warm-up (V8's tiers), untimed
      const r = hooks.timeSubdivideInCore(mesh, task, R);
      report({ task, input: name, n: r.n, seconds: Array.from(r.seconds), checksum: r.checksum,
        result_bytes_per_input_face: r.resultBytes / r.n, heap_growth_per_input_face: r.heapGrowth / r.n });
    } finally {
      mesh.dispose();
    }
  }
}
