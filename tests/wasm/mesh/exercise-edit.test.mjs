// The edit exercise over the real module: api.editQuestion and api.checkEditAnswer. The
// lecture's flip of e3 is written as worked by hand from lecture 000's conventions; then seeded
// random edits on the lecture mesh, the cube and a grid: the rows that change are found here by
// comparing the tables before and after (mesh.apply on a mesh of the test's own), the right
// answer is read from the after-tables under random labels for the new elements, and every
// one-cell corruption must be named on its row and column without the right value.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();
const lecture = api.lectureExample();
const n = (s) => (s === '-' ? -1 : Number(s.slice(1)) - 1);
const TABLES = ['vertices', 'edges', 'faces'];
const FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];

test('flip e3 of the lecture mesh: the question, the rows worked by hand, a wrong wing named without its value', () => {
  const q = api.editQuestion(lecture, [], { op: 'flip-edge', e: 2 });
  assert.deepEqual(q, { rows: { vertices: [2], edges: [0, 1, 2, 3, 4], faces: [0] }, added: { vertices: 0, edges: 0, faces: 0 }, operation: 'flip e3' });
  const rows = ['v1 v3 - F2 e2 e3 e4 e4', 'v1 v2 F1 - e3 e1 e5 e6', 'v4 v1 F1 F2 e5 e4 e2 e1', 'v3 v4 - F2 e1 e1 e7 e3', 'v2 v4 F1 F3 e2 e6 e3 e7'];
  const answer = {
    vertices: { cells: [n('e1')], removed: [false], labels: [] },
    edges: { cells: rows.flatMap((r) => r.split(' ').map(n)), removed: Array(5).fill(false), labels: [] },
    faces: { cells: [n('e3')], removed: [false], labels: [] },
  };
  const right = api.checkEditAnswer(lecture, [], { op: 'flip-edge', e: 2 }, answer);
  assert.deepEqual(right.findings, []);
  assert.equal(right.correct, true);
  assert.deepEqual(right.worked.edges.cells, answer.edges.cells);
  answer.edges.cells[8 * 2 + 4] = n('e2');
  const wrong = api.checkEditAnswer(lecture, [], { op: 'flip-edge', e: 2 }, answer);
  assert.equal(wrong.findings.length, 1);
  const [f] = wrong.findings;
  assert.deepEqual([f.table, f.row, f.field, f.index, f.code, f.given, f.expected], ['edge', 2, 'startLeft', 2, 'wrong-wing', 1, 4]);
  assert.match(f.reason, /^row e3, column S:L: after flip e3/);
  assert.doesNotMatch(f.reason, /\be5\b/);
  assert.equal(wrong.worked.edges.cells[8 * 2 + 4], n('e5'));
});

test('earlier edits are replayed in the core (Compact among them), and errors are named', () => {
  // split e3 (v6, e8), then split e8: asked of the mesh as the drawing numbers it
  const q = api.editQuestion(lecture, [{ op: 'split-edge', e: 2, t: 0.5 }, { op: 'move-vertex', v: 5, p: [1, 1, 0] }], { op: 'split-edge', e: 7, t: 0.25 });
  assert.equal(q.operation, 'split e8 at t = 0.25');
  const gapped = [{ op: 'collapse-edge', e: 3, t: 0.5 }];
  assert.equal(api.editQuestion(lecture, gapped, { op: 'split-edge', e: 5 }).operation, 'split e6 at t = 0.5');
  // after Compact, e6 is e4 (e4 and e5 were removed)
  assert.equal(api.editQuestion(lecture, [...gapped, { op: 'compact' }], { op: 'split-edge', e: 3 }).operation, 'split e4 at t = 0.5');
  assert.throws(() => api.editQuestion(lecture, gapped, { op: 'flip-edge', e: 3 }), (err) => err.code === 'deleted-element');
  assert.throws(() => api.editQuestion(lecture, [], { op: 'flip-edge', e: 0 }), (err) => err.code !== undefined && /e1/.test(err.message));
  assert.throws(() => api.editQuestion(lecture, [], { op: 'explode', e: 0 }), (err) => err.code === 'unknown-operation');
  assert.throws(() => api.checkEditAnswer(lecture, [], { op: 'flip-edge', e: 2 }, { vertices: { cells: [], removed: [], labels: [] } }), (err) => err.code === 'invalid-answer');
  const empty = { vertices: { cells: [], removed: [], labels: [] }, edges: { cells: [], removed: [], labels: [] }, faces: { cells: [], removed: [], labels: [] } };
  assert.throws(() => api.checkEditAnswer(lecture, [], { op: 'flip-edge', e: 2 }, empty), (err) => err.code === 'invalid-answer' && /vertex rows hold 0 cells/.test(err.message));
});

// The winged-edge tables of a live mesh, and its gaps, as plain lists.
function tablesOf(mesh) {
  const t = mesh.wingedEdgeArrays();
  const g = mesh.gaps();
  return {
    vertices: Array.from(t.vertexEdge, (e) => [e]),
    edges: Array.from({ length: t.edges.length / 8 }, (_, i) => FIELDS.map((f) => t.edges[8 * i + t.edgeFields.indexOf(f)])),
    faces: Array.from(t.faceEdge, (e) => [e]),
    gone: { vertices: new Set(g.vertices), edges: new Set(g.edges), faces: new Set(g.faces) },
  };
}
const REFS = { vertices: ['edges'], faces: ['edges'], edges: ['vertices', 'vertices', 'faces', 'faces', 'edges', 'edges', 'edges', 'edges'] };

