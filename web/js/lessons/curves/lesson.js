// @ts-check
// The curve explorer (lectures 000-004): one page for every curve family of the
// course. State: the family, points, tangents, knots, weights, degree, tension, u, the
// construction and its step, the overlays, the matrix form, the view. All mathematics in
// compute() through the core (curve-model.js); draw() only draws; the panels show the
// numbers the core returned.
import { number, integer, boolean, oneOf, list, object, viewSchema } from '../../app/schema.js';
import { FAMILY_IDS, familyInfo, usesKnots, isSpline } from './families.js';
import { OVERLAYS, CONSTRUCTIONS, blendingLabels } from './names.js';
import { computeCurveModel, constructionsFor, createModelCache } from './curve-model.js';
import { drawCurve, drawInfluence, drawPolygon, drawHull, drawVector, drawComb, drawMarks, drawSamples, drawLevels, drawLegend, arrowScale } from '../../ui/curve-overlays.js';
import { createPanels, updatePanels, drawPlots } from './panels.js';
import { formatNumber } from '../../ui/mathml.js';
import { MATRIX_FORMS, migrateTransposed } from '../../ui/matrix-forms.js';
import { curvesExercise } from './exercise.js';
import { defaultCurveState } from './state.js';

const pair = list(number(), { min: 2, max: 2 });
// Parse bound of the per-point lists of a share link or file; each family's own limit is
// checked by checkState and, for interpolation, by the core (api.curveLimits(); a test
// keeps this bound above it).
export const MAX_LIST = 64;

const overlaySchema = object(Object.fromEntries(Object.keys(OVERLAYS).map((k) => [k, boolean()])));

