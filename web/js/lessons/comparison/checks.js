// The comparison tables of lectures 001 and 003, every cell measured on the current curves
// by the core: blending weights (convex hull), distances from the control points to the
// sampled curve (interpolation), subdivision checked against the original, and the joint
// classifier on the inherent and the easily-achieved construction.
import { FAMILY_IDS, familySegments, inherentSegments, easySegments, nubsCurve, nonUniformKnots } from './families.js';

export const SAMPLES_PER_SEGMENT = 101;
// A control point counts as interpolated when the curve passes within this distance
// (world units; the drawing spans about 8 units, so this is far below a pixel).
export const INTERPOLATION_TOLERANCE = 1e-9;
// Blending weights count as non-negative / summing to one within this tolerance (unitless).
export const WEIGHT_TOLERANCE = 1e-12;
export const JOINT_TOLERANCE = 1e-6;

// Lecture 003's table (Hermite, Bezier, B-spline, Catmull-Rom): the reference each live
// cell is compared with. These are the lecture's words, not results.
// The non-uniform B-spline column is lecture 001's.
export const LECTURE_TABLE = {
  convexHull: { hermite: 'N/A', bezier: 'Yes', bspline: 'Yes', 'catmull-rom': 'No', nubs: 'Yes' },
  interpolatesSome: { hermite: 'Yes', bezier: 'Yes', bspline: 'No', 'catmull-rom': 'Yes', nubs: 'No' },
  interpolatesAll: { hermite: 'Yes', bezier: 'No', bspline: 'No', 'catmull-rom': 'Yes', nubs: 'No' },
  subdivision: { hermite: 'Good', bezier: 'Best', bspline: 'Avg', 'catmull-rom': 'Avg', nubs: 'High' },
  inherent: { hermite: 'C0 G0', bezier: 'C0 G0', bspline: 'C2 G2', 'catmull-rom': 'C1 G1', nubs: 'C2 G2' },
  easy: { hermite: 'C1 G1', bezier: 'C1 G1', bspline: 'C2 G2', 'catmull-rom': 'C1 G1', nubs: 'C2 G2' },
};
export const ROW_NAMES = {
  convexHull: 'Convex hull property',
  interpolatesSome: 'Interpolates some control points',
  interpolatesAll: 'Interpolates all control points',
  subdivision: 'Ease of subdivision',
  inherent: 'Inherent continuity',
  easy: 'Easily achieved continuity',
};

export function linspace(a, b, n) {
  const out = new Float64Array(n);
  for (let j = 0; j < n; j += 1) out[j] = a + ((b - a) * j) / (n - 1);
  out[n - 1] = b;
  return out;
}

const fmt = (x) => (x === 0 ? '0.0' : Math.abs(x) < 1e-3 ? x.toExponential(1) : String(Number(x.toPrecision(3))));
const cLabel = (k) => (k < 0 ? '-1' : String(k));

export function sampleSegments(api, segs) {
  return segs.map((curve) => {
    const d = api.curveDomain(curve);
    const params = linspace(d.start, d.end, SAMPLES_PER_SEGMENT);
    return { curve, params, points: api.evaluateCurve(curve, params) };
  });
}

function convexHullCell(api, family, sampled) {
  if (family === 'hermite') {
    // H2 and H3 multiply tangent vectors, not points: there is no hull of points to speak of.
    const b = api.blendingFunctions(sampled[0].curve, sampled[0].params);
    let tangentWeight = 0;
    for (let j = 0; j < sampled[0].params.length; j += 1) tangentWeight = Math.max(tangentWeight, Math.abs(b.values[b.count * j + 2]));
    return { answer: 'N/A', evidence: `H2, H3 weight tangent vectors (up to ${fmt(tangentWeight)}), not points` };
  }
  let minWeight = Infinity;
  let sumError = 0;
  for (const s of sampled) {
    const b = api.blendingFunctions(s.curve, s.params);
    for (let j = 0; j < s.params.length; j += 1) {
      let sum = 0;
      for (let i = 0; i < b.count; i += 1) { const w = b.values[b.count * j + i]; sum += w; minWeight = Math.min(minWeight, w); }
      sumError = Math.max(sumError, Math.abs(sum - 1));
    }
  }
  const yes = minWeight >= -WEIGHT_TOLERANCE && sumError <= WEIGHT_TOLERANCE;
  return yes
    ? { answer: 'Yes', evidence: `weights ≥ 0 (min ${fmt(Math.max(0, minWeight))}), sum 1 (off by ${fmt(sumError)})` }
    : { answer: 'No', evidence: `a weight reaches ${fmt(minWeight)} < 0` };
}

// Distance from each control point to the nearest sample (segment ends included exactly).
export function controlPointDistances(points, sampled) {
  return points.map(([x, y]) => {
    let best = Infinity;
    for (const s of sampled) for (let j = 0; j < s.points.length; j += 2) best = Math.min(best, Math.hypot(s.points[j] - x, s.points[j + 1] - y));
    return best;
  });
}

function interpolationCells(points, sampled) {
  const d = controlPointDistances(points, sampled);
  const hit = d.map((x, i) => (x <= INTERPOLATION_TOLERANCE ? i : -1)).filter((i) => i >= 0);
  const missIndex = d.reduce((best, x, i) => (x > INTERPOLATION_TOLERANCE && (best < 0 || x < d[best]) ? i : best), -1);
  const maxHit = hit.reduce((m, i) => Math.max(m, d[i]), 0);
  const some = hit.length > 0
    ? { answer: 'Yes', evidence: `P${hit.join(', P')} (distance ${fmt(maxHit)})`, interpolated: hit }
    : { answer: 'No', evidence: `nearest P${missIndex} is ${fmt(d[missIndex])} away`, interpolated: hit };
  const farIndex = d.reduce((best, x, i) => (x > d[best] ? i : best), 0);
  const all = hit.length === points.length
    ? { answer: 'Yes', evidence: `distance ${fmt(maxHit)} at every point`, interpolated: hit }
    : { answer: 'No', evidence: `P${farIndex} is ${fmt(d[farIndex])} away`, interpolated: hit };
  return { some, all, distances: d };
}

