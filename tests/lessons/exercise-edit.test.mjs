// The edit exercise and exercises from any view, in Node over the real core. The gallery's
// edit exercises are answered by the rows worked out by hand from lecture 000's tables and
// conventions (L runs S -> E; wing X:Y = the other edge at X of the face on side Y, the
// boundary walked as a face), typed as a student types them; tables and walks asked of an
// edited mesh, of a subdivided mesh and of an imported one check against the drawing's
// numbering, never against a copy of the app's output.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from 'wingspline';
import { lessons } from '../../web/js/lessons/registry.js';
import { parseExercise, exerciseOf } from '../../web/js/exercise/format.js';
import { readExerciseState } from '../../web/js/exercise/player.js';
import { gradeEdit, workedEdit } from '../../web/js/exercise/kinds/edit.js';
import { refuseLargeMesh } from '../../web/js/exercise/subjects.js';
import { meshLesson } from '../../web/js/lessons/mesh/lesson.js';
import { subdivisionLesson } from '../../web/js/lessons/subdivision/lesson.js';
import { stringifyExact } from '../../web/js/app/share-link.js';

const api = await loadWingspline();
const lessonIds = lessons.map((l) => l.id);
const LESSONS = { mesh: meshLesson, subdivision: subdivisionLesson };

function opened(id) {
  const exercise = parseExercise(fs.readFileSync(new URL(`../../web/exercises/${id}.json`, import.meta.url), 'utf8'), { lessonIds });
  return { exercise, subject: subjectOf(exercise) };
}
function subjectOf(exercise) {
  const lesson = LESSONS[exercise.lesson];
  const state = readExerciseState(lesson, exercise);
  const model = exercise.lesson === 'subdivision' ? lesson.compute({}, state, { api }) : null;
  return lesson.exercise.subject({}, model, state, { api });
}

// Lecture 000's rows after each edit, worked by hand (tests/native/mesh/test_mesh_euler.cpp
// derives the same ones): "S E L R S:L S:R E:L E:R", "-" for no face; "removed" for a row the
// edit removes. New elements are written under labels of the student's choosing (v9, e12),
// not the core's next numbers.
const HAND = {
  'mesh-edit-flip-e3': {
    vertices: { v3: 'e1' },
    edges: {
      e1: 'v1 v3 - F2 e2 e3 e4 e4', e2: 'v1 v2 F1 - e3 e1 e5 e6', e3: 'v4 v1 F1 F2 e5 e4 e2 e1',
      e4: 'v3 v4 - F2 e1 e1 e7 e3', e5: 'v2 v4 F1 F3 e2 e6 e3 e7',
    },
    faces: { F1: 'e3' },
  },
  // split e3 at t = 1/2: the new vertex (v6 for the core) is v9 here, the new edge (e8) e12.
  'mesh-edit-split-e3': {
    vertices: { v3: 'e12', new: { v9: 'e12' } },
    edges: {
      e1: 'v1 v3 - F1 e2 e2 e4 e12', e3: 'v2 v9 F1 F2 e2 e5 e12 e12', e4: 'v3 v4 - F2 e1 e12 e7 e5',
      new: { e12: 'v9 v3 F1 F2 e3 e3 e1 e4' },
    },
    faces: {},
  },
  // collapse e4: v4 merges into v3; F2 (v2 v4 v3) goes with e4 and e5; e3 takes e5's place in F3.
  'mesh-edit-collapse-e4': {
    vertices: { v4: 'removed' },
    edges: {
      e1: 'v1 v3 - F1 e2 e2 e7 e3', e3: 'v2 v3 F1 F3 e2 e6 e1 e7', e4: 'removed', e5: 'removed',
      e6: 'v2 v5 F3 - e3 e2 e7 e7', e7: 'v3 v5 - F3 e1 e3 e6 e6',
    },
    faces: { F2: 'removed', F3: 'e3' },
  },
};

const TABLES = ['vertices', 'edges', 'faces'];
const PREFIX = { vertices: 'v', edges: 'e', faces: 'F' };
const cellsOf = (text) => text.split(' ').map((c) => (c === '-' ? 'none' : c));

