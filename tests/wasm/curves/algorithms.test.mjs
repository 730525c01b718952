// The JS contract of the curve algorithms a lesson animates: de Boor, knot insertion,
// conversion to Bezier, knot multiplicities, NURBS presets, curvature, arc length, joint
// continuity, interpolation, patches, transformPoints (docs/api-curves.md).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();

const SAME_CURVE = 1e-12; // one curve by two routes (model units)
const CIRCLE = 1e-12; // | |P - c| - r |, the figure
const zigzag = (n) => Array.from({ length: n }, (_, i) => [i, (i % 2 ? -1 : 1) * (1 + i / 4)]).flat();
// A degree-3 clamped B-spline with a double knot at 2: t = [0 0 0 0 1 2 2 3.5 5 5 5 5].
const clamped = { kind: 'bspline', dim: 2, degree: 3, points: zigzag(8), knots: [0, 0, 0, 0, 1, 2, 2, 3.5, 5, 5, 5, 5] };

function maxDistance(a, b, samples = 201) {
  const { params, points } = api.sampleCurve(a, samples);
  const other = api.evaluateCurve(b, params);
  let m = 0;
  for (let j = 0; j < samples; j += 1) m = Math.max(m, Math.hypot(points[2 * j] - other[2 * j], points[2 * j + 1] - other[2 * j + 1]));
  return m;
}

test('deBoor returns every level, the span and the point on the curve', () => {
  const r = api.deBoor(clamped, 2.7);
  assert.equal(r.span, 6); // t_6 = 2 <= 2.7 < t_7 = 3.5
  assert.equal(r.firstIndex, 3);
  assert.deepEqual(r.levels.map((l) => l.length), [8, 6, 4, 2]);
  assert.deepEqual(r.alphas.map((a) => a.length), [3, 2, 1]);
  assert.deepEqual(Array.from(r.levels[0]), zigzag(8).slice(6, 14));
  const p = api.evaluateCurve(clamped, [2.7]);
  assert.ok(Math.hypot(r.point[0] - p[0], r.point[1] - p[1]) < SAME_CURVE);
});

test('insertKnot keeps the curve and reports the recomputed points', () => {
  const r = api.insertKnot(clamped, 2.7);
  assert.equal(r.curve.points.length, clamped.points.length + 2);
  assert.equal(r.curve.knots.length, clamped.knots.length + 1);
  assert.equal(r.curve.knots[r.insertedIndex], 2.7);
  assert.deepEqual(Array.from(r.recomputed), [4, 5, 6]);
  assert.ok(maxDistance(clamped, r.curve) < SAME_CURVE);
  assert.throws(() => api.insertKnot(clamped, 0), { code: 'knot-multiplicity-exceeded' });
  assert.throws(() => api.insertKnot(clamped, 6), { code: 'parameter-out-of-range' });
  // a uniform B-spline (no knots) comes back with its knots written out
  const uniform = api.insertKnot({ kind: 'bspline', dim: 2, points: zigzag(6) }, 1.5).curve;
  assert.deepEqual(Array.from(uniform.knots), [-3, -2, -1, 0, 1, 1.5, 2, 3, 4, 5, 6]);
});

test('bsplineToBezier gives one Bezier per span tracing the same curve', () => {
  const segments = api.bsplineToBezier(clamped);
  assert.deepEqual(segments.map((s) => [s.start, s.end]), [[0, 1], [1, 2], [2, 3.5], [3.5, 5]]);
  for (const s of segments) {
    assert.equal(s.points.length, 8);
    const bez = { kind: 'bezier', dim: 2, points: s.points };
    const mid = api.evaluateCurve(bez, [0.5]);
    const ref = api.evaluateCurve(clamped, [(s.start + s.end) / 2]);
    assert.ok(Math.hypot(mid[0] - ref[0], mid[1] - ref[1]) < 1e-11);
  }
});

test('knotMultiplicities gives C^(p-m) at every interior knot', () => {
  const k = api.knotMultiplicities(clamped);
  assert.deepEqual(Array.from(k.values), [0, 1, 2, 3.5, 5]);
  assert.deepEqual(Array.from(k.multiplicities), [4, 1, 2, 1, 4]);
  assert.deepEqual(Array.from(k.interior), [0, 1, 1, 1, 0]);
  assert.deepEqual(Array.from(k.continuity).slice(1, 4), [2, 1, 2]);
});