test('seeded random edits through the module: any labels for the new elements accepted, every one-cell corruption named', (t) => {
  const rand = random(2026);
  const meshes = [lecture, api.generateMesh('cube'), api.generateMesh('grid', { nx: 3, ny: 2 }), api.generateMesh('tetrahedron')];
  const names = api.meshOperations.operations.map((o) => o.name);
  let questions = 0;
  let corruptions = 0;
  for (let seed = 0; seed < 300; seed += 1) {
    const loaded = meshes[seed % meshes.length];
    const mesh = api.buildMesh(loaded);
    try {
      // one earlier edit (maybe), then the question's: random operations the core accepts
      const pickOp = () => {
        for (let tries = 0; tries < 100; tries += 1) {
          const entry = api.meshOperations.operations[Math.floor(rand() * names.length)];
          const counts = { vertex: mesh.counts().vertices, edge: mesh.wingedEdgeArrays().edges.length / 8, face: mesh.wingedEdgeArrays().faceEdge.length };
          const op = { op: entry.name };
          for (const a of entry.arguments) op[a.name] = a.kind ? Math.floor(rand() * counts[a.kind]) : 0.5;
          if (entry.arguments[1]?.choices) {
            const first = entry.arguments[0];
            const choices = (() => { try { return Array.from(mesh.adjacency(entry.arguments[1].choices, op[first.name])); } catch { return []; } })();
            for (const a of entry.arguments.slice(1)) if (a.kind && choices.length) op[a.name] = choices[Math.floor(rand() * choices.length)];
          }
          if (mesh.check(op).ok) return op;
        }
        return null;
      };
      const edits = [];
      if (rand() < 0.5) {
        const first = pickOp();
        if (first) { mesh.apply(first); edits.push(first); }
      }
      const op = pickOp();
      if (!op) continue;
      const before = tablesOf(mesh);
      mesh.apply(op);
      const after = tablesOf(mesh);
      const q = api.editQuestion(loaded, edits, op);
      // the rows that change, found here
      for (const t of TABLES) {
        const changed = before[t].map((_, i) => i).filter((i) => !before.gone[t].has(i)
          && (after.gone[t].has(i) || before[t][i].some((c, k) => c !== after[t][i][k])));
        assert.deepEqual(q.rows[t], changed, `${t} rows`);
        assert.equal(q.added[t], after[t].length - before[t].length);
      }
      // random labels for the new elements, above every existing one
      const labelOf = {};
      for (const t of TABLES) {
        labelOf[t] = new Map(before[t].map((_, i) => [i, i]));
        const used = new Set();
        for (let i = before[t].length; i < after[t].length; i += 1) {
          let l;
          do l = before[t].length + Math.floor(rand() * 30); while (used.has(l));
          used.add(l);
          labelOf[t].set(i, l);
        }
      }
      const core = Object.fromEntries(TABLES.map((t) => [t, [...q.rows[t], ...Array.from({ length: q.added[t] }, (_, k) => before[t].length + k)]]));
      const answer = Object.fromEntries(TABLES.map((t) => [t, {
        cells: core[t].flatMap((i) => (after.gone[t].has(i) ? REFS[t].map(() => -2) : after[t][i].map((c, k) => (c === -1 ? -1 : labelOf[REFS[t][k]].get(c))))),
        removed: core[t].map((i) => after.gone[t].has(i)),
        labels: core[t].slice(q.rows[t].length).map((i) => labelOf[t].get(i)),
      }]));
      const right = api.checkEditAnswer(loaded, edits, op, answer);
      assert.deepEqual(right.findings, [], `${op.op} ${JSON.stringify(op)}`);
      questions += 1;
      // each edge cell set to a wrong existing label (or blank): one finding on that row and column
      answer.edges.cells.forEach((good, i) => {
        const row = Math.floor(i / 8);
        if (answer.edges.removed[row] || rand() < 0.5) return;
        const ref = REFS.edges[i % 8];
        const bad = structuredClone(answer);
        let wrong = Math.floor(rand() * before[ref].length);
        if (wrong === good) wrong = -2;
        bad.edges.cells[i] = wrong;
        const r = api.checkEditAnswer(loaded, edits, op, bad);
        assert.equal(r.findings.length, 1, JSON.stringify(r.findings));
        assert.deepEqual([r.findings[0].table, r.findings[0].index, r.findings[0].field], ['edge', row, FIELDS[i % 8]]);
        const letter = { vertices: 'v', edges: 'e', faces: 'F' }[ref];
        const said = r.findings[0].reason.split(q.operation).join('').replace(/^row \S+/, '').replace(/\(e\d+\)|, column/, '');
        if (good >= 0 && r.findings[0].given !== good) assert.doesNotMatch(said, new RegExp(`\\b${letter}${good + 1}\\b(?! has after)`), r.findings[0].reason);
        corruptions += 1;
      });
    } finally {
      mesh.dispose();
    }
  }
  t.diagnostic(`${questions} questions, ${corruptions} corruptions`);
  assert.ok(questions >= 200, `${questions} questions`);
  assert.ok(corruptions >= 1000, `${corruptions} corruptions`);
});
