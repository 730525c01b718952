// @ts-check
// The controls and panels of the subdivision lesson: the mesh and scheme, the level and the
// phase player, the mask of the chosen new point (its old vertices and weights as the core
// gave them), the counts, the winged-edge tables of what is shown and the curve beside it.
// Everything shown comes from the model; the person's choices go back through ctx.commit.
import { h, revealInBoxes } from '../../app/dom.js';
import { findDescriptor, columnHeading } from '../../core/tables.js';
import { createVirtualTable } from '../../ui/virtual-table.js';
import { createCurvePlot } from './curve-plot.js';
import { createExplorerLink } from './explorer-link.js';
import { formatNumber } from '../../ui/mathml.js';
import { SOURCES, SIZES, PHASES, MAX_LEVEL, label, viewOf } from './source.js';
import { createMeshChooser } from '../../ui/mesh/chooser.js';
import { createWingedTables } from '../../ui/mesh/tables.js';
import { createReconnectionPanel, tableEntry, currentCell } from './reconnection.js';
import { NEW_POINT_LABELS } from './draw.js';
import { formatWeight } from './format-weight.js';
import { createTurnControls, MAX_TILT } from '../../ui/turn-controls.js';

const PHASE_NAMES = { 'face-points': 'face points', 'edge-points': 'edge points', 'vertex-points': 'vertex points', reconnection: 'reconnection' };
const RULE_NAMES = {
  'face-point': 'face point: the centroid of the face',
  'edge-interior': 'interior edge rule',
  'edge-boundary': 'boundary edge: the midpoint (the curve rule)',
  'vertex-interior': 'interior vertex rule',
  'vertex-boundary': 'boundary vertex: 1/8, 6/8, 1/8 (the cubic B-spline curve rule)',
  'vertex-isolated': 'isolated vertex: stays',
};
const LISTED_EXTRAORDINARY = 12;
const ROTATE_STEP = 0.1; // radians per arrow key on the focused canvas
const DRAG_RADIANS_PER_PX = 0.01;

const labelled = (text, control) => h('label', {}, text, ' ', control);

