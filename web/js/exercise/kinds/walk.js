// @ts-check
// Kind 2: predict the next edge of the counter-clockwise walk around a vertex (or along a
// face), step after step (lecture 000's traversal). The walk is the core's
// (mesh.traversalSteps / faceEdgeSteps); the student picks the next edge among the mesh's
// edges, by pointer or with the arrow keys, and checks it. A right edge is added to the walk
// (and drawn by the lesson); a wrong one is said from the rule the walk reads.
//
// The answer is every edge the student checked, right or wrong, in order: { picks: [3, 5, …] }
// (edge numbers as the page shows them, e3 = 3), so a grader replays the walk step by step.
//
// structure 'half-edge' walks the half-edges instead (docs/api-mesh.md, "The half-edge view"):
// around a vertex h -> twin(prev(h)), along a face h -> next(h), from the half-edge the vertex
// (face) stores; the student picks among the half-edges, each shown with its two ends (a row
// of the half-edge table without the columns that would answer), or types its label; picks
// are half-edge numbers as the page shows them (h5 = 5). The walk and each verdict are the
// core's (api.checkWalkStep with structure 'half-edge').
// Progress saved before that kept only { known } (the walk shown up to step known): its first
// known - 1 predictions were right, so they are taken from the core's walk.
import { h, setChildren } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { label, readLabel, halfEdgeRows } from './table.js';
import { refuseLargeMesh } from '../subjects.js';
import { findingOf, isPlainObject, unreadable } from './grading.js';

// The walk the exercise asks for: its steps (the core's; `edge` is the step's element, a
// half-edge on a half-edge walk), how many elements there are to pick from, and how the page
// names them.
function walkOf(api, check, subject) {
  const mesh = subject.mesh;
  if (!mesh) throw new ExerciseError('this lesson has no mesh to walk on', 'exercise.check.kind');
  refuseLargeMesh(mesh);
  const halfEdge = check.structure === 'half-edge';
  const built = api.buildMesh(mesh);
  let steps;
  let edgeCount;
  let counts;
  try {
    const we = built.wingedEdge();
    counts = { vertex: we.vertices.length, face: we.faces.length, edge: we.edges.length };
    const count = check.around === 'vertex' ? counts.vertex : counts.face;
    edgeCount = halfEdge ? 2 * counts.edge : counts.edge;
    if (check.element > count) {
      throw new ExerciseError(`its field exercise.check.element is ${check.element}, but the mesh has ${count} ${check.around === 'vertex' ? 'vertices' : 'faces'}`, 'exercise.check.element');
    }
    if (!halfEdge) steps = check.around === 'vertex' ? built.traversalSteps(check.element - 1) : built.faceEdgeSteps(check.element - 1);
  } finally {
    built.dispose();
  }
  // The core checks a step and says why, from the rule the walk reads (S:L or E:R around a
  // vertex, E:L or S:R along a face; twin(prev(h)) or next(h) on the half-edges).
  const structure = halfEdge ? 'half-edge' : 'winged-edge';
  const stepCheck = (step, given) => api.checkWalkStep(mesh, { around: check.around, element: check.element - 1, step, given, structure });
  // The half-edge walk from the exercises module's checker (any lesson with a mesh has it):
  // each step says where it starts and what comes next, until the walk closes.
  if (halfEdge) {
    let r = stepCheck(1, -2);
    steps = [{ edge: r.from }];
    while (!r.done && steps.length < edgeCount) {
      steps.push({ edge: r.expected });
      r = stepCheck(steps.length, -2);
    }
  }
  if (steps.length < 2) throw new ExerciseError(`the walk ${check.around === 'vertex' ? 'around' : 'along'} ${check.around === 'vertex' ? 'v' : 'F'}${check.element} has no step to predict`, 'exercise.check.element');
  const name = halfEdge ? (i) => `h${i + 1}` : (i) => label('edge', i);
  // A half-edge's two ends, for the choices (the lesson's numbering: a blank table's worked answer).
  let ends = null;
  if (halfEdge) {
    const rows = halfEdgeRows(api, mesh, { ...counts, halfedge: edgeCount }).halfedge;
    ends = (i) => `${label('vertex', rows[i].origin)} → ${label('vertex', rows[rows[i].twin].origin)}`;
  }
  const noun = halfEdge ? 'half-edge' : 'edge';
  return { steps, edgeCount, stepCheck, name, ends, noun, halfEdge, where: check.around === 'vertex' ? `around v${check.element}` : `along F${check.element}` };
}

