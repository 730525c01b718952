// Every kind's pure grading function (the shared contract: grade<Kind>({api, check,
// subject, answer}) -> {correct, partial?, incomplete?, findings: [{text, hint?}], note?}) run
// in Node over the real core, with the subject the grader asks for (view {}, the model from
// lesson.compute). Right answers come from the lectures (the slide's tables and walk, the
// Bernstein polynomials), never from the app; a finding's text never holds the right value;
// an answer of the wrong shape (an untrusted file) is a result, never an exception; the walk's
// progress saved in its old shape ({known}) opens as the picks it stood for.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from 'wingspline';
import { lessons } from '../../web/js/lessons/registry.js';
import { parseExercise, feedbackOf } from '../../web/js/exercise/format.js';
import { readExerciseState } from '../../web/js/exercise/player.js';
import { gradeTable, workedTable } from '../../web/js/exercise/kinds/table.js';
import { gradeWalk, workedWalk, migrateWalkAnswer } from '../../web/js/exercise/kinds/walk.js';
import { gradeJoint, workedJoint } from '../../web/js/exercise/kinds/joint.js';
import { gradeValue, workedValue } from '../../web/js/exercise/kinds/value.js';
import { workedProperty } from '../../web/js/exercise/kinds/property.js';
import { workedSubdivide } from '../../web/js/exercise/kinds/subdivide.js';
import { workedEdit } from '../../web/js/exercise/kinds/edit.js';
import { GRADERS } from '../../web/js/exercise/graders.js';
import { meshLesson } from '../../web/js/lessons/mesh/lesson.js';
import { lesson as curvesLesson } from '../../web/js/lessons/curves/lesson.js';
import { lesson as continuityLesson } from '../../web/js/lessons/continuity/lesson.js';
import { lesson as comparisonLesson } from '../../web/js/lessons/comparison/lesson.js';
import { lesson as surfacesLesson } from '../../web/js/lessons/surfaces/lesson.js';
import { subdivisionLesson } from '../../web/js/lessons/subdivision/lesson.js';
import { codeLesson } from '../../web/js/lessons/code/lesson.js';
import { createNodeSandbox } from '../../web/js/code/quickjs-node.js';
import { slideRows, SLIDE_VERTEX_EDGES, SLIDE_FACE_EDGES, slideWalk, SLIDE_HALF_EDGES, SLIDE_HALF_EDGE_VERTICES, SLIDE_HALF_EDGE_FACES } from '../helpers/lecture-slide.mjs';

const api = await loadWingspline();
const LESSONS = Object.fromEntries([meshLesson, curvesLesson, continuityLesson, comparisonLesson, surfacesLesson, subdivisionLesson, codeLesson].map((l) => [l.id, l]));
const sandbox = createNodeSandbox();
const lessonIds = lessons.map((l) => l.id);
// The grader's registry, and the kinds named here, must agree: a kind the grader cannot grade fails this test.
const GRADE = GRADERS;
const WORKED = { table: workedTable, walk: workedWalk, joint: workedJoint, value: workedValue, property: workedProperty, subdivide: workedSubdivide, edit: workedEdit,
  code: ({ check }) => codeLesson.exercise.code.worked(check.task, null) };
const readText = (id) => fs.readFileSync(new URL(`../../web/exercises/${id}.json`, import.meta.url), 'utf8');

// As the grader opens an exercise: headless, view {}, the model from the lesson's compute.
function opened(id) {
  const exercise = parseExercise(readText(id), { lessonIds });
  const lesson = LESSONS[exercise.lesson];
  const state = readExerciseState(lesson, exercise);
  // (the code lesson's subject is its state alone, as the grader asks it; its compute needs a page)
  const model = lesson.id === 'code' ? null : lesson.compute({}, state, { api });
  return { exercise, check: exercise.check, subject: lesson.exercise.subject({}, model, state, { api }) };
}
const shippedIds = fs.readdirSync(new URL('../../web/exercises/', import.meta.url)).filter((f) => f.endsWith('.json')).map((f) => f.slice(0, -5));

