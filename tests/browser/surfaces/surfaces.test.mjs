// The surface lesson: lecture 002's facts about bicubic patches (corners interpolated, the
// Bezier twist formula, the Hermite basis gives the same surface), rotating the view and
// dragging a net point with the mouse, the inspector, and two joined patches.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { handle, drag } from '../../helpers/pointer.mjs';

const EXACT = 1e-12; // world units
const DRAG_PX = 40;

const env = useSiteAndBrowser();

async function openLesson() {
  const page = await env.openPage(`${env.site.url}surfaces.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  return page;
}
const state = (page) => page.evaluate(() => window.wingspline.state);
const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
// positions[3*(17*i + j) + k] at u = i/16, v = j/16
const sampleAt = (s, i, j) => [0, 1, 2].map((k) => s.positions[3 * (17 * i + j) + k]);

test('a Bezier patch interpolates its corner control points and has the lecture\'s twist', async () => {
  const page = await openLesson();
  const { net, samples } = await page.evaluate(() => ({ net: window.wingspline.state.a, samples: window.wingspline.model.patches.a.samples }));
  // Lecture 002: the patch interpolates p00, p03, p30, p33.
  assert.ok(dist(sampleAt(samples, 0, 0), net[0]) < EXACT);
  assert.ok(dist(sampleAt(samples, 0, 16), net[3]) < EXACT);
  assert.ok(dist(sampleAt(samples, 16, 0), net[12]) < EXACT);
  assert.ok(dist(sampleAt(samples, 16, 16), net[15]) < EXACT);
  // ... and an inner control point is not on the surface (it only pulls).
  const centre = sampleAt(samples, 8, 8);
  assert.ok(dist(centre, net[5]) > 0.1);
  // p_uv(0,0) = 9 (p00 - p01 - p10 + p11)
  const twist = [0, 1, 2].map((k) => 9 * (net[0][k] - net[1][k] - net[4][k] + net[5][k]));
  const coreTwist = [0, 1, 2].map((k) => samples.twists[k]);
  assert.ok(dist(twist, coreTwist) < 1e-9);
  const rows = await page.$$eval('.corners-table tbody tr', (trs) => trs.map((tr) => tr.textContent));
  assert.equal(rows.length, 4);
  for (const r of rows) assert.match(r, /0 ✓/);
  await screenshot(page, 'surfaces-bezier');
  assert.deepEqual(page.problems, []);
});

test('rotate the view, then drag a net point: it moves in the view plane and the corner follows', async () => {
  const page = await openLesson();
  const before = await handle(page, 'a11');
  await page.fill('#yaw', '20');
  await page.dispatchEvent('#yaw', 'input');
  await page.waitForFunction(() => window.wingspline.state.camera.yaw === 20);
  const turned = await handle(page, 'a11');
  assert.ok(Math.hypot(turned.x - before.x, turned.y - before.y) > 5, 'the handle moved on screen with the view');
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('w'); // tilt by the keyboard too
  assert.equal((await state(page)).camera.pitch, 45);

  const s0 = await state(page);
  await drag(page, 'a00', DRAG_PX, -DRAG_PX);
  const s1 = await state(page);
  const moved = s1.a[0];
  assert.ok(dist(moved, s0.a[0]) > 0.1, 'p00 moved');
  // A drag in the view plane keeps the depth: the component towards the eye is unchanged.
  const eye = await page.evaluate(() => {
    const { yaw, pitch } = window.wingspline.state.camera;
    const y = (yaw * Math.PI) / 180; const p = (pitch * Math.PI) / 180;
    return [-Math.sin(y) * Math.cos(p), -Math.cos(y) * Math.cos(p), Math.sin(p)];
  });
  const along = (v) => v[0] * eye[0] + v[1] * eye[1] + v[2] * eye[2];
  assert.ok(Math.abs(along(moved) - along(s0.a[0])) < 1e-9);
  const corner = await page.evaluate(() => Array.from(window.wingspline.model.patches.a.samples.positions.slice(0, 3)));
  assert.ok(dist(corner, moved) < EXACT, 'the surface corner is the moved control point');
  // The other corners stayed.
  assert.deepEqual(s1.a[15], s0.a[15]);
  await screenshot(page, 'surfaces-rotated-drag');
  assert.deepEqual(page.problems, []);
});

test('dragging empty canvas turns the view by half a degree per pixel; Shift-drag pans', async () => {
  const page = await openLesson();
  const box = await page.locator('#stage canvas, canvas').first().boundingBox();
  // A point of the canvas at least 40 px from every handle.
  const handles = await page.evaluate(() => window.wingspline.handles());
  const empty = [[box.x + 20, box.y + 20], [box.x + box.width - 20, box.y + 20], [box.x + 20, box.y + box.height - 20]]
    .find(([x, y]) => handles.every((hd) => Math.hypot(hd.x - x, hd.y - y) > 40));
  assert.ok(empty, 'an empty spot on the canvas');
  const s0 = await state(page);
  const a11 = await handle(page, 'a11');
  await page.mouse.move(...empty);
  await page.mouse.down();
  await page.mouse.move(empty[0] + 60, empty[1] + 20, { steps: 6 });
  await page.mouse.up();
  const s1 = await state(page);
  assert.equal(s1.camera.yaw, s0.camera.yaw + 30);
  assert.equal(s1.camera.pitch, s0.camera.pitch + 10);
  assert.deepEqual(s1.view, s0.view, 'turning does not pan');
  assert.deepEqual(s1.a, s0.a, 'the net is unchanged');
  const turned = await handle(page, 'a11');
  assert.ok(Math.hypot(turned.x - a11.x, turned.y - a11.y) > 5, 'the drawing turned');
  // Shift-drag: the stage's pan, the camera stays.
  await page.keyboard.down('Shift');
  await page.mouse.move(...empty);
  await page.mouse.down();
  await page.mouse.move(empty[0] + 50, empty[1], { steps: 5 });
  await page.mouse.up();
  await page.keyboard.up('Shift');
  const s2 = await state(page);
  assert.deepEqual(s2.camera, s1.camera);
  assert.ok(s2.view.cx < s1.view.cx, 'the view panned (content follows the pointer to the right)');
  assert.deepEqual(page.problems, []);
});

test('the inspector sets z of the selected entry exactly', async () => {
  const page = await openLesson();
  await page.focus('#stage');
  for (let k = 0; k < 6; k += 1) await page.keyboard.press(']');
  assert.equal(await page.evaluate(() => window.wingspline.selected), 'a11');
  // The entry fields follow the selection on the next frame: let two frames pass before
  // typing, or that frame writes the old value over the typed one.
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  await page.fill('#entry-z', '2.5');
  await page.dispatchEvent('#entry-z', 'change');
  await page.waitForFunction(() => window.wingspline.state.a[5][2] === 2.5);
  assert.equal(await page.inputValue('#entry-z'), '2.5');
  assert.deepEqual(page.problems, []);
});

test('the Hermite basis gives the same surface, corners from its corner entries', async () => {
  const page = await openLesson();
  const bezier = await page.evaluate(() => Array.from(window.wingspline.model.patches.a.samples.positions));
  const p = await state(page);
  await page.selectOption('#kind', 'hermite');
  await page.waitForFunction(() => window.wingspline.state.kind === 'hermite');
  const s = await state(page);
  const hermite = await page.evaluate(() => Array.from(window.wingspline.model.patches.a.samples.positions));
  let gap = 0;
  for (let k = 0; k < bezier.length; k += 1) gap = Math.max(gap, Math.abs(bezier[k] - hermite[k]));
  assert.ok(gap < 1e-12, `same surface (max difference ${gap})`);
  // Lecture 002: p_u(0,0) = 3 (p10 - p00), p_v(0,0) = 3 (p01 - p00), corners top-left block.
  assert.ok(dist(s.a[0], p.a[0]) < EXACT && dist(s.a[1], p.a[3]) < EXACT && dist(s.a[4], p.a[12]) < EXACT && dist(s.a[5], p.a[15]) < EXACT);
  assert.ok(dist(s.a[8], [0, 1, 2].map((k) => 3 * (p.a[4][k] - p.a[0][k]))) < EXACT);
  assert.ok(dist(s.a[2], [0, 1, 2].map((k) => 3 * (p.a[1][k] - p.a[0][k]))) < EXACT);
  await screenshot(page, 'surfaces-hermite');
  assert.deepEqual(page.problems, []);
});

test('two patches: C1 across the boundary, then C0 only after a drag', async () => {
  const page = await openLesson();
  await page.check('#joined');
  await page.waitForFunction(() => window.wingspline.state.joined);
  let b = await page.evaluate(() => window.wingspline.model.boundary);
  assert.ok(b.positionGap < EXACT && b.duGap < 1e-9, 'C1 join: same boundary and same p_u');
  assert.equal(await page.getAttribute('#boundary-verdict', 'data-c1'), 'true');
  await screenshot(page, 'surfaces-joined-c1');
  await page.selectOption('#join', 'C0');
  await page.waitForFunction(() => window.wingspline.state.join === 'C0');
  await drag(page, 'b11', 0, -DRAG_PX);
  b = await page.evaluate(() => window.wingspline.model.boundary);
  assert.ok(b.positionGap < EXACT, 'still C0');
  assert.ok(b.duGap > 1e-3, 'no longer C1');
  assert.equal(await page.getAttribute('#boundary-verdict', 'data-c0'), 'true');
  assert.equal(await page.getAttribute('#boundary-verdict', 'data-c1'), 'false');
  assert.deepEqual(page.problems, []);
});
