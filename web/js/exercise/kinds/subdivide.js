// @ts-check
// Kind "subdivide": one step of Loop's or Catmull-Clark's scheme by hand. Either
//  * ask 'mask': which mask makes a given new point (the vertex point of v2, the edge point
//    of e3, the face point of F1; interior or boundary), and the point as exact fractions of
//    old vertices named as the drawing labels them ("v1: 3/8"); or
//  * ask 'counts': V, E and F after the step (or a few steps).
// The core checks both exactly (api.checkSubdivideMask, api.checkSubdivideCounts: rational
// arithmetic, no tolerance) and names where the answer is wrong and the rule to re-read,
// never the right value; the values are only in the worked answer.
//
// The subject is the lesson's `{ subdivision: { mesh, scheme } }` (exercise/subjects.js):
// the old mesh of the step asked about, numbered as the drawing labels it.
import { h, setChildren } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { refuseLargeMesh } from '../subjects.js';

export const SCHEME_NAMES = Object.freeze({ loop: 'Loop', 'catmull-clark': 'Catmull-Clark' });
// The masks a student chooses among, per scheme (Loop makes no face points), in the core's names.
export const MASK_LABELS = Object.freeze({
  'face-point': 'Face mask',
  'edge-interior': 'Interior edge mask',
  'edge-boundary': 'Boundary edge mask',
  'vertex-interior': 'Interior vertex mask',
  'vertex-boundary': 'Boundary vertex mask',
});
const MASKS_OF = Object.freeze({
  loop: ['edge-interior', 'edge-boundary', 'vertex-interior', 'vertex-boundary'],
  'catmull-clark': ['face-point', 'edge-interior', 'edge-boundary', 'vertex-interior', 'vertex-boundary'],
});
const COUNT_FIELDS = Object.freeze([['vertices', 'V', 'vertices'], ['edges', 'E', 'edges'], ['faces', 'F', 'faces']]);
// An answer holds at most this many rows, each entry at most this long (an answer may come
// from a file: anything larger is not an answer).
const MAX_ROWS = 64;
const MAX_TEXT = 40;
// The digits a typed number may have (beyond them a double is not exact).
const MAX_DIGITS = 15;
const PREFIX = { vertex: 'v', edge: 'e', face: 'F' };
// The page's examples of a weight are p/q and 2/7, never a fraction a mask of the lectures'
// meshes has (3/8, 1/8, 1/16, ...): an example on the page must not be an answer.

/** "the edge point of e3" */
export function pointWords(point) {
  return `the ${point.type} point of ${PREFIX[point.type]}${point.element}`;
}

const unreadable = (why) => ({ correct: false, incomplete: true, findings: [{ text: `This answer could not be read: ${why}.` }] });
const incomplete = (texts) => ({ correct: false, incomplete: true, findings: texts.map((text) => ({ text })) });
const sentence = (s) => `${s[0].toUpperCase()}${s.slice(1)}`;

/**
 * An old point as the drawing labels it ("v3", "V3" or "3") -> its 0-based index.
 * @param {string} raw
 * @returns {{ vertex: number } | { problem: string }}
 */
export function readOldPoint(raw) {
  const m = /^\s*v?\s*(\d{1,9})\s*$/i.exec(raw);
  if (!m) return { problem: `"${raw.trim().slice(0, 20)}" is not an old point's label (write it as the drawing does, e.g. v3)` };
  const n = Number(m[1]);
  if (n < 1) return { problem: `"${raw.trim().slice(0, 20)}" names no vertex (the drawing counts from v1)` };
  return { vertex: n - 1 };
}

/**
 * A weight typed as a fraction ("3/8", "-1/8"), a whole number ("1", "0") or a finite
 * decimal ("0.375", read exactly as 375/1000) -> {num, den} whole numbers (den > 0).
 * @param {string} raw
 * @returns {{ num: number, den: number } | { problem: string }}
 */
