// Through the JS API: the comparison lesson's measurements and the convex
// hull, now in the core. Checked against independent recomputation here (brute-force
// extreme points, the plane map written out), analytic values, and seeded random cases for
// the general rules, including invariance under scaling, translation and rotation. Errors
// arrive as WingsplineError values with stable codes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();
const code = (f) => { try { f(); return 'no error'; } catch (err) { return err.code; } };
const messageOf = (f) => { try { f(); return ''; } catch (err) { return err.message; } };

// orientation of (a, b, c), exact for small integers
const cross = (p, o, a, b) => (p[2 * a] - p[2 * o]) * (p[2 * b + 1] - p[2 * o + 1]) - (p[2 * a + 1] - p[2 * o + 1]) * (p[2 * b] - p[2 * o]);

// Extreme points of distinct integer points by definition: not inside (or on) a triangle or
// a segment of three / two other points.
function extremePoints(p) {
  const n = p.length / 2;
  const inTriangle = (i, a, b, c) => {
    const d = [cross(p, a, b, i), cross(p, b, c, i), cross(p, c, a, i)];
    return !(d.some((x) => x < 0) && d.some((x) => x > 0));
  };
  const onSegment = (i, a, b) => cross(p, a, b, i) === 0
    && Math.min(p[2 * a], p[2 * b]) <= p[2 * i] && p[2 * i] <= Math.max(p[2 * a], p[2 * b])
    && Math.min(p[2 * a + 1], p[2 * b + 1]) <= p[2 * i + 1] && p[2 * i + 1] <= Math.max(p[2 * a + 1], p[2 * b + 1]);
  const out = [];
  for (let i = 0; i < n; i += 1) {
    let inside = false;
    for (let a = 0; a < n && !inside; a += 1) {
      for (let b = a + 1; b < n && !inside && a !== i; b += 1) {
        if (b === i) continue;
        if (onSegment(i, a, b)) inside = true;
        for (let c = b + 1; c < n && !inside; c += 1) if (c !== i && cross(p, a, b, c) !== 0 && inTriangle(i, a, b, c)) inside = true;
      }
    }
    if (!inside) out.push(i);
  }
  return out;
}

function similar(p, angle, s, tx, ty) {
  const c = Math.cos(angle) * s;
  const sn = Math.sin(angle) * s;
  const q = new Float64Array(p.length);
  for (let i = 0; i < p.length; i += 2) { q[i] = c * p[i] - sn * p[i + 1] + tx; q[i + 1] = sn * p[i] + c * p[i + 1] + ty; }
  return q;
}

test('convexHull: 2000 random grid polygons give the brute-force extreme points, counter-clockwise, at any scale and rotation', () => {
  const rnd = random(1405);
  for (let trial = 0; trial < 2000; trial += 1) {
    const n = 1 + Math.floor(rnd() * 11);
    const seen = new Set();
    const p = [];
    while (p.length < 2 * n) {
      const x = Math.floor(rnd() * 9) - 4; const y = Math.floor(rnd() * 9) - 4;
      if (seen.has(`${x},${y}`)) continue;
      seen.add(`${x},${y}`); p.push(x, y);
    }
    const h = Array.from(api.convexHull(p).indices);
    assert.deepEqual([...h].sort((a, b) => a - b), extremePoints(p), `trial ${trial}: ${p}`);
    for (let e = 0; h.length >= 3 && e < h.length; e += 1) {
      const [a, b, c] = [h[e], h[(e + 1) % h.length], h[(e + 2) % h.length]];
      assert.ok(cross(p, a, b, c) > 0, `trial ${trial}: strictly convex, counter-clockwise`);
      for (let i = 0; i < n; i += 1) assert.ok(cross(p, a, b, i) >= 0, `trial ${trial}: P${i} inside or on the hull`);
    }
    const s = 10 ** (-6 + 12 * rnd());
    const moved = api.convexHull(similar(p, 2 * Math.PI * rnd(), s, 50 * s * rnd(), -50 * s * rnd())).indices;
    assert.deepEqual(Array.from(moved).sort((a, b) => a - b), extremePoints(p), `trial ${trial} at scale ${s}`);
  }
});

