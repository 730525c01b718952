// docs/benchmarks.md `ui_drag`: recompute + redraw per pointer move while dragging a control point on
// the curve lesson (1,000 samples per curve, blending plot and matrix panel visible), in
// headless Chromium, with real mouse events. Timed inside the page (see below), so the
// figure is the page's own work, not the DevTools protocol's round trip.
// Prints one JSON line: median and p95 in ms per move. Never asserted anywhere.
import { startSite, launchBrowser, openPage } from '../../helpers/browser.mjs';
import { wants, report } from '../wasm/harness.mjs';

const MOVES = 300;
const WARMUP = 30;

if (wants('ui_drag')) {
  const site = await startSite();
  const browser = await launchBrowser();
  try {
    const page = await openPage(browser, `${site.url}curves.html`);
    await page.evaluate(() => localStorage.clear());
    await page.goto(`${site.url}curves.html`);
    await page.waitForSelector('body[data-ready=true]');
    // A Bezier curve of degree 5 (6 points): blending plot, matrix panel, polygon on.
    await page.evaluate(() => {
      const { ctx } = window.wingspline;
      const s = ctx.state;
      ctx.commit({ ...s, points: [[0, 0], [1, 2], [2, 2.5], [3, 2], [4, 1], [5, 0]], weights: [1, 1, 1, 1, 1, 1], tangents: Array(6).fill([1, 0]) });
      ctx.fitView(); // all six points on screen
    });
    const samples = await page.evaluate(() => window.wingspline.model.samples.length / 2);
    const p = (await page.evaluate(() => window.wingspline.handles())).find((x) => x.id === 'p2');
    // Instrument: the pointermove handler (the core recomputes inside it) from a window
    // capture listener (first) to a window bubble listener (last), plus the panel update
    // and the drawing of the frame that follows (lesson.update, lesson.draw and
    // lesson.afterFrame (the side plots), wrapped; the shell reads hooks when it calls them).
    // The idle wait for the next frame is not work and is not counted.
    await page.evaluate(() => {
      const lesson = window.wingspline.hooks;
      const times = [];
      const phases = [];
      window.__dragTimes = times;
      window.__dragPhases = phases;
      let t0 = 0;
      let pending = null;
      window.addEventListener('pointermove', () => { t0 = performance.now(); }, true);
      window.addEventListener('pointermove', () => { pending = performance.now() - t0; }, false);
      const update = lesson.update;
      const draw = lesson.draw;
      const afterFrame = lesson.afterFrame;
      let updateTime = 0;
      let drawStart = 0;
      lesson.update = (...args) => { const a = performance.now(); update(...args); updateTime = performance.now() - a; };
      lesson.draw = (...args) => { drawStart = performance.now(); draw(...args); };
      // The shell calls afterFrame after draw on every canvas frame: the frame ends here.
      lesson.afterFrame = (...args) => {
        afterFrame?.(...args);
        const drawTime = performance.now() - drawStart;
        if (pending !== null) {
          times.push(pending + updateTime + drawTime);
          phases.push([pending, updateTime, drawTime]);
        }
        pending = null;
        updateTime = 0;
      };
    });
    await page.mouse.move(p.x, p.y);
    await page.mouse.down();
    for (let k = 0; k < MOVES + WARMUP; k += 1) {
      const a = (2 * Math.PI * k) / 60;
      await page.mouse.move(p.x + 80 * Math.cos(a), p.y + 60 * Math.sin(a));
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0))));
    }
    await page.mouse.up();
    const times = (await page.evaluate(() => window.__dragTimes)).slice(WARMUP);
    // The three parts (profile): the pointermove handler (the core's recompute inside
    // commit), the panel update, the drawing; medians each.
    const phases = (await page.evaluate(() => window.__dragPhases)).slice(WARMUP);
    const medianOf = (k) => { const v = phases.map((x) => x[k]).sort((a, b) => a - b); return v[Math.floor(v.length / 2)]; };
    const sorted = [...times].sort((a, b) => a - b);
    const median = sorted[Math.floor(sorted.length / 2)];
    const p95 = sorted[Math.min(sorted.length - 1, Math.floor(sorted.length * 0.95))];
    const state = await page.evaluate(() => window.wingspline.state);
    report({
      task: 'ui_drag', build: 'browser', unit: 'ms', input: `bezier degree 5, ${samples} samples, blending plot + matrix panel`,
      n: 1, seconds: sorted, checksum: state.points[2][0] + state.points[2][1],
      median_ms: median, p95_ms: p95, moves: times.length,
      move_median_ms: medianOf(0), update_median_ms: medianOf(1), draw_median_ms: medianOf(2),
    });
  } finally {
    await browser.close();
    await site.close();
  }
}
