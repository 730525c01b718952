// @ts-check
// The walk player of the mesh lessons: which walk (the CCW edges around a vertex, or the
// edges of a face) from which element, its pseudocode with the current line, the player's
// buttons and keys, the step's narration and the edges found so far.
// Offers: createWalkPanel(ctx, options) -> { root, player, placeUnderNarration(node),
//   sync(state), update(model, state) }.
// Needs: a state with walk ('vertex'|'face'), vertex, face, step, speed; a model with the
//   walk's frames (ui/mesh/walk.js: walkKind, walkElement, frames, frame, stepIndex,
//   walkRemoved, walkSeenFromBehind) and topology, V, F; the shell's ctx (commit, state,
//   model, message, keymap, stage.canvas, ui.exercise: while a walk is predicted in an
//   exercise, the walk does not step by itself). options: title and pseudocode ({vertex,
//   face}: lines; the frames' `line` is an index into them).
import { h } from '../../app/dom.js';
import { createPlayer } from '../../app/player.js';
import { PSEUDOCODE, foundEdges } from './walk.js';
import { vLabel, fLabel } from '../element-labels.js';

const FOUND_SHOWN = 12; // the last edges found; a pole of valence 100 would fill the panel

const labelled = (text, control) => h('label', {}, text, ' ', control);

/**
 * @param {any} ctx
 * @param {{ title?: string, pseudocode?: {vertex: string[], face: string[]} }} [options]
 */
