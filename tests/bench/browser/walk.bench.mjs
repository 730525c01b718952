// ui_walk_step (docs/benchmarks.md): one step of the vertex walk and one of the face walk,
// from the key press to the frame drawn, on the lecture mesh, sphere_100000 and
// sphere_1000000, in ms per step (median and p95 of 50 steps each), headless Chromium.
// A step is the key handler (state change, recompute) plus the animation frame that follows
// it up to a callback queued after the key: the page's render callback (canvas, tables,
// narration) and whatever else that frame runs, timed from the frame's start (its rAF
// timestamp), so the wait for the frame is not counted and a render queued before the key
// still is (the browser's own style, layout and paint after the callbacks are not included,
// except layout the page forces). The walks: on the
// lecture mesh around v2 and along F1 (the slide's); on a sphere around the vertex in the
// middle of the middle ring (valence 6) and along the middle face. A walk that reaches its
// end starts again (Home, not timed). Never run by npm test.
//   WINGSPLINE_WALK_SITES=before=/tmp/dist-old,after=dist node tests/bench/browser/walk.bench.mjs
// measures several built sites in one run (default: this worktree's dist/).
import { wants, report } from '../wasm/harness.mjs';
import { benchSites, msSummary } from './sites.mjs';
import { startSite, launchBrowser, openPage } from '../../helpers/browser.mjs';
import { chooseSphere } from '../../helpers/mesh-page.mjs';

const TASK = 'ui_walk_step';
const STEPS = 50;
const SPHERES = [[250, 201], [1000, 501]];

async function walkSteps(page, walk, element) {
  await page.selectOption('#walk-kind', walk);
  await page.waitForFunction((k) => window.wingspline.model.walkKind === k, walk, { timeout: 120000 });
  await page.fill('#walk-element', String(element + 1));
  await page.press('#walk-element', 'Enter');
  await page.waitForFunction(([k, e]) => window.wingspline.model.walkKind === k && window.wingspline.model.walkElement === e, [walk, element], { timeout: 120000 });
  await page.click('#walk-title'); // focus off the canvas and the fields, as a presenter's remote would be
  return page.evaluate(async (steps) => {
    const key = (k) => document.activeElement.dispatchEvent(new KeyboardEvent('keydown', { key: k, bubbles: true, cancelable: true }));
    async function step(k) {
      const t0 = performance.now();
      key(k);
      const t1 = performance.now();
      const { start, end } = await new Promise((resolve) => requestAnimationFrame((ts) => resolve({ start: ts, end: performance.now() })));
      return (t1 - t0) + (end - Math.max(start, t1));
    }
    const times = [];
    let checksum = 0;
    await step('Home');
    while (times.length < steps) {
      const m = window.wingspline.model;
      if (m.stepIndex >= m.frames.length - 1) {
        await step('Home');
        continue;
      }
      times.push(await step('PageDown'));
      checksum += window.wingspline.model.stepIndex;
    }
    return { times, checksum };
  }, STEPS);
}


for (const { label, root } of wants(TASK) ? benchSites('WINGSPLINE_WALK_SITES') : []) {
  const site = await startSite({ root });
  const browser = await launchBrowser();
  try {
    const page = await openPage(browser, `${site.url}mesh.html`);
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.waitForSelector('body[data-ready=true]', { timeout: 20000 });
    const inputs = [{ name: 'lecture', vertex: 1, face: 0 }, ...SPHERES.map(([slices, stacks]) => {
      const ring = Math.floor((stacks - 1) / 2);
      return { name: `sphere_${2 * slices * (stacks - 1)}`, slices, stacks, vertex: 1 + (ring - 1) * slices + slices / 2, face: slices * (stacks - 1) };
    })];
    for (const input of inputs) {
      if (input.slices) await chooseSphere(page, input.slices, input.stacks, { timeout: 240000 });
      for (const [walk, element] of [['vertex', input.vertex], ['face', input.face]]) {
        const { times, checksum } = await walkSteps(page, walk, element);
        report({ task: TASK, build: 'browser', input: input.name, walk, ...(label ? { site: label } : {}), n: 1, seconds: times, checksum, unit: 'ms', ...msSummary(times) });
      }
    }
    if (page.problems.length) throw new Error(page.problems.join('\n'));
  } finally {
    await browser.close();
    await site.close();
  }
}