test('convexHull refuses odd and non-finite input with a code and the point named', () => {
  assert.equal(code(() => api.convexHull([0, 0, 1])), 'invalid-points');
  assert.equal(code(() => api.convexHull([0, 0, 1, NaN])), 'non-finite-input');
  assert.match(messageOf(() => api.convexHull([0, 0, 1, NaN])), /point 1/);
  assert.equal(code(() => api.convexHull('0 0')), 'invalid-argument');
  assert.deepEqual(Array.from(api.convexHull([]).indices), []);
});

test('mapPoints: 2000 random maps against x\' = (a x + b y + tx)/w written out, w = px x + py y + 1', () => {
  const rnd = random(77);
  const u = () => 2 * rnd() - 1;
  for (let trial = 0; trial < 2000; trial += 1) {
    const t = { kind: trial % 2 ? 'perspective' : 'affine', angle: 180 * u(), scale: 0.1 + 3 * rnd(), shear: 2 * u(), tx: 10 * u(), ty: 10 * u(), px: 0.05 * u(), py: 0.05 * u() };
    const p = Array.from({ length: 10 }, () => 4 * u());
    const r = api.mapPoints(p, 2, t);
    const ang = (t.angle * Math.PI) / 180;
    const [c, s] = [Math.cos(ang), Math.sin(ang)];
    // scale * [c -s; s c] * [1 shear; 0 1]
    const L = [t.scale * c, t.scale * (c * t.shear - s), t.scale * s, t.scale * (s * t.shear + c)];
    for (let i = 0; i < 5; i += 1) {
      const [x, y] = [p[2 * i], p[2 * i + 1]];
      const w = t.kind === 'perspective' ? t.px * x + t.py * y + 1 : 1;
      assert.ok(Math.abs(r.w[i] - w) <= 1e-15 * Math.abs(w));
      const X = (L[0] * x + L[1] * y + t.tx) / w; const Y = (L[2] * x + L[3] * y + t.ty) / w;
      assert.ok(Math.abs(r.points[2 * i] - X) <= 1e-12 * (1 + Math.abs(X)) && Math.abs(r.points[2 * i + 1] - Y) <= 1e-12 * (1 + Math.abs(Y)), `trial ${trial} point ${i}`);
    }
  }
});

test('mapPoints: behind the eye is an error value naming the point; bad transforms are refused', () => {
  const t = { kind: 'perspective', px: -0.5 };
  assert.equal(code(() => api.mapPoints([0, 0, 1, 0, 3, 1], 2, t, { what: 'P' })), 'perspective-behind-eye');
  assert.match(messageOf(() => api.mapPoints([0, 0, 1, 0, 3, 1], 2, t, { what: 'P' })), /P2 \(3\.00, 1\.00\) behind the eye \(w = -0\.50 ≤ 0\)/);
  assert.equal(api.mapPoints([3, 1], 2, { kind: 'affine', px: -0.5 }).w[0], 1, 'an affine map ignores px, py');
  assert.equal(code(() => api.mapPoints([0, 0], 2, { kind: 'projective' })), 'invalid-argument');
  assert.equal(code(() => api.mapPoints([0, 0], 2, { kind: 'affine', scale: Infinity })), 'non-finite-input');
  assert.equal(code(() => api.mapPoints([0, 0, 0], 3, { kind: 'affine' })), 'invalid-dimension');
});

