// Values nested 100,000 levels deep, inside the size limits, in every input a page reads from
// outside: a share link, a saved state (a stored link code, or a pending edit's JSON), an
// imported JSON state file, an exercise file, an exercise link and an exercise's progress.
// JSON.parse reads them without recursion, but copying or writing them (structuredClone,
// JSON.stringify, the exercise's progress key) recursed once per level and overflowed the
// stack after the reader had accepted them. Each reader now refuses them in one sentence
// naming the path to the field, past MAX_NESTING = 64 levels (docs/state-format.md,
// "Nesting"), and never with a RangeError.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { decodeState, readEnvelopeResolved, packText, MAX_STATE_BYTES } from '../../../web/js/app/share-link.js';
import { checkNesting, SchemaError } from '../../../web/js/app/schema.js';
import { parseExercise, MAX_EXERCISE_CHARS, ExerciseError } from '../../../web/js/exercise/format.js';
import { loadLinkedExercise } from '../../../web/js/exercise/link.js';
import { readProgress } from '../../../web/js/exercise/progress.js';
import { lessons } from '../../../web/js/lessons/registry.js';
import { meshLesson } from '../../../web/js/lessons/mesh/lesson.js';

const DEPTH = 100000;
const lessonIds = lessons.map((l) => l.id);
// Texts of a value nested DEPTH levels: objects {"a": ...} (6 characters a level) for the
// state readers, whose limit is 16 MB; lists [[...]] (2 a level) for an exercise (256 KB).
const deepObjects = (depth) => `${'{"a":'.repeat(depth)}1${'}'.repeat(depth)}`;
const deepLists = (depth) => `${'['.repeat(depth)}${']'.repeat(depth)}`;
const envelopeText = (extra) => `{"format":"wingspline","lesson":"mesh","version":${meshLesson.stateVersion},"state":${JSON.stringify(meshLesson.defaultState()).slice(0, -1)},"extra":${extra}}}`;
const exerciseText = (extra) => JSON.stringify({
  format: 'wingspline-exercise', version: 1, title: 'Deep', lesson: 'mesh', question: 'Walk around v2.',
  stateVersion: meshLesson.stateVersion, state: meshLesson.defaultState(), check: { kind: 'walk', around: 'vertex', element: 2 },
}).replace('"state":{', `"state":{"extra":${extra},`);

// The state's path, cut after six steps: envelope -> state -> extra -> a -> a -> a -> a…
const STATE_PATH = /^its field state\.extra\.a\.a\.a\.a… nests deeper than 64 levels$/;
const EXERCISE_PATH = /^its field exercise\.state\.extra\[0\]\[0\]\[0\]\[0\]… nests deeper than 64 levels$/;
const refusedWith = (pattern) => (err) => {
  assert.ok(!(err instanceof RangeError), `a stack overflow, not a refusal: ${err.message}`);
  assert.match(err.message, pattern);
  return true;
};

test('the texts are within their size limits, and JSON.parse reads them', () => {
  const state = envelopeText(deepObjects(DEPTH));
  const exercise = exerciseText(deepLists(DEPTH));
  assert.ok(state.length < MAX_STATE_BYTES, `${state.length} characters`);
  assert.ok(exercise.length < MAX_EXERCISE_CHARS, `${exercise.length} characters`);
  assert.equal(typeof JSON.parse(state), 'object');
  assert.equal(typeof JSON.parse(exercise), 'object');
});

test('a share link, and a saved state kept as a link code, are refused naming the field', async () => {
  const code = await packText(envelopeText(deepObjects(DEPTH)));
  await assert.rejects(decodeState(meshLesson, code), refusedWith(STATE_PATH));
});

test('a pending edit or an imported JSON state file (parsed JSON) is refused naming the field', async () => {
  const data = JSON.parse(envelopeText(deepObjects(DEPTH)));
  await assert.rejects(readEnvelopeResolved(meshLesson, data), refusedWith(STATE_PATH));
});

test('an exercise file is refused naming the field, as an ExerciseError with its path', () => {
  assert.throws(() => parseExercise(exerciseText(deepLists(DEPTH)), { lessonIds }), (err) => {
    refusedWith(EXERCISE_PATH)(err);
    assert.ok(err instanceof ExerciseError);
    assert.match(err.field, /^exercise\.state\.extra\[0\]/);
    return true;
  });
});

test('an exercise link is refused naming the field', async () => {
  const code = await packText(exerciseText(deepLists(DEPTH)));
  await assert.rejects(loadLinkedExercise({ code }, { lessonIds }), refusedWith(EXERCISE_PATH));
});

test('progress nested 100,000 deep is unreadable: set aside as it was, and the exercise starts fresh', () => {
  const items = new Map();
  const localStorage = {
    getItem: (k) => (items.has(k) ? items.get(k) : null),
    setItem: (k, v) => { items.set(k, String(v)); },
    removeItem: (k) => { items.delete(k); },
  };
  const page = /** @type {any} */ ({ localStorage });
  page.self = page;
  page.top = page; // a page of its own, not framed
  globalThis.window = page;
  try {
    const raw = `{"version":1,"status":"started","checks":1,"answer":${deepObjects(DEPTH)},"state":null,"solvedAt":null,"title":"t","lesson":"mesh"}`;
    items.set('wingspline:exercise:site:deep', raw);
    const read = readProgress('site:deep', { lesson: 'mesh' });
    assert.equal(read.progress, null);
    assert.match(read.problem, /could not be read/);
    assert.equal(items.has('wingspline:exercise:site:deep'), false);
    // The entry is kept, as it was, under a key of its own (the History's).
    const kept = [...items.values()].filter((v) => { try { return JSON.parse(v).raw === raw; } catch { return false; } });
    assert.equal(kept.length, 1);
  } finally {
    delete globalThis.window;
  }
});

test('the limit: 64 levels are read, 65 are refused; wide values of any size are no deeper', async () => {
  const nested = (depth) => { let v = 0; for (let i = 0; i < depth; i += 1) v = [v]; return v; };
  assert.doesNotThrow(() => checkNesting(nested(64)));
  assert.throws(() => checkNesting(nested(65), 'x'), (err) => err instanceof SchemaError && err.message === 'x[0][0][0][0][0][0]… nests deeper than 64 levels');
  // Keys that are not names are quoted, and long ones cut after 24 characters.
  assert.throws(() => checkNesting({ 'my field': { [`${'k'.repeat(30)}`]: nested(70) } }), (err) => err.message === `["my field"].${'k'.repeat(24)}…[0][0][0][0]… nests deeper than 64 levels`);
  // A million faces of three corners: three levels under the root.
  const faces = Array.from({ length: 1000000 }, (_, i) => [i, i + 1, i + 2]);
  assert.doesNotThrow(() => checkNesting({ state: { imported: { faces } } }));
  // A state 64 levels deep from the envelope is read (its unknown field dropped as before).
  let deep = 1;
  for (let i = 0; i < 61; i += 1) deep = { a: deep }; // envelope, state, extra: 3 levels + 61
  const { state, problems } = await readEnvelopeResolved(meshLesson, { format: 'wingspline', lesson: 'mesh', version: meshLesson.stateVersion, state: { ...meshLesson.defaultState(), extra: deep } });
  assert.deepEqual(problems, []);
  assert.equal(state.extra, undefined);
});
