// The comparison tables of lectures 001 and 003. A cell states a guarantee of the
// representation, so it is checked for EVERY polygon (issue 13 item 8): the core's
// structural argument on the family's construction (continuity and interpolation from the
// basis matrices or knots, api.chainGuarantees / api.bsplineGuarantees) and the blending
// weights (convex hull, the same for every polygon). Beside each cell, what THIS polygon
// happens to do: distances from the control points to the sampled curve, the joint
// classifier on the drawn curves, subdivision checked against the original. "Ease of
// subdivision" is the lecture's judgement: quoted, never checked.
import { linspace } from '../../app/arrays.js';
import { formatSize as fmt } from '../../ui/format.js';
import { FAMILY_IDS, familySegments, inherentSegments, easySegments, nubsCurve, nonUniformKnots, constructionOf } from './families.js';

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
    // H2 and H3 multiply tangent vectors, not points: measured, a hull of points does not apply.
    const b = api.blendingFunctions(sampled[0].curve, sampled[0].params);
    let tangentWeight = 0;
    for (let j = 0; j < sampled[0].params.length; j += 1) {
      for (const i of [2, 3]) tangentWeight = Math.max(tangentWeight, Math.abs(b.values[b.count * j + i]));
    }
    if (tangentWeight > WEIGHT_TOLERANCE) return { answer: 'N/A', evidence: `H2, H3 weight tangent vectors (up to ${fmt(tangentWeight)}), not points` };
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

// What this polygon does: the control points its curve passes through (within
// INTERPOLATION_TOLERANCE), whether or not the representation guarantees it.
function polygonInterpolation(points, sampled) {
  const d = controlPointDistances(points, sampled);
  const hit = d.map((x, i) => (x <= INTERPOLATION_TOLERANCE ? i : -1)).filter((i) => i >= 0);
  const farIndex = d.reduce((best, x, i) => (x > d[best] ? i : best), 0);
  const nearMiss = d.reduce((best, x, i) => (x > INTERPOLATION_TOLERANCE && (best < 0 || x < d[best]) ? i : best), -1);
  const some = hit.length ? { answer: 'Yes', evidence: `through P${hit.join(', P')}` } : { answer: 'No', evidence: `nearest P${nearMiss} is ${fmt(d[nearMiss])} away` };
  const all = hit.length === points.length ? { answer: 'Yes', evidence: 'through every point' } : { answer: 'No', evidence: `P${farIndex} is ${fmt(d[farIndex])} away` };
  return { some: { ...some, interpolated: hit }, all: { ...all, interpolated: hit }, distances: d };
}

// The guarantee: the control points every polygon's curve passes through (the core finds the
// slots whose basis function is 1 at a segment end, or at a knot).
function guaranteedInterpolation(g, count) {
  const hit = g.interpolated.filter((j) => j < count);
  const some = hit.length
    ? { answer: 'Yes', evidence: `every polygon: P${hit.join(', P')} (a basis function is 1 there)`, interpolated: hit }
    : { answer: 'No', evidence: 'no basis function reaches 1 at a joint: no point is guaranteed', interpolated: hit };
  const all = hit.length === count
    ? { answer: 'Yes', evidence: 'every polygon: every point', interpolated: hit }
    : { answer: 'No', evidence: `not guaranteed for ${count - hit.length} of ${count} points`, interpolated: hit };
  return { some, all };
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
  return { answer: LECTURE_TABLE.subdivision.nubs, quoted: true, evidence: `${spans.length} knots inserted (Boehm), ${s.curve.points.length / 2} → ${curve.points.length / 2} points; curve moved ${fmt(error)}`, error };
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
  return { answer: LECTURE_TABLE.subdivision[family], quoted: true, evidence: `${how}; halves match to ${fmt(error)}`, error };
}

// What this polygon does at its joints: the core's classifier on the drawn segments.
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
  return { answer: `C${cLabel(parametric)} G${cLabel(geometric)}`, evidence: `this polygon, weakest of ${segs.length - 1} joint${segs.length === 2 ? '' : 's'}`, parametric, geometric };
}

// The guarantee at every joint, for every polygon (the core's structural argument).
function guaranteedContinuity(g, how) {
  if (g.joints === 0) return { answer: '—', evidence: 'one segment: no joint', parametric: null, geometric: null };
  return { answer: `C${cLabel(g.parametric)} G${cLabel(g.geometric)}`, evidence: `${how}, for every polygon: weakest of ${g.joints} joint${g.joints === 1 ? '' : 's'}`,
    parametric: g.parametric, geometric: g.geometric };
}

function guaranteesOf(api, family, count, easy = false) {
  return family === 'nubs' ? api.bsplineGuarantees(constructionOf('nubs', count)) : api.chainGuarantees(constructionOf(family, count, { easy }));
}

// columns[family][row]: the guarantee (answer, evidence; quoted: true for the lecture's own
// judgement); polygon[family][row]: what this polygon does.
export function computeTable(api, points) {
  const columns = {};
  const polygon = {};
  const curves = {};
  const K = points.length;
  for (const family of FAMILY_IDS) {
    const segs = familySegments(family, points);
    const sampled = sampleSegments(api, segs);
    curves[family] = sampled;
    const seen = polygonInterpolation(points, sampled);
    const how = family === 'nubs' ? 'from the knots' : 'from the basis matrix';
    const inherentG = guaranteesOf(api, family, K);
    // Hermite and Bezier have a rule for more; B-splines and Catmull-Rom need none.
    const hasRule = family === 'hermite' || family === 'bezier';
    const easyG = hasRule ? guaranteesOf(api, family, K, true) : inherentG;
    // The drawn Hermite curve shares tangents (the easy construction); the others are drawn bare.
    const interp = guaranteedInterpolation(family === 'hermite' ? easyG : inherentG, K);
    const subdivision = subdivisionCell(api, family, sampled);
    const inherentSeen = continuityCell(api, family === 'nubs' ? spanCurves(api, nubsCurve(points)) : inherentSegments(family, points));
    columns[family] = {
      convexHull: convexHullCell(api, family, sampled),
      interpolatesSome: interp.some,
      interpolatesAll: interp.all,
      subdivision,
      inherent: guaranteedContinuity(inherentG, how),
      easy: guaranteedContinuity(easyG, hasRule ? `${how} with the rule` : `${how} (no rule needed)`),
      distances: seen.distances,
    };
    polygon[family] = {
      convexHull: { answer: '—', evidence: 'the weights do not depend on the polygon' },
      interpolatesSome: seen.some,
      interpolatesAll: seen.all,
      subdivision: { answer: fmt(subdivision.error), evidence: 'largest distance between the split halves and the curve' },
      inherent: inherentSeen,
      easy: hasRule ? continuityCell(api, easySegments(family, points)) : inherentSeen,
    };
  }
  return { columns, polygon, curves, knots: nonUniformKnots(K) };
}
