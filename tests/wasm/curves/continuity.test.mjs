// Trust at the JS boundary: jointContinuity and curvature
// at any scale, the lecture wordings of G^n, undefined curvature reported as such, and arc
// length that returns on coordinates near 1e308 (docs/api-curves.md).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();
const CURVATURE_REL = 1e-12; // relative error of a curvature against its analytic value
const bez = (points) => ({ kind: 'bezier', dim: 2, points });
const scaled = (points, s) => points.map((x) => x * s);
// a: A1 = (3, -3), A2 = (0, -6) at its end; kappa = |A1 x A2| / |A1|^3 = 18 / 18^1.5 (lecture 004).
const A = [0, 0, 1, 1, 2, 1, 3, 0];
const KAPPA_A = 18 / 18 ** 1.5;

test('a joint moved to 1e300 (as typed into the inspector) has a finite curvature', () => {
  for (const s of [1e300, 1e-300]) {
    const j = api.jointContinuity(bez(scaled(A, s)), bez(scaled([3, 0, 4, -1, 5, -3, 6, 0], s)));
    assert.ok(Number.isFinite(j.evidence.curvatureA), `scale ${s}: ${j.evidence.curvatureA}`);
    assert.ok(Math.abs(j.evidence.curvatureA * s - KAPPA_A) <= CURVATURE_REL * KAPPA_A);
    assert.deepEqual([j.parametric, j.geometric], [2, 2]);
  }
  // One point of the lab's first segment typed as x = 1e300 and the rest near 1: P' at the
  // joint (about 3) is below the rounding of an evaluation over data of size 1e300, so the
  // core says "undefined" (null, zero tangent flagged) on that side rather than a number; never
  // Infinity or NaN on either side.
  const j = api.jointContinuity(bez([0, 0, 1e300, 1, 2, 1, 3, 0]), bez([3, 0, 4, -1, 5, -3, 6, 0]));
  for (const [k, zero] of [[j.evidence.curvatureA, j.evidence.zeroTangentA], [j.evidence.curvatureB, j.evidence.zeroTangentB]]) {
    assert.ok(zero ? k === null : Number.isFinite(k), `curvature ${k}, zero tangent ${zero}`);
  }
  assert.ok(Math.abs(j.evidence.curvatureB - KAPPA_A) <= CURVATURE_REL * KAPPA_A);
  // a'' = 6 (P3 - 2 P2 + P1) = (6e300, -6): kappa- = |a' x a''| / |a'|^3 = 1.8e301 / 18^1.5
  assert.ok(Math.abs(j.evidence.curvatureA / (1.8e301 / 18 ** 1.5) - 1) < CURVATURE_REL);
  assert.deepEqual([j.parametric, j.geometric], [1, 1]);
});

test('the verdict does not change with the scale of the drawing', () => {
  for (const s of [1e-8, 1e-6, 1, 1e6, 1e8]) {
    const gap = api.jointContinuity(bez(scaled(A, s)), bez(scaled([3, 1e-4, 4, -1, 5, 0, 6, 1], s)));
    assert.equal(gap.parametric, -1, `a 1e-4 gap at scale ${s}`);
    const corner = api.jointContinuity(bez(scaled(A, s)), bez(scaled([3, 0, 4, 1, 5, 0, 6, 1], s)));
    assert.deepEqual([corner.parametric, corner.geometric], [0, 0], `a right angle at scale ${s}`);
  }
});

test('the lecture wordings of G^n come with the verdict', () => {
  // B1 = A1, B2 = 2 A2: P'' in the same direction, the curvature doubles.
  const j = api.jointContinuity(bez(A), bez([3, 0, 4, -1, 5, -4, 6, 0]));
  const byId = Object.fromEntries(j.wordings.map((w) => [w.id, w]));
  assert.deepEqual(Object.keys(byId).sort(), ['curvature-vector', 'direction', 'proportional']);
  assert.equal(byId['curvature-vector'].geometric, j.geometric);
  assert.equal(j.geometric, 1);
  assert.equal(byId.proportional.geometric, 2);
  assert.equal(byId.proportional.source, 'lectures 001, 004');
  assert.equal(byId.direction.geometric, 2);
  assert.equal(byId.direction.source, 'lecture 003');
  for (const w of j.wordings) assert.ok(w.reason.length > 20 && w.wording.length > 10);
});

