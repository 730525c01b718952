// The curve explorer driven as a person would: drag with the mouse at the position the page
// reports for a handle, type into the inspector, use the keyboard, step a construction.
// Expected values come from the lecture (endpoint interpolation, the circle) or from the
// core asked directly (a point on the curve), never from the page's own drawing code.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser, downloadedBytes } from '../../helpers/browser.mjs';
import { openCurves, frame, chooseFamily, circlePreset } from '../../helpers/curves-page.mjs';

const COORD_TOL = 1e-9;          // world units: a stored coordinate vs its expected value
const CIRCLE_TOL = 1e-12;        // world units: NURBS circle points vs the radius
const DARK_SUM = 200;            // r+g+b below this is curve ink (light theme), not grid
const env = useSiteAndBrowser();
const openLesson = () => openCurves(env);

const handle = async (page, id) => (await page.evaluate(() => window.wingspline.handles())).find((x) => x.id === id);

// Darkest pixel (r+g+b) of the stage canvas within `radius` CSS px of the world point (x, y).
async function darkestNear(page, x, y, radius = 2) {
  return page.evaluate(([wx, wy, r]) => {
    const canvas = document.getElementById('stage');
    const rect = canvas.getBoundingClientRect();
    const { x: cx, y: cy } = window.wingspline.toClient(wx, wy);
    const dpr = canvas.width / rect.width;
    const px = Math.round((cx - rect.left) * dpr);
    const py = Math.round((cy - rect.top) * dpr);
    const d = Math.ceil(r * dpr);
    const data = canvas.getContext('2d').getImageData(px - d, py - d, 2 * d + 1, 2 * d + 1).data;
    let best = 765;
    for (let i = 0; i < data.length; i += 4) best = Math.min(best, data[i] + data[i + 1] + data[i + 2]);
    return best;
  }, [x, y, radius]);
}

// The core's point of the current curve at parameter u (asked directly, not the page's model).
const corePoint = (page, u) => page.evaluate((t) => {
  const { api, model } = window.wingspline;
  return Array.from(api.evaluateCurve(model.spec, [t]));
}, u);

const gEntries = (page) => page.$$eval('.matrix-panel math [data-matrix=G]', (nodes) => [...nodes[0].querySelectorAll('mtd')].map((m) => m.textContent.trim()));

test('dragging a Bezier control point moves the state, the matrix panel and the curve', async () => {
  const page = await openLesson();
  const before = await page.evaluate(() => window.wingspline.state);
  assert.equal(before.family, 'bezier');
  const oldPoint = await corePoint(page, 0.5);
  assert.ok(await darkestNear(page, ...oldPoint) < DARK_SUM, 'the curve is drawn where the core puts P(0.5)');

  const p1 = await handle(page, 'p1');
  await page.mouse.move(p1.x, p1.y);
  await page.mouse.down();
  for (let k = 1; k <= 6; k += 1) await page.mouse.move(p1.x + 10 * k, p1.y + 25 * k);
  await page.mouse.up();
  await frame(page);

  const after = await page.evaluate(() => window.wingspline.state);
  const moved = after.points[1];
  // 60 px right and 150 px down on screen, in world units at the page's zoom (y is up).
  const zoom = before.view.zoom;
  const pixel = 1.5 / zoom;
  assert.ok(Math.abs(moved[0] - (before.points[1][0] + 60 / zoom)) <= pixel
    && Math.abs(moved[1] - (before.points[1][1] - 150 / zoom)) <= pixel, `P1 followed the pointer: ${moved}`);
  // the handle is now under the mouse (within a pixel)
  const p1After = await handle(page, 'p1');
  assert.ok(Math.abs(p1After.x - (p1.x + 60)) <= 1.5 && Math.abs(p1After.y - (p1.y + 150)) <= 1.5);
  // Bezier endpoints stay interpolated (lecture 001): P(0) = P0 whatever P1 does.
  const start = await corePoint(page, 0);
  assert.ok(Math.hypot(start[0] - after.points[0][0], start[1] - after.points[0][1]) < COORD_TOL);

  // the matrix panel shows G with P1's new coordinates, formatted as the panel formats them
  const shown = await gEntries(page);
  const expected = await page.evaluate(async (p) => {
    const { formatNumber } = await import('./js/ui/mathml.js');
    return [formatNumber(p[0], 4), formatNumber(p[1], 4)];
  }, moved);
  assert.deepEqual(shown.slice(2, 4), expected, `row P1 of G is ${shown.slice(2, 4)}`);

  // the curve pixels moved: ink at the core's new P(0.5), none left at the old one
  const newPoint = await corePoint(page, 0.5);
  // P(0.5) moves by B_1,3(0.5) = 3/8 of P1's move (Bernstein weight, lecture 001).
  const p1Move = Math.hypot(moved[0] - before.points[1][0], moved[1] - before.points[1][1]);
  assert.ok(Math.abs(Math.hypot(newPoint[0] - oldPoint[0], newPoint[1] - oldPoint[1]) - 0.375 * p1Move) < 1e-9);
  assert.ok(await darkestNear(page, ...newPoint) < DARK_SUM, 'ink at the new P(0.5)');
  assert.ok(await darkestNear(page, ...oldPoint, 1) >= DARK_SUM, 'no ink left at the old P(0.5)');

  // one drag is one undo step
  await page.click('[data-action=undo]');
  await frame(page);
  assert.deepEqual((await page.evaluate(() => window.wingspline.state)).points, before.points);
  await screenshot(page, 'curves-bezier');
  assert.deepEqual(page.problems, []);
});

