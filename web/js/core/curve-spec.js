// @ts-check
// The curve spec the core reads, and the argument checks every curve call shares (the
// curves part, curves-api.js, and curve sampling, curve-sampling-api.js, which the mesh
// part carries too). This module only checks types and fills defaults; the core checks the
// values and names the offending element in its message.
import { fail, isNumberArray } from './errors.js';

export const EMPTY = new Float64Array(0);
export const CURVE_KINDS = ['bezier', 'bspline', 'nurbs', 'hermite', 'catmull-rom', 'cardinal', 'interpolation'];
export const CUBIC_BASES = ['hermite', 'bezier', 'bspline', 'catmull-rom'];
export const MAX_DERIVATIVE_ORDER = 21;
export const MAX_SAMPLES = 10_000_000;

// A Float64Array view of numbers (no copy when it already is one). Values are checked in
// the core, which names the bad entry; here only the type.
export function numbers(value, what) {
  if (value instanceof Float64Array) return value;
  if (!isNumberArray(value)) fail('invalid-argument', `${what} must be an array or typed array of numbers`);
  return Float64Array.from(value);
}

export function optionalNumbers(value, what) {
  return value === undefined || value === null ? EMPTY : numbers(value, what);
}

export function dimension(dim, what = 'dim') {
  if (dim !== 2 && dim !== 3) fail('invalid-dimension', `${what} must be 2 or 3, not ${String(dim).slice(0, 20)}`);
  return dim;
}

export function wholeNumber(value, what, min, max, code = 'invalid-argument') {
  if (!Number.isInteger(value) || value < min || value > max) {
    fail(code, `${what} must be a whole number from ${min} to ${max}, not ${String(value).slice(0, 40)}`);
  }
  return value;
}

export function finiteNumber(value, what) {
  if (typeof value !== 'number') fail('invalid-argument', `${what} must be a number`);
  if (!Number.isFinite(value)) fail('non-finite-input', `${what} is ${value}, not a finite number`);
  return value;
}

// The curve spec the core reads: every field present, arrays as Float64Array.
export function normalizeCurve(curve, what = 'curve') {
  if (curve === null || typeof curve !== 'object') {
    fail('invalid-argument', `${what} must be an object like { kind: 'bezier', dim: 2, points: [...] }`);
  }
  if (typeof curve.kind !== 'string' || !CURVE_KINDS.includes(curve.kind)) {
    fail('unknown-curve-kind', `${what}.kind is ${JSON.stringify(curve.kind)?.slice(0, 40)}; expected one of ${CURVE_KINDS.join(', ')}`);
  }
  let degree = 0;
  if (curve.degree !== undefined && curve.degree !== null) {
    if (!Number.isInteger(curve.degree)) fail('degree-out-of-range', `${what}.degree must be a whole number, not ${String(curve.degree).slice(0, 40)}`);
    degree = curve.degree;
    if (degree < 1) fail('degree-out-of-range', `${what}.degree must be at least 1, not ${degree}`);
  }
  let tension = 0;
  if (curve.tension !== undefined && curve.tension !== null) tension = finiteNumber(curve.tension, `${what}.tension`);
  return {
    kind: curve.kind,
    dim: dimension(curve.dim, `${what}.dim`),
    points: numbers(curve.points, `${what}.points`),
    degree,
    knots: optionalNumbers(curve.knots, `${what}.knots`),
    weights: optionalNumbers(curve.weights, `${what}.weights`),
    tangents: optionalNumbers(curve.tangents, `${what}.tangents`),
    nodes: optionalNumbers(curve.nodes, `${what}.nodes`),
    tension,
  };
}

export function derivativeOrder(order) {
  return wholeNumber(order, 'the derivative order', 0, MAX_DERIVATIVE_ORDER);
}
