// The core ships in parts (docs/architecture.md, "Module size"): a page asks for the parts it
// uses, the package gets every part by default (mesh and subdivision together from one module). Each module is built from the one
// source: the same version, the same error list, the same answers where two modules hold the
// same code (curve sampling), and C++ errors (native wasm exceptions) become the same
// {code, message} errors in every module.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline, WingsplineError } from 'wingspline';

const pkg = JSON.parse(fs.readFileSync(new URL('../../../package.json', import.meta.url), 'utf8'));
const PARTS = ['mesh', 'subdivision', 'curves', 'exercises'];
// Two triangles sharing the edge v2-v3 (5 edges).
const TWO_TRIANGLES = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], faces: [[0, 1, 2], [2, 1, 3]] };
// An edge shared by three faces: refused by every module that builds meshes.
const THREE_AT_AN_EDGE = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1], faces: [[0, 1, 2], [1, 0, 3], [0, 1, 4]] };

test('each part alone reports the package version and the one error list', async () => {
  const full = await loadWingspline();
  for (const part of PARTS) {
    const api = await loadWingspline({ parts: [part] });
    assert.equal(api.version, pkg.version, part);
    assert.deepEqual(api.errorCodes, full.errorCodes, `${part}: the same error list`);
    assert.equal(await loadWingspline({ parts: [part] }), api, `${part}: one API object per set of parts`);
  }
});

test('a part carries its own functions only', async () => {
  const mesh = await loadWingspline({ parts: ['mesh'] });
  assert.equal(typeof mesh.buildMesh, 'function');
  assert.equal(mesh.subdivide, undefined, 'the mesh lesson\'s module has no subdivision');
  assert.equal(mesh.evaluateCurve, undefined);
  assert.equal(mesh.checkMeshTableAnswer, undefined);
  const subdivision = await loadWingspline({ parts: ['subdivision'] });
  for (const name of ['buildMesh', 'subdivide', 'limitPositions', 'sampleCurve', 'uniformKnots', 'subdivideCurve']) assert.equal(typeof subdivision[name], 'function', name);
  assert.equal(subdivision.segmentMatrices, undefined);
  assert.equal(subdivision.editCostGrowth, undefined, 'the subdivision lesson\'s module does not edit');
  assert.equal(subdivision.queryCostGrowth, undefined, 'nor draws the mesh lesson\'s cost charts');
  assert.deepEqual(subdivision.meshOperations.operations, [], 'nor carries the registry');
  assert.deepEqual([subdivision.meshOperations.tables, subdivision.meshOperations.fields], [mesh.meshOperations.tables, mesh.meshOperations.fields],
    'a playback\'s steps read the same in both');
  const curves = await loadWingspline({ parts: ['curves'] });
  assert.equal(curves.buildMesh, undefined);
  assert.equal(typeof curves.segmentMatrices, 'function');
  const exercises = await loadWingspline({ parts: ['exercises'] });
  assert.equal(typeof exercises.checkMeshTableAnswer, 'function');
  assert.equal(typeof exercises.checkCurveProperty, 'function');
  assert.equal(exercises.buildMesh, undefined);
  // Asked for 'mesh' and 'subdivision', one module holds the meshes (wingspline-meshes): one
  // mesh can be edited and subdivided.
  const both = await loadWingspline({ parts: ['mesh', 'subdivision'] });
  assert.notEqual(both, subdivision);
  assert.equal(typeof both.subdivide, 'function');
  assert.equal(typeof both.editCostGrowth, 'function');
  assert.deepEqual(both.meshOperations, mesh.meshOperations);
  const full = await loadWingspline();
  for (const name of Object.keys(mesh).concat(Object.keys(subdivision), Object.keys(curves), Object.keys(exercises))) {
    assert.ok(name in full, `the package API has ${name}`);
  }
});

