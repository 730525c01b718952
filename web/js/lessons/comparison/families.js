// @ts-check
// The four families of lecture 003's table built on one control polygon P0..P(K-1), as
// curve objects of the core API. Only control data is arranged here; every point on every
// curve comes from the core.
import { flat, pairs } from '../../app/arrays.js';

// Lecture 003's four columns and lecture 001's non-uniform B-spline.
export const FAMILY_IDS = ['hermite', 'bezier', 'bspline', 'catmull-rom', 'nubs'];
export const FAMILY_NAMES = { hermite: 'Hermite', bezier: 'Bezier', bspline: 'B-spline', 'catmull-rom': 'Catmull-Rom', nubs: 'Non-uniform B-spline' };
// Colour index into ctx.colors.series (Okabe-Ito) per family; the legend also names them.
export const FAMILY_COLOR = { hermite: 3, bezier: 0, bspline: 2, 'catmull-rom': 1, nubs: 6 };
export const FAMILY_DASH = { hermite: [10, 4], bezier: [], bspline: [], 'catmull-rom': [3, 4], nubs: [12, 3, 2, 3] };

// The non-uniform cubic B-spline of lecture 001 on the same K points: unclamped knots with
// unequal gaps (K + 4 of them), so its segments have different parameter lengths.
export function nonUniformKnots(count) {
  const gaps = [0.6, 0.4, 1.2, 0.8, 0.5, 1.3, 0.6, 1.1, 0.5, 1];
  const knots = [0];
  for (let i = 1; i < count + 4; i += 1) knots.push(Number((knots[i - 1] + gaps[(i - 1) % gaps.length]).toFixed(6)));
  return knots;
}
export const nubsCurve = (points) => ({ kind: 'bspline', dim: 2, degree: 3, points: flat(points), knots: nonUniformKnots(points.length) });

// Hermite "with tangents from the points": t_i = (P_i+1 - P_i-1) / 2 inside, the one-sided
// chord at the ends (the Catmull-Rom conditions of lecture 002, p'(0) = (p2 - p0)/2), from
// the core: [[x, y], ...].
export const pointTangents = (api, points) => pairs(api.catmullRomTangents(flat(points), 2));

// Each family as a list of segment curves (joints between consecutive entries) and the
// control point indices each segment is built from.
// tangents (Hermite): one [x, y] per point, or null for Catmull-Rom's (pointTangents).
export function familySegments(api, family, points, tangents = null) {
  const segs = [];
  // The non-uniform B-spline is evaluated as one curve; its joints are the core's spans.
  if (family === 'nubs') return [nubsCurve(points)];
  if (family === 'bezier') {
    // Piecewise cubic Bezier: segment i is P3i..P3i+3, neighbours share the end point.
    for (let i = 0; i + 3 < points.length; i += 3) segs.push({ kind: 'bezier', dim: 2, points: flat(points.slice(i, i + 4)) });
  } else if (family === 'hermite') {
    const t = tangents ?? pointTangents(api, points);
    for (let i = 0; i + 1 < points.length; i += 1) {
      segs.push({ kind: 'hermite', dim: 2, points: flat([points[i], points[i + 1]]), tangents: flat([t[i], t[i + 1]]) });
    }
  } else {
    // Uniform B-spline and Catmull-Rom windows of four. Catmull-Rom repeats the end points,
    // so its segments run from P0 to P(K-1) and it passes through every control point.
    const list = family === 'catmull-rom' ? [points[0], ...points, points[points.length - 1]] : points;
    for (let i = 0; i + 3 < list.length; i += 1) segs.push({ kind: family, dim: 2, points: flat(list.slice(i, i + 4)) });
  }
  return segs;
}

