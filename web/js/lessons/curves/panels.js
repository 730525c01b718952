// @ts-check
// The curve explorer's controls and panels: family, degree, tension, the u slider with
// play, the blending plot and knot strip under the drawing; the matrix panel, the
// constructions, overlays, the numeric inspector, knots, weights and the homogeneous view
// on the side. Every change goes through ctx.commit (the core recomputes first; a refused
// change leaves the old state and the message line says why).
import { h, panel } from '../../app/dom.js';
import { createPlayer } from '../../app/player.js';
import { formatNumber, continuityClass, inlineMath, el, mi, mo, mn, fixedMo } from '../../ui/mathml.js';
import {
  FAMILIES, familyInfo, familyMaxPoints, usesKnots, isSpline, hasDegreeChoice, maxDegreeFor, switchFamily, addPoint, removePoint,
  withDegree, continuityLabel,
} from './families.js';
import { pairs } from '../../app/arrays.js';
import { constructionsFor, createModelCache } from './curve-model.js';
import { createBlendingPlot } from '../../ui/blending-plot.js';
import { createMatrixPanel } from '../../ui/matrix-panel.js';
import { createFormSelect, nextForm, lectureNames } from '../../ui/matrix-forms.js';
import { createSubdivisionMatrices } from './subdivision-matrices.js';
import { createKnotStrip } from './knot-strip.js';
import { createHomogeneousInset } from './homogeneous-inset.js';
import { OVERLAYS, DEFAULT_OVERLAYS, blendingLabels } from './names.js';

const U_STEPS = 120;
const CONSTRUCTION_LABELS = {
  'de-casteljau': 'de Casteljau at u (all levels)',
  'de-boor': 'de Boor at u',
  subdivide: 'Subdivide at u into two halves',
  elevate: 'Raise the degree by one',
  'insert-knot': 'Insert a knot at u (Boehm)',
};

// The exact circle of lectures 001/002, from the core (api.nurbsCircle): the quadratic NURBS
// with 9 control points on the square of side 2r, weights 1 and sqrt(2)/2 at the corners,
// knots 0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1.
export function circlePreset(api, radius = 2) {
  const c = api.nurbsCircle({ center: [0, 0], radius });
  const points = pairs(c.points);
  return { family: 'nurbs', degree: c.degree, points, weights: Array.from(c.weights), knots: Array.from(c.knots) };
}