// The hand rows typed into the question's rows (the question lists them; the hand table must
// name exactly those rows, and as many new ones as the question adds).
function typedAnswer(q, hand) {
  const answer = {};
  for (const t of TABLES) {
    const { new: fresh = {}, ...rows } = hand[t];
    assert.deepEqual(q.rows[t].map((i) => `${PREFIX[t]}${i + 1}`), Object.keys(rows), `the ${t} rows the question lists`);
    assert.equal(q.added[t], Object.keys(fresh).length, `new ${t}`);
    const listed = Object.values(rows);
    answer[t] = {
      cells: [...listed, ...Object.values(fresh)].map((text) => (text === 'removed' ? Array(t === 'edges' ? 8 : 1).fill('') : cellsOf(text))),
      removed: [...listed.map((text) => text === 'removed'), ...Object.keys(fresh).map(() => false)],
      labels: Object.keys(fresh),
    };
  }
  return answer;
}

const questionOf = (exercise, subject) => {
  const op = Object.fromEntries(Object.entries(exercise.check.op).map(([k, v]) => [k, k === 'op' || k === 't' ? v : v - 1]));
  return api.editQuestion(subject.loaded, subject.edits, op);
};

for (const id of Object.keys(HAND)) {
  test(`${id}: the rows worked by hand from the lecture's tables are right; a wrong cell is named without its value`, () => {
    const { exercise, subject } = opened(id);
    assert.equal(exercise.check.kind, 'edit');
    // homework in the gallery: feedback at level check (the reader of that field is the feedback levels')
    assert.deepEqual(JSON.parse(fs.readFileSync(new URL(`../../web/exercises/${id}.json`, import.meta.url), 'utf8')).feedback, { level: 'check' });
    const q = questionOf(exercise, subject);
    const answer = typedAnswer(q, HAND[id]);
    const right = gradeEdit({ api, check: exercise.check, subject, answer });
    assert.deepEqual(right.findings, []);
    assert.equal(right.correct, true);
    // every cell of every written row, one at a time, set to a wrong label: named by row and
    // column, and the right label is not in the sentence
    let named = 0;
    for (const t of TABLES) {
      answer[t].cells.forEach((row, i) => row.forEach((good, k) => {
        if (answer[t].removed[i]) return;
        const wrong = structuredClone(answer);
        // (a vertex or face may store any of its edges: e99, no edge at all, is surely wrong)
        const ref = t === 'edges' ? 'vvFFeeee'[k] : 'e';
        wrong[t].cells[i][k] = t !== 'edges' ? 'e99' : good === `${ref}1` ? `${ref}2` : `${ref}1`;
        const r = gradeEdit({ api, check: exercise.check, subject, answer: wrong });
        assert.equal(r.correct, false);
        assert.equal(r.findings.length, 1, JSON.stringify(r.findings));
        const fresh = i >= q.rows[t].length;
        const rowLabel = fresh ? answer[t].labels[i - q.rows[t].length] : `${PREFIX[t]}${q.rows[t][i] + 1}`;
        const rowName = fresh ? `row ${i - q.rows[t].length + 1} \\(${rowLabel}\\)` : `row ${rowLabel}`;
        assert.match(r.findings[0].text, new RegExp(rowName, 'i'));
        if (t === 'edges') assert.match(r.findings[0].text, new RegExp(`column ${['S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R'][k]}`));
        const said = r.findings[0].text.replace(new RegExp(`${rowName}|${q.operation}`, 'gi'), '');
        if (good !== 'none') assert.doesNotMatch(said, new RegExp(`\\b${good}\\b`), r.findings[0].text);
        assert.equal(typeof r.findings[0].hint, 'string');
        assert.doesNotMatch(r.findings[0].hint, new RegExp(`\\b${good}\\b`));
        named += 1;
      }));
    }
    assert.ok(named >= 8);
    // the worked answer holds the right rows
    const lines = workedEdit({ api, check: exercise.check, subject }).lines;
    assert.match(lines[0], new RegExp(`After ${q.operation}`));
    assert.ok(lines.length > 1);
  });
}

