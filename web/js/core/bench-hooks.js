// Benchmark and leak-test hooks (docs/architecture.md, "Teaching path and fast kernels"):
// timing loops inside the module and the every-ring walk of BENCH.md's mesh_ring. They are
// not part of the student API: wingspline.js does not export this file and nothing on the
// `api` object reaches it (tests/wasm/module/bench-hooks.test.mjs checks both). Imported only by
// tests/bench and the tests that need it:
//   import { benchHooks } from '.../js/core/bench-hooks.js';
//   const hooks = benchHooks(await loadWingspline());
import { unwrap, integerIn } from './errors.js';
import { benchAccess } from './mesh-api.js';

export function benchHooks(api) {
  const raw = benchAccess.rawOf(api);
  return Object.freeze({
    // Copies the face set in once, then times the winged-edge build inside the module R
    // times, as the native benchmark does: {seconds: Float64Array, checksum}.
    timeBuildInCore(input, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const { positions, faceOffsets, faceVertices } = benchAccess.indexedInput(input);
      const { seconds, checksum } = unwrap(raw.benchBuildInCore(positions, faceOffsets, faceVertices, repetitions));
      return { seconds, checksum };
    },
    // Times newell_normals on a built mesh inside the module (no copy out), the way the
    // native benchmark does: {seconds: Float64Array (one per repetition), checksum}.
    timeNormalsInCore(mesh, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const { seconds, checksum } = unwrap(raw.benchNormalsInCore(benchAccess.handleOf(mesh), repetitions));
      return { seconds, checksum };
    },
    // Walks every vertex ring of a built mesh in C++ (BENCH.md mesh_ring): {visited, checksum}
    // = the edges met (2E without isolated vertices) and the sum of the neighbours met.
    ringWalk(mesh) {
      const { visited, checksum } = unwrap(raw.benchRingWalk(benchAccess.handleOf(mesh)));
      return { visited, checksum };
    },
    // BENCH.md mesh_edit_flip / mesh_edit_split timed inside the module on fresh copies of a
    // built mesh (the mesh itself is not changed): {seconds, checksum, n} (n = edges tried).
    timeEditInCore(mesh, task, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const { seconds, checksum, n } = unwrap(raw.benchEditInCore(benchAccess.handleOf(mesh), String(task), repetitions));
      return { seconds, checksum, n };
    },
    // BENCH.md mesh_subdivide_loop / mesh_subdivide_cc timed inside the module (the mesh is
    // not changed): {seconds, checksum, n (input faces), resultBytes, heapGrowth (bytes while
    // one result is held)}.
    timeSubdivideInCore(mesh, task, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const r = unwrap(raw.benchSubdivideInCore(benchAccess.handleOf(mesh), String(task), repetitions));
      return { seconds: r.seconds, checksum: r.checksum, n: r.n, resultBytes: r.resultBytes, heapGrowth: r.heapGrowth };
    },
  });
}