// Builds every control and panel of the page and returns the lesson's view: the DOM
// references, the players and the per-page caches the later hooks read (the lesson
// contract, web/js/app/contract.js).
export function createPanels(ctx) {
  const commit = (next, opts) => ctx.commit(next, opts);
  const state = () => ctx.state;
  const clearConstruction = (s) => ({ ...s, construction: { kind: 'none', step: 0 } });

  // ---------------------------------------------------------------- under the drawing
  const family = h('select', { id: 'curve-family', onchange: (e) => {
    const next = switchFamily(ctx.api, state(), e.target.value);
    if (commit(next)) ctx.fitView();
    else e.target.value = state().family;
  } }, FAMILIES.map((f) => h('option', { value: f.id }, f.label)));
  const degree = h('select', { id: 'curve-degree', onchange: (e) => commit(withDegree(ctx.api, state(), Number(e.target.value))) });
  const tension = h('input', { type: 'range', id: 'curve-tension', min: -0.5, max: 1, step: 0.05, oninput: (e) => commit({ ...state(), tension: Number(e.target.value) }, { coalesce: 'tension' }) });
  const tensionOut = h('output', { for: 'curve-tension' });
  const uSlider = h('input', { type: 'range', id: 'curve-u', step: 'any', oninput: (e) => setU(Number(e.target.value)) });
  const uOut = h('output', { for: 'curve-u', class: 'mono' });
  const playU = h('button', { type: 'button', class: 'tool', 'data-action': 'play-u', onclick: () => uPlayer.toggle() }, 'Play u');
  const addButton = h('button', { type: 'button', 'data-action': 'add-point', class: 'tool advanced', onclick: () => addSelected() }, 'Add point');
  const removeButton = h('button', { type: 'button', 'data-action': 'remove-point', class: 'tool advanced', onclick: () => removeSelected() }, 'Remove point');

  function setU(u, coalesce = 'u') {
    const s = state();
    commit({ ...s, u }, { coalesce });
  }
  const uPlayer = createPlayer({
    count: () => U_STEPS + 1,
    getStep: () => { const d = ctx.model.domain; return Math.round(((state().u - d.start) / (d.end - d.start)) * U_STEPS); },
    onStep: (k) => { const d = ctx.model.domain; setU(d.start + ((d.end - d.start) * k) / U_STEPS, 'u-play'); },
    stepsPerSecond: 30,
  });
  uPlayer.onChange(() => { playU.textContent = uPlayer.playing ? 'Pause u' : 'Play u'; playU.setAttribute('aria-pressed', String(uPlayer.playing)); });

  // New points keep this far (CSS px) inside the canvas edge: the handle and its label show.
  const ADD_MARGIN_PX = 24;
  function addSelected(at = null) {
    const s = state();
    const info = familyInfo(s.family);
    const most = familyMaxPoints(info, ctx.api);
    if (s.points.length >= most) { ctx.message.warn(`${info.label} takes at most ${most} points here.`); return; }
    const sel = selectedPoint(ctx);
    const index = at ? s.points.length : (sel ?? s.points.length - 1) + 1;
    const box = visibleBox(ADD_MARGIN_PX);
    const next = addPoint(ctx.api, s, index - 1, at, box);
    if (!commit(next)) return;
    // A point that could not be placed in view (its neighbours are at or past the edge):
    // the view moves to show the whole curve, so nothing is added out of sight.
    const [x, y] = next.points[index];
    if (!at && !(x >= box.minX && x <= box.maxX && y >= box.minY && y <= box.maxY)) ctx.fitView();
    ctx.message.info(`Added P${index}.`);
  }
  // The world box the canvas shows, less `marginPx` on each side.
  function visibleBox(marginPx) {
    const { width, height } = ctx.stage.size;
    const t = ctx.stage.transform();
    const [x0, y0] = t.toWorld(marginPx, height - marginPx);
    const [x1, y1] = t.toWorld(width - marginPx, marginPx);
    return { minX: Math.min(x0, x1), minY: Math.min(y0, y1), maxX: Math.max(x0, x1), maxY: Math.max(y0, y1) };
  }
  function removeSelected() {
    const s = state();
    const sel = selectedPoint(ctx);
    const info = familyInfo(s.family);
    if (sel === null) { ctx.message.warn('Select a control point first (click it, or focus the drawing and press ]).'); return; }
    if (s.points.length <= info.minPoints) { ctx.message.warn(`${info.label} needs at least ${info.minPoints} points.`); return; }
    if (commit(removePoint(ctx.api, s, sel))) { ctx.ui.selected = null; ctx.message.info(`Removed P${sel}.`); }
  }

  const row1 = h('div', { class: 'curve-row' },
    h('label', { for: 'curve-family' }, 'Family'), family,
    h('label', { for: 'curve-degree', class: 'degree-label' }, 'Degree p'), degree,
    h('span', { class: 'tension-group' }, h('label', { for: 'curve-tension' }, 'Tension'), tension, tensionOut),
    addButton, removeButton);
  const row2 = h('div', { class: 'curve-row' }, h('label', { for: 'curve-u' }, 'u'), uSlider, uOut, playU);
  const plots = h('div', { class: 'curve-plots' });
  ctx.controls.append(row1, row2, plots);
  const blending = createBlendingPlot(plots, {
    label: 'Blending functions',
    onSeek(u, { final }) { if (final) ctx.endGesture(); else setU(u, 'u-plot'); },
  });
  const stripBox = h('div', { class: 'knot-strip-box' });
  plots.append(stripBox);
  const strip = createKnotStrip(stripBox, {
    label: 'Knot strip',
    onChange(knots, { final }) {
      if (knots) commit(clearConstruction({ ...state(), knots }), { coalesce: final ? null : 'knot-drag' });
      if (final) ctx.endGesture();
    },
  });

  // ---------------------------------------------------------------- side panels
  const matrixBody = panel(ctx.panels, { id: 'panel-matrix', title: 'Matrix form of the current segment' });
  // The form of a lecture (descending 000/003, ascending 002, transposed 001).
  const { select: formSelect, row: formRow } = createFormSelect('matrix-form', (form) => commit({ ...state(), form }));
  matrixBody.append(formRow);
  // M in exact fractions as on the slides (1/6 [...], 1/2 [...]) or in decimals.
  const fractions = h('input', { type: 'checkbox', id: 'matrix-fractions', onchange: (e) => commit({ ...state(), notation: e.target.checked ? 'fraction' : 'decimal' }) });
  matrixBody.append(h('label', { class: 'check' }, fractions, ' Exact fractions as on the slides (1/6 [integers])'));
  const matrix = createMatrixPanel(matrixBody);
  // Where the lecture notes disagree about the form shown, a short note says so and
  // which form the app computes (quoted in docs/lesson-curves.md).
  const notationNote = h('p', { class: 'hint lecture-note', id: 'notation-note', 'aria-live': 'polite' });
  matrixBody.append(notationNote);
  const splitMatrices = createSubdivisionMatrices(matrixBody, ctx.api);

  const conBody = panel(ctx.panels, { id: 'panel-construction', title: 'Constructions' });
  const conKind = h('select', { id: 'construction-kind', onchange: (e) => { uPlayer.pause(); commit({ ...state(), construction: { kind: e.target.value, step: 0 } }); } });
  const conStep = h('p', { class: 'construction-step', 'aria-live': 'polite' });
  const conPlayer = createPlayer({
    count: () => ctx.model?.construction?.steps ?? 1,
    getStep: () => state().construction.step,
    onStep: (k) => commit({ ...state(), construction: { ...state().construction, step: k } }, { coalesce: 'construction-step' }),
    stepsPerSecond: 1.2,
  });
  const conButtons = {
    restart: h('button', { type: 'button', class: 'tool', 'data-action': 'construction-restart', onclick: () => conPlayer.restart() }, 'Start'),
    prev: h('button', { type: 'button', class: 'tool', 'data-action': 'construction-prev', onclick: () => conPlayer.prev() }, '◀ Back'),
    play: h('button', { type: 'button', class: 'tool', 'data-action': 'construction-play', onclick: () => conPlayer.toggle() }, 'Play'),
    next: h('button', { type: 'button', class: 'tool', 'data-action': 'construction-next', onclick: () => conPlayer.next() }, 'Step ▶'),
    apply: h('button', { type: 'button', class: 'tool', 'data-action': 'construction-apply', onclick: () => applyConstruction() }, 'Apply to the curve'),
  };
  conPlayer.onChange(() => { conButtons.play.textContent = conPlayer.playing ? 'Pause' : 'Play'; });
  conBody.append(h('label', { for: 'construction-kind' }, 'Construction '), conKind,
    h('div', { class: 'button-row' }, Object.values(conButtons)), conStep);

  function applyConstruction() {
    const s = state();
    const con = ctx.model.construction;
    if (!con) return;
    if (con.kind === 'elevate') {
      const next = { ...s, points: con.points, construction: { kind: 'elevate', step: 0 } };
      next.weights = con.points.map(() => 1);
      if (commit(next)) ctx.message.info(`Degree raised to ${con.points.length - 1}: same curve, one more control point.`);
    } else if (con.kind === 'insert-knot') {
      const next = { ...s, points: con.points, knots: con.knots, weights: con.weights ?? con.points.map(() => 1),
        tangents: con.points.map(() => [1, 0]), construction: { kind: 'insert-knot', step: 0 } };
      if (commit(next)) ctx.message.info(`Knot ${formatNumber(con.at, 4)} inserted: same curve, one more control point.`);
    }
  }

  const overlayBody = panel(ctx.panels, { id: 'panel-overlays', title: 'Overlays' });
  const overlayBoxes = {};
  for (const [key, text] of Object.entries(OVERLAYS)) {
    overlayBoxes[key] = h('input', { type: 'checkbox', id: `overlay-${key}`, 'data-overlay': key,
      onchange: (e) => commit({ ...state(), overlays: { ...state().overlays, [key]: e.target.checked } }, { recompute: key === 'comb' }) });
    const row = h('label', { class: 'check' }, overlayBoxes[key], ` ${text}`);
    // The comb needs the core's curvature; without it the option is not offered.
    row.hidden = key === 'comb' && typeof ctx.api.curvature !== 'function';
    overlayBody.append(row);
  }
  const compare = h('input', { type: 'checkbox', id: 'compare-spline', onchange: (e) => commit({ ...state(), compare: e.target.checked }) });
  const compareLabel = h('label', { class: 'check' }, compare, ' Interpolation: also draw a cubic spline through the same points (dashed)');
  overlayBody.append(compareLabel);

  // The x, y of the selected handle are typed in the shell's inspector under the drawing
  // (shell.js; it announces the move); this panel adds what a handle does not carry.
  const inspectorBody = panel(ctx.panels, { id: 'panel-inspector', title: 'Exact values: tangent, weight, u, knots' });
  // Presentation mode (site.css hides .advanced): the inspector, the point editing buttons
  // and the CSV-minded details stay off the projector; family, u, constructions stay.
  inspectorBody.parentElement.classList.add('advanced');
  const inspector = {
    title: h('p', { class: 'inspector-title' }),
    tx: h('input', { type: 'number', step: 0.01, id: 'inspect-tx', onchange: () => typedPoint() }),
    ty: h('input', { type: 'number', step: 0.01, id: 'inspect-ty', onchange: () => typedPoint() }),
    w: h('input', { type: 'number', step: 0.05, min: 0, id: 'inspect-w', onchange: () => typedPoint() }),
    u: h('input', { type: 'number', step: 0.01, id: 'inspect-u', onchange: (e) => { if (!setTypedU(e.target)) e.target.value = state().u; } }),
    knots: h('input', { type: 'text', id: 'inspect-knots', class: 'mono', spellcheck: 'false', onchange: (e) => typedKnots(e.target) }),
  };
  const tangentFields = h('div', { class: 'inspector-grid' },
    h('label', { for: 'inspect-tx' }, 'tangent x'), inspector.tx, h('label', { for: 'inspect-ty' }, 'tangent y'), inspector.ty);
  const weightFields = h('div', { class: 'inspector-grid' }, h('label', { for: 'inspect-w' }, 'weight w'), inspector.w);
  const knotField = h('div', { class: 'inspector-knots' }, h('label', { for: 'inspect-knots' }, 'Knot vector (comma separated, non-decreasing)'), inspector.knots);
  inspectorBody.append(inspector.title, tangentFields, weightFields,
    h('div', { class: 'inspector-grid' }, h('label', { for: 'inspect-u' }, 'u'), inspector.u), knotField);

  function typedPoint() {
    const s = state();
    const i = selectedPoint(ctx) ?? selectedTangent(ctx);
    if (i === null) return;
    const val = (input, old) => (input.value.trim() === '' ? old : Number(input.value));
    const next = { ...s };
    if (s.family === 'hermite') {
      const tx = val(inspector.tx, s.tangents[i][0]);
      const ty = val(inspector.ty, s.tangents[i][1]);
      if (![tx, ty].every(Number.isFinite)) { ctx.message.error(`Type a number for both components of the tangent T${i}.`, 'invalid-number'); return; }
      next.tangents = s.tangents.map((t, j) => (j === i ? [tx, ty] : t));
    }
    if (s.family === 'nurbs') next.weights = s.weights.map((w, j) => (j === i ? val(inspector.w, w) : w));
    if (!commit(next)) ctx.refresh();
  }
  function setTypedU(input) {
    const u = Number(input.value);
    const d = ctx.model.domain;
    if (!Number.isFinite(u) || u < d.start || u > d.end) {
      ctx.message.error(`u must be a number from ${formatNumber(d.start)} to ${formatNumber(d.end)} (the domain of this curve).`, 'parameter-out-of-range');
      return false;
    }
    return commit({ ...state(), u });
  }
  function typedKnots(input) {
    const s = state();
    const parts = input.value.split(/[,\s;]+/).filter((x) => x !== '');
    const knots = parts.map(Number);
    const bad = parts.findIndex((x, j) => !Number.isFinite(knots[j]));
    if (bad >= 0) {
      ctx.message.error(`Knot ${bad} ("${parts[bad].slice(0, 20)}") is not a number; the knots were not changed.`, 'invalid-number');
      input.value = s.knots.join(', ');
      return;
    }
    if (knots.length !== s.knots.length) {
      ctx.message.error(`${s.points.length} points of degree ${s.degree} need ${s.knots.length} knots (K + p + 1), not ${knots.length}; the knots were not changed.`, 'wrong-knot-count');
      input.value = s.knots.join(', ');
      return;
    }
    // The core judges the values (non-decreasing, ...) and names the offending knot.
    if (!commit(clearConstruction({ ...s, knots }))) input.value = s.knots.join(', ');
  }

  const knotsBody = panel(ctx.panels, { id: 'panel-knots', title: 'Knots, multiplicity and continuity' });
  const presets = h('div', { class: 'button-row' },
    h('button', { type: 'button', class: 'tool', 'data-action': 'knots-clamped', onclick: () => setKnots(Array.from(ctx.api.clampedKnots(state().points.length, state().degree))) }, 'Clamped'),
    h('button', { type: 'button', class: 'tool', 'data-action': 'knots-unclamped', onclick: () => setKnots(Array.from(ctx.api.unclampedKnots(state().knots, state().degree))) }, 'Unclamped'),
    h('button', { type: 'button', class: 'tool', 'data-action': 'knots-uniform', onclick: () => setKnots(Array.from(ctx.api.uniformKnots(state().points.length, state().degree))) }, 'Uniform'));
  const knotTable = h('div', { class: 'knot-table' });
  const removalNote = h('p', { class: 'hint', id: 'knot-removal-note' },
    'Raising m inserts the knot again (Boehm): the curve does not move. Lowering m is knot removal, which moves the curve unless it already has the higher continuity there; take a raise back with Undo, which is exact.');
  // When the knots make this B-spline a Bezier curve (decided by the core).
  const bezierNote = h('p', { class: 'hint lecture-note', id: 'bezier-disguise-note', 'aria-live': 'polite', hidden: true });
  knotsBody.append(presets, knotTable, bezierNote, removalNote);
  // A preset keeps u, moved onto the new knots' domain [t_p, t_K] (the core's curveDomain).
  function setKnots(knots) {
    const s = state();
    const d = ctx.api.curveDomain({ ...ctx.model.spec, kind: 'bspline', weights: undefined, knots });
    commit(clearConstruction({ ...s, knots, u: Math.min(d.end, Math.max(d.start, s.u)) }));
  }

  const nurbsBody = panel(ctx.panels, { id: 'panel-nurbs', title: 'NURBS: weights and the homogeneous view' });
  const circle = h('button', { type: 'button', class: 'tool', 'data-action': 'circle-preset', onclick: () => {
    const s = state();
    const next = clearConstruction({ ...s, ...circlePreset(ctx.api, 2), tangents: [], u: 0 });
    next.tangents = next.points.map(() => [1, 0]);
    if (commit(next)) { ctx.fitView(); ctx.message.info('Exact circle: a quadratic NURBS with 9 points and weights 1, √2/2.'); }
  } }, 'Exact circle preset');
  const weightList = h('div', { class: 'weight-list' });
  const insetBox = h('div', { class: 'inset-box' });
  nurbsBody.append(circle, weightList, insetBox);
  const inset = createHomogeneousInset(insetBox);

  // ---------------------------------------------------------------- keys
  // Presenter remote (shell.js binds PageDown/n, PageUp/Shift+n, Space/k, Home, o/b/.):
  // next/prev/reset step the construction; play/pause plays the construction when one is
  // chosen, else u; the overlay key hides the overlays and brings them back.
  let savedOverlays = null;
  ctx.setPresenter({
    next: () => conPlayer.next(),
    prev: () => conPlayer.prev(),
    reset: () => conPlayer.restart(),
    playPause: () => (state().construction.kind !== 'none' ? conPlayer.toggle() : uPlayer.toggle()),
    toggleOverlays: () => {
      const o = state().overlays;
      const anyOn = Object.values(o).some(Boolean);
      const next = anyOn ? Object.fromEntries(Object.keys(o).map((k) => [k, false])) : (savedOverlays ?? { ...DEFAULT_OVERLAYS });
      savedOverlays = anyOn ? o : null;
      commit({ ...state(), overlays: next }, { recompute: true });
    },
  });
  ctx.keymap.add({ keys: ['j'], label: 'u a little back', group: 'Curve', action: () => nudgeU(-1) });
  ctx.keymap.add({ keys: ['l'], label: 'u a little forward', group: 'Curve', action: () => nudgeU(1) });
  ctx.keymap.add({ keys: ['a'], label: 'add a control point after the selected one', group: 'Curve', action: () => addSelected() });
  ctx.keymap.add({ keys: ['Delete', 'Backspace'], label: 'remove the selected control point', group: 'Curve', action: () => removeSelected() });
  ctx.keymap.add({ keys: ['m'], label: 'next matrix form: lectures 000/003, 002, 001', group: 'Curve', action: () => commit({ ...state(), form: nextForm(state().form) }) });
  ctx.keymap.add({ keys: ['f'], label: 'matrix entries: exact fractions or decimals', group: 'Curve', action: () => commit({ ...state(), notation: state().notation === 'fraction' ? 'decimal' : 'fraction' }) });
  ctx.keymap.add({ keys: ['Shift+click'], label: 'add a control point at the mouse (on the drawing)', group: 'Curve' });
  function nudgeU(sign) {
    const d = ctx.model.domain;
    setU(Math.min(d.end, Math.max(d.start, state().u + (sign * (d.end - d.start)) / 50)));
  }

  // Shift+click on the drawing adds a point there (the lesson's click hook calls this).
  const addAt = (x, y) => addSelected([Math.round(x * 1e4) / 1e4, Math.round(y * 1e4) / 1e4]);

  const view = { addAt, cache: createModelCache(), family, degree, tension, tensionOut, uSlider, uOut, blending, strip, stripBox, matrix, formSelect, fractions, notationNote, splitMatrices, conKind, conStep, conButtons, overlayBoxes, compare, compareLabel,
    inspector, tangentFields, weightFields, knotField, knotTable, bezierNote, knotsPanel: knotsBody.parentElement, nurbsPanel: nurbsBody.parentElement, weightList, inset,
    degreeLabel: row1.querySelector('.degree-label'), tensionGroup: row1.querySelector('.tension-group'), lastKnotKey: null, lastWeightKey: null, conPlayer, uPlayer, commit, state, setKnots };
  return view;
}