/** @type {import('../../app/contract.js').Lesson} */
export const lesson = {
  id: 'curves',
  title: 'Curve explorer',
  // The core modules the page loads (docs/architecture.md, "Module size").
  core: ['curves'],
  stateVersion: 3,
  exercise: curvesExercise,
  // Version 2: the notation of the matrix panel; older links show decimals.
  // Version 3: the matrix form (MATRIX_FORMS) replaces the lecture-001 checkbox
  // `transposed`; an old link opens in the form it showed.
  migrations: {
    1: (old) => ({ ...old, notation: 'decimal' }),
    2: (old) => migrateTransposed(old),
  },
  schema: {
    family: oneOf(...FAMILY_IDS),
    points: list(pair, { min: 2, max: MAX_LIST }),
    tangents: list(pair, { min: 0, max: MAX_LIST }),
    knots: list(number(), { min: 0, max: 40 }),
    weights: list(number(), { min: 0, max: MAX_LIST }),
    degree: integer({ min: 1, max: 7 }),
    tension: number({ min: -1, max: 1 }),
    u: number(),
    construction: object({ kind: oneOf(...CONSTRUCTIONS), step: integer({ min: 0, max: 40 }) }),
    overlays: overlaySchema,
    form: oneOf(...MATRIX_FORMS),
    notation: oneOf('decimal', 'fraction'),
    compare: boolean(),
    view: viewSchema(),
  },

  defaultState: defaultCurveState,

  // Cross-field rules (share links, files): the per-point lists and the knot count.
  checkState(s) {
    const K = s.points.length;
    const info = familyInfo(s.family);
    // (interpolation: maxPoints null, the core refuses more than its limit when computing)
    if (K < info.minPoints || K > (info.maxPoints ?? Infinity)) return `${info.label} needs ${info.minPoints} to ${info.maxPoints} points, not ${K}`;
    if (s.family === 'hermite' && s.tangents.length !== K) return `a Hermite curve needs one tangent per point (${K}), not ${s.tangents.length}`;
    if (s.family === 'nurbs' && s.weights.length !== K) return `a NURBS needs one weight per point (${K}), not ${s.weights.length}`;
    if (usesKnots(s.family) && s.knots.length !== K + s.degree + 1) {
      return `${K} points of degree ${s.degree} need ${K + s.degree + 1} knots (K + p + 1), not ${s.knots.length}`;
    }
    if (isSpline(s.family) && s.degree > K - 1) return `degree ${s.degree} needs at least ${s.degree + 1} points`;
    return null;
  },

  compute(view, state, ctx) {
    const problem = lesson.checkState(state);
    if (problem) throw Object.assign(new Error(problem), { code: 'inconsistent-state' });
    // Headless (the exercise grader: view {}), the view gets its model cache here.
    return computeCurveModel(ctx.api, state, view.cache ??= createModelCache());
  },

  setup(ctx) { return createPanels(ctx); },
  update(view, model, state, ctx) { updatePanels(view, model, state, ctx); },

  fitView(view, model, stage) {
    let minX = Infinity; let minY = Infinity; let maxX = -Infinity; let maxY = -Infinity;
    const grow = (x, y) => { minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, y); maxY = Math.max(maxY, y); };
    for (let j = 0; j < model.samples.length; j += 2) grow(model.samples[j], model.samples[j + 1]);
    for (const [x, y] of model.hull) grow(x, y);
    // Hermite: the tangent handles at P_i + T_i/3 are on the picture too
    const { tangents, points } = model.spec;
    if (tangents) for (let j = 0; j + 1 < tangents.length; j += 2) grow(points[j] + tangents[j] / 3, points[j + 1] + tangents[j + 1] / 3);
    return stage.fit(minX, minY, maxX, maxY, 0.1);
  },

  usesHoverPoint: false,

  draw(view, painter, model, state, ctx) {
    const c = ctx.colors;
    const zoom = state.view.zoom;
    const K = state.points.length;
    const seriesOf = (i) => c.series[i % c.series.length];
    const hovered = ctx.ui.hover;
    const o = state.overlays;
    drawGrid(painter, state.view, ctx, c);
    if (o.hull && model.hull.length >= 3) {
      drawHull(painter, model.hull, { stroke: c.muted, fill: c.muted, alpha: 0.1 });
      if (model.segmentHull.length >= 3) drawHull(painter, model.segmentHull, { stroke: c.accent, fill: c.accent, alpha: 0.12 });
    }
    if (o.polygon && state.family !== 'hermite') drawPolygon(painter, state.points, { stroke: c.muted });
    if (state.family === 'hermite') {
      state.points.forEach(([x, y], i) => {
        const [tx, ty] = state.tangents[i];
        painter.arrow(x, y, x + tx / 3, y + ty / 3, { stroke: seriesOf(i), width: 2, dash: [5, 3] });
      });
    }
    if (model.compare) {
      drawCurve(painter, model.compare.samples, { stroke: c.series[2], width: 2.5, dash: [8, 5] });
    }
    drawCurve(painter, model.samples, { stroke: c.ink, width: 3 });
    const item = hoveredItem(hovered, K, state.family);
    if (o.influence && item !== null) drawInfluence(painter, model.samples, model.plot.values, model.plot.count, item, item >= K ? seriesOf(item - K) : seriesOf(item));
    if (o.samples) drawSamples(painter, model.samples, 20, { fill: c.accent });
    if (o.comb && model.comb) drawComb(painter, model.comb, 60 / zoom, { stroke: c.series[3] });
    if (o.knots) {
      if (model.knots) drawMarks(painter, model.knots.positions, model.knots.inside.map((g) => `t=${formatNumber(g.value, 3)}${g.multiplicity > 1 ? ` ×${g.multiplicity}` : ''}`), { fill: c.background, stroke: c.ink, text: c.muted, halo: c.background });
      else if (model.joints) drawMarks(painter, model.joints.positions, null, { fill: c.background, stroke: c.ink });
    }
    drawConstruction(painter, model, state, c);
    // the point at u and its derivative vectors (scaled: P' / 3 is the Bezier-handle length)
    const [px, py] = model.point;
    if (o.tangent) drawVector(painter, model.point, model.d1, 1 / 3, { stroke: c.series[4], halo: c.background }, "P'(u)/3");
    if (o.second) drawVector(painter, model.point, model.d2, 1 / 6, { stroke: c.series[5], halo: c.background }, "P''(u)/6");
    painter.circle(px, py, 7, { fill: c.highlight, stroke: c.background, width: 2 });
    painter.text(px, py, `P(${formatNumber(model.u, 3)})`, { fill: c.highlight, font: 13, dx: 0, dy: 18, halo: c.background, priority: 1 });
    // control points (and Hermite tangent tips) with their labels
    const newPoints = model.construction?.kind === 'insert-knot' && state.construction.step >= 1;
    state.points.forEach(([x, y], i) => {
      const selected = ctx.ui.selected === `p${i}`;
      const w = state.family === 'nurbs' ? ` w=${formatNumber(state.weights[i], 3)}` : '';
      painter.circle(x, y, selected ? 9 : 7, { fill: seriesOf(i), stroke: selected ? c.highlight : c.background, width: selected ? 3 : 2, alpha: newPoints ? 0.35 : 1 });
      painter.text(x, y, `P${i}${w}`, { fill: seriesOf(i), font: 13, dx: 14, dy: -12, halo: c.background, align: 'left', priority: selected ? 3 : 1 });
    });
    if (state.family === 'hermite') {
      state.points.forEach(([x, y], i) => {
        const [tx, ty] = state.tangents[i];
        const selected = ctx.ui.selected === `t${i}`;
        painter.circle(x + tx / 3, y + ty / 3, selected ? 7 : 5, { fill: c.background, stroke: selected ? c.highlight : seriesOf(i), width: 2.5 });
        painter.text(x + tx / 3, y + ty / 3, `T${i}/3`, { fill: seriesOf(i), font: 12, dx: 12, dy: 10, halo: c.background, align: 'left', priority: selected ? 3 : 1 });
      });
    }
    // The legend (under the canvas): the scale of every arrow drawn.
    drawLegend(painter, [
      ...(state.family === 'hermite' ? [[c.ink, `Hermite tangents T_i: dashed arrows drawn at ${arrowScale(1 / 3)} of T_i (label T_i/3)`, [5, 3]]] : []),
      ...(o.tangent ? [[c.series[4], `tangent at the point: arrow drawn at ${arrowScale(1 / 3)} of P'(u)`, []]] : []),
      ...(o.second ? [[c.series[5], `second derivative: arrow drawn at ${arrowScale(1 / 6)} of P''(u)`, []]] : []),
    ]);
  },

  // The blending plot, the knot strip and the homogeneous inset follow every frame (the
  // cursor at u, the hovered point's curve highlighted).
  afterFrame(view, model, state, ctx) {
    drawPlots(view, model, state, ctx, hoveredItem(ctx.ui.hover, state.points.length, state.family));
  },

  // Shift+click adds a control point at the mouse.
  click(view, x, y, ctx, event) {
    if (!event?.shiftKey) return false;
    view.addAt(x, y);
    return true;
  },
  // The panels show the selected point's tangent and weight.
  onSelect(view, id, ctx) { ctx.refresh(); },

  handles(view, model, state) {
    const out = state.points.map(([x, y], i) => ({ id: `p${i}`, x, y, label: `control point P${i}` }));
    if (state.family === 'hermite') {
      state.tangents.forEach(([tx, ty], i) => {
        const [x, y] = state.points[i];
        out.push({ id: `t${i}`, x: x + tx / 3, y: y + ty / 3, label: `tangent T${i} (handle at P${i} + T${i}/3)` });
      });
    }
    return out;
  },

  moveHandle(view, state, id, x, y) {
    const i = Number(id.slice(1));
    const rx = round(x);
    const ry = round(y);
    if (id[0] === 'p') {
      const points = state.points.slice();
      points[i] = [rx, ry];
      return { ...state, points };
    }
    if (id[0] === 't') {
      const tangents = state.tangents.slice();
      const [px, py] = state.points[i];
      tangents[i] = [round(3 * (x - px)), round(3 * (y - py))];
      return { ...state, tangents };
    }
    return null;
  },

  // One line for the History.
  summarize: (state) => {
    const pts = state.points.slice(0, 4).map(([x, y]) => `(${+x.toFixed(2)}, ${+y.toFixed(2)})`).join(' ');
    return `${state.family} curve, ${state.points.length} control points: ${pts}${state.points.length > 4 ? ' …' : ''}`;
  },
  describe(view, model, state) {
    const info = familyInfo(state.family);
    const pts = state.points.map(([x, y], i) => `P${i} (${formatNumber(x, 3)}, ${formatNumber(y, 3)})`).join(', ');
    return `${info.label}, degree ${model.degree}, ${state.points.length} control points: ${pts}. ` +
      `The point at u = ${formatNumber(model.u, 3)} is (${formatNumber(model.point[0], 4)}, ${formatNumber(model.point[1], 4)}), ` +
      `in segment ${model.segmentIndex + 1} of ${model.segment.segmentCount}.` +
      (model.construction ? ` Construction ${model.construction.kind}, step ${Math.min(state.construction.step, model.construction.steps - 1)} of ${model.construction.steps - 1}.` : '') +
      (model.comb ? ` Curvature comb on: the largest curvature is ${formatNumber(model.comb.maxCurvature, 3)}.` : '');
  },

  exports: [
    {
      label: 'Sampled points (CSV)',
      filename: 'curve-samples.csv',
      type: 'text/csv',
      make(view, model) {
        const lines = ['u,x,y'];
        for (let j = 0; j < model.params.length; j += 1) lines.push(`${model.params[j]},${model.samples[2 * j]},${model.samples[2 * j + 1]}`);
        return lines.join('\n') + '\n';
      },
    },
    {
      label: 'Blending function values (CSV)',
      filename: 'blending-functions.csv',
      type: 'text/csv',
      make(view, model, state) {
        const { count, values, params } = model.plot;
        const names = blendingLabels(state, count).map((n) => n.replace(',', '_'));
        const lines = [['u', ...names].join(',')];
        for (let j = 0; j < params.length; j += 1) {
          const row = [params[j]];
          for (let i = 0; i < count; i += 1) row.push(values[count * j + i]);
          lines.push(row.join(','));
        }
        return lines.join('\n') + '\n';
      },
    },
  ],
};


