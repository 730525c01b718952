// Guarantees of each representation for every control polygon through the
// JS API, against the comparison tables of lecture 003 and lecture 001 (typed from the notes).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();

// Segment s reads geometry row r from slot rows[r].
const pick = (slots, rows) => { const m = new Array(4 * slots).fill(0); rows.forEach((j, r) => { m[slots * r + j] = 1; }); return m; };
const points = (n) => new Array(n).fill(true);
const label = (g) => `C${g.parametric} G${g.geometric}`;

test('lecture 003: inherent and easily achieved continuity, interpolation', () => {
  // Hermite, 4 points; inherent: each segment its own tangents (slots 4..9), easy: shared (4..7).
  const own = api.chainGuarantees({ basis: 'hermite', slots: 10, isPoint: [...points(4), ...new Array(6).fill(false)],
    maps: [0, 1, 2].map((s) => pick(10, [s, s + 1, 4 + 2 * s, 5 + 2 * s])) });
  const shared = api.chainGuarantees({ basis: 'hermite', slots: 8, isPoint: [...points(4), false, false, false, false],
    maps: [0, 1, 2].map((s) => pick(8, [s, s + 1, 4 + s, 5 + s])) });
  const bezier = api.chainGuarantees({ basis: 'bezier', slots: 7, isPoint: points(7), maps: [pick(7, [0, 1, 2, 3]), pick(7, [3, 4, 5, 6])] });
  const mirrored = pick(7, [3, 4, 5, 6]);
  mirrored[7 * 1 + 4] = 0; mirrored[7 * 1 + 3] = 2; mirrored[7 * 1 + 2] = -1; // P4 = 2 P3 - P2
  const easyBezier = api.chainGuarantees({ basis: 'bezier', slots: 7, isPoint: points(7), maps: [pick(7, [0, 1, 2, 3]), mirrored] });
  const windows = (basis) => api.chainGuarantees({ basis, slots: 7, isPoint: points(7), maps: [0, 1, 2, 3].map((s) => pick(7, [s, s + 1, s + 2, s + 3])) });
  assert.deepEqual([label(own), label(bezier), label(windows('bspline')), label(windows('catmull-rom'))], ['C0 G0', 'C0 G0', 'C2 G2', 'C1 G1']);
  assert.deepEqual([label(shared), label(easyBezier)], ['C1 G1', 'C1 G1']);
  assert.deepEqual(own.interpolated, [0, 1, 2, 3], 'Hermite: every point, never a tangent');
  assert.deepEqual(bezier.interpolated, [0, 3, 6]);
  assert.deepEqual(windows('bspline').interpolated, []);
  assert.deepEqual(windows('catmull-rom').interpolated, [1, 2, 3, 4, 5]);
});

test('lecture 001: the non-uniform B-spline is C2 G2 and interpolates nothing; C^(p-m) at a knot of multiplicity m', () => {
  const g = api.bsplineGuarantees({ knots: [0, 0.6, 1, 2.2, 3, 3.5, 4.8, 5.4, 6.5, 7, 8], degree: 3, count: 7 });
  assert.equal(label(g), 'C2 G2');
  assert.deepEqual(g.interpolated, []);
  assert.equal(api.bsplineGuarantees({ knots: [0, 0, 0, 0, 1, 2, 2, 3, 4, 4, 4, 4], degree: 3, count: 8 }).parametric, 1);
  assert.deepEqual(api.bsplineGuarantees({ knots: [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2], degree: 3, count: 7 }).interpolated, [0, 3, 6]);
});

test('bad input gets a code and a message', () => {
  assert.throws(() => api.chainGuarantees({ basis: 'spline', slots: 4, isPoint: points(4), maps: [pick(4, [0, 1, 2, 3])] }), { code: 'unknown-basis' });
  assert.throws(() => api.chainGuarantees({ basis: 'bezier', slots: 4, isPoint: points(4), maps: [[1, 2, 3]] }), (e) => e.code === 'invalid-argument' && /maps\[0\]/.test(e.message));
  assert.throws(() => api.chainGuarantees({ basis: 'bezier', slots: 4, isPoint: points(3), maps: [pick(4, [0, 1, 2, 3])] }), { code: 'invalid-argument' });
  assert.throws(() => api.bsplineGuarantees({ knots: [0, 1, 0.5, 2, 3, 4, 5, 6], degree: 3, count: 4 }), { code: 'decreasing-knots' });
  assert.throws(() => api.bsplineGuarantees({ knots: [0, 1, 2], degree: 3, count: 4 }), { code: 'wrong-knot-count' });
});
