// The continuity lab driven like a student would: presets with answers the lectures give,
// drags with the mouse at the positions the page reports, the constraint modes, the speed
// plot's jump, the travelling point, and a share link.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { handle, drag } from '../../helpers/pointer.mjs';

// Tolerances: positions in world units; the page classifies joints at 1e-6 relative.
const POSITION_TOL = 1e-9;
const RELATIVE_TOL = 1e-9;
const DRAG_PX = 45;

const env = useSiteAndBrowser();

async function openLab(hash = '') {
  const page = await env.openPage(`${env.site.url}continuity.html${hash}`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  return page;
}
const state = (page) => page.evaluate(() => window.wingspline.state);
const joints = (page) => page.evaluate(() => window.wingspline.model.joints.map((j) => ({
  parametric: j.parametric, geometric: j.geometric, ratio: j.ratio, left: j.left, right: j.right })));
async function choosePreset(page, name) {
  await page.selectOption('#preset', name);
  await page.waitForFunction((n) => window.wingspline.state.preset === n, name);
}

// Lecture 001: a cubic Bezier's end derivatives are P'(1) = 3 (P3 - P2), P''(1) = 6 (P3 - 2 P2 + P1)
// and P'(0) = 3 (P1 - P0), P''(0) = 6 (P0 - 2 P1 + P2); curvature |x'y'' - y'x''| / |P'|^3.
const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];
const cross = (a, b) => a[0] * b[1] - a[1] * b[0];
const norm = (a) => Math.hypot(a[0], a[1]);
function bezierEnds(points) {
  const [P0, P1, P2, P3, Q0, Q1, Q2] = points;
  const d1L = sub(P3, P2).map((v) => 3 * v);
  const d2L = [0, 1].map((k) => 6 * (P3[k] - 2 * P2[k] + P1[k]));
  const d1R = sub(Q1, Q0).map((v) => 3 * v);
  const d2R = [0, 1].map((k) => 6 * (Q0[k] - 2 * Q1[k] + Q2[k]));
  return { d1L, d2L, d1R, d2R, kL: Math.abs(cross(d1L, d2L)) / norm(d1L) ** 3, kR: Math.abs(cross(d1R, d2R)) / norm(d1R) ** 3, P0 };
}

test('the C1 preset reads C1 and G1, with the lecture\'s derivatives as evidence', async () => {
  const page = await openLab();
  const s = await state(page);
  assert.equal(s.preset, 'c1-bezier');
  const [j] = await joints(page);
  const ends = bezierEnds(s.points);
  // The preset was built with J - P2 = Q1 - J: equal first derivatives (lecture 001).
  assert.equal(j.parametric, 1, 'C1 but not C2: the second derivatives differ');
  // C1 implies G1; G2 would need equal curvature, and the lecture's formula gives different values.
  assert.ok(Math.abs(ends.kL - ends.kR) > 0.1, 'the preset has different curvatures on the two sides');
  assert.equal(j.geometric, 1);
  for (let k = 0; k < 2; k += 1) {
    assert.ok(Math.abs(j.left.d1[k] - ends.d1L[k]) < POSITION_TOL);
    assert.ok(Math.abs(j.right.d2[k] - ends.d2R[k]) < POSITION_TOL);
  }
  assert.ok(Math.abs(j.left.curvature - ends.kL) < RELATIVE_TOL * Math.max(1, ends.kL));
  assert.ok(Math.abs(j.right.curvature - ends.kR) < RELATIVE_TOL * Math.max(1, ends.kR));
  assert.equal(await page.textContent('.joint-card .verdict'), 'C1 · G1');
  await screenshot(page, 'continuity-c1');
  assert.deepEqual(page.problems, []);
});

test('dragging P2 off the line in free mode drops G1 (and C1)', async () => {
  const page = await openLab();
  await page.selectOption('#constraint', 'free');
  await page.waitForFunction(() => window.wingspline.state.constraint === 'free');
  const before = await state(page);
  await drag(page, 'p2', 0, -DRAG_PX);
  const after = await state(page);
  assert.ok(after.points[2][1] > before.points[2][1] + 0.1, 'P2 moved up');
  assert.deepEqual(after.points[5], before.points[5], 'free mode leaves the other side alone');
  // P2, J, Q1 are no longer collinear: no common tangent direction (lecture 001, G1).
  const e = bezierEnds(after.points);
  assert.ok(Math.abs(cross(e.d1L, e.d1R)) > 1e-3);
  const [j] = await joints(page);
  assert.equal(j.parametric, 0);
  assert.equal(j.geometric, 0);
  assert.equal(await page.textContent('.joint-card .verdict'), 'C0 · G0');
  await screenshot(page, 'continuity-free-drag');
  assert.deepEqual(page.problems, []);
});

