// The half-edge view through the JS API: the lecture mesh's rows worked out by hand from the
// slide (the same working as tests/native/mesh/test_half_edge.cpp), after flip e3 and after
// its undo; the flat windowed form against the row form; walks, queries, storage, errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline, WingsplineError } from 'wingspline';
import { withValidMesh } from '../../helpers/wasm-mesh.mjs';

const api = await loadWingspline();

// Every mesh built here is validated first and disposed after (tests/helpers/wasm-mesh.mjs).
const withMesh = (input, body) => withValidMesh(api, input, body);

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

// ---------------------------------------------------------------- an edit in half-edge terms

// The half-edge tables as plain arrays (one per field), to replay a record on.
function tablesOf(mesh) {
  const a = mesh.halfEdgeArrays();
  return {
    halfedge: { origin: Array.from(a.origin), face: Array.from(a.face), next: Array.from(a.next), prev: Array.from(a.prev) },
    vertex: { halfedge: Array.from(a.vertexHalfedge) },
    face: { halfedge: Array.from(a.faceHalfedge) },
  };
}

// Replays `steps` on `before`: each entry's before is what its cell holds then and its after
// differs; rows the edit added start at -1; rows beyond `after`'s (an undo's) are dropped.
function replay(before, after, steps) {
  const t = structuredClone(before);
  for (const [table, fields] of Object.entries(after)) {
    for (const [field, column] of Object.entries(fields)) while (t[table][field].length < column.length) t[table][field].push(-1);
  }
  for (const s of steps) {
    assert.equal(t[s.table][s.field][s.row], s.before, `${s.table} ${s.row} ${s.field}: before`);
    assert.notEqual(s.after, s.before);
    t[s.table][s.field][s.row] = s.after;
  }
  for (const [table, fields] of Object.entries(after)) for (const [field, column] of Object.entries(fields)) t[table][field].length = column.length;
  return t;
}

// Flip e3 of the lecture mesh: LECTURE against FLIPPED above, entry by entry (table row field
// before after, 1-based): e3's two halves turn round, e1's E -> S moves to F2, e5's S -> E to
// F1, and the next/prev around F1 and F2 follow; F1 now stores e3, whose S -> E is on it.
const FLIP_E3 = [
  'halfedge h2 face F1 F2', 'halfedge h2 next h3 h6', 'halfedge h2 prev h5 h8',
  'halfedge h3 next h5 h9', 'halfedge h3 prev h2 h5',
  'halfedge h5 origin v2 v4', 'halfedge h5 next h2 h3', 'halfedge h5 prev h3 h9',
  'halfedge h6 origin v3 v1', 'halfedge h6 next h9 h8', 'halfedge h6 prev h8 h2',
  'halfedge h8 next h6 h2', 'halfedge h8 prev h9 h6',
  'halfedge h9 face F2 F1', 'halfedge h9 next h8 h5', 'halfedge h9 prev h6 h3',
  'face F1 halfedge h2 h5',
];

test('apply(op, {halfEdge: true}): flip e3 of the lecture mesh in half-edge terms, worked out by hand', () => {
  withMesh(api.lectureExample(), (mesh) => {
    const change = mesh.apply({ op: 'flip-edge', e: 2 }, { halfEdge: true });
    const { steps, written } = change.halfEdge;
    const key = (s) => `${s.table} ${s.row} ${s.field}`;
    const byHand = FLIP_E3.map((line) => {
      const [table, row, field, before, after] = line.split(' ');
      return { table, row: label(row), field, before: label(before), after: label(after) };
    });
    assert.deepEqual(steps.map((s) => ({ table: s.table, row: s.row, field: s.field, before: s.before, after: s.after })).sort((a, b) => key(a).localeCompare(key(b))),
      byHand.sort((a, b) => key(a).localeCompare(key(b))));
    assert.equal(written['half-edge'], 17);
    assert.equal(written['winged-edge'], change.steps.filter((s) => s.field !== 'firstCorner').length);
    // Each entry follows the winged-edge step that first names its element, in the steps' order.
    let last = 0;
    for (const s of steps) {
      if (s.step < 0) { assert.equal(s.phase, -1); continue; }
      assert.ok(s.step >= last);
      last = s.step;
      const named = change.steps[s.step];
      assert.equal(named.table, s.table === 'halfedge' ? 'edge' : s.table);
      assert.equal(named.row, s.table === 'halfedge' ? s.row >> 1 : s.row);
      assert.equal(s.phase, named.phase);
    }
    // The rows of one half-edge come together, origin before face before next before prev.
    const order = ['origin', 'face', 'next', 'prev', 'halfedge'];
    steps.forEach((s, i) => {
      const p = steps[i - 1];
      if (p && p.table === s.table && p.row === s.row) assert.ok(order.indexOf(p.field) < order.indexOf(s.field));
    });
    assert.deepEqual(mesh.lastHalfEdgeChange(change), change.halfEdge);
  });
});

test('every operation, replayed in half-edge terms on the view before, gives the view after', () => {
  const operations = [
    () => ({ op: 'flip-edge', e: 7 }), () => ({ op: 'split-edge', e: 9, t: 0.25 }), () => ({ op: 'join-faces', e: 12 }),
    () => ({ op: 'collapse-edge', e: 20 }), () => ({ op: 'poke-face', f: 5 }),
    (m) => { const c = m.adjacency('vertices-of-face', 3); return { op: 'split-face', f: 3, a: c[0], b: c[2] }; },
    (m) => { const n = m.adjacency('vertices-around-vertex', 8); return { op: 'split-vertex', v: 8, a: n[0], b: n[2] }; },
  ];
  // split-face needs a face with two corners not joined by a side: the cube's quads.
  for (const [i, make] of operations.entries()) {
    withMesh(i === 5 ? api.generateMesh('cube') : api.generateMesh('grid', { nx: 4, ny: 4 }), (mesh) => {
      const before = tablesOf(mesh);
      const operation = make(mesh);
      assert.ok(mesh.check(operation).ok, `${operation.op} applies`);
      const change = mesh.apply(operation, { halfEdge: true });
      assert.ok(change.halfEdge.steps.length > 0, operation.op);
      const after = tablesOf(mesh);
      assert.deepEqual(replay(before, after, change.halfEdge.steps), after, operation.op);
      assert.equal(change.halfEdge.written['half-edge'], change.halfEdge.steps.length);
      // Taken back: the undo's own record leads back to the view before.
      mesh.undo();
      assert.deepEqual(replay(after, tablesOf(mesh), mesh.lastHalfEdgeChange().steps), before, `undo ${operation.op}`);
    });
  }
});

test('lastHalfEdgeChange(): null when the view was not kept at the edit', () => {
  withMesh(api.lectureExample(), (mesh) => {
    const change = mesh.apply({ op: 'flip-edge', e: 2 });
    assert.equal(change.halfEdge, undefined);
    assert.equal(mesh.lastHalfEdgeChange(change), null);
    mesh.halfEdge(); // kept from now on: the next edit is followed
    const next = mesh.apply({ op: 'flip-edge', e: 2 });
    assert.ok(mesh.lastHalfEdgeChange(next).steps.length > 0);
  });
});
