// The value-free feedback of the mesh exercises (feedback levels check and hint): every
// finding's message and hint name only where (the row as the grid counts it, the column) and
// the rule, never the right value. The right values come from the lecture's slide (its
// winged-edge, vertex and face tables, its walk) and from the faces themselves (a face's
// corners, a vertex's neighbours), never from the checker; thousands of seeded corruptions.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';
import { SLIDE_EDGE_TABLE, SLIDE_VERTEX_EDGES, SLIDE_FACE_EDGES, slideWalk, FOLEY_EDGE_LIST, FOLEY_POLYGONS } from '../../helpers/lecture-slide.mjs';

const api = await loadWingspline();
const lecture = api.lectureExample();
const mesh = { faces: lecture.faces, vertexCount: lecture.positions.length / 3 };
const HEADS = ['S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R'];
const number = (s) => (s === '-' ? -1 : Number(s.slice(1)) - 1);
// Every element label a text holds (v3, e5, F2; the edge list's V3, E5, P2).
const labelsIn = (text) => new Set(text.match(/\b[vVeEfFpP]\d+\b/g) ?? []);
const words = (f) => `${f.message} ${f.hint}`;

// The slide's tables as an answer, renumbered by `to` (slide edge e -> row to[e]) and with the
// rows in `flip` walked the other way: every such table is right (lecture 000's definition
// does not fix the numbering or the direction).
function slideAnswer(to, flip) {
  const rows = SLIDE_EDGE_TABLE.map((row) => row.split(/\s+/).slice(1).map(number));
  const ref = (e) => (e < 0 ? e : to[e]);
  const edges = new Array(56);
  rows.forEach((c, e) => {
    const cells = flip.has(e) ? [c[1], c[0], c[3], c[2], c[7], c[6], c[5], c[4]] : c;
    for (let k = 0; k < 8; k += 1) edges[8 * to[e] + k] = k < 4 ? cells[k] : ref(cells[k]);
  });
  return { edges, vertexEdges: SLIDE_VERTEX_EDGES.map(number).map(ref), faceEdges: SLIDE_FACE_EDGES.map(number).map(ref) };
}

function shuffled(rnd, n) {
  const to = Array.from({ length: n }, (_, i) => i);
  for (let i = n - 1; i > 0; i -= 1) {
    const j = Math.floor(rnd() * (i + 1));
    [to[i], to[j]] = [to[j], to[i]];
  }
  return to;
}

// The row label a finding's words may name (its own row), by table.
function ownRow(f, names = { vertex: 'v', edge: 'e', face: 'F' }) {
  return f.row >= 0 ? `${names[f.table]}${f.row + 1}` : null;
}

test('winged edge: 3,000 random renumberings with one to three corrupted cells; no finding\'s words hold a value (the slide\'s or any other label)', () => {
  const rnd = random(2801);
  let findings = 0;
  const codes = new Set();
  for (let trial = 0; trial < 3000; trial += 1) {
    const to = shuffled(rnd, 7);
    const flip = new Set([0, 1, 2, 3, 4, 5, 6].filter(() => rnd() < 0.5));
    const right = slideAnswer(to, flip);
    const wrong = { edges: right.edges.slice(), vertexEdges: right.vertexEdges.slice(), faceEdges: right.faceEdges.slice() };
    const corrupted = [];
    const n = 1 + Math.floor(rnd() * 3);
    for (let c = 0; c < n; c += 1) {
      const where = rnd();
      if (where < 0.06) {
        const row = Math.floor(rnd() * 7); // S and E written the other way round
        [wrong.edges[8 * row], wrong.edges[8 * row + 1]] = [wrong.edges[8 * row + 1], wrong.edges[8 * row]];
      } else if (where < 0.8) {
        const i = Math.floor(rnd() * 56);
        const k = i % 8;
        const range = k < 2 ? 5 : k < 4 ? 3 : 7;
        wrong.edges[i] = Math.floor(rnd() * (range + 3)) - 2; // blank, none, a label, one past the table
      } else if (where < 0.9) {
        const v = Math.floor(rnd() * 5);
        wrong.vertexEdges[v] = Math.floor(rnd() * 10) - 2;
      } else {
        const f = Math.floor(rnd() * 3);
        wrong.faceEdges[f] = Math.floor(rnd() * 10) - 2;
      }
    }
    for (let i = 0; i < 56; i += 1) {
      if (wrong.edges[i] !== right.edges[i]) corrupted.push({ row: Math.floor(i / 8), k: i % 8, expected: right.edges[i] });
    }
    const r = api.checkWingedEdgeAnswer(mesh, wrong);
    for (const f of r.findings) {
      findings += 1;
      codes.add(f.code);
      assert.ok(f.message.length > 20 && f.hint.length > 10, `${f.code}: ${f.message} / ${f.hint}`);
      // The only label the words may hold is the finding's own row.
      const own = ownRow(f);
      for (const l of labelsIn(words(f))) assert.equal(l, own, `trial ${trial}, ${f.code} at ${own}: "${words(f)}"`);
      if (f.table === 'edge' && f.field && f.code !== 'swapped-ends' && f.code !== 'not-an-edge' && f.code !== 'duplicate-edge') {
        assert.ok(f.message.startsWith(`Row e${f.row + 1}, column ${HEADS[['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'].indexOf(f.field)]}: `), f.message);
      }
    }
    // The slide's value of each corrupted cell (in this renumbering) is in no finding's words,
    // unless it is that finding's own row (a label the question shows anyway).
    for (const c of corrupted) {
      if (c.expected < 0) continue;
      const label = `${c.k < 2 ? 'v' : c.k < 4 ? 'F' : 'e'}${c.expected + 1}`;
      for (const f of r.findings) if (ownRow(f) !== label) assert.ok(!labelsIn(words(f)).has(label), `trial ${trial}: ${label} in "${words(f)}"`);
    }
    if (corrupted.length) assert.equal(r.correct, false, `trial ${trial}`);
  }
  assert.ok(findings > 3000, `${findings} findings`);
  for (const code of ['blank', 'unknown-label', 'not-an-edge', 'duplicate-edge', 'missing-edge', 'swapped-ends', 'wrong-face', 'wrong-wing', 'not-incident', 'not-on-face']) {
    assert.ok(codes.has(code), `the corruptions reach ${code} (seen: ${[...codes].join(', ')})`);
  }
});

