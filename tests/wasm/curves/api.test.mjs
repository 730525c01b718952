// The JS contract of the curves API: shapes, strides, defaults, the lecture's matrices
// through the public API, and errors as data (docs/api-curves.md).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();

// Tolerances
const EXACT = 1e-14; // small rational matrix entries
const SAME_CURVE = 1e-12; // one curve evaluated by two routes (model units)

// docs/benchmarks.md's cubic Bezier.
const benchBezier = { kind: 'bezier', dim: 3, points: [0, 0, 0, 1, 2, 0.5, 3, 2, 1, 4, 0, 1.5] };
// A zig-zag polygon P_i = (i, (-1)^i (1 + i/4)).
const zigzag = (n) => Array.from({ length: n }, (_, i) => [i, (i % 2 ? -1 : 1) * (1 + i / 4)]).flat();

function close(actual, expected, tol, what) {
  assert.equal(actual.length, expected.length, `${what}: length`);
  for (let i = 0; i < expected.length; i += 1) {
    assert.ok(Math.abs(actual[i] - expected[i]) <= tol, `${what}[${i}] = ${actual[i]}, expected ${expected[i]}`);
  }
}

test('basisMatrix gives lecture 003 matrices, segmentMatrices both conventions', () => {
  assert.deepEqual(Array.from(api.basisMatrix('bezier')), [-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0]);
  close(api.basisMatrix('catmull-rom'), [-1, 3, -3, 1, 2, -5, 4, -1, -1, 0, 1, 0, 0, 2, 0, 0].map((v) => v / 2), EXACT, 'M_CR');
  close(api.basisMatrix('bspline'), [-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0].map((v) => v / 6), EXACT, 'M_BS');
  const hermite = { kind: 'hermite', dim: 2, points: [0, 0, 4, 0], tangents: [3, 6, 3, -6] };
  const s = api.segmentMatrices(hermite, 0);
  assert.deepEqual(Array.from(s.M), [2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0]);
  // lecture 001 writes M_H transposed: [2 -3 0 1; -2 3 0 0; 1 -2 1 0; 1 -1 0 0]
  assert.deepEqual(Array.from(s.MT), [2, -3, 0, 1, -2, 3, 0, 0, 1, -2, 1, 0, 1, -1, 0, 0]);
  assert.deepEqual(s.labels, ['p_0', 'p_1', 't_0', 't_1']);
  assert.deepEqual(Array.from(s.G), [0, 0, 4, 0, 3, 6, 3, -6]);
  // C = M G, row r multiplies u^(3-r)
  const [a, b, c, d] = [0, 1, 2, 3].map((r) => [s.C[2 * r], s.C[2 * r + 1]]);
  const u = 0.3;
  const p = api.evaluateCurve(hermite, [u]);
  close(p, [0, 1].map((k) => a[k] * u ** 3 + b[k] * u ** 2 + c[k] * u + d[k]), SAME_CURVE, 'P(0.3)');
});

test('evaluateCurve, evaluateDerivative, evaluateWithDerivatives: layouts and values', () => {
  const pts = api.evaluateCurve(benchBezier, new Float64Array([0, 0.5, 1]));
  assert.ok(pts instanceof Float64Array);
  close(pts, [0, 0, 0, 2, 1.5, 0.75, 4, 0, 1.5], SAME_CURVE, 'points');
  // P'(0) = 3 (P1 - P0), P'(1) = 3 (P3 - P2)
  close(api.evaluateDerivative(benchBezier, [0, 1], 1), [3, 6, 1.5, 3, -6, 1.5], SAME_CURVE, 'P\'');
  // P''(0) = 6 (P0 - 2 P1 + P2)
  close(api.evaluateDerivative(benchBezier, [0], 2), [6, -12, 0], SAME_CURVE, 'P\'\'');
  const all = api.evaluateWithDerivatives(benchBezier, [0, 1], 2);
  assert.equal(all.length, 2 * 3 * 3);
  close(all.slice(0, 9), [0, 0, 0, 3, 6, 1.5, 6, -12, 0], SAME_CURVE, 'jet at 0');
});

