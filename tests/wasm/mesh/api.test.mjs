// The mesh JS API contract: shapes, typed arrays, 0-based indices, -1 = none,
// errors with codes, disposal. Expected values come from lecture 000's slide tables.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { withValidMesh } from '../../helpers/wasm-mesh.mjs';

const api = await loadWingspline();

// Lecture 000, edge table (1-based on the slide): S E L R | SL SR EL ER; '-' = no face.
const SLIDE_EDGES = `
e1 v1 v3 -  F1 e2 e2 e4 e3
e2 v1 v2 F1 -  e1 e1 e3 e6
e3 v2 v3 F1 F2 e2 e5 e1 e4
e4 v3 v4 -  F2 e1 e3 e7 e5
e5 v2 v4 F2 F3 e3 e6 e4 e7
e6 v2 v5 F3 -  e5 e2 e7 e7
e7 v4 v5 -  F3 e4 e5 e6 e6`;
const label = (s) => (s === '-' ? -1 : Number(s.slice(1)) - 1);
const slideEdges = SLIDE_EDGES.trim().split('\n').map((line) => {
  const [, ...cells] = line.trim().split(/\s+/);
  const [start, end, left, right, startLeft, startRight, endLeft, endRight] = cells.map(label);
  return { start, end, left, right, startLeft, startRight, endLeft, endRight };
});
const SLIDE_VERTEX_EDGES = ['e1', 'e6', 'e3', 'e5', 'e6'].map(label);
const SLIDE_FACE_EDGES = ['e1', 'e3', 'e5'].map(label);

const withMesh = (input, body) => withValidMesh(api, input, body);

test('the lecture example reproduces the slide tables entry for entry', () => {
  withMesh(api.lectureExample(), (mesh) => {
    const we = mesh.wingedEdge();
    assert.deepEqual(we.edges, slideEdges);
    assert.deepEqual(we.vertices.map((v) => v.edge), SLIDE_VERTEX_EDGES);
    assert.deepEqual(we.faces.map((f) => f.edge), SLIDE_FACE_EDGES);
    assert.deepEqual(we.vertices.map((v) => [v.x, v.y, v.z]), [[0, 1, 0], [1, 0, 0], [1, 2, 0], [2, 1, 0], [2, -1, 0]]);
  });
});

test('CCW around v2 is e6, e5, e3, e2, with the columns the lecture reads', () => {
  withMesh(api.lectureExample(), (mesh) => {
    const ring = mesh.edgesAroundVertex(1);
    assert.ok(ring instanceof Int32Array);
    assert.deepEqual(Array.from(ring), ['e6', 'e5', 'e3', 'e2'].map(label));
    assert.deepEqual(mesh.traversalSteps(1), [
      { edge: 5, role: 'start', column: 'startLeft', next: 4 },
      { edge: 4, role: 'start', column: 'startLeft', next: 2 },
      { edge: 2, role: 'start', column: 'startLeft', next: 1 },
      { edge: 1, role: 'end', column: 'endRight', next: 5 },
    ]);
  });
});

test('a refused mesh throws its first problem code and lists every problem in details', () => {
  const { positions } = api.lectureExample();
  assert.throws(() => api.buildMesh({ positions, faces: [[0, 1, 2], [0, 1, 3], [0, 1, 4]] }), (err) =>
    err.code === 'non-manifold-edge' && /v1-v2/.test(err.message) && Array.isArray(err.details) &&
    err.details.some((p) => p.code === 'non-manifold-edge' && p.elements.faces.join() === '0,1,2'));
  assert.equal(api.liveMeshCount(), 0);
});

test('10,000 failing calls leave the module usable; 1,000 build/dispose cycles do not grow the heap', () => {
  const { positions } = api.lectureExample();
  for (let i = 0; i < 10000; i += 1) {
    assert.throws(() => api.buildMesh({ positions, faces: [[0, 1, 9]] }), (err) => err.code === 'index-out-of-range');
  }
  const input = api.lectureExample();
  api.buildMesh(input).dispose();
  const before = api.memoryUsage();
  for (let i = 0; i < 1000; i += 1) {
    const mesh = api.buildMesh(input);
    mesh.dispose();
    mesh.dispose(); // idempotent
    assert.throws(() => mesh.wingedEdge(), (err) => err.code === 'disposed');
  }
  const after = api.memoryUsage();
  assert.equal(api.liveMeshCount(), 0);
  assert.equal(after.linearBytes, before.linearBytes);
  assert.equal(after.heapInUse, before.heapInUse);
});

