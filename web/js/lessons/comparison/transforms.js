// Basis conversion (lecture 002: q = M^-1 M_B P) and invariance (lecture 001 "Invariance")
// on the current polygon. The maps applied to points are the experiment's input; the
// curves before and after are evaluated by the core and compared.
import { familySegments, FAMILY_IDS } from './families.js';
import { linspace, flat } from '../../app/arrays.js';

const SAMPLES = 121;
const MID = 60; // the sample at u = 1/2, where the matrix panels evaluate

export function segmentCurve(kind, g) {
  return kind === 'hermite'
    ? { kind: 'hermite', dim: 2, points: g.slice(0, 4), tangents: g.slice(4, 8) }
    : { kind, dim: 2, points: g };
}

function maxDistance(a, b) {
  let d = 0;
  for (let j = 0; j < a.length; j += 2) d = Math.max(d, Math.hypot(a[j] - b[j], a[j + 1] - b[j + 1]));
  return d;
}

export function computeConversion(api, points, { from, to, start, mode }) {
  const g = flat(points.slice(start, start + 4));
  const params = linspace(0, 1, SAMPLES);
  const original = api.evaluateCurve(segmentCurve(from, g), params);
  if (mode === 'keep-curve') {
    const q = api.convertBasis(g, 2, from, to);
    const converted = api.evaluateCurve(segmentCurve(to, Array.from(q)), params);
    return { mode, from, to, g, q, original, other: converted, distance: maxDistance(original, converted),
      Mfrom: api.basisMatrix(from), Mto: api.basisMatrix(to),
      segmentFrom: api.segmentMatrices(segmentCurve(from, g), 0), segmentTo: api.segmentMatrices(segmentCurve(to, Array.from(q)), 0),
      midFrom: [original[MID * 2], original[MID * 2 + 1]], midTo: [converted[MID * 2], converted[MID * 2 + 1]] };
  }
  // Keep G, swap M: the same four rows read as the geometry of another basis.
  const swapped = api.evaluateCurve(segmentCurve(to, g), params);
  return { mode, from, to, g, q: null, original, other: swapped, distance: maxDistance(original, swapped),
    Mfrom: api.basisMatrix(from), Mto: api.basisMatrix(to),
    segmentFrom: api.segmentMatrices(segmentCurve(from, g), 0), segmentTo: api.segmentMatrices(segmentCurve(to, g), 0),
    midFrom: [original[MID * 2], original[MID * 2 + 1]], midTo: [swapped[MID * 2], swapped[MID * 2 + 1]] };
}

// x' = (a x + b y + tx) / w, y' = (c x + d y + ty) / w, w = px x + py y + 1; the linear
// part is scale * rotation(angle) * shear. px = py = 0 is affine.
export function makeMap(t) {
  const r = (t.angle * Math.PI) / 180;
  const cos = Math.cos(r) * t.scale;
  const sin = Math.sin(r) * t.scale;
  const a = cos; const b = cos * t.shear - sin; const c = sin; const d = sin * t.shear + cos;
  const px = t.kind === 'perspective' ? t.px : 0;
  const py = t.kind === 'perspective' ? t.py : 0;
  const w = (p) => px * p[0] + py * p[1] + 1;
  return {
    w,
    apply(p) {
      const ww = w(p);
      if (!(ww > 0)) {
        throw Object.assign(new Error(`the perspective map sends (${p[0].toFixed(2)}, ${p[1].toFixed(2)}) behind the eye (w = ${ww.toFixed(2)} ≤ 0); use smaller perspective coefficients`), { code: 'perspective-behind-eye' });
      }
      return [(a * p[0] + b * p[1] + t.tx) / ww, (c * p[0] + d * p[1] + t.ty) / ww];
    },
  };
}

function mapFlat(map, values) {
  const out = new Float64Array(values.length);
  for (let j = 0; j < values.length; j += 2) {
    const [x, y] = map.apply([values[j], values[j + 1]]);
    out[j] = x; out[j + 1] = y;
  }
  return out;
}

// For every family: the curve of the mapped control points against the mapped curve.
// For the Bezier segments also the rational form with weights w(P_i) (homogeneous
// coordinates, lecture 002 "NURBS ... handled correctly in perspective view").
export function computeInvariance(api, points, transform) {
  const map = makeMap(transform);
  const mapped = points.map((p) => map.apply(p));
  const rows = {};
  const drawing = {};
  for (const family of FAMILY_IDS) {
    const before = familySegments(family, points);
    const after = familySegments(family, mapped);
    let distance = 0;
    const pieces = [];
    before.forEach((curve, i) => {
      const d = api.curveDomain(curve);
      const params = linspace(d.start, d.end, SAMPLES);
      const mappedCurve = mapFlat(map, api.evaluateCurve(curve, params));
      const curveOfMapped = api.evaluateCurve(after[i], params);
      distance = Math.max(distance, maxDistance(mappedCurve, curveOfMapped));
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
      const own = points.slice(i, i + 4);
      const params = linspace(0, 1, SAMPLES);
      const mappedCurve = mapFlat(map, api.evaluateCurve({ kind: 'bezier', dim: 2, points: flat(own) }, params));
      const weights = own.map((p) => map.w(p));
      const rationalCurve = api.evaluateCurve({ kind: 'bezier', dim: 2, points: flat(own.map((p) => map.apply(p))), weights }, params);
      distance = Math.max(distance, maxDistance(mappedCurve, rationalCurve));
      pieces.push({ rationalCurve, weights });
    }
    rational = { distance, pieces };
  }
  return { kind: transform.kind, mapped, rows, drawing, rational };
}
