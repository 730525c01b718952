// @ts-check
// Comparison lab (lectures 001, 002, 003): one control polygon under Hermite, Bezier,
// uniform B-spline and Catmull-Rom at once; the lectures' comparison table checked live by
// the core; basis conversion both ways; affine and perspective invariance measured.
import { object, list, number, oneOf, integer, boolean, viewSchema } from '../../app/schema.js';
import { h, panel, table, setChildren } from '../../app/dom.js';
import { math, matrix, mi, mo, mn, el, rows4, formatNumber, continuityClass, inlineMath } from '../../ui/mathml.js';
import { formatSize as fmtDistance } from '../../ui/format.js';
import { FAMILY_IDS, FAMILY_NAMES, FAMILY_COLOR, FAMILY_DASH } from './families.js';
import { computeTable, LECTURE_TABLE, ROW_NAMES } from './checks.js';
import { computeConversion, computeInvariance } from './transforms.js';
import { drawCurve, drawPolygon, drawLegend, arrowScale } from '../../ui/curve-overlays.js';

// Hermite tangent arrows are drawn at a third of the tangent (as the curve explorer's T_i/3).
const TANGENT_SCALE = 1 / 3;
import { createBlendingPlot } from '../../ui/blending-plot.js';
import { createMatrixPanel } from '../../ui/matrix-panel.js';
import { MATRIX_FORMS, createFormSelect, nextForm, lectureNames } from '../../ui/matrix-forms.js';
import { computeDerivations, createDerivationPanel } from './derivation-panel.js';
import { comparisonExercise } from './exercise.js';

// The blending functions of one segment per point-based family: the convex hull row's
// evidence (lecture 003: weights in [0, 1] summing to 1), drawn with the curve explorer's plot.
const BLEND_FAMILIES = ['bezier', 'bspline', 'catmull-rom'];

const SCENES = { families: 'All families', conversion: 'Basis conversion', invariance: 'Invariance' };
const BASES = ['hermite', 'bezier', 'bspline', 'catmull-rom'];
const POINT_BASES = ['bezier', 'bspline', 'catmull-rom'];
const pair = list(number(), { min: 2, max: 2 });

// The default polygon: seven points (two cubic Bezier segments), in general position so no
// joint is accidentally smoother than its family guarantees.
const DEFAULT_POINTS = [[-3.2, -1.2], [-2.4, 1.3], [-0.9, 1.6], [-0.2, -0.4], [1.1, -1.5], [2.3, 0.2], [3.3, 1.4]];

// Hermite's own tangents T_i for the default polygon (not Catmull-Rom's
// (P_i+1 - P_i-1)/2, so the two curves differ visibly; dragging the arrow tips edits them).
// A new segment's points get NEW_TANGENT. Plain data, in the points' units.
const DEFAULT_TANGENTS = [[0, 4], [3, 0], [2, -3], [1.5, -3], [3, 0], [1.5, 3], [3, 0]];
const NEW_TANGENT = [2, 0];

const MIN_POINTS = 4;  // one cubic segment (a share link may hold one)
const MIN_POINTS_BY_BUTTON = 7; // two segments: the continuity rows need a joint
const MAX_POINTS = 31; // ten segments (the schema's limit)

// Three more points continuing the polygon: each side turns by a different angle from the
// last one (so no joint comes out accidentally smoother than its family guarantees),
// rounded to hundredths so share links stay short.
// One tangent per point: the ones kept, NEW_TANGENT for new points (a segment added).
function tangentsFor(points, own = DEFAULT_TANGENTS) {
  return points.map((_, i) => (own[i] ?? NEW_TANGENT).slice());
}

function withNewSegment(points) {
  const out = points.map((p) => p.slice());
  const [a, b] = out.slice(-2);
  let d = [b[0] - a[0], b[1] - a[1]];
  const length = Math.hypot(...d) || 1;
  d = [d[0] / length * 1.4, d[1] / length * 1.4];
  for (const turn of [0.7, -0.95, 0.45]) {
    d = [d[0] * Math.cos(turn) - d[1] * Math.sin(turn), d[0] * Math.sin(turn) + d[1] * Math.cos(turn)];
    const last = out[out.length - 1];
    out.push([Math.round((last[0] + d[0]) * 100) / 100, Math.round((last[1] + d[1]) * 100) / 100]);
  }
  return out;
}

const fmt = (x) => formatNumber(x, 3);
// A bracket that keeps its text size next to tall matrices.
const fixed = (text) => { const o = mo(text); o.setAttribute('stretchy', 'false'); return o; };