test('the curvature on a side with P\' = 0 is undefined (null), never 0', () => {
  const j = api.jointContinuity(bez([0, 0, 1, 1, 3, 0, 3, 0]), bez([3, 0, 4, 1, 4, 2, 6, 1]));
  assert.equal(j.evidence.zeroTangentA, true);
  assert.equal(j.evidence.zeroTangentB, false);
  assert.equal(j.evidence.curvatureA, null);
  assert.ok(j.evidence.curvatureB > 0);
  // the cusp of (0,0), (1,1), (0,1), (1,0) at t = 1/2, at 1e-8 and translated: flagged
  const k = api.curvature(bez([3, 3, 3 + 1e-8, 3 + 1e-8, 3, 3 + 1e-8, 3 + 1e-8, 3]), [0.25, 0.5]);
  assert.deepEqual(Array.from(k.singular), [0, 1]);
  const p = api.curvature(bez([-1e-150, 1e-150, 0, -1e-150, 1e-150, 1e-150]), [0.5]);
  assert.ok(Math.abs(p.curvature[0] / 2e150 - 1) < CURVATURE_REL);
});

test('arcLength returns (and is right) for coordinates near 1e308', () => {
  const big = 1.5e308;
  const start = Date.now();
  const L = api.arcLength(bez([0, 0, big / 3, 0, 2 * (big / 3), 0, big, 0]));
  assert.ok(Math.abs(L / big - 1) < 1e-12);
  assert.throws(() => api.arcLength(bez([-big, -big, -big / 3, -big / 3, big / 3, big / 3, big, big])), { code: 'length-overflow' });
  assert.ok(Date.now() - start < 2000);
});

// C^-1 with the gap relative to the size of the pair (docs/api-curves.md): size =
// 2 max |Q - c| over all control points, c their centroid, recomputed here from the points.
test('a gap is C-1 with its relative size, the same after scaling, turning and shifting', () => {
  const a = [0, 0, 1, 1, 2, 1, 3, 0];
  const b = [3, 0.06, 4, -1, 5, 0, 6, 1];
  // centroid (3, 0.2575); the farthest point (6, 1); gap 0.06
  const expected = 0.06 / (2 * Math.hypot(3, 0.7425));
  const REL = 1e-12;
  for (const [s, angle] of [[1e-6, 0], [1, 0.7], [1e6, -2.1]]) {
    const move = (p) => {
      const out = [];
      for (let i = 0; i < p.length; i += 2) {
        const [x, y] = [p[i], p[i + 1]];
        out.push(s * (Math.cos(angle) * x - Math.sin(angle) * y) + 5 * s, s * (Math.sin(angle) * x + Math.cos(angle) * y) - 2 * s);
      }
      return out;
    };
    const j = api.jointContinuity(bez(move(a)), bez(move(b)));
    assert.deepEqual([j.parametric, j.geometric], [-1, -1]);
    assert.ok(Math.abs(j.evidence.relativeGap / expected - 1) < 1e-9, `scale ${s}: ${j.evidence.relativeGap}`);
    assert.ok(Math.abs(j.evidence.positionGap / (0.06 * s) - 1) < 1e-9);
    assert.ok(Math.abs(j.evidence.size / (2 * s * Math.hypot(3, 0.7425)) - 1) < REL * 1e3);
    assert.match(j.evidence.notes[0], /discontinuous/);
  }
  const met = api.jointContinuity(bez(a), bez([3, 0, 4, -1, 5, 0, 6, 1]));
  assert.equal(met.evidence.relativeGap, 0);
});
