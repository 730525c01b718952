// The half-edge view through the JS API: the lecture mesh's rows worked out by hand from the
// slide (the same working as tests/native/mesh/test_half_edge.cpp), after flip e3 and after
// its undo; the flat windowed form against the row form; walks, queries, storage, errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline, WingsplineError } from 'wingspline';

const api = await loadWingspline();

function withMesh(input, body) {
  const mesh = api.buildMesh(input);
  try {
    return body(mesh);
  } finally {
    mesh.dispose();
  }
}

// 'h3' -> 2, 'v2' -> 1, 'F1' -> 0, '-' -> -1: the slides' 1-based labels.
const label = (s) => (s === '-' ? -1 : Number(s.slice(1)) - 1);

// h: origin target face next prev, from the slide (lecture 000):
//   e  S  E  L  R  SL SR EL ER        e_k gives h(2k-1) = S -> E (face L), h(2k) = E -> S (face R);
//   e1 v1 v3 -  F1 e2 e2 e4 e3        next(S -> E) = EL's half-edge leaving E, prev(S -> E) = SL's
//   e2 v1 v2 F1 -  e1 e1 e3 e6        arriving at S; next(E -> S) = SR's leaving S, prev(E -> S) =
//   e3 v2 v3 F1 F2 e2 e5 e1 e4        ER's arriving at E.
//   e4 v3 v4 -  F2 e1 e3 e7 e5
//   e5 v2 v4 F2 F3 e3 e6 e4 e7
//   e6 v2 v5 F3 -  e5 e2 e7 e7
//   e7 v4 v5 -  F3 e4 e5 e6 e6
const LECTURE = [
  'h1 v1 v3 - h7 h4', 'h2 v3 v1 F1 h3 h5', 'h3 v1 v2 F1 h5 h2', 'h4 v2 v1 - h1 h12',
  'h5 v2 v3 F1 h2 h3', 'h6 v3 v2 F2 h9 h8', 'h7 v3 v4 - h13 h1', 'h8 v4 v3 F2 h6 h9',
  'h9 v2 v4 F2 h8 h6', 'h10 v4 v2 F3 h11 h14', 'h11 v2 v5 F3 h14 h10', 'h12 v5 v2 - h4 h13',
  'h13 v4 v5 - h12 h7', 'h14 v5 v4 F3 h10 h11',
];
// Every vertex is on the boundary: its outgoing boundary half-edge. F1 stores e1 (F1 is its R):
// h2; F2 stores e3 (R): h6; F3 stores e5 (R): h10.
const LECTURE_VERTICES = ['h1', 'h4', 'h7', 'h13', 'h12'];
const LECTURE_FACES = ['h2', 'h6', 'h10'];
// After flip e3 (e3 = v4 -> v1, F1 = (v1 v2 v4) on its left, F2 = (v4 v3 v1) on its right; the
// winged-edge rows after it as tests/native/mesh/test_exercise_edit.cpp works them out by hand:
// e1 v1 v3 - F2 e2 e3 e4 e4; e2 v1 v2 F1 - e3 e1 e5 e6; e3 v4 v1 F1 F2 e5 e4 e2 e1;
// e4 v3 v4 - F2 e1 e1 e7 e3; e5 v2 v4 F1 F3 e2 e6 e3 e7; e6, e7 unchanged; F1 stores e3).
const FLIPPED = [
  'h1 v1 v3 - h7 h4', 'h2 v3 v1 F2 h6 h8', 'h3 v1 v2 F1 h9 h5', 'h4 v2 v1 - h1 h12',
  'h5 v4 v1 F1 h3 h9', 'h6 v1 v4 F2 h8 h2', 'h7 v3 v4 - h13 h1', 'h8 v4 v3 F2 h2 h6',
  'h9 v2 v4 F1 h5 h3', 'h10 v4 v2 F3 h11 h14', 'h11 v2 v5 F3 h14 h10', 'h12 v5 v2 - h4 h13',
  'h13 v4 v5 - h12 h7', 'h14 v5 v4 F3 h10 h11',
];
const FLIPPED_FACES = ['h5', 'h6', 'h10'];

// The half-edge rules checked here from the rows alone: next and prev inverse,
// origin(next(h)) = target(h), face(next(h)) = face(h); a gap's row is -1 throughout.
function assertHalfEdgeRules({ halfedges }) {
  halfedges.forEach((row, h) => {
    if (row.origin === -1) return assert.deepEqual(Object.values(row), [-1, -1, -1, -1, -1, -1], `h${h + 1} is a gap`);
    assert.equal(halfedges[row.next].prev, h, `prev(next(h${h + 1}))`);
    assert.equal(halfedges[row.next].origin, row.target, `origin(next(h${h + 1}))`);
    assert.equal(halfedges[row.next].face, row.face, `face(next(h${h + 1}))`);
    assert.equal(halfedges[row.twin].twin, h);
  });
}

