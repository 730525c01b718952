// @ts-check
// Curve sampling, a part of the curves API that the mesh part carries too (the core's
// curve_sampling.cpp is linked into both modules): points and derivatives of a curve, its
// domain, the knot vector presets and the subdivision of a control polygon. The subdivision
// lesson draws a polygon's limit B-spline with these and loads only the mesh module.
// Documented in docs/api-curves.md with the rest of the curves API.
import { unwrap, fail } from './errors.js';
import { EMPTY, MAX_SAMPLES, numbers, dimension, wholeNumber, normalizeCurve, derivativeOrder } from './curve-spec.js';

/** @param {any} raw a module's embind functions (the curves or the mesh module) */
export function createCurveSamplingApi(raw) {
  function evaluate(curve, params, order, all, out) {
    const spec = normalizeCurve(curve);
    const u = numbers(params, 'params');
    if (out !== undefined) {
      const expected = u.length * spec.dim * (all ? order + 1 : 1);
      if (!(out instanceof Float64Array) || out.length !== expected) {
        fail('invalid-argument', `options.out must be a Float64Array of length ${expected}`);
      }
    }
    return unwrap(raw.curveEvaluate(spec, u, order, all, out)).values;
  }

  const api = {
    // Points of the curve: Float64Array, values[dim*j + k] for params[j].
    // options.out: a Float64Array of length dim * params.length to fill instead of
    // allocating a new one (a lesson redrawing on every pointer move reuses its buffer).
    /** @param {object} curve @param {ArrayLike<number>} params @param {{ out?: Float64Array }} [options] */
    evaluateCurve(curve, params, { out } = {}) {
      return evaluate(curve, params, 0, false, out);
    },
    // The derivative of `order` (1 = tangent vector P'(u), 2 = P''(u)); same layout and options.
    /** @param {object} curve @param {ArrayLike<number>} params @param {number} [order] @param {{ out?: Float64Array }} [options] */
    evaluateDerivative(curve, params, order = 1, { out } = {}) {
      return evaluate(curve, params, derivativeOrder(order), false, out);
    },
    // Point and derivatives 1..maxOrder in one pass:
    // values[(maxOrder+1)*dim*j + dim*k + c] is component c of the k-th derivative at params[j].
    /** @param {object} curve @param {ArrayLike<number>} params @param {number} [maxOrder] @param {{ out?: Float64Array }} [options] */
    evaluateWithDerivatives(curve, params, maxOrder = 1, { out } = {}) {
      return evaluate(curve, params, derivativeOrder(maxOrder), true, out);
    },
    // { start, end, degree, controlPointCount, segmentCount }
    curveDomain(curve) {
      const r = unwrap(raw.curveDomain(normalizeCurve(curve)));
      return { start: r.start, end: r.end, degree: r.degree, controlPointCount: r.controlPointCount, segmentCount: r.segmentCount };
    },
    // n evenly spaced parameters over the whole domain (first = start, last = end exactly)
    // and the points there: { params, points } with points[dim*j + k].
    sampleCurve(curve, n = 200) {
      wholeNumber(n, 'the number of samples', 2, MAX_SAMPLES);
      const spec = normalizeCurve(curve);
      const d = unwrap(raw.curveDomain(spec));
      const params = new Float64Array(n);
      for (let j = 0; j < n; j += 1) params[j] = d.start + ((d.end - d.start) * j) / (n - 1);
      params[n - 1] = d.end;
      return { params, points: unwrap(raw.curveEvaluate(spec, params, 0, false, undefined)).values };
    },
    // Knot vector presets (K + p + 1 values, Float64Array; new values rounded to 1e-9):
    // clamped (p+1 zeros, interior j/(K-p), p+1 ones), uniform (t_j = j - p), unclamped
    // (the same domain and interior knots, the ends spread with the neighbouring spacing).
    clampedKnots(count, degree) {
      return unwrap(raw.knotVector('clamped', wholeNumber(count, 'count', 1, 2 ** 31 - 1), wholeNumber(degree, 'degree', 1, 2 ** 31 - 1, 'degree-out-of-range'), EMPTY)).knots;
    },
    uniformKnots(count, degree) {
      return unwrap(raw.knotVector('uniform', wholeNumber(count, 'count', 1, 2 ** 31 - 1), wholeNumber(degree, 'degree', 1, 2 ** 31 - 1, 'degree-out-of-range'), EMPTY)).knots;
    },
    unclampedKnots(knots, degree) {
      return unwrap(raw.knotVector('unclamped', 0, wholeNumber(degree, 'degree', 1, 2 ** 31 - 1, 'degree-out-of-range'), numbers(knots, 'knots'))).knots;
    },
  };
  // Subdivision of a control polygon (docs/api-curves.md "Subdivision"): 'chaikin'
  // (corner cutting -> the uniform quadratic B-spline) or 'cubic-bspline' (Lane-Riesenfeld
  // -> the uniform cubic B-spline), open or closed, `steps` times: Float64Array, dim per point.
  /** @param {ArrayLike<number>} points @param {number} dim @param {{ scheme?: string, closed?: boolean, steps?: number }} [options] */
  api.subdivideCurve = (points, dim, { scheme, closed = false, steps = 1 } = {}) => {
    if (typeof scheme !== 'string') fail('unknown-scheme', "subdivideCurve needs a scheme: 'chaikin' or 'cubic-bspline'");
    if (typeof closed !== 'boolean') fail('invalid-argument', 'closed must be true or false');
    const p = numbers(points, 'points');
    return unwrap(raw.curveSubdivide(p, dimension(dim), scheme, closed, wholeNumber(steps, 'steps', 0, 20))).points;
  };
  return api;
}