test('the u slider moves the point on the curve and the cursor of the blending plot', async () => {
  const page = await openLesson();
  const cursorColumn = () => page.evaluate(() => {
    // the u cursor is the only line in the highlight colour across the plot's middle row
    const canvas = document.querySelector('.blending-canvas');
    const g = canvas.getContext('2d');
    const want = getComputedStyle(document.documentElement).getPropertyValue('--focus').trim();
    const [r, gg, b] = [1, 3, 5].map((i) => parseInt(want.slice(i, i + 2), 16));
    const y = Math.round(canvas.height * 0.5);
    const row = g.getImageData(0, y, canvas.width, 1).data;
    const hits = [];
    for (let x = 0; x < canvas.width; x += 1) {
      if (Math.abs(row[4 * x] - r) + Math.abs(row[4 * x + 1] - gg) + Math.abs(row[4 * x + 2] - b) < 30) hits.push(x);
    }
    return hits.length ? (hits[0] + hits[hits.length - 1]) / 2 / (canvas.width / canvas.getBoundingClientRect().width) : null;
  });
  const x1 = await cursorColumn();
  await page.$eval('#curve-u', (input) => { input.value = '0.8'; input.dispatchEvent(new Event('input', { bubbles: true })); });
  await frame(page);
  const state = await page.evaluate(() => window.wingspline.state);
  assert.equal(state.u, 0.8);
  const x2 = await cursorColumn();
  assert.ok(x1 !== null && x2 !== null, 'the cursor is drawn');
  const width = await page.$eval('.blending-canvas', (c) => c.getBoundingClientRect().width);
  // from u = 0.35 to 0.8 on a plot whose domain [0, 1] spans the width less its margins
  const moved = (x2 - x1) / width;
  assert.ok(moved > 0.35 && moved < 0.45, `the cursor moved by ${moved} of the width for du = 0.45`);
  // the highlighted point on the curve is the core's P(0.8)
  const p = await corePoint(page, 0.8);
  const color = await page.evaluate(([x, y]) => {
    const canvas = document.getElementById('stage');
    const rect = canvas.getBoundingClientRect();
    const c = window.wingspline.toClient(x, y);
    const dpr = canvas.width / rect.width;
    return Array.from(canvas.getContext('2d').getImageData(Math.round((c.x - rect.left) * dpr), Math.round((c.y - rect.top) * dpr), 1, 1).data);
  }, p);
  assert.deepEqual(color.slice(0, 3), [0xc2, 0x41, 0x0c], 'the u marker (highlight colour) sits at the core\'s P(0.8)');
  assert.match(await page.textContent('.matrix-panel'), /P\(0\.8\)/);
  assert.deepEqual(page.problems, []);
});

