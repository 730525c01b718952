// ui_hover and ui_pick (docs/benchmarks.md): a pointer move over sphere_1000000 with the hover
// highlight drawn, in the 2D and the 3D view (median and p95 of 200 moves), and a click that
// picks the element under the pointer (median of 50), in ms, headless Chromium. Each is the
// pointer events' handlers (a move: pointermove; a click: pointerdown and pointerup at one
// place) plus the animation frame that follows, timed as ui_walk_step times a step (from the
// frame's start, so the wait for the frame is not counted). The points: a fixed pseudo-random
// sequence over the middle half of the canvas, where the sphere is; the first move at a view
// also builds the core's pick grid for it (reported apart as first_ms). Never run by npm test.
//   WINGSPLINE_HOVER_SITES=before=/tmp/dist-old,after=dist node tests/bench/browser/hover.bench.mjs
// measures several built sites in one run (default: this worktree's dist/).
import { wants, report } from '../wasm/harness.mjs';
import { benchSites, msSummary } from './sites.mjs';
import { startSite, launchBrowser, openPage } from '../../helpers/browser.mjs';
import { chooseSphere } from '../../helpers/mesh-page.mjs';

const MOVES = 200;
const CLICKS = 50;
const [SLICES, STACKS] = (process.env.WINGSPLINE_HOVER_SPHERE ?? '1000x501').split('x').map(Number);


// The pointer events at canvas points, timed in the page: {first, times, checksum}.
function pointerTimes(page, { count, click }) {
  return page.evaluate(async ([n, isClick]) => {
    const canvas = document.querySelector('#stage');
    const box = canvas.getBoundingClientRect();
    let seed = 12345;
    const random = () => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648; };
    const send = (type, x, y) => canvas.dispatchEvent(new PointerEvent(type, { clientX: x, clientY: y, pointerId: 1, pointerType: 'mouse', isPrimary: true, button: 0, buttons: type === 'pointerup' ? 0 : (type === 'pointerdown' ? 1 : 0), bubbles: true, cancelable: true }));
    const times = [];
    let checksum = 0;
    for (let i = 0; i <= n; i += 1) {
      const x = box.left + box.width * (0.25 + 0.5 * random());
      const y = box.top + box.height * (0.25 + 0.5 * random());
      const t0 = performance.now();
      if (isClick) { send('pointerdown', x, y); send('pointerup', x, y); } else send('pointermove', x, y);
      const t1 = performance.now();
      const { start, end } = await new Promise((resolve) => requestAnimationFrame((ts) => resolve({ start: ts, end: performance.now() })));
      times.push((t1 - t0) + (end - Math.max(start, t1)));
      const s = window.wingspline.view.selection;
      const element = isClick ? s.pick : s.hover;
      checksum += element ? element.index + 1 : 0;
    }
    return { first: times[0], times: times.slice(1), checksum };
  }, [count, click]);
}

if (wants('ui_hover') || wants('ui_pick')) {
  for (const { label, root } of benchSites('WINGSPLINE_HOVER_SITES')) {
    const site = await startSite({ root });
    const browser = await launchBrowser();
    try {
      const page = await openPage(browser, `${site.url}mesh.html`);
      await page.setViewportSize({ width: 1280, height: 800 });
      await page.waitForSelector('body[data-ready=true]', { timeout: 20000 });
      await chooseSphere(page, SLICES, STACKS, { timeout: 240000 });
      const input = `sphere_${2 * SLICES * (STACKS - 1)}`;
      for (const mode3d of [false, true]) {
        await page.evaluate((m) => window.wingspline.ctx.commit({ ...window.wingspline.ctx.state, mode3d: m }), mode3d);
        await page.waitForFunction((m) => window.wingspline.model.mode3d === m, mode3d, { timeout: 120000 });
        await page.waitForTimeout(1000);
        const view = mode3d ? '3d' : '2d';
        if (wants('ui_hover')) {
          const { first, times, checksum } = await pointerTimes(page, { count: MOVES, click: false });
          report({ task: 'ui_hover', build: 'browser', input, view, ...(label ? { site: label } : {}), n: 1, seconds: times, checksum, unit: 'ms', first_ms: first, ...msSummary(times) });
        }
        if (wants('ui_pick')) {
          const { first, times, checksum } = await pointerTimes(page, { count: CLICKS, click: true });
          report({ task: 'ui_pick', build: 'browser', input, view, ...(label ? { site: label } : {}), n: 1, seconds: times, checksum, unit: 'ms', first_ms: first, ...msSummary(times) });
        }
      }
      if (page.problems.length) throw new Error(page.problems.join('\n'));
    } finally {
      await browser.close();
      await site.close();
    }
  }
}
