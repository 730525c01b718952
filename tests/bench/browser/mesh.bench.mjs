// ui_traversal_step (docs/benchmarks.md): one step of the winged-edge walk on a 10,000-face
// mesh in headless Chromium, in ms per step. Input: docs/benchmarks.md's sphere_10000 (100 slices x
// 51 stacks), the walk around vertex 0 (the north pole, valence 100). A step is the key
// press (state change, recompute) plus the page's render callback that redraws the canvas
// and updates the panels (the browser's own paint is not included). Never run by npm test.
import { wants, report } from '../wasm/harness.mjs';
import { startSite, launchBrowser, openPage } from '../../helpers/browser.mjs';

const TASK = 'ui_traversal_step';
const REPETITIONS = 7;
const SLICES = 100;
const STACKS = 51;

if (wants(TASK)) {
  const site = await startSite();
  const browser = await launchBrowser();
  try {
    const page = await openPage(browser, `${site.url}mesh.html`);
    await page.waitForSelector('body[data-ready=true]', { timeout: 20000 });
    await page.selectOption('#mesh-kind', 'sphere');
    await page.fill('#sphere-slices', String(SLICES));
    await page.press('#sphere-slices', 'Enter');
    await page.fill('#sphere-stacks', String(STACKS));
    await page.press('#sphere-stacks', 'Enter');
    await page.waitForFunction((f) => window.wingspline.model?.F === f, 2 * SLICES * (STACKS - 1));
    await page.click('#walk-title'); // focus off the canvas, as a presenter's remote would be
    const result = await page.evaluate(async (repetitions) => {
      const key = (k) => document.activeElement.dispatchEvent(new KeyboardEvent('keydown', { key: k, bubbles: true, cancelable: true }));
      // One step: the key handler, then the page's render callback. rAF callbacks of a frame
      // run in the order they were queued, so `before` (queued before the key) and `after`
      // (queued after it) bracket the page's own render callback exactly.
      async function step(k) {
        let before = 0;
        requestAnimationFrame(() => { before = performance.now(); });
        const t0 = performance.now();
        key(k);
        const inHandler = performance.now() - t0;
        const after = await new Promise((resolve) => requestAnimationFrame(() => resolve(performance.now())));
        return inHandler + (after - before);
      }
      const steps = window.wingspline.model.frames.length - 1;
      const totals = [];
      let checksum = 0;
      for (let r = 0; r < repetitions; r += 1) {
        await step('Home');
        let total = 0;
        for (let s = 0; s < steps; s += 1) {
          total += await step('PageDown');
          checksum += window.wingspline.model.frame.current;
        }
        totals.push(total);
      }
      return { steps, totals, checksum };
    }, REPETITIONS);
    if (page.problems.length) throw new Error(page.problems.join('\n'));
    report({ task: TASK, build: 'browser', input: `sphere_${2 * SLICES * (STACKS - 1)}`, n: result.steps, seconds: result.totals, checksum: result.checksum, unit: 'ms' });
  } finally {
    await browser.close();
    await site.close();
  }
}