export function readFraction(raw) {
  const s = raw.trim().replace(/−/g, '-');
  const shown = `"${s.slice(0, 20)}"`;
  const fraction = /^([+-]?)(\d+)\s*\/\s*(\d+)$/.exec(s);
  const decimal = /^([+-]?)(\d*)(?:\.(\d*))?$/.exec(s);
  if (fraction) {
    if (fraction[2].length > MAX_DIGITS || fraction[3].length > MAX_DIGITS) return { problem: `${shown} has more digits than a weight needs` };
    const den = Number(fraction[3]);
    if (den === 0) return { problem: `${shown} divides by 0` };
    return { num: (fraction[1] === '-' ? -1 : 1) * Number(fraction[2]), den };
  }
  if (decimal && (decimal[2] || decimal[3])) {
    const digits = `${decimal[2]}${decimal[3] ?? ''}`;
    if (digits.length > MAX_DIGITS) return { problem: `${shown} has more digits than a weight needs` };
    return { num: (decimal[1] === '-' ? -1 : 1) * Number(digits || '0'), den: 10 ** (decimal[3]?.length ?? 0) };
  }
  return { problem: `${shown} is not a fraction (write it as p/q, such as 2/7, a whole number or a decimal such as 0.25)` };
}

function isText(x) {
  return typeof x === 'string' && x.length <= MAX_TEXT;
}

// The answer's shape (it may come from a file): a reason it cannot be read, or null.
function shapeProblem(check, answer) {
  if (answer === null || typeof answer !== 'object' || Array.isArray(answer)) return 'it is not an object';
  if (check.ask === 'counts') {
    for (const [key] of COUNT_FIELDS) if (!isText(answer[key])) return `its ${key} is not a short text`;
    return null;
  }
  if (answer.mask !== null && !(typeof answer.mask === 'string' && Object.prototype.hasOwnProperty.call(MASK_LABELS, answer.mask))) return 'its mask is not one of the masks';
  if (!Array.isArray(answer.rows) || answer.rows.length > MAX_ROWS) return `its rows are not a list of at most ${MAX_ROWS}`;
  for (const [i, row] of answer.rows.entries()) {
    if (row === null || typeof row !== 'object' || !isText(row.point) || !isText(row.weight)) return `its row ${i + 1} is not an old point and a weight`;
  }
  return null;
}

function subdivisionOf(subject) {
  const s = subject?.subdivision;
  if (!s?.mesh) throw new ExerciseError('this lesson has no subdivision step to ask about', 'exercise.check.kind');
  return s;
}

const plainFindings = (list) => list.map(({ text, hint }) => (hint ? { text, hint } : { text }));

function gradeMask(api, check, mesh, answer) {
  // Trailing empty rows are rows not used yet; an empty row between others is a gap to fill.
  const rows = [...answer.rows];
  while (rows.length && !rows[rows.length - 1].point.trim() && !rows[rows.length - 1].weight.trim()) rows.pop();
  if (!rows.length) return incomplete([answer.mask ? 'Give the old points the new point averages, each with its weight.' : 'Choose the mask, then give the old points the new point averages, each with its weight.']);
  const problems = [];
  const read = rows.map((row, i) => {
    const where = `Row ${i + 1}`;
    if (!row.point.trim() && !row.weight.trim()) { problems.push(`${where} is empty: fill it in or remove it.`); return null; }
    if (!row.point.trim()) { problems.push(`${where}: name the old point (e.g. v3).`); return null; }
    if (!row.weight.trim()) { problems.push(`${where}: type the weight of ${row.point.trim().slice(0, 20)} as a fraction p/q.`); return null; }
    const p = readOldPoint(row.point);
    const w = readFraction(row.weight);
    if ('problem' in p) { problems.push(`${where}: ${p.problem}.`); return null; }
    if ('problem' in w) { problems.push(`${where}: ${w.problem}.`); return null; }
    return { vertex: p.vertex, num: w.num, den: w.den };
  });
  if (problems.length) return incomplete(problems);
  const point = { type: check.point.type, element: check.point.element - 1 };
  const r = api.checkSubdivideMask(mesh, { scheme: check.scheme, point, mask: answer.mask, rows: read });
  if (r.correct) return { correct: true, findings: [], note: `${MASK_LABELS[answer.mask]}, ${rows.length} old point${rows.length === 1 ? '' : 's'}.` };
  return { correct: false, findings: plainFindings(r.findings) };
}

