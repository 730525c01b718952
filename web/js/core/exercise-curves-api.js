// @ts-check
// Exercise part of the API for curves (kinds 3, 4 and 5; docs/api-curves.md,
// "Exercises: joints, values, properties"): classify a joint and say why, compute a value by
// hand, move points until a property holds. This module checks types and names the field;
// the core decides and writes the feedback.
import { unwrap, fail, isNumberArray } from './errors.js';
import { normalizeCurve } from './curves-api.js';

const DEFAULT_JOINT_TOLERANCE = 1e-9; // relative, the same as jointContinuity
const QUANTITIES = ['blend', 'point', 'mg', 'boehm', 'patch-point'];
const PROPERTIES = ['joint-class', 'passes-through'];
const INDEX_FIELDS = ['i', 'segment', 'row', 'col', 'index'];
const PARAMETER_FIELDS = ['u', 'v'];

function object(value, what, example) {
  if (value === null || typeof value !== 'object') fail('invalid-argument', `${what} must be an object like ${example}`);
  return value;
}

// A class k (whole number; the core checks -1..2) or undefined (not asked).
function optionalClass(value, what) {
  if (value === undefined || value === null) return [false, 0];
  if (!Number.isInteger(value)) fail('invalid-argument', `${what} must be a class k from -1 to 2, not ${String(value).slice(0, 40)}`);
  return [true, value];
}

function jointTolerance(tolerance) {
  if (typeof tolerance !== 'number' || !Number.isFinite(tolerance)) fail('invalid-argument', 'tolerance must be a finite number');
  return tolerance;
}

function finiteNumbers(value, what) {
  if (typeof value === 'number') return finiteNumbers([value], what);
  if (!isNumberArray(value)) fail('invalid-argument', `${what} must be an array of numbers (1 for a scalar, 2 or 3 for a point)`);
  const out = Float64Array.from(value);
  out.forEach((x, k) => { if (!Number.isFinite(x)) fail('non-finite-input', `${what}[${k}] is ${x}, not a finite number`); });
  return out;
}

// {curve} or {patch: {kind, points}} as the core reads it.
function valueSubject(subject) {
  object(subject, 'subject', "{ curve: { kind: 'bezier', dim: 2, points: [...] } } or { patch: { kind: 'bezier', points: [...] } }");
  if (subject.patch !== undefined) {
    const patch = object(subject.patch, 'subject.patch', "{ kind: 'bezier', points: [48 numbers] }");
    if (patch.kind !== 'hermite' && patch.kind !== 'bezier') {
      fail('unknown-basis', `subject.patch.kind must be 'hermite' or 'bezier', not ${JSON.stringify(patch.kind)?.slice(0, 40)}`);
    }
    return { isPatch: true, curve: null, patchKind: patch.kind, patchPoints: finiteNumbers(patch.points, 'subject.patch.points') };
  }
  return { isPatch: false, curve: normalizeCurve(subject.curve, 'subject.curve'), patchKind: '', patchPoints: new Float64Array(0) };
}

// {quantity, i?, segment?, row?, col?, index?, u?, v?}: absent fields go as null; the core
// names the ones a quantity needs.
function valueAsk(ask) {
  object(ask, 'ask', "{ quantity: 'blend', i: 1, u: 0.5 }");
  if (!QUANTITIES.includes(ask.quantity)) {
    fail('unknown-quantity', `ask.quantity is ${JSON.stringify(ask.quantity)?.slice(0, 40)}; expected ${QUANTITIES.join(', ')}`);
  }
  const out = { quantity: ask.quantity };
  for (const k of INDEX_FIELDS) {
    const x = ask[k];
    if (x !== undefined && x !== null && (!Number.isInteger(x) || Math.abs(x) > 2 ** 31 - 1)) {
      fail('invalid-argument', `ask.${k} must be a whole number (0-based), not ${String(x).slice(0, 40)}`);
    }
    out[k] = x ?? null;
  }
  for (const k of PARAMETER_FIELDS) {
    const x = ask[k];
    if (x !== undefined && x !== null && typeof x !== 'number') fail('invalid-argument', `ask.${k} must be a number`);
    if (typeof x === 'number' && !Number.isFinite(x)) fail('non-finite-input', `ask.${k} is ${x}, not a finite number`);
    out[k] = x ?? null;
  }
  return out;
}

const workedOut = (r) => ({ expected: Array.from(r.expected), label: r.label, working: Array.from(r.working) });

