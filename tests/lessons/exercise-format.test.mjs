// The exercise file (docs/exercises.md) as the pages read it: every exercise the
// gallery ships reads, with its lesson state; the gallery has at least two per lesson; a
// damaged file is refused with one sentence naming the field (never a partial exercise); an
// exercise packed into a link comes back exactly.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { lessons } from '../../web/js/lessons/registry.js';
import { LESSON_OBJECTS } from '../../web/js/lessons/all.js';
import { parseExercise, readExercise, ExerciseError, KINDS } from '../../web/js/exercise/format.js';
import { readExerciseState } from '../../web/js/exercise/player.js';
import { readExerciseLink, loadLinkedExercise, exerciseUrl } from '../../web/js/exercise/link.js';
import { meshLesson } from '../../web/js/lessons/mesh/lesson.js';
import { lesson as curvesLesson } from '../../web/js/lessons/curves/lesson.js';
import { lesson as continuityLesson } from '../../web/js/lessons/continuity/lesson.js';
import { lesson as comparisonLesson } from '../../web/js/lessons/comparison/lesson.js';
import { lesson as surfacesLesson } from '../../web/js/lessons/surfaces/lesson.js';
import { subdivisionLesson } from '../../web/js/lessons/subdivision/lesson.js';
import { codeLesson } from '../../web/js/lessons/code/lesson.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const dir = path.join(root, 'web', 'exercises');
const lessonIds = lessons.map((l) => l.id);
const LESSONS = Object.fromEntries([meshLesson, curvesLesson, continuityLesson, comparisonLesson, surfacesLesson, subdivisionLesson, codeLesson].map((l) => [l.id, l]));
const shipped = fs.readdirSync(dir).filter((f) => f.endsWith('.json')).map((f) => ({ file: f, text: fs.readFileSync(path.join(dir, f), 'utf8') }));

test('every shipped exercise reads, with its lesson state, and its id is its file name', () => {
  assert.ok(shipped.length >= 12);
  for (const { file, text } of shipped) {
    const exercise = parseExercise(text, { lessonIds });
    assert.equal(`${exercise.id}.json`, file);
    const lesson = LESSONS[exercise.lesson];
    assert.ok(lesson, `${file}: lesson ${exercise.lesson}`);
    assert.ok(lesson.exercise.kinds.includes(exercise.check.kind), `${file}: ${exercise.lesson} offers ${exercise.check.kind}`);
    const state = readExerciseState(lesson, exercise);
    assert.equal(typeof state, 'object');
  }
});

test('the gallery has at least two exercises for every lesson that offers exercises, and every kind appears', () => {
  const byLesson = {};
  const kinds = new Set();
  for (const { text } of shipped) {
    const x = JSON.parse(text);
    byLesson[x.lesson] = (byLesson[x.lesson] ?? 0) + 1;
    kinds.add(x.check.kind);
  }
  // A lesson offers exercises through its `exercise` (the kinds its drawing gives); the code
  // lesson grades its own tasks (Run) and offers none of the gallery's kinds.
  for (const id of lessonIds) {
    if (!LESSON_OBJECTS[id].exercise) { assert.equal(byLesson[id] ?? 0, 0, `${id} offers no exercises, and the gallery has none`); continue; }
    assert.ok((byLesson[id] ?? 0) >= 2, `${id}: ${byLesson[id] ?? 0} exercises`);
  }
  assert.deepEqual([...kinds].sort(), Object.keys(KINDS).sort()); // every kind has a gallery exercise
});