test('nurbsCircle lies on the circle to 1e-12; arcs, ellipses and conics are NURBS curves', () => {
  const circle = api.nurbsCircle({ center: [2, -1], radius: 1.75 });
  assert.equal(circle.kind, 'nurbs');
  assert.equal(circle.degree, 2);
  assert.equal(circle.weights.length, 9);
  const { points } = api.sampleCurve(circle, 4001);
  for (let j = 0; j < 4001; j += 1) assert.ok(Math.abs(Math.hypot(points[2 * j] - 2, points[2 * j + 1] + 1) - 1.75) < CIRCLE);
  const arc = api.nurbsArc({ center: [0, 0, 1], radius: 2, startAngle: 0, endAngle: Math.PI });
  assert.equal(arc.dim, 3);
  const end = api.evaluateCurve(arc, [1]);
  assert.ok(Math.abs(end[0] + 2) < 1e-14 && Math.abs(end[2] - 1) < 1e-14);
  const ellipse = api.nurbsEllipse({ center: [0, 0], rx: 3, ry: 1 });
  const e = api.evaluateCurve(ellipse, [0.1, 0.6]);
  for (let j = 0; j < 2; j += 1) assert.ok(Math.abs((e[2 * j] / 3) ** 2 + e[2 * j + 1] ** 2 - 1) < 1e-12);
  const conic = api.nurbsConic({ p0: [1, 0], p1: [1, 1], p2: [0, 1], weight: Math.SQRT1_2 });
  assert.equal(conic.conicType, 'ellipse');
  assert.equal(api.nurbsConic({ p0: [0, 0], p1: [1, 1], p2: [2, 0], weight: 3 }).conicType, 'hyperbola');
  assert.throws(() => api.nurbsCircle({ center: [0, 0], radius: -1 }), { code: 'invalid-argument' });
  assert.throws(() => api.nurbsConic({ p0: [0, 0], p1: [1, 1], p2: [2, 0], weight: 0 }), { code: 'invalid-weight' });
});

test('curvature, arcLength and arcLengthParams on the circle', () => {
  const circle = api.nurbsCircle({ center: [0, 0], radius: 2 });
  const k = api.curvature(circle, [0, 0.2, 0.9]);
  for (const v of k.curvature) assert.ok(Math.abs(v - 0.5) < 1e-12);
  assert.equal(k.tangent.length, 6);
  assert.ok(Math.abs(api.arcLength(circle) - 4 * Math.PI) < 1e-12 * 4 * Math.PI);
  const a = api.arcLengthParams(circle, 9);
  assert.equal(a.params.length, 9);
  assert.ok(Math.abs(a.total - 4 * Math.PI) < 1e-11);
  for (let j = 0; j < 8; j += 1) {
    assert.ok(Math.abs(api.arcLength(circle, a.params[j], a.params[j + 1]) - Math.PI / 2) < 1e-10);
  }
});

test('jointContinuity classifies constructed joints with evidence', () => {
  const bez = (points) => ({ kind: 'bezier', dim: 2, points });
  const a = bez([0, 0, 1, 1, 2, 1, 3, 0]);
  const c1 = api.jointContinuity(a, bez([3, 0, 4, -1, 6, 0, 7, 2]));
  assert.equal(c1.parametric, 1);
  assert.equal(c1.geometric, 1);
  assert.equal(c1.evidence.a.length, 6);
  const g1 = api.jointContinuity(a, bez([3, 0, 5, -2, 6, 0, 7, 1]), { tolerance: 1e-9 });
  assert.equal(g1.parametric, 0);
  assert.equal(g1.geometric, 1);
  assert.ok(Math.abs(g1.evidence.ratio - 2) < 1e-12);
  const corner = api.jointContinuity(a, bez([3, 0, 4, 1, 5, 0, 6, 1]));
  assert.deepEqual([corner.parametric, corner.geometric], [0, 0]);
  const zero = api.jointContinuity(bez([0, 0, 1, 1, 3, 0, 3, 0]), bez([3, 0, 3, 0, 4, 2, 6, 1]));
  assert.ok(zero.parametric >= 1);
  assert.equal(zero.geometric, 0);
  assert.equal(zero.evidence.zeroTangent, true);
  assert.throws(() => api.jointContinuity(a, { kind: 'bezier', dim: 3, points: [0, 0, 0, 1, 1, 1] }), { code: 'dimension-mismatch' });
  assert.throws(() => api.jointContinuity(a, a, { tolerance: -1 }), { code: 'invalid-argument' });
});

