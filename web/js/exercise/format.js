// @ts-check
// The exercise file, described once: every field, what it may hold, and the
// sentence a person reads when it holds something else. docs/exercises.md explains each
// field with examples; this file is what reads them. The player (player.js), the authoring
// dialog (author.js), the gallery (pages/gallery.js) and the tests all read exercises here.
//
// An exercise is a lesson state (what the drawing shows), the panels hidden while it is
// answered, a question, and what is checked (`check`, one of the kinds of KINDS). Whole
// numbers in `check` are written as the lectures write them: vertices, edges, faces, joints,
// segments and matrix rows/columns from 1 (v1, e1, F1, the first joint); blending functions
// and control points from 0 (B₀,₃, P₀, Q₀).
import { SchemaError, object, text, oneOf, integer, number, list, checkNesting } from '../app/schema.js';

export const EXERCISE_FORMAT = 'wingspline-exercise';
export const EXERCISE_VERSION = 1;
// An exercise is a small file: a lesson state of a slide-sized example and a question.
export const MAX_EXERCISE_CHARS = 256 * 1024;
export const EXERCISE_ID = /^[a-z0-9][a-z0-9-]{0,63}$/;
// A mesh exercise is worked by hand: at most this many vertices and faces (the lectures'
// examples have under 10; a grid of 10 x 10 squares has 121 vertices and 200 triangles).
export const MAX_EXERCISE_ELEMENTS = 200;

export class ExerciseError extends Error {
  /** @param {string} message @param {string} [field] */
  constructor(message, field = '') {
    super(message);
    this.code = 'invalid-exercise';
    this.field = field;
  }
}