// The points, and Hermite's own tangent tips P_i + T_i/3 (drawn at a third, as the arrows)
// while the families scene shows Hermite with its own tangents.
const ownTangents = (state) => state.scene === 'families' && state.show.hermite && state.hermite.tangents === 'own';
const handlesOf = (state) => [
  ...state.points.map(([x, y], i) => ({ id: `p${i}`, x, y, label: `P${i}` })),
  ...(ownTangents(state) ? state.points.map(([x, y], i) => ({ id: `t${i}`, x: x + state.hermite.own[i][0] / 3, y: y + state.hermite.own[i][1] / 3, label: `T${i}` })) : []),
];

/** @type {import('../../app/contract.js').Lesson} */
export const lesson = {
  id: 'comparison',
  title: 'Comparison lab',
  // The core modules the page loads (docs/architecture.md, "Module size").
  core: ['curves'],
  stateVersion: 4,
  exercise: comparisonExercise,
  // Version 2: the notation of the matrix panels; older links show decimals.
  // Version 3: the matrix form of the panels (MATRIX_FORMS); older links show
  // lectures 000/003's form, as they did.
  // Version 4: Hermite's tangents (own, or Catmull-Rom's). Older links drew
  // Hermite with Catmull-Rom's tangents: they open that way, with own tangents in reserve.
  migrations: {
    1: (old) => ({ ...old, notation: 'decimal' }),
    2: (old) => ({ ...old, form: 'descending' }),
    3: (old) => ({ ...old, hermite: { tangents: 'catmull-rom', own: tangentsFor(Array.isArray(old.points) ? old.points : DEFAULT_POINTS) } }),
  },
  schema: {
    points: list(pair, { min: MIN_POINTS, max: MAX_POINTS }),
    scene: oneOf(...Object.keys(SCENES)),
    show: object(Object.fromEntries(FAMILY_IDS.map((f) => [f, boolean()]))),
    conversion: object({ from: oneOf(...POINT_BASES), to: oneOf(...BASES), start: integer({ min: 0, max: 27 }), mode: oneOf('keep-curve', 'keep-geometry') }),
    transform: object({
      kind: oneOf('affine', 'perspective'), angle: number({ min: -180, max: 180 }), scale: number({ min: 0.1, max: 4 }),
      shear: number({ min: -2, max: 2 }), tx: number({ min: -10, max: 10 }), ty: number({ min: -10, max: 10 }),
      px: number({ min: -0.5, max: 0.5 }), py: number({ min: -0.5, max: 0.5 }),
    }),
    notation: oneOf('decimal', 'fraction'),
    form: oneOf(...MATRIX_FORMS),
    hermite: object({ tangents: oneOf('own', 'catmull-rom'), own: list(pair, { min: MIN_POINTS, max: MAX_POINTS }) }),
    view: viewSchema(),
  },
  checkState(state) {
    if ((state.points.length - 1) % 3 !== 0) return `the polygon needs 3n + 1 points (whole cubic Bezier segments), not ${state.points.length}`;
    if (state.hermite.own.length !== state.points.length) return `Hermite needs one tangent per point (${state.points.length}), not ${state.hermite.own.length}`;
    if (state.conversion.start + 4 > state.points.length) return `the converted segment starts at P${state.conversion.start} but needs four points`;
    return null;
  },
  defaultState: () => ({
    points: DEFAULT_POINTS.map((p) => p.slice()),
    scene: 'families',
    show: { hermite: true, bezier: true, bspline: true, 'catmull-rom': true, nubs: true },
    conversion: { from: 'bezier', to: 'hermite', start: 0, mode: 'keep-curve' },
    transform: { kind: 'affine', angle: 30, scale: 0.8, shear: 0.3, tx: 0.5, ty: -0.4, px: 0.06, py: 0.03 },
    notation: 'decimal',
    form: 'descending',
    hermite: { tangents: 'own', own: DEFAULT_TANGENTS.map((t) => t.slice()) },
    view: { cx: 0, cy: 0, zoom: 90 },
  }),

  compute(view, state, ctx) {
    const api = ctx.api;
    return {
      state,
      table: computeTable(api, state.points, state.hermite.tangents === 'own' ? state.hermite.own : null),
      conversion: computeConversion(api, state.points, state.conversion, state.form),
      invariance: computeInvariance(api, state.points, state.transform),
      blending: BLEND_FAMILIES.map((family) => blendingOfFirstSegment(api, family, state.points)),
      derivations: computeDerivations(api, state.points),
    };
  },

  fitView(view, model, stage) {
    // (the tips of Hermite's own tangents are handles too: they must be in view)
    const tips = handlesOf(model.state).filter((hd) => hd.id[0] === 't').map((hd) => [hd.x, hd.y]);
    const pts = model.state.scene === 'invariance' ? [...model.state.points, ...model.invariance.mapped] : [...model.state.points, ...tips];
    const xs = pts.map((p) => p[0]);
    const ys = pts.map((p) => p[1]);
    const [minY, maxY] = [Math.min(...ys), Math.max(...ys)];
    // (The legend is under the canvas: app/canvas-legend.js.)
    return stage.fit(Math.min(...xs), minY - 0.3, Math.max(...xs), maxY + 0.3 * (maxY - minY) + 0.3);
  },

  setup(ctx) {
    const sceneSelect = h('select', { id: 'scene', onchange: () => {
      // Each scene gets a view that shows all of it (the invariance scene adds the mapped points).
      if (ctx.commit({ ...ctx.state, scene: sceneSelect.value })) ctx.fitView();
    } },
      Object.entries(SCENES).map(([k, v]) => h('option', { value: k }, v)));
    const familyBoxes = FAMILY_IDS.map((f) => {
      const box = h('input', { type: 'checkbox', id: `show-${f}`, onchange: () => ctx.commit({ ...ctx.state, show: { ...ctx.state.show, [f]: box.checked } }, { recompute: false }) });
      return { f, box, label: h('label', { for: `show-${f}`, class: `family-${f}` }, box, FAMILY_NAMES[f]) };
    });
    // One more or one fewer cubic segment (three points); the conversion's segment stays valid.
    const addSegment = () => {
      const state = ctx.state;
      if (state.points.length + 3 > MAX_POINTS) { ctx.message.error(`At most ${MAX_POINTS} points (ten segments)`, 'too-many-points'); return; }
      const points = withNewSegment(state.points);
      if (ctx.commit({ ...state, points, hermite: { ...state.hermite, own: tangentsFor(points, state.hermite.own) } })) ctx.fitView();
    };
    const removeSegment = () => {
      const state = ctx.state;
      if (state.points.length - 3 < MIN_POINTS_BY_BUTTON) { ctx.message.error('Two segments are the least here: the continuity rows need a joint', 'too-few-points'); return; }
      const points = state.points.slice(0, -3);
      ctx.commit({ ...state, points, hermite: { ...state.hermite, own: tangentsFor(points, state.hermite.own) },
        conversion: { ...state.conversion, start: Math.min(state.conversion.start, points.length - 4) } });
    };
    const addButton = h('button', { type: 'button', class: 'tool', id: 'add-segment', onclick: addSegment }, 'Add a segment');
    const removeButton = h('button', { type: 'button', class: 'tool', id: 'remove-segment', onclick: removeSegment }, 'Remove the last segment');
    // Hermite's tangents, its own (default) or Catmull-Rom's (the comparison of
    // lecture 002's Catmull-Rom conditions inside Hermite), with a note saying which.
    const hermiteTangents = h('select', { id: 'hermite-tangents', onchange: () => ctx.commit({ ...ctx.state, hermite: { ...ctx.state.hermite, tangents: hermiteTangents.value } }) },
      h('option', { value: 'own' }, 'its own (drag the tips)'),
      h('option', { value: 'catmull-rom' }, 'Catmull-Rom\'s (P(i+1) − P(i−1))/2'));
    const hermiteNote = h('p', { class: 'hint lecture-note', id: 'hermite-note', 'aria-live': 'polite' });
    ctx.controls.replaceChildren(h('label', { for: 'scene' }, 'Show ', sceneSelect), ...familyBoxes.map((b) => b.label), addButton, removeButton,
      h('label', { for: 'hermite-tangents' }, 'Hermite tangents ', hermiteTangents), hermiteNote);

    // The panel of the current scene is open and first in view; the live table stays below.
    const convBody = panel(ctx.panels, { id: 'conversion-panel', title: h('span', {}, 'Basis conversion: ', inlineMath(el('mrow', mi('q'), mo('='), el('msup', mi('M'), el('mrow', mo('−'), mn('1'))), el('msub', mi('M'), mi('B')), mi('P')))), open: false });
    const invBody = panel(ctx.panels, { id: 'invariance-panel', title: 'Invariance: transform the points or the curve', open: false });
    const tableBody = panel(ctx.panels, { id: 'table-panel', title: 'The comparison table, checked live' });
    const blendBody = panel(ctx.panels, { id: 'blending-panel', title: 'Blending weights (the convex hull row)' });
    const blendPlots = BLEND_FAMILIES.map((f) => createBlendingPlot(blendBody, { label: FAMILY_NAMES[f], height: 130 }));

    const select = (id, options, value, onchange, names = /** @type {Record<string, string>} */ (FAMILY_NAMES)) => {
      const s = h('select', { id, onchange: () => onchange(s.value) }, options.map((o) => h('option', { value: o }, names[o] ?? o)));
      s.value = value;
      return s;
    };
    const setConversion = (patch) => ctx.commit({ ...ctx.state, scene: 'conversion', conversion: { ...ctx.state.conversion, ...patch } });
    const conv = {
      mode: select('conv-mode', ['keep-curve', 'keep-geometry'], 'keep-curve', (v) => setConversion({ mode: v }),
        { 'keep-curve': 'keep the curve, find q', 'keep-geometry': 'keep G, swap M' }),
      from: select('conv-from', POINT_BASES, 'bezier', (v) => setConversion({ from: v })),
      to: select('conv-to', BASES, 'hermite', (v) => setConversion({ to: v })),
      start: h('input', { type: 'number', id: 'conv-start', min: 0, step: 1, onchange: () => setConversion({ start: Number(conv.start.value) }) }),
      out: h('div', { class: 'conversion-out' }),
      matrices: h('div', { class: 'conversion-matrices' }),
      // M in exact fractions as on the slides (1/6 [...], 1/2 [...]) or decimals.
      fractions: h('input', { type: 'checkbox', id: 'conv-fractions', onchange: (e) => ctx.commit({ ...ctx.state, notation: e.target.checked ? 'fraction' : 'decimal' }) }),
    };
    // The form of a lecture for the two matrix panels (000/003, 002, 001).
    ({ select: conv.form, row: conv.formRow } = createFormSelect('conv-form', (form) => ctx.commit({ ...ctx.state, form })));
    convBody.append(h('div', { class: 'form-row' },
      h('label', { for: 'conv-mode' }, 'Mode ', conv.mode), h('label', { for: 'conv-from' }, 'P read as ', conv.from),
      h('label', { for: 'conv-to' }, 'other basis ', conv.to), h('label', { for: 'conv-start' }, 'first point P', conv.start),
      h('label', { class: 'check' }, conv.fractions, ' Exact fractions as on the slides')), conv.formRow, conv.out, conv.matrices);
    conv.fromPanel = createMatrixPanel(conv.matrices);
    conv.toPanel = createMatrixPanel(conv.matrices);

    const setTransform = (patch) => ctx.commit({ ...ctx.state, scene: 'invariance', transform: { ...ctx.state.transform, ...patch } });
    const slider = (key, text, min, max, step) => {
      const input = h('input', { type: 'range', id: `tf-${key}`, min, max, step, oninput: () => setTransform({ [key]: Number(input.value) }) });
      const out = h('output', { for: `tf-${key}` });
      return { key, input, out, label: h('label', { for: `tf-${key}` }, text, ' ', input, out) };
    };
    const inv = {
      kind: select('tf-kind', ['affine', 'perspective'], 'affine', (v) => setTransform({ kind: v }), { affine: 'affine (rotate, scale, shear, move)', perspective: 'perspective' }),
      sliders: [slider('angle', 'angle°', -180, 180, 1), slider('scale', 'scale', 0.1, 2, 0.05), slider('shear', 'shear', -1, 1, 0.05),
        slider('tx', 'move x', -3, 3, 0.1), slider('ty', 'move y', -3, 3, 0.1), slider('px', 'perspective x', -0.2, 0.2, 0.01), slider('py', 'perspective y', -0.2, 0.2, 0.01)],
      out: h('div', { class: 'invariance-out' }),
    };
    invBody.append(h('label', { for: 'tf-kind' }, 'Map ', inv.kind), h('div', { class: 'slider-grid' }, inv.sliders.map((s) => s.label)), inv.out);
    const derivation = createDerivationPanel(ctx.panels);
    const ui = { sceneSelect, familyBoxes, hermiteTangents, hermiteNote, tableBody, conv, inv, blendPlots, addButton, removeButton, shownScene: null, derivation,
      convPanel: convBody.parentElement, invPanel: invBody.parentElement };
    ctx.keymap.add({ keys: ['n'], label: 'add a segment (three points)', group: 'Lesson', action: addSegment });
    ctx.keymap.add({ keys: ['f'], label: 'matrix entries: exact fractions or decimals', group: 'Lesson',
      action: () => ctx.commit({ ...ctx.state, notation: ctx.state.notation === 'fraction' ? 'decimal' : 'fraction' }) });
    ctx.keymap.add({ keys: ['m'], label: 'next matrix form: lectures 000/003, 002, 001', group: 'Lesson',
      action: () => ctx.commit({ ...ctx.state, form: nextForm(ctx.state.form) }) });
    ctx.keymap.add({ keys: ['x'], label: 'remove the last segment', group: 'Lesson', action: removeSegment });

    ctx.keymap.add({ keys: ['v'], label: 'next scene: families, conversion, invariance', group: 'Lesson', action: () => {
      const keys = Object.keys(SCENES);
      ctx.commit({ ...ctx.state, scene: keys[(keys.indexOf(ctx.state.scene) + 1) % keys.length] });
    } });
    FAMILY_IDS.forEach((f, i) => ctx.keymap.add({ keys: [String(i + 1)], label: `show / hide ${FAMILY_NAMES[f]}`, group: 'Lesson',
      action: () => ctx.commit({ ...ctx.state, show: { ...ctx.state.show, [f]: !ctx.state.show[f] } }, { recompute: false }) }));
    // The view: the panels' elements (and which scene's panel was last opened).
    return ui;
  },

  update(ui, model, state, ctx) {
    ui.derivation.update(model.derivations);
    if (ui.shownScene !== state.scene) {
      ui.shownScene = state.scene;
      ui.convPanel.open = state.scene === 'conversion';
      ui.invPanel.open = state.scene === 'invariance';
    }
    ui.sceneSelect.value = state.scene;
    for (const b of ui.familyBoxes) b.box.checked = state.show[b.f];
    ui.hermiteTangents.value = state.hermite.tangents;
    const note = state.hermite.tangents === 'catmull-rom'
      ? 'Catmull-Rom inside Hermite: with the tangents (P(i+1) − P(i−1)) / 2 of lecture 002\'s Catmull-Rom conditions, every inner Hermite segment is the Catmull-Rom segment, so the two curves coincide there (they differ only in the end segments, where Hermite takes the chord and Catmull-Rom repeats the end point).'
      : '';
    if (ui.hermiteNote.textContent !== note) ui.hermiteNote.textContent = note;
    ui.hermiteNote.hidden = note === '';
    ui.addButton.disabled = state.points.length + 3 > MAX_POINTS;
    ui.removeButton.disabled = state.points.length - 3 < MIN_POINTS_BY_BUTTON;
    updateTable(ui.tableBody, model.table);
    updateConversion(ui.conv, model.conversion, state);
    updateInvariance(ui.inv, model.invariance, state);
    model.blending.forEach((b, k) => ui.blendPlots[k].update({
      params: b.params, count: b.count, values: b.values, u: b.uMin, domain: { start: 0, end: 1 }, colors: ctx.colors,
      labels: b.labels, caption: `${FAMILY_NAMES[b.family]}, first segment: smallest weight ${fmt(b.minWeight)} at u = ${fmt(b.uMin)}`,
    }));
    const m = model.conversion;
    const name = (k) => FAMILY_NAMES[k];
    ui.conv.fractions.checked = state.notation === 'fraction';
    ui.conv.form.value = state.form;
    // The four bases here are the lectures' cubics: each form's own names.
    ui.conv.fromPanel.update({ segment: m.segmentFrom, u: 0.5, point: m.midFrom, notation: state.notation, form: state.form,
      names: lectureNames(state.form, m.segmentFrom.basis), title: `${name(m.from)}: the segment as drawn (P)` });
    ui.conv.toPanel.update({ segment: m.segmentTo, u: 0.5, point: m.midTo, notation: state.notation, form: state.form,
      names: lectureNames(state.form, m.segmentTo.basis),
      title: m.q ? `${name(m.to)}: the same curve from q` : `${name(m.to)}: the same G with M swapped` });
  },

  draw(view, painter, model, state, ctx) {
    if (!model) return;
    const c = ctx.colors;
    const strokeOf = (f) => c.series[FAMILY_COLOR[f]];
    drawPolygon(painter, state.points, { stroke: c.muted, width: 1.2, dash: [5, 4] });
    const legend = [];
    if (state.scene === 'families') {
      for (const f of FAMILY_IDS) {
        if (!state.show[f]) continue;
        for (const s of model.table.curves[f]) drawCurve(painter, s.points, { stroke: strokeOf(f), width: f === 'bezier' ? 4 : 2.5, dash: FAMILY_DASH[f] });
        legend.push([strokeOf(f), `${FAMILY_NAMES[f]}${f === 'catmull-rom' ? ' (end points repeated)' : f === 'nubs' ? ` (knots ${model.table.knots.join(', ')})` : f === 'hermite' ? (state.hermite.tangents === 'own' ? `, its own tangents (drag the tips T0..T${state.points.length - 1})` : ', t_i = (P_i+1 − P_i−1)/2: Catmull-Rom inside') : ''}`, FAMILY_DASH[f]]);
      }
      if (state.show.hermite) {
        const t = model.table.tangents;
        state.points.forEach((p, i) => painter.arrow(p[0], p[1], p[0] + t[i][0] * TANGENT_SCALE, p[1] + t[i][1] * TANGENT_SCALE, { stroke: strokeOf('hermite'), width: 1.2, alpha: 0.8 }));
        legend.push([strokeOf('hermite'), `Hermite tangents t_i: arrows drawn at ${arrowScale(TANGENT_SCALE)} of t_i`, []]);
      }
    } else if (state.scene === 'conversion') {
      const m = model.conversion;
      painter.polyline(m.original, { stroke: c.series[0], width: 5, alpha: 0.55 });
      painter.polyline(m.other, { stroke: c.series[1], width: 2, dash: [8, 5] });
      legend.push([c.series[0], `${FAMILY_NAMES[m.from]} segment of P${state.conversion.start}..P${state.conversion.start + 3}`, []]);
      legend.push([c.series[1], m.mode === 'keep-curve' ? `${FAMILY_NAMES[m.to]} curve of q (max distance ${fmtDistance(m.distance)})` : `same G read as ${FAMILY_NAMES[m.to]}`, [8, 5]]);
      if (m.q) drawGeometry(painter, m.to, m.q, c.series[1], 'q', c);
      if (m.q && m.to === 'hermite') legend.push([c.series[1], `Hermite tangents of q: arrows drawn at ${arrowScale(TANGENT_SCALE)} of t_i (label t_i/3)`, []]);
    } else {
      const inv = model.invariance;
      for (const piece of inv.drawing.bezier) {
        painter.polyline(piece.mappedCurve, { stroke: c.ink, width: 5, alpha: 0.3 });
        painter.polyline(piece.curveOfMapped, { stroke: c.series[0], width: 2, dash: [8, 5] });
      }
      painter.polyline(inv.mapped.flat(), { stroke: c.series[0], width: 1, dash: [2, 3] });
      inv.mapped.forEach((p, i) => painter.text(p[0], p[1], `T(P${i})`, { fill: c.series[0], font: 12, dy: -12, halo: c.background }));
      legend.push([c.ink, 'T(curve): the Bezier curve, then mapped', []]);
      legend.push([c.series[0], `curve of T(P): mapped points, then evaluated (max distance ${fmtDistance(inv.rows.bezier.distance)})`, [8, 5]]);
      if (inv.rational) {
        for (const piece of inv.rational.pieces) painter.polyline(piece.rationalCurve, { stroke: c.series[2], width: 2, dash: [2, 4] });
        legend.push([c.series[2], `rational Bezier of T(P), weights w(P_i) (max distance ${fmtDistance(inv.rational.distance)})`, [2, 4]]);
      }
    }
    for (const hd of handlesOf(state)) {
      const on = hd.id === ctx.ui.selected;
      painter.circle(hd.x, hd.y, on ? 8 : 6, { fill: on ? c.highlight : c.background, stroke: c.ink, width: 1.5 });
      painter.text(hd.x, hd.y, hd.label, { fill: c.ink, font: 12, dx: 12, dy: -12, align: 'left', halo: c.background });
    }
    drawLegend(painter, legend);
  },

  handles(view, model, state) { return handlesOf(state); },

  moveHandle(view, state, id, x, y) {
    const i = Number(id.slice(1));
    if (!Number.isInteger(i) || i < 0 || i >= state.points.length) return null;
    if (id[0] === 't') {
      // The tip is drawn at P_i + T_i/3.
      if (!ownTangents(state)) return null;
      const own = state.hermite.own.map((t) => t.slice());
      own[i] = [3 * (x - state.points[i][0]), 3 * (y - state.points[i][1])];
      return { ...state, hermite: { ...state.hermite, own } };
    }
    const points = state.points.map((p) => p.slice());
    points[i] = [x, y];
    return { ...state, points };
  },

  // One line for the History.
  summarize: (state) => `${state.points.length} control points, ${state.scene}`,
  describe(view, model, state) {
    if (!model) return '';
    const cols = model.table.columns;
    const parts = FAMILY_IDS.map((f) => `${FAMILY_NAMES[f]}: interpolates ${cols[f].interpolatesAll.answer === 'Yes' ? 'all' : cols[f].interpolatesSome.answer === 'Yes' ? `P${cols[f].interpolatesSome.interpolated.join(', P')}` : 'no'} control points, inherent ${cols[f].inherent.answer}`);
    return `${state.points.length} control points drawn under four families (${SCENES[state.scene]}). ${parts.join('; ')}.`;
  },

  exports: [{
    label: 'Comparison table (Markdown)', filename: 'comparison-table.md', type: 'text/markdown',
    make(view, model) {
      const head = `| | ${FAMILY_IDS.map((f) => FAMILY_NAMES[f]).join(' | ')} |\n|---|${FAMILY_IDS.map(() => '---').join('|')}|`;
      const cellText = (f, row) => {
        const c = model.table.columns[f][row];
        const seen = model.table.polygon[f][row];
        return `${c.answer} (${c.quoted ? 'quoted from the lecture' : c.evidence}; this polygon: ${seen.answer})`;
      };
      const rows = Object.keys(ROW_NAMES).map((row) => `| ${ROW_NAMES[row]} | ${FAMILY_IDS.map((f) => cellText(f, row)).join(' | ')} |`);
      return `${head}\n${rows.join('\n')}\n`;
    },
  }],
};

