// The curve explorer's B-spline constructions and the curvature comb, driven as a person
// would (select, step with the buttons or the presenter keys, apply, tick an overlay).
// Expected values come from the lecture (de Boor ends at P(u); Boehm's insertion and a
// raised multiplicity leave the curve where it was; a circle of radius r has curvature 1/r)
// and from the core asked directly (evaluateCurve on the state's curve), never from the
// page's drawing code.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { openCurves, frame, chooseFamily, circlePreset } from '../../helpers/curves-page.mjs';

const SAME_POINT_TOL = 1e-12;   // world units: two evaluations of the same curve by the core
const CURVE_UNCHANGED_TOL = 1e-12; // world units: the curve before/after a knot insertion
const CURVATURE_TOL = 1e-9;     // 1/world units: the circle's curvature vs 1/r
const COLOUR_TOL = 40;          // sum of |r|+|g|+|b| differences: "this pixel has that colour"
const SAMPLE_COUNT = 257;       // parameters where the curve is compared before and after

const env = useSiteAndBrowser();
const openLesson = () => openCurves(env);

const state = (page) => page.evaluate(() => window.wingspline.state);

// Seven control points (the lesson's B-spline scene) with clamped cubic knots: interior
// knots 1/4, 1/2, 3/4 (lecture 002's open vector), weights all 1.
const SEVEN = [[0, 0], [0.6, 1.8], [1.8, 2.2], [2.6, 0.4], [3.6, 0.2], [4.2, 1.8], [5.4, 2]];
const SEVEN_KNOTS = [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1];
async function useSevenPoints(page, weights = SEVEN.map(() => 1)) {
  const ok = await page.evaluate(([points, knots, w]) => {
    const { ctx } = window.wingspline;
    return ctx.commit({ ...ctx.state, points, knots, weights: w, degree: 3, tangents: points.map(() => [1, 0]), u: 0 });
  }, [SEVEN, SEVEN_KNOTS, weights]);
  assert.ok(ok, 'the seven-point scene is accepted');
  await frame(page);
}

async function setU(page, u) {
  await page.$eval('#curve-u', (input, v) => { input.value = String(v); input.dispatchEvent(new Event('input', { bubbles: true })); }, u);
  await frame(page);
}

// The core's points of the curve the page currently holds, at `params` (or uniform ones).
const coreSamples = (page, params) => page.evaluate(([ps, n]) => {
  const { api, model } = window.wingspline;
  const d = api.curveDomain(model.spec);
  const at = ps ?? Array.from({ length: n }, (_, j) => d.start + ((d.end - d.start) * j) / (n - 1));
  return { params: at, xy: Array.from(api.evaluateCurve(model.spec, at)) };
}, [params ?? null, SAMPLE_COUNT]);

function maxGap(a, b) {
  assert.equal(a.length, b.length);
  let worst = 0;
  for (let j = 0; j < a.length; j += 2) worst = Math.max(worst, Math.hypot(a[j] - b[j], a[j + 1] - b[j + 1]));
  return worst;
}

// The stage canvas pixel (r, g, b) at world point (x, y).
const pixelAt = (page, x, y) => page.evaluate(([wx, wy]) => {
  const canvas = document.getElementById('stage');
  const rect = canvas.getBoundingClientRect();
  const c = window.wingspline.toClient(wx, wy);
  const dpr = canvas.width / rect.width;
  return Array.from(canvas.getContext('2d').getImageData(Math.round((c.x - rect.left) * dpr), Math.round((c.y - rect.top) * dpr), 1, 1).data).slice(0, 3);
}, [x, y]);
const hexRgb = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
const colourGap = (a, b) => Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]);