// The selected control point (p<i>) or tangent handle (t<i>): null when none is selected,
// or when the state shown has no such point any more (undo, a link, another family).
function selectedPoint(ctx) {
  return selectedIndex(ctx.ui.selected, 'p', ctx.state.points.length);
}
function selectedTangent(ctx) {
  return selectedIndex(ctx.ui.selected, 't', ctx.state.family === 'hermite' ? ctx.state.tangents.length : 0);
}
function selectedIndex(id, letter, count) {
  if (typeof id !== 'string' || id[0] !== letter) return null;
  const i = Number(id.slice(1));
  return Number.isInteger(i) && i >= 0 && i < count ? i : null;
}

const setValue = (input, v) => { if (document.activeElement !== input) input.value = String(v); };

export function updatePanels(els, model, state, ctx) {
  const K = state.points.length;
  els.family.value = state.family;
  // degree
  els.degree.hidden = !hasDegreeChoice(state.family);
  els.degreeLabel.hidden = els.degree.hidden;
  if (!els.degree.hidden) {
    const max = maxDegreeFor(K);
    if (els.degree.options.length !== max) els.degree.replaceChildren(...Array.from({ length: max }, (_, i) => h('option', { value: i + 1 }, String(i + 1))));
    els.degree.value = String(state.degree);
  }
  els.tensionGroup.hidden = state.family !== 'catmull-rom';
  els.tension.value = String(state.tension);
  els.tensionOut.textContent = state.tension === 0 ? '0 (Catmull-Rom)' : formatNumber(state.tension, 3);
  // u
  els.uSlider.min = String(model.domain.start);
  els.uSlider.max = String(model.domain.end);
  setValue(els.uSlider, model.u);
  els.uOut.textContent = formatNumber(model.u, 4);
  // matrix panel
  els.formSelect.value = state.form;
  els.fractions.checked = state.notation === 'fraction';
  const noteText = notationNotes(state).join(' ');
  if (els.notationNote.textContent !== noteText) els.notationNote.textContent = noteText;
  els.notationNote.hidden = noteText === '';
  els.splitMatrices.update(state);
  els.matrix.update({ segment: model.segment, u: model.u, point: model.point, form: state.form, notation: state.notation,
    title: segmentTitle(state, model.segment), names: segmentNames(state, model.segment) });
  // constructions
  const kinds = constructionsFor(state.family, ctx.api);
  const wanted = ['none', ...kinds].join();
  if (els.conKind.dataset.kinds !== wanted) {
    els.conKind.dataset.kinds = wanted;
    els.conKind.replaceChildren(h('option', { value: 'none' }, kinds.length ? 'none' : 'none for this family'),
      ...kinds.map((k) => h('option', { value: k }, CONSTRUCTION_LABELS[k])));
  }
  els.conKind.value = kinds.includes(state.construction.kind) ? state.construction.kind : 'none';
  const con = model.construction;
  const steps = con?.steps ?? 1;
  for (const b of Object.values(els.conButtons)) b.disabled = !con;
  els.conButtons.apply.hidden = !(con && (con.kind === 'elevate' || con.kind === 'insert-knot'));
  els.conButtons.apply.disabled = !con || state.construction.step < steps - 1;
  els.conStep.textContent = con ? constructionText(con, state.construction.step, model) : 'Choose a construction; it is computed at the current u.';
  // overlays
  for (const [k, box] of Object.entries(els.overlayBoxes)) box.checked = state.overlays[k];
  els.compare.checked = state.compare;
  els.compareLabel.hidden = state.family !== 'interpolation';
  // inspector
  const i = selectedPoint(ctx) ?? selectedTangent(ctx);
  els.tangentFields.hidden = i === null || state.family !== 'hermite';
  els.weightFields.hidden = i === null || state.family !== 'nurbs';
  els.inspector.title.textContent = i === null ? 'Select a control point (click it, or focus the drawing and press ] ); its x and y are typed under the drawing.' : `P${i}`;
  if (i !== null && i < K) {
    if (state.family === 'hermite') { setValue(els.inspector.tx, state.tangents[i][0]); setValue(els.inspector.ty, state.tangents[i][1]); }
    if (state.family === 'nurbs') setValue(els.inspector.w, state.weights[i]);
  }
  setValue(els.inspector.u, model.u);
  els.knotField.hidden = !usesKnots(state.family);
  setValue(els.inspector.knots, state.knots.join(', '));
  // knots panel and strip
  els.knotsPanel.hidden = !isSpline(state.family);
  els.stripBox.hidden = !isSpline(state.family);
  const disguise = model.bezierInDisguise
    ? `These knots (${state.knots.map((k) => formatNumber(k, 4)).join(', ')}) make this ${state.family === 'nurbs' ? 'NURBS the rational Bezier curve' : 'B-spline the Bezier curve'} of its ${K} points: `
      + `one segment, clamped ends (lecture 002: {0, 0, 0, 0, 1, 1, 1, 1}, cubic B-spline → cubic Bezier curve). Add a point or insert a knot for a B-spline that is not one.`
    : '';
  if (els.bezierNote.textContent !== disguise) els.bezierNote.textContent = disguise;
  els.bezierNote.hidden = disguise === '';
  if (model.knots) {
    const key = JSON.stringify([model.knots.values, state.degree, state.family]);
    if (key !== els.lastKnotKey) {
      els.lastKnotKey = key;
      els.knotTable.replaceChildren(knotGroupTable(model, state, ctx));
    }
  }
  // NURBS
  els.nurbsPanel.hidden = state.family !== 'nurbs';
  if (state.family === 'nurbs') {
    const key = JSON.stringify(state.weights);
    if (key !== els.lastWeightKey) {
      els.lastWeightKey = key;
      els.weightList.replaceChildren(...state.weights.map((w, j) => weightRow(els, w, j, ctx)));
    }
  }
}

