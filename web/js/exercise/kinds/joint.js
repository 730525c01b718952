// @ts-check
// Kind 3: classify a joint of a piecewise curve (C^k and G^k) and say why (lectures 000,
// 001, 002, 004). The classes and the statements come from the core (api.jointClasses,
// api.jointReasons); the core checks the answer against its own measurement of the joint
// (api.checkJointAnswer), scale-free, and explains it with the measured evidence.
import { h } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { findingOf, incomplete, isPlainObject, unreadable } from './grading.js';

function jointOf(check, subject) {
  const joints = subject.joints;
  if (!joints) throw new ExerciseError('this lesson has no joints to classify', 'exercise.check.kind');
  if (check.joint > joints.length) throw new ExerciseError(`its field exercise.check.joint is ${check.joint}, but the curve has ${joints.length} joint${joints.length === 1 ? '' : 's'}`, 'exercise.check.joint');
  return joints[check.joint - 1];
}

/**
 * Grades a classification {parametric, geometric, why} (the page's answer). Pure: no DOM.
 * @param {{ api: any, check: any, subject: any, answer: unknown }} parts
 * @returns {import('./grading.js').GradeResult}
 */
export function gradeJoint({ api, check, subject, answer }) {
  const shape = 'a classification {parametric: k or null, geometric: k or null, why: [statement ids]}';
  if (!isPlainObject(answer)) return unreadable(shape);
  const a = /** @type {any} */ (answer);
  const classOk = (k) => k === null || k === undefined || (Number.isInteger(k) && k >= -1 && k <= 2);
  const ids = api.jointReasons().map((r) => r.id);
  const why = a.why ?? [];
  if (!classOk(a.parametric) || !classOk(a.geometric) || !Array.isArray(why) || !why.every((x) => ids.includes(x))) return unreadable(shape);
  const missing = [a.parametric == null ? 'the parametric class (Cᵏ)' : null, a.geometric == null ? 'the geometric class (Gᵏ)' : null].filter(Boolean);
  if (missing.length) return incomplete(`Choose ${missing.join(' and ')} first.`);
  const { a: first, b: second } = jointOf(check, subject);
  const r = api.checkJointAnswer(first, second, { parametric: a.parametric, geometric: a.geometric, why });
  return { correct: r.correct, findings: r.findings.map((f) => findingOf(f.message, f.hint)) };
}

/** The worked answer: the measured evidence, statement by statement. @param {{ api: any, check: any, subject: any }} parts */
export function workedJoint({ api, check, subject }) {
  const { a: first, b: second } = jointOf(check, subject);
  return { lines: api.checkJointAnswer(first, second, {}).worked.explanation };
}

/** @param {any} parts */
export function createJointKind({ api, check, subject }) {
  jointOf(check, subject());
  const classes = api.jointClasses();
  const reasons = api.jointReasons();
  const radioGroup = (name, title, options) => {
    const inputs = options.map((o) => /** @type {HTMLInputElement} */ (h('input', { type: 'radio', name: `exercise-${name}`, value: String(o.k), id: `exercise-${name}-${o.k}` })));
    const root = h('fieldset', { class: 'exercise-choices' }, h('legend', {}, title),
      options.map((o, i) => h('label', { class: 'choice', for: `exercise-${name}-${o.k}` }, inputs[i], o.label)));
    return { root, inputs };
  };
  const parametric = radioGroup('parametric', 'Parametric continuity', classes.parametric);
  const geometric = radioGroup('geometric', 'Geometric continuity', classes.geometric);
  const why = reasons.map((r) => /** @type {HTMLInputElement} */ (h('input', { type: 'checkbox', value: r.id, id: `exercise-why-${r.id}` })));
  const whyBox = h('fieldset', { class: 'exercise-why' }, h('legend', {}, 'Why: tick every statement that holds at this joint'),
    reasons.map((r, i) => h('label', { class: 'choice', for: `exercise-why-${r.id}` }, why[i], r.statement)));
  const root = h('div', { class: 'exercise-joint' }, parametric.root, geometric.root, whyBox);
  const picked = (group) => {
    const x = group.inputs.find((i) => i.checked);
    return x ? Number(x.value) : null;
  };
  const answer = () => ({ parametric: picked(parametric), geometric: picked(geometric), why: why.filter((w) => w.checked).map((w) => w.value) });
  return {
    root,
    answer,
    restore(saved) {
      if (!saved || typeof saved !== 'object') return;
      for (const [group, k] of [[parametric, saved.parametric], [geometric, saved.geometric]]) for (const i of group.inputs) i.checked = i.value === String(k);
      if (Array.isArray(saved.why)) for (const w of why) w.checked = saved.why.includes(w.value);
    },
    check: () => gradeJoint({ api, check, subject: subject(), answer: answer() }),
    worked: () => workedJoint({ api, check, subject: subject() }),
  };
}
