// Exercise kinds 3, 4 and 5 at the JS boundary over the real module: the shapes the
// exercise player reads, values against the lectures' formulas, and every error code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();
const bez = (points) => ({ kind: 'bezier', dim: 2, points });
// Lecture 004's Q1-Q3 kind of joint: P'(1) = 3 (a3 - a2) = (3, 0), Q'(0) = 3 (b1 - b0) = (6, 0).
const G1_A = bez([-3, 1, -2, 1, -1, 0, 0, 0]);
const G1_B = bez([0, 0, 2, 0, 3, 1, 4, 3]);
// A C^2 joint (lecture 001's conditions b1 = 2 a3 - a2, b2 = a1 + 4 (a3 - a2)).
const C2_A = bez([0, 0, 1, 1, 2, 1, 3, 0]);
const C2_B = bez([3, 0, 4, -1, 5, -3, 6, 0]);
const IDS = ['meet', 'equal-first', 'same-direction', 'equal-second', 'equal-curvature'];

function throwsCode(f, code, fragment) {
  assert.throws(f, (err) => {
    assert.equal(err.code, code, err.message);
    if (fragment) assert.ok(err.message.includes(fragment), err.message);
    return true;
  });
}

test('jointReasons and jointClasses: the ids, and the classes with the statements they need', () => {
  assert.deepEqual(api.jointReasons().map((r) => r.id), IDS);
  assert.ok(api.jointReasons().every((r) => typeof r.statement === 'string' && r.statement.length > 10));
  const c = api.jointClasses();
  assert.deepEqual(c.parametric.map((x) => x.k), [-1, 0, 1, 2]);
  assert.deepEqual(c.geometric.map((x) => x.k), [-1, 0, 1, 2]);
  assert.deepEqual(c.parametric[2].requires, ['meet', 'equal-first']);
  assert.deepEqual(c.geometric[3].requires, ['meet', 'same-direction', 'equal-curvature']);
  assert.match(c.parametric[3].label, /or smoother/);
});

test('checkJointAnswer: G1 but not C1, the wrong class named, the worked why and explanation', () => {
  const r = api.checkJointAnswer(G1_A, G1_B, { parametric: 1, geometric: 1, why: ['meet', 'same-direction'] });
  assert.equal(r.correct, false);
  assert.equal(r.findings.length, 1);
  assert.deepEqual({ field: r.findings[0].field, given: r.findings[0].given, expected: r.findings[0].expected },
    { field: 'parametric', given: 1, expected: 0 });
  assert.deepEqual(r.worked.why, ['meet', 'same-direction']);
  assert.equal(r.worked.parametric, 0);
  assert.equal(r.worked.geometric, 1);
  assert.ok(r.worked.explanation.some((line) => line.startsWith("P'(1) = (3, 0) and Q'(0) = (6, 0): the same direction, lengths 3 and 6")));
  // A wrong tick: the statement's finding carries booleans.
  const t = api.checkJointAnswer(G1_A, G1_B, { why: ['meet', 'equal-first', 'same-direction'] });
  assert.deepEqual(t.findings.map((f) => [f.field, f.given, f.expected]), [['equal-first', true, false]]);
  // The verdict agrees with jointContinuity on the same pair.
  const j = api.jointContinuity(C2_A, C2_B);
  const right = api.checkJointAnswer(C2_A, C2_B, { parametric: j.parametric, geometric: j.geometric, why: IDS });
  assert.equal(right.correct, true);
  assert.deepEqual(right.findings, []);
});

test('checkJointAnswer and jointClasses: bad answers get stable codes', () => {
  throwsCode(() => api.checkJointAnswer(G1_A, G1_B, { parametric: 3 }), 'invalid-argument', 'parametric');
  throwsCode(() => api.checkJointAnswer(G1_A, G1_B, { geometric: 1.5 }), 'invalid-argument', 'answer.geometric');
  throwsCode(() => api.checkJointAnswer(G1_A, G1_B, { why: ['tangent'] }), 'invalid-argument', "'tangent'");
  throwsCode(() => api.checkJointAnswer(G1_A, G1_B, { why: 'meet' }), 'invalid-argument', 'answer.why');
  throwsCode(() => api.checkJointAnswer(G1_A, null, {}), 'invalid-argument', 'b must be an object');
});

test('checkValueAnswer: B_1,3(0.5) = 3 . 0.5 . 0.25, right and wrong', () => {
  const subject = { curve: bez([0, 0, 1, 2, 3, 2, 4, 0]) };
  const wrong = api.checkValueAnswer(subject, { quantity: 'blend', i: 1, u: 0.5 }, [0.4], 0.001);
  assert.equal(wrong.correct, false);
  assert.deepEqual(wrong.expected, [0.375]);
  assert.equal(wrong.label, 'B₁,₃(0.5)');
  assert.equal(wrong.reason, '0.4 is 0.025 from B₁,₃(0.5) = 0.375; the tolerance is 0.001');
  assert.equal(wrong.working.at(-1), 'at u = 0.5: 3 · 0.5 · 0.25 = 0.375');
  assert.ok(Math.abs(wrong.distance - 0.025) <= 1e-15);
  assert.equal(api.checkValueAnswer(subject, { quantity: 'blend', i: 1, u: 0.5 }, [0.3755], 0.001).correct, true);
});

