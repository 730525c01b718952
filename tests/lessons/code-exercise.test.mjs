// The code exercise kind in Node, as `wingspline grade` runs it: the gallery's code exercises
// are read and opened in the code lesson's state, and submissions holding code are graded by
// running the code in the same QuickJS sandbox on the slide's mesh and on hidden meshes from a
// fresh seed. The lecture's rule (tests/helpers/code-solutions.mjs) is right; the starter, a
// wrong walk, an endless loop and a syntax error are wrong, each with a reason naming the mesh
// or the line; a finding never carries the core's answer (the exercise's feedback levels).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from '../../dist/js/core/wingspline.js';
import { makeSubmission, exerciseHash } from '../../web/js/exercise/submission.js';
import { gradeFiles, RESULTS } from '../../web/js/exercise/grade.js';
import { parseExercise } from '../../web/js/exercise/format.js';
import { readExerciseState } from '../../web/js/exercise/player.js';
import { GRADERS } from '../../web/js/exercise/graders.js';
import { LESSON_OBJECTS } from '../../web/js/lessons/all.js';
import { taskOf } from '../../web/js/lessons/code/tasks.js';
import { createNodeSandbox } from '../../web/js/code/quickjs-node.js';
import { CORRECT } from '../helpers/code-solutions.mjs';

const api = await loadWingspline();
const sandbox = createNodeSandbox();
const run = (request) => sandbox.run(request);
const lessonIds = Object.keys(LESSON_OBJECTS);
const galleryText = (id) => fs.readFileSync(new URL(`../../web/exercises/${id}.json`, import.meta.url), 'utf8');
const file = (name, text) => ({ name, size: Buffer.byteLength(text), read: () => text });

// A student's submission whose code exercise holds `sources` (task id -> code) in its state.
async function submissionWith(exerciseId, sources, { student = 'Ada' } = {}) {
  const exercise = parseExercise(galleryText(exerciseId), { lessonIds });
  const state = { ...readExerciseState(LESSON_OBJECTS.code, exercise), code: sources };
  const entry = { id: exercise.id, hash: await exerciseHash(exercise), progress: { status: 'started', checks: 1, answer: null, state, title: exercise.title, lesson: 'code', kind: 'code' } };
  return JSON.stringify(await makeSubmission({ student, app: api.version, entries: [entry] }));
}

async function gradeOne(exerciseId, sources) {
  const { rows, problems } = await gradeFiles({
    api, lessons: LESSON_OBJECTS, graders: GRADERS, run,
    files: [file(`${exerciseId}.json`, galleryText(exerciseId)), file('ada.json', await submissionWith(exerciseId, sources))],
  });
  assert.deepEqual(problems, []);
  assert.equal(rows.length, 1);
  return rows[0];
}

test('the gallery has code exercises, and each opens in the code lesson on its task with the starter', () => {
  for (const id of ['code-edges-around-vertex', 'code-flip-edge']) {
    const exercise = parseExercise(galleryText(id), { lessonIds });
    assert.equal(exercise.check.kind, 'code');
    const state = readExerciseState(LESSON_OBJECTS.code, exercise);
    assert.equal(state.task, exercise.check.task, `${id}: the state shows the task asked`);
    assert.deepEqual(state.code, {}, `${id}: nobody's code is handed out`);
    assert.ok(taskOf(exercise.check.task));
  }
});

