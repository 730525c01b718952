// The comparison lesson's table and invariance experiment (web/js/lessons/comparison) as a
// person reads them: every verdict must be the same when the whole polygon is scaled, moved
// or rotated (issue 14 item 5: the measurements live in the core, with tolerances relative to
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