function constructionText(con, step, model) {
  const last = con.steps - 1;
  const s = Math.min(step, last);
  if (con.kind === 'de-casteljau' || con.kind === 'de-boor') {
    const name = con.kind === 'de-casteljau' ? 'de Casteljau' : 'de Boor';
    if (con.kind === 'de-boor' && s === 0) {
      const first = con.firstIndex;
      return `de Boor at u = ${formatNumber(model.u, 4)} in the span [t${con.span}, t${con.span + 1}): level 0 is P${first}..P${first + last} (ringed), the ${last + 1} points that act there. Step to interpolate.`;
    }
    if (s === 0) return `${name} at u = ${formatNumber(model.u, 4)}: level 0 is the control polygon. Step to interpolate.`;
    return `${name}, level ${s} of ${last}: ${con.levels[s].length} point${con.levels[s].length > 1 ? 's' : ''}` +
      (s === last ? ` — the point on the curve P(${formatNumber(model.u, 4)}).` : ', each between two of the level before.');
  }
  if (con.kind === 'subdivide') return s === 0 ? 'All de Casteljau levels at u; the next step splits the curve.' : 'Left half (L) and right half (R): together they trace the same curve.';
  if (con.kind === 'elevate') return s === 0 ? `Degree ${model.degree}; the next step shows degree ${model.degree + 1}.` : `Degree ${model.degree + 1}: ${con.points.length} points, the same curve. Apply to keep them.`;
  if (con.kind === 'insert-knot') {
    const n = con.newPoints.length;
    return s === 0 ? `Insert the knot u = ${formatNumber(con.at, 4)}: the next step shows the new control polygon.`
      : `${n} new control points (Q${con.newPoints.join(', Q')}, highlighted) replace ${n - 1} old ones; the curve is unchanged. Apply to keep them.`;
  }
  return '';
}

