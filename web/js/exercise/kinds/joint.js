// @ts-check
// Kind 3: classify a joint of a piecewise curve (C^k and G^k) and say why (lectures 000,
// 001, 002, 004). The classes and the statements come from the core (api.jointClasses,
// api.jointReasons); the core checks the answer against its own measurement of the joint
// (api.checkJointAnswer), scale-free, and explains it with the measured evidence.
import { h } from '../../app/dom.js';
import { ExerciseError } from '../format.js';

/** @param {any} parts */
export function createJointKind({ api, check, subject }) {
  const jointOf = () => {
    const joints = subject().joints;
    if (!joints) throw new ExerciseError('this lesson has no joints to classify', 'exercise.check.kind');
    if (check.joint > joints.length) throw new ExerciseError(`its field exercise.check.joint is ${check.joint}, but the curve has ${joints.length} joint${joints.length === 1 ? '' : 's'}`, 'exercise.check.joint');
    return joints[check.joint - 1];
  };
  jointOf();
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
    check() {
      const a = answer();
      const missing = [a.parametric === null ? 'the parametric class (Cᵏ)' : null, a.geometric === null ? 'the geometric class (Gᵏ)' : null].filter(Boolean);
      if (missing.length) return { correct: false, incomplete: true, findings: [`Choose ${missing.join(' and ')} first.`] };
      const { a: first, b: second } = jointOf();
      const r = api.checkJointAnswer(first, second, a);
      return { correct: r.correct, findings: r.findings.map((f) => f.reason) };
    },
    worked() {
      const { a: first, b: second } = jointOf();
      const r = api.checkJointAnswer(first, second, answer());
      return { lines: r.worked.explanation };
    },
  };
}