test('with the G1 constraint a drag builds a G1-not-C1 joint and the speed jumps by the leg ratio', async () => {
  const page = await openLab();
  await page.selectOption('#constraint', 'G1');
  await page.waitForFunction(() => window.wingspline.state.constraint === 'G1');
  // Pull Q1 away from the joint and sideways: the constraint turns P2 to stay collinear.
  await drag(page, 'p5', DRAG_PX, DRAG_PX * 0.6);
  const s = await state(page);
  const [, , P2, J, , Q1] = s.points;
  const legL = sub(J, P2);
  const legR = sub(Q1, J);
  assert.ok(Math.abs(cross(legL, legR)) < 1e-9 * norm(legL) * norm(legR), 'P2, J, Q1 collinear');
  const expectedRatio = norm(legR) / norm(legL); // |P'(0+)| / |P'(1-)| = |Q1 - J| / |J - P2|
  assert.ok(Math.abs(expectedRatio - 1) > 0.05, 'the legs now differ in length');
  const [j] = await joints(page);
  assert.equal(j.geometric >= 1, true, 'G1 holds');
  assert.equal(j.parametric, 0, 'C1 fails: the derivatives differ in length');
  assert.ok(Math.abs(j.ratio - expectedRatio) < 1e-9);
  assert.match(await page.textContent('.joint-card .verdict'), /^C0 · G[12]$/);
  // The speed plot is drawn from these samples: |P'| jumps at u = 1 by the ratio.
  const speeds = await page.evaluate(() => {
    const [a, b] = window.wingspline.model.segments;
    return { left: a.speed[a.speed.length - 1], right: b.speed[0] };
  });
  assert.ok(Math.abs(speeds.right / speeds.left - expectedRatio) < 1e-9);
  assert.ok(Math.abs(speeds.left - 3 * norm(legL)) < 1e-9, '|P\'(1-)| = 3 |J - P2|');
  // The plot canvas shows a jump: its pixels differ left and right of the joint mark.
  const plotDrawn = await page.evaluate(() => {
    const c = document.getElementById('plot-speed');
    const g = c.getContext('2d');
    const data = g.getImageData(0, 0, c.width, c.height).data;
    let ink = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 200 || data[i + 2] < 100) ink += 1;
    return ink;
  });
  assert.ok(plotDrawn > 200, 'the speed plot is drawn');
  await screenshot(page, 'continuity-g1-not-c1');
  assert.deepEqual(page.problems, []);
});

test('the C1 constraint keeps J - P2 = Q1 - J while dragging (lecture 001)', async () => {
  const page = await openLab();
  await drag(page, 'p2', -DRAG_PX, DRAG_PX / 2);
  const s = await state(page);
  const [, , P2, J, J2, Q1] = s.points;
  assert.deepEqual(J, J2, 'the joint is shared');
  assert.ok(norm(sub(sub(J, P2), sub(Q1, J))) < POSITION_TOL);
  const [j] = await joints(page);
  assert.ok(j.parametric >= 1 && j.geometric >= 1);
});

test('presets: zero tangents give C1 without G1; Hermite sharing the tangent is C1; B-spline C2; Catmull-Rom C1', async () => {
  const page = await openLab();
  await choosePreset(page, 'zero-tangent');
  let s = await state(page);
  // P2 = J = Q1: both first derivatives are the zero vector (lecture 004's exception).
  assert.deepEqual(s.points[2], s.points[3]);
  assert.deepEqual(s.points[5], s.points[4]);
  let [j] = await joints(page);
  assert.ok(j.parametric >= 1, 'equal (zero) derivatives: C1');
  assert.equal(j.geometric, 0, 'no tangent direction: not G1');
  await screenshot(page, 'continuity-zero-tangent');

  await choosePreset(page, 'hermite-shared');
  s = await state(page);
  assert.equal(s.family, 'hermite');
  [j] = await joints(page);
  assert.ok(j.parametric >= 1, 'shared point and tangent: C1 by construction');

  await choosePreset(page, 'bspline');
  for (const k of await joints(page)) { assert.equal(k.parametric, 2); assert.equal(k.geometric, 2); }
  await choosePreset(page, 'catmull-rom');
  for (const k of await joints(page)) { assert.equal(k.parametric, 1, 'Catmull-Rom is C1, not C2'); assert.ok(k.geometric >= 1); }
  assert.deepEqual(page.problems, []);
});

