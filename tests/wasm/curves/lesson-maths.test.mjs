// Through the JS API: the segment holding a parameter, the knot vector
// presets and the continuity constraints that used to be computed in the curve lessons'
// JavaScript. Checked against segmentMatrices' ranges, exact fractions, and the core's joint
// classifier (jointContinuity) on random seeded chains.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();
const code = (f) => { try { f(); return 'no error'; } catch (err) { return err.code; } };

test('segmentAt names the segment whose range [start, end] holds u, for every family', () => {
  const rnd = random(1401);
  const pts = (K) => Array.from({ length: 2 * K }, () => rnd() * 8 - 4);
  for (let trial = 0; trial < 600; trial += 1) {
    const K = 4 + (trial % 5);
    const kinds = [
      { kind: 'hermite', dim: 2, points: pts(K), tangents: pts(K) },
      { kind: 'catmull-rom', dim: 2, points: pts(K) },
      { kind: 'bspline', dim: 2, points: pts(K), degree: 1 + (trial % 3) },
      { kind: 'bspline', dim: 2, points: pts(K), degree: 2, knots: api.clampedKnots(K, 2) },
    ];
    const curve = kinds[trial % 4];
    const d = api.curveDomain(curve);
    const u = trial % 9 === 0 ? d.end : d.start + rnd() * (d.end - d.start);
    const s = api.segmentAt(curve, u);
    const m = api.segmentMatrices(curve, s);
    assert.ok(m.start <= u && u <= m.end, `trial ${trial}: u = ${u} in segment ${s} [${m.start}, ${m.end}]`);
    if (u < d.end) assert.ok(u < m.end, `trial ${trial}: u = ${u} is the start of the next segment, not the end of ${s}`);
  }
  const h = { kind: 'hermite', dim: 2, points: [0, 0, 1, 0, 2, 0], tangents: [1, 0, 1, 0, 1, 0] };
  assert.equal(code(() => api.segmentAt(h, 2.5)), 'parameter-out-of-range');
  assert.equal(code(() => api.segmentAt(h, Number.NaN)), 'non-finite-input');
  assert.equal(code(() => api.segmentAt(h, '1')), 'invalid-argument');
});

test('knot presets: clamped j/(K-p), uniform j - p, unclamped ends spread, and which is clamped', () => {
  assert.deepEqual(Array.from(api.clampedKnots(7, 3)), [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1]);
  assert.deepEqual(Array.from(api.uniformKnots(5, 2)), [-2, -1, 0, 1, 2, 3, 4, 5]);
  assert.deepEqual(Array.from(api.unclampedKnots([0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1], 3)), [-0.75, -0.5, -0.25, 0, 0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75]);
  for (let p = 1; p <= 7; p += 1) {
    for (let K = p + 1; K <= 24; K += 1) {
      const t = api.clampedKnots(K, p);
      assert.equal(t.length, K + p + 1);
      // interior j/(K-p), to the presets' rounding of whole billionths (0.5e-9)
      for (let j = 1; j < K - p; j += 1) assert.ok(Math.abs(t[p + j] * (K - p) - j) <= 0.5e-9 * (K - p));
      assert.equal(api.isClampedKnots(t, p), true);
      assert.equal(api.isClampedKnots(api.uniformKnots(K, p), p), false);
    }
  }
  // the uniform B-spline's implicit knots, as knotMultiplicities reports them
  const r = api.knotMultiplicities({ kind: 'bspline', dim: 2, degree: 3, points: [0, 0, 1, 1, 2, 0, 3, 1, 4, 0] });
  assert.deepEqual(Array.from(r.knots), [-3, -2, -1, 0, 1, 2, 3, 4, 5]);
  assert.equal(code(() => api.clampedKnots(3, 3)), 'too-few-points');
  assert.equal(code(() => api.clampedKnots(5, 0)), 'degree-out-of-range');
  assert.equal(code(() => api.clampedKnots(5.5, 2)), 'invalid-argument');
  assert.equal(code(() => api.unclampedKnots([0, 1, 0.5, 1], 1)), 'decreasing-knots');
});

// Two segments' curves from 4 entries each (Bezier P0..P3; Hermite p0, p1, t0, t1).
function segments(family, q) {
  const out = [];
  for (let s = 0; 8 * s < q.length; s += 1) {
    const e = Array.from(q.slice(8 * s, 8 * s + 8));
    out.push(family === 'bezier' ? { kind: 'bezier', dim: 2, points: e } : { kind: 'hermite', dim: 2, points: e.slice(0, 4), tangents: e.slice(4) });
  }
  return out;
}

test('dragging with a constraint keeps every joint at least that continuous (classifier, random chains)', () => {
  const rnd = random(14014);
  const wanted = { C0: [0, 0], G1: [0, 1], C1: [1, 1], C2: [2, 2] };
  let joints = 0;
  for (let trial = 0; trial < 800; trial += 1) {
    const family = trial % 2 ? 'hermite' : 'bezier';
    const mode = Object.keys(wanted)[(trial >> 1) % 4];
    const n = 2 + (trial % 3);
    const scale = 10 ** ((trial % 9) - 4);
    const start = api.enforceConstraint(Float64Array.from({ length: 8 * n }, () => scale * (rnd() * 8 - 4)), 2, family, mode);
    const index = Math.floor(rnd() * 4 * n);
    const to = [scale * (rnd() * 8 - 4), scale * (rnd() * 8 - 4)];
    const q = api.dragWithConstraint(start, 2, family, mode, index, to);
    assert.deepEqual([q[2 * index], q[2 * index + 1]], to, 'the dragged entry is where it was dragged');
    const segs = segments(family, q);
    for (let j = 1; j < segs.length; j += 1) {
      const v = api.jointContinuity(segs[j - 1], segs[j]);
      assert.ok(v.parametric >= wanted[mode][0] && v.geometric >= wanted[mode][1], `trial ${trial} ${family} ${mode}: joint ${j} is C${v.parametric} G${v.geometric}`);
      joints += 1;
    }
  }
  assert.ok(joints > 1000);
});

test('constraint calls refuse what they cannot do, with codes', () => {
  const p = [0, 0, 1, 2, 2, 2, 3, 0, 3, 0, 4, -2, 5, 1, 6, 0];
  assert.equal(code(() => api.dragWithConstraint(p, 2, 'bezier', 'C3', 0, [0, 0])), 'invalid-argument');
  assert.equal(code(() => api.dragWithConstraint(p, 2, 'nurbs', 'C1', 0, [0, 0])), 'unknown-basis');
  assert.equal(code(() => api.dragWithConstraint(p, 2, 'bspline', 'C1', 0, [0, 0])), 'unsupported-curve-kind');
  assert.equal(code(() => api.dragWithConstraint(p, 2, 'bezier', 'C1', 8, [0, 0])), 'invalid-argument');
  assert.equal(code(() => api.dragWithConstraint(p.slice(0, 6), 2, 'bezier', 'C1', 0, [0, 0])), 'wrong-point-count');
  assert.equal(code(() => api.dragWithConstraint(p, 2, 'bezier', 'C1', 0, [0, Infinity])), 'non-finite-input');
  // one more segment: Bezier starts at the old end; windows of four get P_n = P_n-1 + (P_n-1 - P_n-3)/2
  assert.deepEqual(Array.from(api.appendSegment(p, 2, 'bezier', 'free').slice(16, 18)), [6, 0]);
  assert.deepEqual(Array.from(api.appendSegment([0, 0, 1, 1, 2, 0, 3, 1], 2, 'catmull-rom', 'free').slice(8)), [4, 1]);
});