/**
 * A saved walk answer in today's shape: { picks } as is, the old { known } as the right picks
 * the walk had shown (from the core's steps); null when it is neither.
 * @param {unknown} saved @param {Array<{ edge: number }>} steps
 */
export function migrateWalkAnswer(saved, steps) {
  if (!isPlainObject(saved)) return null;
  const s = /** @type {any} */ (saved);
  if (Array.isArray(s.picks)) return { picks: s.picks };
  if (Number.isSafeInteger(s.known) && s.known >= 1 && s.known <= steps.length + 1) {
    return { picks: Array.from({ length: s.known - 1 }, (_, i) => (i + 1 < steps.length ? steps[i + 1].edge : steps[0].edge) + 1) };
  }
  return null;
}

// The picks replayed: how far the walk got, and the last pick's verdict.
function replay(walk, picks) {
  let known = 1;
  let last = null;
  for (const pick of picks) {
    if (known > walk.steps.length) break; // picks after the walk closed are not steps
    last = walk.stepCheck(known, pick - 1);
    if (last.correct) known += 1;
  }
  return { known, last };
}

const readPicks = (answer, edgeCount) => {
  if (!isPlainObject(answer)) return null;
  const picks = /** @type {any} */ (answer).picks;
  if (!Array.isArray(picks) || picks.length > 10000 || !picks.every((p) => Number.isInteger(p) && p >= 1 && p <= edgeCount)) return null;
  return picks;
};

/**
 * Grades a walk: { picks } replayed against the core's walk. Right: the walk is closed;
 * partial: some steps found; a wrong last pick is said (where, the rule), never the edge.
 * Pure: no DOM.
 * @param {{ api: any, check: any, subject: any, answer: unknown }} parts
 * @returns {import('./grading.js').GradeResult}
 */
export function gradeWalk({ api, check, subject, answer }) {
  const walk = walkOf(api, check, subject);
  const migrated = migrateWalkAnswer(answer, walk.steps);
  const picks = migrated && readPicks(migrated, walk.edgeCount);
  if (!picks) return unreadable(`the ${walk.noun}s picked, in order: {picks: [${walk.noun} numbers from 1 to ${walk.edgeCount}]}`);
  const { known, last } = replay(walk, picks);
  const n = walk.steps.length;
  if (known > n) return { correct: true, findings: [], note: last ? `${last.reason}.` : `The walk ${walk.where} is closed.` };
  if (!last) return { correct: false, incomplete: true, findings: [{ text: pickFirst(walk) }] };
  if (last.correct) return { correct: false, partial: true, findings: [], note: `Right: ${last.reason}.` };
  return { correct: false, partial: known > 1, findings: [findingOf(last.message, last.hint)], note: known > 1 ? `${known - 1} of ${n} steps found.` : undefined };
}

/** The worked walk: every step with the rule it reads. @param {{ api: any, check: any, subject: any }} parts */
export function workedWalk({ api, check, subject }) {
  const { steps, stepCheck, name } = walkOf(api, check, subject);
  return { lines: steps.map((s, k) => `${name(s.edge)} → ${stepCheck(k + 1, k + 1 < steps.length ? steps[k + 1].edge : steps[0].edge).reason}.`) };
}

const pickFirst = (walk) => (walk.halfEdge
  ? 'Pick the next half-edge first (click it, use the arrow keys in the list, or type its label).'
  : 'Pick the next edge first (click it, or use the arrow keys in the list).');

