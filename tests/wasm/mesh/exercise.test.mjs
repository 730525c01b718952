// Exercise kind 1 over the real module: a student's winged-edge table for lecture
// 000's mesh, checked by api.checkWingedEdgeAnswer. The slide's table is written here as the
// slide prints it; renumbered and flipped copies are made here (a correct table in another
// numbering), and the expected value of a corrupted cell is the slide's own
// (tests/helpers/lecture-slide.mjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';
import { SLIDE_EDGE_TABLE } from '../../helpers/lecture-slide.mjs';

const api = await loadWingspline();

const FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
const HEADS = ['S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R'];

const number = (s) => (s === '-' ? -1 : Number(s.slice(1)) - 1);
function slideAnswer() {
  return {
    edges: SLIDE_EDGE_TABLE.flatMap((row) => row.split(/\s+/).slice(1).map(number)),
    vertexEdges: ['e1', 'e6', 'e3', 'e5', 'e6'].map(number),
    faceEdges: ['e1', 'e3', 'e5'].map(number),
  };
}
const lecture = api.lectureExample();
const mesh = { faces: lecture.faces, vertexCount: lecture.positions.length / 3 };

// Walking a row's edge the other way swaps S/E, L/R, S:L with E:R and S:R with E:L.
function flipRow(answer, r) {
  const c = answer.edges.slice(8 * r, 8 * r + 8);
  answer.edges.splice(8 * r, 8, c[1], c[0], c[3], c[2], c[7], c[6], c[5], c[4]);
}
function renumber(answer, to) {
  const ref = (e) => (e < 0 ? e : to[e]);
  const edges = new Array(answer.edges.length);
  to.forEach((r, e) => {
    for (let k = 0; k < 8; k += 1) edges[8 * r + k] = k < 4 ? answer.edges[8 * e + k] : ref(answer.edges[8 * e + k]);
  });
  return { edges, vertexEdges: answer.vertexEdges.map(ref), faceEdges: answer.faceEdges.map(ref) };
}

test('the slide\'s table is accepted; renumbered with e5 flipped, and with any one edge flipped, too', () => {
  assert.deepEqual(api.checkWingedEdgeAnswer(mesh, slideAnswer()).findings, []);
  const moved = renumber(slideAnswer(), [3, 6, 0, 1, 5, 2, 4]);
  flipRow(moved, 5); // the slide's e5 is row e6 now
  const r = api.checkWingedEdgeAnswer(mesh, moved);
  assert.equal(r.correct, true, JSON.stringify(r.findings));
  for (let e = 0; e < 7; e += 1) {
    const a = slideAnswer();
    flipRow(a, e);
    assert.deepEqual(api.checkWingedEdgeAnswer(mesh, a).findings, [], `e${e + 1} flipped`);
  }
});

test('row e5 with S:L = e2: one finding naming the row, the column, e3 and why', () => {
  const a = slideAnswer();
  a.edges[8 * 4 + 4] = 1;
  const { correct, findings } = api.checkWingedEdgeAnswer(mesh, a);
  assert.equal(correct, false);
  assert.equal(findings.length, 1);
  const [f] = findings;
  assert.deepEqual({ table: f.table, row: f.row, field: f.field, given: f.given, expected: f.expected, code: f.code },
    { table: 'edge', row: 4, field: 'startLeft', given: 1, expected: 2, code: 'wrong-wing' });
  assert.match(f.reason, /^row e5: the left wing at the Start \(S:L\) is e3, not e2: /);
  assert.match(f.reason, /counter-clockwise around v2/);
});