test('every gallery exercise grades headless: a bad answer shape is a result, never an exception; the worked answer has lines', async () => {
  for (const id of shippedIds) {
    const { exercise, check, subject } = opened(id);
    const support = LESSONS[exercise.lesson].exercise;
    // The code kind's answer is the state's code (its subject); the others' the answer given.
    const bads = check.kind === 'code'
      ? [undefined, null, {}, { code: null }, { code: 'x' }, { code: { task: check.task, sources: 42 } }].map((s) => ({ subject: s, answer: null }))
      : [undefined, null, 42, 'x'.repeat(500), [], { picks: 'e1' }, { parametric: 'C1' }, { 'edge:0:start': 7 }].map((a) => ({ subject, answer: a }));
    for (const { subject: asked, answer: bad } of bads) {
      const r = await GRADE[check.kind]({ api, check, subject: asked, answer: bad, support, run: (request) => sandbox.run(request) });
      assert.equal(typeof r.correct, 'boolean', `${id}: ${JSON.stringify(bad)}`);
      assert.ok(Array.isArray(r.findings), id);
      for (const f of r.findings) assert.equal(typeof f.text, 'string', id);
      if (check.kind !== 'property') assert.equal(r.correct, false, `${id}: ${JSON.stringify(bad ?? asked)?.slice(0, 40)}`);
    }
    const worked = WORKED[check.kind]({ api, check, subject });
    assert.ok(worked.lines.length >= 1 && worked.lines.every((l) => typeof l === 'string'), id);
  }
});

test('the gallery\'s feedback: homework is level check; the two exercises whose answer the slides print are self-study (worked)', () => {
  const levels = Object.fromEntries(shippedIds.map((id) => [id, feedbackOf(parseExercise(readText(id), { lessonIds })).level]));
  assert.deepEqual(Object.entries(levels).filter(([, l]) => l !== 'check').map(([id]) => id).sort(), ['mesh-edge-list-foley', 'mesh-winged-edge-slide']);
  // A file from before the levels keeps the worked answer it always offered.
  const old = JSON.parse(readText('mesh-walk-around-v2'));
  delete old.feedback;
  assert.deepEqual(feedbackOf(parseExercise(JSON.stringify(old), { lessonIds })), { level: 'worked', hintAfter: 2 });
  old.feedback = { level: 'hint', hintAfter: 21 };
  assert.throws(() => parseExercise(JSON.stringify(old), { lessonIds }), /exercise\.feedback\.hintAfter/);
  old.feedback = { level: 'answers' };
  assert.throws(() => parseExercise(JSON.stringify(old), { lessonIds }), /exercise\.feedback\.level/);
});

test('table: the slide\'s tables typed as the slide prints them are right; a wrong cell is named without its value', () => {
  const { check, subject } = opened('mesh-winged-edge-slide');
  const rows = slideRows();
  const FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
  const given = new Set(check.given ?? []);
  const typed = (value) => (value === '-' ? 'none' : value);
  const answer = {};
  rows.forEach((r, i) => [r.S, r.E, r.L, r.R, r.SL, r.SR, r.EL, r.ER].forEach((v, k) => { if (!given.has(FIELDS[k])) answer[`edge:${i}:${FIELDS[k]}`] = typed(v); }));
  SLIDE_VERTEX_EDGES.forEach((e, v) => { if (!given.has('vertexEdge')) answer[`vertex:${v}:edge`] = e; });
  SLIDE_FACE_EDGES.forEach((e, f) => { if (!given.has('faceEdge')) answer[`face:${f}:edge`] = e; });
  assert.deepEqual(gradeTable({ api, check, subject, answer }), { correct: true, findings: [] });
  const wrong = { ...answer, 'edge:4:startLeft': 'e2' }; // e5's S:L is e3 on the slide
  const r = gradeTable({ api, check, subject, answer: wrong });
  assert.equal(r.correct, false);
  assert.equal(r.findings.length, 1);
  assert.match(r.findings[0].text, /^Row e5, column S:L: /);
  assert.doesNotMatch(r.findings[0].text, /\be3\b/);
  assert.doesNotMatch(r.findings[0].hint ?? '', /\be3\b/);
  assert.deepEqual(gradeTable({ api, check, subject, answer: {} }).incomplete, true);
  const unreadable = gradeTable({ api, check, subject, answer: { ...answer, 'edge:4:startLeft': 'x9' } });
  assert.equal(unreadable.incomplete, true);
  assert.match(unreadable.findings[0].text, /^e5 S:L: "x9" is not an edge/);
});

test('walk: the slide\'s walk around v2 replayed from its picks; a wrong pick names the step, never the edge', () => {
  const { check, subject } = opened('mesh-walk-around-v2');
  const walk = slideWalk('vertex', `v${check.element}`).map((e) => Number(e.slice(1)));
  const picks = [...walk.slice(1), walk[0]];
  assert.equal(gradeWalk({ api, check, subject, answer: { picks } }).correct, true);
  const partial = gradeWalk({ api, check, subject, answer: { picks: picks.slice(0, 2) } });
  assert.deepEqual([partial.correct, partial.partial, partial.findings], [false, true, []]);
  const wrongEdge = [1, 2, 3, 4, 5, 6, 7].find((e) => e !== picks[1] && e !== walk[1]);
  const wrong = gradeWalk({ api, check, subject, answer: { picks: [picks[0], wrongEdge] } });
  assert.equal(wrong.correct, false);
  assert.equal(wrong.findings.length, 1);
  assert.match(wrong.findings[0].text, new RegExp(`^Step 2, from e${walk[1]}: `));
  assert.doesNotMatch(`${wrong.findings[0].text} ${wrong.findings[0].hint}`, new RegExp(`\\be${picks[1]}\\b`));
  // Picks after a wrong one still count once right: the grader replays every step.
  assert.equal(gradeWalk({ api, check, subject, answer: { picks: [picks[0], wrongEdge, ...picks.slice(1)] } }).correct, true);
  assert.equal(gradeWalk({ api, check, subject, answer: { picks: [0] } }).incomplete, true);
  assert.equal(gradeWalk({ api, check, subject, answer: { picks: [] } }).incomplete, true);
});