test('an answer that is not an answer to the question reads as "could not be read", never an exception', () => {
  const { exercise, subject } = opened('mesh-edit-flip-e3');
  for (const bad of [null, 7, 'x', {}, { vertices: { cells: [['e1', 'e2']], removed: [false], labels: [] } }, { edges: [] }]) {
    const r = gradeEdit({ api, check: exercise.check, subject, answer: bad });
    assert.equal(r.correct, false);
    assert.equal(r.incomplete, true);
    assert.match(r.findings[0].text, /could not be read/);
  }
  const q = questionOf(exercise, subject);
  const typed = typedAnswer(q, HAND['mesh-edit-flip-e3']);
  typed.edges.cells[2][4] = 'x7';
  const r = gradeEdit({ api, check: exercise.check, subject, answer: typed });
  assert.match(r.findings[0].text, /^Row e3, column S:L: "x7" is not an edge/);
  // a row left blank is one finding, not eight; two blank cells of a row are one too
  typed.edges.cells[2][4] = 'e5';
  typed.edges.cells[0] = Array(8).fill('');
  typed.edges.cells[1][6] = '';
  typed.edges.cells[1][7] = '';
  const blanks = gradeEdit({ api, check: exercise.check, subject, answer: typed }).findings.map((f) => f.text);
  assert.deepEqual(blanks.map((t) => t.split(' is').shift().split(' are').shift()), ['Row e1: every column', 'Row e2: columns E:L and E:R']);
});

// The mesh lesson's state for the slide's mesh with these edits.
function meshState(ops) {
  const { exercise } = opened('mesh-winged-edge-slide');
  return { ...exercise.state, ops };
}
const asExercise = (lesson, state, check) => parseExercise(stringifyExact(exerciseOf({
  title: 'from a view', lesson: lesson.id, question: 'q', stateVersion: lesson.stateVersion, state, hide: [], check,
})), { lessonIds });

test('a table and a walk asked of an edited mesh check against the drawing\'s numbering (the edits replayed in the core)', () => {
  // split e3: the hand tables after it (v6, e8 as the core numbers them: the drawing's labels)
  const exercise = asExercise(meshLesson, meshState([{ op: 'split-edge', e: 2, t: 0.5 }]), { kind: 'walk', around: 'vertex', element: 3 });
  const subject = subjectOf(exercise);
  const rows = ['v1 v3 - F1 e2 e2 e4 e8', 'v1 v2 F1 - e1 e1 e3 e6', 'v2 v6 F1 F2 e2 e5 e8 e8', 'v3 v4 - F2 e1 e8 e7 e5',
    'v2 v4 F2 F3 e3 e6 e4 e7', 'v2 v5 F3 - e5 e2 e7 e7', 'v4 v5 - F3 e4 e5 e6 e6', 'v6 v3 F1 F2 e3 e3 e1 e4'];
  const n = (x) => (x === '-' ? -1 : Number(x.slice(1)) - 1);
  const table = {
    edges: rows.flatMap((r) => r.split(' ').map(n)),
    vertexEdges: ['e1', 'e6', 'e8', 'e5', 'e6', 'e8'].map(n),
    faceEdges: ['e1', 'e3', 'e5'].map(n),
  };
  assert.deepEqual(api.checkMeshTableAnswer(subject.mesh, 'winged-edge', table).findings, []);
  // the CCW walk around v3 from its stored edge e8: v3 is e8's End, so E:R = e4; v3 is e4's
  // Start, so S:L = e1; v3 is e1's End, so E:R = e8 again
  const walk = ['e8', 'e4', 'e1'].map(n);
  for (let k = 1; k <= walk.length; k += 1) {
    const r = api.checkWalkStep(subject.mesh, { around: 'vertex', element: 2, step: k, given: walk[k % walk.length] });
    assert.equal(r.correct, true, `step ${k}: ${r.reason}`);
  }
  assert.equal(api.checkWalkStep(subject.mesh, { around: 'vertex', element: 2, step: 1, given: n('e3') }).correct, false);
});

