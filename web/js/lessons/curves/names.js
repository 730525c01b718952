// @ts-check
// What the curve explorer calls things: its overlays and constructions, and the names of
// the blending functions (shared by the drawing, the panels and the CSV export).
import { isSpline } from './families.js';

export const CONSTRUCTIONS = ['none', 'de-casteljau', 'de-boor', 'subdivide', 'elevate', 'insert-knot'];
export const OVERLAYS = {
  polygon: 'Control polygon',
  hull: 'Convex hull',
  tangent: "Tangent P'(u)",
  second: "Second derivative P''(u)",
  comb: 'Curvature comb',
  knots: 'Knots / segment joints',
  samples: 'Sample points (every 20th of 1,000)',
  influence: 'Tint the curve by the point under the mouse',
};
// The overlays a new page shows (and the presenter's overlay key brings back).
export const DEFAULT_OVERLAYS = Object.freeze({ polygon: true, hull: false, tangent: false, second: false, comb: false, knots: true, samples: false, influence: true });

// Blending function i belongs to point i (Hermite: items K..2K-1 are the tangents).
export function blendingLabels(state, count) {
  const K = state.points.length;
  const p = state.degree;
  return Array.from({ length: count }, (_, i) => {
    if (state.family === 'hermite') return i < K ? `H_P${i}` : `H_T${i - K}`;
    // Lecture 002 writes the B-spline basis B_id (d the degree); NURBS R_i,d is its weighted form.
    if (isSpline(state.family)) return state.family === 'nurbs' ? `R${i},${p}` : `B${i},${p}`;
    if (state.family === 'bezier') return `B${i},${K - 1}`;
    if (state.family === 'interpolation') return `L${i}`;
    return `B_P${i}`;
  });
}