function blendingOfFirstSegment(api, family, points) {
  const params = Array.from({ length: 101 }, (_, j) => j / 100);
  const curve = family === 'bezier' ? { kind: 'bezier', dim: 2, points: points.slice(0, 4).flat() }
    : family === 'bspline' ? { kind: 'bspline', dim: 2, points: points.slice(0, 4).flat() }
      : { kind: 'catmull-rom', dim: 2, points: [points[0], ...points.slice(0, 3)].flat() };
  const b = api.blendingFunctions(curve, params);
  // The smallest weight and where it first occurs, from the core (the same 101 parameters).
  const w = api.blendingWeightCheck([curve], params.length);
  const labels = family === 'catmull-rom' ? ['P0', 'P0', 'P1', 'P2'] : ['P0', 'P1', 'P2', 'P3'];
  return { family, params, count: b.count, values: b.values, minWeight: w.minWeight, uMin: w.minWeightAt, labels };
}

function updateTable(body, tbl) {
  const rows = Object.keys(ROW_NAMES).map((row) => [ROW_NAMES[row], ...FAMILY_IDS.flatMap((f) => {
    const cell = tbl.columns[f][row];
    const seen = tbl.polygon[f][row];
    const expected = LECTURE_TABLE[row][f];
    const measured = cell.answer !== '—';
    const agrees = cell.answer === expected;
    // The lecture's own judgement is shown as a quotation: no check mark, no verdict.
    const verdict = cell.quoted
      ? h('span', { class: 'lecture quoted' }, 'quoted from the lecture, not checked')
      : measured ? h('span', { class: agrees ? 'lecture agrees' : 'lecture differs' }, `lecture: ${expected} ${agrees ? '✓' : '≠'}`)
        : h('span', { class: 'lecture' }, `lecture: ${expected} (at a joint)`);
    // One column per family (the guarantee, then what this polygon does under it): five
    // families fit a projector's side column without a sideways scroll.
    return [h('div', { class: 'family-cell' },
      h('div', { class: 'live-cell', 'data-row': row, 'data-family': f, 'data-answer': cell.answer, 'data-agrees': cell.quoted ? null : String(agrees), 'data-quoted': cell.quoted ? 'true' : null },
        h('strong', {}, cell.answer), h('span', { class: 'evidence' }, cell.evidence), verdict),
      h('div', { class: 'polygon-cell', 'data-row': row, 'data-family': f, 'data-answer': seen.answer },
        h('span', { class: 'polygon-label' }, 'this polygon: '), h('strong', {}, seen.answer), h('span', { class: 'evidence' }, seen.evidence)))];
  })]);
  body.replaceChildren(
    table({ caption: 'Lecture 003 (Hermite to Catmull-Rom) and lecture 001 (non-uniform B-spline): each guarantee checked for every polygon, and under it what this polygon does',
      head: [['', ...FAMILY_IDS.map((f) => FAMILY_NAMES[f])]],
      rows, className: 'data-table comparison-table' }),
    h('p', { class: 'hint' }, 'Guaranteed: what holds for every control polygon. Continuity and interpolation come from the core\'s structural argument: the derivatives at a joint are linear in the control data, so ', continuityClass('C', 'k'), ' holds for every polygon exactly when their coefficients (basis matrix, or the basis functions at a knot) agree, and a point is always interpolated when its basis function is 1 at a joint. Convex hull: the blending weights of the points are ≥ 0 and sum to 1 (lecture 003). This polygon: distances from the control points to the curve and the core\'s classifier at its joints, which may be smoother than guaranteed. Ease of subdivision is the lecture\'s judgement, quoted; beside it, how well this polygon\'s split halves match.'),
  );
}