test('an edited mesh with gaps is refused for a table with a sentence naming Compact; after Compact it is asked', () => {
  // collapse e4 removes v4, e4, e5 and F2: four gaps
  const gapped = subjectOf(asExercise(meshLesson, meshState([{ op: 'collapse-edge', e: 3, t: 0.5 }]), { kind: 'walk', around: 'vertex', element: 1 }));
  assert.throws(() => refuseLargeMesh(gapped.mesh), /left 4 gaps in the numbering; use Compact in the edit panel first/);
  const compacted = subjectOf(asExercise(meshLesson, meshState([{ op: 'collapse-edge', e: 3, t: 0.5 }, { op: 'compact' }]), { kind: 'walk', around: 'vertex', element: 1 }));
  refuseLargeMesh(compacted.mesh);
  // after the collapse and Compact: 4 vertices, 5 edges, 2 faces (V - E + F = 1, an open disc)
  assert.equal(compacted.mesh.positions.length / 3, 4);
  assert.equal(compacted.mesh.edges.length, 5);
  assert.equal(compacted.mesh.faceOffsets.length - 1, 2);
  // an edit exercise is still asked of the gapped mesh, numbered as the drawing (e4, e5 gaps)
  const q = api.editQuestion(gapped.loaded, gapped.edits, { op: 'flip-edge', e: 2 });
  assert.equal(q.operation, 'flip e3');
});

