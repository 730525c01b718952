// The Fit button on every lesson's canvas (for a phone): one button of the page
// skeleton, on the canvas's corner, named for assistive technology, 44 x 44 CSS px or more on
// a phone; a tap (phone), a click or the keyboard (desktop) brings every handle back inside
// the canvas after the view was moved away. Where the handles are is asked of the app.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { lessons } from '../../../web/js/lessons/registry.js';

const env = useSiteAndBrowser();
const PHONE = { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true };
const DESKTOP = { viewport: { width: 1280, height: 720 } };
// The smallest touch target on a phone (CSS px; WCAG 2.5.5, Apple's and Google's guides).
const TOUCH_TARGET_PX = 44;
// Layout positions are multiples of 1/64 CSS px: a box may measure one such unit less.
const LAYOUT_UNIT_PX = 1 / 64;

const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

// Handles (client px, from the app) inside and outside the canvas's box.
async function handlesInCanvas(page) {
  return page.evaluate(() => {
    const r = document.getElementById('stage').getBoundingClientRect();
    const all = window.wingspline.handles();
    const outside = all.filter((hd) => !(hd.x >= r.left && hd.x <= r.right && hd.y >= r.top && hd.y <= r.bottom)).map((hd) => hd.label);
    return { count: all.length, outside };
  });
}

// The view moved far away: zoomed in 8x about a point well off the drawing (as the person
// would with the wheel or fingers; set through the app so every lesson starts from the same
// kind of lost view).
async function lookAway(page) {
  await page.evaluate(() => {
    const c = window.wingspline.ctx;
    const v = c.state.view;
    const { width } = c.stage.size;
    c.setView({ cx: v.cx + 3 * width / v.zoom, cy: v.cy - 2 * width / v.zoom, zoom: v.zoom * 8 });
  });
  await settle(page);
  const away = await handlesInCanvas(page);
  assert.ok(away.count > 0);
  assert.equal(away.outside.length, away.count, 'every handle is off the canvas before Fit');
}

// The one Fit button: on the canvas (its box within the canvas's box), named, one per page.
async function fitButton(page) {
  const button = page.getByRole('button', { name: /^Fit the drawing/ });
  assert.equal(await button.count(), 1, 'one Fit button');
  assert.equal(await page.getByRole('button', { name: /^Fit$/ }).count(), 0, 'no per-lesson Fit button besides it');
  const b = await button.boundingBox();
  const c = await page.locator('#stage').boundingBox();
  assert.ok(b.x >= c.x && b.y >= c.y && b.x + b.width <= c.x + c.width + 0.5 && b.y + b.height <= c.y + c.height + 0.5,
    `the button lies on the canvas (${JSON.stringify(b)} in ${JSON.stringify(c)})`);
  return { button, box: b };
}

for (const { id, page: file } of lessons.filter((l) => l.ready)) {
  const url = () => `${env.site.url}${file ?? `${id}.html`}`;

  test(`${id} on a phone: a tap on Fit brings every handle back onto the canvas`, async () => {
    const page = await env.openLesson(url(), PHONE);
    const { button, box } = await fitButton(page);
    assert.ok(box.width >= TOUCH_TARGET_PX - LAYOUT_UNIT_PX && box.height >= TOUCH_TARGET_PX - LAYOUT_UNIT_PX, `a ${TOUCH_TARGET_PX} px touch target (${box.width} x ${box.height})`);
    await lookAway(page);
    await button.scrollIntoViewIfNeeded();
    const b = await button.boundingBox();
    await page.touchscreen.tap(b.x + b.width / 2, b.y + b.height / 2);
    await settle(page);
    assert.deepEqual((await handlesInCanvas(page)).outside, [], 'every handle is on the canvas');
    assert.deepEqual(page.problems, []);
  });

  test(`${id} at a desk: Fit by a click, and by the keyboard (Tab to it, Enter; or 0)`, async () => {
    const page = await env.openLesson(url(), DESKTOP);
    const { button } = await fitButton(page);
    await lookAway(page);
    await button.click();
    await settle(page);
    assert.deepEqual((await handlesInCanvas(page)).outside, [], 'after a click every handle is on the canvas');
    // From the canvas, Tab reaches the button next; Enter presses it.
    await lookAway(page);
    await page.focus('#stage');
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.activeElement?.getAttribute('aria-label')?.startsWith('Fit the drawing')), true, 'Tab from the canvas reaches Fit');
    await page.keyboard.press('Enter');
    await settle(page);
    assert.deepEqual((await handlesInCanvas(page)).outside, [], 'after Enter every handle is on the canvas');
    // The key the button names (aria-keyshortcuts) does the same from the canvas.
    const key = await button.getAttribute('aria-keyshortcuts');
    assert.ok(key, 'the button names its key');
    await lookAway(page);
    await page.focus('#stage');
    await page.keyboard.press(key);
    await settle(page);
    assert.deepEqual((await handlesInCanvas(page)).outside, [], `after ${key} every handle is on the canvas`);
    assert.deepEqual(page.problems, []);
  });
}
