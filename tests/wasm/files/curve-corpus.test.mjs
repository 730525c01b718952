// The malformed-curve corpus through wasm: every tests/corpus/curves/*.curve file
// gives its `expect` code from evaluateCurve (and evaluateDerivative), with a message naming
// its `names`; the module keeps working after any number of them. The same files are checked
// natively in tests/native/files/test_curve_corpus.cpp.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { curveFiles, readCurve } from '../../helpers/corpus.mjs';

const api = await loadWingspline();
// Coincident control points: the bases sum to one up to a few ulps.
const PARTITION_OF_UNITY = 1e-14;

test('the corpus holds every malformed curve of the issue', () => {
  assert.deepEqual(curveFiles(), ['coincident-1000.curve', 'decreasing-knots.curve', 'degree-0.curve', 'degree-30.curve',
    'nan-point.curve', 'negative-weight.curve', 'wrong-knot-count.curve', 'zero-weight.curve']);
});

for (const file of curveFiles()) {
  const { curve, params, expect, names } = readCurve(file);
  test(`${file}: ${expect}`, () => {
    if (expect === 'ok') {
      const values = api.evaluateCurve(curve, params);
      const d1 = api.evaluateDerivative(curve, params, 1);
      assert.equal(values.length, params.length * curve.dim);
      for (let j = 0; j < params.length; j += 1) {
        for (let k = 0; k < curve.dim; k += 1) {
          assert.ok(Math.abs(values[curve.dim * j + k] - curve.points[k]) <= PARTITION_OF_UNITY, `P(${params[j]})[${k}]`);
          assert.ok(Math.abs(d1[curve.dim * j + k]) <= PARTITION_OF_UNITY, `P'(${params[j]})[${k}]`);
        }
      }
      return;
    }
    for (const call of [() => api.evaluateCurve(curve, params), () => api.evaluateDerivative(curve, params, 1)]) {
      assert.throws(call, (err) => {
        assert.ok(err instanceof Error);
        assert.equal(err.code, expect, err.message);
        for (const word of names) assert.ok(err.message.includes(word), `"${err.message}" names ${word}`);
        return true;
      });
    }
  });
}

test('10,000 malformed curves in a row leave the module exact', () => {
  const bad = curveFiles().map(readCurve).filter((c) => c.expect !== 'ok');
  for (let i = 0; i < 10000; i += 1) {
    const { curve, params } = bad[i % bad.length];
    assert.throws(() => api.evaluateCurve(curve, params));
  }
  // Cubic Bezier at t = 1/2: (P0 + 3 P1 + 3 P2 + P3) / 8, exactly representable here.
  const mid = api.evaluateCurve({ kind: 'bezier', dim: 2, points: [0, 0, 1, 2, 3, 2, 4, 0] }, [0.5]);
  assert.deepEqual(Array.from(mid), [2, 1.5]);
});
