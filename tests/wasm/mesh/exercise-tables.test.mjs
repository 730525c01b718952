// Exercise kinds 1 and 2 over the real module: api.checkMeshTableAnswer for the face
// table, the edge list and the adjacency lists (and the winged edge through the same entry
// point), api.checkWalkStep for the CCW walk. The lectures' tables are written here as the
// slides print them; other correct answers (renumbered, rotated, reversed) are made here from
// the faces, and the expected value of a corrupted cell is the one the cell held.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();

const lecture = api.lectureExample();
const mesh = { faces: lecture.faces, vertexCount: lecture.positions.length / 3 };
const foley = api.foleyExample();
const foleyMesh = { faces: foley.faces, vertexCount: foley.positions.length / 3 };

const codeOf = (fn) => {
  try {
    fn();
  } catch (err) {
    return err.code;
  }
  return 'accepted';
};

test('faces: the slide\'s face table is accepted from any corner; one face clockwise is one finding', () => {
  // Lecture 000, "Vertex and Face Tables": F1 = V1 V2 V3, F2 = V2 V4 V3, F3 = V2 V5 V4.
  const slide = [[0, 1, 2], [1, 3, 2], [1, 4, 3]];
  const r = api.checkMeshTableAnswer(mesh, 'faces', { faces: slide });
  assert.deepEqual(r, { correct: true, findings: [], worked: { faces: slide } });
  assert.equal(api.checkMeshTableAnswer(mesh, 'faces', { faces: [[2, 0, 1], [3, 2, 1], [4, 3, 1]] }).correct, true);
  const cw = api.checkMeshTableAnswer(mesh, 'faces', { faces: [[0, 1, 2], [1, 2, 3], [1, 4, 3]] });
  assert.equal(cw.correct, false);
  assert.deepEqual(cw.findings.map((f) => [f.table, f.row, f.field, f.code]), [['face', 1, 'vertices', 'clockwise']]);
  assert.match(cw.findings[0].reason, /^face F2: .*counter-clockwise/);
  assert.deepEqual(cw.worked.faces, slide);
});

test('faces: one corrupted corner is named with the vertex it should be (seeded, 300 cases)', () => {
  const rand = random(1903);
  const cube = api.generateMesh('cube');
  const m = { faces: cube.faces, vertexCount: cube.positions.length / 3 };
  for (let trial = 0; trial < 300; trial += 1) {
    const faces = cube.faces.map((f) => {
      const k = Math.floor(rand() * f.length);
      return [...f.slice(k), ...f.slice(0, k)];
    });
    const f = Math.floor(rand() * faces.length);
    const i = Math.floor(rand() * 4);
    const old = faces[f][i];
    const value = [-2, -1, 8, 9][Math.floor(rand() * 4)];
    const wrong = faces.map((x) => x.slice());
    wrong[f][i] = value;
    const r = api.checkMeshTableAnswer(m, 'faces', { faces: wrong });
    assert.equal(r.findings.length, 1, `trial ${trial}`);
    const x = r.findings[0];
    assert.deepEqual([x.table, x.row, x.field, x.index, x.given, x.expected, x.code],
      ['face', f, 'vertices', i, value, old, value === -2 ? 'blank' : 'unknown-label']);
    assert.deepEqual(r.worked.faces, faces);
  }
});

test('edge-list: Foley\'s table as printed is accepted, and renumbered with rows reversed', () => {
  // Lecture 001: E1 = (V1, V2, P1, λ), E2 = (V2, V3, P2, λ), E3 = (V3, V4, P2, λ), E4 = (V4, V2, P1, P2),
  // E5 = (V4, V1, P1, λ); P1 = (E1, E4, E5), P2 = (E2, E3, E4).
  const edges = [0, 1, 0, -1, 1, 2, 1, -1, 2, 3, 1, -1, 3, 1, 0, 1, 3, 0, 0, -1];
  const polygons = [[0, 3, 4], [1, 2, 3]];
  assert.deepEqual(api.checkMeshTableAnswer(foleyMesh, 'edge-list', { edges, polygons }),
    { correct: true, findings: [], worked: { edges, polygons } });
  // Rows in the order E5 E4 E3 E2 E1, each run the other way, P1/P2 swapped on E4.
  const renumbered = [0, 3, 0, -1, 1, 3, 1, 0, 3, 2, 1, -1, 2, 1, 1, -1, 1, 0, 0, -1];
  assert.equal(api.checkMeshTableAnswer(foleyMesh, 'edge-list', { edges: renumbered, polygons: [[4, 1, 0], [3, 2, 1]] }).correct, true);
  // P1 written as P2 on E4 (the wrong face): named on row e4 with the face it should be.
  const wrong = edges.slice();
  wrong[4 * 3 + 3] = 0;
  const r = api.checkMeshTableAnswer(foleyMesh, 'edge-list', { edges: wrong, polygons });
  assert.deepEqual(r.findings.map((f) => [f.table, f.row, f.field, f.given, f.expected, f.code]), [['edge', 3, 'p2', 0, 1, 'wrong-face']]);
  assert.match(r.findings[0].reason, /^row e4: P₂ is F2, not F1/);
  assert.deepEqual(r.worked.edges, edges);
  // A polygon listing an edge that is not its side.
  const p = api.checkMeshTableAnswer(foleyMesh, 'edge-list', { edges, polygons: [[0, 3, 1], [1, 2, 3]] });
  assert.deepEqual(p.findings.map((f) => [f.table, f.row, f.field, f.index, f.given, f.expected, f.code]),
    [['face', 0, 'edges', 2, 1, 4, 'not-on-face']]);
  assert.deepEqual(p.worked.polygons, polygons);
});