// The "inherent" version of a family: only what the representation itself guarantees.
// Hermite segments with their own tangents (each segment's chord at both ends) and Bezier
// segments that only share end points are C0; B-spline and Catmull-Rom windows overlap,
// so their joints are what they are.
export function inherentSegments(api, family, points) {
  if (family === 'hermite') {
    const segs = [];
    for (let i = 0; i + 1 < points.length; i += 1) {
      // The chord P_i+1 - P_i at both ends: the end rule of the tangents from two points.
      const own = flat([points[i], points[i + 1]]);
      segs.push({ kind: 'hermite', dim: 2, points: own, tangents: api.catmullRomTangents(own, 2) });
    }
    return segs;
  }
  return familySegments(api, family, points);
}

// The "easily achieved" version (lecture 001 "Achieving Continuity"): Hermite shares the
// tangent at the joint; Bezier makes P3i-1, P3i, P3i+1 collinear with equal legs
// (P3i+1 = 2 P3i - P3i-1). B-spline and Catmull-Rom need nothing.
export function easySegments(api, family, points) {
  if (family === 'bezier') {
    // The core's C1 constraint at every joint, left to right (docs/api-curves.md): the
    // segments as 4 entries each, the right leg moved to R1 = 2 J - L2.
    const entries = [];
    for (let i = 0; i + 3 < points.length; i += 3) entries.push(...points.slice(i, i + 4));
    const q = api.enforceConstraint(flat(entries), 2, 'bezier', 'C1');
    const segs = [];
    for (let s = 0; 8 * s < q.length; s += 1) segs.push({ kind: 'bezier', dim: 2, points: q.slice(8 * s, 8 * s + 8) });
    return segs;
  }
  return familySegments(api, family, points);
}

// Each family's construction as the core's guarantee check reads it:
// which control data each segment's geometry rows are, for ANY polygon of `count` points.
// Slots 0..count-1 are P0..P(count-1); Hermite adds tangent-vector slots after them.
// maps[s][slots*r + j] = weight of slot j in geometry row r of segment s. `easy` is lecture
// 001's "Achieving Continuity": Hermite neighbours share the tangent; Bezier sets
// P3i+1 = 2 P3i - P3i-1. The non-uniform B-spline is described by its knots instead.
export function constructionOf(family, count, { easy = false } = {}) {
  if (family === 'nubs') return { knots: nonUniformKnots(count), degree: 3, count };
  const segments = [];
  let slots = count;
  let isPoint = new Array(count).fill(true);
  if (family === 'hermite') {
    // Inherent: each segment has its own two tangents; easy: one tangent per point.
    const tangentSlots = easy ? count : 2 * (count - 1);
    slots = count + tangentSlots;
    isPoint = [...isPoint, ...new Array(tangentSlots).fill(false)];
    for (let i = 0; i + 1 < count; i += 1) {
      const rows = easy ? [i, i + 1, count + i, count + i + 1] : [i, i + 1, count + 2 * i, count + 2 * i + 1];
      segments.push(rows.map((j) => ({ [j]: 1 })));
    }
  } else if (family === 'bezier') {
    for (let i = 0; i + 3 < count; i += 3) {
      const rows = [i, i + 1, i + 2, i + 3].map((j) => ({ [j]: 1 }));
      if (easy && i > 0) rows[1] = { [i]: 2, [i - 1]: -1 }; // P3i+1 = 2 P3i - P3i-1
      segments.push(rows);
    }
  } else {
    // Windows of four; Catmull-Rom repeats the end points (as familySegments draws it).
    const list = family === 'catmull-rom' ? [0, ...Array.from({ length: count }, (_, i) => i), count - 1] : Array.from({ length: count }, (_, i) => i);
    for (let i = 0; i + 3 < list.length; i += 1) segments.push(list.slice(i, i + 4).map((j) => ({ [j]: 1 })));
  }
  const maps = segments.map((rows) => {
    const m = new Float64Array(4 * slots);
    rows.forEach((row, r) => { for (const [j, w] of Object.entries(row)) m[slots * r + Number(j)] += w; });
    return m;
  });
  return { basis: family, slots, isPoint, maps };
}