function knotGroupTable(model, state, ctx) {
  const groups = model.knots.groups;
  const inDomain = (g) => g.value >= model.domain.start && g.value <= model.domain.end;
  // Continuity is a property of a joint between two segments: strictly inside the domain.
  const joint = (g) => g.value > model.domain.start && g.value < model.domain.end;
  const where = (g) => (joint(g) ? continuityLabel(g.continuity) : inDomain(g) ? 'end of the domain' : 'outside the domain');
  const editable = usesKnots(state.family);
  const tbl = h('table', { class: 'data-table knot-groups' },
    h('caption', {}, `Degree p = ${state.degree}: a knot of multiplicity m gives continuity `, continuityClass('C', 'p−m'), ' there.'),
    h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, 'knot'), h('th', { scope: 'col' }, 'multiplicity m'), h('th', { scope: 'col' }, 'continuity'), editable ? h('th', { scope: 'col' }, 'raise m') : null)),
    h('tbody', {}, groups.map((g) => h('tr', { 'data-knot': String(g.value) },
      h('th', { scope: 'row' }, formatNumber(g.value, 4)),
      h('td', {}, String(g.multiplicity)),
      h('td', { class: 'continuity' }, where(g)),
      editable ? h('td', {},
        h('button', { type: 'button', class: 'tool small', 'data-action': 'raise-multiplicity', 'aria-label': `raise the multiplicity of knot ${formatNumber(g.value, 4)} (m + 1)`,
          disabled: !joint(g) || g.multiplicity >= state.degree || state.points.length >= 24, onclick: () => raiseMultiplicity(g.value, ctx) }, 'm + 1')) : null))));
  return tbl;
}