test('the grader runs submitted code: the lecture\'s rule is right, the starter and a wrong walk are wrong, naming the slide\'s mesh without the core\'s answer', async () => {
  const right = await gradeOne('code-edges-around-vertex', { 'edges-around-vertex': CORRECT['edges-around-vertex'] });
  assert.equal(right.result, RESULTS.right, right.reason);
  assert.equal(right.score, 1);

  // The starter returns [] : wrong on the slide's mesh, asked at v2 (the statement's vertex).
  const starter = await gradeOne('code-edges-around-vertex', {});
  assert.equal(starter.result, RESULTS.wrong);
  assert.match(starter.reason, /^On the slide's mesh \(lecture 000\), v2: your function returned \[\]\. It parts from the core's answer at entry 1\. 0 of \d+ meshes passed\.$/);

  // The wrong wing: clockwise. On the slide (lecture 000) the walk around v2 is e6 e5 e3 e2; the
  // clockwise one from e6 meets e2 next, so the answers part at entry 2.
  const wrong = await gradeOne('code-edges-around-vertex', { 'edges-around-vertex': CORRECT['edges-around-vertex'].replace('r.startLeft', 'r.startRight').replace('r.endRight', 'r.endLeft') });
  assert.equal(wrong.result, RESULTS.wrong);
  assert.match(wrong.reason, /^On the slide's mesh \(lecture 000\), v2: your function returned \[e6 e2 e3 e5\]\. It parts from the core's answer at entry 2\./);
  assert.doesNotMatch(wrong.reason, /e6 e5 e3 e2/, 'the core\'s answer is not in the reason');

  // Code written for another task only: the exercise's task is graded, from its starter.
  const elsewhere = await gradeOne('code-edges-around-vertex', { 'edges-of-face': CORRECT['edges-of-face'] });
  assert.equal(elsewhere.result, RESULTS.wrong);
});

test('an endless loop and a syntax error in a submission are wrong with their line; grading goes on', async () => {
  const t0 = Date.now();
  const endless = await gradeOne('code-edges-around-vertex', { 'edges-around-vertex': 'function spin() {\n  while (true) {}\n}\nfunction edgesAroundVertex(mesh, v) {\n  spin();\n  return [];\n}' });
  assert.equal(endless.result, RESULTS.wrong);
  assert.match(endless.reason, /line 2/i, endless.reason);
  // One mesh's budget (1.5 s) and not one per mesh: the run stops at the first endless loop.
  assert.ok(Date.now() - t0 < 10000, `${Date.now() - t0} ms`);
  const syntax = await gradeOne('code-edges-around-vertex', { 'edges-around-vertex': 'function edgesAroundVertex(mesh, v) {\n  const x = ;\n  return [];\n}' });
  assert.equal(syntax.result, RESULTS.wrong);
  assert.match(syntax.reason, /^Line 2/, syntax.reason);
});

test('an edit exercise: the flip written from the winged-edge record is right; one that forgets what v3 stores is wrong, said in the core\'s words', async () => {
  const right = await gradeOne('code-flip-edge', { 'flip-edge': CORRECT['flip-edge'] });
  assert.equal(right.result, RESULTS.right, right.reason);
  const wrong = await gradeOne('code-flip-edge', { 'flip-edge': CORRECT['flip-edge'].replace('if (mesh.vertex(E).edge === e) mesh.vertex(E).edge = c;', '') });
  assert.equal(wrong.result, RESULTS.wrong);
  assert.match(wrong.reason, /^On the slide's mesh \(lecture 000\), e3: the tables your function left are not the winged edge of the mesh after the flip, so nothing was applied\./);
  assert.match(wrong.reason, /v3/, 'the core names the vertex whose row is wrong');
});

test('a folder of submissions with code: one row per file, a damaged state named, nothing crashes', async () => {
  const exercise = galleryText('code-edges-around-vertex');
  const good = await submissionWith('code-edges-around-vertex', { 'edges-around-vertex': CORRECT['edges-around-vertex'] }, { student: 'Grace' });
  const starter = await submissionWith('code-edges-around-vertex', {}, { student: 'Alan' });
  const damaged = JSON.parse(good);
  damaged.exercises[0].state.code = { 'edges-around-vertex': 42 };
  const { rows } = await gradeFiles({
    api, lessons: LESSON_OBJECTS, graders: GRADERS, run,
    files: [file('ex.json', exercise), file('grace.json', good), file('alan.json', starter), file('eve.json', JSON.stringify(damaged))],
  });
  assert.deepEqual(rows.map((r) => [r.file, r.result]), [['grace.json', RESULTS.right], ['alan.json', RESULTS.wrong], ['eve.json', RESULTS.ungradable]]);
  assert.match(rows[2].reason, /code/);
  // Without a sandbox the grader says so for the code row instead of failing.
  const { rows: noSandbox } = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: GRADERS, files: [file('ex.json', exercise), file('grace.json', good)] });
  assert.equal(noSandbox[0].result, RESULTS.ungradable);
  assert.match(noSandbox[0].reason, /sandbox/);
});
