// The submission file and the gradebook's files, in Node: what a damaged, edited or hostile
// file becomes (a named row or a named refusal, never a crash), and that the CSV a spreadsheet
// opens runs nothing and reads back as written (parsed by the tests' own RFC 4180 reader,
// tests/helpers/csv.mjs). The grading of answers by the core, kind by kind, is tests/lessons/exercise-grade.test.mjs
// and, from the packed tarball, tests/package/package.test.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import {
  readSubmission, makeSubmission, SubmissionError, exerciseHash, MAX_SUBMISSION_BYTES,
} from '../../web/js/exercise/submission.js';
import { gradeFiles, gradebookCsv, gradebookMarkdown, gradebookTotalsCsv, csvCell, markdownCell, COLUMNS, RESULTS } from '../../web/js/exercise/grade.js';
import { LESSON_OBJECTS } from '../../web/js/lessons/all.js';
import { GRADERS } from '../../web/js/exercise/graders.js';
import { parseExercise } from '../../web/js/exercise/format.js';
import fs from 'node:fs';
import { parseCsv } from '../helpers/csv.mjs';

const api = await loadWingspline();
const lessonIds = Object.keys(LESSON_OBJECTS);
const galleryText = (id) => fs.readFileSync(new URL(`../../web/exercises/${id}.json`, import.meta.url), 'utf8');
const file = (name, text) => ({ name, size: Buffer.byteLength(text), read: () => text });

test('a cell a spreadsheet would run starts with an apostrophe; commas, quotes and line breaks are quoted', () => {
  for (const danger of ['=HYPERLINK("http://x","y")', '+1+1', '-2+3', '@SUM(A1)', '\tx', '\rx']) {
    const cell = csvCell(danger);
    const back = cell.startsWith('"') ? cell.slice(1, -1).replace(/""/g, '"') : cell;
    assert.equal(back, `'${danger}`, `${JSON.stringify(danger)} is written as text`);
  }
  assert.equal(csvCell('plain text'), 'plain text');
  assert.equal(csvCell('a, b'), '"a, b"');
  assert.equal(csvCell('say "hi"'), '"say ""hi"""');
  assert.equal(csvCell('two\nlines'), '"two\nlines"');
  assert.equal(csvCell(3), '3', 'numbers are written as numbers');
});

test('the gradebook CSV reads back, cell for cell, as the rows it was written from (escaped cells as text)', () => {
  const rows = [
    { file: 'a.json', student: '=cmd|\' /C calc\'!A0', exercise: 'x', title: 'T, with "quotes"', result: 'wrong', score: 0, checks: 3, hints: 1, worked: 'no', feedback: 'check', note: '', reason: 'row e3, column S:L\nand more' },
    { file: 'b.json', student: 'Ada', exercise: 'x', title: 'T', result: 'right', score: 1, checks: 1, hints: 0, worked: 'no', feedback: 'check', note: '@note', reason: '' },
  ];
  const records = parseCsv(gradebookCsv(rows));
  assert.deepEqual(records[0], COLUMNS.map(([, heading]) => heading));
  assert.equal(records.length, 3);
  rows.forEach((r, i) => COLUMNS.forEach(([key], k) => {
    const want = String(r[key]);
    assert.equal(records[i + 1][k], /^[=+\-@\t\r]/.test(want) ? `'${want}` : want, `row ${i + 1}, ${key}`);
  }));
});

test('Markdown cells hold one line and no character Markdown or HTML would read', () => {
  const cell = markdownCell('a | b <script>alert(1)</script> [x](javascript:y) *z*\nnext');
  assert.ok(!/(^|[^\\])[|<>[\]()*]/.test(cell), cell);
  assert.ok(!cell.includes('\n'));
});

