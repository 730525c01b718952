// @ts-check
// Homework helper: a piecewise cubic Bezier curve (four segments, three joints) and the
// continuity of each joint, C^k (the derivatives agree) and G^k (the unit tangent, then the
// curvature vector, agree), as the core measures it (lectures 001 and 004), with the
// numbers behind each verdict.
//   node examples/bezier-joints.mjs
// Change the points and run it again: a joint is C1 when P3 - P2 of one segment equals
// Q1 - Q0 of the next, G1 when they only point the same way.
import { loadWingspline } from 'wingspline';

/** @type {number[][][]} four segments, four [x, y] control points each */
const segments = [
  [[0, 0], [1, 1], [2, 1], [3, 0]],
  [[3, 0], [4, -1], [5, -3], [6, -3]], // joint 1: C2 (Q1 - Q0 = P3 - P2, and P'' agrees)
  [[6, -3], [8, -3], [9, -1], [10, 0]], // joint 2: G1 only (same direction, twice as long)
  [[10, 0], [10, 2], [11, 3], [12, 2]], // joint 3: a corner, C0 only
];

const api = await loadWingspline();
/** @type {(s: number[][]) => import('wingspline').BezierCurve} */
const bezier = (s) => ({ kind: 'bezier', dim: 2, points: s.flat() });
segments.forEach((s, i) => console.log(`segment ${i + 1}: ${JSON.stringify(s)}`));
for (let j = 0; j + 1 < segments.length; j += 1) {
  const { parametric, geometric, evidence } = api.jointContinuity(bezier(segments[j]), bezier(segments[j + 1]));
  const c = parametric < 0 ? 'not even C^0' : `C^${parametric}`;
  const g = geometric < 0 ? 'not even G^0' : `G^${geometric}`;
  console.log(`joint ${j + 1}: ${c} ${g}  (position gap ${evidence.positionGap.toExponential(1)}, `
    + `P' gap ${evidence.d1Gap.toExponential(1)}, |Q'|/|P'| = ${evidence.ratio.toFixed(3)}, `
    + `tangent angle ${evidence.tangentAngle.toExponential(1)} rad, P'' gap ${evidence.d2Gap.toExponential(1)})`);
}
