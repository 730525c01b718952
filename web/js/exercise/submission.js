// @ts-check
// The submission file a student hands in (docs/exercises.md, "Handing in and grading"):
// who says they are (typed, unverified), which exercises (a shipped one's id, any one's
// content hash), and per exercise what was done in this browser: the answer as typed (the
// drawing, for the kinds whose drawing is the answer), the checks used, the hints shown,
// whether the worked answer was seen, the feedback level. Nothing in it is trusted by the
// grader (grade.js): it re-checks every answer with the core; the file's own "solved" is
// shown to the student only. The same reader serves the grader and the tests; the gallery
// page writes the file (pages/gallery.js).
import { SchemaError, object, text, oneOf, integer, list, boolean, nullable, checkNesting } from '../app/schema.js';
import { stringifyExact, sha256 } from '../app/share-link.js';
import { EXERCISE_ID } from './format.js';

export const SUBMISSION_FORMAT = 'wingspline-submission';
export const SUBMISSION_VERSION = 1;
// A submission holds answers to hand-sized exercises: a table of 200 edges, a drawing. A file
// larger than this is refused by name before it is read (an upload folder may hold anything).
export const MAX_SUBMISSION_BYTES = 4 * 1024 * 1024;
export const MAX_SUBMISSION_EXERCISES = 500;
const HASH = /^sha256-[0-9a-f]{64}$/;

export class SubmissionError extends Error {
  /** @param {string} message @param {string} [field] */
  constructor(message, field = '') {
    super(message);
    this.code = 'invalid-submission';
    this.field = field;
  }
}

/**
 * The content hash of an exercise as read (format.js readExercise): the key that tells the
 * version a student answered from the lecturer's copy. Equal exercises have equal hashes
 * whatever their file's spacing, as long as both were read by readExercise.
 * @param {any} exercise
 */
export function exerciseHash(exercise) {
  return sha256(stringifyExact(exercise));
}

// What one exercise entry holds (all fields checked; the answer's own shape is the kind's to
// read, in its grade function, which treats it as untrusted).
const ENTRY = object({
  id: nullable((v, path) => {
    text({ maxLength: 64 })(v, path);
    if (!EXERCISE_ID.test(v)) throw new SchemaError(path, 'must be an exercise name (lower-case letters, digits and hyphens)');
    return v;
  }),
  hash: nullable((v, path) => {
    text({ maxLength: 80 })(v, path);
    if (!HASH.test(v)) throw new SchemaError(path, 'must be an exercise\'s content hash (sha256- and 64 hex digits)');
    return v;
  }),
  title: text({ maxLength: 120 }),
  lesson: text({ maxLength: 40 }),
  kind: text({ maxLength: 40 }),
  feedback: text({ maxLength: 20 }),
  status: oneOf('started', 'solved'),
  checks: integer({ min: 0, max: 1e9 }),
  hintsShown: integer({ min: 0, max: 1e9 }),
  sawWorked: boolean(),
  answer: (v) => v,
  state: (v) => v,
}, { optional: ['title', 'lesson', 'kind', 'feedback', 'hintsShown', 'sawWorked', 'answer', 'state'] });

const BODY = object({
  format: oneOf(SUBMISSION_FORMAT),
  version: integer({ min: 1, max: SUBMISSION_VERSION }),
  app: text({ maxLength: 40 }),
  student: text({ maxLength: 200 }),
  madeAt: text({ maxLength: 40 }),
  exercises: list(ENTRY, { max: MAX_SUBMISSION_EXERCISES }),
  digest: text({ maxLength: 80 }),
}, { optional: ['madeAt', 'digest'] });

// The digest covers everything but itself: a file edited by hand (or damaged on the way)
// no longer matches. It is no signature (anyone can recompute it): the grader says so in the
// row, and grades the answers as they are, which it checks itself anyway.
const digestOf = (body) => sha256(stringifyExact(body));

/**
 * A submission from this browser's progress entries.
 * @param {{ student: string, app: string, entries: Array<{ id: string | null, hash: string | null, progress: any }>, now?: Date }} parts
 */
export async function makeSubmission({ student, app, entries, now = new Date() }) {
  const exercises = entries.map(({ id, hash, progress: p }) => {
    /** @type {any} */
    const out = {
      id: id ?? null,
      hash: hash ?? p.hash ?? null,
      title: String(p.title ?? '').slice(0, 120),
      lesson: String(p.lesson ?? ''),
      kind: String(p.kind ?? ''),
      feedback: String(p.feedback ?? ''),
      status: p.status === 'solved' ? 'solved' : 'started',
      checks: Number.isSafeInteger(p.checks) && p.checks >= 0 ? p.checks : 0,
      hintsShown: Number.isSafeInteger(p.hintsShown) && p.hintsShown >= 0 ? p.hintsShown : 0,
      sawWorked: Boolean(p.sawWorked),
      answer: p.answer ?? null,
    };
    if (p.state && typeof p.state === 'object') out.state = p.state;
    return out;
  });
  const body = { format: SUBMISSION_FORMAT, version: SUBMISSION_VERSION, app, student: student.trim().slice(0, 200), madeAt: now.toISOString(), exercises };
  return { ...body, digest: await digestOf(body) };
}

/**
 * Reads a submission's text. Throws a SubmissionError of one sentence naming the field;
 * returns the submission and whether its digest still matches its content.
 * @param {string} textValue
 * @returns {Promise<{ submission: any, intact: boolean }>}
 */
export async function readSubmission(textValue) {
  if (typeof textValue !== 'string' || textValue.trim() === '') throw new SubmissionError('it is empty');
  let data;
  try {
    data = JSON.parse(textValue);
  } catch (err) {
    const at = /position (\d+)/.exec(String(err.message));
    const line = at ? textValue.slice(0, Number(at[1])).split('\n').length : null;
    throw new SubmissionError(`it is not valid JSON${line ? ` (line ${line})` : ''}: the file may be damaged or cut short`);
  }
  if (data === null || typeof data !== 'object' || Array.isArray(data)) throw new SubmissionError('it does not hold a submission (a JSON object)');
  if (data.format !== SUBMISSION_FORMAT) {
    throw new SubmissionError(data.format === 'wingspline-exercise' ? 'it is an exercise, not a submission' : `it is not a Wingspline submission (its "format" must be "${SUBMISSION_FORMAT}")`, 'format');
  }
  if (Number.isSafeInteger(data.version) && data.version > SUBMISSION_VERSION) {
    throw new SubmissionError(`it was made by a newer Wingspline (submission version ${data.version}; this grader reads version ${SUBMISSION_VERSION})`, 'version');
  }
  let submission;
  try {
    checkNesting(data, 'submission');
    submission = BODY(data, 'submission');
  } catch (err) {
    if (err instanceof SchemaError) throw new SubmissionError(`its field ${err.message}`, err.path);
    throw err;
  }
  const intact = typeof data.digest === 'string' && data.digest === await digestOf(stripDigest(data));
  return { submission, intact };
}

const stripDigest = (data) => {
  const { digest: _, ...body } = data;
  return body;
};
