// Fingers on the drawing of every lesson, on a 390 x 844 phone: one
// finger scrolls the page unless it starts on a handle; a finger on a handle drags it and
// the page stays; two fingers pan (their midpoint) and zoom (their distance) the drawing
// about their midpoint, and the page stays. Real touch sequences through the browser's input
// pipeline (CDP Input.dispatchTouchEvent: the browser itself decides whether a touch
// scrolls); where things are is asked of the app (window.wingspline.handles, toClient).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { lessons } from '../../../web/js/lessons/registry.js';

const env = useSiteAndBrowser();
const PHONE = { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true };
// A finger closer than this (CSS px) to a handle could be taken as on it (stage.js: 24 px
// for touch); the free spots the tests use are farther from every handle.
const CLEAR_PX = 40;

const frames = (page, n = 3) => page.evaluate((count) => new Promise((resolve) => {
  let left = count;
  const step = () => (--left <= 0 ? resolve() : requestAnimationFrame(step));
  requestAnimationFrame(step);
}), n);

async function openPhone(id, file) {
  const page = await env.openLesson(`${env.site.url}${file ?? `${id}.html`}`, PHONE);
  // The canvas in the middle of the screen, with page above and below it to scroll.
  await page.evaluate(() => document.getElementById('stage').scrollIntoView({ block: 'center' }));
  await frames(page);
  const cdp = await page.context().newCDPSession(page);
  // touchPoints: [[x, y], ...] in viewport CSS px; each finger keeps its index as its id.
  const touch = (type, points = []) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })),
  });
  return { page, touch };
}

// The part of the canvas on screen, and spots in it at least CLEAR_PX from every handle
// (the handles as the app reports them, in client px).
async function layout(page) {
  return page.evaluate((clear) => {
    const r = document.getElementById('stage').getBoundingClientRect();
    const box = { left: Math.max(r.left, 0), top: Math.max(r.top, 0), right: Math.min(r.right, innerWidth), bottom: Math.min(r.bottom, innerHeight) };
    const handles = window.wingspline.handles();
    const free = [];
    for (let y = box.top + 30; y <= box.bottom - 30; y += 10) {
      for (let x = box.left + 30; x <= box.right - 30; x += 10) {
        if (handles.every((hd) => Math.hypot(hd.x - x, hd.y - y) >= clear)) free.push([x, y]);
      }
    }
    return { box, handles, free, scrollY: window.scrollY };
  }, CLEAR_PX);
}

const lessonState = (page) => page.evaluate(() => JSON.stringify(window.wingspline.state));
const withoutView = (json) => { const s = JSON.parse(json); delete s.view; return s; };

