// @ts-check
// The grader behind `wingspline grade` (scripts/wingspline.mjs; docs/exercises.md, "Handing
// in and grading"): the lecturer's exercise files and the students' submission files in, one
// gradebook row per submission file and exercise out. Every answer is checked again by the
// core through its kind's grade function (graders.js), from the lecturer's copy of the
// exercise; nothing a submission says of itself (solved, its checks) decides a grade. A file
// that cannot be used (too large, not JSON, not a submission, edited fields of the wrong shape)
// is a row naming the file and the reason, never a crash. DOM-free: it runs in Node.
import { parseExercise, ExerciseError } from './format.js';
import { readExerciseState } from './player.js';
import { readSubmission, exerciseHash, MAX_SUBMISSION_BYTES, SubmissionError } from './submission.js';
import { MAX_EXERCISE_CHARS } from './format.js';
import { readEnvelope } from '../app/share-link.js';

// The gradebook's columns, in order: [key, heading].
export const COLUMNS = Object.freeze([
  ['file', 'submission file'],
  ['student', 'student (as typed, unverified)'],
  ['exercise', 'exercise'],
  ['title', 'title'],
  ['result', 'result'],
  ['score', 'score'],
  // What the student's browser recorded: the file says so, and a student who edits the file
  // can change it (its digest is no secret), so the headings say where the figures come from.
  ['checks', 'checks (as the file says)'],
  ['hints', 'hints shown (as the file says)'],
  ['worked', 'worked answer seen (as the file says)'],
  ['feedback', 'feedback level (as the file says)'],
  ['note', 'note'],
  ['reason', 'reason'],
]);

// The results a row can hold. `right` scores 1; wrong, not answered and not handed in score 0;
// the others score nothing (the lecturer looks at the file).
export const RESULTS = Object.freeze({
  right: 'right',
  wrong: 'wrong',
  unanswered: 'not answered',
  missing: 'not handed in',
  otherVersion: 'answered a different version',
  ungradable: 'could not be graded',
  damaged: 'damaged file',
  tooLarge: 'file too large',
  exerciseAmongSubmissions: 'an exercise file among the submissions',
});

const MAX_REASON_CHARS = 2000;
const MAX_FINDINGS = 12;
const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
const sizeWords = (bytes) => (bytes >= 1024 * 1024 ? `${(bytes / (1024 * 1024)).toFixed(1)} MB` : `${Math.ceil(bytes / 1024)} KB`);

/**
 * A file handed to the grader: its name (as the lecturer's folder names it), its size in bytes,
 * and its text (read only after the size was found acceptable).
 * @typedef {{ name: string, size: number, read: () => string | Promise<string> }} GradeFile
 */

/**
 * Sorts files by what they hold, in the order given (`grade EXERCISES... SUBMISSIONS...`):
 * the exercise files come first; anything else is taken for a student's submission (the
 * uploads are the files that may be damaged). An exercise file after the first submission is
 * in the uploads, where a student could have put it: it never adds or replaces an exercise,
 * and has a row of its own. Each file is read once; one that cannot be read is a row too.
 * @param {GradeFile[]} files
 */
async function sortFiles(files) {
  const exercises = [];
  const submissions = [];
  for (const file of files) {
    if (file.size > Math.max(MAX_SUBMISSION_BYTES, MAX_EXERCISE_CHARS)) {
      submissions.push({ name: file.name, size: file.size, text: null });
      continue;
    }
    let text;
    try {
      text = String(await file.read());
    } catch (err) {
      submissions.push({ name: file.name, size: file.size, text: null, unreadable: String(err?.message ?? err) });
      continue;
    }
    let format = null;
    try {
      format = JSON.parse(text)?.format ?? null;
    } catch {
      // not JSON: a damaged submission row says so
    }
    if (format !== 'wingspline-exercise') submissions.push({ name: file.name, size: file.size, text });
    else if (submissions.length) submissions.push({ name: file.name, size: file.size, text, exercise: true });
    else exercises.push({ name: file.name, size: file.size, text });
  }
  return { exercises, submissions };
}