export function setupPanels(ctx, view) {
  const state = () => ctx.state;
  const stage = ctx.stage.canvas;

  // ------------------------------------------------------------ mesh, scheme, level, phase
  const chooser = createMeshChooser(ctx, { kinds: SOURCES, sizes: SIZES, choose, importClass: 'tool advanced' });
  const schemeSelect = h('select', { id: 'scheme', 'aria-label': 'Scheme' },
    h('option', { value: 'loop' }, 'Loop (triangles)'), h('option', { value: 'catmull-clark' }, 'Catmull-Clark (any polygons)'));
  const button = (text, action, title, id) => h('button', { type: 'button', class: 'tool', title, 'aria-label': title, id, onclick: action }, text);
  const levelLabel = h('span', { class: 'level-label', id: 'level-label', 'aria-live': 'polite' });
  const phaseLabel = h('span', { class: 'phase-label', id: 'phase-label', 'aria-live': 'polite' });
  const limitBox = h('input', { type: 'checkbox', id: 'limit-positions' });
  const shadingSelect = h('select', { id: 'shading', 'aria-label': 'Shading' }, h('option', { value: 'flat' }, 'flat'), h('option', { value: 'smooth' }, 'smooth'));

  const commit = (patch, options) => ctx.commit({ ...state(), ...patch }, options);
  const turnControls = createTurnControls((rotation) => commit({ rotation }, { coalesce: 'rotate' }), { onEnd: () => ctx.endGesture() });

  ctx.controls.replaceChildren(
    ...chooser.elements,
    labelled('Scheme', schemeSelect),
    h('span', { class: 'level-group', role: 'group', 'aria-label': 'Level' },
      button('−', () => levelTo(state().level - 1), 'Level down (< or ↓)', 'level-down'), levelLabel,
      button('+', () => levelTo(state().level + 1), 'Level up (> or ↑)', 'level-up')),
    h('span', { class: 'phase-group', role: 'group', 'aria-label': 'Phases of one step' },
      button('◀ Back', () => prevPhase(), 'Back: the previous phase (← or PageUp)', 'phase-prev'),
      button('Next phase ▶', () => nextPhase(), 'Next phase (→, n or PageDown)', 'phase-next'), phaseLabel),
    h('label', {}, limitBox, ' limit positions (l)'),
    labelled('Shading', shadingSelect), turnControls.root,
    h('span', { class: 'hint advanced' }, 'Drag a control vertex to reshape; drag elsewhere with a mouse, or use turn and tilt, to turn (arrows on the canvas); click a new point for its mask.'),
  );

  // A new mesh or scheme starts at level 0. Loop refuses a mesh with faces that are not
  // triangles (the core names the face): the message offers Catmull-Clark.
  function choose(patch) {
    // Another mesh opens in its own view (source.js: the lecture's example from the top).
    const turn = patch.meshKind && patch.meshKind !== state().meshKind ? { rotation: viewOf(patch.meshKind) } : {};
    const next = { ...state(), ...patch, ...turn, moved: patch.scheme ? state().moved : [], level: 0, phase: 0, focus: -1, reconnect: -1 };
    if (ctx.commit(next)) {
      levelNote.hidden = true;
      queueMicrotask(() => ctx.fitView());
      return;
    }
    syncControls();
    const refusal = view.lastRefusal;
    if (next.scheme === 'loop' && refusal?.code === 'not-a-triangle-mesh') {
      ctx.message.warn(refusal.message, {
        code: 'not-a-triangle-mesh', sticky: true,
        action: { id: 'use-catmull-clark', label: 'Use Catmull-Clark', run: () => choose({ ...patch, scheme: 'catmull-clark' }) },
      });
    }
  }
  schemeSelect.addEventListener('change', () => choose({ scheme: schemeSelect.value }));
  limitBox.addEventListener('change', () => commit({ limit: limitBox.checked }));
  shadingSelect.addEventListener('change', () => commit({ shading: shadingSelect.value }));

  // A level the core refuses (too large for the mesh limits) keeps the level shown and
  // says why, here and on the message line.
  function levelTo(k) {
    if (k < 0) return;
    if (k > MAX_LEVEL) {
      ctx.message.info(`Level ${MAX_LEVEL} is the last level this page shows.`);
      return;
    }
    const ok = commit({ level: k, phase: 0, focus: -1, reconnect: -1 });
    levelNote.hidden = ok;
    levelNote.textContent = ok ? '' : ctx.message.text;
  }
  // Phases with no points (Loop has no face points) are stepped over.
  const empty = (p) => p < PHASES.length && ctx.model?.phases[p - 1]?.count === 0;
  function nextPhase() {
    const s = state();
    if (s.phase >= PHASES.length) { levelTo(s.level + 1); return; }
    let p = s.phase + 1;
    while (empty(p)) p += 1;
    const ok = commit({ phase: p, focus: -1, reconnect: -1 });
    levelNote.hidden = ok;
    levelNote.textContent = ok ? '' : ctx.message.text;
  }
  function prevPhase() {
    const s = state();
    if (s.phase === 0) {
      if (s.level > 0) commit({ level: s.level - 1, phase: PHASES.length, focus: -1, reconnect: -1 });
      return;
    }
    let p = s.phase - 1;
    while (p > 0 && empty(p)) p -= 1;
    commit({ phase: p, focus: -1, reconnect: -1 });
  }

  const notOnCanvas = (event) => event.target !== stage;
  ctx.setPresenter({ next: nextPhase, prev: prevPhase, reset: () => commit({ level: 0, phase: 0, focus: -1, reconnect: -1 }), toggleOverlays: () => commit({ limit: !state().limit }) });
  ctx.keymap.add({ keys: ['ArrowRight'], label: 'next phase of the step (canvas not focused)', group: 'Subdivision', action: nextPhase, when: notOnCanvas });
  ctx.keymap.add({ keys: ['ArrowLeft'], label: 'previous phase', group: 'Subdivision', action: prevPhase, when: notOnCanvas });
  ctx.keymap.add({ keys: ['>', 'ArrowUp'], label: 'level up (↑: canvas not focused)', group: 'Subdivision', action: () => levelTo(state().level + 1), when: (e) => e.key === '>' || notOnCanvas(e) });
  ctx.keymap.add({ keys: ['<', 'ArrowDown'], label: 'level down', group: 'Subdivision', action: () => levelTo(state().level - 1), when: (e) => e.key === '<' || notOnCanvas(e) });
  ctx.keymap.add({ keys: ['l'], label: 'limit positions on / off', group: 'Subdivision', action: () => commit({ limit: !state().limit }) });
  ctx.keymap.add({ keys: ['s'], label: 'flat / smooth shading', group: 'Subdivision', action: () => commit({ shading: state().shading === 'flat' ? 'smooth' : 'flat' }) });
  ctx.keymap.add({ keys: ['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown'], label: 'turn the mesh (canvas focused)', group: 'View',
    when: (e) => e.target === stage,
    action: (e) => {
      const { yaw, pitch } = state().rotation;
      const d = { ArrowLeft: [-ROTATE_STEP, 0], ArrowRight: [ROTATE_STEP, 0], ArrowUp: [0, -ROTATE_STEP], ArrowDown: [0, ROTATE_STEP] }[e.key];
      commit({ rotation: { yaw: yaw + d[0], pitch: Math.max(-MAX_TILT, Math.min(MAX_TILT, pitch + d[1])) } }, { coalesce: 'rotate' });
    } });

  // Turning by dragging (mouse, pen or finger: pointer events); one undo step per drag.
  window.addEventListener('pointermove', (event) => {
    const r = view.rotating;
    if (!r) return;
    const yaw = r.yaw + (event.clientX - r.x) * DRAG_RADIANS_PER_PX;
    const pitch = Math.max(-MAX_TILT, Math.min(MAX_TILT, r.pitch + (event.clientY - r.y) * DRAG_RADIANS_PER_PX));
    commit({ rotation: { yaw, pitch } }, { coalesce: 'rotate' });
  });
  const endRotation = () => { if (view.rotating) { view.rotating = null; ctx.endGesture(); } };
  window.addEventListener('pointerup', endRotation);
  window.addEventListener('pointercancel', endRotation);

  // ------------------------------------------------------------ the step panel
  const phaseList = h('ol', { class: 'phase-list', id: 'phase-list' });
  const countCells = {};
  const countRow = (what, name) => {
    const cells = ['level', 'now', 'next'].map((col) => (countCells[`${name}-${col}`] = h('td', { id: `count-${name}-${col}` })));
    return h('tr', {}, h('th', { scope: 'row' }, what), ...cells);
  };
  const levelHead = h('th', { scope: 'col' }, 'level');
  const nextHead = h('th', { scope: 'col' }, 'next level');
  const countsTable = h('table', { class: 'data-table counts-table', id: 'counts' },
    h('caption', {}, 'Vertices, edges, faces'),
    h('thead', {}, h('tr', {}, h('th', {}, ''), levelHead, h('th', { scope: 'col' }, 'shown'), nextHead)),
    h('tbody', {}, countRow('V', 'vertices'), countRow('E', 'edges'), countRow('F', 'faces')));
  const levelNote = h('p', { class: 'callout warning level-note', id: 'level-note', hidden: true, 'aria-live': 'polite' });
  const maskTitle = h('h3', { id: 'mask-title' });
  const maskRule = h('p', { class: 'mask-rule', id: 'mask-rule' });
  const maskTerms = h('ul', { class: 'mask-terms', id: 'mask-terms' });
  const maskValence = h('p', { class: 'mask-valence', id: 'mask-valence' });
  const maskPanel = h('section', { class: 'mask-panel', id: 'mask-panel', 'aria-live': 'polite' }, maskTitle, maskRule, maskTerms, maskValence);
  const extraordinary = h('p', { class: 'extraordinary', id: 'extraordinary' });
  const reconnection = createReconnectionPanel(ctx, { onStep: (i) => commit({ reconnect: i }, { history: false }) });
  const stepPanel = h('section', { class: 'step-panel', id: 'step-panel', 'aria-labelledby': 'step-title' },
    h('h2', { id: 'step-title' }, 'One step, phase by phase'), levelNote, phaseList, reconnection.root, maskPanel, countsTable, extraordinary);

  // ------------------------------------------------------------ the curve beside it
  const curveScheme = h('select', { id: 'curve-scheme', 'aria-label': 'Curve scheme' },
    h('option', { value: 'chaikin' }, 'Chaikin (quadratic B-spline)'), h('option', { value: 'cubic-bspline' }, 'cubic (Lane-Riesenfeld)'));
  curveScheme.addEventListener('change', () => commit({ curveScheme: curveScheme.value }));
  const curveCaption = h('p', { class: 'hint', id: 'curve-caption' });
  const closedBox = h('input', { type: 'checkbox', id: 'curve-closed' });
  closedBox.addEventListener('change', () => commit({ curve: { ...state().curve, closed: closedBox.checked } }));
  const curvePanel = h('section', { class: 'curve-panel', id: 'curve-panel', 'aria-labelledby': 'curve-title' },
    h('h2', { id: 'curve-title' }, 'The same rule on a curve'), labelled('Scheme', curveScheme), h('label', {}, closedBox, ' closed'));
  const curvePlot = createCurvePlot(curvePanel, ctx);
  const explorerAnchor = h('a', { href: 'curves.html', id: 'curve-explorer-link' }, 'insert a knot into this polygon\'s B-spline in the curve explorer');
  const explorerLink = createExplorerLink(explorerAnchor, ctx);
  // The scheme's own name: Chaikin's step is knot insertion into the quadratic B-spline,
  // the cubic rule's into the cubic one (both at the middle of every span).
  const insertionScheme = h('span', { id: 'curve-insertion-scheme' }, 'One cubic step');
  curvePanel.append(curveCaption, h('p', {}, insertionScheme, ' is knot insertion at the middle of every span: ', explorerAnchor,
    ' (an open B-spline: a closed polygon goes there open).'));

  // ------------------------------------------------------------ winged-edge tables
  const descriptor = (name) => findDescriptor(ctx.api.tableDescriptors, 'winged-edge', name);
  const wingedTables = createWingedTables(ctx.api);
  const tableOf = (name) => wingedTables(ctx.model.we, ctx.model.counts)[name];
  const cell = (column, value) => {
    if (column.refers) return label(column.refers, value);
    return Array.isArray(value) ? value.map((x) => formatNumber(x, 4)).join(', ') : formatNumber(value, 4);
  };
  const wingedTable = (name, id) => {
    const d = descriptor(name);
    return createVirtualTable({
      id, caption: d.title, head: [['', ...d.columns.map((c) => columnHeading(c))]],
      rowLabel: (i) => label(d.rows, i),
      // During the reconnection's playback an entry shows once the core has written it.
      row: (i) => { const r = tableOf(name).row(i); return d.columns.map((c) => tableEntry(ctx.model, d.rows, i, c.name, cell(c, r[c.name]))); },
    });
  };
  const tables = { vertices: wingedTable('vertices', 'sub-vertex-table'), edges: wingedTable('edges', 'sub-edge-table'), faces: wingedTable('faces', 'sub-face-table') };
  const tablesPanel = h('section', { class: 'tables-panel', id: 'tables-panel', 'aria-labelledby': 'tables-title' },
    h('h2', { id: 'tables-title' }, 'Winged-edge tables of the mesh shown'), ...Object.values(tables).map((t) => t.root));

  ctx.panels.replaceChildren(reconnection.playerBox, stepPanel, curvePanel, tablesPanel);

  function syncControls() {
    const s = state();
    chooser.sync(s);
    schemeSelect.value = s.scheme;
    limitBox.checked = s.limit;
    shadingSelect.value = s.shading;
    curveScheme.value = s.curveScheme;
    closedBox.checked = s.curve.closed;
    turnControls.sync(s.rotation);
  }

  function updateStep(model) {
    const nonEmpty = model.phases.filter((p) => p.count > 0 || p.name === 'reconnection');
    const done = new Set(model.shownPhases.map((p) => p.name));
    phaseList.replaceChildren(...PHASES.map((name, k) => {
      const phase = model.phases[k];
      const named = { 'face-points': ', each labelled with its face', 'edge-points': ', each labelled with its edge' }[name];
      const li = h('li', { 'data-phase': name }, PHASE_NAMES[name],
        phase && phase.name !== 'reconnection' ? ` (${phase.count}${phase.count > 0 && phase.count <= NEW_POINT_LABELS && named ? named : ''})` : '', phase?.count === 0 && phase.name !== 'reconnection' ? ' — none for this scheme' : '');
      li.classList.toggle('is-done', done.has(name));
      if (model.shownPhases.length && model.shownPhases[model.shownPhases.length - 1].name === name) li.setAttribute('aria-current', 'step');
      return li;
    }));
    levelLabel.textContent = `level ${model.level}`;
    const shownCount = nonEmpty.filter((p) => done.has(p.name)).length;
    phaseLabel.textContent = model.steps
      ? (shownCount ? `level ${model.level} → ${model.level + 1}, phase ${shownCount} of ${nonEmpty.length}: ${PHASE_NAMES[model.shownPhases[model.shownPhases.length - 1].name]}` : `level ${model.level}: no phase shown`)
      : 'no further step';
    // Counts: the level's, what is drawn now (the new points join V phase by phase; E and F
    // change at the reconnection), and the next level's (the core's counts of the step).
    const lc = model.levelCounts;
    const nc = model.nextCounts;
    const added = model.pointPhases.filter((p) => p.name !== 'vertex-points').reduce((n, p) => n + p.count, 0);
    const now = model.phase >= PHASES.length ? model.counts : { vertices: lc.vertices + added, edges: lc.edges, faces: lc.faces };
    levelHead.textContent = `level ${model.level}`;
    nextHead.textContent = `level ${model.level + 1}`;
    for (const name of ['vertices', 'edges', 'faces']) {
      countCells[`${name}-level`].textContent = lc[name].toLocaleString('en');
      countCells[`${name}-now`].textContent = now[name].toLocaleString('en');
      countCells[`${name}-next`].textContent = nc ? nc[name].toLocaleString('en') : '—';
    }
    if (!model.steps) { levelNote.hidden = false; levelNote.textContent = `Level ${model.level + 1} is refused: ${model.stepsRefusal}`; }
    updateMask(model);
    const ex = model.extraordinary;
    const regular = model.scheme === 'loop' ? 6 : 4;
    extraordinary.textContent = !model.steps || model.phase >= PHASES.length ? ''
      : ex.length ? `Extraordinary vertices (interior, valence ≠ ${regular}; ringed in the drawing): ${ex.slice(0, LISTED_EXTRAORDINARY).map(({ v, n }) => `${label('vertex', v)} (n = ${n})`).join(', ')}${ex.length > LISTED_EXTRAORDINARY ? ` and ${ex.length - LISTED_EXTRAORDINARY} more` : ''}.`
        : model.interiorVertices === 0 ? 'No interior vertex: every vertex is on the boundary and takes the boundary rule, so none is extraordinary.'
          : `No extraordinary vertices: every interior vertex has valence ${regular}.`;
  }

  function updateMask(model) {
    const i = model.focus;
    maskPanel.hidden = i < 0;
    if (i < 0) return;
    const s = model.steps;
    const { vertices: V, edges: E } = model.levelCounts;
    const rule = s.ruleNames[s.rules[i]];
    const what = i < V ? `vertex point of ${label('vertex', i)}` : i < V + E ? `edge point of ${label('edge', i - V)}` : `face point of ${label('face', i - V - E)}`;
    maskTitle.textContent = `Mask of the new ${label('vertex', i)} (${what})`;
    maskRule.textContent = RULE_NAMES[rule] ?? rule;
    const terms = [];
    for (let k = s.masks.offsets[i]; k < s.masks.offsets[i + 1]; k += 1) terms.push({ v: s.masks.vertices[k], w: s.masks.weights[k] });
    maskTerms.replaceChildren(...terms.map(({ v, w }) => h('li', { 'data-vertex': label('vertex', v) },
      h('span', { class: 'weight' }, formatWeight(w)), ' × ', h('span', { class: 'old-vertex' }, `old ${label('vertex', v)}`))));
    // The vertex rule's valence n, and for Loop beta: each neighbour's weight in the mask.
    if (rule === 'vertex-interior') {
      const neighbour = terms.find((t) => t.v !== i);
      maskValence.textContent = model.scheme === 'loop'
        ? `n = ${s.valences[i]}, β = ${neighbour ? formatWeight(neighbour.w) : '—'} (each neighbour's weight; the vertex keeps the rest)`
        : `n = ${s.valences[i]}`;
    } else maskValence.textContent = '';
  }

  let shownSource = null;
  return {
    curvePlot,
    update(model, s) {
      syncControls();
      if (!model) return;
      if (shownSource !== null && shownSource !== model.sourceKey) queueMicrotask(() => ctx.fitView());
      shownSource = model.sourceKey;
      updateStep(model);
      const c = model.curve;
      insertionScheme.textContent = c.degree === 2 ? 'One Chaikin step (quadratic B-spline)' : 'One cubic step';
      curveCaption.textContent = `${c.steps} step${c.steps === 1 ? '' : 's'} (as many as the mesh's level): ${c.control.length / 2} points became ${c.refined.length / 2}; the curve is the uniform ${c.closed ? 'periodic ' : ''}${c.degree === 2 ? 'quadratic' : 'cubic'} B-spline of the ${c.closed ? 'closed ' : ''}polygon, which the steps approach. Drag a control point to reshape.`;
      reconnection.update(model);
      for (const [name, t] of Object.entries(tables)) t.refresh(model.counts[name]);
      // The cell the reconnection wrote last: marked, and its row scrolled into its table's view.
      const written = currentCell(model);
      for (const [name, t] of Object.entries(tables)) {
        const here = written?.name === name;
        t.mark(here ? { rows: { 'is-highlighted': [written.row] }, read: [[written.row, written.column]] } : {});
        if (!here) continue;
        // The cell in view at every step: its table scrolled to the row, the side column (never
        // the page) to the cell, below the sticky player, with the table's head when it fits.
        const cellEl = t.reveal(written.row)?.children[written.column] ?? null;
        // (the margin keeps the cell and the head clear of the player at the column's top).
        revealInBoxes(cellEl, { context: t.table.tHead, margin: 8 + reconnection.coveredTop() });
      }
      explorerLink.update(model, s).catch((err) => ctx.message.error(`The link to the curve explorer could not be made: ${err.message}`, 'link-error'));
    },
  };
}
