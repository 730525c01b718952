// @ts-check
// Basis conversion (lecture 002: q = M^-1 M_B P) and invariance (lecture 001 "Invariance")
// on the current polygon. The maps applied to points are the experiment's input; the
// curves before and after are evaluated, mapped and compared by the core.
import { familySegments, FAMILY_IDS } from './families.js';
import { linspace, flat, pairs } from '../../app/arrays.js';

const SAMPLES = 121;
const MID = 60; // the sample at u = 1/2, where the matrix panels evaluate

export function segmentCurve(kind, g) {
  return kind === 'hermite'
    ? { kind: 'hermite', dim: 2, points: g.slice(0, 4), tangents: g.slice(4, 8) }
    : { kind, dim: 2, points: g };
}

const maxDistance = (api, a, b) => api.maxDistance(a, b, 2).distance;

export function computeConversion(api, points, { from, to, start, mode }, form = 'descending') {
  const g = flat(points.slice(start, start + 4));
  const params = linspace(0, 1, SAMPLES);
  const original = api.evaluateCurve(segmentCurve(from, g), params);
  if (mode === 'keep-curve') {
    const q = api.convertBasis(g, 2, from, to);
    const converted = api.evaluateCurve(segmentCurve(to, Array.from(q)), params);
    return { mode, from, to, g, q, original, other: converted, distance: maxDistance(api, original, converted),
      Mfrom: api.basisMatrix(from), Mto: api.basisMatrix(to),
      segmentFrom: api.segmentMatrices(segmentCurve(from, g), 0, { form }), segmentTo: api.segmentMatrices(segmentCurve(to, Array.from(q)), 0, { form }),
      midFrom: [original[MID * 2], original[MID * 2 + 1]], midTo: [converted[MID * 2], converted[MID * 2 + 1]] };
  }
  // Keep G, swap M: the same four rows read as the geometry of another basis.
  const swapped = api.evaluateCurve(segmentCurve(to, g), params);
  return { mode, from, to, g, q: null, original, other: swapped, distance: maxDistance(api, original, swapped),
    Mfrom: api.basisMatrix(from), Mto: api.basisMatrix(to),
    segmentFrom: api.segmentMatrices(segmentCurve(from, g), 0, { form }), segmentTo: api.segmentMatrices(segmentCurve(to, g), 0, { form }),
    midFrom: [original[MID * 2], original[MID * 2 + 1]], midTo: [swapped[MID * 2], swapped[MID * 2 + 1]] };
}

// The map of the plane (affine, or perspective with w = px x + py y + 1) is the core's:
// api.mapPoints maps flat points and gives w(P_i), or refuses a point behind the eye
// ('perspective-behind-eye', naming it).
const mapFlat = (api, transform, values, what) => api.mapPoints(values, 2, transform, { what });

// For every family: the curve of the mapped control points against the mapped curve.
// For the Bezier segments also the rational form with weights w(P_i) (homogeneous
// coordinates, lecture 002 "NURBS ... handled correctly in perspective view").
export function computeInvariance(api, points, transform) {
  const control = mapFlat(api, transform, flat(points), 'P');
  const mapped = pairs(control.points);
  const rows = {};
  const drawing = {};
  for (const family of FAMILY_IDS) {
    const before = familySegments(api, family, points);
    const after = familySegments(api, family, mapped);
    let distance = 0;
    const pieces = [];
    before.forEach((curve, i) => {
      const d = api.curveDomain(curve);
      const params = linspace(d.start, d.end, SAMPLES);
      const mappedCurve = mapFlat(api, transform, api.evaluateCurve(curve, params), `sample of the ${family} curve `).points;
      const curveOfMapped = api.evaluateCurve(after[i], params);
      distance = Math.max(distance, maxDistance(api, mappedCurve, curveOfMapped));
      pieces.push({ mappedCurve, curveOfMapped });
    });
    rows[family] = { distance };
    drawing[family] = pieces;
  }
  let rational = null;
  if (transform.kind === 'perspective') {
    let distance = 0;
    const pieces = [];
    for (let i = 0; i + 3 < points.length; i += 3) {
      const params = linspace(0, 1, SAMPLES);
      const mappedCurve = mapFlat(api, transform, api.evaluateCurve({ kind: 'bezier', dim: 2, points: flat(points.slice(i, i + 4)) }, params), 'sample of the Bezier curve ').points;
      const weights = Array.from(control.w.slice(i, i + 4));
      const rationalCurve = api.evaluateCurve({ kind: 'bezier', dim: 2, points: control.points.slice(2 * i, 2 * i + 8), weights }, params);
      distance = Math.max(distance, maxDistance(api, mappedCurve, rationalCurve));
      pieces.push({ rationalCurve, weights });
    }
    rational = { distance, pieces };
  }
  return { kind: transform.kind, mapped, rows, drawing, rational };
}
