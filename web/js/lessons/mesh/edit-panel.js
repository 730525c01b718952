// @ts-check
// "Edit the mesh": the picked vertex, edge or face (canvas, table row, touch or
// the number fields here), the operations that apply to it (each enabled or saying why
// not, from mesh.check), the last edit played back one pointer assignment at a time (on the
// half-edge tab, one half-edge entry at a time), the counts and Euler's formula, how many
// pointer entries the winged edge and the half-edge wrote, and how many stored entries
// every representation rewrote.
// Edits go into state.ops (edit-ops.js withEdit), so undo, links and reload keep them.
import { h, revealInBoxes } from '../../app/dom.js';
import { createPlayer } from '../../app/player.js';
import { editOps, withEdit } from './edit-ops.js';
import { visibleSteps, playbackSteps, playbackStepText } from './edit-playback.js';
import { vLabel, eLabel, fLabel } from './labels.js';
import { exists, whyNot, goneNote, keptCorner } from './live-elements.js';
import { createGrowthPlot, COST_GRIDS, COST_FACES } from './growth.js';

const LABEL = { vertex: vLabel, edge: eLabel, face: fLabel };
const REPRESENTATION_NAMES = {
  'independent-faces': 'Independent faces',
  'vertex-face-tables': 'Vertex and face tables',
  'adjacency-lists': 'Adjacency lists',
  'partial-adjacency-lists': 'Partial adjacency lists',
  'edge-list': 'Edge list',
  'winged-edge': 'Winged edge',
};

const count = (x) => x.toLocaleString('en');
const listed = (names) => (names.length < 2 ? names.join('') : `${names.slice(0, -1).join(', ')} and ${names[names.length - 1]}`);

