// The half-edge exercises over the real module: api.checkMeshTableAnswer(mesh, 'half-edge')
// and api.checkWalkStep with structure 'half-edge'. Lecture 000's half-edge table is written
// here by hand (edge e_k gives h(2k-1) = S -> E and h(2k) = E -> S; the boundary loop
// v1 -> v3 -> v4 -> v5 -> v2 -> v1 is h1, h7, h13, h12, h4); renumbered answers are made from it
// here, and the expected value of a changed cell is the one the cell held.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();
const lecture = api.lectureExample();
const mesh = { faces: lecture.faces, vertexCount: lecture.positions.length / 3 };

// Rows h1..h14: origin, face (0 = none), next, prev, twin; 1-based as the page writes them.
const TABLE = [
  [1, 0, 7, 4, 2], [3, 1, 3, 5, 1], [1, 1, 5, 2, 4], [2, 0, 1, 12, 3], [2, 1, 2, 3, 6],
  [3, 2, 9, 8, 5], [3, 0, 13, 1, 8], [4, 2, 6, 9, 7], [2, 2, 8, 6, 10], [4, 3, 11, 14, 9],
  [2, 3, 14, 10, 12], [5, 0, 4, 13, 11], [4, 0, 12, 7, 14], [5, 3, 10, 11, 13],
];
const slideAnswer = () => ({
  halfedges: TABLE.flat().map((x) => x - 1),
  vertexHalfedges: [0, 3, 6, 12, 11], // h1 h4 h7 h13 h12: each vertex's boundary half-edge
  faceHalfedges: [1, 5, 9], // h2 h6 h10
});

// The same table with its rows in another order: row r of the new table is the slide's perm[r].
function renumbered(answer, perm) {
  const rowOf = new Map(perm.map((old, r) => [old, r]));
  const halfedges = [];
  for (const old of perm) {
    const [o, f, n, p, t] = answer.halfedges.slice(5 * old, 5 * old + 5);
    halfedges.push(o, f, rowOf.get(n), rowOf.get(p), rowOf.get(t));
  }
  return { halfedges, vertexHalfedges: answer.vertexHalfedges.map((x) => rowOf.get(x)), faceHalfedges: answer.faceHalfedges.map((x) => rowOf.get(x)) };
}

test('half-edge table: the slide\'s mesh by hand is right; so is any renumbering', () => {
  const r = api.checkMeshTableAnswer(mesh, 'half-edge', slideAnswer());
  assert.equal(r.correct, true, JSON.stringify(r.findings[0]));
  assert.deepEqual(r.worked.halfedges, slideAnswer().halfedges);
  const rand = random(31);
  for (let trial = 0; trial < 300; trial += 1) {
    const perm = [...Array(14).keys()];
    for (let i = 13; i > 0; i -= 1) { const j = Math.floor(rand() * (i + 1)); [perm[i], perm[j]] = [perm[j], perm[i]]; }
    const answer = renumbered(slideAnswer(), perm);
    assert.equal(api.checkMeshTableAnswer(mesh, 'half-edge', answer).correct, true);
    // One pointer changed: one finding, on that row and column, expecting what it held.
    const row = Math.floor(rand() * 14);
    const k = 2 + Math.floor(rand() * 3);
    const bad = structuredClone(answer);
    bad.halfedges[5 * row + k] = (answer.halfedges[5 * row + k] + 1 + Math.floor(rand() * 13)) % 14;
    const c = api.checkMeshTableAnswer(mesh, 'half-edge', bad);
    assert.equal(c.findings.length, 1, JSON.stringify(c.findings));
    const [f] = c.findings;
    assert.deepEqual([f.table, f.row, f.field, f.expected], ['halfedge', row, ['next', 'prev', 'twin'][k - 2], answer.halfedges[5 * row + k]]);
    // Its message names no half-edge but its own row.
    assert.deepEqual([...new Set(f.message.match(/\bh\d+\b/g))], [`h${row + 1}`]);
  }
});

test('half-edge table: the words of a finding, and the small tables', () => {
  const a = slideAnswer();
  a.halfedges[5 * 4 + 2] = 5; // row h5 (v2 -> v3 on F1), next: h6 instead of h2
  const [f] = api.checkMeshTableAnswer(mesh, 'half-edge', a).findings;
  assert.equal(f.code, 'wrong-next');
  assert.equal(f.message, 'Row h5, column next: this is not next(h5). Re-read: next(h) must start where h ends (v3), and lie on the same face (F1): the next side counter-clockwise round that face, the boundary loop counting as a face.');
  assert.match(f.reason, /h2/);
  assert.ok(f.hint.length > 0 && !/\bh\d/.test(f.hint.replace('h5', '')));

  const b = slideAnswer();
  b.vertexHalfedges[1] = 8; // v2 stores h9 (v2 -> v4 on F2): leaves v2, but v2 is on the boundary
  b.faceHalfedges[2] = 0; // F3 stores h1: not on F3
  const c = api.checkMeshTableAnswer(mesh, 'half-edge', b);
  assert.deepEqual(c.findings.map((x) => [x.table, x.row, x.field, x.code]), [['vertex', 1, 'halfedge', 'not-boundary'], ['face', 2, 'halfedge', 'not-on-face']]);
  assert.equal(c.worked.vertexHalfedges[1], 3); // h4, v2's boundary half-edge
});

test('half-edge table: the shape is checked', () => {
  const a = slideAnswer();
  a.halfedges.pop();
  assert.throws(() => api.checkMeshTableAnswer(mesh, 'half-edge', a), { code: 'invalid-answer' });
  assert.throws(() => api.checkMeshTableAnswer(mesh, 'half-edge', { ...slideAnswer(), faceHalfedges: [0.5, 1, 2] }), { code: 'invalid-answer' });
});

test('half-edge walk: around v2 from h4: h11, h9, h5, back to h4; along F2 from h6: h9, h8, h6', () => {
  const around = [10, 8, 4, 3];
  for (let k = 1; k <= 4; k += 1) {
    const r = api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: k, given: around[k - 1], structure: 'half-edge' });
    assert.equal(r.correct, true);
    assert.equal(r.from, k === 1 ? 3 : around[k - 2]);
    assert.equal(r.done, k === 4);
  }
  const wrong = api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: 1, given: 11, structure: 'half-edge' });
  assert.equal(wrong.correct, false);
  assert.equal(wrong.reason, 'not h12: the CCW walk around v2 goes from h4 to twin(prev(h4)): prev(h4) is h12, and its twin is h11');
  assert.match(wrong.message, /^Step 1, from h4: that is not the half-edge the walk reaches next\. Re-read the rule: around a vertex counter-clockwise, h -> twin\(prev\(h\)\)/);
  assert.doesNotMatch(wrong.message + wrong.hint, /h11|h12/);
  const along = [8, 7, 5];
  for (let k = 1; k <= 3; k += 1) assert.equal(api.checkWalkStep(lecture, { around: 'face', element: 1, step: k, given: along[k - 1], structure: 'half-edge' }).correct, true);
  assert.throws(() => api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: 1, given: 0, structure: 'quad-edge' }), { code: 'invalid-argument' });
  assert.throws(() => api.checkWalkStep(lecture, { around: 'vertex', element: 1, step: 5, given: 0, structure: 'half-edge' }), { code: 'invalid-step' });
});