test('the travelling point steps at parametric speed and the state survives a share link', async () => {
  const page = await openLab();
  await choosePreset(page, 'g1-not-c1');
  await page.locator('#play').focus();
  await page.keyboard.press('n');
  await page.keyboard.press('n');
  let s = await state(page);
  assert.equal(s.u, 2 / 40);
  // Equal parameter steps cover unequal distances after the joint: speed 2x (the preset's 1 : 2 legs).
  await page.fill('#u', '0.5');
  await page.dispatchEvent('#u', 'input');
  await page.waitForFunction(() => window.wingspline.state.u === 0.5);
  const t = await page.evaluate(() => window.wingspline.model.traveller);
  const api = await page.evaluate(async () => {
    const c = window.wingspline.model.segments[0].curve;
    return Array.from(window.wingspline.api.evaluateCurve(c, [0.5]));
  });
  assert.ok(norm(sub(t.point, api)) < POSITION_TOL, 'the point is the curve at u');
  s = await state(page);
  const url = await page.evaluate(() => window.wingspline.shareUrl());
  const other = await env.openPage(url);
  await other.waitForSelector('body[data-ready=true]');
  const restored = await other.evaluate(() => window.wingspline.state);
  assert.deepEqual(restored.points, s.points);
  assert.equal(restored.u, 0.5);
  assert.deepEqual(page.problems, []);
  assert.deepEqual(other.problems, []);
});

test('keyboard: select a handle with ] and move it with the arrows', async () => {
  const page = await openLab();
  await page.focus('#stage');
  await page.keyboard.press(']');
  await page.keyboard.press(']');
  const selected = await page.evaluate(() => window.wingspline.selected);
  assert.equal(selected, 'p1');
  const before = await state(page);
  await page.keyboard.press('ArrowUp');
  const after = await state(page);
  assert.ok(after.points[1][1] > before.points[1][1]);
  assert.match(await page.textContent('#stage-description'), /joint 1: C/);
});

test('a third segment added under the C2 constraint joins with C2 at both joints', async () => {
  const page = await openLab();
  await page.selectOption('#constraint', 'C2');
  await page.waitForFunction(() => window.wingspline.state.constraint === 'C2');
  await page.click('#add-segment');
  await page.waitForFunction(() => window.wingspline.model.segmentCount === 3);
  const s = await state(page);
  assert.equal(s.points.length, 12);
  // Lecture 001/002: C2 needs equal second derivatives, 6 (L1 - 2 L2 + L3) = 6 (R0 - 2 R1 + R2).
  for (const j of [1, 2]) {
    const [, L1, L2, L3] = s.points.slice(4 * (j - 1), 4 * j);
    const [R0, R1, R2] = s.points.slice(4 * j, 4 * j + 3);
    for (let k = 0; k < 2; k += 1) assert.ok(Math.abs((L1[k] - 2 * L2[k] + L3[k]) - (R0[k] - 2 * R1[k] + R2[k])) < 1e-9);
  }
  for (const j of await joints(page)) { assert.equal(j.parametric, 2); assert.equal(j.geometric, 2); }
  await page.click('#remove-segment');
  await page.waitForFunction(() => window.wingspline.model.segmentCount === 2);
  // The panels follow the model on the next frame.
  await page.waitForFunction(() => document.querySelector('#remove-segment').disabled, null, { timeout: 5000 })
    .catch(() => assert.fail('two segments is the least with a joint: Remove segment should be disabled'));
  assert.deepEqual(page.problems, []);
});

