// @ts-check
// The curve explorer's public state builders: the one place that writes the shape of a
// curve-explorer state (docs/state-format.md), for the lesson's own default and for pages
// that link to the explorer (lessons/links.js). No DOM; nothing computed here (knots come
// from the caller, who asked the core for them).
import { defaultPoints, defaultTangents, DEFAULT_KNOTS } from './families.js';
import { DEFAULT_OVERLAYS } from './names.js';

// The explorer as it opens: a cubic Bezier curve.
export function defaultCurveState() {
  const points = defaultPoints.bezier.map((p) => p.slice());
  return {
    family: 'bezier',
    points,
    tangents: defaultTangents(points),
    knots: DEFAULT_KNOTS.slice(),
    weights: points.map(() => 1),
    degree: 3,
    tension: 0,
    u: 0.35,
    construction: { kind: 'none', step: 0 },
    overlays: { ...DEFAULT_OVERLAYS },
    form: 'descending',
    notation: 'decimal',
    compare: true,
    view: { cx: 2, cy: 1, zoom: 120 },
  };
}

/**
 * The explorer showing Boehm's knot insertion at parameter u on the B-spline of degree
 * `degree` over `points` ([x, y] each) and `knots` (K + degree + 1 of them), centred on the
 * points. Its first step is shown (one insertion).
 * @param {{ points: number[][], degree: number, knots: number[], u: number }} spline
 */
export function knotInsertionState({ points, degree, knots, u }) {
  const base = defaultCurveState();
  let minX = Infinity; let maxX = -Infinity; let minY = Infinity; let maxY = -Infinity;
  for (const [x, y] of points) { minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, y); maxY = Math.max(maxY, y); }
  return {
    ...base,
    family: 'bspline',
    points: points.map((p) => p.slice()),
    degree,
    knots: knots.slice(),
    weights: points.map(() => 1),
    tangents: points.map(() => [1, 0]),
    u,
    construction: { kind: 'insert-knot', step: 1 },
    view: { ...base.view, cx: (minX + maxX) / 2, cy: (minY + maxY) / 2 },
  };
}