export function createExerciseCurvesApi(raw) {
  return {
    // Kind 3: the statements about the joint of a's end (P) and b's start (Q) a student ticks
    // as true: [{id, statement}], ids 'meet', 'equal-first', 'same-direction', 'equal-second',
    // 'equal-curvature' (exactly the statements that decide jointContinuity's verdict).
    jointReasons() {
      return Array.from(unwrap(raw.exerciseJointReasons()).reasons, ({ id, statement }) => ({ id, statement }));
    },
    // The classes a student picks from: {parametric: [{k, label, requires}], geometric: [...]},
    // k = -1..2; requires: the statement ids the class needs. The verdict stops at 2: the
    // class k = 2 reads "C² (or smoother)".
    jointClasses() {
      const r = unwrap(raw.exerciseJointClasses());
      const list = (l) => Array.from(l, ({ k, label, requires }) => ({ k, label, requires: Array.from(requires) }));
      return { parametric: list(r.parametric), geometric: list(r.geometric) };
    },
    // {correct, findings: [{field: 'parametric'|'geometric'|<reason id>, given, expected,
    // reason, message, hint}], worked: {parametric, geometric, why, explanation}}. A field left out of the
    // answer is not checked. Classes are numbers k; reason findings give booleans (ticked / true).
    checkJointAnswer(a, b, answer = {}, { tolerance = DEFAULT_JOINT_TOLERANCE } = {}) {
      object(answer, 'answer', "{ parametric: 1, geometric: 1, why: ['meet', 'equal-first'] }");
      const [hasP, p] = optionalClass(answer.parametric, 'answer.parametric');
      const [hasG, g] = optionalClass(answer.geometric, 'answer.geometric');
      const hasWhy = answer.why !== undefined && answer.why !== null;
      if (hasWhy && (!Array.isArray(answer.why) || !answer.why.every((x) => typeof x === 'string'))) {
        fail('invalid-argument', 'answer.why must be a list of statement ids (see jointReasons())');
      }
      const r = unwrap(raw.exerciseCheckJoint(normalizeCurve(a, 'a'), normalizeCurve(b, 'b'), jointTolerance(tolerance),
        hasP, p, hasG, g, hasWhy, hasWhy ? answer.why : []));
      const w = r.worked;
      return {
        correct: r.correct,
        findings: Array.from(r.findings, ({ field, given, expected, reason, message, hint }) => ({ field, given, expected, reason, message, hint })),
        worked: { parametric: w.parametric, geometric: w.geometric, why: Array.from(w.why), explanation: Array.from(w.explanation) },
      };
    },
    // Kind 4: the value asked, its label in the lectures' notation and the worked lines:
    // {expected: number[], label, working: string[]}.
    workedValue(subject, ask) {
      return workedOut(unwrap(raw.exerciseWorkedValue(valueSubject(subject), valueAsk(ask))));
    },
    // {correct, expected, distance (Euclidean; Infinity for a wrong count), label, working,
    // reason ('' when right), code ('' | 'not-within' | 'wrong-count'), message and hint (the
    // value-free words: what was asked in the question's terms, the formula; a nudge)};
    // tolerance: absolute, in the units of the quantity. As many numbers as the value has are
    // expected: another count is a wrong answer (code 'wrong-count'), not an error.
    checkValueAnswer(subject, ask, given, tolerance) {
      if (typeof tolerance !== 'number') fail('invalid-argument', 'tolerance must be a number (absolute, in the units of the value)');
      const r = unwrap(raw.exerciseCheckValue(valueSubject(subject), valueAsk(ask), finiteNumbers(given, 'given'), tolerance));
      return { correct: r.correct, ...workedOut(r), distance: r.distance, reason: r.reason, code: r.code, message: r.message, hint: r.hint };
    },
    // Kind 5: {holds, reason, measured}. property {kind: 'joint-class', parametric?, geometric?,
    // tolerance?} with subject {a, b}; {kind: 'passes-through', point, tolerance (relative to
    // the control polygon's diameter)} with subject {curve}.
    checkCurveProperty(subject, property) {
      object(subject, 'subject', '{ a, b } or { curve }');
      object(property, 'property', "{ kind: 'joint-class', parametric: 1 }");
      if (!PROPERTIES.includes(property.kind)) {
        fail('unknown-property', `property.kind is ${JSON.stringify(property.kind)?.slice(0, 40)}; expected ${PROPERTIES.join(' or ')}`);
      }
      if (property.kind === 'joint-class') {
        const [hasP, p] = optionalClass(property.parametric, 'property.parametric');
        const [hasG, g] = optionalClass(property.geometric, 'property.geometric');
        const r = unwrap(raw.exerciseJointClass(normalizeCurve(subject.a, 'subject.a'), normalizeCurve(subject.b, 'subject.b'),
          jointTolerance(property.tolerance ?? DEFAULT_JOINT_TOLERANCE), hasP, p, hasG, g));
        return { holds: r.holds, reason: r.reason, measured: { parametric: r.parametric, geometric: r.geometric, why: Array.from(r.why) } };
      }
      if (typeof property.tolerance !== 'number') fail('invalid-argument', 'property.tolerance must be a number (relative to the control polygon\'s size)');
      const r = unwrap(raw.exercisePassesThrough(normalizeCurve(subject.curve, 'subject.curve'), finiteNumbers(property.point, 'property.point'),
        property.tolerance));
      return {
        holds: r.holds,
        reason: r.reason,
        measured: { distance: r.distance, relativeDistance: r.relativeDistance, size: r.size, u: r.u, closest: Array.from(r.closest) },
      };
    },
  };
}