export function createWalkPanel(ctx, { title = 'Winged-edge walk', pseudocode = PSEUDOCODE } = {}) {
  const state = () => ctx.state;
  const commit = (patch, opts) => ctx.commit({ ...state(), ...patch }, opts);
  const stage = ctx.stage.canvas;

  const walkKind = h('select', { id: 'walk-kind', 'aria-label': 'Walk' },
    h('option', { value: 'vertex' }, 'CCW edges around a vertex'), h('option', { value: 'face' }, 'Edges of a face'));
  const walkElement = h('input', { type: 'number', id: 'walk-element', min: 1, step: 1, 'aria-label': 'Vertex or face number (1-based, as on the slide)' });
  const walkElementLabel = h('label', { for: 'walk-element' }, 'v');
  const code = h('ol', { class: 'pseudocode', id: 'walk-code', 'aria-label': 'Pseudocode' });
  const narration = h('p', { class: 'walk-text', id: 'walk-text', 'aria-live': 'polite' });
  const found = h('p', { class: 'walk-found', id: 'walk-found' });
  // Shown when the walked element's normal points away from the viewer.
  const side = h('p', { class: 'walk-side hint', id: 'walk-side', 'aria-live': 'polite', hidden: true });
  walkKind.addEventListener('change', () => commit({ walk: walkKind.value, step: 0 }, { history: false }));
  walkElement.addEventListener('change', () => {
    const n = Number(walkElement.value) - 1;
    const limit = state().walk === 'vertex' ? ctx.model.V : ctx.model.F;
    if (!Number.isInteger(n) || n < 0 || n >= limit) {
      ctx.message.error(`Choose a number from 1 to ${limit}`, 'invalid-element');
      sync(state());
      return;
    }
    commit(state().walk === 'vertex' ? { vertex: n, step: 0 } : { face: n, step: 0 }, { history: false });
  });

  const player = createPlayer({
    count: () => ctx.model?.frames.length ?? 0,
    getStep: () => ctx.model?.stepIndex ?? 0,
    // While a walk is being predicted (an exercise), the walk does not step by itself.
    onStep: (i) => { if (ctx.ui.exercise !== 'walk') commit({ step: i }, { history: false }); },
    stepsPerSecond: state().speed,
  });
  const button = (text, action, tip) => h('button', { type: 'button', class: 'tool', title: tip, 'aria-label': tip, onclick: action }, text);
  const playButton = button('▶ Play', () => player.toggle(), 'Play or pause the walk (Space)');
  playButton.id = 'walk-play';
  const speed = h('input', { type: 'range', id: 'walk-speed', min: 0.25, max: 6, step: 0.25, 'aria-label': 'Steps per second' });
  speed.addEventListener('input', () => { player.setSpeed(Number(speed.value)); commit({ speed: Number(speed.value) }, { history: false, recompute: false }); });
  const stepLabel = h('span', { class: 'walk-step', id: 'walk-step' });
  player.onChange(() => { playButton.textContent = player.playing ? '⏸ Pause' : '▶ Play'; playButton.setAttribute('aria-pressed', String(player.playing)); });

  const root = h('section', { class: 'walk-panel', id: 'walk-panel', 'aria-labelledby': 'walk-title' },
    h('h2', { id: 'walk-title' }, title),
    h('div', { class: 'walk-choice' }, labelled('Walk', walkKind), walkElementLabel, walkElement),
    code,
    h('div', { class: 'walk-controls', role: 'group', 'aria-label': 'Walk player' },
      button('Restart', () => player.restart(), 'Restart (Home)'),
      button('◀ Back', () => player.prev(), 'Step back (← or PageUp)'),
      playButton,
      button('Step ▶', () => player.next(), 'Step forward (→ or PageDown)'),
      h('span', { class: 'advanced' }, labelled('speed', speed)), stepLabel),
    narration, side, found);

  const notOnCanvas = (event) => event.target !== stage;
  ctx.keymap.add({ keys: [' '], label: 'play / pause the walk', group: 'Walk', shownWith: root, action: () => player.toggle(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['ArrowRight', 'PageDown', 'n'], label: 'next step of the walk (arrows when the canvas is not focused)', group: 'Walk', shownWith: root, action: () => player.next(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['ArrowLeft', 'PageUp', 'b'], label: 'previous step of the walk', group: 'Walk', shownWith: root, action: () => player.prev(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['Home'], label: 'restart the walk', group: 'Walk', shownWith: root, action: () => player.restart(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['End'], label: 'last step of the walk', group: 'Walk', shownWith: root, action: () => player.end(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['PageDown', 'PageUp', 'n', 'b'], label: 'on the focused canvas too: PageDown/n next, PageUp/b back (presenter remote)', group: 'Walk', shownWith: root,
    action: (event) => (event.key === 'PageDown' || event.key === 'n' ? player.next() : player.prev()), when: (event) => event.target === stage });

  function sync(s) {
    walkKind.value = s.walk;
    speed.value = s.speed;
  }

  let lastWalkKey = null;
  function update(model, s) {
    const lines = pseudocode[model.walkKind];
    const key = `${model.topology}:${model.walkKind}:${model.walkElement}`;
    if (key !== lastWalkKey) {
      lastWalkKey = key;
      code.replaceChildren(...lines.map((line, i) => h('li', { 'data-line': i }, line)));
      walkElementLabel.textContent = model.walkKind === 'vertex' ? 'v' : 'F';
      walkElement.max = model.walkKind === 'vertex' ? model.V : model.F;
    }
    walkElement.value = model.walkElement + 1;
    const frame = model.frame;
    for (const li of code.children) {
      const current = frame && Number(li.dataset.line) === frame.line;
      li.classList.toggle('is-current', Boolean(current));
      if (current) li.setAttribute('aria-current', 'step'); else li.removeAttribute('aria-current');
    }
    const what = model.walkKind === 'vertex' ? vLabel(model.walkElement) : fLabel(model.walkElement);
    stepLabel.textContent = `step ${model.stepIndex} / ${Math.max(0, model.frames.length - 1)}`;
    narration.textContent = frame ? frame.text
      : model.walkRemoved ? `${what} was removed by an edit: nothing to walk (choose another ${model.walkKind === 'vertex' ? 'vertex' : 'face'}).` : `${what}: nothing to walk.`;
    side.hidden = !model.walkSeenFromBehind;
    side.textContent = model.walkSeenFromBehind
      ? `Viewed from behind: the normal of ${what} points away from you, so the counter-clockwise walk appears clockwise here. Turn the mesh to see it from the front.`
      : '';
    const shown = frame ? foundEdges(frame, FOUND_SHOWN) : [];
    const skipped = frame ? frame.foundCount - shown.length : 0;
    found.replaceChildren('Found so far: ',
      ...(skipped ? [h('span', { class: 'walk-none' }, `(${skipped} earlier) `)] : []),
      ...(shown.length ? shown.map((e, k) => h('span', { class: 'found-edge' }, `${skipped + k + 1}. e`, h('sub', {}, String(e + 1))))
        : [h('span', { class: 'walk-none' }, 'none yet')]));
    if (player.speed !== s.speed) player.setSpeed(s.speed);
  }

  // A node shown right under the narration (the mesh lesson's row the walk reads, on phones).
  const placeUnderNarration = (node) => narration.after(node);

  return { root, player, placeUnderNarration, sync, update };
}