test('maxDistance: analytic distances and the index where they are reached', () => {
  const a = []; const b = [];
  for (let j = 0; j < 40; j += 1) {
    const t = (2 * Math.PI * j) / 40;
    a.push(1 + 5 * Math.cos(t), 2 + 5 * Math.sin(t));
    const r = j === 9 ? 1 : 3;
    b.push(1 + r * Math.cos(t), 2 + r * Math.sin(t));
  }
  const d = api.maxDistance(a, b, 2);
  assert.ok(Math.abs(d.distance - 4) <= 1e-14 * 5);
  assert.equal(d.index, 9);
  assert.equal(api.maxDistance([0, 0, 0], [2, 3, 6], 3).distance, 7);
  assert.equal(code(() => api.maxDistance([0, 0], [0, 0, 1, 1], 2)), 'invalid-argument');
  assert.equal(code(() => api.maxDistance([0, NaN], [0, 0], 2)), 'non-finite-input');
});

test('blendingWeightCheck: lecture 003\'s convex hull row, with the analytic extremes at u = 1/3', () => {
  const p = [0, 0, 1, 2, 3, 2, 4, 0];
  for (const kind of ['bezier', 'bspline']) assert.equal(api.blendingWeightCheck([{ kind, dim: 2, points: p }]).convexHull, true, kind);
  const cr = api.blendingWeightCheck([{ kind: 'catmull-rom', dim: 2, points: p }], 4);
  assert.equal(cr.convexHull, false);
  assert.ok(Math.abs(cr.minWeight + 2 / 27) < 1e-14, 'min of (-u^3 + 2u^2 - u)/2 is -2/27');
  assert.ok(Math.abs(cr.minWeightAt - 1 / 3) < 1e-15, 'at u = 1/3');
  const h = api.blendingWeightCheck([{ kind: 'hermite', dim: 2, points: [0, 0, 1, 0], tangents: [1, 1, 1, -1] }], 4);
  assert.equal(h.weightsPoints, false);
  assert.ok(Math.abs(h.tangentWeight - 4 / 27) < 1e-14, 'max of u^3 - 2u^2 + u is 4/27');
  assert.equal(code(() => api.blendingWeightCheck([])), 'invalid-argument');
  assert.equal(code(() => api.blendingWeightCheck([{ kind: 'bezier', dim: 2, points: p }], 1)), 'invalid-argument');
});

test('pointCurveDistances: the interpolated points of random Bezier chains do not depend on scale, place or rotation', () => {
  const rnd = random(9);
  for (let trial = 0; trial < 500; trial += 1) {
    const p = Array.from({ length: 14 }, () => 8 * rnd());
    const s = 10 ** (-7 + 14 * rnd());
    const q = similar(p, 2 * Math.PI * rnd(), s, 1e3 * s * rnd(), 1e3 * s * rnd());
    const chain = (pts) => [{ kind: 'bezier', dim: 2, points: pts.slice(0, 8) }, { kind: 'bezier', dim: 2, points: pts.slice(6, 14) }];
    const a = api.pointCurveDistances(p, 2, chain(p));
    const b = api.pointCurveDistances(q, 2, chain(Array.from(q)));
    assert.deepEqual(Array.from(a.interpolated), [0, 3, 6], `trial ${trial}`);
    assert.deepEqual(Array.from(b.interpolated), [0, 3, 6], `trial ${trial} at scale ${s}`);
    assert.equal(b.farthest, a.farthest);
    for (let i = 0; i < 7; i += 1) assert.ok(Math.abs(b.distances[i] - s * a.distances[i]) <= 1e-8 * s * a.distances[i] + b.tolerance);
  }
  // analytic: a straight uniform B-spline on x = 0, 3, 6, 9 runs from 3 to 6
  const line = [0, 1, 3, 1, 6, 1, 9, 1];
  const d = api.pointCurveDistances(line, 2, [{ kind: 'bspline', dim: 2, points: line }], 7);
  assert.deepEqual(Array.from(d.distances, (x) => Math.round(x * 1e12) / 1e12), [3, 0, 0, 3]);
  assert.deepEqual(Array.from(d.interpolated), [1, 2]);
  assert.equal(d.nearestMissed, 0);
});

