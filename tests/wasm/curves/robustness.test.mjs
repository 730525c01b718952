// Random valid and invalid curves: every call either returns finite numbers of the documented
// length or throws an Error with a stable code; the heap is the same afterwards. A fixed
// seed keeps the run reproducible.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline, WingsplineError } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();

const KINDS = ['bezier', 'bspline', 'nurbs', 'hermite', 'catmull-rom', 'cardinal', 'interpolation'];
const CODES = new Set(['unknown-curve-kind', 'invalid-dimension', 'invalid-argument', 'invalid-points', 'non-finite-input',
  'too-few-points', 'degree-out-of-range', 'wrong-knot-count', 'decreasing-knots', 'knot-multiplicity-exceeded',
  'empty-domain', 'wrong-weight-count', 'invalid-weight', 'wrong-tangent-count', 'wrong-node-count',
  'nodes-not-increasing', 'parameter-out-of-range', 'singular-matrix',
  'nodes-too-close', 'nodes-out-of-range', 'vandermonde-out-of-range', 'weight-ratio-out-of-range']);

function randomCurve(rnd) {
  const pick = (list) => list[Math.floor(rnd() * list.length)];
  const kind = pick(KINDS);
  const dim = rnd() < 0.5 ? 2 : 3;
  const count = 1 + Math.floor(rnd() * 9);
  const value = () => (rnd() < 0.02 ? pick([NaN, Infinity]) : (rnd() - 0.5) * 10);
  const curve = { kind, dim, points: Array.from({ length: count * dim }, value) };
  if (rnd() < 0.5) curve.degree = 1 + Math.floor(rnd() * 4);
  if (rnd() < 0.5) {
    const p = curve.degree ?? 3;
    const n = count + p + 1 + (rnd() < 0.2 ? pick([-1, 1]) : 0);
    let t = 0;
    curve.knots = Array.from({ length: Math.max(n, 0) }, () => (t += rnd() < 0.3 ? 0 : rnd() < 0.05 ? -1 : rnd()));
  }
  if (rnd() < 0.4) curve.weights = Array.from({ length: count }, () => (rnd() < 0.05 ? -1 : 0.2 + rnd()));
  if (kind === 'hermite') curve.tangents = Array.from({ length: (count + (rnd() < 0.1 ? 1 : 0)) * dim }, value);
  if (kind === 'cardinal') curve.tension = rnd();
  return curve;
}

test('2,000 random curves: finite results of the documented length or a coded error', () => {
  const rnd = random(20261122);
  let evaluated = 0;
  const before = api.memoryUsage().heapInUse;
  for (let i = 0; i < 2000; i += 1) {
    const curve = randomCurve(rnd);
    const params = Array.from({ length: 5 }, () => rnd() * 3 - 0.5);
    for (const call of [() => api.evaluateCurve(curve, params), () => api.evaluateDerivative(curve, params, 2),
      () => api.blendingFunctions(curve, params).values]) {
      try {
        const values = call();
        assert.ok(values instanceof Float64Array);
        for (const v of values) assert.ok(Number.isFinite(v), `${JSON.stringify(curve)} gave ${v}`);
        evaluated += 1;
      } catch (err) {
        assert.ok(err instanceof WingsplineError, `not a WingsplineError: ${err}`);
        assert.ok(CODES.has(err.code), `unexpected code ${err.code}: ${err.message}`);
        assert.ok(err.message.length > 10);
      }
    }
    try {
      const { params: u, points } = api.sampleCurve(curve, 7);
      assert.equal(points.length, 7 * curve.dim);
      assert.equal(u.length, 7);
    } catch (err) {
      assert.ok(CODES.has(err.code), `unexpected code ${err.code}: ${err.message}`);
    }
  }
  assert.ok(evaluated > 100, `only ${evaluated} random calls succeeded`);
  assert.equal(api.memoryUsage().heapInUse, before);
});
