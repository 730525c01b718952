// @ts-check
// Named starting pictures, each built so the lecture predicts the answer at its joint
// (lecture 001 "Geometric/Parametric Continuity", lecture 004's Q1-Q2 / Q1-Q3 figure).
// Bezier and Hermite: 4 entries per segment. B-spline and Catmull-Rom: shared points.
const J = [0, 0.5];
const LEFT = [[-3, -1], [-2.2, 1.2], [-1, 1.4], J];
const mirror = (p, s = 1) => [J[0] + s * (J[0] - p[0]), J[1] + s * (J[1] - p[1])];

export const PRESETS = {
  'c1-bezier': {
    label: 'C1 Bezier joint: collinear, equal legs',
    family: 'bezier',
    constraint: 'C1',
    note: 'J - P2 = Q1 - J: the first derivatives are equal (C1), so the tangent directions agree too (G1).',
    points: [...LEFT, J, mirror(LEFT[2]), [2.2, -1.5], [3, 0.5]],
  },
  'g1-not-c1': {
    label: 'G1 but not C1: collinear, legs 1 : 2',
    family: 'bezier',
    constraint: 'G1',
    note: 'Same direction, twice the length: the shape looks smooth (G1) but the speed doubles at the joint (not C1).',
    points: [...LEFT, J, mirror(LEFT[2], 2), [3.2, -1.6], [3.6, 0.6]],
  },
  'c0-corner': {
    label: 'C0 only: a corner',
    family: 'bezier',
    constraint: 'C0',
    note: 'The segments meet (C0) but the tangents point different ways: a corner.',
    points: [...LEFT, J, [1.2, 1.9], [2.2, -1.5], [3, 0.5]],
  },
  'zero-tangent': {
    label: 'C1 without G1: zero tangents (the exception)',
    family: 'bezier',
    constraint: 'free',
    note: 'P2 = J = Q1: both first derivatives are the zero vector, so they are equal (C1), yet the curve has a corner: no tangent direction, not G1. C1 implies G1 only when the tangent is not zero (lecture 004).',
    points: [[-3, -1], [-1.4, 1.7], J, J, J, J, [1.5, 1.6], [3, 0.2]],
  },
  'gap': {
    label: 'C-1: a gap (the joint is discontinuous)',
    family: 'bezier',
    constraint: 'free',
    note: 'Lecture 004: C-1, the joint is discontinuous, V1(1) ≠ V2(0); a piecewise constant interpolant is C-1. In free mode drag an end (or select it with ] and move it with the arrows) to open a gap; “keep C0” closes it.',
    points: [...LEFT, [0.45, 0.8], [1.2, -0.2], [2.2, -1.5], [3, 0.5]],
  },
  'c2-bezier': {
    label: 'C2 Bezier joint (R2 = L1 - 4 L2 + 4 L3)',
    family: 'bezier',
    constraint: 'C2',
    note: 'Equal first and second derivatives: C2, and G2 with it.',
    // R2 = L1 - 4 L2 + 4 J = (-2.2, 1.2) - 4 (-1, 1.4) + 4 (0, 0.5) = (1.8, -2.4)
    points: [...LEFT, J, mirror(LEFT[2]), [1.8, -2.4], [3, 0.5]],
  },
  'hermite-shared': {
    label: 'Hermite: joint sharing one tangent',
    family: 'hermite',
    constraint: 'C1',
    note: 'Hermite segments that share the point and the tangent vector at the joint are C1 by construction (lecture 001).',
    // p0, p1, t0, t1 per segment
    points: [[-3, -1], J, [3, 6], [4, -1], J, [3, -0.5], [4, -1], [2, 3]],
  },
  'bspline': {
    label: 'Uniform cubic B-spline (C2 everywhere)',
    family: 'bspline',
    constraint: 'free',
    note: 'Neighbouring segments share three of their four control points; every joint is C2 (lecture 002).',
    points: [[-3, -1], [-2.2, 1.4], [-0.8, 1.6], [0.4, -0.6], [1.8, -1.2], [2.6, 1.2], [3.4, 0.4]],
  },
  'catmull-rom': {
    label: 'Catmull-Rom spline (C1, not C2)',
    family: 'catmull-rom',
    constraint: 'free',
    note: 'p\'(0) = (p2 - p0)/2 is shared by neighbours: C1 and G1 at every joint, the curvature jumps (lecture 002).',
    points: [[-3, -1], [-2.2, 1.4], [-0.8, 1.6], [0.4, -0.6], [1.8, -1.2], [2.6, 1.2], [3.4, 0.4]],
  },
};

export const DEFAULT_PRESET = 'c1-bezier';
