// The three labs on a phone: they load, draw, keep every control reachable without
// horizontal scrolling of the page, and log nothing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();

for (const id of ['continuity', 'comparison', 'surfaces']) {
  test(`${id} is usable on a phone`, async () => {
    const page = await env.openPage(`${env.site.url}${id}.html`, { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });
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
    await screenshot(page, `${id}-phone`);
    assert.deepEqual(page.problems, []);
  });
}
