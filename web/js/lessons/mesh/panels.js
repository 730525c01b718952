// @ts-check
// The controls and panels of the mesh lesson: mesh choice, the walk player with its
// pseudocode, and the tabs of representations, queries, storage and planes. Everything
// shown comes from the model (what the core returned); the panels only lay it out and
// send the person's choices back through ctx.commit.
import { h } from '../../app/dom.js';
import { MESH_KINDS, MESH_SIZES } from './choices.js';
import { createMeshChooser } from '../../ui/mesh/chooser.js';
import { createWalkPanel } from '../../ui/mesh/walk-panel.js';
import { pickElement as elementAt } from '../../ui/mesh/pick.js';
import { createRepresentationTabs } from './tabs.js';
import { createEditPanel } from './edit-panel.js';
import { createTurnControls, MAX_TILT } from '../../ui/turn-controls.js';
import { exists, whyNot } from './live-elements.js';

const BIG_TABLES = 100000; // faces: from this size a new mesh's tables fill a task after its first frame

const TAB_LABELS = {
  winged: 'Winged edge', faces: 'Independent faces', 'vertex-face': 'Vertex & face tables', adjacency: 'Adjacency lists',
  'edge-list': 'Edge list (Foley)', 'half-edge': 'Half-edge', queries: 'Queries', storage: 'Storage', planes: 'Planes & normals',
};

// selection: the view's hovered and picked element ({kind, index} or null), owned by the
// lesson view (lesson.js setup) and read by the tables and the drawing.
export function setupPanels(ctx, selection) {
  const state = () => ctx.state;
  const commit = (patch, opts) => ctx.commit({ ...state(), ...patch }, opts);
  const stage = ctx.stage.canvas;

  // ------------------------------------------------------------ mesh choice
  const chooser = createMeshChooser(ctx, { kinds: MESH_KINDS, sizes: MESH_SIZES, choose: chooseMesh });
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
  ctx.controls.replaceChildren(
    ...chooser.elements, toggle3d, turnControls.root,
    h('span', { class: 'hint' }, 'Drag a vertex to move it (a click without dragging makes it the walk\'s vertex); drag empty space to pan (in 3D: to rotate, or use turn and tilt); wheel or two fingers zoom; hover an edge or face to find its table rows.'),
  );

  // ------------------------------------------------------------ the walk
  const walk = createWalkPanel(ctx);
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
  walk.placeUnderNarration(tabs.walkRow); // the row the walk reads, under its narration (phones)
  const rest = h('div', { class: 'panels-rest' }, edit.root, tabs.root);
  // The edit player sits above the walk: while an edit plays the walk folds to its title
  // (web/css/mesh.css), so the player, its current assignment and the table's rewritten cell
  // share the column with the drawing beside it.
  ctx.panels.replaceChildren(report, edit.now, walk.root, rest);
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

  // A press on the canvas is a click only if it is released where it went down: a drag
  // (turning the 3D view, panning the 2D one) never picks. The element under the press is
  // kept as `pressed` and picked on release, unless the pointer moved more than CLICK_SLOP_PX.
  const CLICK_SLOP_PX = 4;
  let rotating = null;
  let pressed = null;
  window.addEventListener('pointermove', (event) => {
    if (pressed && Math.hypot(event.clientX - pressed.x, event.clientY - pressed.y) > CLICK_SLOP_PX) pressed = null;
    if (!rotating) return;
    const yaw = rotating.yaw + (event.clientX - rotating.x) * 0.01;
    const pitch = Math.max(-MAX_TILT, Math.min(MAX_TILT, rotating.pitch + (event.clientY - rotating.y) * 0.01));
    ctx.commit({ ...state(), rotation: { yaw, pitch } }, { history: false });
  });
  window.addEventListener('pointerup', (event) => {
    rotating = null;
    const click = pressed;
    pressed = null;
    if (click && Math.hypot(event.clientX - click.x, event.clientY - click.y) <= CLICK_SLOP_PX) pickElement(click.element, { fromCanvas: true });
  });
  window.addEventListener('pointercancel', () => { rotating = null; pressed = null; });

  // The stage asks on a press: true keeps the press (the 3D view turns with it), false lets
  // the stage pan the 2D view. Without a pointer event (a test's direct call), it picks.
  function canvasClick(x, y, event) {
    const element = elementAt(ctx.model, x, y, state().view.zoom);
    if (!event) {
      if (element) pickElement(element, { fromCanvas: true });
      return Boolean(element);
    }
    pressed = element ? { element, x: event.clientX, y: event.clientY } : null;
    if (state().mode3d && !event.shiftKey) {
      rotating = { x: event.clientX, y: event.clientY, ...state().rotation };
      return true;
    }
    return false;
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
    chooser.sync(s);
    toggle3d.setAttribute('aria-pressed', String(s.mode3d));
    turnControls.sync(s.rotation, s.mode3d);
    walk.sync(s);
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
      walk.update(model, s);
      edit.update(model);
      ctx.panels.toggleAttribute('data-edit-playing', Boolean(model.lastOperation) && model.editStep < model.editSteps);
      // The tables of a newly chosen big mesh fill in a task of their own, after the frame
      // that shows it (no task over 50 ms when a million faces arrive).
      if (newMesh && model.F > BIG_TABLES) {
        setTimeout(() => { if (ctx.model === model) tabs.update(model, state()); }, 0);
      } else {
        tabs.update(model, s);
      }
    },
    canvasClick,
    pickElement,
    showReport,
    player: walk.player,
  };
  syncControls();
  return panels;
}
