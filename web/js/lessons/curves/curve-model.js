// @ts-check
// compute(): every number the curve explorer shows comes from the wasm core through this
// module (the lesson's `compute`). The result is a plain model the drawing and the panels
// read; nothing here draws. One core call per curve and purpose (batch API): the samples,
// the blending values at the same parameters, the derivatives at u, the segment matrices.
import { curveSpec, familyDegree, isSpline, usesKnots } from './families.js';
import { linspace, pairs, flat } from '../../app/arrays.js';

export const SAMPLES_PER_CURVE = 1000;
const COMB_SAMPLES = 120;
// One blending call serves the plot and the influence tint (the tint maps each curve sample
// to the plot parameter at the same fraction of the domain; both are uniform in u).
const PLOT_PARAMS = 250;

// The parameters are uniform in the parameter (linspace), as the lecture samples a curve
// (the sample-points overlay shows how uneven that is along the curve).
const uniformParams = linspace;

// The convex hull of control points (the hull overlay, lectures 001 and 003: a Bezier or
// B-spline curve lies inside it): the core's hull, counter-clockwise, as [x, y] pairs.
const convexHull = (api, points) => Array.from(api.convexHull(flat(points)).indices, (i) => points[i]);

// The lesson's model cache (kept in its view, one per page): the parts that depend only on
// the curve (not on u, the overlays or the construction step), so playing u or stepping a
// construction costs no resampling. The samples go into one of two reused buffers (the core
// fills them: no garbage per pointer move); the one the current model holds is never the
// one being written.
export function createModelCache() {
  return {
    key: null,
    value: null,
    sampleBuffers: [new Float64Array(2 * SAMPLES_PER_CURVE), new Float64Array(2 * SAMPLES_PER_CURVE)],
    nextSampleBuffer: 0,
  };
}

function curvePart(api, state, spec, cache) {
  const key = JSON.stringify([state.family, state.points, state.tangents, state.knots, state.weights, state.degree, state.tension]);
  if (cache.key === key) return cache.value;
  const domain = api.curveDomain(spec);
  const sameDomain = cache.value && cache.value.domain.start === domain.start && cache.value.domain.end === domain.end;
  const params = sameDomain ? cache.value.params : uniformParams(domain.start, domain.end, SAMPLES_PER_CURVE);
  const curve = api.evaluateCurve(spec, params, { out: cache.sampleBuffers[cache.nextSampleBuffer] });
  cache.nextSampleBuffer = 1 - cache.nextSampleBuffer;
  const plotParams = sameDomain ? cache.value.plotParams : uniformParams(domain.start, domain.end, PLOT_PARAMS);
  const blending = api.blendingFunctions(spec, plotParams);
  const value = { domain, params, curve, plotParams, blending };
  cache.key = key;
  cache.value = value;
  return value;
}

// The knots as the core reports them: the whole vector (a uniform B-spline's implicit t_j =
// j - p included) and each distinct value with its multiplicity m, the index of its first
// copy and the continuity C^(p-m) there.
function knotModel(api, spec, domain) {
  const r = api.knotMultiplicities(spec);
  const groups = Array.from(r.values, (value, k) => ({
    value, multiplicity: r.multiplicities[k], firstIndex: r.firstIndices[k], interior: r.interior[k] === 1, continuity: r.continuity[k],
  }));
  const inside = groups.filter((g) => g.value >= domain.start && g.value <= domain.end);
  const positions = api.evaluateCurve(spec, Float64Array.from(inside.map((g) => g.value)));
  return { values: Array.from(r.knots), groups, inside, positions };
}

export function computeCurveModel(api, state, cache) {
  const spec = curveSpec(state);
  const part = curvePart(api, state, spec, cache);
  const { domain } = part;
  const degree = familyDegree(state);
  const u = Math.min(Math.max(state.u, domain.start), domain.end);
  // P, P', P'' at u in one pass: values[2k + c] is component c of the k-th derivative.
  const pd = api.evaluateWithDerivatives(spec, Float64Array.of(u), 2);
  const segmentIndex = api.segmentAt(spec, u);
  const segment = api.segmentMatrices(spec, segmentIndex, { form: state.form });

  const model = {
    spec,
    family: state.family,
    degree,
    domain,
    u,
    samples: part.curve,
    params: part.params,
    plot: { params: part.plotParams, count: part.blending.count, values: part.blending.values },
    point: [pd[0], pd[1]],
    d1: [pd[2], pd[3]],
    d2: [pd[4], pd[5]],
    segment,
    segmentIndex,
    hull: convexHull(api, state.points),
    segmentHull: convexHull(api, segmentPointIndices(segment, state).map((i) => state.points[i])),
    knots: null,
    comb: null,
    construction: null,
    compare: null,
    homogeneous: null,
  };

  if (isSpline(state.family)) {
    model.knots = knotModel(api, spec, domain);
    // Lecture 002's {0,0,0,0,1,1,1,1}: this B-spline is its points' Bezier curve.
    model.bezierInDisguise = usesKnots(state.family) && api.isBezierInDisguise(Float64Array.from(state.knots), state.degree);
  } else {
    // Segment joints: the curve at the segment boundaries of the piecewise families.
    const n = domain.segmentCount ?? 1;
    const joints = uniformParams(domain.start, domain.end, n + 1);
    model.joints = { params: joints, positions: api.evaluateCurve(spec, joints) };
  }

  if (state.overlays.comb) model.comb = curvatureComb(api, spec, domain);
  if (state.family === 'interpolation' && state.compare) model.compare = interpolatingSpline(api, state);
  if (state.family === 'nurbs') model.homogeneous = homogeneousView(api, state, spec, part, u);
  model.construction = construction(api, state, spec, u, degree);
  return model;
}