function expected(rows, vertices, faces) {
  return {
    halfedges: rows.map((row) => {
      const [h, origin, target, face, next, prev] = row.split(' ').map(label);
      return { origin, target, face, next, prev, twin: h % 2 === 0 ? h + 1 : h - 1 };
    }),
    vertices: vertices.map((h) => ({ halfedge: label(h) })),
    faces: faces.map((h) => ({ halfedge: label(h) })),
  };
}

test('halfEdge() of the lecture mesh: the rows worked out by hand, after flip e3 and after its undo', () => {
  withMesh(api.lectureExample(), (mesh) => {
    assert.deepEqual(mesh.halfEdge(), expected(LECTURE, LECTURE_VERTICES, LECTURE_FACES));
    assertHalfEdgeRules(mesh.halfEdge());
    mesh.apply({ op: 'flip-edge', e: 2 });
    assert.deepEqual(mesh.halfEdge(), expected(FLIPPED, LECTURE_VERTICES, FLIPPED_FACES));
    assertHalfEdgeRules(mesh.halfEdge());
    mesh.undo();
    assert.deepEqual(mesh.halfEdge(), expected(LECTURE, LECTURE_VERTICES, LECTURE_FACES));
  });
});

test('a gap left by join-faces is -1 in every field until compact()', () => {
  withMesh(api.lectureExample(), (mesh) => {
    mesh.halfEdge(); // made before the edit, so the edit updates it
    const change = mesh.apply({ op: 'join-faces', e: 2 });
    const view = mesh.halfEdge();
    for (const h of [4, 5]) assert.deepEqual(view.halfedges[h], { origin: -1, target: -1, face: -1, next: -1, prev: -1, twin: -1 });
    assert.equal(view.faces[change.removed.faces[0]].halfedge, -1);
    assertHalfEdgeRules(view);
    mesh.compact();
    assert.equal(mesh.halfEdge().halfedges.length, 12);
    assertHalfEdgeRules(mesh.halfEdge());
  });
});

test('halfEdgeArrays(): the row form as Int32Arrays, whole and in windows', () => {
  withMesh(api.generateMesh('grid', { nx: 5, ny: 4 }), (mesh) => {
    const e = Array.from({ length: mesh.counts().edges }, (_, i) => i).find((i) => mesh.check({ op: 'flip-edge', e: i }).ok);
    mesh.apply({ op: 'flip-edge', e });
    const rows = mesh.halfEdge();
    const all = mesh.halfEdgeArrays();
    assert.equal(all.halfedges, rows.halfedges.length);
    assert.equal(all.vertices, rows.vertices.length);
    assert.equal(all.faces, rows.faces.length);
    for (const key of ['origin', 'face', 'next', 'prev', 'vertexHalfedge', 'faceHalfedge']) assert.ok(all[key] instanceof Int32Array, key);
    rows.halfedges.forEach((row, h) => {
      assert.deepEqual([all.origin[h], all.origin[h ^ 1], all.face[h], all.next[h], all.prev[h], h ^ 1],
        [row.origin, row.target, row.face, row.next, row.prev, row.twin], `h${h + 1}`);
    });
    assert.deepEqual(Array.from(all.vertexHalfedge), rows.vertices.map((v) => v.halfedge));
    assert.deepEqual(Array.from(all.faceHalfedge), rows.faces.map((f) => f.halfedge));
    const w = mesh.halfEdgeArrays({ offset: 10, limit: 7 });
    assert.equal(w.offset, 10);
    assert.deepEqual(Array.from(w.next), Array.from(all.next.subarray(10, 17)));
    assert.deepEqual(Array.from(w.vertexHalfedge), Array.from(all.vertexHalfedge.subarray(10, 17)));
    assert.deepEqual(Array.from(w.faceHalfedge), Array.from(all.faceHalfedge.subarray(10, 17)));
    const end = mesh.halfEdgeArrays({ offset: all.halfedges - 2, limit: 100 });
    assert.equal(end.origin.length, 2);
    assert.throws(() => mesh.halfEdgeArrays({ offset: -1 }), (e) => e instanceof WingsplineError && e.code === 'invalid-argument');
  });
});