test('interpolatePolynomial returns the Vandermonde system of lecture 000', () => {
  const r = api.interpolatePolynomial([0, 0, 1, 1, 2, 0], 2);
  assert.deepEqual(Array.from(r.nodes), [0, 0.5, 1]);
  assert.deepEqual(Array.from(r.vandermonde), [0, 0, 1, 0.25, 0.5, 1, 1, 1, 1]);
  // y(u) = 4u - 4u^2: rows (a_2, a_1, a_0) = (-4, 4, 0); x(u) = 2u
  const y = [r.coefficients[1], r.coefficients[3], r.coefficients[5]];
  y.forEach((v, i) => assert.ok(Math.abs(v - [-4, 4, 0][i]) < 1e-12));
  const p = api.evaluateCurve(r.curve, [0.5]);
  assert.ok(Math.abs(p[0] - 1) < 1e-12 && Math.abs(p[1] - 1) < 1e-12);
});

test('samplePatch: grid layout, normals and the Bezier twist 9(p00 - p01 - p10 + p11)', () => {
  const points = [];
  for (let i = 0; i < 4; i += 1) for (let j = 0; j < 4; j += 1) points.push(i, j, i === 1 && j === 1 ? 1 : 0);
  const s = api.samplePatch({ kind: 'bezier', points, nu: 4, nv: 3 });
  assert.equal(s.positions.length, 4 * 3 * 3);
  assert.equal(s.normals.length, 4 * 3 * 3);
  assert.equal(s.twists.length, 12);
  assert.ok(Math.abs(s.twists[2] - 9) < 1e-12); // z: 9 (0 - 0 - 0 + 1)
  assert.deepEqual(Array.from(s.positions.slice(3 * (3 * 3 + 2), 3 * (3 * 3 + 2) + 3)), [3, 3, 0]); // p(1,1) = p33
  assert.throws(() => api.samplePatch({ kind: 'bspline', points, nu: 2, nv: 2 }), { code: 'unknown-basis' });
  assert.throws(() => api.samplePatch({ kind: 'bezier', points: points.slice(3), nu: 2, nv: 2 }), { code: 'wrong-point-count' });
});

test('transformPoints applies a homogeneous affine matrix (affine invariance demo)', () => {
  const m = [0, -1, 2, 1, 0, 3, 0, 0, 1]; // rotate 90 degrees, translate (2, 3)
  const bez = { kind: 'bezier', dim: 2, points: zigzag(4) };
  const moved = { ...bez, points: api.transformPoints(bez.points, 2, m) };
  const a = api.transformPoints(api.evaluateCurve(bez, [0.3, 0.8]), 2, m);
  const b = api.evaluateCurve(moved, [0.3, 0.8]);
  a.forEach((v, i) => assert.ok(Math.abs(v - b[i]) < 1e-12));
});

test('a thousand failures of every algorithm leave the heap as it was', () => {
  const calls = [
    () => api.deBoor(clamped, 9),
    () => api.insertKnot(clamped, 0),
    () => api.bsplineToBezier({ ...clamped, knots: [0, 0, 0, 0, 1, 2, 2, 3.5, 5, 5, 5] }),
    () => api.curvature(clamped, [NaN]),
    () => api.arcLength(clamped, 4, 1),
    () => api.segmentMatrices(clamped, 9),
    () => api.deCasteljau([0, 0, 1], 2, 0.5),
    () => api.jointContinuity(clamped, { ...clamped, weights: [1] }),
  ];
  for (const call of calls) assert.throws(call);
  const before = api.memoryUsage().heapInUse;
  for (let i = 0; i < 1000; i += 1) for (const call of calls) assert.throws(call, (err) => typeof err.code === 'string');
  assert.equal(api.memoryUsage().heapInUse, before);
  assert.equal(api.deBoor(clamped, 2.7).levels.length, 4);
});