// Raising m inserts the knot once more (Boehm, in the core): the curve stays, one point more.
function raiseMultiplicity(value, ctx) {
  const s = ctx.state;
  let r;
  try { r = ctx.api.insertKnot(ctx.model.spec, value); } catch (err) { ctx.message.error(err.message, err.code); return; }
  const points = pairs(r.curve.points);
  const knots = Array.from(r.curve.knots);
  const next = { ...s, points, knots, weights: r.curve.weights?.length ? Array.from(r.curve.weights) : points.map(() => 1),
    tangents: points.map(() => [1, 0]), construction: { kind: 'none', step: 0 } };
  if (ctx.commit(next)) {
    const g = ctx.model.knots.groups.find((k) => k.value === value);
    ctx.message.info(`Knot ${formatNumber(value, 4)} now has multiplicity ${g.multiplicity} (C${g.continuity} there); the curve did not move, P${r.newPoints.join(', P')} are new.`);
  }
}

// Lowering a multiplicity (knot removal) is offered only as the exact operation: taking back
// a raise with Undo. Removing a knot from an arbitrary curve changes the curve unless it is
// already C^(p-m+1) there, and the core has no knot removal to judge or minimise the change;
// a button that silently moved the curve would teach the wrong thing (a decision of docs/lesson-curves.md).