test('checkValueAnswer: a point, an entry of M G, Boehm and a patch point against their formulas', () => {
  const P = [0, 0, 1, 2, 3, 2, 4, 0];
  const subject = { curve: bez(P) };
  // P(0.5) = (P0 + 3 P1 + 3 P2 + P3) / 8 = (2, 1.5)
  const point = api.checkValueAnswer(subject, { quantity: 'point', u: 0.5 }, [2, 1.5], 1e-12);
  assert.equal(point.correct, true);
  // (M G)_1,1 with the slide's Bezier row (3, -6, 3, 0): -6 . 2 + 3 . 2 = -6 (lecture 003)
  const mg = api.workedValue(subject, { quantity: 'mg', segment: 0, row: 1, col: 1 });
  assert.deepEqual(mg.expected, [-6]);
  // Boehm on the uniform cubic B-spline P_i = (i, i^2), u = 1/2: Q_2 = (P_1 + P_2) / 2 (a_2 = 1/2).
  const bs = { kind: 'bspline', dim: 2, points: [0, 0, 1, 1, 2, 4, 3, 9, 4, 16] };
  const q = api.workedValue({ curve: bs }, { quantity: 'boehm', u: 0.5, index: 2 });
  assert.deepEqual(q.expected, [1.5, 2.5]);
  assert.ok(q.working.some((l) => l.startsWith('a₂ = (u − u₂) / (u₅ − u₂)')));
  // A bilinear-looking Bezier patch p_ij = (i, j, i j): p(u, v) = (3u, 3v, 9uv) (linear precision of Bernstein).
  const points = [];
  for (let i = 0; i < 4; i += 1) for (let j = 0; j < 4; j += 1) points.push(i, j, i * j);
  const pp = api.workedValue({ patch: { kind: 'bezier', points } }, { quantity: 'patch-point', u: 0.25, v: 0.5 });
  pp.expected.forEach((x, k) => assert.ok(Math.abs(x - [0.75, 1.5, 1.125][k]) <= 1e-14, `${k}: ${x}`));
});

test('checkValueAnswer: unknown quantity, missing and bad fields, wrong sizes', () => {
  const subject = { curve: bez([0, 0, 1, 2, 3, 2, 4, 0]) };
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'slope', u: 0.5 }, [1], 0.1), 'unknown-quantity', 'slope');
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'blend', u: 0.5 }, [1], 0.1), 'invalid-argument', 'ask.i is missing');
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'blend', i: 0.5, u: 0.5 }, [1], 0.1), 'invalid-argument', 'ask.i');
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'blend', i: 9, u: 0.5 }, [1], 0.1), 'invalid-argument', 'ask.i is 9');
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'point', u: Infinity }, [1, 1], 0.1), 'non-finite-input', 'ask.u');
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'point', u: 2 }, [1, 1], 0.1), 'parameter-out-of-range');
  // A wrong count of numbers is the student's mistake: a wrong answer said plainly, not an error.
  const count = api.checkValueAnswer(subject, { quantity: 'point', u: 0.5 }, [1], 0.1);
  assert.deepEqual([count.correct, count.code, count.distance, count.message], [false, 'wrong-count', Infinity, 'P(u) is a point: type its x and y (you typed one number).']);
  assert.equal(api.checkValueAnswer(subject, { quantity: 'blend', i: 1, u: 0.5 }, [0.1, 0.2], 0.1).message, 'The answer is a single number; you typed two numbers.');
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'point', u: 0.5 }, [1, NaN], 0.1), 'non-finite-input', 'given[1]');
  throwsCode(() => api.checkValueAnswer(subject, { quantity: 'point', u: 0.5 }, [1, 1], -0.1), 'invalid-argument', 'tolerance');
  throwsCode(() => api.workedValue(subject, { quantity: 'patch-point', u: 0.5, v: 0.5 }), 'invalid-argument', 'subject must be {patch');
  throwsCode(() => api.workedValue({ patch: { kind: 'nurbs', points: [] } }, { quantity: 'patch-point', u: 0, v: 0 }), 'unknown-basis');
  throwsCode(() => api.workedValue({ patch: { kind: 'bezier', points: [0, 0, 0] } }, { quantity: 'patch-point', u: 0, v: 0 }), 'wrong-point-count', '48 numbers');
  throwsCode(() => api.workedValue({ patch: { kind: 'bezier', points: new Array(48).fill(0) } }, { quantity: 'patch-point', u: 0, v: 1.5 }),
    'parameter-out-of-range', 'ask.v');
  throwsCode(() => api.workedValue({ curve: { kind: 'hermite', dim: 2, points: [0, 0, 1, 0], tangents: [1, 0, 1, 0] } },
    { quantity: 'boehm', u: 0.5, index: 0 }), 'unsupported-curve-kind');
});

