// Through the JS API: the interpolating polynomial and lecture
// 000's V^-1 against exact rational arithmetic (BigInt) at random offsets and scales, the
// core's limits as the curve explorer reads them, NURBS weights at any magnitude, and the
// Bezier segments of a long B-spline.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { lesson, MAX_LIST } from '../../../web/js/lessons/curves/lesson.js';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();
const EPS = Number.EPSILON;

// ---- exact rationals {n, d} (BigInt, d > 0)
const gcd = (a, b) => { a = a < 0n ? -a : a; b = b < 0n ? -b : b; while (b) [a, b] = [b, a % b]; return a; };
const rat = (n, d = 1n) => { if (d < 0n) { n = -n; d = -d; } const g = gcd(n, d) || 1n; return { n: n / g, d: d / g }; };
const add = (x, y) => rat(x.n * y.d + y.n * x.d, x.d * y.d);
const sub = (x, y) => rat(x.n * y.d - y.n * x.d, x.d * y.d);
const mul = (x, y) => rat(x.n * y.n, x.d * y.d);
const div = (x, y) => rat(x.n * y.d, x.d * y.n);
const abs = (x) => rat(x.n < 0n ? -x.n : x.n, x.d);
// a double exactly as a rational (every finite double is one)
function exact(v) {
  let m = v, e = 0;
  while (!Number.isInteger(m)) { m *= 2; e += 1; }
  return rat(BigInt(m), 1n << BigInt(e));
}
// the nearest double, well enough for a tolerance of many ulps: a quotient of 80 bits
const bits = (v) => (v < 0n ? -v : v).toString(2).length;
const toNumber = (x) => {
  if (x.n === 0n) return 0;
  const shift = 80 + bits(x.d) - bits(x.n);
  const q = shift >= 0 ? (x.n << BigInt(shift)) / x.d : x.n / (x.d << BigInt(-shift));
  return Number(q) * 2 ** -shift;
};

// Random nodes 2^e (M + m_i) (m_i distinct small integers), data y_i integers times 2^f,
// parameter 2^e (M + a/64): every value is a double, and the test's arithmetic is exact.
function randomCase(rnd) {
  const K = 2 + Math.floor(rnd() * 5);
  const ms = new Set();
  while (ms.size < K) ms.add(Math.floor(rnd() * 24));
  const m = [...ms].sort((a, b) => a - b);
  const e = Math.floor(rnd() * 60) - 30, f = Math.floor(rnd() * 40) - 20;
  const M = Math.floor(rnd() * 2 ** 20) * (rnd() < 0.5 ? -1 : 1);
  const nodes = m.map((mi) => 2 ** e * (M + mi));
  const ys = [];
  for (let i = 0; i < 2 * K; i += 1) ys.push(2 ** f * (Math.floor(rnd() * 2001) - 1000));
  const a = 64 * m[0] + Math.floor(rnd() * (64 * (m[K - 1] - m[0]) + 1));
  return { K, nodes, points: ys, x: 2 ** e * (M + a / 64) };
}

test('the interpolant and its derivative equal exact rational Lagrange at random offsets and scales (13.1)', () => {
  const rnd = random(131);
  for (let trial = 0; trial < 1500; trial += 1) {
    const { K, nodes, points, x } = randomCase(rnd);
    const curve = { kind: 'interpolation', dim: 2, points, nodes };
    const got = api.evaluateWithDerivatives(curve, [x], 1);
    const u = nodes.map(exact), X = exact(x);
    for (let c = 0; c < 2; c += 1) {
      // p(x) = sum y_i L_i(x); p'(x) = sum y_i sum_(m != i) prod_(j != i, m) (x - u_j) / prod_(j != i) (u_i - u_j)
      let value = rat(0n), slope = rat(0n), scaleV = rat(0n), scaleD = rat(0n);
      for (let i = 0; i < K; i += 1) {
        let den = rat(1n), num = rat(1n), numAbs = rat(1n);
        for (let j = 0; j < K; j += 1) if (j !== i) { den = mul(den, sub(u[i], u[j])); num = mul(num, sub(X, u[j])); numAbs = mul(numAbs, abs(sub(X, u[j]))); }
        const y = exact(points[2 * i + c]);
        value = add(value, div(mul(y, num), den));
        scaleV = add(scaleV, abs(div(mul(y, numAbs), den)));
        let d = rat(0n), dAbs = rat(0n);
        for (let m = 0; m < K; m += 1) {
          if (m === i) continue;
          let term = rat(1n), termAbs = rat(1n);
          for (let j = 0; j < K; j += 1) if (j !== i && j !== m) { term = mul(term, sub(X, u[j])); termAbs = mul(termAbs, abs(sub(X, u[j]))); }
          d = add(d, term);
          dAbs = add(dAbs, termAbs);
        }
        slope = add(slope, div(mul(y, d), den));
        scaleD = add(scaleD, abs(div(mul(y, dAbs), den)));
      }
      // Backward-stable bound: a few roundings per factor, times the sum of |terms| (the
      // condition of the data-to-value map), 16 K eps in all.
      const tolV = 16 * K * EPS * toNumber(scaleV), tolD = 16 * K * EPS * toNumber(scaleD);
      const msg = `trial ${trial}: nodes ${nodes}, x ${x}`;
      assert.ok(Math.abs(got[c] - toNumber(value)) <= tolV, `${msg}: value ${got[c]} vs ${toNumber(value)}`);
      assert.ok(Math.abs(got[2 + c] - toNumber(slope)) <= tolD, `${msg}: slope ${got[2 + c]} vs ${toNumber(slope)}`);
    }
  }
});