test('a mesh of the subdivision part refuses edits with part-not-loaded and stays as it was; one of both parts is edited, then subdivided', async () => {
  const subdivision = await loadWingspline({ parts: ['subdivision'] });
  const m = subdivision.buildMesh(TWO_TRIANGLES);
  const tables = m.wingedEdge();
  const version = m.coreVersion();
  const refused = (err) => err instanceof WingsplineError && err.code === 'part-not-loaded' && /parts: \['mesh'\]/.test(err.message);
  assert.throws(() => m.apply({ op: 'flip-edge', e: 2 }), refused);
  assert.throws(() => m.check({ op: 'flip-edge', e: 2 }), refused);
  assert.throws(() => m.flipEdge(2), refused);
  assert.throws(() => m.compact(), refused);
  assert.deepEqual(m.wingedEdge(), tables);
  assert.deepEqual(m.coreVersion(), version);
  // Subdivision and the reconnection's playback still read their steps through the format.
  const playback = subdivision.reconnectionPlayback(m, { scheme: 'loop' });
  assert.ok(playback.steps.length > 0 && playback.steps.every((s) => ['vertex', 'edge', 'face'].includes(s.table)));
  m.dispose();
  const full = await loadWingspline({ parts: ['mesh', 'subdivision'] });
  const e = full.buildMesh(TWO_TRIANGLES);
  const change = e.apply({ op: 'split-edge', e: 2 });
  assert.deepEqual([change.added.vertices.length, e.counts().vertices], [1, 5]);
  // The split made a face with four corners: Catmull-Clark gives V + E + F vertices and one
  // quad per face corner, a corner being an edge side with a face (left or right).
  const { vertices: V, edges: E, faces: F } = e.counts();
  const corners = e.wingedEdge().edges.reduce((n, edge) => n + (edge.left >= 0) + (edge.right >= 0), 0);
  const fine = full.subdivide(e, { scheme: 'catmull-clark', steps: 1 });
  assert.deepEqual([fine.counts().vertices, fine.counts().faces], [V + E + F, corners]);
  fine.dispose();
  e.dispose();
});

test('parts that do not exist are refused with invalid-argument', async () => {
  for (const parts of [[], ['meshes'], 'mesh', [1]]) {
    await assert.rejects(loadWingspline({ parts }), (err) => err instanceof WingsplineError && err.code === 'invalid-argument' && /mesh/.test(err.message), JSON.stringify(parts));
  }
});

test('a refusal thrown in C++ is the same {code, message} error in every module that builds meshes', async () => {
  for (const part of ['mesh', 'subdivision']) {
    const api = await loadWingspline({ parts: [part] });
    assert.throws(() => api.buildMesh(THREE_AT_AN_EDGE), (err) => err instanceof WingsplineError && err.code === 'non-manifold-edge' && /3 faces/.test(err.message), part);
    const m = api.buildMesh(TWO_TRIANGLES);
    assert.equal(m.counts().edges, 5, `${part}: the module keeps working after a refusal`);
    m.dispose();
  }
  const exercises = await loadWingspline({ parts: ['exercises'] });
  assert.throws(() => exercises.checkMeshTableAnswer({ faces: [[0, 1, 2]], vertexCount: 3 }, 'no-such-table', {}), (err) => err instanceof WingsplineError && typeof err.code === 'string');
});

test('curve sampling answers bit for bit the same in the curves and the subdivision modules', async () => {
  const curves = await loadWingspline({ parts: ['curves'] });
  const subdivision = await loadWingspline({ parts: ['subdivision'] });
  const points = [0, 0, 1, 2, 3, 2, 4, 0, 5, 1];
  for (const degree of [2, 3]) {
    const knots = curves.uniformKnots(5, degree);
    assert.deepEqual(subdivision.uniformKnots(5, degree), knots);
    const spec = { kind: 'bspline', dim: 2, degree, points, knots };
    assert.deepEqual(subdivision.sampleCurve(spec, 33), curves.sampleCurve(spec, 33));
  }
  for (const scheme of ['chaikin', 'cubic-bspline']) {
    assert.deepEqual(subdivision.subdivideCurve(points, 2, { scheme, steps: 3 }), curves.subdivideCurve(points, 2, { scheme, steps: 3 }));
  }
  assert.throws(() => subdivision.sampleCurve({ kind: 'bspline', dim: 2, degree: 3, points, knots: [0, 1] }), (err) => err instanceof WingsplineError && typeof err.code === 'string');
});

test('the subdivision lesson\'s module names no edit binding and no operation of the registry; the mesh lesson\'s names them all', () => {
  // Embind registers each function under its name (a string in the module's data); the
  // registry's wording ("flip {e}") comes with the operations' checks and changes.
  const read = (name) => fs.readFileSync(new URL(`../../../dist/wasm/wingspline-${name}.wasm`, import.meta.url)).toString('latin1');
  const subdivision = read('subdivision');
  const mesh = read('mesh');
  for (const name of ['meshEdit', 'meshEditCostGrowth', 'meshCompact', 'meshOperationDescriptors', 'split {e} at t = {t}']) {
    assert.ok(!subdivision.includes(name), `wingspline-subdivision.wasm names ${name}`);
    assert.ok(mesh.includes(name), `wingspline-mesh.wasm lacks ${name}`);
  }
  for (const name of ['meshChangeFormat', 'meshReconnectionPlayback', 'meshSubdivide']) assert.ok(subdivision.includes(name), name);
});