/** @param {any} parts */
export function createWalkKind({ api, check, subject, support, ctx }) {
  const walk = walkOf(api, check, subject());
  const { steps, edgeCount, where, name, noun } = walk;

  // Every pick checked, in order (edge numbers from 1); known: the walk shows steps[0..known-1];
  // known = steps.length + 1 once the student has also said that the walk comes back to its
  // first edge (the loop's "while").
  /** @type {number[]} */
  let picks = [];
  let known = 1;
  const path = h('p', { class: 'exercise-walk-path', 'aria-live': 'polite' });
  const prompt = h('p', { class: 'exercise-walk-prompt' });
  const group = h('div', { class: 'exercise-choices', role: 'radiogroup', 'aria-label': `The next ${noun}` });
  const radios = Array.from({ length: edgeCount }, (_, e) => {
    const id = walk.halfEdge ? `exercise-halfedge-${e + 1}` : `exercise-edge-${e + 1}`;
    const input = /** @type {HTMLInputElement} */ (h('input', { type: 'radio', name: 'exercise-next-edge', value: String(e), id }));
    group.append(h('label', { class: 'choice', for: id }, input, name(e), walk.ends ? h('span', { class: 'hint' }, `(${walk.ends(e)})`) : null));
    return input;
  });
  // A half-edge can be typed too (h5 or 5): the list is long, and typing is how the table is
  // filled in. Typing picks the half-edge in the list; Enter checks, as in the list.
  const typed = walk.halfEdge
    ? /** @type {HTMLInputElement} */ (h('input', { type: 'text', class: 'cell', id: 'exercise-walk-typed', spellcheck: 'false', autocomplete: 'off', autocapitalize: 'off', 'aria-label': 'Type the next half-edge (h1, h2, …)' }))
    : null;
  // A pick in the list (pointer or arrow keys) replaces what was typed.
  if (typed) group.addEventListener('change', () => { typed.value = ''; });
  typed?.addEventListener('input', () => {
    const r = readLabel(typed.value, 'halfedge', edgeCount, false);
    for (const radio of radios) radio.checked = r.value !== undefined && r.value >= 0 && Number(radio.value) === r.value;
  });
  const typedRow = typed ? h('p', { class: 'exercise-walk-typed' }, h('label', { for: 'exercise-walk-typed' }, 'or type it: '), typed) : null;
  const root = h('div', { class: 'exercise-walk' }, path, prompt, group, typedRow);

  function show() {
    const done = known > steps.length;
    setChildren(path, `The walk ${where}: `, steps.slice(0, Math.min(known, steps.length)).map((s, i) => [i ? ' → ' : '', h('strong', {}, name(s.edge))]), done ? ` → back to ${name(steps[0].edge)}` : ' → ?');
    prompt.textContent = done ? `The walk is closed: every ${noun} is found.` : `Step ${known}: the walk is at ${name(steps[known - 1].edge)}. Which ${noun} comes next?`;
    for (const r of radios) { r.checked = false; r.disabled = done; }
    if (typed) { typed.value = ''; typed.disabled = done; }
    // The drawing shows the walk's start only: a later frame of the lesson's walk draws the
    // next edge dashed, which is the answer to the step asked.
    support.showWalk?.(ctx, check.around, check.element - 1);
  }

  return {
    root,
    answer: () => ({ picks: [...picks] }),
    restore(saved) {
      const migrated = migrateWalkAnswer(saved, steps);
      const read = migrated && readPicks(migrated, edgeCount);
      if (!read) return;
      picks = read;
      known = replay(walk, picks).known;
    },
    start: show,
    check() {
      if (known > steps.length) return { correct: true, incomplete: true, findings: [] };
      if (typed && typed.value.trim() !== '') {
        const r = readLabel(typed.value, 'halfedge', edgeCount, false);
        if (r.problem) return { correct: false, incomplete: true, findings: [{ text: `${r.problem}.` }] };
      }
      const picked = radios.find((r) => r.checked);
      if (!picked) return { correct: false, findings: [{ text: pickFirst(walk) }], incomplete: true };
      picks = [...picks, Number(picked.value) + 1];
      const result = gradeWalk({ api, check, subject: subject(), answer: { picks } });
      const before = known;
      known = replay(walk, picks).known;
      if (known > before) show();
      return result;
    },
    worked: () => workedWalk({ api, check, subject: subject() }),
    reset() { picks = []; known = 1; show(); },
  };
}
