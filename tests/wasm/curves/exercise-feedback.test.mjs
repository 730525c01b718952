// The value-free feedback of the curve exercises (feedback levels check and hint): a joint's
// finding names the family or the statement, never the class nor its truth; a value's names
// what was asked in the question's terms, never the value nor how far off the answer is. The
// right values are computed here from the lectures' formulas (Bernstein polynomials, de
// Casteljau, the Bézier basis matrix; lecture 001's joint conditions), over thousands of
// seeded random curves and answers.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();
const bez = (points) => ({ kind: 'bezier', dim: 2, points });
const IDS = ['meet', 'equal-first', 'same-direction', 'equal-second', 'equal-curvature'];
const CLASS_TOKEN = /[CG](⁻¹|⁰|¹|²)|\btrue\b|\bfalse\b/;
const numbersIn = (text) => (text.match(/-?\d+(?:\.\d+)?(?:e-?\d+)?/g) ?? []).map(Number);
const binomial = (n, k) => (k < 0 || k > n ? 0 : k === 0 || k === n ? 1 : binomial(n - 1, k - 1) + binomial(n - 1, k));
const bernstein = (n, i, u) => binomial(n, i) * u ** i * (1 - u) ** (n - i);
function deCasteljau(points, u) {
  let p = points.slice();
  while (p.length > 1) p = p.slice(1).map((q, k) => [(1 - u) * p[k][0] + u * q[0], (1 - u) * p[k][1] + u * q[1]]);
  return p[0];
}
// A number the words must not hold: within display rounding (6 significant digits) of x.
const near = (t, x) => Math.abs(t - x) <= 5e-6 * Math.max(1, Math.abs(x));

test('joints: 2,000 random joints and answers; each finding\'s words are the same for every joint (no class, no truth, no evidence)', () => {
  const rnd = random(2811);
  const r2 = () => Math.round((rnd() * 8 - 4) * 4) / 4;
  const seen = {};
  let findings = 0;
  for (let trial = 0; trial < 2000; trial += 1) {
    const a = [[r2(), r2()], [r2(), r2()], [r2(), r2()], [r2(), r2()]];
    const end = a[3];
    const d1 = [end[0] - a[2][0], end[1] - a[2][1]];
    const kind = Math.floor(rnd() * 5); // lecture 001's conditions: C2, C1, G1 (a longer tangent), C0, apart
    const s = kind === 2 ? 2 : 1;
    const b0 = kind === 4 ? [end[0] + 1, end[1]] : end;
    const b1 = kind <= 2 ? [end[0] + s * d1[0], end[1] + s * d1[1]] : [r2(), r2()];
    const b2 = kind === 0 ? [a[1][0] + 4 * d1[0], a[1][1] + 4 * d1[1]] : [r2(), r2()];
    const b = [b0, b1, b2, [r2(), r2()]];
    const answer = { parametric: Math.floor(rnd() * 4) - 1, geometric: Math.floor(rnd() * 4) - 1, why: IDS.filter(() => rnd() < 0.5) };
    const r = api.checkJointAnswer(bez(a.flat()), bez(b.flat()), answer);
    for (const f of r.findings) {
      findings += 1;
      assert.doesNotMatch(f.message, CLASS_TOKEN, f.message);
      assert.doesNotMatch(f.hint, CLASS_TOKEN, f.hint);
      const words = `${f.message}\n${f.hint}`;
      seen[f.field] ??= words;
      assert.equal(words, seen[f.field], `${f.field}: the same words whatever the joint`);
    }
  }
  assert.ok(findings > 2000, `${findings}`);
  assert.deepEqual(Object.keys(seen).sort(), ['geometric', 'parametric', ...IDS].sort());
});