test('OFF/OBJ parse with line-numbered errors and round-trip bit for bit', () => {
  const sphere = api.generateMesh('sphere', { slices: 7, stacks: 4 });
  const back = api.parseMesh(api.formatMesh(sphere, { format: 'obj' }), { format: 'obj' });
  assert.ok(back.positions instanceof Float64Array);
  assert.deepEqual(back.positions, sphere.positions);
  assert.deepEqual(back.faces, sphere.faces);
  assert.throws(() => api.parseMesh('OFF\n3 1 0\n0 0 0\n1 x 0\n', { format: 'off' }),
    (err) => err.code === 'parse-error' && err.line === 4 && /line 4/.test(err.message));
});

test('generated meshes: closed solids have Euler 2, normals are unit, planes have both forms', () => {
  for (const kind of ['tetrahedron', 'cube', 'sphere']) {
    withMesh(api.generateMesh(kind), (mesh) => {
      assert.equal(mesh.counts().euler, 2, kind);
      const n = mesh.normals();
      for (let f = 0; f < n.length / 3; f += 1) {
        assert.ok(Math.abs(Math.hypot(n[3 * f], n[3 * f + 1], n[3 * f + 2]) - 1) < 1e-12);
      }
      const planes = mesh.planes();
      assert.equal(planes.length, mesh.counts().faces);
      assert.equal(planes[0].cross.length, 4);
    });
  }
  withMesh(api.generateMesh('cube'), (mesh) => {
    // Vertex 0 is a corner of 3 quads: independent faces rewrite 3 copies, the others 1 entry.
    assert.equal(mesh.setVertexPosition(0, [0, 0, 0]).changedEntries['independent-faces'], 3);
  });
});

test('normals({into}) fills the caller\'s array with the same unit normals; a wrong array is refused', () => {
  withMesh(api.generateMesh('cube'), (mesh) => {
    const fresh = mesh.normals();
    const into = new Float64Array(3 * 6).fill(Number.NaN);
    assert.equal(mesh.normals({ into }), into);
    assert.deepEqual(into, fresh);
    // Cube face 0 lies in z = 0 with outward normal -z.
    assert.deepEqual(Array.from(into.subarray(0, 3)), [0, 0, -1]);
    assert.throws(() => mesh.normals({ into: new Float64Array(5) }), (err) => err.code === 'invalid-argument');
    assert.throws(() => mesh.normals({ into: [0, 0, 0] }), (err) => err.code === 'invalid-argument');
  });
});

// buildMeshInSteps gives buildMesh's mesh, one phase of the core's build per step.
test('buildMeshInSteps: the phases in order, then the same tables as buildMesh; a refusal ends the build', () => {
  const live = api.liveMeshCount();
  const input = api.generateMesh('sphere', { slices: 12, stacks: 7, layout: 'csr' });
  const job = api.buildMeshInSteps(input);
  const phases = [job.phase];
  while (!job.step()) phases.push(job.phase);
  assert.deepEqual(phases, ['counting sides', 'bucketing sides', 'pairing twins', 'numbering edges', 'face wings', 'boundary wings', 'checks', 'stored edges']);
  assert.equal(job.phase, 'done');
  const whole = api.buildMesh(input);
  try {
    const a = job.mesh.wingedEdgeArrays();
    const b = whole.wingedEdgeArrays();
    for (const k of ['positions', 'edges', 'vertexEdge', 'faceEdge']) assert.deepEqual(Array.from(a[k] ?? []), Array.from(b[k] ?? []), k);
    assert.equal(job.step(), true, 'a finished build stays finished');
  } finally {
    job.mesh.dispose();
    whole.dispose();
  }
  // Three faces on one edge: refused in a step with buildMesh's code; the build is then over.
  const bad = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 1, 1, 1], faces: [[0, 1, 2], [1, 0, 3], [0, 1, 4]] };
  const refused = api.buildMeshInSteps(bad);
  assert.throws(() => { while (!refused.step()); }, (e) => e.code === 'non-manifold-edge');
  assert.throws(() => refused.step(), (e) => e.code === 'invalid-argument' && /over/.test(e.message));
  assert.equal(api.liveMeshCount(), live, 'no mesh left behind');
});
