// Messages name mesh elements as the pages do: the slides' 1-based labels (v1, e1, F1), as the
// lesson tables label their rows (web/js/ui/element-labels.js), although the API's indices are
// 0-based. Every call that takes an element is asked for one past the last, for -1 and for a
// removed one; each refusal must name the element and the range by their labels. Then the
// messages of representative errors (building, validating, reading files, the tables, the
// walk exercise) are scanned for 0-based wording.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { elementLabel } from '../../../web/js/ui/element-labels.js';

const api = await loadWingspline();

// What a person reading a message would take for counting from 0: a range from 0, "index N is
// out of range", "indices 0 ...", "(0-based)".
const ZERO_BASED = /\b0 to \d|\bindex -?\d+ is out of range|\bindices? 0\b|0-based|\b(vertices|edges|faces) 0\b/;

function errorOf(call) {
  try {
    const r = call();
    if (r && r.ok === false) return { code: r.code, message: r.message }; // a check's verdict
  } catch (err) {
    return { code: err.code, message: err.message };
  }
  return null;
}

// Every call of a Mesh that names an element of `kind`, with that element's index.
const CALLS = {
  vertex: {
    edgesAroundVertex: (m, v) => m.edgesAroundVertex(v),
    facesAroundVertex: (m, v) => m.facesAroundVertex(v),
    verticesAroundVertex: (m, v) => m.verticesAroundVertex(v),
    traversalSteps: (m, v) => m.traversalSteps(v),
    vertexNormal: (m, v) => m.vertexNormal(v),
    setVertexPosition: (m, v) => m.setVertexPosition(v, [0, 0, 0]),
    checkSetVertexEdge: (m, v) => m.checkSetVertexEdge(v, 0),
    setVertexEdge: (m, v) => m.setVertexEdge(v, 0),
    'query faces-around-vertex': (m, v) => m.query('faces-around-vertex', v),
    'query edges-around-vertex': (m, v) => m.query('edges-around-vertex', v),
    'check split-face (corner)': (m, v) => m.check('split-face', 0, v, 0),
    splitFace: (m, v) => m.splitFace(0, 0, v),
  },
  edge: {
    facesOfEdge: (m, e) => m.facesOfEdge(e),
    'query faces-of-edge': (m, e) => m.query('faces-of-edge', e),
    splitEdge: (m, e) => m.splitEdge(e),
    joinFaces: (m, e) => m.joinFaces(e),
    flipEdge: (m, e) => m.flipEdge(e),
    collapseEdge: (m, e) => m.collapseEdge(e),
    'check split-edge': (m, e) => m.check('split-edge', e),
    'apply collapse-edge': (m, e) => m.apply({ op: 'collapse-edge', e, t: 0.5 }),
    'setVertexEdge (edge)': (m, e) => m.setVertexEdge(0, e),
    'checkSetFaceEdge (edge)': (m, e) => m.checkSetFaceEdge(0, e),
  },
  face: {
    edgesOfFace: (m, f) => m.edgesOfFace(f),
    verticesOfFace: (m, f) => m.verticesOfFace(f),
    faceNeighbours: (m, f) => m.faceNeighbours(f),
    faceEdgeSteps: (m, f) => m.faceEdgeSteps(f),
    'query edges-of-face': (m, f) => m.query('edges-of-face', f),
    'query neighbours-of-face': (m, f) => m.query('neighbours-of-face', f),
    pokeFace: (m, f) => m.pokeFace(f),
    'check poke-face': (m, f) => m.check('poke-face', f),
    setFaceEdge: (m, f) => m.setFaceEdge(f, 0),
    'splitFace (face)': (m, f) => m.splitFace(f, 0, 2),
  },
};
const PLURAL = { vertex: 'vertices', edge: 'edges', face: 'faces' };

function withLecture(body) {
  const mesh = api.buildMesh(api.lectureExample()); // v1..v5, e1..e7, F1..F3
  try {
    return body(mesh);
  } finally {
    mesh.dispose();
  }
}

test('every call refuses a missing element by its label and names the range as the tables do ("there is no F4: the mesh has faces F1 to F3")', () => {
  let asked = 0;
  withLecture((mesh) => {
    const counts = { vertex: mesh.counts().vertices, edge: mesh.counts().edges, face: mesh.counts().faces };
    for (const [kind, calls] of Object.entries(CALLS)) {
      const n = counts[kind];
      const range = `the mesh has ${PLURAL[kind]} ${elementLabel(kind, 0)} to ${elementLabel(kind, n - 1)}`;
      for (const [name, call] of Object.entries(calls)) {
        for (const [index, names] of [[n, `there is no ${elementLabel(kind, n)}`], [n + 1000, `there is no ${elementLabel(kind, n + 1000)}`],
          [-1, `-1 names no ${kind} (it stands for none)`]]) {
          const err = errorOf(() => call(mesh, index));
          assert.ok(err, `${name}(${index}) was accepted`);
          assert.equal(err.code, 'invalid-element', `${name}(${index}): ${err.message}`);
          assert.equal(err.message, `${names}: ${range}`, `${name}(${index})`);
          asked += 1;
        }
      }
    }
    assert.equal(mesh.validate().ok, true);
  });
  assert.ok(asked >= 90, `${asked} refusals`);
});

