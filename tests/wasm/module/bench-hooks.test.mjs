// The benchmark's entry points live in a module of their own (build/wasm/wingspline-core-bench,
// core/bench/ + the bindings; its hooks in tests/bench/wasm/bench-core.mjs), outside the
// shipped module and the student API: the shipped wasm holds none of their names, and
// nothing reachable from the package's exports, the api object or a built mesh names them.
// The hooks themselves still work, checked against independent recomputation.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as wingspline from 'wingspline';
import { loadWingspline } from 'wingspline';
import fs from 'node:fs';
import { loadBenchCore } from '../../bench/wasm/bench-core.mjs';

const api = await loadWingspline();
const HOOK_NAMES = ['benchBuildInCore', 'benchNormalsInCore', 'benchRingWalk', 'meshRingWalk', 'ringWalk',
  'timeBuildInCore', 'timeNormalsInCore', 'benchHooks', 'benchAccess', 'meshInternals', 'benchEditInCore', 'timeEditInCore',
  'benchSubdivideInCore', 'timeSubdivideInCore'];
const bench = await loadBenchCore();

// Every property name reachable from `root` through own properties and prototypes
// (functions are not called; a mesh is inspected as an object).
function reachableNames(root) {
  const names = new Set();
  const seen = new Set();
  const queue = [root];
  while (queue.length) {
    const x = queue.pop();
    if (x === null || (typeof x !== 'object' && typeof x !== 'function') || seen.has(x)) continue;
    if (x === Object.prototype || x === Function.prototype) continue;
    seen.add(x);
    for (const key of Reflect.ownKeys(x)) {
      if (typeof key === 'string') names.add(key);
      const d = Object.getOwnPropertyDescriptor(x, key);
      if (d && 'value' in d) queue.push(d.value);
    }
    queue.push(Object.getPrototypeOf(x));
  }
  return names;
}

test('the student API exposes no benchmark or leak-test hook', () => {
  const mesh = api.buildMesh(api.generateMesh('cube'));
  try {
    for (const [what, root] of [['module exports', wingspline], ['api', api], ['a built mesh', mesh]]) {
      const names = reachableNames(root);
      for (const hook of HOOK_NAMES) assert.ok(!names.has(hook), `${what} reaches '${hook}'`);
    }
    assert.deepEqual(Object.keys(wingspline).sort(), ['WingsplineError', 'loadWingspline']);
  } finally {
    mesh.dispose();
  }
});

test('no shipped module holds a benchmark entry point; the bench module holds them all', () => {
  const dir = new URL('../../../dist/wasm/', import.meta.url);
  const shipped = fs.readdirSync(dir).filter((f) => f.endsWith('.wasm'));
  // quickjs.wasm is the code lesson's sandbox engine (npm's @jitl/quickjs-wasmfile-release-sync).
  assert.deepEqual(shipped.sort(), ['quickjs.wasm', 'wingspline-curves.wasm', 'wingspline-exercises.wasm', 'wingspline-mesh.wasm', 'wingspline-meshes.wasm', 'wingspline-subdivision.wasm']);
  const benchWasm = fs.readFileSync(new URL('../../../build/wasm/wingspline-core-bench.wasm', import.meta.url)).toString('latin1');
  for (const name of ['benchBuildInCore', 'benchNormalsInCore', 'benchRingWalk', 'benchEditInCore', 'benchSubdivideInCore']) {
    for (const file of shipped) assert.ok(!fs.readFileSync(new URL(file, dir)).toString('latin1').includes(name), `${file} names ${name}`);
    assert.ok(benchWasm.includes(name), `the bench module lacks ${name}`);
  }
  // the package exports the API, its manifest and the wasm files, and no bench entry
  const pkg = JSON.parse(fs.readFileSync(new URL('../../../package.json', import.meta.url), 'utf8'));
  assert.equal(pkg.exports['.'].default, './dist/js/core/wingspline.js');
  assert.deepEqual(Object.keys(pkg.exports).filter((k) => /bench/i.test(k) || /bench/i.test(JSON.stringify(pkg.exports[k]))), []);
});

test('bench hooks: the ring walk visits 2E edges and sums the neighbours, counted from the edge table', () => {
  const { api, hooks } = bench;
  for (const input of [api.generateMesh('sphere', { slices: 9, stacks: 5 }), api.generateMesh('grid', { nx: 4, ny: 3 })]) {
    const mesh = api.buildMesh(input);
    try {
      const { edges } = mesh.wingedEdgeArrays();
      // Each edge is met once from each end: from S (neighbour E) and from E (neighbour S).
      let sum = 0;
      for (let e = 0; e < edges.length; e += 8) sum += edges[e] + edges[e + 1];
      const walk = hooks.ringWalk(mesh);
      assert.equal(walk.visited, edges.length / 4);
      assert.equal(walk.checksum, sum);
    } finally {
      mesh.dispose();
    }
  }
});

test('bench hooks: the in-core timers time R repetitions and refuse what the API refuses', () => {
  const { api, hooks } = bench;
  const cube = api.generateMesh('cube');
  const build = hooks.timeBuildInCore(cube, 3);
  assert.equal(build.seconds.length, 3);
  assert.ok(Array.from(build.seconds).every((s) => s >= 0));
  // checksum: per repetition, the last edge's end-right wing plus E (12 on a cube).
  const mesh = api.buildMesh(cube);
  try {
    const { edges } = mesh.wingedEdgeArrays();
    assert.equal(build.checksum, 3 * (edges[edges.length - 1] + 12));
    const normals = hooks.timeNormalsInCore(mesh, 2);
    assert.equal(normals.seconds.length, 2);
    const n = mesh.normals();
    assert.equal(normals.checksum, 2 * (n[0] + n[n.length - 1]));
    assert.throws(() => hooks.timeNormalsInCore(mesh, 0), { code: 'invalid-argument' });
  } finally {
    mesh.dispose();
  }
  assert.throws(() => hooks.ringWalk(mesh), { code: 'disposed' });
  assert.throws(() => hooks.timeBuildInCore({ positions: [0, 0, 0, 1, 0, 0], faces: [[0, 1, 1]] }, 1));
});
