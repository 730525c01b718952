// @ts-check
// Constraint modes while dragging (lecture 001 "Achieving Continuity", lecture 002 "C^n and
// G^n"). The piecewise curve is stored as 4 entries per segment: Bezier P0..P3, or Hermite
// p0, p1 and the tangent vectors t0, t1. The core moves the points (api.dragWithConstraint,
// api.enforceConstraint, api.appendSegment; the rules are in docs/api-curves.md); this
// module only turns the state's [x, y] pairs into the core's flat layout and back.
import { flat, pairs } from '../../app/arrays.js';

export const CONSTRAINTS = ['free', 'C0', 'G1', 'C1', 'C2'];

// Moves entry `index` to `to` and restores the constraint at every joint, working outwards
// from the dragged segment (each joint's master is the side nearer the drag).
export const dragWithConstraint = (api, points, family, mode, index, to) =>
  pairs(api.dragWithConstraint(flat(points), 2, family, mode, index, to));

// Applies `mode` to the whole curve, left to right (used when the mode is switched).
export const enforceAll = (api, points, family, mode) => pairs(api.enforceConstraint(flat(points), 2, family, mode));

// One more segment after the last one, with the mode applied at the new joint; the
// shared-point families (B-spline, Catmull-Rom) get one more point.
export const appendSegment = (api, points, family, mode) => pairs(api.appendSegment(flat(points), 2, family, mode));