test('values: 3,000 random Bézier curves, u and wrong answers; the words hold neither the value nor the distance', () => {
  const rnd = random(2812);
  const M3 = [[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]]; // lecture 003's Bézier matrix
  const seenQuantities = new Set();
  for (let trial = 0; trial < 3000; trial += 1) {
    const n = 1 + Math.floor(rnd() * 3);
    const points = Array.from({ length: n + 1 }, () => [Math.round((rnd() * 10 - 5) * 100) / 100, Math.round((rnd() * 10 - 5) * 100) / 100]);
    const u = Math.round((0.01 + 0.98 * rnd()) * 100) / 100;
    const curve = bez(points.flat());
    const quantity = n === 3 && rnd() < 0.3 ? 'mg' : rnd() < 0.5 ? 'blend' : 'point';
    let ask;
    let expected;
    if (quantity === 'blend') {
      const i = Math.floor(rnd() * (n + 1));
      ask = { quantity, i, u };
      expected = [bernstein(n, i, u)];
    } else if (quantity === 'point') {
      ask = { quantity, u };
      expected = deCasteljau(points, u);
    } else {
      const row = Math.floor(rnd() * 4); const col = Math.floor(rnd() * 2);
      ask = { quantity, segment: 0, row, col };
      expected = [M3[row].reduce((sum, m, j) => sum + m * points[j][col], 0)];
    }
    seenQuantities.add(quantity);
    const wrong = expected.map((x) => x + (rnd() < 0.5 ? -1 : 1) * (0.05 + rnd()));
    const r = api.checkValueAnswer({ curve }, ask, wrong, 0.01);
    assert.equal(r.correct, false);
    assert.equal(r.code, 'not-within');
    const distance = Math.hypot(...wrong.map((x, k) => x - expected[k]));
    // The only numbers the words may hold: u, and the lectures' (000, 001, 003: 0, 1, 3) and
    // the 1 of [u³ u² u 1]. Any other number must be neither the value nor the distance.
    const allowed = new Set([u, 0, 1, 3]);
    for (const t of numbersIn(`${r.message} ${r.hint}`)) {
      if (allowed.has(t)) continue;
      for (const x of expected) assert.ok(!near(t, x), `trial ${trial}: ${t} is the value ${x}: "${r.message}"`);
      assert.ok(!near(t, distance), `trial ${trial}: ${t} is the distance: "${r.message}"`);
      assert.fail(`trial ${trial}: an unexpected number ${t} in "${r.message} ${r.hint}"`);
    }
    // The right answer is right (the lecture's formula agrees with the core).
    assert.equal(api.checkValueAnswer({ curve }, ask, expected, 1e-9).correct, true, `trial ${trial}: ${JSON.stringify(ask)}`);
  }
  assert.deepEqual([...seenQuantities].sort(), ['blend', 'mg', 'point']);
});

test('values: the question\'s language: M G entries counted from "first", the parameter u, wrong counts in a plain sentence', () => {
  const curve = bez([0, 0, 1, 2, 3, 3, 4, 0]);
  const mg = api.checkValueAnswer({ curve }, { quantity: 'mg', segment: 0, row: 1, col: 1 }, [100], 0.01);
  assert.match(mg.message, /^Your answer is not within the tolerance of the second row, second column \(y\) of M G for the first segment\./);
  assert.doesNotMatch(mg.message, /\bt\b|segment 0|₀/);
  assert.match(api.checkValueAnswer({ curve }, { quantity: 'point', u: 0.25 }, [9, 9], 0.01).message, /P\(u\) at u = 0\.25/);
  const cases = [
    [{ quantity: 'blend', i: 1, u: 0.5 }, [1, 2], 'The answer is a single number; you typed two numbers.'],
    [{ quantity: 'point', u: 0.5 }, [1], 'P(u) is a point: type its x and y (you typed one number).'],
    [{ quantity: 'point', u: 0.5 }, [1, 2, 3], 'P(u) is a point: type its x and y (you typed three numbers).'],
  ];
  for (const [ask, given, sentence] of cases) {
    const r = api.checkValueAnswer({ curve }, ask, given, 0.01);
    assert.deepEqual([r.correct, r.code, r.message], [false, 'wrong-count', sentence]);
  }
});