function gradeCounts(api, check, mesh, answer) {
  const given = {};
  const problems = [];
  for (const [key, letter, words] of COUNT_FIELDS) {
    const s = answer[key].trim();
    if (!/^\d{1,12}$/.test(s)) {
      problems.push(s ? `${letter}: "${s.slice(0, 20)}" is not a whole number of ${words}.` : `${letter}: type the number of ${words}.`);
    }
    given[key] = Number(s);
  }
  if (problems.length) return incomplete(problems);
  const r = api.checkSubdivideCounts(mesh, { scheme: check.scheme, steps: check.steps ?? 1, ...given });
  return r.correct ? { correct: true, findings: [] } : { correct: false, findings: plainFindings(r.findings) };
}

/**
 * Grades an answer (what the page kind's answer() returns; it may come from a file) against
 * the core. Pure and DOM-free: runs in Node over loadWingspline().
 * @param {{ api: any, check: any, subject: any, answer: any }} parts
 * @returns {{ correct: boolean, partial?: boolean, incomplete?: boolean, findings: Array<{ text: string, hint?: string }>, note?: string }}
 */
export function gradeSubdivide({ api, check, subject, answer }) {
  const why = shapeProblem(check, answer);
  if (why) return unreadable(why);
  const { mesh } = subdivisionOf(subject);
  return check.ask === 'counts' ? gradeCounts(api, check, mesh, answer) : gradeMask(api, check, mesh, answer);
}

/**
 * The worked answer: the mask and every weight with why it is there (mask), or the counts
 * before and after (counts). The only place the values are shown.
 * @param {{ api: any, check: any, subject: any }} parts
 * @returns {{ lines: string[] }}
 */
export function workedSubdivide({ api, check, subject }) {
  const { mesh } = subdivisionOf(subject);
  const scheme = SCHEME_NAMES[check.scheme];
  if (check.ask === 'counts') {
    const before = api.subdivisionCounts(mesh, { scheme: check.scheme, steps: 0 });
    const steps = check.steps ?? 1;
    const after = api.subdivisionCounts(mesh, { scheme: check.scheme, steps });
    return {
      lines: [
        `The mesh drawn: V = ${before.vertices}, E = ${before.edges}, F = ${before.faces}.`,
        `After ${steps === 1 ? 'one' : steps} ${scheme} step${steps === 1 ? '' : 's'}: V = ${after.vertices}, E = ${after.edges}, F = ${after.faces}.`,
      ],
    };
  }
  const point = { type: check.point.type, element: check.point.element - 1 };
  const s = api.subdivideStencil(mesh, { scheme: check.scheme, point });
  const fraction = ({ num, den }) => (den === 1 ? String(num) : `${num}/${den}`);
  return {
    lines: [
      `${sentence(pointWords(check.point))} is made by the ${MASK_LABELS[s.rule].toLowerCase()} (${scheme}).`,
      ...Array.from(s.vertices, (v, i) => `v${v + 1}: ${fraction(s.weights[i])} (${s.roles[i]})`),
      'The weights add up to 1.',
    ],
  };
}