test('the half-edge walks: CCW around v2 from h4, and from e6 the winged-edge walk\'s order', () => {
  withMesh(api.lectureExample(), (mesh) => {
    // h4 (v2 -> v1, boundary): prev h12, twin h11; prev h10, twin h9; prev h6, twin h5; prev h3, twin h4.
    assert.deepEqual(mesh.halfEdgeTraversalSteps(1).map((s) => [s.halfedge + 1, s.column, s.read + 1, s.next + 1]),
      [[4, 'prev', 12, 11], [11, 'prev', 10, 9], [9, 'prev', 6, 5], [5, 'prev', 3, 4]]);
    const wing = mesh.traversalSteps(1).map((s) => s.edge);
    assert.deepEqual(mesh.halfEdgeTraversalSteps(1, { start: 10 }).map((s) => s.halfedge >> 1), wing);
    assert.deepEqual(mesh.halfEdgeFaceSteps(1).map((s) => [s.halfedge + 1, s.column, s.next + 1]), [[6, 'next', 9], [9, 'next', 8], [8, 'next', 6]]);
    assert.deepEqual(mesh.halfEdgeFaceSteps(1).map((s) => s.halfedge >> 1), mesh.faceEdgeSteps(1).map((s) => s.edge));
    assert.throws(() => mesh.halfEdgeTraversalSteps(1, { start: 0 }), (e) => e instanceof WingsplineError && e.code === 'invalid-argument');
    assert.throws(() => mesh.halfEdgeFaceSteps(3), (e) => e instanceof WingsplineError && e.code === 'invalid-element');
  });
});

test('halfEdgeQuery answers as the six representations do; storage and errors', () => {
  withMesh(api.lectureExample(), (mesh) => {
    const sorted = (a) => Array.from(a).sort((x, y) => x - y);
    for (const [kind, n] of [['faces-around-vertex', 5], ['edges-around-vertex', 5], ['edges-of-face', 3], ['neighbours-of-face', 3], ['faces-of-edge', 7]]) {
      for (let x = 0; x < n; x += 1) {
        const half = mesh.halfEdgeQuery(kind, x);
        const all = mesh.query(kind, x);
        for (const [rep, a] of Object.entries(all)) assert.deepEqual(sorted(half.answer), sorted(a.answer), `${kind} ${x} ${rep}`);
        assert.ok(half.entriesRead > 0);
      }
    }
    // Edges of F2: its half-edge, then one next per side.
    assert.deepEqual(mesh.halfEdgeQuery('edges-of-face', 1), { answer: Int32Array.from([2, 4, 3]), entriesRead: 4 });
    const s = mesh.halfEdgeStorage();
    // 5 vertices x 3 doubles, 14 half-edges x 4 int32, 5 + 3 int32.
    assert.equal(s.bytes, 5 * 3 * 8 + (14 * 4 + 5 + 3) * 4);
    assert.equal(s.bytes, mesh.storage()['winged-edge'].bytes, 'the same bytes as the winged edge');
    assert.deepEqual(s.arrays.map((a) => a.name), ['vertex coordinates', 'half-edge origin', 'half-edge face', 'half-edge next', 'half-edge prev', 'vertex half-edge', 'face half-edge']);
    assert.throws(() => mesh.halfEdgeQuery('nearest', 0), (e) => e instanceof WingsplineError && e.code === 'unknown-query');
  });
});

test('the subdivision part has no half-edge view: part-not-loaded', async () => {
  const subdivision = await loadWingspline({ parts: ['subdivision'] });
  const mesh = subdivision.buildMesh(subdivision.lectureExample());
  try {
    assert.throws(() => mesh.halfEdge(), (e) => e instanceof WingsplineError && e.code === 'part-not-loaded');
  } finally {
    mesh.dispose();
  }
});

// The cost chart's half-edge line: at the middle vertex of the triangulated grid (valence 6)
// the half-edge reads the vertex's half-edge, then per step face(h) and prev(h): 1 + 2 x 6 = 13
// at every size; the winged edge also tests which side it is on: 1 + 3 x 6 = 19.
test('queryCostGrowth: the half-edge reads stay flat from a thousand to a million faces', () => {
  const { sizes, reads } = api.queryCostGrowth('faces-around-vertex', [22, 708]);
  assert.deepEqual(sizes.map((s) => s.faces), [968, 1002528]);
  assert.deepEqual(reads.map((r) => r['half-edge']), [13, 13]);
  assert.deepEqual(reads.map((r) => r['winged-edge']), [19, 19]);
  // Edges of a triangle: the face's half-edge, then three nexts.
  assert.deepEqual(api.queryCostGrowth('edges-of-face', [22]).reads[0]['half-edge'], 4);
});