test('winged edge: one wrong cell of the slide names its row and column, and never the slide\'s value (every cell, every wrong label)', () => {
  const identity = [0, 1, 2, 3, 4, 5, 6];
  let cases = 0;
  for (let i = 0; i < 56; i += 1) {
    const k = i % 8;
    const range = k < 2 ? 5 : k < 4 ? 3 : 7;
    for (let value = -2; value < range; value += 1) {
      const a = slideAnswer(identity, new Set());
      const right = a.edges[i];
      if (value === right) continue;
      a.edges[i] = value;
      const { findings } = api.checkWingedEdgeAnswer(mesh, a);
      assert.ok(findings.length >= 1);
      const label = right < 0 ? null : `${k < 2 ? 'v' : k < 4 ? 'F' : 'e'}${right + 1}`;
      for (const f of findings) {
        cases += 1;
        if (label && ownRow(f) !== label) assert.ok(!labelsIn(words(f)).has(label), `e${Math.floor(i / 8) + 1} ${HEADS[k]} = ${value}: "${words(f)}"`);
        if (right < 0) assert.doesNotMatch(words(f), /\bnone\b(?! where)(?! only)/, 'a none is not given away either');
      }
    }
  }
  assert.ok(cases > 300, `${cases}`);
});

test('faces, edge list, adjacency: 3,000 seeded corruptions; the words name only their own row', () => {
  const rnd = random(2802);
  const faces = lecture.faces.map((f) => Array.from(f));
  // The adjacency lists from the faces: consecutive corners are neighbours.
  const neighbours = Array.from({ length: mesh.vertexCount }, () => new Set());
  for (const f of faces) f.forEach((v, i) => { const w = f[(i + 1) % f.length]; neighbours[v].add(w); neighbours[w].add(v); });
  const foley = api.foleyExample();
  const foleyMesh = { faces: foley.faces, vertexCount: foley.positions.length / 3 };
  const foleyEdges = FOLEY_EDGE_LIST.flatMap((row) => row.map((x) => (x === 'λ' ? -1 : Number(x.slice(1)) - 1)));
  const foleyPolygons = FOLEY_POLYGONS.map((p) => p.map((x) => Number(x.slice(1)) - 1));
  let findings = 0;
  for (let trial = 0; trial < 3000; trial += 1) {
    const which = trial % 3;
    let r;
    let names;
    if (which === 0) {
      const answer = faces.map((f) => f.slice());
      const face = answer[Math.floor(rnd() * answer.length)];
      const i = Math.floor(rnd() * face.length);
      const old = face[i];
      const roll = rnd();
      if (roll < 0.7) face[i] = Math.floor(rnd() * (mesh.vertexCount + 2)) - 1; else if (roll < 0.85) face.splice(i, 1); else face.reverse();
      if (old === face[i] && roll < 0.7) continue;
      r = api.checkMeshTableAnswer(mesh, 'faces', { faces: answer });
      names = { vertex: 'v', edge: 'e', face: 'F' };
    } else if (which === 1) {
      const edges = foleyEdges.slice();
      const polygons = foleyPolygons.map((p) => p.slice());
      if (rnd() < 0.6) {
        const i = Math.floor(rnd() * edges.length);
        edges[i] = Math.floor(rnd() * (i % 4 < 2 ? 6 : 4)) - 2;
      } else {
        const p = polygons[Math.floor(rnd() * polygons.length)];
        p[Math.floor(rnd() * p.length)] = Math.floor(rnd() * 7) - 1;
      }
      r = api.checkMeshTableAnswer(foleyMesh, 'edge-list', { edges, polygons });
      names = { vertex: 'V', edge: 'E', face: 'P' };
    } else {
      const lists = neighbours.map((s) => [...s]);
      const list = lists[Math.floor(rnd() * lists.length)];
      if (rnd() < 0.7) list[Math.floor(rnd() * list.length)] = Math.floor(rnd() * (mesh.vertexCount + 2)) - 2;
      else list.splice(Math.floor(rnd() * list.length), 1);
      r = api.checkMeshTableAnswer(mesh, 'adjacency', { vertexVertices: lists });
      names = { vertex: 'v', edge: 'e', face: 'F' };
    }
    for (const f of r.findings) {
      findings += 1;
      assert.ok(f.message.length > 20 && f.hint.length > 10, f.code);
      const own = ownRow(f, names);
      // (the edge list's column heads V1, V2, P1, P2 are the grid's, not values)
      for (const l of labelsIn(words(f).replace(/column [VP][12]\b/g, ''))) assert.equal(l, own, `trial ${trial}, ${f.code}: "${words(f)}"`);
    }
  }
  assert.ok(findings > 1500, `${findings} findings`);
});

