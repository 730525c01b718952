// The comparison lesson's table and invariance experiment (web/js/lessons/comparison) as a
// person reads them: every verdict must be the same when the whole polygon is scaled, moved
// or rotated (the measurements live in the core, with tolerances relative to
// the polygon's size), and a perspective map that sends a control point behind the eye says
// which point.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { computeTable } from '../../web/js/lessons/comparison/checks.js';
import { computeInvariance } from '../../web/js/lessons/comparison/transforms.js';
import { FAMILY_IDS } from '../../web/js/lessons/comparison/families.js';
import { lesson } from '../../web/js/lessons/comparison/lesson.js';

const api = await loadWingspline();
const ROWS = ['convexHull', 'interpolatesSome', 'interpolatesAll', 'inherent', 'easy'];

function similar(points, { angle = 0, scale = 1, tx = 0, ty = 0 }) {
  const c = Math.cos(angle) * scale;
  const s = Math.sin(angle) * scale;
  return points.map(([x, y]) => [c * x - s * y + tx, s * x + c * y + ty]);
}

// The verdicts a person reads in the table (answers and the interpolated points); the
// evidence strings hold measured numbers, which scale with the polygon.
function verdicts(table) {
  const out = {};
  for (const f of FAMILY_IDS) {
    for (const r of ROWS) {
      out[`${f} ${r} guaranteed`] = table.columns[f][r].answer;
      out[`${f} ${r} this polygon`] = table.polygon[f][r].answer;
      if (table.polygon[f][r].interpolated) out[`${f} ${r} through`] = table.polygon[f][r].interpolated.join(',');
    }
    out[`${f} subdivision`] = table.columns[f].subdivision.answer;
  }
  return out;
}

test('the table\'s verdicts do not change when the polygon is scaled, moved or rotated', () => {
  const points = lesson.defaultState().points;
  const reference = verdicts(computeTable(api, points));
  // Catmull-Rom passes through every point: the reference says so before anything is compared.
  assert.equal(reference['catmull-rom interpolatesAll this polygon'], 'Yes');
  for (const t of [{ scale: 1e-6 }, { scale: 1e7 }, { angle: 0.65 }, { tx: 3e4, ty: -2e4 }, { angle: 2.2, scale: 3e5, tx: 1e9 }]) {
    assert.deepEqual(verdicts(computeTable(api, similar(points, t))), reference, JSON.stringify(t));
  }
});

test('a perspective map that sends a control point behind the eye is refused, naming the point', () => {
  const points = lesson.defaultState().points;
  const transform = { ...lesson.defaultState().transform, kind: 'perspective', px: -0.5, py: 0 };
  // w = 1 - x/2 <= 0 for x >= 2: the first such control point
  const first = points.findIndex(([x]) => 1 - x / 2 <= 0);
  assert.ok(first >= 0, 'the default polygon reaches x >= 2');
  assert.throws(() => computeInvariance(api, points, transform), (err) => {
    assert.equal(err.code, 'perspective-behind-eye');
    assert.match(err.message, new RegExp(`P${first} \\(`));
    return true;
  });
});

// The default view shows five different curves. Hermite has its own
// tangents (state), so its curve is not Catmull-Rom's; Catmull-Rom inside Hermite stays an
// explicit choice. Distances by the core (maxDistance over the same parameters per
// segment), relative to the polygon's bounding-box diagonal (unitless).
const VISIBLY_DIFFERENT = 0.05; // 5 % of the diagonal: several pixels at any zoom that shows the polygon
const SAME_CURVE = 1e-9;        // rounding only

function segmentDistances(model, a, b) {
  const A = model.table.curves[a];
  const B = model.table.curves[b];
  assert.equal(A.length, B.length, `${a} and ${b} have the same segments`);
  return A.map((s, i) => api.maxDistance(s.points, B[i].points, 2).distance);
}
const diagonal = (points) => Math.hypot(Math.max(...points.map((p) => p[0])) - Math.min(...points.map((p) => p[0])),
  Math.max(...points.map((p) => p[1])) - Math.min(...points.map((p) => p[1])));

test('default: the Hermite curve (own tangents) differs visibly from Catmull-Rom; the Catmull-Rom choice gives Catmull-Rom inside', () => {
  const state = lesson.defaultState();
  assert.equal(state.hermite.tangents, 'own');
  assert.equal(state.hermite.own.length, state.points.length, 'one tangent per point');
  const d = diagonal(state.points);
  const own = lesson.compute(null, state, { api });
  const ownGap = Math.max(...segmentDistances(own, 'hermite', 'catmull-rom')) / d;
  assert.ok(ownGap > VISIBLY_DIFFERENT, `Hermite vs Catmull-Rom: ${ownGap} of the diagonal`);
  // Catmull-Rom's tangents t_i = (P_i+1 - P_i-1)/2: the inner segments coincide with the
  // Catmull-Rom curve (its end segments repeat P0 and P(K-1), Hermite takes the chord there).
  const cr = lesson.compute(null, { ...state, hermite: { ...state.hermite, tangents: 'catmull-rom' } }, { api });
  const inner = segmentDistances(cr, 'hermite', 'catmull-rom').slice(1, -1);
  assert.ok(inner.length >= 4);
  for (const x of inner) assert.ok(x / d <= SAME_CURVE, `inner segment ${x / d}`);
  // The drawn arrows are the tangents the curve uses.
  assert.deepEqual(own.table.tangents, state.hermite.own);
});

test('a state with a tangent count other than the point count is refused, naming the rule', () => {
  const state = lesson.defaultState();
  assert.match(lesson.checkState({ ...state, hermite: { ...state.hermite, own: state.hermite.own.slice(1) } }), /one tangent per point/);
  assert.equal(lesson.checkState(state), null);
});

test('the comparison lab\'s non-uniform B-spline is never a Bezier curve in disguise (the core decides), for every polygon size', async () => {
  const { nonUniformKnots } = await import('../../web/js/lessons/comparison/families.js');
  for (let K = 4; K <= 31; K += 3) assert.equal(api.isBezierInDisguise(nonUniformKnots(K), 3), false, `${K} points`);
  // ... while lecture 002's clamped vector for four points is one.
  assert.equal(api.isBezierInDisguise([0, 0, 0, 0, 1, 1, 1, 1], 3), true);
});
