// @ts-check
// "Make an exercise from this view": the lesson's state as shown becomes an
// exercise. The dialog starts from the lesson's suggestion for a kind (its `exercise.suggest`),
// lets the author choose what is checked, what is hidden and the question, reads the result
// back exactly as a student's page will (format.js, the lesson's state schema, the kind's
// checks against the drawing), and then offers the JSON file and a link.
import { h, setChildren } from '../app/dom.js';
import { download } from '../app/file-io.js';
import { stringifyExact } from '../app/share-link.js';
import { lessons } from '../lessons/registry.js';
import { KINDS, TABLES, WALK_STRUCTURES, QUANTITIES, FEEDBACK_LEVELS, DEFAULT_HINT_AFTER, exerciseOf, parseExercise } from './format.js';
import { readExerciseState, CREATE } from './player.js';
import { exerciseUrl } from './link.js';
import { loadWingspline } from '../core/wingspline.js';

const lessonIds = lessons.map((l) => l.id);

// The fields of `check` the dialog offers per kind: name, label, and either options or a number.
/** @returns {Array<{ name: string, label: string, type: string, options?: any, min?: number, max?: number, step?: any }>} */
function fieldsOf(kind, subject) {
  const num = (name, label, extra = {}) => ({ name, label, type: 'number', ...extra });
  const pick = (name, label, options) => ({ name, label, type: 'select', options });
  if (kind === 'table') {
    return [pick('table', 'Table to fill in', Object.fromEntries(Object.entries(TABLES).map(([k, v]) => [k, v.label]))),
      { name: 'given', label: 'Columns given (comma-separated: start, end, left, …; empty for none)', type: 'list' }];
  }
  if (kind === 'edit') return []; // the operation is the lesson's last edit (its suggestion)
  if (kind === 'code') return []; // the task is the one shown (its suggestion)
  if (kind === 'walk') {
    return [pick('around', 'Walk', { vertex: 'around a vertex', face: 'along a face' }), num('element', 'Vertex or face number (1-based)', { min: 1, step: 1 }),
      pick('structure', 'Structure walked', WALK_STRUCTURES)];
  }
  if (kind === 'joint') return [num('joint', 'Joint (1 = the first)', { min: 1, step: 1 })];
  if (kind === 'subdivide') {
    return [pick('scheme', 'Scheme (the drawing\'s)', { loop: 'Loop', 'catmull-clark': 'Catmull-Clark' }), pick('ask', 'Ask', { mask: 'the mask and weights of a new point', counts: 'the counts V, E, F after the step' }),
      pick('point.type', 'New point (mask)', { vertex: 'the vertex point of', edge: 'the edge point of', face: 'the face point of' }), num('point.element', 'Old element (1-based: v1, e1, F1)', { min: 1, step: 1 }),
      num('steps', 'Steps (counts; empty: 1)', { min: 1, max: 4, step: 1 })];
  }
  if (kind === 'value') {
    const quantities = Object.fromEntries(Object.entries(QUANTITIES).filter(([k]) => (k === 'patch-point' ? Boolean(subject.patch) : !subject.patch)).map(([k, v]) => [k, v.label]));
    return [pick('quantity', 'Value to compute', quantities),
      ...(subject.curves ? [pick('family', 'Family', Object.fromEntries(Object.keys(subject.curves).map((f) => [f, f])))] : []),
      num('i', 'i (the blending function Bᵢ, from 0)', { min: 0, step: 1 }), num('u', 'u', { step: 'any' }), num('v', 'v', { step: 'any' }),
      num('segment', 'Segment (from 1)', { min: 1, step: 1 }), num('row', 'Row of M G (from 1)', { min: 1, step: 1 }), num('col', 'Column of M G (from 1)', { min: 1, step: 1 }),
      num('index', 'The new control point Qᵢ: i (from 0)', { min: 0, step: 1 }), num('tolerance', 'Tolerance (absolute)', { min: 0, step: 'any' })];
  }
  return [pick('property.kind', 'Property', subject.joints ? { 'joint-class': 'a joint of exactly this class' } : { 'passes-through': 'the curve passes through a point' }),
    ...(subject.joints ? [num('property.joint', 'Joint (1 = the first)', { min: 1, step: 1 }), num('property.parametric', 'Exactly Cᵏ: k (-1 to 3; empty: any)', { min: -1, max: 3, step: 1 }), num('property.geometric', 'Exactly Gᵏ: k (empty: any)', { min: -1, max: 3, step: 1 })]
      : [num('property.x', 'Point x', { step: 'any' }), num('property.y', 'Point y', { step: 'any' }), num('property.tolerance', 'Tolerance (fraction of the largest distance between two control points)', { min: 0, step: 'any' }),
        ...(subject.curves ? [pick('property.family', 'Family', Object.fromEntries(Object.keys(subject.curves).map((f) => [f, f])))] : [])])];
}