// selection: the view's {hover, pick}; pick({kind, index}) makes an element the picked one.
export function createEditPanel(ctx, selection, { pick }) {
  const state = () => ctx.state;
  // The operations of the core's registry that the panel offers, one button and key each.
  const EDIT_OPS = editOps(ctx.api.meshOperations);
  const EDIT_OP = Object.fromEntries(EDIT_OPS.map((o) => [o.op, o]));
  const kindSelect = h('select', { id: 'edit-kind', 'aria-label': 'Kind of element to edit' },
    h('option', { value: 'vertex' }, 'vertex'), h('option', { value: 'edge' }, 'edge'), h('option', { value: 'face' }, 'face'));
  const number = h('input', { type: 'number', id: 'edit-element', min: 1, step: 1, 'aria-label': 'Element number (1-based, as in the tables)' });
  const choose = () => {
    const kind = kindSelect.value;
    // Changing the kind before a number is typed is not a mistake: nothing to choose yet.
    if (number.value.trim() === '') return;
    const n = Number(number.value) - 1;
    const limit = { vertex: ctx.model.V, edge: ctx.model.E, face: ctx.model.F }[kind];
    if (!Number.isInteger(n) || n < 0 || n >= limit) {
      ctx.message.error(`Choose ${kind === 'edge' ? 'an' : 'a'} ${kind} number from 1 to ${limit}`, 'invalid-element');
      return;
    }
    if (!exists(ctx.model, { kind, index: n })) {
      ctx.message.error(`${whyNot(ctx.model, { kind, index: n })}: choose another ${kind}`, 'invalid-element');
      return;
    }
    pick({ kind, index: n });
  };
  kindSelect.addEventListener('change', choose);
  number.addEventListener('change', choose);

  const tInput = h('input', { type: 'range', id: 'edit-t', min: 0.1, max: 0.9, step: 0.05, 'aria-label': 'Parameter t (where a new or merged vertex lies)' });
  const tValue = h('output', { for: 'edit-t', id: 'edit-t-value' });
  tInput.addEventListener('input', () => ctx.commit({ ...state(), editT: Number(tInput.value) }, { history: false, recompute: false }));
  // The two elements an operation needs besides the picked one (split face: two corners of
  // the face; split vertex: two neighbours of the vertex), offered from the registry's
  // `choices` query of the picked element.
  const cornerA = h('select', { id: 'edit-corner-a', 'aria-label': 'First choice' });
  const cornerB = h('select', { id: 'edit-corner-b', 'aria-label': 'Second choice' });
  const corners = h('span', { class: 'edit-corners' }, h('label', {}, 'from ', cornerA), ' ', h('label', {}, 'to ', cornerB));
  for (const s of [cornerA, cornerB]) s.addEventListener('change', () => refreshButtons());

  const picked = h('p', { class: 'edit-picked', id: 'edit-picked', 'aria-live': 'polite' });
  const buttons = new Map();
  const reasons = h('ul', { class: 'edit-reasons hint', id: 'edit-reasons' });
  for (const entry of EDIT_OPS) {
    const b = h('button', { type: 'button', class: 'tool', 'data-op': entry.op, title: `${entry.label} (${entry.key}): ${entry.counts}`, onclick: () => run(entry.op) }, entry.label);
    buttons.set(entry.op, b);
  }
  const compactButton = h('button', { type: 'button', class: 'tool', id: 'edit-compact', onclick: () => runCompact(),
    title: 'Renumber the tables without the gaps removed elements left' }, 'Compact numbering');

  const euler = h('p', { class: 'edit-euler', id: 'edit-euler', 'aria-live': 'polite' });
  const costs = h('table', { class: 'data-table edit-costs', id: 'edit-costs' });
  const costNote = h('p', { class: 'edit-cost-note', id: 'edit-cost-note' });
  const growth = createGrowthPlot(ctx, { id: 'edit-growth', faces: COST_FACES, yLabel: 'entries read + written',
    caption: 'The same edit on grids of growing size: entries read + written by each representation (the core\'s counting reader)',
    names: (rep) => REPRESENTATION_NAMES[rep] ?? rep });
  const growthNote = h('p', { class: 'hint', id: 'edit-growth-note' });
  // The series of one operation kind, once per panel (the core measures small grids and
  // gives every size exactly: edit_costs.h); a refusal (no face of a triangle grid can be
  // split) is kept as its message.
  const growthByOp = new Map();
  const growthOf = (op) => {
    if (!growthByOp.has(op)) {
      try {
        const g = ctx.api.editCostGrowth(op, COST_GRIDS);
        const series = {};
        g.costs.forEach((c) => { for (const [rep, { reads, writes }] of Object.entries(c)) (series[rep] ??= []).push(reads + writes); });
        growthByOp.set(op, { sizes: g.sizes, series, reads: g.costs.map((c) => Object.fromEntries(Object.entries(c).map(([rep, x]) => [rep, x.reads]))) });
      } catch (err) {
        growthByOp.set(op, { refused: /** @type {Error} */ (err).message });
      }
    }
    return growthByOp.get(op);
  };
  const phaseList = h('ol', { class: 'pseudocode edit-phases', id: 'edit-phases', 'aria-label': 'The algorithm of the last edit' });
  const stepList = h('ol', { class: 'pseudocode edit-steps', id: 'edit-steps', 'aria-label': 'Pointer assignments of the last edit' });
  let scrollFrame = 0; // the step list's scroll, waiting for the next frame
  const stepLabel = h('span', { class: 'walk-step', id: 'edit-step' });
  // The assignment the player is at, in one line under its buttons: the player and this line
  // sit at the top of the side column (panels.js), above the walk, which folds away while
  // an edit plays, so the drawing, this line and the rewritten cell are on one screen.
  const currentLine = h('p', { class: 'edit-current', id: 'edit-current', 'aria-live': 'polite' });
  const lastTitle = h('h3', { id: 'edit-last' }, 'Last edit');
  // The pointer entries each structure wrote in the last edit (the core's count of each).
  const written = h('p', { class: 'edit-written', id: 'edit-written' });

  const player = createPlayer({
    count: () => playbackSteps(ctx.model?.lastOperation, state().tab).length + 1,
    getStep: () => shownSteps(),
    onStep: (i) => ctx.commit({ ...state(), editStep: i }, { history: false }),
    stepsPerSecond: 2,
  });
  const shownSteps = () => {
    const n = playbackSteps(ctx.model?.lastOperation, state().tab).length;
    const s = state().editStep;
    return s < 0 || s > n ? n : s;
  };
  // The visible text is the accessible name (axe: label-content-name-mismatch); the title adds the why.
  const tool = (label, action, title, id) => h('button', { type: 'button', class: 'tool', title, onclick: action, id }, label);
  const playButton = tool('▶ Play', () => player.toggle(), 'Play the last edit assignment by assignment', 'edit-play');
  player.onChange(() => { playButton.textContent = player.playing ? '⏸ Pause' : '▶ Play'; playButton.setAttribute('aria-pressed', String(player.playing)); });

  const controls = h('div', { class: 'walk-controls', role: 'group', 'aria-label': 'Edit player' },
    tool('|◀ Before', () => player.restart(), 'Before the edit: no assignment made yet', 'edit-restart'),
    tool('◀ Back', () => player.prev(), 'Previous assignment', 'edit-back'),
    playButton,
    tool('Step ▶', () => player.next(), 'Next assignment', 'edit-next'),
    tool('After ▶|', () => player.end(), 'After the edit: every assignment made', 'edit-end'),
    stepLabel);
  const now = h('section', { class: 'edit-now', id: 'edit-now', 'aria-label': 'Playing the last edit', hidden: true },
    h('h2', { class: 'edit-now-title', id: 'edit-now-title' }), controls, currentLine);

  const root = h('section', { class: 'walk-panel edit-panel', id: 'edit-panel', 'aria-labelledby': 'edit-title' },
    h('h2', { id: 'edit-title' }, 'Edit the mesh'),
    h('div', { class: 'walk-choice' }, h('label', {}, 'Pick ', kindSelect), number, picked),
    h('div', { class: 'walk-choice' }, h('label', {}, 't ', tInput), tValue, corners),
    h('div', { class: 'edit-buttons', role: 'group', 'aria-label': 'Operations' }, ...buttons.values(), compactButton),
    reasons,
    euler,
    lastTitle,
    written,
    phaseList,
    stepList,
    costs,
    costNote,
    growth.root,
    growthNote);

  // The operation of the state that pressing `op` makes now, or null when nothing fits.
  function operationFor(op) {
    const entry = EDIT_OP[op];
    const p = selection.pick;
    if (!p || p.kind !== entry.needs || !ctx.model) return null;
    return entry.make(p.index, { t: state().editT, a: Number(cornerA.value), b: Number(cornerB.value) });
  }

  function checkOf(op) {
    const operation = operationFor(op);
    const entry = EDIT_OP[op];
    if (!operation) return { ok: false, message: `pick ${entry.needs === 'edge' ? 'an edge' : `a ${entry.needs}`} first` };
    return ctx.model.mesh.check(operation);
  }

  function run(op) {
    const check = checkOf(op);
    if (!check.ok) {
      ctx.message.error(`${EDIT_OP[op].label}: ${check.message}`, check.code ?? 'not-applicable');
      return;
    }
    const operation = operationFor(op);
    if (ctx.commit(withEdit(state(), operation))) ctx.message.info(`Done: ${EDIT_OP[op].what(operation)}. Step through the assignments below, or undo (Ctrl+Z).`);
  }

  function runCompact() {
    if (ctx.commit(withEdit(state(), { op: 'compact' }))) {
      selection.pick = null;
      ctx.message.info('Compacted: the gaps are gone and the elements after them moved up; the tables show the new numbers.');
    }
  }

  // While an edit exercise is answered the drawing stays the mesh before the operation: the
  // operations' keys are off (the panel itself is hidden), or a key would draw the answer.
  for (const entry of EDIT_OPS) {
    ctx.keymap.add({ keys: [entry.key], label: `${entry.label.toLowerCase()} (the picked ${entry.needs})`, group: 'Edit',
      action: () => run(entry.op), when: () => selection.pick?.kind === entry.needs && ctx.ui.exercise !== 'edit' });
  }

  // The choices for the picked element (the registry's query: the corners of a face, the
  // neighbours of a vertex), read again when the mesh or the pick changes; a choice the
  // person made stays while the element still offers it.
  let lastCornersKey = null;
  function refreshCorners(model) {
    const p = selection.pick;
    const chooser = p && exists(model, p) ? EDIT_OPS.find((o) => o.needs === p.kind && o.choices.length === 2) : null;
    corners.hidden = !chooser;
    if (!chooser) { lastCornersKey = null; return; }
    const key = `${model.topology}:${p.kind}:${p.index}`;
    if (key === lastCornersKey) return;
    lastCornersKey = key;
    cornerA.setAttribute('aria-label', `${chooser.label}: ${chooser.choices[0].label}`);
    cornerB.setAttribute('aria-label', `${chooser.label}: ${chooser.choices[1].label}`);
    const list = Array.from(model.mesh.adjacency(chooser.choices[0].choices, p.index));
    const options = () => list.map((v) => h('option', { value: String(v) }, vLabel(v)));
    const [a, b] = [Number(cornerA.value), Number(cornerB.value)];
    cornerA.replaceChildren(...options());
    cornerB.replaceChildren(...options());
    cornerA.value = String(keptCorner(a, list, list[0]));
    cornerB.value = String(keptCorner(b, list, list[Math.min(2, list.length - 1)]));
  }

  function refreshButtons() {
    const items = [];
    for (const entry of EDIT_OPS) {
      const b = buttons.get(entry.op);
      const applies = selection.pick?.kind === entry.needs;
      b.hidden = Boolean(selection.pick) && !applies;
      const check = applies ? checkOf(entry.op) : null;
      b.disabled = !check?.ok;
      b.setAttribute('aria-disabled', String(!check?.ok));
      if (applies && !check.ok) items.push(h('li', { 'data-op': entry.op, 'data-code': check.code }, `${entry.label}: ${check.message}`));
    }
    if (!selection.pick) items.push(h('li', {}, 'Pick a vertex, edge or face (click or tap it, click its table row, or type its number above); the operations that apply to it appear here.'));
    reasons.replaceChildren(...items);
  }

  // V − E + F after the last edit, and before it (the record's added and removed elements
  // taken back): an Euler operation keeps the sum.
  function refreshEuler(model) {
    const c = model.counts;
    const r = model.lastOperation;
    const back = (kind) => (r ? (r.removed?.[kind]?.length ?? 0) - (r.added?.[kind]?.length ?? 0) : 0);
    const [v0, e0, f0] = [c.vertices + back('vertices'), c.edges + back('edges'), c.faces + back('faces')];
    const before = r && r.steps?.length ? `before the last edit ${v0} − ${e0} + ${f0} = ${v0 - e0 + f0}; after it ` : '';
    euler.textContent = `V − E + F: ${before}${c.vertices} − ${c.edges} + ${c.faces} = ${c.euler}` +
      ` · boundary loops ${c.boundaryLoops}${model.gaps ? ` · ${model.gaps} numbers are gaps left by removed elements` : ''}` +
      ` · edits ${model.editCount}`;
  }

  // What the playback and the costs last showed: a walk step, a hover or a pick updates the
  // panels too, and must not rebuild the step list, the cost table and the chart (they change
  // with the edit, the player's step, the mesh's size and the theme only).
  let playbackShown = null;
  let costsShown = null;
  const same = (a, b) => a !== null && b !== null && a.length === b.length && a.every((x, i) => x === b[i]);

  function refreshPlayback(model) {
    const record = model.lastOperation;
    const steps = playbackSteps(record, state().tab);
    const shown = shownSteps();
    const key = [record, shown, model.lastEdit, model.F, ctx.colors, model.halfEdgePlayback];
    if (same(key, playbackShown)) return;
    playbackShown = key;
    // On the half-edge tab the player plays the same edit in half-edge terms.
    const what = model.halfEdgePlayback ? `${steps.length} half-edge entries` : `${steps.length} assignments`;
    lastTitle.textContent = record ? `Last edit: ${EDIT_OP[record.op]?.what(model.lastEdit) ?? record.op} — ${what}`
      : model.lastEdit?.op === 'compact' ? 'Last edit: compact (every table renumbered without its gaps)' : 'Last edit: none yet';
    stepLabel.textContent = record ? `${shown} of ${steps.length}` : '';
    now.hidden = !record;
    now.firstElementChild.textContent = lastTitle.textContent;
    currentLine.textContent = !record ? '' : shown === 0 ? 'Before the edit: no assignment made yet.'
      : `${shown === steps.length ? 'Last assignment' : `Assignment ${shown}`}: ${playbackStepText(steps[shown - 1])}${record.phases?.[steps[shown - 1].phase] ? ` (${record.phases[steps[shown - 1].phase]})` : ''}`;
    for (const b of controls.querySelectorAll('button')) b.disabled = !record;
    // The algorithm's lines (the core's), the one that made the current assignment marked.
    const phase = shown > 0 ? steps[shown - 1].phase : -1;
    phaseList.replaceChildren(...(record?.phases ?? []).map((line, i) => h('li', { 'data-line': i, class: i === phase ? 'is-current' : '', 'aria-current': i === phase ? 'step' : null }, line)));
    stepList.replaceChildren(...steps.map((s, i) => h('li', { 'data-step': i, class: i < shown ? (i === shown - 1 ? 'is-current' : 'is-done') : '' }, playbackStepText(s))));
    const counted = record?.halfEdge?.written;
    written.hidden = !counted;
    written.textContent = counted ? `Pointer entries written: winged edge ${count(counted['winged-edge'])}, half-edge ${count(counted['half-edge'])}`
      + ' (the winged edge counts each assignment its algorithm made, the half-edge each entry that changed; the Half-edge tab plays them one at a time).' : '';
    phaseList.hidden = !phaseList.children.length;
    stepList.hidden = !steps.length;
    // The current line within the list's own box only (the column scrolls to the table's
    // rewritten cell, tabs.js; the page never scrolls), at the start of the next frame: the
    // list is laid out by then, so its place is read without a layout of its own.
    if (!scrollFrame) {
      scrollFrame = requestAnimationFrame(() => {
        scrollFrame = 0;
        const currentItem = stepList.querySelector('.is-current');
        if (!currentItem || stepList.hidden) return;
        const r = currentItem.getBoundingClientRect();
        const b = stepList.getBoundingClientRect();
        if (r.top < b.top || r.bottom > b.bottom) stepList.scrollTop += r.top - b.top - (b.height - r.height) / 2;
      });
    }
    refreshCosts(model, record);
  }

  // What the last edit cost each representation, in the lesson's words, and the same edit's
  // cost against mesh size: the winged edge's flat, a table without adjacency searching.
  function refreshCosts(model, record) {
    const cost = model.editCost;
    const key = [record, cost, model.lastEdit, model.F, ctx.colors];
    if (same(key, costsShown)) return;
    costsShown = key;
    costNote.hidden = growth.root.hidden = growthNote.hidden = !cost;
    if (!cost || !record) { costs.replaceChildren(); return; }
    costs.replaceChildren(
      h('caption', {}, 'What the last edit cost each representation: entries of its tables read to find what to change, and entries written'),
      h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'representation'), h('th', { scope: 'col' }, 'read'), h('th', { scope: 'col' }, 'written'), h('th', { scope: 'col' }, 'read + written'))),
      h('tbody', {}, Object.entries(cost).map(([key, c]) => h('tr', { 'data-representation': key },
        h('th', { scope: 'row' }, REPRESENTATION_NAMES[key] ?? key), h('td', { 'data-cost': 'reads' }, count(c.reads)),
        h('td', { 'data-cost': 'writes' }, count(c.writes)), h('td', {}, count(c.reads + c.writes))))));
    const entry = EDIT_OP[record.op];
    const finds = entry?.finds(model.lastEdit ?? {}) || 'what it changes';
    const we = cost['winged-edge'];
    const words = [`The winged edge wrote ${we.writes} entries (one per line of the playback above: ${visibleSteps(record).length} lines) and read ${we.reads} to find ${finds}: only the records around them.`];
    const g = growthOf(record.op);
    const last = COST_FACES.length - 1;
    // On a big mesh the core counted the winged edge alone (ui/mesh/mesh-source.js,
    // COUNTED_COSTS_FACES): the others are in the chart, measured on grids.
    const alone = Object.keys(cost).length === 1;
    const grows = g.refused ? [] : Object.keys(g.reads[0]).filter((rep) => g.reads[last][rep] > g.reads[0][rep]);
    const searching = alone ? [] : grows.filter((rep) => rep in cost);
    if (alone) {
      words.push(`On a mesh of ${count(model.F)} faces only the winged edge is counted after each edit: counting the other representations means building them again before and after the edit, itself a pass over every face, the very cost the lesson warns about.`,
        g.refused ? '' : `The chart below gives what the same edit costs each of them on grids up to ${count(COST_FACES[last])} faces${grows.length ? `: the ${listed(grows.map((rep) => REPRESENTATION_NAMES[rep].toLowerCase()))} search the whole mesh` : ''}.`);
    } else if (searching.length) {
      const names = searching.map((rep) => `${REPRESENTATION_NAMES[rep].toLowerCase()} (${count(cost[rep].reads)} read, ${count(cost[rep].writes)} written)`);
      words.push(`The ${listed(names)} had to search the whole mesh, all ${count(model.F)} faces, to find ${finds}: they store no way from one element to its neighbours.`,
        `On a grid of ${count(COST_FACES[last])} faces the same edit reads ${listed(searching.map((rep) => `${count(g.reads[last][rep])} (${REPRESENTATION_NAMES[rep].toLowerCase()})`))}; the winged edge still reads ${count(g.reads[last]['winged-edge'])}.`);
    } else if (!g.refused) {
      words.push(`Every representation finds ${finds} from the element itself here, without a search: the cost does not grow with the mesh (chart below).`);
    }
    words.push('Written counts, for the winged edge, each assignment its algorithm made (an entry written twice is two); for the others, the entries that differ before and after.');
    costNote.textContent = words.filter(Boolean).join(' ');
    growth.root.hidden = Boolean(g.refused);
    growthNote.textContent = g.refused ? `No chart against mesh size: on a grid of triangles ${g.refused}.` : `The winged edge's line is flat: its cost depends on the neighbourhood, not on F.${grows.length ? ' A searching representation\'s line climbs with F.' : ''}`;
    if (!g.refused) growth.update(g);
  }

  return {
    root,
    // The player and the current assignment (panels.js places it above the walk).
    now,
    update(model) {
      const p = selection.pick;
      const gone = goneNote(selection, model);
      picked.textContent = p ? `Picked: ${LABEL[p.kind](p.index)}` : gone ? `Nothing picked (${gone})` : 'Nothing picked';
      if (p) { kindSelect.value = p.kind; number.value = String(p.index + 1); }
      number.max = String({ vertex: model.V, edge: model.E, face: model.F }[kindSelect.value]);
      tInput.value = String(state().editT);
      tValue.textContent = String(state().editT);
      refreshCorners(model);
      refreshButtons();
      refreshEuler(model);
      compactButton.disabled = !model.gaps;
      compactButton.title = model.gaps ? `Renumber the tables without the ${model.gaps} gaps removed elements left` : 'Nothing to compact: no element has been removed';
      refreshPlayback(model);
    },
  };
}