test('edge-list: 200 seeded renumberings of a grid\'s edge list accepted; a changed P cell named with the face it held', () => {
  const rand = random(1904);
  const grid = api.generateMesh('grid', { nx: 3, ny: 2 });
  const m = { faces: grid.faces, vertexCount: grid.positions.length / 3 };
  // The edges from the faces: neighbouring corners; the face running a -> b.
  const runs = new Map();
  const pairs = [];
  const sides = grid.faces.map(() => []);
  const seen = new Map();
  grid.faces.forEach((face, f) => face.forEach((a, i) => {
    const b = face[(i + 1) % face.length];
    runs.set(`${a},${b}`, f);
    const key = `${Math.min(a, b)},${Math.max(a, b)}`;
    if (!seen.has(key)) {
      seen.set(key, pairs.length);
      pairs.push([a, b]);
    }
    sides[f].push(seen.get(key));
  }));
  const run = (a, b) => runs.get(`${a},${b}`) ?? -1;
  for (let trial = 0; trial < 200; trial += 1) {
    const to = pairs.map((_, e) => e);
    for (let i = to.length - 1; i > 0; i -= 1) {
      const j = Math.floor(rand() * (i + 1));
      [to[i], to[j]] = [to[j], to[i]];
    }
    const edges = new Array(4 * pairs.length);
    pairs.forEach(([a, b], e) => {
      const [s, t] = rand() < 0.5 ? [a, b] : [b, a];
      const p = rand() < 0.5 ? [run(s, t), run(t, s)] : [run(t, s), run(s, t)];
      edges.splice(4 * to[e], 4, s, t, ...p);
    });
    const polygons = sides.map((list) => list.map((e) => to[e]));
    const ok = api.checkMeshTableAnswer(m, 'edge-list', { edges, polygons });
    assert.deepEqual(ok.findings, [], `trial ${trial}`);
    const row = Math.floor(rand() * pairs.length);
    const k = 2 + Math.floor(rand() * 2);
    const wrong = edges.slice();
    const old = edges[4 * row + k];
    wrong[4 * row + k] = -2;
    const r = api.checkMeshTableAnswer(m, 'edge-list', { edges: wrong, polygons });
    assert.deepEqual(r.findings.map((f) => [f.table, f.row, f.field, f.given, f.expected, f.code]),
      [['edge', row, k === 2 ? 'p1' : 'p2', -2, old, 'blank']], `trial ${trial}`);
    assert.deepEqual(r.worked.edges, edges);
  }
});

test('adjacency: each vertex\'s neighbours in any order; a wrong one and a missing one are named', () => {
  // From the slide's faces: v1: v2 v3; v2: v1 v3 v4 v5; v3: v1 v2 v4; v4: v2 v3 v5; v5: v2 v4.
  const right = [[1, 2], [0, 2, 3, 4], [0, 1, 3], [1, 2, 4], [1, 3]];
  assert.deepEqual(api.checkMeshTableAnswer(mesh, 'adjacency', { vertexVertices: right }),
    { correct: true, findings: [], worked: { vertexVertices: right } });
  assert.equal(api.checkMeshTableAnswer(mesh, 'adjacency', { vertexVertices: right.map((r) => r.slice().reverse()) }).correct, true);
  const wrong = right.map((r) => r.slice());
  wrong[1][3] = 4 - 4; // v2 lists v1 twice instead of v5
  wrong[4] = [1];
  const r = api.checkMeshTableAnswer(mesh, 'adjacency', { vertexVertices: wrong });
  assert.deepEqual(r.findings.map((f) => [f.table, f.row, f.index, f.given, f.expected, f.code]),
    [['vertex', 1, 3, 0, 4, 'not-adjacent'], ['vertex', 4, -1, -1, 3, 'missing-vertex']]);
  assert.match(r.findings[0].reason, /^vertex v2, item 4: v1 is listed twice/);
  assert.deepEqual(r.worked.vertexVertices, right);
});