/**
 * Grades submission files against exercise files. `run`: the code sandbox's (web/js/code/
 * quickjs-node.js under Node), for the code kind's submitted functions.
 * @param {{ api: any, files: GradeFile[], lessons: Record<string, any>, graders: Record<string, Function>, run?: (request: any) => Promise<any> }} parts
 * @returns {Promise<{ rows: any[], exercises: any[], problems: string[] }>}
 */
export async function gradeFiles({ api, files, lessons, graders, run }) {
  const sorted = await sortFiles(files);
  const lessonIds = Object.keys(lessons);
  const problems = [];
  /** @type {Array<{ file: string, exercise: any, hash: string, state: any }>} */
  const exercises = [];
  for (const file of sorted.exercises) {
    try {
      const exercise = parseExercise(file.text, { lessonIds });
      const state = readExerciseState(lessons[exercise.lesson], exercise);
      const hash = await exerciseHash(exercise);
      if (exercises.some((x) => x.hash === hash)) continue; // the same exercise given twice
      if (exercise.id && exercises.some((x) => x.exercise.id === exercise.id)) {
        problems.push(`${file.name}: another exercise file has the id "${exercise.id}"; this one is left out (give each exercise its own id)`);
        continue;
      }
      exercises.push({ file: file.name, exercise, hash, state });
    } catch (err) {
      problems.push(`${file.name}: this exercise cannot be used: ${err.message}`);
    }
  }
  const rows = [];
  for (const file of sorted.submissions) rows.push(...await gradeSubmission({ api, file, exercises, lessons, graders, run }));
  return { rows, exercises, problems };
}

async function gradeSubmission({ api, file, exercises, lessons, graders, run }) {
  const fileRow = (result, reason) => row({ file: file.name, result, reason });
  if (file.unreadable !== undefined) return [fileRow(RESULTS.damaged, `the file cannot be read from the disk: ${file.unreadable}`)];
  if (file.exercise) {
    return [fileRow(RESULTS.exerciseAmongSubmissions, 'an exercise file given after the first submission (in the uploads): it is neither graded nor used as an exercise; give the exercise files first')];
  }
  if (file.text === null) {
    return [fileRow(RESULTS.tooLarge, `the file is ${sizeWords(file.size)}; a submission is at most ${sizeWords(MAX_SUBMISSION_BYTES)}, so it was not read`)];
  }
  let read;
  try {
    read = await readSubmission(file.text);
  } catch (err) {
    if (!(err instanceof SubmissionError)) throw err;
    return [fileRow(RESULTS.damaged, `the file cannot be read: ${err.message}`)];
  }
  const { submission, intact } = read;
  const notes = [`name as typed in the file ${file.name}; not verified`];
  if (!intact) notes.push('the file was changed after it was exported (its digest does not match): its answers were graded as they are');
  if (!exercises.length) return [row({ file: file.name, student: submission.student, result: RESULTS.missing, note: notes.join('; '), reason: 'no exercise file could be used, so nothing was graded' })];
  const out = [];
  for (const x of exercises) {
    const base = { file: file.name, student: submission.student, exercise: x.exercise.id ?? x.hash.slice(7, 19), title: x.exercise.title };
    // The entry for this exercise: the same content first; a shipped exercise also by its id.
    const entries = submission.exercises;
    const same = entries.find((e) => e.hash === x.hash);
    const byId = !same && x.exercise.id ? entries.find((e) => e.id === x.exercise.id) : null;
    const entry = same ?? byId;
    if (!entry) {
      out.push(row({ ...base, result: RESULTS.missing, score: 0, note: notes.join('; ') }));
      continue;
    }
    const facts = {
      checks: entry.checks,
      hints: entry.hintsShown ?? 0,
      worked: entry.sawWorked ? 'yes' : 'no',
      feedback: entry.feedback || '',
    };
    const entryNotes = [...notes];
    if (byId && entry.hash) {
      out.push(row({ ...base, ...facts, result: RESULTS.otherVersion, note: entryNotes.join('; '),
        reason: `the submission answered a version of "${x.exercise.id}" whose content differs from your copy (its hash ${entry.hash.slice(7, 19)}…, yours ${x.hash.slice(7, 19)}…); it was not graded` }));
      continue;
    }
    if (byId) entryNotes.push('the file does not say which version of the exercise was answered (saved before submissions carried it); graded against your copy');
    const graded = await gradeEntry({ api, x, entry, lessons, graders, run });
    if (graded.result === RESULTS.wrong && entry.status === 'solved') entryNotes.push('the file says solved; the check says not');
    out.push(row({ ...base, ...facts, ...graded, note: entryNotes.join('; ') }));
  }
  return out;
}