test('a submission made here reads back intact; any edit to it is noticed by its digest', async () => {
  const made = await makeSubmission({ student: '  Ada Lovelace  ', app: api.version, entries: [{ id: 'mesh-walk-around-v2', hash: null, progress: { status: 'solved', checks: 2, answer: { picks: [4] }, title: 'Walk', lesson: 'mesh', kind: 'walk' } }] });
  assert.equal(made.student, 'Ada Lovelace', 'the name is kept as typed, without the spaces around it');
  const text = JSON.stringify(made, null, 2);
  const read = await readSubmission(text);
  assert.equal(read.intact, true);
  assert.equal(read.submission.exercises[0].checks, 2);
  const edited = JSON.parse(text);
  edited.exercises[0].status = 'solved';
  edited.exercises[0].checks = 1;
  assert.equal((await readSubmission(JSON.stringify(edited))).intact, false, 'an edited count breaks the digest');
});

test('a submission that cannot be used is refused in one sentence naming the field', async () => {
  const base = await makeSubmission({ student: 'Ada', app: '0.1.0', entries: [] });
  const cases = [
    ['', /it is empty/],
    ['{"format": "wingspline-submission", "version": 1, "exer', /not valid JSON.*damaged or cut short/],
    ['[1, 2]', /does not hold a submission/],
    [galleryText('mesh-walk-around-v2'), /it is an exercise, not a submission/],
    [JSON.stringify({ ...base, version: 7 }), /newer Wingspline \(submission version 7/],
    [JSON.stringify({ ...base, exercises: [{ id: 'x', hash: null, status: 'solved', checks: 'lots' }] }), /submission\.exercises\[0\]\.checks must be a whole number/],
    [JSON.stringify({ ...base, exercises: [{ id: 'Not An Id!', hash: null, status: 'solved', checks: 1 }] }), /submission\.exercises\[0\]\.id must be an exercise name/],
    [JSON.stringify({ ...base, exercises: [{ id: 'x', hash: 'md5-1', status: 'solved', checks: 1 }] }), /submission\.exercises\[0\]\.hash must be an exercise's content hash/],
    [JSON.stringify({ ...base, student: 5 }), /submission\.student must be text/],
  ];
  for (const [text, pattern] of cases) {
    await assert.rejects(readSubmission(text), (err) => err instanceof SubmissionError && pattern.test(err.message), `${text.slice(0, 60)} → ${pattern}`);
  }
});

test('damaged, oversized and foreign files are rows naming the file; an exercise with no entry is "not handed in"', async () => {
  const exerciseText = galleryText('mesh-walk-around-v2');
  const good = await makeSubmission({ student: 'Grace', app: '0.1.0', entries: [] });
  const big = { name: 'huge.json', size: MAX_SUBMISSION_BYTES + 1, read: () => { throw new Error('a file over the limit is never read'); } };
  const { rows, exercises, problems } = await gradeFiles({
    api, lessons: LESSON_OBJECTS, graders: {},
    files: [file('ex.json', exerciseText), file('cut.json', '{"format": "wingspline-submission", "ver'), big,
      file('notes.json', '{"hello": 1}'), file('grace.json', JSON.stringify(good))],
  });
  assert.deepEqual(problems, []);
  assert.equal(exercises.length, 1);
  const by = Object.fromEntries(rows.map((r) => [r.file, r]));
  assert.equal(by['cut.json'].result, RESULTS.damaged);
  assert.match(by['cut.json'].reason, /not valid JSON/);
  assert.equal(by['huge.json'].result, RESULTS.tooLarge);
  assert.match(by['huge.json'].reason, /4\.0 MB/);
  assert.equal(by['notes.json'].result, RESULTS.damaged);
  assert.match(by['notes.json'].reason, /not a Wingspline submission/);
  assert.equal(by['grace.json'].result, RESULTS.missing);
  assert.equal(by['grace.json'].score, 0);
  assert.match(by['grace.json'].note, /grace\.json; not verified/);
  const md = gradebookMarkdown(rows, { exercises, problems, app: api.version });
  for (const name of ['cut\\.json', 'huge\\.json', 'notes\\.json', 'grace\\.json']) assert.ok(md.includes(name), `${name} has its row`);
});

test('an entry for another version of the exercise is its own row, not graded', async () => {
  const exercise = parseExercise(galleryText('mesh-walk-around-v2'), { lessonIds });
  const other = { ...exercise, question: `${exercise.question} (changed)` };
  assert.notEqual(await exerciseHash(other), await exerciseHash(exercise));
  const sub = await makeSubmission({ student: 'Alan', app: '0.1.0', entries: [{ id: exercise.id, hash: await exerciseHash(other), progress: { status: 'solved', checks: 1, answer: { picks: [] } } }] });
  const { rows } = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: { walk: () => assert.fail('a different version is not graded') },
    files: [file('ex.json', galleryText('mesh-walk-around-v2')), file('alan.json', JSON.stringify(sub))] });
  assert.equal(rows.length, 1);
  assert.equal(rows[0].result, RESULTS.otherVersion);
  assert.match(rows[0].reason, /differs from your copy/);
  assert.equal(rows[0].score, '');
});