for (const { id, page: file } of lessons.filter((l) => l.ready)) {
  test(`${id}: one finger away from the handles scrolls the page, and leaves the drawing as it was`, async () => {
    const { page, touch } = await openPhone(id, file);
    const { free, box, scrollY } = await layout(page);
    // A vertical swipe of 160 px from the free spot nearest the canvas's middle height.
    const midY = (box.top + box.bottom) / 2;
    const start = free.sort((a, b) => Math.abs(a[1] - midY) - Math.abs(b[1] - midY))[0];
    assert.ok(start, 'a spot on the canvas away from every handle');
    const maxScroll = await page.evaluate(() => document.documentElement.scrollHeight - innerHeight);
    const dir = scrollY < maxScroll ? -1 : 1; // finger up scrolls down while there is page below
    const before = await lessonState(page);
    await touch('touchStart', [start]);
    for (let k = 1; k <= 8; k += 1) await touch('touchMove', [[start[0], start[1] + dir * 20 * k]]);
    await touch('touchEnd');
    await frames(page, 4);
    const after = await page.evaluate(() => window.scrollY);
    assert.notEqual(after, scrollY, `the page scrolled (scrollY ${scrollY} -> ${after})`);
    assert.equal(await lessonState(page), before, 'the lesson state and its view are unchanged');
    assert.deepEqual(page.problems, []);
  });

  test(`${id}: one finger on a handle drags it, and the page does not scroll (on a handle that only selects, it scrolls the page and moves nothing)`, async () => {
    const { page, touch } = await openPhone(id, file);
    const { handles, box, scrollY } = await layout(page);
    if (!handles.some((hd) => hd.draggable)) {
      // A lesson whose handles only select (the code lesson's vertices): the finger is the
      // page's, as away from the handles.
      const target = handles.find((hd) => hd.x >= box.left + 20 && hd.x <= box.right - 20 && hd.y >= box.top + 60 && hd.y <= box.bottom - 60);
      assert.ok(target, 'a handle on screen');
      const maxScroll = await page.evaluate(() => document.documentElement.scrollHeight - innerHeight);
      const dir = scrollY < maxScroll ? -1 : 1;
      const before = withoutView(await lessonState(page));
      await touch('touchStart', [[target.x, target.y]]);
      for (let k = 1; k <= 8; k += 1) await touch('touchMove', [[target.x, target.y + dir * 20 * k]]);
      await touch('touchEnd');
      await frames(page, 4);
      assert.notEqual(await page.evaluate(() => window.scrollY), scrollY, 'the page scrolled');
      const after = await page.evaluate((hid) => window.wingspline.handles().find((hd) => hd.id === hid), target.id);
      assert.deepEqual(after.world, target.world, `${target.label} stayed where it was`);
      assert.deepEqual(withoutView(await lessonState(page)), before, 'the lesson state is unchanged');
      assert.deepEqual(page.problems, []);
      return;
    }
    // A draggable handle on screen whose nearest other handle is more than 30 px away, so
    // the finger can only mean that one; 50 px of room above or below it inside the canvas
    // (a vertical move: the one the browser would take as a page scroll).
    const target = handles.find((hd) => hd.draggable && hd.x >= box.left + 20 && hd.x <= box.right - 20 && hd.y >= box.top + 60 && hd.y <= box.bottom - 10
      && handles.every((o) => o === hd || Math.hypot(o.x - hd.x, o.y - hd.y) > 30));
    assert.ok(target, 'a draggable handle on screen, clear of the others');
    await touch('touchStart', [[target.x, target.y]]);
    for (let k = 1; k <= 5; k += 1) await touch('touchMove', [[target.x + 2 * k, target.y - 10 * k]]);
    await touch('touchEnd');
    await frames(page);
    const moved = await page.evaluate((hid) => window.wingspline.handles().find((hd) => hd.id === hid), target.id);
    assert.ok(moved, 'the handle is still there');
    assert.notDeepEqual(moved.world, target.world, `${target.label} moved`);
    assert.equal(await page.evaluate(() => window.scrollY), scrollY, 'the page did not scroll');
    assert.deepEqual(page.problems, []);
  });

  test(`${id}: a one-finger tap on a handle selects it and moves nothing`, async () => {
    const { page, touch } = await openPhone(id, file);
    const { handles, box } = await layout(page);
    const target = handles.find((hd) => hd.x >= box.left + 10 && hd.x <= box.right - 10 && hd.y >= box.top + 10 && hd.y <= box.bottom - 10
      && handles.every((o) => o === hd || Math.hypot(o.x - hd.x, o.y - hd.y) > 30));
    assert.ok(target, 'a handle on screen, clear of the others');
    const before = withoutView(await lessonState(page));
    await touch('touchStart', [[target.x, target.y]]);
    await touch('touchEnd');
    await frames(page);
    assert.equal(await page.evaluate(() => window.wingspline.selected), target.id, `${target.label} is selected`);
    const after = await page.evaluate((hid) => window.wingspline.handles().find((hd) => hd.id === hid), target.id);
    assert.deepEqual(after.world, target.world, 'the handle stayed where it was');
    // The mesh lesson makes a tapped vertex the walk's vertex (lesson.js onSelect): that is
    // the one change a tap may make there.
    const changed = withoutView(await lessonState(page));
    if (id === 'mesh') { delete changed.vertex; delete changed.step; delete before.vertex; delete before.step; }
    assert.deepEqual(changed, before, 'nothing else changed');
    assert.deepEqual(page.problems, []);
  });

  test(`${id}: two fingers zoom the drawing about their midpoint and pan it, and the page does not scroll`, async () => {
    const { page, touch } = await openPhone(id, file);
    const { free, box, scrollY } = await layout(page);
    const other = withoutView(await lessonState(page));
    // The midpoint: the free spot nearest the visible canvas's centre; fingers 30 px either
    // side of it, horizontally, spreading to 60 px either side (distance x2).
    const c = [(box.left + box.right) / 2, (box.top + box.bottom) / 2];
    const m = free.sort((a, b) => Math.hypot(a[0] - c[0], a[1] - c[1]) - Math.hypot(b[0] - c[0], b[1] - c[1]))[0];
    assert.ok(m, 'a free spot for the midpoint');
    const view0 = await page.evaluate(() => window.wingspline.state.view);
    // The world point under the midpoint before the gesture (asked of the stage).
    const world = await page.evaluate(([x, y]) => {
      const r = document.getElementById('stage').getBoundingClientRect();
      return window.wingspline.ctx.stage.transform().toWorld(x - r.left, y - r.top);
    }, m);
    await touch('touchStart', [[m[0] - 30, m[1]]]);
    await touch('touchStart', [[m[0] - 30, m[1]], [m[0] + 30, m[1]]]);
    for (let k = 1; k <= 6; k += 1) await touch('touchMove', [[m[0] - 30 - 5 * k, m[1]], [m[0] + 30 + 5 * k, m[1]]]);
    await frames(page);
    const view1 = await page.evaluate(() => window.wingspline.state.view);
    // Zoom by the ratio of the distances (120 / 60), within 1% (the stage clamps nothing here).
    assert.ok(Math.abs(view1.zoom / view0.zoom - 2) < 0.02, `zoom x${(view1.zoom / view0.zoom).toFixed(3)}, expected x2`);
    const under = await page.evaluate(([x, y]) => window.wingspline.toClient(x, y), world);
    assert.ok(Math.hypot(under.x - m[0], under.y - m[1]) < 1.5, `the world point under the midpoint stays there (${under.x.toFixed(1)}, ${under.y.toFixed(1)} vs ${m[0]}, ${m[1]})`);
    // Then both fingers move 40 px right and 25 px down: the same world point follows them.
    for (let k = 1; k <= 5; k += 1) await touch('touchMove', [[m[0] - 60 + 8 * k, m[1] + 5 * k], [m[0] + 60 + 8 * k, m[1] + 5 * k]]);
    await touch('touchEnd');
    await frames(page);
    const view2 = await page.evaluate(() => window.wingspline.state.view);
    assert.ok(Math.abs(view2.zoom / view1.zoom - 1) < 1e-9, 'a two-finger move does not zoom');
    const panned = await page.evaluate(([x, y]) => window.wingspline.toClient(x, y), world);
    assert.ok(Math.hypot(panned.x - (m[0] + 40), panned.y - (m[1] + 25)) < 1.5, `the drawing followed the fingers (${panned.x.toFixed(1)}, ${panned.y.toFixed(1)} vs ${m[0] + 40}, ${m[1] + 25})`);
    assert.equal(await page.evaluate(() => window.scrollY), scrollY, 'the page did not scroll');
    assert.deepEqual(withoutView(await lessonState(page)), other, 'only the view changed');
    assert.deepEqual(page.problems, []);
  });
}