// The slide's half-edge tables (worked by hand) as typed, with the rows renumbered by `order`
// (student row r is the slide's half-edge order[r], 1-based).
function halfEdgeTyped(order) {
  const rename = (x) => (/^h\d+$/.test(x) ? `h${order.indexOf(Number(x.slice(1))) + 1}` : x);
  const fields = ['origin', 'face', 'next', 'prev', 'twin'];
  const answer = {};
  order.forEach((k, r) => SLIDE_HALF_EDGES[k - 1].forEach((v, c) => { answer[`halfedge:${r}:${fields[c]}`] = rename(v); }));
  SLIDE_HALF_EDGE_VERTICES.forEach((x, v) => { answer[`vertex:${v}:halfedge`] = rename(x); });
  SLIDE_HALF_EDGE_FACES.forEach((x, f) => { answer[`face:${f}:halfedge`] = rename(x); });
  return answer;
}

test('half-edge table: the slide\'s half-edge tables in the slide\'s numbering and renumbered are right; a wrong cell is named without its value', () => {
  const { check, subject } = opened('mesh-half-edge-table-lecture');
  assert.equal(check.table, 'half-edge');
  const slide = [...Array(14).keys()].map((i) => i + 1);
  assert.deepEqual(gradeTable({ api, check, subject, answer: halfEdgeTyped(slide) }), { correct: true, findings: [] });
  const backwards = [...slide].reverse();
  const answer = halfEdgeTyped(backwards);
  assert.deepEqual(gradeTable({ api, check, subject, answer }), { correct: true, findings: [] });
  // Row h10 here is the slide's h5 (v2 -> v3 on F1): its twin is the slide's h6, here h9; write h8.
  assert.equal(answer['halfedge:9:twin'], 'h9');
  const r = gradeTable({ api, check, subject, answer: { ...answer, 'halfedge:9:twin': 'h8' } });
  assert.equal(r.findings.length, 1);
  assert.match(r.findings[0].text, /^Row h10, column twin: this is not twin\(h10\)\. Re-read: twin\(h\) is the other half of h's edge/);
  assert.doesNotMatch(`${r.findings[0].text} ${r.findings[0].hint}`, /\bh9\b/);
  // Typed labels that do not read are said before any check.
  const unreadable = gradeTable({ api, check, subject, answer: { ...answer, 'halfedge:0:next': 'e3' } });
  assert.equal(unreadable.incomplete, true);
  assert.match(unreadable.findings[0].text, /^h1 next: "e3" is not a half-edge/);
  // The worked table, in the student's numbering.
  const worked = workedTable({ api, check, subject, answer });
  assert.equal(worked.lines[9], 'Half-edges, h10: origin v2, face F1, next h13, prev h12, twin h9');
});

test('half-edge table with given columns: origin and twin come filled in as the Half-edge tab numbers the half-edges (the slide\'s), and the rest typed in that numbering is right', () => {
  const { subject } = opened('mesh-half-edge-table-lecture');
  const check = { kind: 'table', table: 'half-edge', given: ['origin', 'twin'] };
  const slide = halfEdgeTyped([...Array(14).keys()].map((i) => i + 1));
  const typed = Object.fromEntries(Object.entries(slide).filter(([key]) => !/:(origin|twin)$/.test(key)));
  assert.deepEqual(gradeTable({ api, check, subject, answer: typed }), { correct: true, findings: [] });
  // The given cells are the slide's: the worked table keeps them (h1 = v1 -> v3, its twin h2).
  assert.match(workedTable({ api, check, subject, answer: typed }).lines[0], /^Half-edges, h1: origin v1, face none, next h7, prev h4, twin h2$/);
  // The same rows typed in another numbering no longer fit the given origins and twins.
  const other = Object.fromEntries(Object.entries(halfEdgeTyped([...Array(14).keys()].map((i) => 14 - i))).filter(([key]) => !/:(origin|twin)$/.test(key)));
  assert.equal(gradeTable({ api, check, subject, answer: other }).correct, false);
});

test('half-edge walk: around v2 from h4 replayed from its picks (h11 h9 h5 h4, worked by hand); a wrong pick names the step and the rule, never the half-edge', () => {
  const { check, subject } = opened('mesh-half-edge-walk-around-v2');
  assert.equal(check.structure, 'half-edge');
  assert.equal(gradeWalk({ api, check, subject, answer: { picks: [11, 9, 5, 4] } }).correct, true);
  const wrong = gradeWalk({ api, check, subject, answer: { picks: [11, 10] } }); // h10: the twin of the right h9
  assert.deepEqual([wrong.correct, wrong.partial], [false, true]);
  assert.match(wrong.findings[0].text, /^Step 2, from h11: that is not the half-edge the walk reaches next/);
  assert.doesNotMatch(`${wrong.findings[0].text} ${wrong.findings[0].hint}`, /\bh9\b/);
  assert.equal(gradeWalk({ api, check, subject, answer: { picks: [15] } }).incomplete, true); // 14 half-edges
  assert.deepEqual(workedWalk({ api, check, subject }).lines.map((l) => l.split(':')[0]), ['h4 → h11', 'h11 → h9', 'h9 → h5', 'h5 → h4']);
  const along = opened('mesh-half-edge-walk-along-f2');
  assert.equal(gradeWalk({ api, ...along, answer: { picks: [9, 8, 6] } }).correct, true); // from h6: h9, h8, back to h6
});

test('walk: progress kept in the old shape {known} opens as the right picks it stood for (fixture)', () => {
  const fixture = JSON.parse(fs.readFileSync(new URL('../fixtures/exercise-progress/walk-known-v1.json', import.meta.url), 'utf8'));
  const { check, subject } = opened('mesh-walk-around-v2');
  const walk = slideWalk('vertex', `v${check.element}`).map((e) => Number(e.slice(1)));
  const steps = walk.map((e) => ({ edge: e - 1 }));
  assert.deepEqual(migrateWalkAnswer(fixture.entry.answer, steps), { picks: walk.slice(1, fixture.entry.answer.known) });
  const r = gradeWalk({ api, check, subject, answer: fixture.entry.answer });
  assert.deepEqual([r.correct, r.partial], [false, true]);
  // Closed walk in the old shape: every step right.
  assert.equal(gradeWalk({ api, check, subject, answer: { known: walk.length + 1 } }).correct, true);
  assert.equal(gradeWalk({ api, check, subject, answer: { known: walk.length + 2 } }).incomplete, true);
});

test('joint: the G1-not-C1 joint; a wrong class names the family, never the class', () => {
  const { check, subject } = opened('continuity-classify-g1');
  const wrong = gradeJoint({ api, check, subject, answer: { parametric: 2, geometric: 1, why: [] } });
  assert.equal(wrong.correct, false);
  for (const f of wrong.findings) assert.doesNotMatch(f.text, /[CG](⁻¹|⁰|¹|²)|\btrue\b|\bfalse\b/);
  assert.ok(wrong.findings.some((f) => /parametric class/.test(f.text)));
  assert.equal(gradeJoint({ api, check, subject, answer: { parametric: null, geometric: 1, why: [] } }).incomplete, true);
  assert.equal(gradeJoint({ api, check, subject, answer: { parametric: 1, geometric: 1, why: ['tangent'] } }).incomplete, true);
});

test('value: the Bernstein value at u = 1/2 from the lecture\'s formula; a wrong number is said without the value, a wrong count plainly', () => {
  const { check, subject } = opened('curves-bernstein-half');
  // B_{i,3}(u) = C(3, i) u^i (1 - u)^(3 - i) (lecture 001).
  const C = [1, 3, 3, 1][check.i];
  const expected = C * check.u ** check.i * (1 - check.u) ** (3 - check.i);
  assert.equal(gradeValue({ api, check, subject, answer: String(expected) }).correct, true);
  const r = gradeValue({ api, check, subject, answer: String(expected + 0.5) });
  assert.equal(r.correct, false);
  assert.ok(!r.findings[0].text.includes(String(Number(expected.toPrecision(6)))), r.findings[0].text);
  assert.equal(gradeValue({ api, check, subject, answer: '1, 2' }).findings[0].text, 'The answer is a single number; you typed two numbers.');
  const mg = opened('comparison-hermite-mg');
  const text = gradeValue({ api, check: mg.check, subject: mg.subject, answer: '3' }).findings[0].text;
  assert.match(text, /first row, first column \(x\) of M G for the first segment/);
  // The only numbers: the lectures' (000, 003) and the 1 of [u³ u² u 1].
  assert.deepEqual([...new Set(text.match(/-?\d+(\.\d+)?/g))].sort(), ['000', '003', '1']);
});