test('de Boor steps level by level (presenter keys and buttons) to the core\'s P(u)', async () => {
  const page = await openLesson();
  await chooseFamily(page, 'bspline');
  await useSevenPoints(page);
  await setU(page, 0.6);
  await page.selectOption('#construction-kind', 'de-boor');
  await frame(page);
  const s = await state(page);
  const p = s.degree;
  const con = await page.evaluate(() => {
    const c = window.wingspline.model.construction;
    return { levels: c.levels, names: c.names, span: c.span, firstIndex: c.firstIndex, steps: c.steps };
  });
  assert.equal(con.steps, p + 1, 'levels 0..p');
  // Level 0 is P_(span-p)..P_span of the state, and the span holds u: t_span <= u < t_span+1.
  assert.equal(con.firstIndex, con.span - p);
  assert.ok(s.knots[con.span] <= 0.6 && 0.6 < s.knots[con.span + 1], `u = 0.6 in [t${con.span}, t${con.span + 1})`);
  assert.deepEqual(con.levels[0], s.points.slice(con.span - p, con.span + 1));
  assert.deepEqual(con.names[0], Array.from({ length: p + 1 }, (_, j) => con.span - p + j));
  assert.match(await page.textContent('.construction-step'), new RegExp(`P${con.span - p}\\.\\.P${con.span}`));
  // Step with the presenter remote's PageDown (focus on a button, not on the drawing, where
  // keys move the selected point) and with the button itself.
  await page.focus('[data-action=construction-prev]');
  for (let k = 1; k <= p; k += 1) {
    if (k % 2) await page.keyboard.press('PageDown');
    else await page.click('[data-action=construction-next]');
    await frame(page);
    assert.equal((await state(page)).construction.step, k);
    assert.match(await page.textContent('.construction-step'), new RegExp(`level ${k} of ${p}`));
    // entry j of level k is d_(firstIndex + k + j)^k
    assert.equal(con.names[k][0], con.firstIndex + k);
  }
  const point = (await coreSamples(page, [0.6])).xy;
  const last = con.levels[p][0];
  assert.ok(Math.hypot(last[0] - point[0], last[1] - point[1]) < SAME_POINT_TOL, 'the last level is P(u)');
  await screenshot(page, 'curves-de-boor');
  await page.keyboard.press('PageUp');
  await frame(page);
  assert.equal((await state(page)).construction.step, p - 1);
  await page.keyboard.press('Home');
  await frame(page);
  assert.equal((await state(page)).construction.step, 0);
  assert.deepEqual(page.problems, []);
});

test('inserting a knot highlights the new control points and leaves the curve where it was', async () => {
  const page = await openLesson();
  await chooseFamily(page, 'nurbs');
  await useSevenPoints(page, [1, 2, 0.5, 1, 3, 1, 1]);
  await setU(page, 0.4);
  const s0 = await state(page);
  const before0 = await coreSamples(page);
  await page.selectOption('#construction-kind', 'insert-knot');
  await frame(page);
  await page.click('[data-action=construction-next]');
  await frame(page);
  const con = await page.evaluate(() => {
    const c = window.wingspline.model.construction;
    return { points: c.points, changed: c.changed, newPoints: c.newPoints };
  });
  assert.equal(con.points.length, s0.points.length + 1, 'one control point more');
  // Boehm (lecture 002): p new points replace p - 1 old ones around the span of u.
  assert.equal(con.newPoints.length, s0.degree);
  assert.match(await page.textContent('.construction-step'), new RegExp(`${s0.degree} new control points`));
  // The new points are drawn in the highlight colour; the kept ones are the old points.
  const highlight = hexRgb(await page.evaluate(() => window.wingspline.ctx.colors.highlight));
  for (const i of con.newPoints) {
    const colour = await pixelAt(page, ...con.points[i]);
    assert.ok(colourGap(colour, highlight) < COLOUR_TOL, `Q${i} is highlighted: ${colour} vs ${highlight}`);
  }
  const kept = con.points.filter((_, i) => !con.changed[i]);
  // (a NURBS point goes through (w x, w y, w) and back: equal up to rounding)
  for (const q of kept) assert.ok(s0.points.some((p) => Math.hypot(p[0] - q[0], p[1] - q[1]) < SAME_POINT_TOL), `Q (${q}) is an old point`);
  await screenshot(page, 'curves-insert-knot');
  await page.click('[data-action=construction-apply]');
  await frame(page);
  const s1 = await state(page);
  assert.equal(s1.points.length, s0.points.length + 1);
  assert.equal(s1.knots.length, s0.knots.length + 1);
  assert.ok(s1.knots.includes(0.4), 'the knot 0.4 is in the knot vector');
  const after1 = await coreSamples(page, before0.params);
  const gap = maxGap(before0.xy, after1.xy);
  assert.ok(gap < CURVE_UNCHANGED_TOL, `the curve did not move (largest gap ${gap})`);
  assert.deepEqual(page.problems, []);
});