// A valid exercise to damage, one field at a time.
const base = () => JSON.parse(shipped.find((x) => x.file === 'curves-bernstein-half.json').text);
const DAMAGE = [
  ['not JSON', null, /not valid JSON/, (t) => t.slice(0, 40)],
  ['a lesson state, not an exercise', (x) => { x.format = 'wingspline'; }, /lesson state, not an exercise/],
  ['another format', (x) => { x.format = 'other'; }, /format/],
  ['a newer version', (x) => { x.version = 7; }, /newer Wingspline \(exercise version 7/],
  ['no title', (x) => { delete x.title; }, /exercise\.title is missing/],
  ['an empty question', (x) => { x.question = '   '; }, /exercise\.question must not be empty/],
  ['a long title', (x) => { x.title = 'x'.repeat(121); }, /exercise\.title is longer than 120/],
  ['an unknown lesson', (x) => { x.lesson = 'knitting'; }, /exercise\.lesson names "knitting"/],
  ['a bad id', (x) => { x.id = 'Bad Id!'; }, /exercise\.id must be lower-case/],
  ['hide not a list', (x) => { x.hide = 'panel-matrix'; }, /exercise\.hide must be a list/],
  ['an unknown kind', (x) => { x.check.kind = 'essay'; }, /exercise\.check\.kind must be one of table, walk, joint, value, property/],
  ['a negative tolerance', (x) => { x.check.tolerance = -1; }, /exercise\.check\.tolerance/],
  ['a zero tolerance', (x) => { x.check.tolerance = 0; }, /exercise\.check\.tolerance must be greater than 0/],
  ['a blend without u', (x) => { delete x.check.u; }, /exercise\.check\.u is missing/],
  ['an unknown quantity', (x) => { x.check.quantity = 'area'; }, /exercise\.check\.quantity must be one of/],
  ['a fractional index', (x) => { x.check.i = 1.5; }, /exercise\.check\.i must be a whole number/],
  ['a walk from vertex 0', (x) => { x.check = { kind: 'walk', around: 'vertex', element: 0 }; }, /exercise\.check\.element must be between 1/],
  ['a table with an unknown column', (x) => { x.check = { kind: 'table', table: 'winged-edge', given: ['colour'] }; }, /exercise\.check\.given\[0\] must be a column/],
  ['a table with every column given', (x) => { x.check = { kind: 'table', table: 'edge-list', given: ['v1', 'v2', 'p1', 'p2'] }; }, /exercise\.check\.given gives every column: nothing is left to fill in/],
  ['a joint class with no class', (x) => { x.check = { kind: 'property', property: { kind: 'joint-class', joint: 1 } }; }, /exercise\.check\.property must name the class/],
  ['a point with one coordinate', (x) => { x.check = { kind: 'property', property: { kind: 'passes-through', point: [1], tolerance: 0.01 } }; }, /exercise\.check\.property\.point must have 2 to 2 entries/],
  ['no state', (x) => { delete x.state; }, /exercise\.state is missing/],
];

for (const [what, damage, expected, asText] of DAMAGE) {
  test(`an exercise with ${what} is refused, naming the field`, () => {
    const x = base();
    let text = JSON.stringify(x);
    if (damage) { damage(x); text = JSON.stringify(x); }
    if (asText) text = asText(text);
    assert.throws(() => parseExercise(text, { lessonIds }), (err) => err instanceof ExerciseError && expected.test(err.message));
  });
}

test('a state field the lesson refuses refuses the exercise, naming the field (never a partial state)', () => {
  const x = readExercise(base(), { lessonIds });
  x.state = { ...x.state, points: [[0, 0], [1, 'two'], [3, 2], [4, 0]] };
  assert.throws(() => readExerciseState(curvesLesson, x), (err) => err instanceof ExerciseError && /exercise\.state\.points/.test(err.message));
  const newer = { ...readExercise(base(), { lessonIds }), stateVersion: curvesLesson.stateVersion + 1 };
  assert.throws(() => readExerciseState(curvesLesson, newer), /newer Wingspline/);
  assert.throws(() => readExerciseState(meshLesson, readExercise(base(), { lessonIds })), /exercise of the curves lesson/);
  const wrongKind = { ...readExercise(base(), { lessonIds }), check: { kind: 'walk', around: 'vertex', element: 1 } };
  assert.throws(() => readExerciseState(curvesLesson, wrongKind), /Curve explorer has no exercises of the kind "walk"/);
});

test('an exercise packed into a link comes back exactly; a damaged or foreign link is refused in one sentence', async () => {
  for (const { text } of shipped) {
    const exercise = parseExercise(text, { lessonIds });
    const url = await exerciseUrl(exercise, `${exercise.lesson}.html`, 'http://127.0.0.1:8000/');
    const link = readExerciseLink(new URL(url).hash);
    assert.ok(link && 'code' in link);
    assert.deepEqual(await loadLinkedExercise(link, { lessonIds }), exercise);
  }
  await assert.rejects(loadLinkedExercise({ code: 'not*base64' }, { lessonIds }), (err) => err instanceof ExerciseError && /^the link/.test(err.message));
  await assert.rejects(loadLinkedExercise({ code: 'AAAA' }, { lessonIds }), ExerciseError);
  assert.deepEqual(readExerciseLink('#exercise=../../etc/passwd'), { problem: 'the link names the exercise "../../etc/passwd", which is not an exercise name' });
  assert.deepEqual(readExerciseLink('#exercise=mesh-walk-around-v2'), { id: 'mesh-walk-around-v2' });
  assert.equal(readExerciseLink('#s=abc'), null);
  // A shipped id whose file holds another exercise is refused.
  await assert.rejects(loadLinkedExercise({ id: 'curves-bernstein-half' }, { lessonIds, fetchText: async () => shipped.find((x) => x.file === 'mesh-walk-around-v2.json').text }), /holds the exercise "mesh-walk-around-v2"/);
});
