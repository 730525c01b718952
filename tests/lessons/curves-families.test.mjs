// The curve explorer's state bookkeeping (web/js/lessons/curves/families.js): switching the
// family, adding and removing points, changing the degree must always leave a state the
// lesson accepts (checkState) and the core evaluates, with K + p + 1 knots in the style the
// knots had (clamped stays clamped, uniform stays uniform). The knot vectors themselves
// come from the core; these tests drive thousands of random edit sequences.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../helpers/seeded-random.mjs';
import {
  FAMILY_IDS, DEFAULT_KNOTS, curveSpec, switchFamily, addPoint, removePoint, withDegree, usesKnots, maxDegreeFor, familyInfo, familyMaxPoints,
} from '../../web/js/lessons/curves/families.js';
import { lesson } from '../../web/js/lessons/curves/lesson.js';

const api = await loadWingspline();

test('the default scene\'s knots are the core\'s clamped vector of 4 points of degree 3', () => {
  assert.deepEqual(DEFAULT_KNOTS, Array.from(api.clampedKnots(4, 3)));
  assert.equal(lesson.checkState(lesson.defaultState()), null);
});

test('random edit sequences keep a state the lesson and the core accept, knots in their style', () => {
  const rnd = random(1405);
  const pick = (list) => list[Math.floor(rnd() * list.length)];
  let edits = 0;
  for (let run = 0; run < 60; run += 1) {
    let state = lesson.defaultState();
    for (let step = 0; step < 40; step += 1) {
      const K = state.points.length;
      const info = familyInfo(state.family);
      const before = state;
      const op = pick(['family', 'add', 'remove', 'degree']);
      if (op === 'family') state = switchFamily(api, state, pick(FAMILY_IDS));
      else if (op === 'add' && K < familyMaxPoints(info, api)) state = addPoint(api, state, Math.floor(rnd() * K) - 1);
      else if (op === 'remove' && K > info.minPoints) state = removePoint(api, state, Math.floor(rnd() * K));
      else if (op === 'degree' && usesKnots(state.family)) state = withDegree(api, state, 1 + Math.floor(rnd() * maxDegreeFor(K)));
      edits += 1;
      const where = `run ${run} step ${step} (${op}, ${before.family} -> ${state.family})`;
      assert.equal(lesson.checkState(state), null, where);
      assert.doesNotThrow(() => api.curveDomain(curveSpec(state)), where);
      assert.equal(state.tangents.length, state.points.length, where);
      assert.equal(state.weights.length, state.points.length, where);
      if (usesKnots(state.family) && usesKnots(before.family) && op !== 'family') {
        // the knots keep their style: a clamped vector stays clamped, a uniform one uniform
        const wasClamped = api.isClampedKnots(before.knots, before.degree);
        assert.equal(api.isClampedKnots(state.knots, state.degree), wasClamped, `${where}: style kept`);
      }
    }
  }
  assert.ok(edits >= 2400);
});

test('adding a point between two others puts it at their midpoint; removing takes exactly that point', () => {
  const state = lesson.defaultState();
  const added = addPoint(api, state, 1);
  assert.deepEqual(added.points[2], [(state.points[1][0] + state.points[2][0]) / 2, (state.points[1][1] + state.points[2][1]) / 2]);
  assert.deepEqual(removePoint(api, added, 2).points, state.points);
});
