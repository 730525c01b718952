// Constraint modes while dragging (lecture 001 "Achieving Continuity", lecture 002 "C^n and
// G^n"). The piecewise curve is stored as 4 entries per segment: Bezier P0..P3, or Hermite
// p0, p1 and the tangent vectors t0, t1. A joint j sits between segment j-1 (left, L) and
// segment j (right, R). These rules move control points; the curve itself is always
// evaluated and classified by the core.
//   C0  share the end point: L3 = R0 (Hermite: L.p1 = R.p0)
//   G1  L2, J, R1 collinear, J between them: R1 - J = a (J - L2), a > 0 (Hermite: R.t0 = a L.t1)
//   C1  a = 1, "J - P02 = P11 - J" (lecture 001) (Hermite: the joint shares one tangent)
//   C2  equal second derivatives: Bezier 6(L1 - 2L2 + L3) = 6(R0 - 2R1 + R2), so
//       R2 = L1 - 4 L2 + 4 L3; Hermite P''(1) = 6p0 - 6p1 + 2t0 + 4t1 = -6q0 + 6q1 - 4s0 - 2s1 = Q''(0)
export const CONSTRAINTS = ['free', 'C0', 'G1', 'C1', 'C2'];
const LEVEL = { free: -1, C0: 0, G1: 0.5, C1: 1, C2: 2 };

const add = (a, b) => [a[0] + b[0], a[1] + b[1]];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];
const scale = (a, s) => [a[0] * s, a[1] * s];
const length = (a) => Math.hypot(a[0], a[1]);

export const segmentCount = (points) => points.length / 4;

// Makes joint j satisfy `mode`, changing only the side that is not the master.
function enforceJoint(points, family, j, mode, master) {
  const level = LEVEL[mode];
  if (level < 0) return;
  const l = 4 * (j - 1);
  const r = 4 * j;
  if (family === 'bezier') {
    if (master === 'left') points[r] = points[l + 3].slice(); else points[l + 3] = points[r].slice();
    const J = points[r];
    if (level === 0.5) {
      if (master === 'left') {
        const d = sub(J, points[l + 2]); const n = length(d); const keep = length(sub(points[r + 1], J));
        if (n > 1e-12) points[r + 1] = add(J, scale(d, keep / n));
      } else {
        const d = sub(points[r + 1], J); const n = length(d); const keep = length(sub(J, points[l + 2]));
        if (n > 1e-12) points[l + 2] = sub(J, scale(d, keep / n));
      }
    } else if (level >= 1) {
      if (master === 'left') points[r + 1] = sub(scale(J, 2), points[l + 2]);
      else points[l + 2] = sub(scale(J, 2), points[r + 1]);
    }
    if (level >= 2) {
      if (master === 'left') points[r + 2] = add(sub(points[l + 1], scale(points[l + 2], 4)), scale(J, 4));
      else points[l + 1] = add(sub(points[r + 2], scale(points[r + 1], 4)), scale(J, 4));
    }
    return;
  }
  // Hermite: [p0, p1, t0, t1] per segment; the joint is L.p1 = R.p0, tangents L.t1 and R.t0.
  if (master === 'left') points[r] = points[l + 1].slice(); else points[l + 1] = points[r].slice();
  if (level === 0.5) {
    if (master === 'left') {
      const d = points[l + 3]; const n = length(d); const keep = length(points[r + 2]);
      if (n > 1e-12) points[r + 2] = scale(d, keep / n);
    } else {
      const d = points[r + 2]; const n = length(d); const keep = length(points[l + 3]);
      if (n > 1e-12) points[l + 3] = scale(d, keep / n);
    }
  } else if (level >= 1) {
    if (master === 'left') points[r + 2] = points[l + 3].slice(); else points[l + 3] = points[r + 2].slice();
  }
  if (level >= 2) {
    const [p0, p1, t0, t1] = points.slice(l, l + 4);
    const [q0, q1, s0, s1] = points.slice(r, r + 4);
    if (master === 'left') {
      const a = add(add(scale(sub(p0, p1), 6), scale(t0, 2)), scale(t1, 4));
      points[r + 3] = scale(sub(sub(scale(sub(q1, q0), 6), scale(s0, 4)), a), 0.5);
    } else {
      const a = sub(sub(scale(sub(q1, q0), 6), scale(s0, 4)), scale(s1, 2));
      points[l + 2] = scale(sub(sub(a, scale(sub(p0, p1), 6)), scale(t1, 4)), 0.5);
    }
  }
}

// Moves entry `index` to `to` and restores the constraint at every joint, working outwards
// from the dragged segment (each joint's master is the side nearer the drag).
export function dragWithConstraint(pointsIn, family, mode, index, to) {
  const points = pointsIn.map((p) => p.slice());
  const segments = segmentCount(points);
  const s = Math.floor(index / 4);
  const k = index % 4;
  const delta = sub(to, points[index]);
  points[index] = to.slice();
  if (mode === 'free') return points;
  // Moving a joint end point carries its Bezier neighbours along, so the joint keeps its shape.
  const isStart = family === 'bezier' ? k === 0 : k === 0;
  const isEnd = family === 'bezier' ? k === 3 : k === 1;
  if (family === 'bezier' && isEnd) {
    points[4 * s + 2] = add(points[4 * s + 2], delta);
    if (s + 1 < segments) points[4 * (s + 1) + 1] = add(points[4 * (s + 1) + 1], delta);
  }
  if (family === 'bezier' && isStart) {
    points[4 * s + 1] = add(points[4 * s + 1], delta);
    if (s > 0) points[4 * (s - 1) + 2] = add(points[4 * (s - 1) + 2], delta);
  }
  if (isEnd && s + 1 < segments) {
    points[4 * (s + 1)] = points[index].slice();
  }
  if (isStart && s > 0) {
    points[4 * (s - 1) + (family === 'bezier' ? 3 : 1)] = points[index].slice();
  }
  for (let j = s + 1; j < segments; j += 1) enforceJoint(points, family, j, mode, 'left');
  for (let j = s; j >= 1; j -= 1) enforceJoint(points, family, j, mode, 'right');
  return points;
}

// Applies `mode` to the whole curve, left to right (used when the mode is switched).
export function enforceAll(pointsIn, family, mode) {
  const points = pointsIn.map((p) => p.slice());
  for (let j = 1; j < segmentCount(points); j += 1) enforceJoint(points, family, j, mode, 'left');
  return points;
}

// One more segment after the last one: a copy of the last segment moved along its chord
// (Bezier), or continuing from its end point with its end tangent (Hermite), then the mode
// applied at the new joint. Shared-point families get one more point.
export function appendSegment(pointsIn, family, mode) {
  const points = pointsIn.map((p) => p.slice());
  const n = points.length;
  if (family === 'bezier') {
    const [L0, L1, L2, L3] = points.slice(n - 4);
    const d = sub(L3, L0);
    points.push(L3.slice(), add(L1, d), add(L2, d), add(L3, d));
  } else if (family === 'hermite') {
    const [p0, p1, t0, t1] = points.slice(n - 4);
    points.push(p1.slice(), add(p1, sub(p1, p0)), t1.slice(), t0.slice());
  } else {
    points.push(add(points[n - 1], scale(sub(points[n - 1], points[n - 3]), 0.5)));
    return points;
  }
  return enforceAll(points, family, mode);
}