/** @param {any} parts */
export function createSubdivideKind({ api, check, subject, support, ctx }) {
  const sub = subdivisionOf(subject());
  refuseLargeMesh(sub.mesh);
  if (sub.scheme !== check.scheme) {
    throw new ExerciseError(`its field exercise.check.scheme is ${check.scheme}, but the drawing shows ${SCHEME_NAMES[sub.scheme] ?? sub.scheme} subdivision`, 'exercise.check.scheme');
  }
  // Asked once now: a point the core cannot ask about (no such element, Loop's beta at
  // valence 5) refuses the exercise at once, with the core's sentence.
  let marked = null; // the old vertices the drawing marks: the asked vertex, edge's ends or face's corners
  try {
    if (check.ask === 'mask') marked = askedCorners(api, check, sub.mesh);
    else api.subdivisionCounts(sub.mesh, { scheme: check.scheme, steps: check.steps ?? 1 });
  } catch (err) {
    if (err instanceof ExerciseError) throw err;
    throw new ExerciseError(`its check cannot be asked of this drawing: ${err.message}`, 'exercise.check');
  }
  const ui = check.ask === 'counts' ? countsForm(check) : maskForm(check);
  const current = () => ui.answer();
  return {
    root: ui.root,
    answer: current,
    restore(saved) { if (!shapeProblem(check, saved)) ui.restore(saved); },
    focus: () => ui.focus(),
    check: () => gradeSubdivide({ api, check, subject: subject(), answer: current() }),
    worked: () => workedSubdivide({ api, check, subject: subject() }),
    draw(painter, colors) {
      if (marked) support.markSubdividePoint?.(ctx, painter, colors, { corners: marked, type: check.point.type, label: `${PREFIX[check.point.type]}${check.point.element}` });
    },
  };
}

// The asked element's old vertices (for the drawing's mark), checked by the core first.
function askedCorners(api, check, mesh) {
  const point = { type: check.point.type, element: check.point.element - 1 };
  api.subdivideStencil(mesh, { scheme: check.scheme, point });
  if (point.type === 'vertex') return [point.element];
  if (point.type === 'face') return Array.from(mesh.faceVertices.subarray(mesh.faceOffsets[point.element], mesh.faceOffsets[point.element + 1]));
  const built = api.buildMesh(mesh);
  try {
    const { edges } = built.wingedEdgeArrays();
    return [edges[8 * point.element], edges[8 * point.element + 1]];
  } finally {
    built.dispose();
  }
}

// ---------------------------------------------------------------- the page's forms