// One answer checked again: the subject from the lecturer's exercise (or, for the kinds whose
// drawing is the answer, from the drawing in the file, read through the lesson's schema).
async function gradeEntry({ api, x, entry, lessons, graders, run }) {
  const { exercise } = x;
  const lesson = lessons[exercise.lesson];
  const kind = exercise.check.kind;
  const grade = graders[kind];
  if (!grade) return { result: RESULTS.ungradable, reason: `this grader has no check for the kind "${kind}"` };
  const support = lesson.exercise;
  const drawingIsAnswer = Boolean(support?.keepsState?.includes(kind));
  const empty = (v) => v === null || v === undefined || v === '';
  if (drawingIsAnswer ? !entry.state || typeof entry.state !== 'object' : empty(entry.answer)) {
    return { result: RESULTS.unanswered, score: 0 };
  }
  try {
    let state = x.state;
    if (drawingIsAnswer) {
      let read;
      try {
        read = readEnvelope(lesson, { format: 'wingspline', lesson: lesson.id, version: lesson.stateVersion, state: entry.state });
      } catch (err) {
        return { result: RESULTS.ungradable, reason: `the drawing in the file cannot be read: ${err.message}` };
      }
      if (read.problems.length) return { result: RESULTS.ungradable, reason: `the drawing in the file cannot be read: its field ${read.problems[0]}` };
      state = read.state;
    }
    const model = support.usesModel ? lesson.compute({}, state, { api }) : null;
    const subject = support.subject({}, model, state, { api });
    const r = await grade({ api, check: exercise.check, subject, answer: entry.answer ?? null, support, run });
    if (r.correct) return { result: RESULTS.right, score: 1 };
    const findings = (r.findings ?? []).map((f) => (typeof f === 'string' ? f : f.text));
    const reason = findings.slice(0, MAX_FINDINGS).join(' | ') + (findings.length > MAX_FINDINGS ? ` | … and ${findings.length - MAX_FINDINGS} more` : '');
    return { result: r.incomplete && !findings.length ? RESULTS.unanswered : RESULTS.wrong, score: 0, reason: reason || (r.partial ? 'right so far, not finished' : '') };
  } catch (err) {
    const why = err instanceof ExerciseError ? err.message : String(err?.message ?? err);
    return { result: RESULTS.ungradable, reason: `the answer could not be checked: ${why}` };
  }
}

function row(fields) {
  return {
    file: '', student: '', exercise: '', title: '', result: '', score: '', checks: '', hints: '', worked: '', feedback: '', note: '', reason: '',
    ...fields,
  };
}

// ---- the gradebook files