test('walk: every wrong edge at every step of every walk on the slide; the words name the element and the edge the step starts from, never the next edge', () => {
  const numbering = { ...mesh, edges: SLIDE_EDGE_TABLE.map((row) => row.split(/\s+/).slice(1, 3).map(number)), vertexEdges: SLIDE_VERTEX_EDGES.map(number), faceEdges: SLIDE_FACE_EDGES.map(number) };
  let cases = 0;
  for (const [around, count] of [['vertex', 5], ['face', 3]]) {
    for (let element = 0; element < count; element += 1) {
      const name = `${around === 'vertex' ? 'v' : 'F'}${element + 1}`;
      const walk = slideWalk(around, name); // the slide's own rule, read off its tables
      for (let step = 1; step <= walk.length; step += 1) {
        const expected = step < walk.length ? walk[step] : walk[0];
        const from = walk[step - 1];
        for (let given = -2; given < 7; given += 1) {
          if (given === -1 || `e${given + 1}` === expected) continue;
          const r = api.checkWalkStep(numbering, { around, element, step, given });
          assert.equal(r.correct, false);
          cases += 1;
          assert.ok(r.message.startsWith(`Step ${step}, from ${from}: `), r.message);
          for (const l of labelsIn(`${r.message} ${r.hint}`)) assert.ok(l === name || l === from, `${name} step ${step}: ${l} in "${r.message} ${r.hint}"`);
          assert.ok(!labelsIn(`${r.message} ${r.hint}`).has(expected) || expected === from);
        }
        const right = api.checkWalkStep(numbering, { around, element, step, given: number(expected) });
        assert.equal(right.correct, true);
        assert.equal(right.message, '');
      }
    }
  }
  assert.ok(cases > 150, `${cases}`);
});

test('walk: 2,000 random wrong steps on a built grid; the words name only the element and the step\'s edge', () => {
  const rnd = random(2803);
  // A 4 x 3 grid of squares, each split into two triangles (vertex (i, j) = 5 j + i).
  const faces = [];
  for (let j = 0; j < 3; j += 1) for (let i = 0; i < 4; i += 1) {
    const a = 5 * j + i; const b = a + 1; const c = a + 6; const d = a + 5;
    faces.push([a, b, c], [a, c, d]);
  }
  const grid = { faces, vertexCount: 20 };
  const built = api.buildMesh({ positions: new Float64Array(60).map((_, k) => (k % 3 === 0 ? (k / 3) % 5 : k % 3 === 1 ? Math.floor(k / 15) : 0)), faces });
  const E = built.wingedEdge().edges.length;
  let cases = 0;
  try {
    while (cases < 2000) {
      const around = rnd() < 0.5 ? 'vertex' : 'face';
      const element = Math.floor(rnd() * (around === 'vertex' ? 20 : faces.length));
      const steps = around === 'vertex' ? built.traversalSteps(element) : built.faceEdgeSteps(element);
      const step = 1 + Math.floor(rnd() * steps.length);
      const given = Math.floor(rnd() * (E + 1)) - 1;
      const r = api.checkWalkStep(grid, { around, element, step, given: given < 0 ? -2 : given });
      if (r.correct) continue;
      cases += 1;
      const name = `${around === 'vertex' ? 'v' : 'F'}${element + 1}`;
      const from = `e${steps[step - 1].edge + 1}`;
      for (const l of labelsIn(`${r.message} ${r.hint}`)) assert.ok(l === name || l === from, `${l} in "${r.message} ${r.hint}"`);
    }
  } finally {
    built.dispose();
  }
});
