// The lectures' notation through the public API: the basis matrices as the slides
// write them (one fraction, integer entries), typed from lecture 003, and the segment
// matrix's form (null when the matrix has no small common denominator).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();

const LECTURE_003 = {
  hermite: [1, [2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0]],
  bezier: [1, [-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0]],
  bspline: [6, [-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0]],
  'catmull-rom': [2, [-1, 3, -3, 1, 2, -5, 4, -1, -1, 0, 1, 0, 0, 2, 0, 0]],
};

test('basisMatrixRational gives lecture 003 fraction and integers', () => {
  for (const [kind, [denominator, integers]] of Object.entries(LECTURE_003)) {
    const r = api.basisMatrixRational(kind);
    assert.equal(r.denominator, denominator, kind);
    assert.deepEqual(Array.from(r.numerators), integers, kind);
  }
  assert.throws(() => api.basisMatrixRational('bsplin'), (e) => e.code === 'unknown-basis');
});

test('segmentMatrices carries the rational form of M: 1/2 for Catmull-Rom, null for irregular knots', () => {
  const cr = api.segmentMatrices({ kind: 'catmull-rom', dim: 2, points: [0, 0, 1, 1, 2, 0, 3, 1] }, 0);
  assert.equal(cr.rational.denominator, 2);
  assert.deepEqual(Array.from(cr.rational.numerators), LECTURE_003['catmull-rom'][1]);
  // Each numerator over the denominator is the entry the core multiplies with.
  cr.rational.numerators.forEach((n, i) => assert.ok(Math.abs(n / 2 - cr.M[i]) <= 1e-15, `entry ${i}`));
  const uniform = api.segmentMatrices({ kind: 'bspline', dim: 2, degree: 3, points: [0, 0, 1, 2, 2, -1, 3, 1, 4, 0], knots: [-3, -2, -1, 0, 1, 2, 3, 4, 5] }, 1);
  assert.equal(uniform.rational.denominator, 6);
  assert.deepEqual(Array.from(uniform.rational.numerators), LECTURE_003.bspline[1]);
  const irregular = api.segmentMatrices({ kind: 'bspline', dim: 2, degree: 3, points: [0, 0, 1, 2, 2, -1, 3, 1, 4, 0], knots: [0, 0, 0, 0, Math.SQRT1_2, 1, 1, 1, 1] }, 0);
  assert.equal(irregular.rational, null);
});

test('bezierSubdivisionMatrices at t = 1/2 carry lecture 002\'s G_B^L and G_B^R as 1/8 [integers]', () => {
  // Lecture 002 (002_5284cf65dc3cb6f3.txt), typed from the slide.
  const GL = [8, 0, 0, 0, 4, 4, 0, 0, 2, 4, 2, 0, 1, 3, 3, 1];
  const GR = [1, 3, 3, 1, 0, 2, 4, 2, 0, 0, 4, 4, 0, 0, 0, 8];
  const s = api.bezierSubdivisionMatrices(3, 0.5);
  assert.equal(s.leftRational.denominator, 8);
  assert.deepEqual(Array.from(s.leftRational.numerators), GL);
  assert.equal(s.rightRational.denominator, 8);
  assert.deepEqual(Array.from(s.rightRational.numerators), GR);
  // At t = 1/3 the left matrix's rows are (1-t, t)^i expanded: denominators 3^3 = 27.
  assert.equal(api.bezierSubdivisionMatrices(3, 1 / 3).leftRational.denominator, 27);
  // An irrational t has no slide form.
  assert.equal(api.bezierSubdivisionMatrices(3, Math.SQRT1_2).leftRational, null);
});

