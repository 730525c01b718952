// @ts-check
// Kind 2: predict the next edge of the counter-clockwise walk around a vertex (or along a
// face), step after step (lecture 000's traversal). The walk is the core's
// (mesh.traversalSteps / faceEdgeSteps); the student picks the next edge among the mesh's
// edges, by pointer or with the arrow keys, and checks it. A right edge is added to the walk
// (and drawn by the lesson); a wrong one is explained from the rule the walk reads.
import { h, setChildren } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { label } from './table.js';
import { refuseLargeMesh } from '../subjects.js';

/** @param {any} parts */
export function createWalkKind({ api, check, subject, support, ctx }) {
  const mesh = subject().mesh;
  if (!mesh) throw new ExerciseError('this lesson has no mesh to walk on', 'exercise.check.kind');
  refuseLargeMesh(mesh);
  const built = api.buildMesh(mesh);
  let steps;
  let edgeCount;
  try {
    const we = built.wingedEdge();
    const count = check.around === 'vertex' ? we.vertices.length : we.faces.length;
    edgeCount = we.edges.length;
    if (check.element > count) {
      throw new ExerciseError(`its field exercise.check.element is ${check.element}, but the mesh has ${count} ${check.around === 'vertex' ? 'vertices' : 'faces'}`, 'exercise.check.element');
    }
    steps = check.around === 'vertex' ? built.traversalSteps(check.element - 1) : built.faceEdgeSteps(check.element - 1);
  } finally {
    built.dispose();
  }
  if (steps.length < 2) throw new ExerciseError(`the walk ${check.around === 'vertex' ? 'around' : 'along'} ${check.around === 'vertex' ? 'v' : 'F'}${check.element} has no step to predict`, 'exercise.check.element');
  const where = check.around === 'vertex' ? `around v${check.element}` : `along F${check.element}`;
  // The core checks a step and says why, from the rule the walk reads (S:L or E:R around a
  // vertex, E:L or S:R along a face).
  const stepCheck = (step, given) => api.checkWalkStep(mesh, { around: check.around, element: check.element - 1, step, given });

  // Predictions made: the walk shows steps[0..known-1]; known = steps.length + 1 once the
  // student has also said that the walk comes back to its first edge (the loop's "while").
  let known = 1;
  const path = h('p', { class: 'exercise-walk-path', 'aria-live': 'polite' });
  const prompt = h('p', { class: 'exercise-walk-prompt' });
  const group = h('div', { class: 'exercise-choices', role: 'radiogroup', 'aria-label': 'The next edge' });
  const radios = Array.from({ length: edgeCount }, (_, e) => {
    const input = /** @type {HTMLInputElement} */ (h('input', { type: 'radio', name: 'exercise-next-edge', value: String(e), id: `exercise-edge-${e + 1}` }));
    group.append(h('label', { class: 'choice', for: `exercise-edge-${e + 1}` }, input, label('edge', e)));
    return input;
  });
  const root = h('div', { class: 'exercise-walk' }, path, prompt, group);

  function show() {
    const done = known > steps.length;
    setChildren(path, `The walk ${where}: `, steps.slice(0, Math.min(known, steps.length)).map((s, i) => [i ? ' → ' : '', h('strong', {}, label('edge', s.edge))]), done ? ` → back to ${label('edge', steps[0].edge)}` : ' → ?');
    prompt.textContent = done ? 'The walk is closed: every edge is found.' : `Step ${known}: the walk is at ${label('edge', steps[known - 1].edge)}. Which edge comes next?`;
    for (const r of radios) { r.checked = false; r.disabled = done; }
    support.showWalk?.(ctx, check.around, check.element - 1);
  }

  return {
    root,
    answer: () => ({ known }),
    restore(saved) {
      if (saved && Number.isSafeInteger(saved.known) && saved.known >= 1 && saved.known <= steps.length + 1) known = saved.known;
    },
    start: show,
    check() {
      if (known > steps.length) return { correct: true, incomplete: true, findings: [] };
      const picked = radios.find((r) => r.checked);
      if (!picked) return { correct: false, findings: ['Pick the next edge first (click it, or use the arrow keys in the list).'], incomplete: true };
      const given = Number(picked.value);
      const r = stepCheck(known, given);
      if (!r.correct) return { correct: false, findings: [`${r.reason[0].toUpperCase()}${r.reason.slice(1)}.`] };
      known += 1;
      const closed = known > steps.length;
      show();
      return { correct: closed, partial: !closed, findings: [], note: closed ? `${r.reason}.` : `Right: ${r.reason}.` };
    },
    worked() {
      return { lines: steps.map((s, k) => `${label('edge', s.edge)} → ${stepCheck(k + 1, k + 1 < steps.length ? steps[k + 1].edge : steps[0].edge).reason}.`) };
    },
    reset() { known = 1; show(); },
  };
}