test('a table and a walk asked of a subdivided mesh (level 1) use the drawing\'s numbering', () => {
  const state = { ...subdivisionLesson.defaultState(), level: 1 };
  const exercise = asExercise(subdivisionLesson, state, { kind: 'walk', around: 'vertex', element: 1 });
  const model = subdivisionLesson.compute({}, readExerciseState(subdivisionLesson, exercise), { api });
  const subject = subdivisionLesson.exercise.subject({}, model, state, { api });
  // one Loop step of the tetrahedron: V = 4 + 6, E = 2 * 6 + 3 * 4, F = 4 * 4
  assert.equal(subject.mesh.positions.length / 3, 10);
  assert.equal(subject.mesh.edges.length, 24);
  assert.equal(subject.mesh.faceOffsets.length - 1, 16);
  // The walk the drawing shows around v1 (the lesson's mesh) is the one the check accepts.
  const steps = model.mesh.traversalSteps(0);
  assert.equal(steps.length, 3); // an old vertex of the tetrahedron keeps its valence
  for (let k = 1; k <= steps.length; k += 1) {
    assert.equal(api.checkWalkStep(subject.mesh, { around: 'vertex', element: 0, step: k, given: steps[k % steps.length].edge }).correct, true);
  }
  // The drawing's own tables answer the table exercise of the subdivided mesh.
  const t = model.mesh.wingedEdgeArrays();
  const answer = { edges: Array.from(t.edges), vertexEdges: Array.from(t.vertexEdge), faceEdges: Array.from(t.faceEdge) };
  assert.deepEqual(t.edgeFields, ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight']);
  assert.deepEqual(api.checkMeshTableAnswer(subject.mesh, 'winged-edge', answer).findings, []);
});

test('an exercise made from an imported mesh carries the mesh inline and opens with nothing stored', () => {
  // A square of two triangles, imported (the flat form an import writes).
  const imported = { name: 'square.off', positions: [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], faceSizes: [3, 3], faceVertices: [0, 1, 2, 0, 2, 3] };
  const state = { ...meshState([]), meshKind: 'file', imported };
  const exercise = asExercise(meshLesson, state, { kind: 'edit', op: { op: 'flip-edge', e: 3 } });
  const text = stringifyExact(exercise);
  assert.doesNotMatch(text, /\$content/);
  const read = parseExercise(text, { lessonIds });
  const subject = subjectOf(read);
  // the diagonal v1-v3 is e3 (edges numbered in order of first appearance: v1v2, v2v3, v3v1)
  const q = api.editQuestion(subject.loaded, subject.edits, { op: 'flip-edge', e: 2 });
  assert.equal(q.operation, 'flip e3');
  assert.deepEqual(q.added, { vertices: 0, edges: 0, faces: 0 });
  assert.ok(q.rows.edges.includes(2));
});

// The gallery's flip of e3 in half-edge terms (check.structure "half-edge"), through the same
// grade function the grader uses. By hand (tests/native/mesh/test_exercise_half_edge_edit.cpp):
// after the flip F1 = h3 h9 h5, F2 = h2 h6 h8; rows h2 h3 h5 h6 h8 h9 change and F1's half-edge.
const HALF_EDGE_FLIP_E3 = {
  halfedges: [['v3', 'F2', 'h6', 'h8'], ['v1', 'F1', 'h9', 'h5'], ['v4', 'F1', 'h3', 'h9'], ['v1', 'F2', 'h8', 'h2'], ['v4', 'F2', 'h2', 'h6'], ['v2', 'F1', 'h5', 'h3']],
  vertices: [],
  faces: [['h5']],
};
test('mesh-half-edge-flip-e3: the half-edge rows worked by hand are right; every wrong cell is named without its value; the worked answer lists them', () => {
  const { exercise, subject } = opened('mesh-half-edge-flip-e3');
  assert.deepEqual(exercise.check, { kind: 'edit', op: { op: 'flip-edge', e: 3 }, structure: 'half-edge' });
  const answer = Object.fromEntries(Object.entries(HALF_EDGE_FLIP_E3).map(([t, rows]) => [t, { cells: rows.map((r) => [...r]), removed: rows.map(() => false), labels: [] }]));
  const right = gradeEdit({ api, check: exercise.check, subject, answer });
  assert.deepEqual(right.findings, []);
  assert.equal(right.correct, true);
  const rowLabels = { halfedges: ['h2', 'h3', 'h5', 'h6', 'h8', 'h9'], faces: ['F1'] };
  let named = 0;
  for (const t of ['halfedges', 'faces']) {
    answer[t].cells.forEach((row, i) => row.forEach((good, k) => {
      const wrong = structuredClone(answer);
      // A label of the right kind that is surely wrong: h1 is on the boundary, on no face of these rows.
      const ref = t === 'faces' ? 'h' : ['v', 'F', 'h', 'h'][k];
      wrong[t].cells[i][k] = ref === 'F' ? (good === 'F3' ? 'F1' : 'F3') : good === `${ref}1` ? `${ref}2` : `${ref}1`;
      const r = gradeEdit({ api, check: exercise.check, subject, answer: wrong });
      assert.equal(r.correct, false);
      assert.equal(r.findings.length, 1, JSON.stringify(r.findings));
      assert.match(r.findings[0].text, new RegExp(`^Row ${rowLabels[t][i]}, column ${t === 'faces' ? 'half-edge' : ['origin', 'face', 'next', 'prev'][k]}`));
      const said = r.findings[0].text.replace(new RegExp(`Row ${rowLabels[t][i]}|next\\(${rowLabels[t][i]}\\)|prev\\(${rowLabels[t][i]}\\)|${rowLabels[t][i]} |flip e3`, 'g'), '');
      if (t !== 'faces') assert.doesNotMatch(said, new RegExp(`\\b${good}\\b`), r.findings[0].text);
      assert.equal(typeof r.findings[0].hint, 'string');
      named += 1;
    }));
  }
  assert.equal(named, 25);
  // Unreadable shapes are "could not be read", never an exception.
  assert.equal(gradeEdit({ api, check: exercise.check, subject, answer: { halfedges: {} } }).incomplete, true);
  const lines = workedEdit({ api, check: exercise.check, subject }).lines;
  assert.equal(lines[0], 'After flip e3:');
  assert.ok(lines.includes('h8: origin v4, face F2, next h2, prev h6'), lines.join('\n'));
});