// Lecture 002's ascending form (b(u) = M^T u with u = (1, u, u^2, u^3);
// 002 prints M_s and the blending functions, typed here) and lecture 001's transposed one.
const LECTURE_002 = {
  // columns: 002's b(u) = (2u^3 - 3u^2 + 1, -2u^3 + 3u^2, u^3 - 2u^2 + u, u^3 - u^2) expanded
  hermite: [1, [1, 0, 0, 0, 0, 0, 1, 0, -3, 3, -2, -1, 2, -2, 1, 1]],
  // columns: ((1-u)^3, 3u(1-u)^2, 3u^2(1-u), u^3) expanded
  bezier: [1, [1, 0, 0, 0, -3, 3, 0, 0, 3, -6, 3, 0, -1, 3, -3, 1]],
  // M_s = B^-1 A as printed
  bspline: [6, [1, 4, 1, 0, -3, 0, 3, 0, 3, -6, 3, 0, -1, 3, -3, 1]],
};
// Lecture 001's printed M_H and M_B.
const LECTURE_001 = {
  hermite: [1, [2, -3, 0, 1, -2, 3, 0, 0, 1, -2, 1, 0, 1, -1, 0, 0]],
  bezier: [1, [-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0]],
};

test('basisMatrixRational(kind, form) gives lecture 002\'s and lecture 001\'s printed matrices', () => {
  for (const [form, table] of [['ascending', LECTURE_002], ['transposed', LECTURE_001], ['descending', LECTURE_003]]) {
    for (const [kind, [denominator, integers]] of Object.entries(table)) {
      const r = api.basisMatrixRational(kind, form);
      assert.equal(r.denominator, denominator, `${form} ${kind}`);
      assert.deepEqual(Array.from(r.numerators), integers, `${form} ${kind}`);
    }
  }
  assert.throws(() => api.basisMatrixRational('bspline', 'sideways'), (e) => e.code === 'unknown-form' && /ascending \(002\)/.test(e.message));
});

test('segmentMatrices(..., { form }) shows M, G, C as the lecture writes them; the products hold', () => {
  const curve = { kind: 'hermite', dim: 2, points: [0, 0, 3, 1, 5, -1], tangents: [1, 2, 2, 0, 1, -1] };
  for (const form of ['descending', 'ascending', 'transposed']) {
    const s = api.segmentMatrices(curve, 1, { form });
    const { M, G, C, size: n, geometryRows: gr, geometryColumns: gc } = s.shown;
    assert.equal(s.shown.form, form);
    // 002: C = M g; 001: G M = C^T (G a row of points). Recomputed here.
    for (let i = 0; i < gr; i += 1) {
      for (let j = 0; j < gc; j += 1) {
        let sum = 0;
        for (let k = 0; k < n; k += 1) sum += form === 'transposed' ? G[n * i + k] * M[n * k + j] : M[n * i + k] * G[gc * k + j];
        assert.ok(Math.abs(sum - C[gc * i + j]) <= 1e-12 * 5, `${form} C[${i}][${j}]`);
      }
    }
    // The shown M of a Hermite segment is the lecture's matrix.
    const expected = { descending: LECTURE_003, ascending: LECTURE_002, transposed: LECTURE_001 }[form].hermite[1];
    assert.deepEqual(Array.from(s.shown.rational.numerators), expected, form);
  }
  assert.throws(() => api.segmentMatrices(curve, 0, { form: 'reversed' }), (e) => e.code === 'unknown-form');
});

test('isBezierInDisguise: lecture 002\'s {0,0,0,0,1,1,1,1} yes; more points or spread ends no; bad input refused', () => {
  assert.equal(api.isBezierInDisguise([0, 0, 0, 0, 1, 1, 1, 1], 3), true);
  assert.equal(api.isBezierInDisguise([2, 2, 2, 5, 5, 5], 2), true);
  assert.equal(api.isBezierInDisguise([0, 0, 0, 0, 0.5, 1, 1, 1, 1], 3), false);
  assert.equal(api.isBezierInDisguise([-3, -2, -1, 0, 1, 2, 3, 4], 3), false);
  assert.throws(() => api.isBezierInDisguise([0, 0, 1], 3), (e) => e.code === 'wrong-knot-count');
  // The curves agree exactly when it says so: the B-spline and the Bezier of the same points.
  const points = [0, 0, 1, 3, 4, 2, 5, -1];
  const params = Float64Array.from({ length: 21 }, (_, j) => j / 20);
  const b = api.evaluateCurve({ kind: 'bezier', dim: 2, points }, params);
  const s = api.evaluateCurve({ kind: 'bspline', dim: 2, degree: 3, points, knots: [0, 0, 0, 0, 1, 1, 1, 1] }, params);
  assert.ok(api.maxDistance(b, s, 2).distance <= 1e-12 * 5);
});