test('splitCheck and knotRefinementCheck: split halves and refined curves trace the original', () => {
  const rnd = random(21);
  for (let trial = 0; trial < 300; trial += 1) {
    const s = 10 ** (6 * (2 * rnd() - 1));
    const p = Array.from({ length: 8 }, () => s * (2 * rnd() - 1));
    const size = Math.max(...p.map(Math.abs));
    const segs = [{ kind: 'bezier', dim: 2, points: p }, { kind: 'bspline', dim: 2, points: p }, { kind: 'catmull-rom', dim: 2, points: p },
      { kind: 'hermite', dim: 2, points: p.slice(0, 4), tangents: p.slice(4) }];
    const r = api.splitCheck(segs);
    assert.equal(r.segments, 4);
    assert.ok(r.error <= 1e-13 * 8 * size, `trial ${trial}: ${r.error} at size ${size}`);
    const q = Array.from({ length: 12 }, () => s * (2 * rnd() - 1));
    const k = api.knotRefinementCheck({ kind: 'bspline', dim: 2, degree: 3, points: q, knots: [0, 0.6, 1, 2.2, 3, 3.5, 4.8, 5.4, 6.5, 7] });
    assert.deepEqual([k.inserted, k.pointsBefore, k.pointsAfter], [3, 6, 9]);
    assert.ok(k.error <= 1e-13 * 8 * Math.max(...q.map(Math.abs)));
  }
  assert.equal(code(() => api.splitCheck([{ kind: 'nurbs', dim: 2, points: [0, 0, 1, 1], weights: [1, 2] }])), 'invalid-argument');
  assert.equal(code(() => api.splitCheck([])), 'invalid-argument');
});

test('patchCornerCheck and patchJoinCheck: corners are their net entries, shared rows join C0, matched legs C1, a shift d is a gap |d|', () => {
  const rnd = random(33);
  for (let trial = 0; trial < 300; trial += 1) {
    const s = 10 ** (6 * (2 * rnd() - 1));
    const t = s * 10 ** (6 * rnd());
    const net = () => Array.from({ length: 48 }, () => s * (2 * rnd() - 1) + t);
    const a = net();
    for (const kind of ['bezier', 'hermite']) {
      const c = api.patchCornerCheck({ kind, points: a });
      assert.deepEqual(c.corners.map((x) => x.entry), kind === 'bezier' ? [0, 3, 12, 15] : [0, 1, 4, 5]);
      assert.ok(c.corners.every((x) => x.interpolated), `trial ${trial}: ${kind} corners at scale ${s}, offset ${t}`);
    }
    const b = net();
    for (let k = 0; k < 12; k += 1) b[k] = a[36 + k]; // q0j = p3j
    let j = api.patchJoinCheck({ kind: 'bezier', a, b });
    assert.deepEqual([j.c0, j.c1], [true, false], `trial ${trial}`);
    for (let k = 0; k < 12; k += 1) b[12 + k] = 2 * a[36 + k] - a[24 + k]; // q1j = 2 p3j - p2j
    j = api.patchJoinCheck({ kind: 'bezier', a, b });
    assert.deepEqual([j.c0, j.c1], [true, true], `trial ${trial}`);
    const d = [s * 1e-6 * (1.5 + 0.5 * rnd()), 0, -s * 1e-6];
    for (let e = 0; e < 4; e += 1) for (let k = 0; k < 3; k += 1) b[3 * e + k] += d[k];
    j = api.patchJoinCheck({ kind: 'bezier', a, b });
    const len = Math.hypot(...d);
    assert.equal(j.c0, false);
    assert.ok(Math.abs(j.positionGap - len) <= 1e-3 * len && Math.abs(j.duGap - 3 * len) <= 3e-3 * len, `trial ${trial}`);
  }
  assert.equal(code(() => api.patchCornerCheck({ kind: 'bspline', points: new Array(48).fill(0) })), 'unknown-basis');
  assert.equal(code(() => api.patchJoinCheck({ kind: 'bezier', a: new Array(48).fill(0), b: new Array(45).fill(0) })), 'wrong-point-count');
});

