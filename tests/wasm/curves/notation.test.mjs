// Issue 18, the lectures' notation through the public API: the basis matrices as the slides
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
