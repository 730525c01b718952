// Every lesson on a phone: it loads, draws, keeps every control reachable without
// horizontal scrolling of the page, and logs nothing (the mesh lesson was 405 px
// wide at 390, its one-column grid grown by its widest content).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { lessons } from '../../../web/js/lessons/registry.js';

const env = useSiteAndBrowser();

for (const { id, page: file } of lessons) {
  test(`${id} is usable on a phone`, async () => {
    const page = await env.openPage(`${env.site.url}${file ?? `${id}.html`}`, { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });
    await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
    // A too-wide element makes a mobile browser widen its layout viewport, so compare with the device width.
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - 390);
    assert.ok(overflow <= 0, `no horizontal page scrolling (overflow ${overflow}px)`);
    // Every handle the page reports lies on the canvas.
    const box = await page.locator('#stage').boundingBox();
    const handles = await page.evaluate(() => window.wingspline.handles());
    assert.ok(handles.length > 0);
    const inside = handles.filter((hd) => hd.x >= box.x && hd.x <= box.x + box.width && hd.y >= box.y && hd.y <= box.y + box.height);
    assert.ok(inside.length >= handles.length * 0.8, `${inside.length} of ${handles.length} handles are in view`);
    // Boxes that scroll sideways (wide tables, long formulas) show that they do: marked, with
    // their edge shadows (site.css); boxes that fit are not marked.
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
    const boxes = await page.$$eval('.table-scroll, .formula, .formula-out, .panel-body', (list) => list
      .filter((b) => b.getClientRects().length)
      .map((b) => ({ wide: b.scrollWidth > b.clientWidth + 1, marked: b.dataset.scrollsX !== undefined, shadow: getComputedStyle(b).backgroundImage.includes('gradient') })));
    for (const b of boxes) {
      assert.equal(b.marked, b.wide, 'a box is marked exactly when it scrolls sideways');
      if (b.wide) assert.ok(b.shadow, 'a sideways-scrolling box shows its edge shadows');
    }
    await screenshot(page, `${id}-phone`);
    assert.deepEqual(page.problems, []);
  });
}