test('random renumberings and flips of the slide are accepted; one wrong cell is named with the slide\'s value', () => {
  const rnd = random(1919);
  for (let trial = 0; trial < 600; trial += 1) {
    const to = [0, 1, 2, 3, 4, 5, 6];
    for (let i = 6; i > 0; i -= 1) {
      const j = Math.floor(rnd() * (i + 1));
      [to[i], to[j]] = [to[j], to[i]];
    }
    const right = renumber(slideAnswer(), to);
    for (let r = 0; r < 7; r += 1) if (rnd() < 0.5) flipRow(right, r);
    assert.equal(api.checkWingedEdgeAnswer(mesh, right).correct, true, `trial ${trial}`);
    // One cell of L, R or a wing changed to another value (blank, none, a label past the table, another label).
    const row = Math.floor(rnd() * 7);
    const k = 2 + Math.floor(rnd() * 6);
    const range = k < 4 ? 3 : 7;
    const old = right.edges[8 * row + k];
    let value = old;
    while (value === old) value = Math.floor(rnd() * (range + 3)) - 2;
    const wrong = { ...right, edges: right.edges.slice() };
    wrong.edges[8 * row + k] = value;
    const { findings } = api.checkWingedEdgeAnswer(mesh, wrong);
    assert.equal(findings.length, 1, `trial ${trial}: ${JSON.stringify(findings)}`);
    const [f] = findings;
    assert.deepEqual([f.table, f.row, f.field, f.given, f.expected], ['edge', row, FIELDS[k], value, old]);
    assert.ok(f.reason.startsWith(`row e${row + 1}: `), f.reason);
    assert.ok(f.reason.includes(HEADS[k].length > 1 ? `(${HEADS[k]})` : `${HEADS[k]} `), f.reason);
    assert.equal(f.code, value === -2 ? 'blank' : value >= range ? 'unknown-label' : k < 4 ? 'wrong-face' : 'wrong-wing');
    // The worked answer is the table as it was.
    assert.deepEqual(Array.from(api.workedWingedEdgeAnswer(mesh, wrong).edges), right.edges);
  }
});

test('the worked answer fills blank cells in the student\'s numbering', () => {
  const a = slideAnswer();
  for (const i of [2, 12, 20, 30, 47]) a.edges[i] = api.answerCells.blank;
  a.vertexEdges[3] = -2;
  const { findings } = api.checkWingedEdgeAnswer(mesh, a);
  assert.deepEqual(findings.map((f) => f.code), ['blank', 'blank', 'blank', 'blank', 'blank', 'blank']);
  const worked = api.workedWingedEdgeAnswer(mesh, a);
  assert.deepEqual(Array.from(worked.edges), slideAnswer().edges);
  assert.ok([2, 3, 4].includes(worked.vertexEdges[3]), 'an edge at v4: e3, e4 or e5');
  assert.deepEqual(Array.from(worked.faceEdges), slideAnswer().faceEdges);
});

test('malformed answers and meshes are errors with stable codes', () => {
  const code = (m, a) => {
    try {
      api.checkWingedEdgeAnswer(m, a);
    } catch (err) {
      return err.code;
    }
    return 'accepted';
  };
  const a = slideAnswer();
  assert.equal(code(mesh, { ...a, edges: a.edges.slice(0, -1) }), 'invalid-answer');
  assert.equal(code(mesh, { ...a, vertexEdges: a.vertexEdges.slice(1) }), 'invalid-answer');
  assert.equal(code(mesh, { ...a, edges: a.edges.map((x, i) => (i === 9 ? -7 : x)) }), 'invalid-answer');
  assert.equal(code(mesh, { ...a, edges: a.edges.map((x, i) => (i === 9 ? 'v2' : x)) }), 'invalid-argument');
  assert.equal(code(mesh, { ...a, faceEdges: undefined }), 'invalid-argument');
  assert.equal(code({ faces: mesh.faces }, a), 'invalid-argument');
  assert.equal(code({ faces: [[0, 1, 2], [1, 3, 9], [1, 4, 3]], vertexCount: 5 }, a), 'index-out-of-range');
  assert.equal(code({ faceOffsets: new Int32Array([0, 3, 2]), faceVertices: new Int32Array([0, 1, 2]), vertexCount: 5 }, a), 'invalid-faces');
  assert.equal(code(mesh, null), 'invalid-argument');
});

test('checking leaks no wasm memory', () => {
  const a = slideAnswer();
  a.edges[5] = 0;
  for (let i = 0; i < 50; i += 1) api.checkWingedEdgeAnswer(mesh, a);
  const before = api.memoryUsage().heapInUse;
  for (let i = 0; i < 2000; i += 1) {
    api.checkWingedEdgeAnswer(mesh, a);
    api.workedWingedEdgeAnswer(mesh, a);
  }
  assert.equal(api.memoryUsage().heapInUse, before);
});

test('S and E written the other way round in row e3, all else right: one finding, swapped-ends', () => {
  const a = slideAnswer();
  [a.edges[16], a.edges[17]] = [a.edges[17], a.edges[16]];
  const { findings } = api.checkWingedEdgeAnswer(mesh, a);
  assert.deepEqual(findings.map((f) => [f.code, f.row, f.field, f.given, f.expected]), [['swapped-ends', 2, 'start', 2, 1]]);
  assert.match(findings[0].reason, /^row e3: S and E are the other way round/);
  assert.deepEqual(Array.from(api.workedWingedEdgeAnswer(mesh, a).edges), slideAnswer().edges);
});
