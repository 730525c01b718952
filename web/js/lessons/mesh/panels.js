// The controls and panels of the mesh lesson: mesh choice, the walk player with its
// pseudocode, and the tabs of representations, queries, storage and planes. Everything
// shown comes from the model (what the core returned); the panels only lay it out and
// send the person's choices back through ctx.commit.
import { h } from '../../app/dom.js';
import { createPlayer } from '../../app/player.js';
import { MESH_KINDS } from './mesh-source.js';
import { PSEUDOCODE, foundEdges } from './walk.js';
import { createRepresentationTabs } from './tabs.js';
import { vLabel, fLabel } from './labels.js';
import { pickElement as elementAt } from './draw.js';
import { createEditPanel } from './edit-panel.js';
import { createTurnControls, MAX_TILT } from '../../ui/turn-controls.js';
import { exists, whyNot } from './live-elements.js';

const BIG_TABLES = 100000; // faces: from this size a new mesh's tables fill a task after its first frame

const TAB_LABELS = {
  winged: 'Winged edge', faces: 'Independent faces', 'vertex-face': 'Vertex & face tables', adjacency: 'Adjacency lists',
  'edge-list': 'Edge list (Foley)', queries: 'Queries', storage: 'Storage', planes: 'Planes & normals',
};

const FOUND_SHOWN = 12; // the last edges found; a pole of valence 100 would fill the panel

function labelled(labelText, control) {
  return h('label', {}, labelText, ' ', control);
}