function drawGeometry(painter, basis, q, color, name, c) {
  if (basis === 'hermite') {
    const p = [[q[0], q[1]], [q[2], q[3]]];
    const t = [[q[4], q[5]], [q[6], q[7]]];
    p.forEach((pt, i) => {
      painter.arrow(pt[0], pt[1], pt[0] + t[i][0] * TANGENT_SCALE, pt[1] + t[i][1] * TANGENT_SCALE, { stroke: color, width: 2 });
      painter.circle(pt[0], pt[1], 5, { fill: color });
      painter.text(pt[0], pt[1], `${name}: p${i}, t${i}/3`, { fill: color, font: 12, dy: 16, halo: c.background });
    });
    return;
  }
  for (let i = 0; i < 4; i += 1) {
    painter.polygon([q[2 * i] - 0.06, q[2 * i + 1] - 0.06, q[2 * i] + 0.06, q[2 * i + 1] - 0.06, q[2 * i] + 0.06, q[2 * i + 1] + 0.06, q[2 * i] - 0.06, q[2 * i + 1] + 0.06], { fill: color });
    painter.text(q[2 * i], q[2 * i + 1], `${name}${i}`, { fill: color, font: 12, dy: 16, halo: c.background });
  }
  painter.polyline(Array.from(q), { stroke: color, width: 1, dash: [2, 3] });
}