test('an exercise file that cannot be used is named, and the others are still graded', async () => {
  const broken = galleryText('mesh-walk-around-v2').replace('"lesson": "mesh"', '"lesson": "origami"');
  const { problems, exercises } = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: {},
    files: [file('bad-exercise.json', broken), file('ok.json', galleryText('comparison-hermite-mg'))] });
  assert.equal(exercises.length, 1);
  assert.equal(problems.length, 1);
  assert.match(problems[0], /^bad-exercise\.json: this exercise cannot be used: .*origami/);
});

test('the exercise files come first: one among the submissions neither replaces nor adds an exercise, and has its row', async () => {
  const real = galleryText('comparison-hermite-mg');
  const forged = JSON.parse(real);
  forged.question = `${forged.question} (forged)`;
  const bonus = { ...forged, id: 'bonus-exercise' };
  const sub = await makeSubmission({ student: 'Mallory', app: '0.1.0', entries: [] });
  const { rows, exercises } = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: {},
    files: [file('ex.json', real), file('mallory.json', JSON.stringify(sub)), file('forged.json', JSON.stringify(forged)), file('bonus.json', JSON.stringify(bonus))] });
  assert.equal(exercises.length, 1);
  assert.equal(exercises[0].exercise.question, JSON.parse(real).question, 'the lecturer\'s copy is the one graded against');
  const by = Object.fromEntries(rows.map((r) => [r.file, r]));
  assert.equal(by['forged.json'].result, RESULTS.exerciseAmongSubmissions);
  assert.equal(by['bonus.json'].result, RESULTS.exerciseAmongSubmissions);
  assert.ok(!rows.some((r) => r.exercise === 'bonus-exercise'));
  // The uploads given first: no exercise at all (the command then says to give them first).
  const first = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: {}, files: [file('mallory.json', JSON.stringify(sub)), file('ex.json', real)] });
  assert.equal(first.exercises.length, 0);
  assert.equal(first.rows.find((r) => r.file === 'ex.json').result, RESULTS.exerciseAmongSubmissions);
});

test('a file that cannot be read from the disk is a row naming it; the others are graded', async () => {
  const sub = await makeSubmission({ student: 'Grace', app: '0.1.0', entries: [] });
  const locked = { name: 'locked.json', size: 100, read: () => { throw new Error('EACCES: permission denied'); } };
  const { rows } = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: {},
    files: [file('ex.json', galleryText('mesh-walk-around-v2')), locked, file('grace.json', JSON.stringify(sub))] });
  const by = Object.fromEntries(rows.map((r) => [r.file, r]));
  assert.equal(by['locked.json'].result, RESULTS.damaged);
  assert.match(by['locked.json'].reason, /cannot be read from the disk: EACCES/);
  assert.equal(by['grace.json'].result, RESULTS.missing);
});

