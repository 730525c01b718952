// @ts-check
// The curve families of lectures 000-004 as the lesson's state knows them, and the
// bookkeeping that keeps a state consistent when the family, the degree or the number of
// points changes (knot count K + p + 1, one weight and one tangent per point). No curve
// mathematics here: the core evaluates and makes the knot vectors; this module only builds
// the description it reads and keeps the state's lists the right length.
import { flat } from '../../app/arrays.js';

export const FAMILIES = [
  { id: 'hermite', label: 'Hermite (points and tangents)', minPoints: 2, maxPoints: 16, lecture: '000, 001, 003, 004' },
  { id: 'bezier', label: 'Bezier (any degree)', minPoints: 2, maxPoints: 16, lecture: '001, 002, 003' },
  { id: 'bspline-uniform', label: 'Uniform B-spline', minPoints: 2, maxPoints: 24, lecture: '001, 002, 003' },
  { id: 'bspline', label: 'Non-uniform B-spline', minPoints: 2, maxPoints: 24, lecture: '001, 002' },
  { id: 'nurbs', label: 'NURBS (weights)', minPoints: 2, maxPoints: 24, lecture: '001, 002' },
  { id: 'catmull-rom', label: 'Catmull-Rom / cardinal', minPoints: 4, maxPoints: 24, lecture: '002, 003' },
  // maxPoints null: the core's own limit, api.curveLimits().maxInterpolationPoints
  { id: 'interpolation', label: 'Polynomial interpolation', minPoints: 2, maxPoints: null, lecture: '000, 004' },
];

// The most points `info`'s family takes: its own figure, or the core's limit.
export const familyMaxPoints = (info, api) => info.maxPoints ?? api.curveLimits().maxInterpolationPoints;

export const FAMILY_IDS = FAMILIES.map((f) => f.id);
export const MAX_SPLINE_DEGREE = 7;
export const familyInfo = (id) => FAMILIES.find((f) => f.id === id);

export const usesKnots = (family) => family === 'bspline' || family === 'nurbs';
export const isSpline = (family) => family === 'bspline' || family === 'nurbs' || family === 'bspline-uniform';
export const hasDegreeChoice = isSpline;

// The degree the family uses for `count` points (Bezier and interpolation: count - 1).
export function familyDegree(state) {
  const K = state.points.length;
  if (state.family === 'bezier' || state.family === 'interpolation') return K - 1;
  if (isSpline(state.family)) return state.degree;
  return 3;
}

export const maxDegreeFor = (count) => Math.max(1, Math.min(MAX_SPLINE_DEGREE, count - 1));

// Knot vectors of K + p + 1 entries (lecture 002: open/clamped, uniform, unclamped) come
// from the core: api.clampedKnots, api.uniformKnots, api.unclampedKnots, api.isClampedKnots.

// The default scene's knots: the clamped vector of 4 points of degree 3 (p + 1 zeros, p + 1
// ones; a test checks it against api.clampedKnots(4, 3)).
export const DEFAULT_KNOTS = [0, 0, 0, 0, 1, 1, 1, 1];

export function continuityLabel(k) {
  return k < 0 ? 'C-1 (break)' : `C${k}`;
}

const round = (x) => Math.round(x * 1e9) / 1e9;

// Knots for `count` points of `degree` in the style of `previous` (clamped or uniform). The
// families without knots keep a vector too (switching back to a B-spline starts from it);
// there the degree is capped at what `count` points carry, and a vector too short to say
// counts as clamped.
export function knotsLike(api, previous, count, degree, previousDegree = degree) {
  const p = Math.min(degree, maxDegreeFor(count));
  const uniform = previous?.length >= 2 * previousDegree + 2 && !api.isClampedKnots(previous, previousDegree);
  return Array.from(uniform ? api.uniformKnots(count, p) : api.clampedKnots(count, p));
}

// The description of the curve the core reads ({kind, dim, points, degree?,
// knots?, weights?, tangents?, tension?}). Points flat, points[2*i + k].
export function curveSpec(state) {
  const points = flat(state.points);
  switch (state.family) {
    case 'hermite':
      return { kind: 'hermite', dim: 2, points, tangents: flat(state.tangents) };
    case 'bezier':
      return { kind: 'bezier', dim: 2, points };
    case 'bspline-uniform':
      return { kind: 'bspline', dim: 2, points, degree: state.degree };
    case 'bspline':
      return { kind: 'bspline', dim: 2, points, degree: state.degree, knots: Float64Array.from(state.knots) };
    case 'nurbs':
      return { kind: 'nurbs', dim: 2, points, degree: state.degree, knots: Float64Array.from(state.knots), weights: Float64Array.from(state.weights) };
    case 'catmull-rom':
      return state.tension === 0
        ? { kind: 'catmull-rom', dim: 2, points }
        : { kind: 'cardinal', dim: 2, points, tension: state.tension };
    case 'interpolation':
      return { kind: 'interpolation', dim: 2, points };
    default:
      throw new Error(`unknown curve family ${state.family}`);
  }
}