test('curveDomain and sampleCurve follow the documented domains', () => {
  assert.deepEqual(api.curveDomain({ kind: 'bspline', dim: 2, points: zigzag(7) }),
    { start: 0, end: 4, degree: 3, controlPointCount: 7, segmentCount: 4 });
  assert.deepEqual(api.curveDomain({ kind: 'catmull-rom', dim: 2, points: zigzag(6) }),
    { start: 0, end: 3, degree: 3, controlPointCount: 6, segmentCount: 3 });
  assert.deepEqual(api.curveDomain({ kind: 'hermite', dim: 2, points: zigzag(3), tangents: zigzag(3) }),
    { start: 0, end: 2, degree: 3, controlPointCount: 3, segmentCount: 2 });
  const clamped = { kind: 'bspline', dim: 2, degree: 2, points: zigzag(5), knots: [0, 0, 0, 1, 3, 4, 4, 4] };
  assert.deepEqual(api.curveDomain(clamped), { start: 0, end: 4, degree: 2, controlPointCount: 5, segmentCount: 3 });
  const { params, points } = api.sampleCurve(clamped, 5);
  assert.deepEqual(Array.from(params), [0, 1, 2, 3, 4]);
  assert.equal(points.length, 10);
  close(points.slice(0, 2), [0, 1], SAME_CURVE, 'clamped start = P0');
  close(points.slice(8), zigzag(5).slice(8), SAME_CURVE, 'clamped end = P4');
});

test('blendingFunctions: values[count*j + i], partition of unity', () => {
  const curve = { kind: 'nurbs', dim: 2, degree: 2, points: zigzag(5), weights: [1, 2, 0.5, 1, 3] };
  const params = [0, 0.4, 1.1, 2.9, 3];
  const { count, values } = api.blendingFunctions(curve, params);
  assert.equal(count, 5);
  assert.equal(values.length, 25);
  for (let j = 0; j < params.length; j += 1) {
    let sum = 0;
    for (let i = 0; i < count; i += 1) {
      assert.ok(values[count * j + i] >= 0);
      sum += values[count * j + i];
    }
    assert.ok(Math.abs(sum - 1) < SAME_CURVE);
  }
});

test('deCasteljau gives every level, subdivision matches lecture 002 at 1/2', () => {
  const r = api.deCasteljau(benchBezier.points, 3, 0.5);
  assert.equal(r.degree, 3);
  assert.deepEqual(r.levels.map((l) => l.length), [12, 9, 6, 3]);
  close(r.levels[1], [0.5, 1, 0.25, 2, 2, 0.75, 3.5, 1, 1.25], EXACT, 'level 1 midpoints');
  close(r.point, [2, 1.5, 0.75], EXACT, 'point');
  const { left, right } = api.bezierSubdivisionMatrices(3, 0.5);
  close(left, [8, 0, 0, 0, 4, 4, 0, 0, 2, 4, 2, 0, 1, 3, 3, 1].map((v) => v / 8), EXACT, 'G_B^L');
  close(right, [1, 3, 3, 1, 0, 2, 4, 2, 0, 0, 4, 4, 0, 0, 0, 8].map((v) => v / 8), EXACT, 'G_B^R');
  const halves = api.subdivideBezier(benchBezier.points, 3, 0.5);
  close(halves.left.slice(9), [2, 1.5, 0.75], EXACT, 'left ends on P(1/2)');
  close(halves.right.slice(0, 3), [2, 1.5, 0.75], EXACT, 'right starts on P(1/2)');
});

test('convertBasis: Bezier to Hermite is p0, p3, 3(p1-p0), 3(p3-p2)', () => {
  const q = api.convertBasis([0, 0, 1, 2, 3, 2, 4, 0], 2, 'bezier', 'hermite');
  close(q, [0, 0, 4, 0, 3, 6, 3, -6], 1e-13, 'q');
});

test('every bad input is an Error with a code; the module stays usable', () => {
  const cases = [
    [() => api.evaluateCurve({ kind: 'bezir', dim: 2, points: [0, 0, 1, 1] }, [0]), 'unknown-curve-kind', /bezir/],
    [() => api.evaluateCurve({ kind: 'bspline', dim: 2, degree: 2, points: zigzag(4), knots: [0, 0, 0, 2, 1, 1, 1] }, [0.5]), 'decreasing-knots', /t_3 = 2 > t_4 = 1/],
    [() => api.evaluateCurve({ kind: 'bspline', dim: 2, degree: 2, points: zigzag(4), knots: [0, 0, 0, 1, 1, 1] }, [0.5]), 'wrong-knot-count', /K \+ p \+ 1 = 7/],
    [() => api.evaluateCurve({ kind: 'nurbs', dim: 2, points: zigzag(4), weights: [1, 1, 0, 1] }, [0.5]), 'invalid-weight', /point 2/],
    [() => api.evaluateCurve({ kind: 'catmull-rom', dim: 2, points: zigzag(3) }, [0.5]), 'too-few-points', /at least 4/],
    [() => api.evaluateCurve({ kind: 'bspline', dim: 2, degree: 30, points: zigzag(40) }, [0.5]), 'degree-out-of-range', /1 to 20/],
    [() => api.evaluateCurve({ kind: 'bezier', dim: 2, points: [0, 0, NaN, 1] }, [0.5]), 'non-finite-input', /point 1 \(x\)/],
    [() => api.evaluateCurve(benchBezier, [0.5, Infinity]), 'non-finite-input', /parameter 1/],
    [() => api.evaluateCurve(benchBezier, [1.5]), 'parameter-out-of-range', /\[0, 1\]/],
    [() => api.evaluateCurve({ kind: 'bezier', dim: 4, points: [0, 0, 0, 0] }, [0]), 'invalid-dimension', /2 or 3/],
    [() => api.evaluateCurve({ kind: 'bezier', dim: 2, points: 'abc' }, [0]), 'invalid-argument', /points/],
    [() => api.evaluateCurve(benchBezier, ['x']), 'invalid-argument', /params/],
    [() => api.segmentMatrices({ kind: 'catmull-rom', dim: 2, points: zigzag(5) }, 2), 'segment-out-of-range', /0 to 1/],
  ];
  for (const [call, code, message] of cases) {
    assert.throws(call, (err) => err.code === code && message.test(err.message), `expected ${code}`);
  }
  close(api.evaluateCurve(benchBezier, [1]), [4, 0, 1.5], EXACT, 'still usable');
});