test("lecture 000's V^-1 as shown equals the exact inverse at random offsets and scales (13.1)", () => {
  const rnd = random(1313);
  for (let trial = 0; trial < 400; trial += 1) {
    const { K, nodes, points } = randomCase(rnd);
    const r = api.interpolatePolynomial(points, 2, nodes);
    const u = nodes.map(exact);
    // column j: coefficients (ascending) of prod_(m != j) (u - u_m) / (u_j - u_m), and the
    // same with |u_m| (no cancellation): the componentwise scale of the rounding
    for (let j = 0; j < K; j += 1) {
      let poly = [rat(1n)], polyAbs = [rat(1n)], den = rat(1n);
      for (let m = 0; m < K; m += 1) {
        if (m === j) continue;
        const next = Array.from({ length: poly.length + 1 }, () => rat(0n));
        const nextAbs = Array.from({ length: poly.length + 1 }, () => rat(0n));
        poly.forEach((a, k) => { next[k + 1] = add(next[k + 1], a); next[k] = sub(next[k], mul(a, u[m])); });
        polyAbs.forEach((a, k) => { nextAbs[k + 1] = add(nextAbs[k + 1], a); nextAbs[k] = add(nextAbs[k], mul(a, abs(u[m]))); });
        poly = next; polyAbs = nextAbs;
        den = mul(den, sub(u[j], u[m]));
      }
      for (let k = 0; k < K; k += 1) {
        const want = toNumber(div(poly[k], den)), scale = Math.abs(toNumber(div(polyAbs[k], den)));
        const shown = r.inverse[(K - 1 - k) * K + j];
        assert.ok(Math.abs(shown - want) <= 8 * K * EPS * scale, `trial ${trial}: V^-1[${K - 1 - k}][${j}] = ${shown}, exact ${want}`);
      }
    }
  }
});

test('the curve explorer reads the interpolation limit from the core (13.1)', () => {
  const { maxInterpolationPoints } = api.curveLimits();
  assert.ok(maxInterpolationPoints >= 32);
  assert.ok(MAX_LIST >= maxInterpolationPoints, 'the share-link parse bound is above the core limit');
  const pts = Array.from({ length: maxInterpolationPoints }, (_, i) => [i / 4, Math.sin(i)]);
  const state = { ...lesson.defaultState(), family: 'interpolation', points: pts, tangents: pts.map(() => [1, 0]), weights: pts.map(() => 1) };
  assert.equal(lesson.checkState(state), null);
  lesson.schema.points(pts, 'points'); // parses (throws otherwise)
  const flat = pts.flat();
  const r = api.interpolatePolynomial(flat, 2);
  const onCurve = api.evaluateCurve(r.curve, r.nodes);
  const size = Math.max(...flat.map(Math.abs));
  for (let i = 0; i < flat.length; i += 1) assert.ok(Math.abs(onCurve[i] - flat[i]) <= 8 * EPS * size, `point ${i >> 1}`);
  assert.throws(() => api.interpolatePolynomial([...flat, 9, 9], 2), (err) => err.code === 'degree-out-of-range' && err.message.includes(`${maxInterpolationPoints} points`));
});

test('NURBS with weights at any magnitude: finite, the same curve (13.5)', () => {
  const points = [0, 0, 1, 2, 3, 2, 4, 0, 5, 1];
  const knots = [0, 0, 0, 0, 0.5, 1, 1, 1, 1];
  const params = Array.from({ length: 21 }, (_, i) => i / 20);
  const plain = api.evaluateWithDerivatives({ kind: 'bspline', dim: 2, points, knots }, params, 2);
  for (const w of [5e-324, 1e-320, 1e-300, 1e300, Number.MAX_VALUE]) {
    const got = api.evaluateWithDerivatives({ kind: 'nurbs', dim: 2, points, knots, weights: points.filter((_, i) => i % 2 === 0).map(() => w) }, params, 2);
    got.forEach((v, i) => assert.ok(Number.isFinite(v) && Math.abs(v - plain[i]) <= 1e-12 * 50, `weight ${w}, value ${i}: ${v} vs ${plain[i]}`));
  }
  assert.throws(() => api.evaluateCurve({ kind: 'nurbs', dim: 2, points, knots, weights: [1, 1e301, 1, 1, 1] }, [0.5]),
    (err) => err.code === 'weight-ratio-out-of-range');
});

test('bsplineToBezier on 20,000 points: one segment per span, each the B-spline there (13.16)', () => {
  const K = 20000;
  const points = [];
  for (let i = 0; i < K; i += 1) points.push(i, Math.sin(i));
  const curve = { kind: 'bspline', dim: 2, points };
  const segments = api.bsplineToBezier(curve);
  assert.equal(segments.length, K - 3);
  for (const s of [0, 7, 9999, K - 4]) {
    const seg = segments[s];
    const want = api.evaluateCurve(curve, [seg.start + 0.3 * (seg.end - seg.start)]);
    const got = api.evaluateCurve({ kind: 'bezier', dim: 2, points: seg.points }, [0.3]);
    for (let k = 0; k < 2; k += 1) assert.ok(Math.abs(got[k] - want[k]) <= 1e-12 * K, `segment ${s}`);
  }
});