// Default scenes. The Bezier cubic is docs/benchmarks.md's P0..P3 (z dropped).
export const defaultPoints = {
  hermite: [[0, 0], [2, 1.5], [4, 0]],
  bezier: [[0, 0], [1, 2], [3, 2], [4, 0]],
  'bspline-uniform': [[0, 0], [0.6, 1.8], [1.8, 2.2], [2.6, 0.4], [3.6, 0.2], [4.2, 1.8], [5.4, 2]],
  bspline: [[0, 0], [0.6, 1.8], [1.8, 2.2], [2.6, 0.4], [3.6, 0.2], [4.2, 1.8], [5.4, 2]],
  nurbs: [[0, 0], [0.6, 1.8], [1.8, 2.2], [2.6, 0.4], [3.6, 0.2], [4.2, 1.8], [5.4, 2]],
  'catmull-rom': [[0, 0], [0.8, 1.6], [2, 2], [3, 0.6], [4.2, 0.4], [5, 1.8]],
  // Nearly flat data with one bump: one polynomial through them overshoots near the ends
  // (lecture 004, "the curve oscillates more" as the degree grows).
  interpolation: [[0, 0.6], [0.6, 0.5], [1.2, 0.6], [1.8, 0.55], [2.4, 1.7], [3, 0.6], [3.6, 0.55], [4.2, 0.6], [4.8, 0.5]],
};

export const defaultTangents = (points) => points.map((p, i) => {
  const a = points[Math.max(0, i - 1)];
  const b = points[Math.min(points.length - 1, i + 1)];
  return [round(b[0] - a[0]), round(b[1] - a[1])];
});

// A consistent state for `family`, keeping the points when the family can use them.
export function switchFamily(api, state, family) {
  const info = familyInfo(family);
  let points = state.points.map((p) => p.slice());
  if (points.length < info.minPoints || points.length > (info.maxPoints ?? Infinity)) points = defaultPoints[family].map((p) => p.slice());
  const degree = isSpline(family) ? Math.min(isSpline(state.family) ? state.degree : 3, maxDegreeFor(points.length)) : state.degree;
  const next = { ...state, family, points, degree };
  next.tangents = points.length === state.tangents.length ? state.tangents : defaultTangents(points);
  next.weights = points.length === state.weights.length ? state.weights : points.map(() => 1);
  next.knots = usesKnots(family)
    ? (state.knots.length === points.length + degree + 1 && usesKnots(state.family) ? state.knots : Array.from(api.clampedKnots(points.length, degree)))
    : state.knots;
  if (!usesKnots(family) && next.knots.length !== points.length + degree + 1) next.knots = Array.from(api.clampedKnots(points.length, Math.min(degree, maxDegreeFor(points.length))));
  next.construction = { kind: 'none', step: 0 };
  next.u = 0;
  return next;
}

// Adds a point after index `after` (the midpoint with the next, or beyond the end).
// `box` ({minX, minY, maxX, maxY}, world units: the visible view less a margin), when given,
// shortens a point that continues the polygon past an end so it stays in view; the caller
// re-fits the view when that is not possible (the end point itself at or beyond the edge).
export function addPoint(api, state, after, at = null, box = null) {
  const K = state.points.length;
  const i = Math.min(Math.max(after, -1), K - 1);
  let p;
  if (at) p = at;
  else if (i < K - 1 && i >= 0) p = mid(state.points[i], state.points[i + 1]);
  else if (i === K - 1) p = extend(state.points[K - 2] ?? [0, 0], state.points[K - 1], box);
  else p = extend(state.points[1], state.points[0], box);
  const points = insertAt(state.points, i + 1, p.map(round));
  const tangents = insertAt(state.tangents, i + 1, [1, 0]);
  const weights = insertAt(state.weights, i + 1, 1);
  return withCount(api, { ...state, points, tangents, weights }, state);
}

export function removePoint(api, state, index) {
  const points = state.points.filter((_, i) => i !== index);
  const tangents = state.tangents.filter((_, i) => i !== index);
  const weights = state.weights.filter((_, i) => i !== index);
  return withCount(api, { ...state, points, tangents, weights }, state);
}

// Knots and degree that fit the new number of points, in the old knots' style.
function withCount(api, next, previous) {
  const degree = isSpline(next.family) ? Math.min(previous.degree, maxDegreeFor(next.points.length)) : previous.degree;
  const knots = knotsLike(api, previous.knots, next.points.length, degree, previous.degree);
  return { ...next, degree, knots, construction: { kind: 'none', step: 0 } };
}

export function withDegree(api, state, degree) {
  const knots = knotsLike(api, state.knots, state.points.length, degree, state.degree);
  return { ...state, degree, knots, construction: { kind: 'none', step: 0 } };
}

const mid = (a, b) => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
// b + s (b - a): s = 1 (one more leg of the same length), or the largest s that stays in
// `box` when that is at least MIN_LEG_FRACTION of a leg (a shorter one would crowd b).
const MIN_LEG_FRACTION = 0.25;
function extend(a, b, box = null) {
  const d = [b[0] - a[0], b[1] - a[1]];
  let s = 1;
  if (box) {
    const lo = [box.minX, box.minY];
    const hi = [box.maxX, box.maxY];
    for (const k of [0, 1]) {
      if (d[k] > 0) s = Math.min(s, (hi[k] - b[k]) / d[k]);
      else if (d[k] < 0) s = Math.min(s, (lo[k] - b[k]) / d[k]);
    }
    if (!(s >= MIN_LEG_FRACTION)) s = 1;
  }
  return [b[0] + s * d[0], b[1] + s * d[1]];
}
const insertAt = (arr, i, v) => [...arr.slice(0, i), v, ...arr.slice(i)];