function geometryRows(values) {
  const rows = [];
  for (let i = 0; i < 4; i += 1) rows.push([values[2 * i], values[2 * i + 1]]);
  return rows;
}

function updateConversion(ui, m, state) {
  ui.mode.value = state.conversion.mode;
  ui.from.value = state.conversion.from;
  ui.to.value = state.conversion.to;
  ui.start.max = String(state.points.length - 4);
  ui.start.value = String(state.conversion.start);
  const sub = (base, s) => el('msub', mi(base), mi(s));
  const short = { hermite: 'H', bezier: 'B', bspline: 'S', 'catmull-rom': 'R' };
  // Two pieces that wrap: "= q" goes under the product when the column is narrow (a
  // projector's side column), instead of being cut off.
  const formula = m.q
    ? [math(mi('q'), mo('='), el('msup', sub('M', short[m.to]), el('mn', '-1')), sub('M', short[m.from]), mi('P'), mo('='),
      el('msup', matrix(rows4(m.Mto)), el('mn', '-1')), matrix(rows4(m.Mfrom)), matrix(geometryRows(m.g))), math(mo('='), matrix(geometryRows(m.q)))]
    : [math(mi('P'), fixed('('), mi('u'), fixed(')'), mo('='), el('msup', mi('u'), mi('T')), matrix(rows4(m.Mto)), matrix(geometryRows(m.g)))];
  setChildren(ui.out,
    h('div', { class: 'formula formula-pieces' }, ...formula),
    h('p', { 'data-conversion-distance': String(m.distance) }, m.q
      ? `The ${FAMILY_NAMES[m.to]} curve of q is the ${FAMILY_NAMES[m.from]} curve of P: max distance ${fmtDistance(m.distance)} over 121 samples.`
      : `The same four rows read as ${FAMILY_NAMES[m.to]} geometry give another curve: max distance ${fmt(m.distance)} from the ${FAMILY_NAMES[m.from]} curve.`),
    m.to === 'hermite' && m.q ? h('p', { class: 'hint' }, 'Hermite rows are p0, p1, t0, t1: two points and two tangent vectors (drawn at 1/3 length).') : null,
    h('p', { class: 'hint' }, m.q
      ? 'Below, the core\'s matrix form of both: different M and G, the same coefficients C = M G, so the same curve.'
      : 'Below, the core\'s matrix form of both: the same G, different M, so different coefficients C = M G.'),
  );
}