function segmentPointIndices(segment, state) {
  const ids = segment.controlIndices ? Array.from(segment.controlIndices) : [];
  const K = state.points.length;
  // Hermite rows 2 and 3 are tangents, not points: their indices are not hull points.
  if (state.family === 'hermite') return ids.slice(0, 2).filter((i) => i >= 0 && i < K);
  return ids.filter((i) => i >= 0 && i < K);
}

// The comb (lecture 004), from the core: at each sample a tooth along the left normal
// (-t_y, t_x) of the unit tangent, of length the signed curvature, so the teeth stand on the
// concave side (the side the curve turns to). At a cusp the tooth has length 0, never NaN.
function curvatureComb(api, spec, domain) {
  const c = api.curvatureComb(spec, uniformParams(domain.start, domain.end, COMB_SAMPLES));
  return { teeth: c.teeth, maxCurvature: c.maxCurvature, count: COMB_SAMPLES, singular: c.singular };
}

// Lecture 004's comparison: the same points through one cubic spline. Catmull-Rom with the
// end points doubled runs through every point, each piece a cubic.
function interpolatingSpline(api, state) {
  const pts = state.points;
  const doubled = [pts[0], ...pts, pts[pts.length - 1]];
  const spec = { kind: 'catmull-rom', dim: 2, points: Float64Array.from(doubled.flat()) };
  const domain = api.curveDomain(spec);
  const samples = api.evaluateCurve(spec, uniformParams(domain.start, domain.end, SAMPLES_PER_CURVE));
  return { spec, samples };
}

// The NURBS as the shadow of a polynomial B-spline in 3D: control points (w x, w y, w), the
// same knots; its points divided by w give the rational curve (lectures 001, 002).
function homogeneousView(api, state, spec, part, u) {
  const h = api.homogeneousLift(spec.points, 2, state.weights);
  const lifted = Array.from({ length: h.length / 3 }, (_, i) => [h[3 * i], h[3 * i + 1], h[3 * i + 2]]);
  const spec3 = { kind: 'bspline', dim: 3, degree: state.degree, knots: spec.knots, points: h };
  const params = uniformParams(part.domain.start, part.domain.end, 200);
  const curve3 = api.evaluateCurve(spec3, params);
  const at = api.evaluateCurve(spec3, Float64Array.of(u));
  return { lifted, curve3, at: [at[0], at[1], at[2]], projected: state.points };
}

// The construction being shown: computed whole, drawn up to the current step.
function construction(api, state, spec, u, degree) {
  const c = state.construction;
  if (c.kind === 'none' || !constructionsFor(state.family, api).includes(c.kind)) return null;
  const K = state.points.length;
  if (c.kind === 'de-casteljau' && state.family === 'bezier') {
    const r = api.deCasteljau(spec.points, 2, u);
    return { kind: c.kind, levels: r.levels.map((l) => pairs(l)), steps: r.levels.length };
  }
  if (c.kind === 'de-boor' && isSpline(state.family)) {
    // Entry j of level r is d_(firstIndex + r + j)^r (the core's numbering); level 0 is
    // P_(span-p)..P_span, the p + 1 points that act on this span.
    const r = api.deBoor(spec, u);
    const names = r.levels.map((level, lv) => pairs(level).map((_, j) => r.firstIndex + lv + j));
    return { kind: c.kind, levels: r.levels.map((l) => pairs(l)), names, span: r.span, firstIndex: r.firstIndex, alphas: r.alphas, steps: r.levels.length };
  }
  if (c.kind === 'subdivide' && state.family === 'bezier') {
    const r = api.deCasteljau(spec.points, 2, u);
    const s = api.subdivideBezier(spec.points, 2, u);
    return { kind: c.kind, levels: r.levels.map((l) => pairs(l)), left: pairs(s.left), right: pairs(s.right), steps: 2 };
  }
  if (c.kind === 'elevate' && state.family === 'bezier') {
    const r = api.elevateDegree(spec.points, 2);
    return { kind: c.kind, points: pairs(r.points), degree: K, steps: 2 };
  }
  if (c.kind === 'insert-knot' && usesKnots(state.family)) {
    // Boehm (lecture 002): the core says which points are new (0 < a_i < 1); the others
    // are the old points, renumbered after the insertion.
    const r = api.insertKnot(spec, u);
    const points = pairs(r.curve.points);
    const changed = points.map(() => false);
    for (const i of r.newPoints) changed[i] = true;
    return {
      kind: c.kind, points, knots: Array.from(r.curve.knots), weights: r.curve.weights?.length ? Array.from(r.curve.weights) : null,
      changed, newPoints: Array.from(r.newPoints), insertedIndex: r.insertedIndex, at: u, steps: 2,
    };
  }
  return null;
}

// Which construction kinds a family offers (those the loaded core provides: the page
// follows the core's API as it grows).
const CONSTRUCTION_CALLS = { 'de-casteljau': 'deCasteljau', subdivide: 'subdivideBezier', elevate: 'elevateDegree', 'de-boor': 'deBoor', 'insert-knot': 'insertKnot' };
export function constructionsFor(family, api) {
  let kinds = [];
  if (family === 'bezier') kinds = ['de-casteljau', 'subdivide', 'elevate'];
  else if (family === 'bspline' || family === 'nurbs') kinds = ['de-boor', 'insert-knot'];
  else if (family === 'bspline-uniform') kinds = ['de-boor'];
  return kinds.filter((k) => typeof api?.[CONSTRUCTION_CALLS[k]] === 'function');
}