test('catmullRomTangents: (P_i+1 - P_i-1)/2 is the exact derivative of points on a parabola, the chord at the ends', () => {
  // P_i = (i^2, 3 - 2i): P'(i) = (2i, -2); P_1 - P_0 = (1, -2), P_4 - P_3 = (7, -2)
  const p = [0, 3, 1, 1, 4, -1, 9, -3, 16, -5];
  assert.deepEqual(Array.from(api.catmullRomTangents(p, 2)), [1, -2, 2, -2, 4, -2, 6, -2, 7, -2]);
  assert.equal(code(() => api.catmullRomTangents([1, 2], 2)), 'too-few-points');
  assert.equal(code(() => api.catmullRomTangents([1, 2, 3], 2)), 'invalid-points');
});

test('convertPatchBasis: a Bezier net\'s Hermite entries are lecture 002\'s, the surface is the same, and back again', () => {
  const rnd = random(43);
  for (let trial = 0; trial < 200; trial += 1) {
    const s = 10 ** (6 * (2 * rnd() - 1));
    const p = Array.from({ length: 48 }, () => s * (2 * rnd() - 1));
    const size = Math.max(...p.map(Math.abs));
    const h = api.convertPatchBasis(p, 'bezier', 'hermite');
    const e = (i, j) => 3 * (4 * i + j);
    for (let k = 0; k < 3; k += 1) {
      assert.ok(Math.abs(h[e(0, 1) + k] - p[e(0, 3) + k]) <= 1e-14 * size, 'p(0,1) = p03');
      assert.ok(Math.abs(h[e(2, 0) + k] - 3 * (p[e(1, 0) + k] - p[e(0, 0) + k])) <= 1e-13 * size, 'p_u(0,0) = 3 (p10 - p00)');
    }
    const a = api.samplePatch({ kind: 'bezier', points: p, nu: 4, nv: 4 }).positions;
    const b = api.samplePatch({ kind: 'hermite', points: h, nu: 4, nv: 4 }).positions;
    assert.ok(api.maxDistance(a, b, 3).distance <= 1e-13 * size, `trial ${trial}`);
    assert.ok(api.maxDistance(api.convertPatchBasis(h, 'hermite', 'bezier'), p, 3).distance <= 1e-13 * size, `trial ${trial}`);
  }
  assert.equal(code(() => api.convertPatchBasis(new Array(48).fill(0), 'bspline', 'bezier')), 'unknown-basis');
  assert.equal(code(() => api.convertPatchBasis(new Array(45).fill(0), 'bezier', 'hermite')), 'wrong-point-count');
});

test('curvatureComb and homogeneousLift: a circle\'s teeth point at the centre with length 1/r; (w x, w y, w)', () => {
  const circle = api.nurbsCircle({ center: [3, -1], radius: 2.5 });
  const d = api.curveDomain(circle);
  const params = Array.from({ length: 21 }, (_, j) => d.start + ((d.end - d.start) * j) / 20);
  const c = api.curvatureComb(circle, params);
  assert.equal(c.singular, 0);
  assert.ok(Math.abs(c.maxCurvature - 1 / 2.5) < 1e-12);
  for (let j = 0; j < 21; j += 1) {
    const [x, y, kx, ky] = c.teeth.slice(4 * j, 4 * j + 4);
    assert.ok(Math.abs(kx - (3 - x) / 6.25) < 1e-12 && Math.abs(ky - (-1 - y) / 6.25) < 1e-12, `tooth ${j}`);
  }
  assert.deepEqual(Array.from(api.homogeneousLift([1, 2, 3, 4], 2, [0.5, 3])), [0.5, 1, 0.5, 9, 12, 3]);
  assert.equal(code(() => api.homogeneousLift([1, 2, 3, 4], 2, [1, -1])), 'invalid-weight');
  assert.equal(code(() => api.curvatureComb({ kind: 'bezier', dim: 3, points: [0, 0, 0, 1, 1, 1] }, [0.5])), 'invalid-dimension');
});