function maskForm(check) {
  const what = pointWords(check.point);
  const masks = MASKS_OF[check.scheme];
  const group = h('div', { class: 'exercise-choices', role: 'radiogroup', 'aria-label': `The mask that makes ${what}` });
  const radios = masks.map((m) => {
    const input = /** @type {HTMLInputElement} */ (h('input', { type: 'radio', name: 'exercise-mask', value: m, id: `exercise-mask-${m}` }));
    group.append(h('label', { class: 'choice', for: `exercise-mask-${m}` }, input, MASK_LABELS[m]));
    return input;
  });
  const body = h('tbody', {});
  const addButton = h('button', { type: 'button', id: 'exercise-add-row', onclick: () => { addRow('', ''); focusRow(rows.length - 1); } }, 'Add an old point');
  /** @type {Array<{ tr: HTMLElement, point: HTMLInputElement, weight: HTMLInputElement }>} */
  const rows = [];

  function renumber() {
    rows.forEach((r, i) => {
      r.point.setAttribute('aria-label', `Row ${i + 1}: old point`);
      r.weight.setAttribute('aria-label', `Row ${i + 1}: weight`);
      r.tr.querySelector('button')?.setAttribute('aria-label', `Remove row ${i + 1}`);
      r.tr.dataset.row = String(i + 1);
    });
  }
  function addRow(point, weight) {
    if (rows.length >= MAX_ROWS) return;
    const p = /** @type {HTMLInputElement} */ (h('input', { type: 'text', class: 'exercise-old-point', autocomplete: 'off', spellcheck: 'false', placeholder: 'v1', value: point, size: 5 }));
    const w = /** @type {HTMLInputElement} */ (h('input', { type: 'text', class: 'exercise-weight', autocomplete: 'off', spellcheck: 'false', inputmode: 'text', placeholder: 'p/q', value: weight, size: 8 }));
    const row = { tr: h('tr', {}), point: p, weight: w };
    const remove = h('button', { type: 'button', class: 'exercise-remove-row', onclick: () => removeRow(row) }, '✕');
    setChildren(row.tr, h('td', {}, p), h('td', {}, w), h('td', {}, remove));
    body.append(row.tr);
    rows.push(row);
    renumber();
  }
  function removeRow(row) {
    const i = rows.indexOf(row);
    if (i < 0) return;
    row.tr.remove();
    rows.splice(i, 1);
    if (!rows.length) addRow('', '');
    renumber();
    focusRow(Math.min(i, rows.length - 1));
    body.dispatchEvent(new Event('change', { bubbles: true })); // the player keeps the answer
  }
  function focusRow(i) { rows[i]?.point.focus(); }
  addRow('', '');
  // Keys in the grid: Alt+Insert (or Alt+N) adds a row after this one's, Alt+Delete removes this row.
  body.addEventListener('keydown', (event) => {
    const at = rows.findIndex((r) => r.tr.contains(/** @type {Node} */ (event.target)));
    if (at < 0 || !event.altKey) return;
    if (event.key === 'Insert' || event.key === 'n' || event.key === 'N') {
      event.preventDefault();
      addRow('', '');
      const last = rows.pop();
      rows.splice(at + 1, 0, /** @type {any} */ (last));
      rows[at].tr.after(rows[at + 1].tr);
      renumber();
      focusRow(at + 1);
    } else if (event.key === 'Delete') {
      event.preventDefault();
      removeRow(rows[at]);
    }
  });
  const root = h('div', { class: 'exercise-subdivide' },
    h('fieldset', {}, h('legend', {}, `Which mask makes ${what}?`), group),
    h('table', { class: 'data-table exercise-weights', id: 'exercise-weights' },
      h('caption', {}, `${what[0].toUpperCase()}${what.slice(1)} as fractions of old points`),
      h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'Old point'), h('th', { scope: 'col' }, 'Weight'), h('th', { scope: 'col' }, h('span', { class: 'visually-hidden' }, 'Remove')))),
      body),
    h('p', {}, addButton),
    h('p', { class: 'hint' }, 'Name old points as the drawing labels them (v1, v2, …) and type exact fractions p/q. Alt+N adds a row, Alt+Delete removes the row you are in.'));
  return {
    root,
    answer: () => ({ mask: radios.find((r) => r.checked)?.value ?? null, rows: rows.map((r) => ({ point: r.point.value.slice(0, MAX_TEXT), weight: r.weight.value.slice(0, MAX_TEXT) })) }),
    restore(saved) {
      for (const r of radios) r.checked = r.value === saved.mask;
      for (const r of [...rows]) r.tr.remove();
      rows.length = 0;
      for (const r of saved.rows) addRow(r.point, r.weight);
      if (!rows.length) addRow('', '');
    },
    focus: () => (radios.find((r) => r.checked) ?? radios[0]).focus(),
  };
}

function countsForm(check) {
  const steps = check.steps ?? 1;
  const fields = COUNT_FIELDS.map(([key, letter, words]) => ({
    key, letter, words,
    input: /** @type {HTMLInputElement} */ (h('input', {
      type: 'text', inputmode: 'numeric', autocomplete: 'off', id: `exercise-count-${key}`, class: 'exercise-count', size: 6, 'aria-label': `${letter}: the number of ${words}`,
    })),
  }));
  const after = `after ${steps === 1 ? 'one step' : `${steps} steps`} of ${SCHEME_NAMES[check.scheme]}'s scheme`;
  const root = h('div', { class: 'exercise-subdivide exercise-counts' },
    h('fieldset', {}, h('legend', {}, `The counts ${after}`),
      fields.map((f) => h('p', {}, h('label', { for: `exercise-count-${f.key}` }, `${f.letter} (${f.words}) `), f.input))));
  return {
    root,
    answer: () => Object.fromEntries(fields.map((f) => [f.key, f.input.value.slice(0, MAX_TEXT)])),
    restore(saved) { for (const f of fields) f.input.value = saved[f.key]; },
    focus: () => fields[0].input.focus(),
  };
}