function weightRow(els, w, j, ctx) {
  const id = `weight-${j}`;
  const slider = h('input', { type: 'range', id, min: 0.05, max: 5, step: 0.05, value: w, 'data-weight': j,
    oninput: (e) => setWeight(els, j, Number(e.target.value), ctx, 'weight-slider') });
  const num = h('input', { type: 'number', min: 0, step: 0.05, value: w, 'aria-label': `weight of P${j} (exact)`,
    onchange: (e) => setWeight(els, j, Number(e.target.value), ctx, null) });
  return h('div', { class: 'weight-row' }, h('label', { for: id }, `w${j}`), slider, num);
}

function setWeight(els, j, w, ctx, coalesce) {
  const s = ctx.state;
  const weights = s.weights.slice();
  weights[j] = w;
  if (!ctx.commit({ ...s, weights }, { coalesce })) els.lastWeightKey = null;
}

// Secondary canvases redrawn after every frame (the cursor and the hover highlight).
export function drawPlots(els, model, state, ctx, hoveredItem) {
  const K = state.points.length;
  const labels = blendingLabels(state, model.plot.count);
  const hermite = state.family === 'hermite';
  els.blending.update({
    params: model.plot.params,
    count: model.plot.count,
    values: model.plot.values,
    u: model.u,
    domain: model.domain,
    colors: ctx.colors,
    labels,
    colorIndex: hermite ? (i) => i % K : null,
    dashed: hermite ? (i) => i >= K : null,
    knots: model.knots ? model.knots.groups.map((g) => g.value) : Array.from(model.joints?.params ?? []),
    highlight: hoveredItem === null ? null : (hermite ? hoveredItem % K : hoveredItem),
    present: ctx.ui.present,
    caption: cachedCaption(els, state),
  });
  if (model.knots) {
    els.strip.update({ knots: model.knots.values, groups: model.knots.groups, degree: state.degree, domain: model.domain, u: model.u,
      editable: usesKnots(state.family), colors: ctx.colors, present: ctx.ui.present });
  }
  if (model.homogeneous) {
    els.inset.update({ ...model.homogeneous, curve2: model.samples, colors: ctx.colors });
  }
}

