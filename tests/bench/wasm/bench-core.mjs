// The bench module and its hooks: build/wasm/wingspline-core-bench.{js,wasm} is every binding
// of the shipped modules, compiled once with the same flags, plus the benchmark's entry points
// (core/bench/): timing loops inside the module, the every-ring walk of mesh_ring and the
// edit tasks. No shipped module (dist/wasm) contains them and nothing in the
// package or the student API reaches them (tests/wasm/module/bench-hooks.test.mjs). Built
// by `npm run bench` and by the wasm test layer (scripts/build.mjs, buildWasm({bench: true})).
//   import { loadBenchCore } from '../../bench/wasm/bench-core.mjs';
//   const { api, hooks } = await loadBenchCore();
// `api` is the full API over the bench module, handed as every part (meshes for the hooks are
// built with it).
import fs from 'node:fs/promises';
import { unwrap, integerIn } from '../../../web/js/core/errors.js';
import { meshInternals } from '../../../web/js/core/mesh-api.js';
import { createApi } from '../../../web/js/core/api.js';
import { createMeshesPart } from '../../../web/js/core/mesh-part.js';
import { createCurvesPart } from '../../../web/js/core/curves-part.js';
import { createExercisesPart } from '../../../web/js/core/exercises-part.js';

const MODULE = new URL('../../../build/wasm/wingspline-core-bench.js', import.meta.url);
const WASM = new URL('../../../build/wasm/wingspline-core-bench.wasm', import.meta.url);

let loading = null;
export function loadBenchCore() {
  loading ??= (async () => {
    const { default: create } = await import(MODULE.href);
    const raw = await create({ wasmBinary: await fs.readFile(WASM) });
    const api = createApi({ meshes: raw, curves: raw, exercises: raw }, { meshes: createMeshesPart, curves: createCurvesPart, exercises: createExercisesPart });
    return { api, hooks: benchHooks(raw) };
  })();
  return loading;
}

function benchHooks(raw) {
  return Object.freeze({
    // Copies the face set in once, then times the winged-edge build inside the module R
    // times, as the native benchmark does: {seconds: Float64Array, checksum}.
    timeBuildInCore(input, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const { positions, faceOffsets, faceVertices } = meshInternals.indexedInput(input);
      const { seconds, checksum } = unwrap(raw.benchBuildInCore(positions, faceOffsets, faceVertices, repetitions));
      return { seconds, checksum };
    },
    // Times newell_normals on a built mesh inside the module (no copy out), the way the
    // native benchmark does: {seconds: Float64Array (one per repetition), checksum}.
    timeNormalsInCore(mesh, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const { seconds, checksum } = unwrap(raw.benchNormalsInCore(meshInternals.handleOf(mesh), repetitions));
      return { seconds, checksum };
    },
    // Walks every vertex ring of a built mesh in C++ (docs/benchmarks.md mesh_ring): {visited, checksum}
    // = the edges met (2E without isolated vertices) and the sum of the neighbours met.
    ringWalk(mesh) {
      const { visited, checksum } = unwrap(raw.benchRingWalk(meshInternals.handleOf(mesh)));
      return { visited, checksum };
    },
    // docs/benchmarks.md mesh_edit_flip / mesh_edit_split timed inside the module on fresh copies of a
    // built mesh (the mesh itself is not changed): {seconds, checksum, n} (n = edges tried).
    timeEditInCore(mesh, task, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const { seconds, checksum, n } = unwrap(raw.benchEditInCore(meshInternals.handleOf(mesh), String(task), repetitions));
      return { seconds, checksum, n };
    },
    // docs/benchmarks.md mesh_subdivide_loop / mesh_subdivide_cc timed inside the module (the mesh is
    // not changed): {seconds, checksum, n (input faces), resultBytes, heapGrowth (bytes while
    // one result is held)}.
    timeSubdivideInCore(mesh, task, repetitions) {
      integerIn(repetitions, 'repetitions', 1, 1000);
      const r = unwrap(raw.benchSubdivideInCore(meshInternals.handleOf(mesh), String(task), repetitions));
      return { seconds: r.seconds, checksum: r.checksum, n: r.n, resultBytes: r.resultBytes, heapGrowth: r.heapGrowth };
    },
  });
}