// selection: the view's hovered and picked element ({kind, index} or null), owned by the
// lesson view (lesson.js setup) and read by the tables and the drawing.
export function setupPanels(ctx, selection) {
  const state = () => ctx.state;
  const commit = (patch, opts) => ctx.commit({ ...state(), ...patch }, opts);
  const stage = ctx.stage.canvas;

  // ------------------------------------------------------------ mesh choice
  const meshSelect = h('select', { id: 'mesh-kind', 'aria-label': 'Mesh' }, MESH_KINDS.map((k) => h('option', { value: k.id }, k.label)));
  const sizeInput = (id, label, min, max) => h('input', { type: 'number', id, min, max, step: 1, 'aria-label': label });
  const fanN = sizeInput('fan-size', 'Fan triangles', 1, 64);
  const gridX = sizeInput('grid-nx', 'Grid quads across', 1, 400);
  const gridY = sizeInput('grid-ny', 'Grid quads down', 1, 400);
  const sphereS = sizeInput('sphere-slices', 'Sphere slices', 3, 1000);
  const sphereT = sizeInput('sphere-stacks', 'Sphere stacks', 3, 600);
  const sizeGroups = {
    fan: h('span', { class: 'size-group' }, labelled('triangles', fanN)),
    grid: h('span', { class: 'size-group' }, labelled('nx', gridX), labelled('ny', gridY)),
    sphere: h('span', { class: 'size-group' }, labelled('slices', sphereS), labelled('stacks', sphereT)),
  };
  const importButton = h('button', { type: 'button', class: 'tool', onclick: () => document.getElementById('import-file')?.click() }, 'Open OFF/OBJ…');
  const toggle3d = h('button', { type: 'button', class: 'tool', id: 'toggle-3d', 'aria-pressed': 'false', onclick: () => set3d(!state().mode3d) }, '3D view');

  const turnControls = createTurnControls((rotation) => ctx.commit({ ...state(), rotation }, { history: false }));

  function chooseMesh(patch) {
    const next = { ...state(), ...patch, moved: [], ops: [], vertex: 0, face: 0, step: 0 };
    if (next.meshKind === 'lecture') next.vertex = 1;
    next.query = { ...next.query, vertex: next.vertex, face: 0, edge: 0 };
    next.mode3d = patch.meshKind && !['lecture', 'foley', 'fan', 'file'].includes(next.meshKind) ? true : (patch.meshKind ? false : next.mode3d);
    if (ctx.commit(next)) ctx.fitView();
    else syncControls();
  }
  function set3d(on) {
    if (ctx.commit({ ...state(), mode3d: on })) ctx.fitView();
  }
  meshSelect.addEventListener('change', () => {
    if (meshSelect.value === 'file' && !state().imported) {
      syncControls();
      document.getElementById('import-file')?.click();
      return;
    }
    chooseMesh({ meshKind: meshSelect.value });
  });
  const sizeChange = (input, make) => input.addEventListener('change', () => {
    const n = Number(input.value);
    if (!Number.isInteger(n) || n < Number(input.min) || n > Number(input.max)) {
      ctx.message.error(`${input.getAttribute('aria-label')} must be a whole number from ${input.min} to ${input.max}`, 'invalid-size');
      syncControls();
      return;
    }
    chooseMesh(make(n));
  });
  sizeChange(fanN, (n) => ({ fanSize: n }));
  sizeChange(gridX, (n) => ({ grid: { ...state().grid, nx: n } }));
  sizeChange(gridY, (n) => ({ grid: { ...state().grid, ny: n } }));
  sizeChange(sphereS, (n) => ({ sphere: { ...state().sphere, slices: n } }));
  sizeChange(sphereT, (n) => ({ sphere: { ...state().sphere, stacks: n } }));

  ctx.controls.replaceChildren(
    labelled('Mesh', meshSelect), ...Object.values(sizeGroups), importButton, toggle3d, turnControls.root,
    h('span', { class: 'hint' }, 'Drag a vertex to move it (a click without dragging makes it the walk\'s vertex); drag empty space to pan (in 3D: to rotate, or use turn and tilt); wheel or two fingers zoom; hover an edge or face to find its table rows.'),
  );

  // ------------------------------------------------------------ the walk
  const walkKind = h('select', { id: 'walk-kind', 'aria-label': 'Walk' },
    h('option', { value: 'vertex' }, 'CCW edges around a vertex'), h('option', { value: 'face' }, 'Edges of a face'));
  const walkElement = h('input', { type: 'number', id: 'walk-element', min: 1, step: 1, 'aria-label': 'Vertex or face number (1-based, as on the slide)' });
  const walkElementLabel = h('label', { for: 'walk-element' }, 'v');
  const code = h('ol', { class: 'pseudocode', id: 'walk-code', 'aria-label': 'Pseudocode' });
  const narration = h('p', { class: 'walk-text', id: 'walk-text', 'aria-live': 'polite' });
  const found = h('p', { class: 'walk-found', id: 'walk-found' });
  // Shown when the walked element's normal points away from the viewer (issue 13 item 11).
  const side = h('p', { class: 'walk-side hint', id: 'walk-side', 'aria-live': 'polite', hidden: true });
  walkKind.addEventListener('change', () => commit({ walk: walkKind.value, step: 0 }, { history: false }));
  walkElement.addEventListener('change', () => {
    const n = Number(walkElement.value) - 1;
    const limit = state().walk === 'vertex' ? ctx.model.V : ctx.model.F;
    if (!Number.isInteger(n) || n < 0 || n >= limit) {
      ctx.message.error(`Choose a number from 1 to ${limit}`, 'invalid-element');
      syncControls();
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
  const button = (label, action, title) => h('button', { type: 'button', class: 'tool', title, 'aria-label': title, onclick: action }, label);
  const playButton = button('▶ Play', () => player.toggle(), 'Play or pause the walk (Space)');
  playButton.id = 'walk-play';
  const speed = h('input', { type: 'range', id: 'walk-speed', min: 0.25, max: 6, step: 0.25, 'aria-label': 'Steps per second' });
  speed.addEventListener('input', () => { player.setSpeed(Number(speed.value)); commit({ speed: Number(speed.value) }, { history: false, recompute: false }); });
  const stepLabel = h('span', { class: 'walk-step', id: 'walk-step' });
  player.onChange(() => { playButton.textContent = player.playing ? '⏸ Pause' : '▶ Play'; playButton.setAttribute('aria-pressed', String(player.playing)); });

  const walkPanel = h('section', { class: 'walk-panel', id: 'walk-panel', 'aria-labelledby': 'walk-title' },
    h('h2', { id: 'walk-title' }, 'Winged-edge walk'),
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
  ctx.keymap.add({ keys: [' '], label: 'play / pause the walk', group: 'Walk', action: () => player.toggle(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['ArrowRight', 'PageDown', 'n'], label: 'next step of the walk (arrows when the canvas is not focused)', group: 'Walk', action: () => player.next(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['ArrowLeft', 'PageUp', 'b'], label: 'previous step of the walk', group: 'Walk', action: () => player.prev(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['Home'], label: 'restart the walk', group: 'Walk', action: () => player.restart(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['End'], label: 'last step of the walk', group: 'Walk', action: () => player.end(), when: notOnCanvas });
  ctx.keymap.add({ keys: ['PageDown', 'PageUp', 'n', 'b'], label: 'on the focused canvas too: PageDown/n next, PageUp/b back (presenter remote)', group: 'Walk',
    action: (event) => (event.key === 'PageDown' || event.key === 'n' ? player.next() : player.prev()), when: (event) => event.target === stage });
  ctx.keymap.add({ keys: ['3'], label: '2D / 3D view', group: 'View', action: () => set3d(!state().mode3d) });

  // ------------------------------------------------------------ validation report of a file
  const report = h('section', { class: 'callout mesh-report', id: 'mesh-report', hidden: true, 'aria-live': 'polite' });
  function showReport(name, problems) {
    if (!problems.length) { report.hidden = true; report.replaceChildren(); return; }
    const errors = problems.filter((p) => p.severity === 'error').length;
    report.classList.toggle('error', errors > 0);
    report.classList.toggle('warning', errors === 0);
    const elementList = ({ vertices, edges, faces }) => [...vertices.map((v) => `v${v + 1}`), ...edges.map((e) => `e${e + 1}`), ...faces.map((f) => `F${f + 1}`)].join(' ');
    report.replaceChildren(
      h('h2', {}, `Validation report of ${name}`),
      h('p', {}, errors ? `${errors === 1 ? 'This problem keeps' : `These ${errors} problems keep`} the file from being a winged-edge mesh; the mesh shown before stays. Elements are numbered as in the file.` : 'Warnings only: the mesh was loaded.'),
      h('ul', {}, problems.map((p) => h('li', { 'data-code': p.code, class: p.severity },
        h('strong', {}, p.severity === 'error' ? 'error ' : 'warning '), h('code', {}, p.code), ': ', p.message,
        elementList(p.elements) ? h('span', { class: 'report-elements' }, ` [${elementList(p.elements)}]`) : null))),
      h('button', { type: 'button', class: 'tool', onclick: () => { report.hidden = true; } }, 'Close report'),
    );
    report.hidden = false;
  }

  // ------------------------------------------------------------ tabs
  const tabs = createRepresentationTabs(ctx, TAB_LABELS, { pickElement: (element) => pickElement(element), selection });
  const edit = createEditPanel(ctx, selection, { pick: (element) => pickElement(element, { fromCanvas: true }) });
  // The walk stays at the top of the side column; what it reads scrolls below it (wide
  // screens; web/css/mesh.css), so the pseudocode and the highlighted row are on screen together.
  narration.after(tabs.walkRow); // the row the walk reads, under its narration (phones)
  const rest = h('div', { class: 'panels-rest' }, edit.root, tabs.root);
  ctx.panels.replaceChildren(report, walkPanel, rest);
  if (typeof ResizeObserver !== 'undefined') new ResizeObserver(() => tabs.revealAgain()).observe(rest);

  // ------------------------------------------------------------ canvas hover, click, rotate
  const sameElement = (a, b) => (a === b) || (a && b && a.kind === b.kind && a.index === b.index);
  function setHover(element) {
    if (sameElement(selection.hover, element)) return;
    selection.hover = element;
    tabs.markElements();
    ctx.render();
  }
  stage.addEventListener('pointermove', (event) => {
    if (event.buttons || !ctx.model || rotating) return;
    const rect = stage.getBoundingClientRect();
    const [x, y] = ctx.stage.transform().toWorld(event.clientX - rect.left, event.clientY - rect.top);
    const overHandle = ctx.ui.hover;
    setHover(overHandle ? { kind: 'vertex', index: Number(String(overHandle).slice(1)) } : elementAt(ctx.model, x, y, state().view.zoom));
  });
  stage.addEventListener('pointerleave', () => setHover(null));

  let rotating = null;
  window.addEventListener('pointermove', (event) => {
    if (!rotating) return;
    const yaw = rotating.yaw + (event.clientX - rotating.x) * 0.01;
    const pitch = Math.max(-MAX_TILT, Math.min(MAX_TILT, rotating.pitch + (event.clientY - rotating.y) * 0.01));
    ctx.commit({ ...state(), rotation: { yaw, pitch } }, { history: false });
  });
  window.addEventListener('pointerup', () => { rotating = null; });

  function canvasClick(x, y, event) {
    const element = elementAt(ctx.model, x, y, state().view.zoom);
    if (element) pickElement(element, { fromCanvas: true });
    if (state().mode3d && event && !event.shiftKey) {
      rotating = { x: event.clientX, y: event.clientY, ...state().rotation };
      return true;
    }
    return Boolean(element);
  }

  // A picked element is highlighted everywhere; a face or vertex also becomes the walk's.
  // A number that is not an element of this mesh (a struck-through gap row) is not picked: said.
  function pickElement(element, { fromCanvas = false } = {}) {
    if (element && ctx.model && !exists(ctx.model, element)) {
      ctx.message.error(`${whyNot(ctx.model, element)}: pick another element`, 'invalid-element');
      return;
    }
    selection.pick = element;
    selection.gone = null;
    if (ctx.model) edit.update(ctx.model);
    tabs.markElements({ reveal: fromCanvas });
    // (while a walk is being predicted, its element is the exercise's)
    const walkIsMine = ctx.ui.exercise !== 'walk';
    if (walkIsMine && element?.kind === 'face' && state().walk === 'face' && state().face !== element.index) commit({ face: element.index, step: 0 }, { history: false });
    // A vertex picked on a mesh too big for handles (the stage's onSelect) walks from it too.
    if (walkIsMine && element?.kind === 'vertex' && state().walk === 'vertex' && state().vertex !== element.index) commit({ vertex: element.index, step: 0 }, { history: false });
    ctx.render();
  }

  function syncControls() {
    const s = state();
    meshSelect.value = s.meshKind;
    for (const [kind, group] of Object.entries(sizeGroups)) group.hidden = s.meshKind !== kind;
    fanN.value = s.fanSize; gridX.value = s.grid.nx; gridY.value = s.grid.ny; sphereS.value = s.sphere.slices; sphereT.value = s.sphere.stacks;
    toggle3d.setAttribute('aria-pressed', String(s.mode3d));
    turnControls.sync(s.rotation, s.mode3d);
    walkKind.value = s.walk;
    speed.value = s.speed;
  }

  let lastWalkKey = null;
  function updateWalk(model, s) {
    const lines = PSEUDOCODE[model.walkKind];
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

  let shownSource = null;
  const panels = {
    update(model, s) {
      syncControls();
      if (!model) return;
      // Another mesh was chosen (not another state of this one): fit the view to it.
      const newMesh = shownSource !== model.source;
      if (shownSource !== null && newMesh) {
        queueMicrotask(() => ctx.fitView());
      }
      shownSource = model.source;
      updateWalk(model, s);
      edit.update(model);
      // The tables of a newly chosen big mesh fill in a task of their own, after the frame
      // that shows it (issue 17: no task over 50 ms when a million faces arrive).
      if (newMesh && model.F > BIG_TABLES) {
        setTimeout(() => { if (ctx.model === model) tabs.update(model, state()); }, 0);
      } else {
        tabs.update(model, s);
      }
    },
    canvasClick,
    pickElement,
    showReport,
    player,
  };
  syncControls();
  return panels;
}