test('keyboard only: select a control point with ] and move it with the arrows', async () => {
  const page = await openLesson();
  const before = await page.evaluate(() => window.wingspline.state);
  await page.focus('#stage');
  await page.keyboard.press(']');
  await page.keyboard.press(']');
  assert.equal(await page.evaluate(() => window.wingspline.selected), 'p1');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowUp');
  await frame(page);
  const after = await page.evaluate(() => window.wingspline.state);
  const step = 10 / before.view.zoom; // stage.js: an arrow moves 10 screen pixels
  assert.ok(Math.abs(after.points[1][0] - (before.points[1][0] + step)) < 1e-3);
  assert.ok(Math.abs(after.points[1][1] - (before.points[1][1] + step)) < 1e-3);
  // the inspector shows the selected point's exact values
  assert.equal(Number(await page.inputValue('#inspect-x')), after.points[1][0]);
  assert.deepEqual(page.problems, []);
});

test('a decreasing knot typed in the inspector is refused with a message; the old knots stay', async () => {
  const page = await openLesson();
  await chooseFamily(page, 'bspline');
  const before = await page.evaluate(() => window.wingspline.state);
  const bad = before.knots.slice();
  bad[5] = bad[4] - 0.1; // t_5 < t_4
  await page.fill('#inspect-knots', bad.join(', '));
  await page.press('#inspect-knots', 'Enter');
  await frame(page);
  const after = await page.evaluate(() => window.wingspline.state);
  assert.deepEqual(after.knots, before.knots);
  const message = await page.evaluate(() => window.wingspline.message());
  assert.match(message, /knot/i);
  assert.match(message, /decreas|non-decreasing|order|less than|smaller/i);
  assert.equal(await page.getAttribute('#message', 'data-kind'), 'error');
  assert.equal(await page.inputValue('#inspect-knots'), before.knots.join(', '));
  assert.deepEqual(page.problems, []);
});

test('a knot of multiplicity p drops the continuity label at that knot to C0', async () => {
  const page = await openLesson();
  await chooseFamily(page, 'bspline');
  // the Bezier's 4 points carry over; 3 more give interior knots (clamped, K + p + 1 = 11)
  for (let k = 0; k < 3; k += 1) await page.click('[data-action=add-point]');
  await frame(page);
  const s = await page.evaluate(() => window.wingspline.state);
  assert.equal(s.degree, 3);
  assert.equal(s.points.length, 7);
  assert.equal(s.knots.length, s.points.length + s.degree + 1);
  const label = (v) => page.$eval(`.knot-groups tr[data-knot="${v}"] td.continuity`, (td) => td.textContent);
  assert.equal(await label(0.5), 'C2', 'a simple interior knot of a cubic: C2 (lecture 002)');
  // 7 points, degree 3: 11 knots; 0.5 three times (m = p)
  const knots = [0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1];
  await page.fill('#inspect-knots', knots.join(', '));
  await page.press('#inspect-knots', 'Enter');
  await frame(page);
  assert.deepEqual((await page.evaluate(() => window.wingspline.state)).knots, knots);
  assert.equal(await label(0.5), 'C0');
  assert.equal(await page.$eval('.knot-groups tr[data-knot="0.5"] td:nth-of-type(1)', (td) => td.textContent), '3');
  // C0 at a triple knot of a cubic: the curve passes through the control point P3 there
  const p = await corePoint(page, 0.5);
  const p3 = (await page.evaluate(() => window.wingspline.state)).points[3];
  assert.ok(Math.hypot(p[0] - p3[0], p[1] - p3[1]) < COORD_TOL, 'P(0.5) = P3 at a knot of multiplicity p');
  await screenshot(page, 'curves-bspline-knots');
  assert.deepEqual(page.problems, []);
});