test('10,000 failing calls leave the module usable and the heap does not grow', () => {
  const bad = { kind: 'bspline', dim: 2, degree: 2, points: zigzag(4), knots: [0, 0, 0, 2, 1, 1, 1] };
  const good = { kind: 'bspline', dim: 2, degree: 2, points: zigzag(4), knots: [0, 0, 0, 0.5, 1, 1, 1] };
  const params = new Float64Array(1000).map((_, j) => j / 999);
  // warm up: the first calls may allocate lasting runtime structures
  for (let i = 0; i < 100; i += 1) {
    assert.throws(() => api.evaluateCurve(bad, params), { code: 'decreasing-knots' });
    assert.throws(() => api.evaluateCurve(good, [2]), { code: 'parameter-out-of-range' });
  }
  const before = api.memoryUsage().heapInUse;
  for (let i = 0; i < 5000; i += 1) {
    assert.throws(() => api.evaluateCurve(bad, params), { code: 'decreasing-knots' });
    assert.throws(() => api.evaluateCurve(good, [0.5, 2]), { code: 'parameter-out-of-range' });
  }
  assert.equal(api.memoryUsage().heapInUse, before);
  const p = api.evaluateCurve(good, params);
  assert.equal(p.length, 2000);
  close(p.slice(0, 2), [0, 1], SAME_CURVE, 'clamped start after the errors');
});

test('options.out is filled and returned; a wrong buffer is refused', () => {
  const out = new Float64Array(6);
  const r = api.evaluateCurve(benchBezier, [0, 1], { out });
  assert.equal(r, out);
  close(out, [0, 0, 0, 4, 0, 1.5], EXACT, 'out');
  const d = new Float64Array(2 * 2 * 3);
  assert.equal(api.evaluateWithDerivatives(benchBezier, [0, 1], 1, { out: d }), d);
  close(d.slice(3, 6), [3, 6, 1.5], SAME_CURVE, 'P\'(0) in out');
  assert.throws(() => api.evaluateCurve(benchBezier, [0, 1], { out: new Float64Array(5) }), { code: 'invalid-argument' });
  assert.throws(() => api.evaluateCurve(benchBezier, [0, 1], { out: [0, 0, 0, 0, 0, 0] }), { code: 'invalid-argument' });
});

test('the uniform B-spline does not interpolate its control points; Catmull-Rom interpolates the inner ones', () => {
  const points = zigzag(6);
  const { points: bs } = api.sampleCurve({ kind: 'bspline', dim: 2, points }, 301);
  const { points: cr } = api.sampleCurve({ kind: 'catmull-rom', dim: 2, points }, 301);
  const hits = (samples, i) => {
    for (let j = 0; j < samples.length / 2; j += 1) {
      if (Math.hypot(samples[2 * j] - points[2 * i], samples[2 * j + 1] - points[2 * i + 1]) < SAME_CURVE) return true;
    }
    return false;
  };
  for (let i = 0; i < 6; i += 1) assert.equal(hits(bs, i), false, `B-spline passes P${i}`);
  // Catmull-Rom samples at u = 0, 1, 2, 3 are exactly P1..P4 (the sample step is 3/300)
  for (let i = 1; i <= 4; i += 1) assert.equal(hits(cr, i), true, `Catmull-Rom misses P${i}`);
  assert.equal(hits(cr, 0), false);
  assert.equal(hits(cr, 5), false);
});