test('winged-edge through checkMeshTableAnswer: the worked answer in the answer\'s shape', () => {
  const answer = { edges: [], vertexEdges: [-2, -2, -2, -2, -2], faceEdges: [-2, -2, -2] };
  const r = api.checkMeshTableAnswer(mesh, 'winged-edge', answer);
  assert.equal(r.correct, false);
  assert.equal(r.findings.filter((f) => f.code === 'missing-edge').length, 7);
  assert.ok(Array.isArray(r.worked.edges) && r.worked.edges.length === 56);
  assert.equal(api.checkMeshTableAnswer(mesh, 'winged-edge', r.worked).correct, true);
});

test('checkMeshTableAnswer errors: unknown-table, invalid-answer naming the row and field', () => {
  assert.equal(codeOf(() => api.checkMeshTableAnswer(mesh, 'quad-edge', {})), 'unknown-table');
  assert.equal(codeOf(() => api.checkMeshTableAnswer(mesh, 'faces', null)), 'invalid-answer');
  assert.equal(codeOf(() => api.checkMeshTableAnswer(mesh, 'faces', { faces: [[0, 1, 2], [1, 3, 2]] })), 'invalid-answer');
  let err;
  try {
    api.checkMeshTableAnswer(mesh, 'faces', { faces: [[0, 1, 2], [1, 'v4', 2], [1, 4, 3]] });
  } catch (e) {
    err = e;
  }
  assert.equal(err.code, 'invalid-answer');
  assert.match(err.message, /faces: face F2, item 2 must be a whole number/);
  try {
    api.checkMeshTableAnswer(foleyMesh, 'edge-list', { edges: [0, 1, 0, -7], polygons: [[], []] });
  } catch (e) {
    err = e;
  }
  assert.equal(err.code, 'invalid-answer');
  assert.match(err.message, /row e1, p2 holds -7/);
  assert.equal(codeOf(() => api.checkMeshTableAnswer(mesh, 'adjacency', { vertexVertices: [[1]] })), 'invalid-answer');
  assert.equal(codeOf(() => api.checkMeshTableAnswer(mesh, 'winged-edge', { edges: [0.5], vertexEdges: [], faceEdges: [] })), 'invalid-answer');
});

test('walk: the slide\'s CCW walk around v2 (e6, e5, e3, e2, back to e6), every step, every edge', () => {
  const walk = [5, 4, 2, 1, 5]; // read off the slide's table: v2 is the Start of e6, e5, e3 (S:L), the End of e2 (E:R)
  for (let k = 1; k <= 4; k += 1) {
    for (let g = -2; g <= 7; g += 1) {
      const r = api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: k, given: g });
      assert.equal(r.correct, g === walk[k]);
      assert.equal(r.expected, walk[k]);
      assert.equal(r.done, k === 4);
    }
  }
  assert.equal(api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: 1, given: 4 }).reason,
    'e5: v2 is the Start of e6, so the CCW walk around v2 reads its S:L column, e5');
  assert.equal(api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: 4, given: 3 }).reason,
    'not e4: v2 is the End of e2, so the CCW walk around v2 reads its E:R column, which is e6; that is the first edge again, so the walk is closed');
  // Along F2 from its table's edge e3: S:R of e3 is e5 (F2 on its Right), E:L of e5 is e4, then back to e3.
  const face = [2, 4, 3, 2];
  for (let k = 1; k <= 3; k += 1) assert.equal(api.checkWalkStep(lecture, { around: 'face', element: 1, step: k, given: face[k] }).correct, true);
});

test('walk: the same answers as mesh.traversalSteps on a built grid, and the errors', () => {
  const grid = api.generateMesh('grid', { nx: 3, ny: 2 });
  const built = api.buildMesh(grid);
  try {
    const m = { faces: grid.faces, vertexCount: grid.positions.length / 3 };
    for (let v = 0; v < m.vertexCount; v += 1) {
      const steps = built.traversalSteps(v);
      steps.forEach((s, k) => {
        const r = api.checkWalkStep(m, { around: 'vertex', element: v, step: k + 1, given: s.next });
        assert.equal(r.correct, true);
        assert.equal(r.done, k === steps.length - 1);
        assert.equal(s.next, steps[(k + 1) % steps.length].edge);
      });
    }
  } finally {
    built.dispose();
  }
  const q = (o) => codeOf(() => api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: 1, given: 0, ...o }));
  assert.equal(q({ element: 5 }), 'index-out-of-range');
  assert.equal(q({ around: 'face', element: 3 }), 'index-out-of-range');
  assert.equal(q({ step: 0 }), 'invalid-step');
  assert.equal(q({ step: 5 }), 'invalid-step');
  assert.equal(q({ around: 'edge' }), 'invalid-argument');
  assert.equal(q({ given: 1.5 }), 'invalid-argument');
  assert.equal(codeOf(() => api.checkWalkStep({ faces: [[0, 1, 2]], vertexCount: 4 }, { around: 'vertex', element: 3, step: 1, given: 0 })), 'no-walk');
});