test('Hermite joints: C1 shares the tangent, C2 also matches P\'\' from the Hermite blending functions', async () => {
  const page = await openLab();
  await choosePreset(page, 'hermite-shared');
  let s = await state(page);
  // p0, p1, t0, t1 per segment: the joint shares point and tangent.
  assert.deepEqual(s.points[1], s.points[4]);
  assert.deepEqual(s.points[3], s.points[6]);
  await page.selectOption('#constraint', 'C2');
  await page.waitForFunction(() => window.wingspline.state.constraint === 'C2');
  s = await state(page);
  const [p0, p1, t0, t1, q0, q1, s0, s1] = s.points;
  // H0'' = 12u - 6, H1'' = -12u + 6, H2'' = 6u - 4, H3'' = 6u - 2 (lecture 000's blending functions).
  const left = [0, 1].map((k) => 6 * p0[k] - 6 * p1[k] + 2 * t0[k] + 4 * t1[k]);
  const right = [0, 1].map((k) => -6 * q0[k] + 6 * q1[k] - 4 * s0[k] - 2 * s1[k]);
  for (let k = 0; k < 2; k += 1) assert.ok(Math.abs(left[k] - right[k]) < 1e-9);
  const [j] = await joints(page);
  assert.equal(j.parametric, 2);
  assert.equal(j.geometric, 2);
  assert.deepEqual(page.problems, []);
});

// Typing 1e300 into the inspector (as a person would: click the point,
// type, Enter) must never put Infinity or NaN in the joint table; either the lab shows a
// finite (or plainly undefined) curvature, or it refuses the value with a clear message.
test('typing x = 1e300 for P1 in the inspector: the joint table shows no Infinity (or the value is refused clearly)', async () => {
  const page = await openLab();
  const before = await state(page);
  const p1 = await handle(page, 'p1');
  await page.mouse.click(p1.x, p1.y);
  await page.waitForFunction(() => !document.querySelector('#inspect-x').disabled);
  await page.click('#inspect-x', { clickCount: 3 });
  await page.keyboard.type('1e300');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.wingspline.state.points[1][0] === 1e300 || window.wingspline.message());
  const after = await state(page);
  const row = await page.$$eval('.joint-card tr', (rows) => rows.map((r) => r.textContent).find((t) => t.startsWith('curvature')));
  assert.ok(row, 'the joint table has a curvature row');
  assert.doesNotMatch(row, /Infinity|NaN/);
  if (after.points[1][0] === 1e300) {
    // lecture 001: P''(1) = 6 (P3 - 2 P2 + P1) is about 6e300 now, so the left curvature is a huge finite number
    const [j] = await joints(page);
    assert.ok(Number.isFinite(j.left.curvature) && j.left.curvature > 1e290, `left curvature ${j.left.curvature}`);
  } else {
    assert.deepEqual(after.points, before.points, 'a refused value leaves the drawing as it was');
    assert.match(await page.evaluate(() => window.wingspline.message()), /x|coordinate|limit|large/i);
  }
  assert.deepEqual(page.problems, []);
});