test('an entry with no answer is "not answered" (score 0); an answer the check cannot read is "could not be graded" (no score)', async () => {
  const text = galleryText('comparison-hermite-mg');
  const exercise = parseExercise(text, { lessonIds });
  const hash = await exerciseHash(exercise);
  const sub = await makeSubmission({ student: 'Ada', app: '0.1.0', entries: [{ id: exercise.id, hash, progress: { status: 'started', checks: 0, answer: '' } }] });
  const one = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: { value: () => assert.fail('an empty answer is not checked') },
    files: [file('ex.json', text), file('ada.json', JSON.stringify(sub))] });
  assert.equal(one.rows[0].result, RESULTS.unanswered);
  assert.equal(one.rows[0].score, 0);
  const answered = await makeSubmission({ student: 'Ada', app: '0.1.0', entries: [{ id: exercise.id, hash, progress: { status: 'started', checks: 1, answer: '1' } }] });
  const two = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: { [exercise.check.kind]: () => { throw new Error('the answer has no cells'); } },
    files: [file('ex.json', text), file('ada.json', JSON.stringify(answered))] });
  assert.equal(two.rows[0].result, RESULTS.ungradable);
  assert.match(two.rows[0].reason, /the answer could not be checked: the answer has no cells/);
  assert.equal(two.rows[0].score, '');
  // A kind this grader has no check for.
  const three = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: {}, files: [file('ex.json', text), file('ada.json', JSON.stringify(answered))] });
  assert.equal(three.rows[0].result, RESULTS.ungradable);
  assert.match(three.rows[0].reason, /has no check for the kind/);
});

test('the totals: one row per submission file, right of the exercises graded, as a percent', () => {
  const rows = [
    { file: 'a.json', student: 'Ada', score: 1 }, { file: 'a.json', student: 'Ada', score: 0 }, { file: 'a.json', student: 'Ada', score: 1 },
    { file: 'b.json', student: '=1+1', score: '' },
  ];
  const table = parseCsv(gradebookTotalsCsv(rows, 3));
  assert.deepEqual(table, [
    ['submission file', 'student (as typed, unverified)', 'right', 'of', 'percent'],
    ['a.json', 'Ada', '2', '3', '66.7'],
    ['b.json', "'=1+1", '0', '3', '0'],
  ]);
});

test('the grader grades the half-edge exercises: a right walk and a wrong table, by the core, as the page would', async () => {
  // Around v2 from h4, twin(prev(h)) gives h11, h9, h5 and back to h4 (worked by hand from
  // lecture 000's half-edge table, tests/helpers/lecture-slide.mjs); the table typed with
  // nothing but h1's origin, which is wrong, so it is graded wrong, naming the row and column.
  const walkText = galleryText('mesh-half-edge-walk-around-v2');
  const tableText = galleryText('mesh-half-edge-table-lecture');
  const walkExercise = parseExercise(walkText, { lessonIds });
  const tableExercise = parseExercise(tableText, { lessonIds });
  const sub = await makeSubmission({
    student: 'Ada', app: '0.1.0', entries: [
      { id: walkExercise.id, hash: await exerciseHash(walkExercise), progress: { status: 'solved', checks: 4, answer: { picks: [11, 9, 5, 4] } } },
      { id: tableExercise.id, hash: await exerciseHash(tableExercise), progress: { status: 'solved', checks: 1, answer: { 'halfedge:0:origin': 'v2' } } },
    ],
  });
  const { rows } = await gradeFiles({ api, lessons: LESSON_OBJECTS, graders: GRADERS,
    files: [file('walk.json', walkText), file('table.json', tableText), file('ada.json', JSON.stringify(sub))] });
  const by = Object.fromEntries(rows.map((r) => [r.exercise, r]));
  assert.equal(by['mesh-half-edge-walk-around-v2'].result, RESULTS.right);
  assert.equal(by['mesh-half-edge-walk-around-v2'].score, 1);
  assert.equal(by['mesh-half-edge-table-lecture'].result, RESULTS.wrong);
  assert.equal(by['mesh-half-edge-table-lecture'].score, 0);
  assert.match(by['mesh-half-edge-table-lecture'].reason, /Row h1, column origin: /);
  assert.match(by['mesh-half-edge-table-lecture'].note, /the file says solved; the check says not/);
});
