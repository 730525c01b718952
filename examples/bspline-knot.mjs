// @ts-check
// Homework helper: a clamped cubic B-spline, one knot inserted by Boehm's rule (lecture
// 003), and the curve sampled before and after into a CSV file (u, x and y before, x and y
// after): the two columns agree, because knot insertion does not change the curve.
//   node examples/bspline-knot.mjs [out.csv] [u]
// Defaults: bspline-knot.csv in the current folder, u = 0.4.
import { writeFile } from 'node:fs/promises';
import { loadWingspline } from 'wingspline';

const out = process.argv[2] ?? 'bspline-knot.csv';
const u = Number(process.argv[3] ?? 0.4);

const api = await loadWingspline();
const degree = 3;
const points = [0, 0, 1, 3, 3, 4, 5, 1, 7, 2, 8, 5]; // six control points, x y each
/** @type {import('wingspline').BSplineCurve} */
const curve = { kind: 'bspline', dim: 2, degree, points, knots: api.clampedKnots(points.length / 2, degree) };
const inserted = api.insertKnot(curve, u);

/** @type {(flat: ArrayLike<number>) => number[][]} */
const pairs = (flat) => Array.from({ length: flat.length / 2 }, (_, i) => [flat[2 * i], flat[2 * i + 1]]);
console.log(`degree: ${degree}`);
console.log(`knots before: ${JSON.stringify(Array.from(curve.knots ?? []))}`);
console.log(`points before: ${JSON.stringify(pairs(points))}`);
console.log(`insert u = ${u}`);
console.log(`knots after: ${JSON.stringify(Array.from(inserted.curve.knots ?? []))}`);
console.log(`points after: ${JSON.stringify(pairs(Array.from(inserted.curve.points)))}`);
console.log(`Boehm's rule recomputed Q${inserted.recomputed.join(', Q')} with a = ${Array.from(inserted.alphas, (a) => a.toFixed(4)).join(', ')}`);

const before = api.sampleCurve(curve, 101);
const after = api.evaluateCurve(inserted.curve, before.params);
const lines = ['u,x_before,y_before,x_after,y_after'];
before.params.forEach((s, j) => lines.push([s, before.points[2 * j], before.points[2 * j + 1], after[2 * j], after[2 * j + 1]].join(',')));
await writeFile(out, `${lines.join('\n')}\n`);
let gap = 0;
before.params.forEach((_, j) => { gap = Math.max(gap, Math.hypot(after[2 * j] - before.points[2 * j], after[2 * j + 1] - before.points[2 * j + 1])); });
console.log(`${before.params.length} samples written to ${out}; largest distance between the curves before and after: ${gap.toExponential(2)}`);
