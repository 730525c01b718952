// @ts-check
// Everything the continuity lab computes, through the core: the segments as curve objects,
// samples with first and second derivatives and curvature along the whole curve, and the
// core's classification of every joint (api.jointContinuity) with its evidence.
import { flat, linspace } from '../../app/arrays.js';

export const SAMPLES_PER_SEGMENT = 81;
// Joints are classified by the core with its default relative tolerance (1e-9,
// docs/api-curves.md): positions relative to the joint's bounding box, derivatives and
// curvatures relative to the larger of the two compared, so the verdict does not depend on
// the zoom or the size of the drawing. The constraint modes place points exactly (up to
// rounding), so it keeps their verdicts and still sees a relative difference of 1e-6.

// The curve objects of the core API, one per segment.
export function segmentCurves(family, points) {
  const curves = [];
  if (family === 'bezier') {
    for (let i = 0; i + 3 < points.length; i += 4) curves.push({ kind: 'bezier', dim: 2, points: flat(points.slice(i, i + 4)) });
  } else if (family === 'hermite') {
    for (let i = 0; i + 3 < points.length; i += 4) {
      curves.push({ kind: 'hermite', dim: 2, points: flat(points.slice(i, i + 2)), tangents: flat(points.slice(i + 2, i + 4)) });
    }
  } else {
    // Uniform B-spline and Catmull-Rom: segment i is the window P_i..P_i+3 (lecture 003).
    for (let i = 0; i + 3 < points.length; i += 1) curves.push({ kind: family, dim: 2, points: flat(points.slice(i, i + 4)) });
  }
  return curves;
}

// One segment sampled: points, P', P'' and curvature at SAMPLES_PER_SEGMENT parameters.
function sampleSegment(api, curve, index) {
  const domain = api.curveDomain(curve);
  const params = linspace(domain.start, domain.end, SAMPLES_PER_SEGMENT);
  const all = api.evaluateWithDerivatives(curve, params, 2);
  const n = params.length;
  const points = new Float64Array(2 * n);
  const d1 = new Float64Array(2 * n);
  const d2 = new Float64Array(2 * n);
  for (let j = 0; j < n; j += 1) {
    for (let c = 0; c < 2; c += 1) {
      points[2 * j + c] = all[6 * j + c];
      d1[2 * j + c] = all[6 * j + 2 + c];
      d2[2 * j + c] = all[6 * j + 4 + c];
    }
  }
  const k = api.curvature(curve, params);
  // The global parameter of the lab: segment i runs over [i, i + 1].
  const u = params.map((t) => index + (t - domain.start) / (domain.end - domain.start));
  // Where P' = 0 the curvature is undefined (the core's singular flag): NaN here, so the plot
  // leaves a gap and names the place instead of drawing the stored 0.
  const curvature = Float64Array.from(k.curvature, (v, j) => (k.singular[j] ? Number.NaN : v));
  const undefinedAt = [];
  for (let j = 0; j < n; j += 1) if (k.singular[j]) undefinedAt.push({ u: u[j], speed: k.speed[j] });
  return { curve, domain, params, u, points, d1, d2, curvature, speed: k.speed, undefinedAt };
}

export function computeModel(api, state) {
  const curves = segmentCurves(state.family, state.points);
  if (curves.length < 2) throw Object.assign(new Error('The continuity lab needs at least two segments to have a joint.'), { code: 'too-few-segments' });
  const segments = curves.map((c, i) => sampleSegment(api, c, i));
  const joints = [];
  for (let j = 1; j < segments.length; j += 1) {
    const a = segments[j - 1];
    const b = segments[j];
    const verdict = api.jointContinuity(a.curve, b.curve);
    const e = verdict.evidence;
    // e.a / e.b hold [P, P', P''] of each side at the joint (2 numbers each).
    // curvature is null where that side's P' = 0 (undefined, never 0).
    const side = (d, curvature, speed) => ({ point: [d[0], d[1]], d1: [d[2], d[3]], d2: [d[4], d[5]], curvature, speed });
    joints.push({
      index: j,
      u: j,
      parametric: verdict.parametric,
      geometric: verdict.geometric,
      ratio: e.ratio,
      positionGap: e.positionGap,
      relativeGap: e.relativeGap,
      zeroTangent: e.zeroTangent,
      tangentAngle: e.tangentAngle,
      notes: e.notes,
      wordings: verdict.wordings,
      left: side(e.a, e.curvatureA, a.speed[SAMPLES_PER_SEGMENT - 1]),
      right: side(e.b, e.curvatureB, b.speed[0]),
    });
  }
  // The travelling point at the global parameter u.
  const s = Math.min(segments.length - 1, Math.floor(state.u));
  const seg = segments[s];
  const t = seg.domain.start + (state.u - s) * (seg.domain.end - seg.domain.start);
  const at = api.evaluateWithDerivatives(seg.curve, [t], 1);
  const traveller = { segment: s, t, point: [at[0], at[1]], velocity: [at[2], at[3]] };
  return { segments, joints, traveller, segmentCount: segments.length };
}

