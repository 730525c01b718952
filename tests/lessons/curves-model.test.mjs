// The curve explorer's compute (web/js/lessons/curves/curve-model.js) keeps its cache in the
// lesson's view, not in the module: two pages (two views) never share or overwrite each
// other's samples, and a cached model is the one the core computes afresh.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { computeCurveModel, createModelCache } from '../../web/js/lessons/curves/curve-model.js';
import { defaultPoints } from '../../web/js/lessons/curves/families.js';
import { lesson } from '../../web/js/lessons/curves/lesson.js';

const api = await loadWingspline();
const moved = (state, dx) => ({ ...state, points: state.points.map(([x, y]) => [x + dx, y]) });

test('two views keep their own samples: computing in one never changes the other\'s model', () => {
  const a = createModelCache();
  const b = createModelCache();
  const s0 = lesson.defaultState();
  const mA = computeCurveModel(api, s0, a);
  const kept = Float64Array.from(mA.samples);
  // The other view computes several different curves (each fills one of its two buffers).
  for (let k = 1; k <= 3; k += 1) computeCurveModel(api, moved(s0, k), b);
  assert.deepEqual(Array.from(mA.samples), Array.from(kept));
});

test('in one view, the model on screen is never the buffer the next compute writes', () => {
  const cache = createModelCache();
  const s0 = lesson.defaultState();
  const m0 = computeCurveModel(api, s0, cache);
  const kept = Float64Array.from(m0.samples);
  const m1 = computeCurveModel(api, moved(s0, 1), cache);
  assert.deepEqual(Array.from(m0.samples), Array.from(kept));
  assert.notEqual(m1.samples, m0.samples);
});

test('the cached samples equal a fresh evaluation, and the segment and knots are the core\'s', () => {
  const cache = createModelCache();
  const state = { ...lesson.defaultState(), family: 'bspline-uniform', points: defaultPoints['bspline-uniform'].map((q) => q.slice()), degree: 3, u: 2.5 };
  computeCurveModel(api, moved(state, 3), cache);
  const m = computeCurveModel(api, state, cache);
  const again = computeCurveModel(api, state, createModelCache());
  assert.deepEqual(Array.from(m.samples), Array.from(again.samples));
  assert.equal(m.segmentIndex, api.segmentAt(m.spec, 2.5));
  // K = 7, p = 3 without knots: t_j = j - p, each once, C2 at the interior ones
  assert.deepEqual(m.knots.values, Array.from({ length: 11 }, (_, j) => j - 3));
  assert.ok(m.knots.groups.every((g) => g.multiplicity === 1 && g.continuity === 2));
});