// The zero-tangent preset's curvature is "undefined" in the table and in the
// curvature plot's note (the same rule in the core for both), and every joint card shows what
// lectures 001/004 and 003 would say.
test('zero tangents: curvature "undefined" in the table and the plot agree; the lecture wordings are shown', async () => {
  const page = await openLab();
  await choosePreset(page, 'zero-tangent');
  // the plots (and their note) are drawn on the next frame
  await page.waitForFunction(() => document.querySelector('#curvature-undefined')?.textContent.includes('undefined'));
  const row = await page.$$eval('.joint-card tr', (rows) => rows.map((r) => r.textContent).find((t) => t.startsWith('curvature')));
  assert.match(row, /undefined \(\|P'⁻\| = 0 at u = 1/);
  assert.match(row, /undefined \(\|P'⁺\| = 0 at u = 1/);
  const note = await page.textContent('#curvature-undefined');
  assert.match(note, /κ undefined .* u = 1 \(\|P'\| = 0\)/);
  // Both sides of the joint have P' = 0 at u = 1: one place, named once.
  assert.equal(note.split('u = 1 (').length - 1, 1, `u = 1 is named once: ${note}`);
  await page.click('.joint-card details.wordings summary');
  const rows = await page.$$eval('.joint-card details.wordings tbody tr', (trs) => trs.map((r) => Array.from(r.cells, (c) => c.textContent)));
  assert.equal(rows.length, 3);
  assert.ok(rows.some((r) => r[1] === 'lectures 001, 004' && /proportional/.test(r[0])));
  assert.ok(rows.some((r) => r[1] === 'lecture 003' && /direction of the n th derivative/.test(r[0])));
  assert.deepEqual(page.problems, []);
});

// A state whose preset has no note (a name from a JSON file or a link, which the schema
// accepts as text) once printed the literal word "null" under the rule (a known
// pattern: replaceChildren writes a null child as text).
test('a preset without a note prints no "null" in the rule panel', async () => {
  const page = await openLab();
  await page.evaluate(() => { const c = window.wingspline.ctx; c.commit({ ...c.state, preset: 'my-own-curve' }); });
  await page.waitForFunction(() => window.wingspline.state.preset === 'my-own-curve');
  const text = await page.textContent('#rule-panel');
  assert.match(text, /C1 \(equal first derivatives\) implies G1/);
  for (const word of ['null', 'undefined', 'NaN']) assert.ok(!text.includes(word), `the rule panel prints "${word}": ${text}`);
  assert.deepEqual(page.problems, []);
});

// C^-1 as lecture 004 says it ("the joint is discontinuous, V1(1) != V2(0)"), the gap
// relative to the size of the two segments: 2 max |Q - c| over their 8 control points, c the
// centroid (docs/api-curves.md), recomputed here from the page's state.
function expectedGap(points) {
  const all = points.slice(0, 8);
  const c = [0, 1].map((k) => all.reduce((s, p) => s + p[k], 0) / all.length);
  const size = 2 * Math.max(...all.map((p) => norm(sub(p, c))));
  const gap = norm(sub(points[4], points[3]));
  return { gap, relative: gap / size };
}
async function gapCard(page) {
  // the panel is written on the frame after a change: wait until it shows the model's verdict
  await page.waitForFunction(() => document.querySelector('.joint-card')?.dataset.parametric === String(window.wingspline.model.joints[0].parametric)
    && document.querySelector('.joint-card .ratio').textContent.includes(String(Number((100 * window.wingspline.model.joints[0].relativeGap).toPrecision(3)))));
  const [j] = await joints(page);
  const text = await page.textContent('.joint-card .ratio');
  const verdict = await page.textContent('.joint-card .verdict');
  return { j, text, verdict };
}
function checkGap(s, { j, text, verdict }) {
  const want = expectedGap(s.points);
  assert.ok(want.gap > 1e-3, 'the ends came apart');
  assert.equal(j.parametric, -1);
  assert.equal(j.geometric, -1);
  assert.equal(verdict, 'C-1 · G-1');
  assert.match(text, /the joint is discontinuous, V1\(1\) ≠ V2\(0\)/);
  // the page shows the relative gap in per cent with 3 significant digits
  const shown = Number(/gap is ([\d.]+)% of the size/.exec(text)?.[1]);
  assert.ok(Math.abs(shown / (100 * want.relative) - 1) < 5e-3, `shown ${shown}%, expected ${100 * want.relative}%`);
}

test('in free mode a dragged end leaves a gap, and the lab says C-1 in the lecture\'s words', async () => {
  const page = await openLab();
  await page.selectOption('#constraint', 'free');
  await page.waitForFunction(() => window.wingspline.state.constraint === 'free');
  await drag(page, 'p4', DRAG_PX, -DRAG_PX);
  const s = await state(page);
  checkGap(s, await gapCard(page));
  await screenshot(page, 'continuity-gap-pointer');
  assert.deepEqual(page.problems, []);
});

test('the keyboard makes a gap too: ] to the start of Q2, arrows to move it', async () => {
  const page = await openLab();
  await page.selectOption('#constraint', 'free');
  await page.waitForFunction(() => window.wingspline.state.constraint === 'free');
  await page.focus('#stage');
  for (let i = 0; i < 5; i += 1) await page.keyboard.press(']');
  assert.equal(await page.evaluate(() => window.wingspline.selected), 'p4');
  const before = await state(page);
  for (let i = 0; i < 3; i += 1) await page.keyboard.press('ArrowRight');
  const s = await state(page);
  assert.deepEqual(s.points[3], before.points[3], 'the end of Q1 stays');
  // the panel and the spoken description follow on the next frame
  await page.waitForFunction(() => /joint 1: C-1/.test(document.getElementById('stage-description').textContent));
  checkGap(s, await gapCard(page));
});

test('the gap preset starts at C-1', async () => {
  const page = await openLab();
  await choosePreset(page, 'gap');
  const s = await state(page);
  checkGap(s, await gapCard(page));
  await screenshot(page, 'continuity-gap-preset');
  assert.deepEqual(page.problems, []);
});
