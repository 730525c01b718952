// @ts-check
// Kind 4: compute a value by hand (a blending function at u, a point P(u), an entry of M G,
// a knot inserted by Boehm's rule, a patch point) within the tolerance the exercise states.
// The student types a number, a fraction (3/8) or a point (1.5, 2); the core computes the
// value, compares and shows the working (api.checkValueAnswer).
import { h } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { findingOf, incomplete, unreadable } from './grading.js';

// "0.375", "3/8", "-1/6", "(1.5, 2)", "1.5 2": the numbers typed, or a sentence.
export function readNumbers(raw) {
  const s = raw.trim().replace(/^[([]\s*/, '').replace(/\s*[)\]]$/, '').replace(/−/g, '-');
  if (s === '') return { problem: 'Type your answer first.' };
  const parts = s.split(/\s*[,;]\s*|\s+/).filter((p) => p !== '');
  const out = [];
  for (const p of parts) {
    const m = /^([+-]?(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?)(?:\/([+-]?(?:\d+\.?\d*|\.\d+)))?$/i.exec(p);
    if (!m) return { problem: `"${p.slice(0, 20)}" is not a number (write a decimal such as d.ddd, a fraction p/q, or a point as x, y).` };
    const x = Number(m[1]) / (m[2] === undefined ? 1 : Number(m[2]));
    if (!Number.isFinite(x)) return { problem: `"${p.slice(0, 20)}" is not a finite number.` };
    out.push(x);
  }
  return { value: out };
}

// The core's ask from the exercise's check (indices as the lectures write them, see
// format.js) and the subject it is asked of.
export function askOf(check, subject) {
  const { quantity } = check;
  let of;
  if (quantity === 'patch-point') of = subject.patch ? { patch: subject.patch } : null;
  else if (check.family !== undefined) of = subject.curves?.[check.family] ? { curve: subject.curves[check.family] } : null;
  else of = subject.curve ? { curve: subject.curve } : null;
  if (!of) {
    throw new ExerciseError(check.family !== undefined ? `its field exercise.check.family names "${check.family}", which this lesson does not draw` : `this lesson has nothing to ask ${quantity} of`, check.family !== undefined ? 'exercise.check.family' : 'exercise.check.quantity');
  }
  const ask = { quantity };
  if (check.i !== undefined) ask.i = check.i;
  if (check.u !== undefined) ask.u = check.u;
  if (check.v !== undefined) ask.v = check.v;
  if (check.index !== undefined) ask.index = check.index;
  if (check.segment !== undefined) ask.segment = check.segment - 1;
  if (check.row !== undefined) ask.row = check.row - 1;
  if (check.col !== undefined) ask.col = check.col - 1;
  return { of, ask };
}

/**
 * Grades a typed value (the page's answer: the text as typed). Pure: no DOM.
 * @param {{ api: any, check: any, subject: any, answer: unknown }} parts
 * @returns {import('./grading.js').GradeResult}
 */
export function gradeValue({ api, check, subject, answer }) {
  if (typeof answer !== 'string' || answer.length > 200) return unreadable('a number or a point, typed as text');
  const typed = readNumbers(answer);
  if (typed.problem) return incomplete(typed.problem);
  const { of, ask } = askOf(check, subject);
  const r = api.checkValueAnswer(of, ask, typed.value, check.tolerance);
  return { correct: r.correct, findings: r.correct ? [] : [findingOf(r.message, r.hint)] };
}

/** The worked answer: the core's working and the value. @param {{ api: any, check: any, subject: any }} parts */
export function workedValue({ api, check, subject }) {
  const { of, ask } = askOf(check, subject);
  const r = api.workedValue(of, ask);
  return { lines: [...r.working, `${r.label} = ${r.expected.map((x) => String(Number(x.toPrecision(6)))).join(', ')}`] };
}

/** @param {any} parts */
export function createValueKind({ api, check, subject }) {
  // Asked once now: a question the core cannot answer for this drawing is refused at once.
  try {
    const { of, ask } = askOf(check, subject());
    api.workedValue(of, ask);
  } catch (err) {
    if (err instanceof ExerciseError) throw err;
    throw new ExerciseError(`its check cannot be asked of this drawing: ${err.message}`, 'exercise.check');
  }
  const input = /** @type {HTMLInputElement} */ (h('input', { type: 'text', class: 'exercise-value', id: 'exercise-value', inputmode: 'text', autocomplete: 'off', spellcheck: 'false' }));
  const root = h('div', { class: 'exercise-value-box' },
    h('label', { for: 'exercise-value' }, 'Your answer'), input,
    // The format in letters: an example number could be this exercise's answer (3/8 was B₁,₃(½)'s).
    h('p', { class: 'hint' }, `A decimal (d.ddd), a fraction (p/q), or a point (x, y). Within ${check.tolerance} of the exact value counts as right.`));
  return {
    root,
    answer: () => input.value,
    restore(saved) { if (typeof saved === 'string') input.value = saved.slice(0, 200); },
    focus: () => input.focus(),
    check: () => gradeValue({ api, check, subject: subject(), answer: input.value }),
    worked: () => workedValue({ api, check, subject: subject() }),
  };
}