// The tables a student can fill in (kind 1), as the mesh lesson's tabs name them, with the
// columns an exercise may give (shown filled in) instead of blank.
export const TABLES = Object.freeze({
  'winged-edge': { label: 'the winged-edge tables (edge, vertex and face tables)', columns: ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight', 'vertexEdge', 'faceEdge'] },
  faces: { label: 'the face table (each face lists its vertices)', columns: [] },
  'edge-list': { label: 'the edge list (E = V₁, V₂, P₁, P₂) and the polygon table', columns: ['v1', 'v2', 'p1', 'p2'] },
  adjacency: { label: 'the adjacency lists (the vertices next to each vertex)', columns: [] },
  'half-edge': { label: 'the half-edge tables (half-edge, vertex and face tables)', columns: ['origin', 'face', 'next', 'prev', 'twin', 'vertexHalfedge', 'faceHalfedge'] },
});

// The structures a walk can be predicted on: the winged edge's edges (the lecture's walk) or
// the half-edges (around a vertex h -> twin(prev(h)), along a face h -> next(h)).
export const WALK_STRUCTURES = Object.freeze({ 'winged-edge': 'the winged edge (edges)', 'half-edge': 'the half-edge structure (half-edges)' });

// What kind 4 can ask, and the fields each needs (written as the lectures write them).
export const QUANTITIES = Object.freeze({
  blend: { label: 'a blending function at u', fields: ['i', 'u'] },
  point: { label: 'a point P(u) of the curve', fields: ['u'] },
  mg: { label: 'an entry of the product M G of a segment', fields: ['segment', 'row', 'col'] },
  boehm: { label: 'a new control point after inserting a knot (Boehm\'s rule)', fields: ['u', 'index'] },
  'patch-point': { label: 'a point p(u, v) of the patch', fields: ['u', 'v'] },
});

// What kind 5 can ask the student to make true by moving control points.
export const PROPERTIES = Object.freeze({
  'joint-class': { label: 'make a joint exactly Cᵏ (and Gᵏ)' },
  'passes-through': { label: 'make the curve pass through a point' },
});

// The kinds (the first five in the order they came, then the homework kinds). Which lessons offer a kind is the lesson's to say
// (its `exercise.kinds`, app/contract.js).
export const KINDS = Object.freeze({
  table: { label: 'Fill in a table' },
  walk: { label: 'Predict the next edge (or half-edge) of a walk' },
  joint: { label: 'Classify a joint (Cᵏ and Gᵏ) and say why' },
  value: { label: 'Compute a value by hand' },
  property: { label: 'Move control points until a property holds' },
  subdivide: { label: 'One subdivision step by hand' },
  edit: { label: 'Write the rows an edit rewrites' },
  code: { label: 'Write the code' },
});

// What a check tells the student (the author chooses; docs/exercises.md, "Feedback levels"):
// check: right or wrong, and where, with the rule to re-read, never the right value; hint: also
// a nudge per mistake once the student has checked hintAfter times wrongly; worked: also the
// worked answer on request (recorded in the progress).
export const FEEDBACK_LEVELS = Object.freeze({
  check: { label: 'Check only: where it is wrong and the rule, never the right value' },
  hint: { label: 'Check, then hints after a number of wrong tries' },
  worked: { label: 'Check, hints, and the worked answer on request (self-study)' },
});
export const DEFAULT_HINT_AFTER = 2;
// A file without `feedback` was written when the worked answer was always on offer: it keeps
// that (level worked), so an exercise handed out before levels existed behaves as it did.
// The authoring dialog writes the field, level check by default.
export const LEGACY_FEEDBACK = Object.freeze({ level: 'worked', hintAfter: DEFAULT_HINT_AFTER });

/** The exercise's feedback with the defaults filled in. @param {any} exercise @returns {{ level: 'check'|'hint'|'worked', hintAfter: number }} */
export function feedbackOf(exercise) {
  const f = exercise?.feedback;
  if (!f) return { ...LEGACY_FEEDBACK };
  return { level: f.level, hintAfter: f.hintAfter ?? DEFAULT_HINT_AFTER };
}

const positive = (v, path) => {
  const x = number({ min: 0, max: 1e9 })(v, path);
  if (!(x > 0)) throw new SchemaError(path, 'must be greater than 0');
  return x;
};
const ordinal = integer({ min: 1, max: 1e6 });
const index0 = integer({ min: 0, max: 1e6 });
const parameter = number({ min: -1e9, max: 1e9 });
const order = integer({ min: -1, max: 3 });

// The fields of `check`, per kind (optional ones listed).
const CHECKS = {
  table: [{ kind: oneOf('table'), table: oneOf(...Object.keys(TABLES)), given: list(text({ maxLength: 20 }), { max: 12 }) }, ['given']],
  walk: [{ kind: oneOf('walk'), around: oneOf('vertex', 'face'), element: ordinal, structure: oneOf(...Object.keys(WALK_STRUCTURES)) }, ['structure']],
  joint: [{ kind: oneOf('joint'), joint: ordinal }, []],
  value: [{
    kind: oneOf('value'), quantity: oneOf(...Object.keys(QUANTITIES)), tolerance: positive,
    i: index0, u: parameter, v: parameter, segment: ordinal, row: ordinal, col: ordinal, index: index0,
    family: text({ maxLength: 40 }),
  }, ['i', 'u', 'v', 'segment', 'row', 'col', 'index', 'family']],
  property: [{ kind: oneOf('property'), property: (v, path) => readProperty(v, path) }, []],
  subdivide: [{
    kind: oneOf('subdivide'), scheme: oneOf('loop', 'catmull-clark'), ask: oneOf('mask', 'counts'),
    point: object({ type: oneOf('vertex', 'edge', 'face'), element: ordinal }), steps: integer({ min: 1, max: 4 }),
  }, ['point', 'steps']],
  edit: [{ kind: oneOf('edit'), op: (v, path) => readEditOperation(v, path), structure: oneOf('winged-edge', 'half-edge') }, ['structure']],
  // The task is one of the code lesson's (its tasks.js ids); the lesson names an unknown one.
  code: [{ kind: oneOf('code'), task: text({ maxLength: 64 }) }, []],
};

// Kind subdivide: a mask question names its new point (and no steps: it is about one step);
// a counts question names no point. Loop makes no face points.
function readSubdivide(check, path) {
  if (check.ask === 'mask') {
    if (!check.point) throw new SchemaError(`${path}.point`, 'is missing (a mask question names the new point: {type: "vertex", "edge" or "face", element})');
    if (check.steps !== undefined) throw new SchemaError(`${path}.steps`, 'is only for ask "counts" (a mask question is about one step)');
    if (check.scheme === 'loop' && check.point.type === 'face') throw new SchemaError(`${path}.point.type`, 'is "face", but Loop\'s scheme makes no face points (use vertex or edge)');
  } else if (check.point) {
    throw new SchemaError(`${path}.point`, 'is only for ask "mask" (a counts question is about the whole mesh)');
  }
}

// An edit's operation as the lesson state stores it ({op: 'flip-edge', e: 3}), its elements
// counted from 1 as the lectures count them; which arguments an operation takes is the core
// registry's to say (the edit kind asks it, and names the field).
function readEditOperation(v, path) {
  if (v === null || v === undefined) throw new SchemaError(path, 'must name the operation asked, e.g. {"op": "flip-edge", "e": 3} (in the lesson: make the edit, then Make an exercise)');
  const op = object({ op: text({ maxLength: 40 }), e: ordinal, f: ordinal, v: ordinal, a: ordinal, b: ordinal, t: parameter },
    { optional: ['e', 'f', 'v', 'a', 'b', 't'] })(v, path);
  if (!/^[a-z][a-z-]*$/.test(op.op)) throw new SchemaError(`${path}.op`, `must be an operation's name such as flip-edge, not "${op.op}"`);
  return op;
}

function readProperty(v, path) {
  const kind = v && typeof v === 'object' ? v.kind : undefined;
  if (kind === 'joint-class') {
    const p = object({ kind: oneOf('joint-class'), joint: ordinal, parametric: order, geometric: order }, { optional: ['parametric', 'geometric'] })(v, path);
    if (p.parametric === undefined && p.geometric === undefined) throw new SchemaError(path, 'must name the class to reach: parametric (C^k), geometric (G^k) or both');
    return p;
  }
  if (kind === 'passes-through') {
    return object({ kind: oneOf('passes-through'), point: list(number(), { min: 2, max: 2 }), tolerance: positive, family: text({ maxLength: 40 }) }, { optional: ['family'] })(v, path);
  }
  return oneOf(...Object.keys(PROPERTIES))(kind, `${path}.kind`);
}

function readCheck(v, path) {
  const kind = v && typeof v === 'object' && !Array.isArray(v) ? v.kind : undefined;
  if (!Object.prototype.hasOwnProperty.call(CHECKS, kind)) {
    if (!v || typeof v !== 'object' || Array.isArray(v)) return object({})(v, path);
    return oneOf(...Object.keys(KINDS))(kind, `${path}.kind`);
  }
  const [shape, optional] = CHECKS[kind];
  const check = object(shape, { optional })(v, path);
  if (kind === 'value') {
    for (const field of QUANTITIES[check.quantity].fields) {
      if (check[field] === undefined) throw new SchemaError(`${path}.${field}`, `is missing (${QUANTITIES[check.quantity].label} needs ${QUANTITIES[check.quantity].fields.join(', ')})`);
    }
  }
  if (kind === 'subdivide') readSubdivide(check, path);
  if (kind === 'table') {
    const all = TABLES[check.table].columns;
    if (all.length && all.every((c) => check.given?.includes(c))) throw new SchemaError(`${path}.given`, 'gives every column: nothing is left to fill in');
    for (const [i, column] of (check.given ?? []).entries()) {
      if (!TABLES[check.table].columns.includes(column)) {
        throw new SchemaError(`${path}.given[${i}]`, TABLES[check.table].columns.length
          ? `must be a column of ${TABLES[check.table].label} (${TABLES[check.table].columns.join(', ')}), not "${column}"`
          : `must be empty: ${TABLES[check.table].label} has no column to give`);
      }
    }
  }
  return check;
}

const EXERCISE = object({
  format: oneOf(EXERCISE_FORMAT),
  version: integer({ min: 1, max: 1e6 }),
  id: (v, path) => {
    text({ maxLength: 64 })(v, path);
    if (!EXERCISE_ID.test(v)) throw new SchemaError(path, 'must be lower-case letters, digits and hyphens (at most 64), starting with a letter or digit');
    return v;
  },
  title: (v, path) => nonEmpty(v, path, 120),
  lesson: text({ maxLength: 40 }),
  source: text({ maxLength: 200 }),
  question: (v, path) => nonEmpty(v, path, 2000),
  stateVersion: integer({ min: 1, max: 1e6 }),
  state: (v, path) => {
    if (v === null || typeof v !== 'object' || Array.isArray(v)) throw new SchemaError(path, 'must be a lesson state (an object)');
    return v;
  },
  hide: list(text({ maxLength: 64 }), { max: 24 }),
  order: integer({ min: 0, max: 1e6 }),
  feedback: object({ level: oneOf(...Object.keys(FEEDBACK_LEVELS)), hintAfter: integer({ min: 1, max: 20 }) }, { optional: ['hintAfter'] }),
  check: readCheck,
}, { optional: ['id', 'source', 'hide', 'order', 'feedback'] });

function nonEmpty(v, path, maxLength) {
  const s = text({ maxLength })(v, path);
  if (s.trim() === '') throw new SchemaError(path, 'must not be empty');
  return s;
}

/**
 * Reads a parsed exercise: the outer fields and `check`; the state is read by the lesson
 * (readExerciseState). Throws an ExerciseError of one sentence naming the field.
 * @param {unknown} data
 * @param {{ lessonIds: string[] }} options
 */
export function readExercise(data, { lessonIds }) {
  if (data === null || typeof data !== 'object' || Array.isArray(data)) throw new ExerciseError('it does not hold an exercise (a JSON object)');
  const raw = /** @type {any} */ (data);
  if (raw.format !== EXERCISE_FORMAT) {
    throw new ExerciseError(raw.format === 'wingspline' ? 'it is a lesson state, not an exercise (open it with Import in the lesson)' : `it is not a Wingspline exercise (its "format" must be "${EXERCISE_FORMAT}")`, 'format');
  }
  if (Number.isSafeInteger(raw.version) && raw.version > EXERCISE_VERSION) {
    throw new ExerciseError(`it was made by a newer Wingspline (exercise version ${raw.version}; this page reads version ${EXERCISE_VERSION})`, 'version');
  }
  let exercise;
  try {
    // At most MAX_NESTING levels (app/limits.js), measured before anything walks the value.
    checkNesting(raw, 'exercise');
    exercise = EXERCISE(raw, 'exercise');
  } catch (err) {
    if (err instanceof SchemaError) throw new ExerciseError(`its field ${err.message}`, err.path);
    throw err;
  }
  if (!lessonIds.includes(exercise.lesson)) {
    throw new ExerciseError(`its field exercise.lesson names "${exercise.lesson.slice(0, 40)}", which is not a lesson (${lessonIds.join(', ')})`, 'exercise.lesson');
  }
  return exercise;
}

/**
 * Parses and reads exercise text (a file, a fetched gallery entry, a link's unpacked text).
 * @param {string} textValue
 * @param {{ lessonIds: string[] }} options
 */
export function parseExercise(textValue, options) {
  if (typeof textValue !== 'string' || textValue.trim() === '') throw new ExerciseError('it is empty');
  if (textValue.length > MAX_EXERCISE_CHARS) throw new ExerciseError(`it is ${Math.round(textValue.length / 1024)} KB, more than an exercise can be (${MAX_EXERCISE_CHARS / 1024} KB)`);
  let data;
  try {
    data = JSON.parse(textValue);
  } catch (err) {
    const at = /position (\d+)/.exec(String(err.message));
    const line = at ? textValue.slice(0, Number(at[1])).split('\n').length : null;
    throw new ExerciseError(`it is not valid JSON${line ? ` (line ${line})` : ''}`);
  }
  return readExercise(data, options);
}

/**
 * A new exercise object (the authoring dialog's output), read back through readExercise by
 * the caller before it is offered.
 * @param {{ id?: string, title: string, lesson: string, source?: string, question: string, stateVersion: number, state: any, hide?: string[], feedback?: { level: string, hintAfter?: number }, check: any }} fields
 */
export function exerciseOf({ id, title, lesson, source, question, stateVersion, state, hide, feedback, check }) {
  /** @type {any} */
  const out = { format: EXERCISE_FORMAT, version: EXERCISE_VERSION };
  if (id) out.id = id;
  Object.assign(out, { title, lesson });
  if (source) out.source = source;
  Object.assign(out, { question, stateVersion, state });
  if (hide?.length) out.hide = hide;
  if (feedback) out.feedback = feedback.level === 'check' ? { level: 'check' } : { level: feedback.level, hintAfter: feedback.hintAfter ?? DEFAULT_HINT_AFTER };
  out.check = check;
  return out;
}
