// @ts-check
// The reconnection phase played pointer by pointer, as the mesh lesson plays an edit: the
// core's assignments (api.reconnectionPlayback: every entry of the next level's tables,
// written once, old edge by old edge and old face by old face) stepped with Before, Back,
// Play, Step and After; the algorithm's lines with how many of each are made; the current
// assignment in words. The tables show only the entries written so far (tableEntry below)
// and mark the cell written last; the drawing marks its element (draw.js). Every number
// is the core's.
import { h } from '../../app/dom.js';
import { createPlayer } from '../../app/player.js';
import { assignmentText, columnOfField } from '../../ui/mesh/assignments.js';
import { label } from './source.js';

const TABLE_OF = { vertex: 'vertices', edge: 'edges', face: 'faces' };

/**
 * @param {any} ctx
 * @param {{ onStep: (i: number) => void }} options
 */
export function createReconnectionPanel(ctx, { onStep }) {
  const current = () => ctx.model?.reconnection ?? null;
  const player = createPlayer({
    count: () => (current()?.steps?.length ?? 0) + 1,
    getStep: () => current()?.shown ?? 0,
    onStep,
    stepsPerSecond: 4,
  });
  const tool = (text, action, title, id) => h('button', { type: 'button', class: 'tool', title, onclick: action, id }, text);
  const playButton = tool('▶ Play', () => player.toggle(), 'Play the reconnection assignment by assignment', 'reconnect-play');
  player.onChange(() => { playButton.textContent = player.playing ? '⏸ Pause' : '▶ Play'; playButton.setAttribute('aria-pressed', String(player.playing)); });
  const stepLabel = h('span', { class: 'walk-step', id: 'reconnect-step' });
  const now = h('p', { class: 'reconnect-current', id: 'reconnect-current', 'aria-live': 'polite' });
  const lines = h('ol', { class: 'pseudocode reconnect-lines', id: 'reconnect-lines', 'aria-label': 'The reconnection, line by line' });
  const note = h('p', { class: 'hint', id: 'reconnect-note' });
  const controls = h('div', { class: 'walk-controls', role: 'group', 'aria-label': 'Reconnection player' },
    tool('|◀ Before', () => player.restart(), 'Before the reconnection: the next level\'s tables are empty', 'reconnect-restart'),
    tool('◀ Back', () => player.prev(), 'Previous assignment', 'reconnect-back'),
    playButton,
    tool('Step ▶', () => player.next(), 'Next assignment', 'reconnect-next'),
    tool('After ▶|', () => player.end(), 'After the reconnection: every entry written', 'reconnect-end'),
    stepLabel);
  // The player and the current assignment: the lesson puts them at the top of the side
  // column, where they stay (sticky, subdivision.css) while the column scrolls to the cell
  // written, on a projector too; the lines and the note sit in the step panel.
  const playerBox = h('section', { class: 'reconnect-player', id: 'reconnect-player', 'aria-labelledby': 'reconnect-title', hidden: true },
    h('h2', { id: 'reconnect-title' }, 'Reconnection, pointer by pointer'), controls, now);
  const root = h('div', { class: 'reconnect-panel', id: 'reconnect-panel', hidden: true }, note, lines);

  return {
    root,
    playerBox,
    player,
    // Pixels of the column's top the sticky player covers (for revealInBoxes).
    coveredTop: () => (playerBox.hidden ? 0 : playerBox.getBoundingClientRect().height),
    update(model) {
      const r = model.reconnection;
      root.hidden = !r;
      playerBox.hidden = !r || r.tooBig !== undefined;
      if (!r) { if (player.playing) player.pause(); return; }
      if (r.tooBig !== undefined) {
        note.textContent = `The playback is offered for levels of up to 500 faces; this level has ${r.tooBig.toLocaleString('en')}. The tables show the next level as it is built.`;
        controls.hidden = true; now.textContent = ''; lines.replaceChildren();
        return;
      }
      controls.hidden = false;
      const n = r.steps.length;
      note.textContent = `The next level's tables start empty; the core writes each of their ${n.toLocaleString('en')} entries once, in this order. The tables below show what is written so far.`;
      stepLabel.textContent = `${r.shown} of ${n}`;
      const step = r.shown > 0 ? r.steps[r.shown - 1] : null;
      const source = step ? r.sources[r.shown - 1] : -1;
      const whose = !step ? '' : step.phase === 0 || step.phase === 4 ? `old ${label('edge', source)}: ` : step.phase <= 3 ? `old ${label('face', source)}: ` : '';
      now.textContent = step ? `${whose}${assignmentText(step)}` : 'Nothing written yet: press Step.';
      // Per line: how many of its assignments are made.
      const total = r.lines.map(() => 0);
      const done = r.lines.map(() => 0);
      for (let i = 0; i < n; i += 1) { total[r.steps[i].phase] += 1; if (i < r.shown) done[r.steps[i].phase] += 1; }
      lines.replaceChildren(...r.lines.map((text, i) => h('li', {
        'data-line': i, class: step?.phase === i ? 'is-current' : done[i] === total[i] && total[i] ? 'is-done' : '', 'aria-current': step?.phase === i ? 'step' : null,
      }, text, h('span', { class: 'hint' }, ` (${done[i]} of ${total[i]})`))));
    },
  };
}

// What a table cell shows during the playback: the value when it is written, '' before.
export function tableEntry(model, table, row, field, text) {
  const r = model.reconnection;
  if (!r || r.tooBig !== undefined || r.shown >= r.steps.length) return text;
  if (!['edge', 'start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'].includes(field)) return text;
  const at = r.firstWrite.get(`${table}:${row}:${field}`) ?? -1;
  return at >= 0 && at < r.shown ? text : '';
}

// The cell the current assignment wrote, for the tables' marks: {name, row, column} or null.
export function currentCell(model) {
  const r = model.reconnection;
  if (!r || r.tooBig !== undefined || r.shown === 0 || r.shown >= r.steps.length) return null;
  const s = r.steps[r.shown - 1];
  return { name: TABLE_OF[s.table], table: s.table, row: s.row, column: columnOfField(s.table, s.field) };
}