test('raising a knot\'s multiplicity keeps the curve and lowers the continuity label', async () => {
  const page = await openLesson();
  await chooseFamily(page, 'bspline');
  await useSevenPoints(page);
  const s0 = await state(page);
  assert.equal(s0.degree, 3);
  const knot = s0.knots[s0.degree + 1];
  const label = () => page.$eval(`.knot-groups tr[data-knot="${knot}"] td.continuity`, (td) => td.textContent);
  assert.equal(await label(), 'C2', 'a simple knot of a cubic');
  const before0 = await coreSamples(page);
  for (const expected of ['C1', 'C0']) {
    await page.click(`.knot-groups tr[data-knot="${knot}"] [data-action=raise-multiplicity]`);
    await frame(page);
    assert.equal(await label(), expected);
    const gap = maxGap(before0.xy, (await coreSamples(page, before0.params)).xy);
    assert.ok(gap < CURVE_UNCHANGED_TOL, `the curve did not move (largest gap ${gap})`);
  }
  // m = p: no further raise inside the domain (C0 is the least a joint keeps); no lowering
  // button (knot removal moves the curve; Undo takes a raise back exactly).
  assert.ok(await page.isDisabled(`.knot-groups tr[data-knot="${knot}"] [data-action=raise-multiplicity]`));
  assert.equal(await page.$$eval('[data-action=lower-multiplicity]', (b) => b.length), 0);
  await page.click('[data-action=undo]');
  await frame(page);
  assert.equal(await label(), 'C1');
  assert.equal((await state(page)).points.length, s0.points.length + 1);
  assert.deepEqual(page.problems, []);
});

test('the curvature comb of the exact circle: curvature 1/r, teeth towards the centre, drawn', async () => {
  const page = await openLesson();
  await circlePreset(page);
  const radius = 2;
  const off = await page.evaluate(() => window.wingspline.model.comb);
  assert.equal(off, null, 'no comb before the overlay is on');
  await page.check('#overlay-comb');
  await frame(page);
  const comb = await page.evaluate(() => {
    const c = window.wingspline.model.comb;
    return { teeth: Array.from(c.teeth), count: c.count, maxCurvature: c.maxCurvature };
  });
  assert.ok(Math.abs(comb.maxCurvature - 1 / radius) < CURVATURE_TOL);
  for (let j = 0; j < comb.count; j += 1) {
    const [x, y, kx, ky] = comb.teeth.slice(4 * j, 4 * j + 4);
    assert.ok(Math.abs(Math.hypot(kx, ky) - 1 / radius) < CURVATURE_TOL, `tooth ${j} has length 1/r`);
    // the tooth points from the foot to the centre (0, 0): foot + r^2 * tooth = centre
    assert.ok(Math.hypot(x + radius * radius * kx, y + radius * radius * ky) < 1e-9, `tooth ${j} points at the centre`);
  }
  // Drawn: a pixel on the line of the teeth's tips (inside the circle) has the comb colour.
  // The first tooth whose tip no label covers (labels sit on top of the drawing;
  // the app reports where: labelRects).
  const tip = await page.evaluate(() => {
    const { model, ctx } = window.wingspline;
    const c = model.comb;
    const s = (60 / ctx.state.view.zoom) / c.maxCurvature;
    const labels = window.wingspline.labelRects();
    for (let j = 0; j < c.count; j += 1) {
      const at = [c.teeth[4 * j] + c.teeth[4 * j + 2] * s, c.teeth[4 * j + 1] + c.teeth[4 * j + 3] * s];
      const p = window.wingspline.toClient(...at);
      if (!labels.some((l) => p.x > l.x - 3 && p.x < l.x + l.width + 3 && p.y > l.y - 3 && p.y < l.y + l.height + 3)) return [...at, ctx.colors.series[3]];
    }
    return null;
  });
  assert.ok(tip, 'a tooth tip is not under a label');
  const colour = await pixelAt(page, tip[0], tip[1]);
  const background = hexRgb(await page.evaluate(() => window.wingspline.ctx.colors.background));
  assert.ok(colourGap(colour, background) > COLOUR_TOL, `ink at the first tooth's tip: ${colour}`);
  await screenshot(page, 'curves-comb');
  assert.deepEqual(page.problems, []);
});

test('de Boor on a uniform B-spline labels its points from the core\'s firstIndex', async () => {
  const page = await openLesson();
  await chooseFamily(page, 'bspline-uniform');
  await useSevenPoints(page);
  const d = await page.evaluate(() => window.wingspline.model.domain);
  // segment i = [i, i+1] uses P_i..P_i+p (lecture 002): u = 2.5 is in segment 2
  assert.ok(d.end > 2.5);
  await setU(page, 2.5);
  await page.selectOption('#construction-kind', 'de-boor');
  await frame(page);
  const con = await page.evaluate(() => window.wingspline.model.construction);
  assert.equal(con.firstIndex, 2);
  const s = await state(page);
  assert.deepEqual(con.levels[0], s.points.slice(2, 2 + s.degree + 1));
  assert.deepEqual(page.problems, []);
});
