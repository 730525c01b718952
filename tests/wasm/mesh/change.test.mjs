// The mesh's change model through the JS API: checked operations, change
// records, mesh.version, and caches keyed on it (representations() after an operation
// reflect it). Expected values come from lecture 000's slide tables.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();

function withLecture(body) {
  const mesh = api.buildMesh(api.lectureExample());
  try {
    return body(mesh);
  } finally {
    mesh.dispose();
  }
}

const valid = (mesh) => assert.deepEqual(mesh.validate().problems.filter((p) => p.severity === 'error'), []);

test('setVertexEdge: v2 stores e3 instead of e6; the row, the walk and the version follow', () => withLecture((mesh) => {
  assert.deepEqual(mesh.version, { topology: 0, geometry: 0 });
  assert.deepEqual(mesh.checkSetVertexEdge(1, 2), { ok: true });
  const change = mesh.setVertexEdge(1, 2);
  assert.equal(change.op, 'set-vertex-edge');
  assert.deepEqual(change.rows, [{ table: 'vertex', row: 1, fields: [{ field: 'edge', before: 5, after: 2 }] }]);
  assert.deepEqual(change.added, { vertices: [], edges: [], faces: [] });
  assert.deepEqual(change.removed, { vertices: [], edges: [], faces: [] });
  assert.deepEqual(change.before, { topology: 0, geometry: 0 });
  assert.deepEqual(change.after, { topology: 1, geometry: 0 });
  assert.deepEqual(mesh.version, { topology: 1, geometry: 0 });
  assert.deepEqual(mesh.coreVersion(), mesh.version);
  assert.equal(mesh.wingedEdge().vertices[1].edge, 2);
  assert.deepEqual(Array.from(mesh.edgesAroundVertex(1)), [2, 1, 5, 4]); // e3, e2, e6, e5
  assert.equal(mesh.traversalSteps(1)[0].edge, 2);
  valid(mesh);
}));

test('a refused operation throws its code, names the elements and changes nothing', () => withLecture((mesh) => {
  const before = mesh.wingedEdgeArrays();
  // e7 (v4-v5) does not touch v1.
  const verdict = mesh.checkSetVertexEdge(0, 6);
  assert.equal(verdict.ok, false);
  assert.equal(verdict.code, 'edge-not-incident');
  assert.match(verdict.message, /e7 does not touch v1/);
  assert.throws(() => mesh.setVertexEdge(0, 6), { code: 'edge-not-incident', message: verdict.message });
  // e1 is not a side of F3.
  assert.throws(() => mesh.setFaceEdge(2, 0), { code: 'edge-not-on-face', message: /e1 is not a side of F3/ });
  assert.throws(() => mesh.setFaceEdge(3, 0), { code: 'invalid-element', message: /there is no F4: the mesh has faces F1 to F3/ });
  assert.throws(() => mesh.setVertexEdge(0, 1.5), { code: 'invalid-argument' });
  assert.throws(() => mesh.apply({ op: 'flip', e: 0 }), { code: 'unknown-operation' });
  const after = mesh.wingedEdgeArrays();
  for (const key of ['positions', 'vertexEdge', 'edges', 'faceEdge']) assert.deepEqual(after[key], before[key], key);
  assert.deepEqual(mesh.version, { topology: 0, geometry: 0 });
  assert.deepEqual(mesh.coreVersion(), { topology: 0, geometry: 0 });
}));

test('versions move exactly on change: the stored edge again, or the same position, change nothing', () => withLecture((mesh) => {
  mesh.setFaceEdge(1, 4);
  assert.deepEqual(mesh.version, { topology: 1, geometry: 0 });
  const again = mesh.setFaceEdge(1, 4);
  assert.deepEqual(again.rows, []);
  assert.deepEqual(mesh.version, { topology: 1, geometry: 0 });
  mesh.setVertexPosition(0, [0, 1, 0]); // where v1 already is
  assert.deepEqual(mesh.version, { topology: 1, geometry: 0 });
  mesh.setVertexPosition(0, [0, 1.5, 0]);
  assert.deepEqual(mesh.version, { topology: 1, geometry: 1 });
  assert.deepEqual(mesh.coreVersion(), mesh.version);
  const version = mesh.version;
  assert.ok(Object.isFrozen(version));
  assert.equal(mesh.version, version, 'an unchanged version is the same object (cheap to compare)');
}));

test('representations() after an operation reflect it, and equal a mesh built with those stored edges', () => withLecture((mesh) => {
  const before = mesh.representations();
  mesh.setVertexEdge(1, 2);
  mesh.setFaceEdge(0, 2); // F1 stores e3
  const after = mesh.representations();
  assert.equal(after['winged-edge'].vertices[1].edge, 2);
  assert.equal(after['winged-edge'].faces[0].edge, 2);
  // The face set is unchanged, so the other five representations are too.
  for (const key of ['independent-faces', 'vertex-face-tables', 'adjacency-lists', 'partial-adjacency-lists', 'edge-list']) {
    assert.deepEqual(after[key], before[key], key);
  }
  // From scratch: the slide's mesh built with today's stored edges.
  const spec = api.lectureExample();
  const vertexEdges = Array.from(mesh.wingedEdgeArrays().vertexEdge);
  const faceEdges = Array.from(mesh.wingedEdgeArrays().faceEdge);
  const fresh = api.buildMesh({ ...spec, vertexEdges, faceEdges });
  try {
    const scratch = fresh.representations();
    for (const key of Object.keys(scratch)) {
      const { storage: a, ...restA } = after[key];
      const { storage: b, ...restB } = scratch[key];
      assert.deepEqual(restA, restB, key);
      assert.deepEqual(a, b, `${key} storage`);
    }
    assert.deepEqual(Array.from(fresh.edgesOfFace(0)), Array.from(mesh.edgesOfFace(0)));
  } finally {
    fresh.dispose();
  }
  valid(mesh);
}));

test('planes keep each face\'s first three corners after its stored edge changed', () => withLecture((mesh) => {
  const before = mesh.planes();
  mesh.setFaceEdge(0, 2);
  assert.deepEqual(mesh.planes().map((p) => p.crossCorners), before.map((p) => p.crossCorners));
  assert.deepEqual(before[0].crossCorners, [0, 1, 2]); // F1 = (v1 v2 v3) as given
}));

test('apply() takes the lesson state\'s operation records', () => withLecture((mesh) => {
  const change = mesh.apply({ op: 'set-face-edge', f: 1, e: 3 });
  assert.deepEqual(change.rows, [{ table: 'face', row: 1, fields: [{ field: 'edge', before: 2, after: 3 }] }]);
  mesh.apply({ op: 'set-vertex-edge', v: 4, e: 6 });
  assert.equal(mesh.wingedEdge().vertices[4].edge, 6);
  assert.deepEqual(mesh.version, { topology: 2, geometry: 0 });
  assert.notEqual(mesh.id, 0);
}));