// Dragging must not silently change the walk's vertex. A pinch whose first finger
// lands on a mesh vertex is a gesture on the view: the walk keeps its vertex. Failed before:
// the vertex under the first finger became the walk's vertex when the fingers lifted.
test('mesh: a pinch that starts on a vertex zooms and leaves the walk\'s vertex alone', async () => {
  const { page, touch } = await openPhone('mesh');
  const { handles } = await layout(page);
  const vertex0 = await page.evaluate(() => window.wingspline.state.vertex);
  const target = handles.find((hd) => hd.label !== `v${vertex0 + 1}` && hd.y > 60 && hd.y < 780);
  assert.ok(target, 'a vertex other than the walk\'s, on screen');
  const zoom0 = await page.evaluate(() => window.wingspline.state.view.zoom);
  await touch('touchStart', [[target.x, target.y]]);
  await touch('touchStart', [[target.x, target.y], [target.x + 60, target.y]]);
  for (let k = 1; k <= 6; k += 1) await touch('touchMove', [[target.x - 5 * k, target.y], [target.x + 60 + 5 * k, target.y]]);
  await touch('touchEnd');
  await frames(page, 4);
  assert.ok(await page.evaluate(() => window.wingspline.state.view.zoom) > zoom0 * 1.2, 'the pinch zoomed');
  assert.equal(await page.evaluate(() => window.wingspline.state.vertex), vertex0, 'the walk keeps its vertex');
  assert.deepEqual(page.problems, []);
});