test('a removed element is named by its label too, and a non-integer says what an index is', () => {
  withLecture((mesh) => {
    mesh.collapseEdge(3); // e4 = v3 -> v4: v4, e4, e5 and F2 become gaps
    const gaps = mesh.gaps();
    assert.deepEqual([Array.from(gaps.vertices), Array.from(gaps.edges), Array.from(gaps.faces)], [[3], [3, 4], [1]]);
    for (const [kind, index, label] of [['vertex', 3, 'v4'], ['edge', 4, 'e5'], ['face', 1, 'F2']]) {
      for (const [name, call] of Object.entries(CALLS[kind])) {
        const err = errorOf(() => call(mesh, index));
        assert.ok(err, `${name}(${index}) was accepted`);
        assert.equal(err.code, 'deleted-element', `${name}: ${err.message}`);
        assert.equal(err.message, `${label} was removed by an edit (its number stays a gap until the mesh is compacted)`, name);
      }
    }
    const err = errorOf(() => mesh.edgesOfFace(1.5));
    assert.equal(err.code, 'invalid-argument');
    assert.equal(err.message, 'face must be a whole number, the face\'s index (0 is the first face), not 1.5');
  });
});

test('the messages of building, validating, reading files, reading tables and the walk exercise count from 1', () => {
  const lecture = api.lectureExample();
  const messages = [];
  const expectError = (call, code, ...parts) => {
    const err = errorOf(call);
    assert.ok(err, `accepted: expected ${code}`);
    assert.equal(err.code, code, err.message);
    for (const part of parts) assert.ok(err.message.includes(part), `"${err.message}" does not say "${part}"`);
    messages.push(err.message);
  };
  // A face list naming vertex index 9 and -1 of a mesh of five vertices.
  const bad = { positions: lecture.positions, faces: [[0, 1, 2], [1, 9, -1]] };
  expectError(() => api.buildMesh(bad), 'index-out-of-range', 'F2 refers to v10 (index 9), -1, no vertex', 'vertices v1 to v5');
  const problems = api.validateMesh(bad).problems; // and warnings for v4 and v5, on no face
  assert.deepEqual(problems.map((p) => p.code), ['index-out-of-range', 'isolated-vertex', 'isolated-vertex']);
  assert.deepEqual(problems.slice(1).map((p) => p.message.slice(0, 2)), ['v4', 'v5']);
  messages.push(...problems.map((p) => p.message));
  // The optional numbering: the edge list, the vertex and face tables.
  expectError(() => api.buildMesh({ ...lecture, edges: lecture.edges.map((e, i) => (i === 2 ? [1, 7] : e)) }), 'invalid-edge-list',
    'e3 = [1, 7]', 'there is no v8', 'vertices v1 to v5');
  expectError(() => api.buildMesh({ ...lecture, vertexEdges: [0, 1, 2, 3, 9] }), 'invalid-vertex-edge', 'e10 for v5', 'edges e1 to e7');
  expectError(() => api.buildMesh({ ...lecture, faceEdges: [0, 2, 7] }), 'invalid-face-edge', 'e8 for F3', 'edges e1 to e7');
  expectError(() => api.buildMesh({ positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], faces: [[0, 1, 2], [0, 1.5, 2]] }), 'invalid-argument', 'corner 2 of F2');
  // Files: OFF counts vertices from 0, OBJ from 1; both name the vertex by its label.
  expectError(() => api.parseMesh('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n'), 'index-out-of-range',
    'F1 refers to vertex 5, that is v6', 'vertices v1 to v3');
  expectError(() => api.parseMesh('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 7\n', { format: 'obj' }), 'index-out-of-range',
    'F2 refers to v7', 'vertices v1 to v3');
  // A table read past its window names the rows as the table shows them.
  withLecture((mesh) => {
    const faces = mesh.tables('winged-edge', { offset: 1, limit: 1 }).faces;
    expectError(() => faces.row(0), 'invalid-element', 'F1 is not among the rows read (F2)');
    expectError(() => mesh.tables('winged-edge').edges.row(7), 'invalid-element', 'e8 is not among the rows read (e1 to e7)');
  });
  // The walk exercise: no such vertex, and a given edge the mesh does not have.
  expectError(() => api.checkWalkStep(lecture, { around: 'vertex', element: 5, step: 1, given: 0 }), 'index-out-of-range',
    'there is no v6: the mesh has vertices v1 to v5');
  const reason = api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: 1, given: 9 }).reason;
  assert.ok(reason.startsWith('not e10 (the mesh has no such edge): '), reason);
  messages.push(reason);
  for (const m of messages) assert.doesNotMatch(m, ZERO_BASED, m);
});