test('de Casteljau steps level by level to the point on the curve', async () => {
  const page = await openLesson();
  await page.selectOption('#construction-kind', 'de-casteljau');
  await frame(page);
  for (let k = 1; k <= 3; k += 1) {
    await page.click('[data-action=construction-next]');
    await frame(page);
    assert.equal((await page.evaluate(() => window.wingspline.state)).construction.step, k);
    assert.match(await page.textContent('.construction-step'), new RegExp(`level ${k} of 3`));
  }
  const level3 = await page.evaluate(() => window.wingspline.model.construction.levels[3][0]);
  const p = await corePoint(page, 0.35);
  assert.ok(Math.hypot(level3[0] - p[0], level3[1] - p[1]) < 1e-12, 'the last level is P(u) (de Casteljau = Bernstein)');
  await screenshot(page, 'curves-de-casteljau');
  // back with the presenter key (not on the focused drawing)
  await page.focus('[data-action=construction-prev]');
  await page.keyboard.press('PageUp');
  await frame(page);
  assert.equal((await page.evaluate(() => window.wingspline.state)).construction.step, 2);
  assert.deepEqual(page.problems, []);
});

test('the NURBS circle preset gives points on the circle and the homogeneous view', async () => {
  const page = await openLesson();
  await circlePreset(page);
  const r = await page.evaluate(() => {
    const { api, model } = window.wingspline;
    const params = Array.from({ length: 361 }, (_, j) => j / 360);
    const xy = api.evaluateCurve(model.spec, params);
    let worst = 0;
    for (let j = 0; j < params.length; j += 1) worst = Math.max(worst, Math.abs(Math.hypot(xy[2 * j], xy[2 * j + 1]) - 2));
    return { worst, visible: !document.querySelector('#panel-nurbs').hidden };
  });
  assert.ok(r.worst < CIRCLE_TOL, `largest distance from the radius: ${r.worst}`);
  assert.ok(r.visible, 'the NURBS panel with the homogeneous view is shown');
  await screenshot(page, 'curves-nurbs-circle');
  assert.deepEqual(page.problems, []);
});

test('every family draws, Hermite tangents drag, interpolation shows the spline beside it', async () => {
  const page = await openLesson();
  for (const family of ['hermite', 'bspline-uniform', 'catmull-rom', 'interpolation']) {
    await chooseFamily(page, family);
    const p = await corePoint(page, await page.evaluate(() => window.wingspline.model.domain.start));
    assert.ok(p.every(Number.isFinite));
    await screenshot(page, `curves-${family}`);
    if (family === 'hermite') {
      const t1 = await handle(page, 't1');
      await page.mouse.move(t1.x, t1.y);
      await page.mouse.down();
      await page.mouse.move(t1.x + 30, t1.y - 30);
      await page.mouse.up();
      const s = await page.evaluate(() => window.wingspline.state);
      const tip = [s.points[1][0] + s.tangents[1][0] / 3, s.points[1][1] + s.tangents[1][1] / 3];
      const moved = await handle(page, 't1');
      assert.ok(Math.abs(moved.x - (t1.x + 30)) < 1.5 && Math.abs(moved.y - (t1.y - 30)) < 1.5);
      // the handle the page reports sits at P1 + T1/3 of the state (the tangent tip)
      assert.ok(Math.hypot(tip[0] - moved.world.x, tip[1] - moved.world.y) < COORD_TOL, 'the tangent handle is P1 + T1/3');
      // Hermite interpolates its points (lecture 003): P(1) = P1
      const at1 = await corePoint(page, 1);
      assert.ok(Math.hypot(at1[0] - s.points[1][0], at1[1] - s.points[1][1]) < COORD_TOL);
    }
  }
  assert.ok(await page.isVisible('#compare-spline'));
  assert.deepEqual(page.problems, []);
});