function updateInvariance(ui, inv, state) {
  ui.kind.value = state.transform.kind;
  for (const s of ui.sliders) {
    s.input.value = String(state.transform[s.key]);
    s.out.textContent = fmt(state.transform[s.key]);
    s.input.disabled = (s.key === 'px' || s.key === 'py') && state.transform.kind !== 'perspective';
  }
  const rows = FAMILY_IDS.map((f) => [FAMILY_NAMES[f], fmtDistance(inv.rows[f].distance),
    inv.rows[f].distance < 1e-9 ? 'same curve' : 'different curves']);
  if (inv.rational) rows.push(['Rational Bezier, weights w(P_i)', fmtDistance(inv.rational.distance), inv.rational.distance < 1e-9 ? 'same curve' : 'different curves']);
  ui.out.replaceChildren(
    table({ caption: `${state.transform.kind === 'affine' ? 'Affine' : 'Perspective'} map T: max distance between T(curve) and the curve of T(P)`,
      head: [['family', 'max distance', 'verdict']], rows, className: 'data-table invariance-table' }),
    h('p', { class: 'hint' }, state.transform.kind === 'affine'
      ? 'Affine maps (rotation, scale, shear, translation) commute with the blending weights because they sum to 1: every family is invariant (lecture 001).'
      : 'A perspective map divides by w = px x + py y + 1. Polynomial curves are not invariant; the rational curve with weights w(P_i) is (lecture 001: "rational splines are also perspective invariant").'),
  );
}