// The non-uniform B-spline refines by knot insertion (Boehm, lecture 001 "a knot can be
// inserted so the curve can easily be reshaped"): one knot in the middle of every span,
// and the refined curve must be the same curve.
function knotInsertionCell(api, sampled) {
  const s = sampled[0];
  let curve = s.curve;
  const spans = api.bsplineToBezier(curve);
  for (const span of spans) curve = api.insertKnot(curve, (span.start + span.end) / 2).curve;
  const refined = api.evaluateCurve(curve, s.params);
  let error = 0;
  for (let j = 0; j < refined.length; j += 2) error = Math.max(error, Math.hypot(refined[j] - s.points[j], refined[j + 1] - s.points[j + 1]));
  return { answer: LECTURE_TABLE.subdivision.nubs, evidence: `${spans.length} knots inserted (Boehm), ${s.curve.points.length / 2} → ${curve.points.length / 2} points; curve moved ${fmt(error)}`, error };
}

// The spans of the non-uniform B-spline as separate curves over their own knot intervals
// (clamped cubics with knots a,a,a,a,b,b,b,b), so the classifier compares derivatives in
// the curve's own parameter t, not in a local u per span.
function spanCurves(api, curve) {
  return api.bsplineToBezier(curve).map((b) => ({ kind: 'bspline', dim: 2, degree: 3, points: b.points,
    knots: [b.start, b.start, b.start, b.start, b.end, b.end, b.end, b.end] }));
}

// Splits every segment at u = 1/2 and measures how far the halves are from the original.
function subdivisionCell(api, family, sampled) {
  if (family === 'nubs') return knotInsertionCell(api, sampled);
  let error = 0;
  const quarter = [0, 0.25, 0.5, 0.75, 1];
  for (const s of sampled) {
    let bezier;
    if (family === 'bezier') bezier = s.curve.points;
    else if (family === 'hermite') bezier = api.convertBasis([...s.curve.points, ...s.curve.tangents], 2, 'hermite', 'bezier');
    else bezier = api.convertBasis(s.curve.points, 2, family, 'bezier');
    const halves = api.subdivideBezier(bezier, 2, 0.5);
    const left = api.evaluateCurve({ kind: 'bezier', dim: 2, points: halves.left }, quarter);
    const right = api.evaluateCurve({ kind: 'bezier', dim: 2, points: halves.right }, quarter);
    const d = api.curveDomain(s.curve);
    const at = (f) => d.start + f * (d.end - d.start);
    const original = api.evaluateCurve(s.curve, [...quarter.map((q) => at(q / 2)), ...quarter.map((q) => at(0.5 + q / 2))]);
    for (let j = 0; j < 5; j += 1) {
      error = Math.max(error, Math.hypot(left[2 * j] - original[2 * j], left[2 * j + 1] - original[2 * j + 1]),
        Math.hypot(right[2 * j] - original[10 + 2 * j], right[2 * j + 1] - original[10 + 2 * j + 1]));
    }
  }
  const how = family === 'bezier' ? 'G_B^L P and G_B^R P directly'
    : family === 'hermite' ? 'to Bezier (q = M_B⁻¹ M_H g), then split' : 'to Bezier (q = M_B⁻¹ M P) first, then split';
  return { answer: LECTURE_TABLE.subdivision[family], evidence: `${how}; halves match to ${fmt(error)}`, error };
}

function continuityCell(api, segs) {
  // One segment has no joint: nothing to measure, and no claim is made.
  if (segs.length < 2) return { answer: '—', evidence: 'one segment: no joint to measure', parametric: null, geometric: null };
  let parametric = 2;
  let geometric = 2;
  for (let i = 1; i < segs.length; i += 1) {
    const v = api.jointContinuity(segs[i - 1], segs[i], { tolerance: JOINT_TOLERANCE });
    parametric = Math.min(parametric, v.parametric);
    geometric = Math.min(geometric, v.geometric);
  }
  return { answer: `C${cLabel(parametric)} G${cLabel(geometric)}`, evidence: `weakest of ${segs.length - 1} joint${segs.length === 2 ? '' : 's'}`, parametric, geometric };
}

export function computeTable(api, points) {
  const columns = {};
  const curves = {};
  for (const family of FAMILY_IDS) {
    const segs = familySegments(family, points);
    const sampled = sampleSegments(api, segs);
    curves[family] = sampled;
    const interp = interpolationCells(points, sampled);
    const inherent = continuityCell(api, family === 'nubs' ? spanCurves(api, nubsCurve(points)) : inherentSegments(family, points));
    columns[family] = {
      convexHull: convexHullCell(api, family, sampled),
      interpolatesSome: interp.some,
      interpolatesAll: interp.all,
      subdivision: subdivisionCell(api, family, sampled),
      inherent,
      // B-splines and Catmull-Rom need no rule: their easy construction is the inherent one.
      easy: family === 'bspline' || family === 'catmull-rom' || family === 'nubs' ? inherent : continuityCell(api, easySegments(family, points)),
      distances: interp.distances,
    };
  }
  return { columns, curves, knots: nonUniformKnots(points.length) };
}
