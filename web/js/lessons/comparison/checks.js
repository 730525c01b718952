// @ts-check
// The comparison tables of lectures 001 and 003. A cell states a guarantee of the
// representation, so it is checked for EVERY polygon: the core's
// structural argument on the family's construction (continuity and interpolation from the
// basis matrices or knots, api.chainGuarantees / api.bsplineGuarantees) and the blending
// weights (convex hull, the same for every polygon). Beside each cell, what THIS polygon
// happens to do: distances from the control points to the sampled curve, the joint
// classifier on the drawn curves, subdivision checked against the original. "Ease of
// subdivision" is the lecture's judgement: quoted, never checked.
import { linspace, flat } from '../../app/arrays.js';
import { formatSize as fmt } from '../../ui/format.js';
import { FAMILY_IDS, familySegments, inherentSegments, easySegments, nubsCurve, nonUniformKnots, constructionOf, pointTangents } from './families.js';

// The measurements are the core's (api.blendingWeightCheck, api.pointCurveDistances,
// api.splitCheck, api.knotRefinementCheck), with their tolerances relative to the size of the
// polygon (docs/api-curves.md "Comparison measurements"); this module words them.
export const SAMPLES_PER_SEGMENT = 101;
// Relative tolerance of the core's joint classifier (api.jointContinuity).
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

function convexHullCell(api, sampled) {
  const w = api.blendingWeightCheck(sampled.map((s) => s.curve), SAMPLES_PER_SEGMENT);
  // Hermite: H2 and H3 multiply tangent vectors, not points: a hull of points does not apply.
  if (!w.weightsPoints) return { answer: 'N/A', evidence: `H2, H3 weight tangent vectors (up to ${fmt(w.tangentWeight)}), not points` };
  return w.convexHull
    ? { answer: 'Yes', evidence: `weights ≥ 0 (min ${fmt(Math.max(0, w.minWeight))}), sum 1 (off by ${fmt(w.sumError)})` }
    : { answer: 'No', evidence: `a weight reaches ${fmt(w.minWeight)} < 0` };
}

// Distance from each control point to the nearest sample of the curve (segment ends
// included exactly), and the points within the core's interpolation tolerance.
export function controlPointDistances(api, points, sampled) {
  return api.pointCurveDistances(flat(points), 2, sampled.map((s) => s.curve), SAMPLES_PER_SEGMENT);
}

// What this polygon does: the control points its curve passes through (within the core's
// tolerance, relative to the polygon's size), whether or not the representation guarantees it.
function polygonInterpolation(api, points, sampled) {
  const m = controlPointDistances(api, points, sampled);
  const d = Array.from(m.distances);
  const hit = Array.from(m.interpolated);
  const some = hit.length ? { answer: 'Yes', evidence: `through P${hit.join(', P')}` } : { answer: 'No', evidence: `nearest P${m.nearestMissed} is ${fmt(d[m.nearestMissed])} away` };
  const all = hit.length === points.length ? { answer: 'Yes', evidence: 'through every point' } : { answer: 'No', evidence: `P${m.farthest} is ${fmt(d[m.farthest])} away` };
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
  const k = api.knotRefinementCheck(sampled[0].curve, SAMPLES_PER_SEGMENT);
  return { answer: LECTURE_TABLE.subdivision.nubs, quoted: true, evidence: `${k.inserted} knots inserted (Boehm), ${k.pointsBefore} → ${k.pointsAfter} points; curve moved ${fmt(k.error)}`, error: k.error };
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
  const { error } = api.splitCheck(sampled.map((s) => s.curve));
  const how = family === 'bezier' ? 'lecture 002\'s left and right subdivision matrices (1/8 [integers]) times P directly'
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
// tangents: Hermite's own tangents (one [x, y] per point), or null for Catmull-Rom's.
export function computeTable(api, points, tangents = null) {
  const columns = {};
  const polygon = {};
  const curves = {};
  const K = points.length;
  for (const family of FAMILY_IDS) {
    const segs = familySegments(api, family, points, tangents);
    const sampled = sampleSegments(api, segs);
    curves[family] = sampled;
    const seen = polygonInterpolation(api, points, sampled);
    const how = family === 'nubs' ? 'from the knots' : 'from the basis matrix';
    const inherentG = guaranteesOf(api, family, K);
    // Hermite and Bezier have a rule for more; B-splines and Catmull-Rom need none.
    const hasRule = family === 'hermite' || family === 'bezier';
    const easyG = hasRule ? guaranteesOf(api, family, K, true) : inherentG;
    // The drawn Hermite curve shares tangents (the easy construction); the others are drawn bare.
    const interp = guaranteedInterpolation(family === 'hermite' ? easyG : inherentG, K);
    const subdivision = subdivisionCell(api, family, sampled);
    const inherentSeen = continuityCell(api, family === 'nubs' ? spanCurves(api, nubsCurve(points)) : inherentSegments(api, family, points));
    columns[family] = {
      convexHull: convexHullCell(api, sampled),
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
      easy: hasRule ? continuityCell(api, easySegments(api, family, points)) : inherentSeen,
    };
  }
  return { columns, polygon, curves, knots: nonUniformKnots(K), tangents: tangents ?? pointTangents(api, points) };
}