// A spreadsheet runs a cell that starts with =, +, - or @ (and tab or carriage return, which
// some read past): such a text cell is written with a leading apostrophe, shown as text.
const DANGEROUS_START = /^[=+\-@\t\r]/;
export function csvCell(value) {
  if (typeof value === 'number') return String(value);
  let s = String(value ?? '');
  if (s.length > MAX_REASON_CHARS) s = `${s.slice(0, MAX_REASON_CHARS)}…`;
  if (DANGEROUS_START.test(s)) s = `'${s}`;
  return /[",\r\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

// CSV (RFC 4180, CRLF line ends, a header row) of `rows` under `columns` ([key, heading]).
function csvOf(columns, rows) {
  const lines = [columns.map(([, heading]) => csvCell(heading)).join(',')];
  for (const r of rows) lines.push(columns.map(([key]) => csvCell(r[key])).join(','));
  return `${lines.join('\r\n')}\r\n`;
}

/** The gradebook as CSV, one row per submission file and exercise. */
export function gradebookCsv(rows) {
  return csvOf(COLUMNS, rows);
}

// Per submission file, in the rows' order: {file, student, right, of, percent}, `of` being
// the number of exercises graded against (the totals CSV and the Markdown summary).
function totalsPerFile(rows, exerciseCount) {
  const byFile = new Map();
  for (const r of rows) {
    if (!byFile.has(r.file)) byFile.set(r.file, { file: r.file, student: r.student, right: 0, of: exerciseCount, percent: 0 });
    if (r.score === 1) byFile.get(r.file).right += 1;
  }
  for (const t of byFile.values()) t.percent = exerciseCount ? Math.round((1000 * t.right) / exerciseCount) / 10 : 0;
  return [...byFile.values()];
}

// One row per submission file: the figure to carry into a course's gradebook (docs/exercises.md
// says how with Moodle and Canvas). `of` is the number of exercises graded against.
export const TOTAL_COLUMNS = Object.freeze([
  ['file', 'submission file'], ['student', 'student (as typed, unverified)'], ['right', 'right'], ['of', 'of'], ['percent', 'percent'],
]);
/** @param {any[]} rows @param {number} exerciseCount */
export function gradebookTotalsCsv(rows, exerciseCount) {
  return csvOf(TOTAL_COLUMNS, totalsPerFile(rows, exerciseCount));
}

// Markdown cells: one line, every character Markdown or HTML would read escaped.
export function markdownCell(value) {
  let s = String(value ?? '').replace(/[\r\n]+/g, ' ');
  if (s.length > MAX_REASON_CHARS) s = `${s.slice(0, MAX_REASON_CHARS)}…`;
  return s.replace(/[\\`*_{}[\]()#+\-.!|<>&~]/g, (c) => `\\${c}`);
}

/**
 * The gradebook as Markdown: a summary per submission file, then the table.
 * @param {any[]} rows @param {{ exercises: any[], problems: string[], app: string }} about
 */
export function gradebookMarkdown(rows, { exercises, problems, app }) {
  const totals = totalsPerFile(rows, exercises.length);
  const out = [
    '# Gradebook',
    '',
    `Graded by Wingspline ${markdownCell(app)}: every answer checked again by the core. ${plural(exercises.length, 'exercise')}, ${plural(totals.length, 'submission file')}. Names are as the students typed them; they are not verified.`,
    '',
  ];
  if (problems.length) out.push('## Exercise files left out', '', ...problems.map((p) => `- ${markdownCell(p)}`), '');
  out.push('## Per file', '', '| submission file | student | right | of |', '| --- | --- | --- | --- |');
  for (const t of totals) out.push(`| ${markdownCell(t.file)} | ${markdownCell(t.student)} | ${t.right} | ${t.of} |`);
  out.push('', '## Every answer', '', `| ${COLUMNS.map(([, h]) => markdownCell(h)).join(' | ')} |`, `| ${COLUMNS.map(() => '---').join(' | ')} |`);
  for (const r of rows) out.push(`| ${COLUMNS.map(([key]) => markdownCell(r[key])).join(' | ')} |`);
  return `${out.join('\n')}\n`;
}