function hoveredItem(hovered, K, family) {
  if (typeof hovered !== 'string') return null;
  const i = Number(hovered.slice(1));
  if (hovered[0] === 'p') return i;
  if (hovered[0] === 't' && family === 'hermite') return K + i;
  return null;
}

function drawConstruction(painter, model, state, c) {
  const con = model.construction;
  if (!con) return;
  const step = state.construction.step;
  const halo = c.background;
  if (con.kind === 'de-casteljau' || con.kind === 'de-boor') {
    drawLevels(painter, con.levels, step, c.series, halo, con.kind === 'de-boor' ? { names: con.names, symbol: 'd' } : {});
  } else if (con.kind === 'subdivide') {
    if (step === 0) drawLevels(painter, con.levels, con.levels.length - 1, c.series, halo, {});
    else {
      drawPolygon(painter, con.left, { stroke: c.series[0], dash: [], width: 3 });
      drawPolygon(painter, con.right, { stroke: c.series[1], dash: [], width: 3 });
      con.left.forEach(([x, y], i) => { painter.circle(x, y, 5, { fill: c.series[0] }); painter.text(x, y, `L${i}`, { fill: c.series[0], font: 12, dy: 16, halo }); });
      con.right.forEach(([x, y], i) => { painter.circle(x, y, 5, { fill: c.series[1] }); painter.text(x, y, `R${i}`, { fill: c.series[1], font: 12, dy: -16, halo }); });
    }
  } else if (con.kind === 'elevate' && step >= 1) {
    drawPolygon(painter, con.points, { stroke: c.series[2], dash: [], width: 2.5 });
    con.points.forEach(([x, y], i) => { painter.circle(x, y, 6, { fill: c.series[2], stroke: halo, width: 1.5 }); painter.text(x, y, `Q${i}`, { fill: c.series[2], font: 12, dy: 18, halo }); });
  } else if (con.kind === 'insert-knot') {
    painter.circle(model.point[0], model.point[1], 11, { stroke: c.highlight, width: 2, dash: [3, 3] });
    if (step >= 1) {
      drawPolygon(painter, con.points, { stroke: c.series[2], dash: [], width: 2.5 });
      con.points.forEach(([x, y], i) => {
        const isNew = con.changed[i];
        painter.circle(x, y, isNew ? 8 : 5, { fill: isNew ? c.highlight : c.series[2], stroke: halo, width: 1.5 });
        // upper left: below are the knot labels, upper right the control point labels
        painter.text(x, y, isNew ? `Q${i} new` : `Q${i}`, { fill: isNew ? c.highlight : c.series[2], font: 12, dx: -12, dy: -14, align: 'right', halo });
      });
    }
  }
}

function drawGrid(painter, view, ctx, c) {
  const t = ctx.stage.transform();
  const [x0, y1] = t.toWorld(0, 0);
  const [x1, y0] = t.toWorld(t.width, t.height);
  const step = gridStep(view.zoom);
  for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) painter.line(x, y0, x, y1, { stroke: Math.abs(x) < 1e-9 ? c.muted : c.grid, width: 1 });
  for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) painter.line(x0, y, x1, y, { stroke: Math.abs(y) < 1e-9 ? c.muted : c.grid, width: 1 });
}

function gridStep(zoom) {
  const raw = 60 / zoom;
  const p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
}

const round = (x) => Math.round(x * 1e4) / 1e4;
export { constructionsFor, OVERLAYS, CONSTRUCTIONS, blendingLabels };
