// The continuity lab's handles (web/js/lessons/continuity/lesson.js): dragging any handle of
// a Bezier or Hermite preset in a constraint mode gives a state whose joints the lab's own
// model (the core's classifier) finds at least that continuous; free mode moves only the
// dragged entry. The lesson is driven through its hooks with a view holding the core.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../helpers/seeded-random.mjs';
import { lesson } from '../../web/js/lessons/continuity/lesson.js';
import { PRESETS } from '../../web/js/lessons/continuity/presets.js';
import { enforceAll } from '../../web/js/lessons/continuity/constraints.js';

const api = await loadWingspline();
const view = { api };
const ctx = { api };
const WANTED = { C0: [0, 0], G1: [0, 1], C1: [1, 1], C2: [2, 2] };

test('a dragged handle keeps every joint at least as continuous as the mode asks', () => {
  const rnd = random(1406);
  let joints = 0;
  for (const [name, preset] of Object.entries(PRESETS)) {
    // (zero-tangent: its legs have no direction, the documented case where G1 cannot be kept)
    if ((preset.family !== 'bezier' && preset.family !== 'hermite') || name === 'zero-tangent') continue;
    for (const mode of Object.keys(WANTED)) {
      // choosing the mode applies it to the whole curve, as the page does
      const points = enforceAll(api, preset.points, preset.family, mode);
      let state = { ...lesson.defaultState(), family: preset.family, preset: name, constraint: mode, points };
      for (let k = 0; k < 25; k += 1) {
        const handles = lesson.handles(view, null, state);
        const hd = handles[Math.floor(rnd() * handles.length)];
        state = lesson.moveHandle(view, state, hd.id, hd.x + rnd() * 2 - 1, hd.y + rnd() * 2 - 1);
        const moved = lesson.handles(view, null, state).find((x) => x.id === hd.id);
        assert.ok(Math.hypot(moved.x - hd.x, moved.y - hd.y) > 0, `${name} ${mode}: the dragged handle moved`);
        for (const j of lesson.compute(view, state, ctx).joints) {
          assert.ok(j.parametric >= WANTED[mode][0] && j.geometric >= WANTED[mode][1], `${name} ${mode} drag ${k}: J${j.index} is C${j.parametric} G${j.geometric}`);
          joints += 1;
        }
      }
    }
  }
  assert.ok(joints >= 500);
});

test('free mode moves the dragged entry only', () => {
  const state = { ...lesson.defaultState(), constraint: 'free' };
  const next = lesson.moveHandle(view, state, 'p5', 7, -3);
  state.points.forEach((p, i) => assert.deepEqual(next.points[i], i === 5 ? [7, -3] : p));
});
