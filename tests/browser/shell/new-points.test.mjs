// New points appear inside the view (for a phone): whenever a person adds points
// (continuity "Add segment", comparison "Add a segment", the curve explorer's "Add point",
// the surfaces' second patch), every handle is on the canvas afterwards, on a 390 x 844
// phone (a narrow view) and at 1280 x 720; also when the person had zoomed in on part of the
// drawing first. Where the handles are is asked of the app; the buttons are pressed as a
// person does (a tap on the phone, a click at the desk).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();
const VIEWPORTS = {
  phone: { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true },
  desk: { viewport: { width: 1280, height: 720 } },
};

const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

// The labels of the handles outside the canvas's box (client px, from the app).
const handlesOff = (page) => page.evaluate(() => {
  const r = document.getElementById('stage').getBoundingClientRect();
  return window.wingspline.handles().filter((hd) => !(hd.x >= r.left && hd.x <= r.right && hd.y >= r.top && hd.y <= r.bottom)).map((hd) => hd.label);
});
const handleCount = (page) => page.evaluate(() => window.wingspline.handles().length);

// Zoomed in 3x about the canvas's middle with the + key on the canvas (stage.js).
async function zoomIn(page) {
  await page.focus('#stage');
  for (let k = 0; k < 5; k += 1) await page.keyboard.press('+');
  await settle(page);
}

async function press(page, kind, selector) {
  const target = page.locator(selector);
  await target.scrollIntoViewIfNeeded();
  if (kind === 'phone') await target.tap(); else await target.click();
  await settle(page);
}

// lesson, the control that adds points, how many presses (to the lesson's limit or near it).
const CASES = [
  { id: 'continuity', add: '#add-segment', times: 6 },
  { id: 'comparison', add: '#add-segment', times: 8 },
  { id: 'curves', add: '[data-action=add-point]', times: 6 },
  { id: 'surfaces', add: '#joined', times: 1 },
];

for (const [kind, options] of Object.entries(VIEWPORTS)) {
  for (const { id, add, times } of CASES) {
    for (const zoomed of [false, true]) {
      test(`${id} (${kind}${zoomed ? ', zoomed in first' : ''}): every handle is on the canvas after each addition`, async () => {
        const page = await env.openLesson(`${env.site.url}${id}.html`, options);
        if (zoomed) await zoomIn(page);
        for (let k = 0; k < times; k += 1) {
          const before = await handleCount(page);
          await press(page, kind, add);
          assert.ok(await handleCount(page) > before, `press ${k + 1} added handles`);
          assert.deepEqual(await handlesOff(page), [], `after press ${k + 1} every handle is on the canvas`);
        }
        assert.deepEqual(page.problems, []);
      });
    }
  }
}