test('CSV exports of the samples and the blending functions', async () => {
  const page = await openLesson();
  const csv = async (name) => {
    await page.click('.menu > summary');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click(`[data-export="${name}"]`)]);
    return (await downloadedBytes(download)).toString('utf8').trim().split('\n');
  };
  const samples = await csv('curve-samples.csv');
  assert.equal(samples[0], 'u,x,y');
  assert.equal(samples.length, 1001);
  const last = samples[1000].split(',').map(Number);
  assert.deepEqual(last, [1, 4, 0], 'a Bezier curve ends at its last control point P3 = (4, 0)');
  const blending = await csv('blending-functions.csv');
  assert.equal(blending[0], 'u,B0_3,B1_3,B2_3,B3_3');
  // partition of unity in every exported row (lecture 001)
  for (const line of blending.slice(1)) {
    const v = line.split(',').map(Number).slice(1);
    assert.ok(Math.abs(v.reduce((a, b) => a + b, 0) - 1) < 1e-12);
  }
  assert.deepEqual(page.problems, []);
});

// The canvas's box on the page and the handles' page positions, as the app reports them.
const canvasBox = (page) => page.$eval('#stage', (c) => { const r = c.getBoundingClientRect(); return { left: r.left, top: r.top, right: r.right, bottom: r.bottom }; });
const CLICK_TOL_PX = 1; // page px: a stored point is rounded to 1e-4 world units, far below a pixel at the default zoom

test('Shift+click on empty drawing adds a control point where the mouse is', async () => {
  const page = await openLesson();
  const before = await page.evaluate(() => window.wingspline.state.points.length);
  const box = await canvasBox(page);
  // An empty spot: the lower-left part of the canvas, at least 40 px from every handle.
  const handles = await page.evaluate(() => window.wingspline.handles());
  let spot = null;
  for (let fy = 0.9; fy > 0.1 && !spot; fy -= 0.05) {
    for (let fx = 0.1; fx < 0.9 && !spot; fx += 0.05) {
      const x = box.left + fx * (box.right - box.left);
      const y = box.top + fy * (box.bottom - box.top);
      if (handles.every((hd) => Math.hypot(hd.x - x, hd.y - y) > 40)) spot = { x, y };
    }
  }
  assert.ok(spot, 'an empty spot on the canvas');
  await page.mouse.move(spot.x, spot.y);
  await page.keyboard.down('Shift');
  await page.mouse.down();
  await page.mouse.up();
  await page.keyboard.up('Shift');
  await frame(page);
  const after = await page.evaluate(() => window.wingspline.handles().filter((x) => /^p\d+$/.test(x.id)));
  assert.equal(after.length, before + 1, 'one more control point');
  const nearest = Math.min(...after.map((hd) => Math.hypot(hd.x - spot.x, hd.y - spot.y)));
  assert.ok(nearest < CLICK_TOL_PX, `a control point where the mouse clicked (nearest ${nearest.toFixed(2)} px away)`);
  assert.deepEqual(page.problems, []);
});

test('"Add point" places every new point inside the visible canvas', async () => {
  const page = await openLesson();
  for (const family of ['bezier', 'bspline-uniform', 'hermite']) {
    await chooseFamily(page, family);
    const max = family === 'bspline-uniform' ? 24 : 16;
    let count = await page.evaluate(() => window.wingspline.state.points.length);
    while (count < max) {
      await page.click('[data-action="add-point"]');
      await frame(page);
      const now = await page.evaluate(() => window.wingspline.state.points.length);
      assert.equal(now, count + 1, `${family}: Add point added one point`);
      count = now;
      const box = await canvasBox(page);
      const handles = await page.evaluate(() => window.wingspline.handles().filter((x) => /^p\d+$/.test(x.id)));
      for (const hd of handles) {
        assert.ok(hd.x >= box.left && hd.x <= box.right && hd.y >= box.top && hd.y <= box.bottom,
          `${family}, ${count} points: ${hd.label} at (${hd.x.toFixed(0)}, ${hd.y.toFixed(0)}) lies inside the canvas ${JSON.stringify(box)}`);
      }
    }
  }
  assert.deepEqual(page.problems, []);
});