// Every field some quantity uses (format.js QUANTITIES); a quantity's unused ones are left out.
const VALUE_FIELDS = [...new Set(Object.values(QUANTITIES).flatMap((q) => q.fields))];

/** @param {{ ctx: any, lesson: any, view: any, message: any }} parts */
export async function openAuthorDialog({ ctx, lesson, view, message }) {
  const support = lesson.exercise;
  let subject;
  try {
    subject = support.subject(view, ctx.model, ctx.state, ctx);
  } catch (err) {
    message.warn(`No exercise can be made from this view: ${err.message}.`, { code: 'exercise-author-refused' });
    return null;
  }
  // The lesson's core with the exercise checkers, which check the exercise as it is made.
  let api;
  try {
    api = await loadWingspline({ parts: [...lesson.core, 'exercises'] });
  } catch (err) {
    message.warn(`No exercise can be made now: ${err.message}`, { code: 'exercise-author-refused' });
    return null;
  }
  const panels = [...document.querySelectorAll('#panels details.panel[id], #panels section[id]')]
    .filter((el) => el.id !== 'exercise-panel' && el.id !== 'mesh-report')
    .map((el) => ({ id: el.id, title: (el.querySelector('summary, h2')?.textContent ?? el.id).trim().slice(0, 80) }));

  const kindSelect = /** @type {HTMLSelectElement} */ (h('select', { id: 'author-kind' }, support.kinds.map((k) => h('option', { value: k }, KINDS[k].label))));
  const title = /** @type {HTMLInputElement} */ (h('input', { type: 'text', id: 'author-title', maxlength: 120 }));
  const source = /** @type {HTMLInputElement} */ (h('input', { type: 'text', id: 'author-source', maxlength: 200, placeholder: 'e.g. Lecture 000, the winged-edge slide' }));
  const question = /** @type {HTMLTextAreaElement} */ (h('textarea', { id: 'author-question', rows: 4, maxlength: 2000 }));
  const fieldBox = h('div', { class: 'author-fields' });
  // Feedback: a new exercise tells where, never the value (level check), unless the author allows more.
  const levelSelect = /** @type {HTMLSelectElement} */ (h('select', { id: 'author-feedback' },
    Object.entries(FEEDBACK_LEVELS).map(([k, v]) => h('option', { value: k, selected: k === 'check' }, v.label))));
  const hintAfter = /** @type {HTMLInputElement} */ (h('input', { type: 'number', id: 'author-hint-after', min: 1, max: 20, step: 1, value: String(DEFAULT_HINT_AFTER) }));
  const hintAfterBox = h('div', { hidden: true }, h('label', { class: 'field', for: 'author-hint-after' }, 'Hints after this many wrong checks (1 to 20)'), hintAfter);
  levelSelect.addEventListener('change', () => { hintAfterBox.hidden = levelSelect.value === 'check'; });
  const hideBoxes = panels.map((p) => /** @type {HTMLInputElement} */ (h('input', { type: 'checkbox', value: p.id, id: `author-hide-${p.id}` })));
  const problem = h('p', { class: 'author-problem', role: 'alert' });
  const result = h('p', { class: 'author-result', 'aria-live': 'polite' });
  /** @type {Map<string, HTMLInputElement | HTMLSelectElement>} */
  let inputs = new Map();
  let suggested = null; // the lesson's suggestion for the kind shown (an edit's: its state and operation)

  function fill(kind) {
    const suggestion = support.suggest?.(kind, ctx.state, { api, subject }) ?? { check: { kind }, hide: [], question: '' };
    suggested = suggestion;
    inputs = new Map();
    const check = suggestion.check;
    const valueOf = (name) => (name.startsWith('point.') ? check.point?.[name.slice(6)] : name.startsWith('property.') ? (name === 'property.x' ? check.property?.point?.[0] : name === 'property.y' ? check.property?.point?.[1] : check.property?.[name.slice(9)]) : check[name]);
    setChildren(fieldBox, fieldsOf(kind, subject).map((f) => {
      const id = `author-field-${f.name.replace('.', '-')}`;
      const current = valueOf(f.name);
      const input = f.type === 'select'
        ? h('select', { id }, Object.entries(f.options).map(([k, v]) => h('option', { value: k, selected: k === current }, v)))
        : h('input', { id, type: f.type === 'list' ? 'text' : 'number', min: f.min, max: f.max, step: f.step, value: current === undefined ? '' : Array.isArray(current) ? current.join(', ') : String(current) });
      inputs.set(f.name, /** @type {any} */ (input));
      return h('div', { 'data-field': f.name }, h('label', { class: 'field', for: id }, f.label), input);
    }));
    // A value shows only the fields its quantity needs.
    const quantity = inputs.get('quantity');
    const showFields = () => {
      for (const name of VALUE_FIELDS) {
        const box = /** @type {HTMLElement | null} */ (fieldBox.querySelector(`[data-field="${name}"]`));
        if (box) box.hidden = !QUANTITIES[quantity?.value]?.fields.includes(name);
      }
    };
    if (quantity) { quantity.addEventListener('change', showFields); showFields(); }
    question.value = suggestion.question;
    for (const box of hideBoxes) box.checked = suggestion.hide.includes(box.value);
    if (!title.value) title.value = `${lesson.title}: ${KINDS[kind].label.toLowerCase()}`;
  }

  // The check as typed (empty numbers left out; a quantity's unused fields left out).
  function checkOf(kind) {
    if (kind === 'edit' || kind === 'code') return { ...suggested?.check, kind };
    const check = { kind };
    const property = {};
    for (const [name, input] of inputs) {
      const raw = input.value.trim();
      if (raw === '') continue;
      const f = fieldsOf(kind, subject).find((x) => x.name === name);
      const value = f.type === 'number' ? Number(raw) : f.type === 'list' ? raw.split(/[\s,]+/).filter(Boolean) : raw;
      if (name.startsWith('property.')) property[name.slice(9)] = value;
      else if (name.startsWith('point.')) check.point = { ...check.point, [name.slice(6)]: value };
      else check[name] = value;
    }
    if (kind === 'subdivide') delete check[check.ask === 'counts' ? 'point' : 'steps'];
    if (kind === 'walk' && check.structure === 'winged-edge') delete check.structure; // the default, as files written before it read
    if (kind === 'value') for (const name of VALUE_FIELDS) if (!QUANTITIES[check.quantity]?.fields.includes(name)) delete check[name];
    if (kind === 'property') {
      if (property.x !== undefined || property.y !== undefined) { property.point = [property.x, property.y]; delete property.x; delete property.y; }
      check.property = property;
    }
    return check;
  }

  // The exercise read back as a student's page reads it, and asked of this drawing.
  function build() {
    const kind = kindSelect.value;
    const exercise = exerciseOf({
      title: title.value.trim(), lesson: lesson.id, source: source.value.trim(), question: question.value.trim(),
      stateVersion: lesson.stateVersion, state: suggested?.state ?? ctx.state, hide: hideBoxes.filter((b) => b.checked).map((b) => b.value), check: checkOf(kind),
      feedback: { level: levelSelect.value, hintAfter: hintAfter.value.trim() === '' ? undefined : Number(hintAfter.value) },
    });
    // As a student's page reads it: the text (with its size limit), the lesson's state, and
    // the kind's own checks against this drawing (a walk element, a joint, a mesh too big
    // to work by hand, a quantity the curve cannot give), the answer form built and dropped.
    const read = parseExercise(stringifyExact(exercise), { lessonIds });
    readExerciseState(lesson, read);
    const asked = suggested?.state ? support.subject(view, ctx.model, suggested.state, ctx) : subject;
    CREATE[kind]({ api, check: read.check, subject: () => asked, support, ctx, view: () => view });
    return read;
  }

  async function run(action) {
    setChildren(problem);
    setChildren(result);
    // The link of an earlier export is hidden until this one's is written: never a stale link.
    linkBox.hidden = true;
    let exercise;
    try {
      exercise = build();
    } catch (err) {
      problem.textContent = `Not yet an exercise: ${err.message}.`;
      return;
    }
    const url = await exerciseUrl(exercise, `${lesson.id}.html`);
    if (action === 'json') {
      download(`${(exercise.title.toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '') || 'exercise').slice(0, 60)}.exercise.json`, stringifyExact(exercise, 2) + '\n', 'application/json');
      result.textContent = 'The exercise file is downloaded: students open it from the exercise gallery (Open an exercise file), or you send its link.';
    } else if (action === 'link') {
      let copied = true;
      try { await navigator.clipboard.writeText(url); } catch { copied = false; }
      linkBox.value = url;
      linkBox.hidden = false;
      result.textContent = copied ? 'The link (below) is copied: it opens this exercise, with nothing else needed.' : 'Copy the link below: it opens this exercise.';
      linkBox.focus();
      linkBox.select();
    } else {
      window.open(url, '_blank', 'noopener');
    }
  }

  const linkBox = /** @type {HTMLTextAreaElement} */ (h('textarea', { class: 'author-link', id: 'author-link', rows: 3, readonly: true, hidden: true, 'aria-label': 'Exercise link' }));
  const dialog = /** @type {HTMLDialogElement} */ (h('dialog', { class: 'keymap-dialog exercise-author', 'aria-labelledby': 'author-heading' },
    h('h2', { id: 'author-heading' }, 'Make an exercise from this view'),
    h('p', { class: 'hint' }, 'The drawing as it is now is the exercise\'s starting point. Choose what is checked and what is hidden, write the question, then export it.'),
    h('label', { class: 'field', for: 'author-kind' }, 'Kind'), kindSelect,
    fieldBox,
    h('label', { class: 'field', for: 'author-title' }, 'Title'), title,
    h('label', { class: 'field', for: 'author-question' }, 'Question'), question,
    h('label', { class: 'field', for: 'author-source' }, 'Source (optional)'), source,
    h('label', { class: 'field', for: 'author-feedback' }, 'Feedback the student gets'), levelSelect, hintAfterBox,
    h('fieldset', {}, h('legend', {}, 'Hide while answering'), h('div', { class: 'hide-list' }, panels.map((p, i) => h('label', { class: 'choice', for: hideBoxes[i].id }, hideBoxes[i], p.title)))),
    problem, result, linkBox,
    h('div', { class: 'dialog-actions' },
      h('button', { type: 'button', class: 'primary', id: 'author-export-json', onclick: () => run('json') }, 'Export JSON'),
      h('button', { type: 'button', id: 'author-copy-link', onclick: () => run('link') }, 'Copy link'),
      h('button', { type: 'button', id: 'author-try', onclick: () => run('try') }, 'Try it'),
      h('button', { type: 'button', id: 'author-close', onclick: () => dialog.close() }, 'Close'))));
  kindSelect.addEventListener('change', () => fill(kindSelect.value));
  dialog.addEventListener('close', () => dialog.remove());
  document.body.append(dialog);
  fill(kindSelect.value);
  dialog.showModal();
  kindSelect.focus();
  return dialog;
}