// The blending plot's caption with its names typeset (no raw "N_i,3"), built
// once per family and degree. B-splines are B_i,d with d the degree, as lecture 002 writes
// B_id (the plot's own labels follow: B0,3 ...).
function cachedCaption(els, state) {
  const key = JSON.stringify([state.family, state.degree, state.points.length]);
  if (els.captionKey !== key) {
    els.captionKey = key;
    els.captionNode = captionFor(state);
  }
  return els.captionNode;
}

function captionFor(state) {
  const span = (...parts) => h('span', {}, ...parts);
  const f = (name, sub) => inlineMath(el('mrow', el('msub', mi(name), el('mrow', ...sub)), fixedMo('('), mi('u'), fixedMo(')')));
  const i = mi('i');
  const comma = mo(',');
  const n = (k) => mn(String(k));
  switch (state.family) {
    case 'hermite': return span('Hermite blending functions ', f('H', [n(0)]), ' .. ', f('H', [n(3)]), ' (lecture 000): solid for the points, dashed for the tangents');
    case 'bezier': return span('Bernstein polynomials ', f('B', [i, comma, n(state.points.length - 1)]), ' (lecture 001)');
    case 'interpolation': return span('Lagrange polynomials ', f('L', [i]), ': each is 1 at its node and 0 at the others (lecture 000)');
    case 'nurbs': return span('Rational basis ', f('R', [i, comma, mi('d')]), ' = ', inlineMath(el('mrow', el('msub', mi('w'), i.cloneNode(true)), el('msub', mi('B'), el('mrow', mi('i'), mo(','), mi('d'))), mo('/'), mo('∑'), el('msub', mi('w'), mi('j')), el('msub', mi('B'), el('mrow', mi('j'), mo(','), mi('d'))))), `, d = ${state.degree} (lecture 002's NURBS)`);
    case 'catmull-rom': return span('Catmull-Rom / cardinal blending functions (lecture 003)');
    default: return span('B-spline basis ', f('B', [i, comma, mi('d')]), `, degree d = ${state.degree}, by Cox-de Boor (lecture 002)`);
  }
}

// The lectures' slips and disagreements that concern the matrix shown.
function notationNotes(state) {
  const notes = [];
  if (state.family === 'catmull-rom' && state.tension === 0) {
    notes.push('Lecture 002 prints the first row of M_R as (−1 3 −3 0); lecture 003 has (−1 3 −3 1), '
      + 'and only that row makes the blending functions add up to 1. The app computes lecture 003\'s matrix.');
  }
  if (state.form === 'ascending') {
    notes.push('Lecture 002 writes u = (1, u, u², u³) and C = M g: the matrix of lectures 000 and 003 with its rows in the opposite order '
      + '(the row of u⁰ first); g is the same geometry.');
  }
  if (state.form === 'transposed') {
    notes.push('Lecture 001 writes T = [t³ t² t 1] as a row in Q(t) = T · C and as a column in G · M · T on the same slide; '
      + 'this form is the second one (T a column, M the transpose of the matrix of lectures 000 and 003, as in 001\'s M_H).');
  }
  return notes;
}

// The heading of the matrix panel in the lectures' words (never a state or basis
// id): the family, and the basis when it is not the family's own name.
const BASIS_NAMES = { hermite: 'Hermite', bezier: 'Bezier (Bernstein)', bspline: 'B-spline', 'catmull-rom': 'Catmull-Rom',
  cardinal: 'cardinal spline', interpolation: 'Lagrange interpolation', nurbs: 'NURBS' };
function segmentTitle(state, segment) {
  const label = familyInfo(state.family).label;
  if (state.family === 'catmull-rom' && state.tension !== 0) return `${label}: cardinal spline, tension ${formatNumber(state.tension, 3)}`;
  if (state.family === 'nurbs') return `${label}: homogeneous B-spline segment`;
  const name = BASIS_NAMES[segment.basis];
  return name && !label.includes(name.split(' ')[0]) ? `${label}: ${name} basis` : label;
}

// The lecture's own names when the segment is one of the lectures' cubics (a Bezier of
// degree 3, the uniform cubic B-spline, Catmull-Rom without tension, Hermite).
function segmentNames(state, segment) {
  const cubic = segment.degree === 3 && (state.family === 'hermite' || state.family === 'bezier'
    || (state.family === 'bspline-uniform') || (state.family === 'catmull-rom' && state.tension === 0));
  return cubic ? lectureNames(state.form, segment.basis) : null;
}