test('checkCurveProperty: joint-class and passes-through, with what to change', () => {
  const c2 = api.checkCurveProperty({ a: C2_A, b: C2_B }, { kind: 'joint-class', parametric: 1 });
  assert.equal(c2.holds, false);
  assert.match(c2.reason, /^the joint is C²: P''\(1\) = Q''\(0\); move a point so that P''\(1\) ≠ Q''\(0\)/);
  assert.deepEqual(c2.measured, { parametric: 2, geometric: 2, why: IDS });
  assert.equal(api.checkCurveProperty({ a: G1_A, b: G1_B }, { kind: 'joint-class', parametric: 0, geometric: 1 }).holds, true);
  // The NURBS unit circle: its control square has the diagonal 2 sqrt 2; (1.5, 0) is 0.5 away.
  const circle = api.nurbsCircle({ center: [0, 0], radius: 1 });
  const far = api.checkCurveProperty({ curve: circle }, { kind: 'passes-through', point: [1.5, 0], tolerance: 0.1 });
  assert.equal(far.holds, false);
  assert.ok(Math.abs(far.measured.distance - 0.5) <= 1e-12);
  assert.ok(Math.abs(far.measured.size - 2 * Math.SQRT2) <= 1e-15 * 4);
  assert.match(far.reason, /^the curve comes no closer than 0\.5 to \(1\.5, 0\)/);
  const near = api.checkCurveProperty({ curve: circle }, { kind: 'passes-through', point: [0, 1.2], tolerance: 0.1 });
  assert.equal(near.holds, true); // 0.2 <= 0.1 . 2.83
  // The same drawing 1e6 times larger: the same verdict.
  const big = api.checkCurveProperty({ curve: api.nurbsCircle({ center: [5e6, -3e6], radius: 1e6 }) },
    { kind: 'passes-through', point: [5e6, -3e6 + 1.2e6], tolerance: 0.1 });
  assert.equal(big.holds, true);
  assert.ok(Math.abs(big.measured.relativeDistance - near.measured.relativeDistance) <= 1e-9);
});

test('checkCurveProperty: unknown property, missing tolerance, bad classes and points', () => {
  const circle = api.nurbsCircle({ center: [0, 0], radius: 1 });
  throwsCode(() => api.checkCurveProperty({ curve: circle }, { kind: 'tangent-to' }), 'unknown-property', 'tangent-to');
  throwsCode(() => api.checkCurveProperty({ curve: circle }, { kind: 'passes-through', point: [1, 0] }), 'invalid-argument', 'property.tolerance');
  throwsCode(() => api.checkCurveProperty({ curve: circle }, { kind: 'passes-through', point: [1, 0], tolerance: 2 }), 'invalid-argument', 'tolerance');
  throwsCode(() => api.checkCurveProperty({ curve: circle }, { kind: 'passes-through', point: [1, 0, 0], tolerance: 0.1 }), 'invalid-argument', '3 coordinates');
  throwsCode(() => api.checkCurveProperty({ a: C2_A, b: C2_B }, { kind: 'joint-class' }), 'invalid-argument', 'parametric or geometric');
  throwsCode(() => api.checkCurveProperty({ a: C2_A, b: C2_B }, { kind: 'joint-class', geometric: 5 }), 'invalid-argument', 'geometric');
  throwsCode(() => api.checkCurveProperty({ curve: bez([1, 1, 1, 1]) }, { kind: 'passes-through', point: [0, 0], tolerance: 0.1 }), 'degenerate-curve');
});

test('thousands of exercise checks leave the wasm heap where it was', () => {
  const subject = { curve: bez([0, 0, 1, 2, 3, 2, 4, 0]) };
  const run = () => {
    api.checkJointAnswer(G1_A, G1_B, { parametric: 1, why: ['meet'] });
    api.checkValueAnswer(subject, { quantity: 'blend', i: 1, u: 0.5 }, [0.4], 0.001);
    try { api.checkValueAnswer(subject, { quantity: 'blend', i: 9, u: 0.5 }, [0.4], 0.001); } catch { /* refused: counted below */ }
    api.checkCurveProperty({ a: C2_A, b: C2_B }, { kind: 'joint-class', parametric: 1 });
  };
  for (let n = 0; n < 200; n += 1) run();
  const before = api.memoryUsage().heapInUse;
  for (let n = 0; n < 3000; n += 1) run();
  assert.equal(api.memoryUsage().heapInUse, before);
});
