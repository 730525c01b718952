// api.cubicDerivation(family) over the real wasm module: the exact matrices of the
// derivation panel (docs/api-curves.md, "Derivations"), checked against the lectures' matrices
// and by recomputation here in exact integer arithmetic (BigInt fractions).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();
// a fraction matrix { rows, cols, num, den } as BigInt pairs
const fr = (m) => Array.from(m.num, (n, i) => [BigInt(n), BigInt(m.den[i])]);
const gcd = (a, b) => (b === 0n ? (a < 0n ? -a : a) : gcd(b, a % b));
const norm = ([n, d]) => { const g = gcd(n, d) || 1n; return d < 0n ? [-n / g, -d / g] : [n / g, d / g]; };
const add = (a, b) => norm([a[0] * b[1] + b[0] * a[1], a[1] * b[1]]);
const mul = (a, b) => norm([a[0] * b[0], a[1] * b[1]]);
function product(a, b, r, k, c) {
  const out = [];
  for (let i = 0; i < r; i += 1) for (let j = 0; j < c; j += 1) {
    let s = [0n, 1n];
    for (let t = 0; t < k; t += 1) s = add(s, mul(a[k * i + t], b[c * t + j]));
    out.push(s);
  }
  return out;
}
const ints = (den, nums) => nums.map((n) => norm([BigInt(n), BigInt(den)]));
const identity = (n) => Array.from({ length: n * n }, (_, i) => [i % (n + 1) === 0 ? 1n : 0n, 1n]);

test('Hermite: the constraint matrix and M_H = its inverse, as in lecture 000', () => {
  const d = api.cubicDerivation('hermite');
  assert.equal(d.size, 4);
  assert.deepEqual(fr(d.constraint), ints(1, [0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 1, 0, 3, 2, 1, 0]));
  assert.deepEqual(fr(d.basis), ints(1, [2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0]));
  assert.deepEqual(product(fr(d.constraint), fr(d.inverse), 4, 4, 4), identity(4));
});

test('Bezier: M_H S = M_B with R1 = 3(P2 - P1), R4 = 3(P4 - P3)', () => {
  const h = api.cubicDerivation('hermite');
  const d = api.cubicDerivation('bezier');
  assert.deepEqual(fr(d.substitution), ints(1, [1, 0, 0, 0, 0, 0, 0, 1, -3, 3, 0, 0, 0, 0, -3, 3]));
  assert.deepEqual(product(fr(h.basis), fr(d.substitution), 4, 4, 4), fr(d.basis));
  assert.deepEqual(fr(d.basis), ints(1, [-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0]));
});

test('uniform B-spline: the 16 conditions, their solution 1/6 [...] and A A^-1 = I', () => {
  const d = api.cubicDerivation('bspline');
  assert.equal(d.size, 16);
  assert.deepEqual(fr(d.basis), ints(6, [-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0]));
  assert.deepEqual(product(fr(d.constraint), fr(d.inverse), 16, 16, 16), identity(16));
  const B = fr(d.basis);
  const x = [];
  for (let c = 0; c < 4; c += 1) for (let r = 0; r < 4; r += 1) x.push(B[4 * r + c]);
  assert.deepEqual(product(fr(d.constraint), x, 16, 16, 1), fr(d.rhs));
  assert.equal(d.conditions.length, 16);
  assert.match(d.conditions[1], /b1\(1\) = b0\(0\)/);
});

test('Catmull-Rom and unknown names are refused with a stable code', () => {
  assert.throws(() => api.cubicDerivation('catmull-rom'), (e) => e.code === 'unsupported-curve-kind' && /uniform B-spline/.test(e.message));
  assert.throws(() => api.cubicDerivation('spline'), (e) => e.code === 'unknown-basis');
});
