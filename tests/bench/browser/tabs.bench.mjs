// ui_tab_switch (docs/benchmarks.md): ms to show each table tab of the mesh lesson with
// sphere_100000 loaded (docs/benchmarks.md: 250 slices x 201 stacks), in headless Chromium. A switch
// is the tab button's click (state change, recompute) plus the page's render callback that
// updates the panels and redraws the canvas, and the style and layout that leaves (forced
// and timed; the browser's paint is not included), bracketed by animation frames (a callback queued before the click and one after). `panels_ms` is the part
// spent in the lesson's update hook (the tabs themselves, without the canvas drawing).
// Each repetition first moves vertex 0 a little, so the mesh has a new version and every
// per-version cache is cold: "cold" is the first show of each tab on that version, "warm"
// the second. One row per tab and phase, and the largest over the tabs per repetition; the
// same on the lecture mesh for comparison.
// Never run by npm test.
//   WINGSPLINE_TAB_SITES=before=/tmp/dist-old,after=dist node tests/bench/browser/tabs.bench.mjs
// measures several built sites in one run (default: this worktree's dist/).
import { wants, report } from '../wasm/harness.mjs';
import { benchSites } from './sites.mjs';
import { startSite, launchBrowser, openPage } from '../../helpers/browser.mjs';
import { chooseSphere } from '../../helpers/mesh-page.mjs';

const TASK = 'ui_tab_switch';
const REPETITIONS = 5;
// slices x stacks: docs/benchmarks.md's sphere_100000 and sphere_1000000
// (WINGSPLINE_TAB_SPHERES=250x201 for the smaller alone). On the million faces the page may
// update the panels in a frame after the one timed here: panels_ms is the lesson's update
// hook wherever it ran.
const SPHERES = (process.env.WINGSPLINE_TAB_SPHERES ?? '250x201,1000x501').split(',').map((s) => s.split('x').map(Number));

// sphere: [slices, stacks] of a sphere; otherwise (null) the lecture mesh the page opens with
// (the yardstick: a switch on any mesh costs what it costs there).
async function measure(root, sphere) {
  const site = await startSite({ root });
  const browser = await launchBrowser();
  try {
    const page = await openPage(browser, `${site.url}mesh.html`);
    await page.waitForSelector('body[data-ready=true]', { timeout: 20000 });
    if (sphere) await chooseSphere(page, sphere[0], sphere[1], { timeout: 240000 });
    const result = await page.evaluate(async (repetitions) => {
      const w = window.wingspline;
      const hooks = w.hooks;
      const update = hooks.update;
      let panelsMs = 0;
      hooks.update = (...args) => {
        const t0 = performance.now();
        const out = update(...args);
        panelsMs += performance.now() - t0;
        return out;
      };
      const frame = () => new Promise((resolve) => requestAnimationFrame(() => resolve(performance.now())));
      // One switch: the click handler, then the page's render callback (rAF callbacks run
      // in the order they were queued, so `before` and `after` bracket the page's own).
      async function show(tab) {
        let before = 0;
        requestAnimationFrame(() => { before = performance.now(); });
        panelsMs = 0;
        const t0 = performance.now();
        document.getElementById(`tab-${tab}`).click();
        const inHandler = performance.now() - t0;
        // The style and layout the switch left to the browser are forced and timed too, so
        // moving work from the script into the browser's layout cannot hide it.
        const after = await new Promise((resolve) => requestAnimationFrame(() => { void document.body.offsetHeight; resolve(performance.now()); }));
        await frame(); // let the browser paint before the next switch
        return { total: inHandler + (after - before), panels: panelsMs };
      }
      const tabs = [...document.querySelectorAll('[role=tab][data-tab]')].map((b) => b.dataset.tab);
      const times = { cold: {}, warm: {} };
      for (const tab of tabs) { times.cold[tab] = []; times.warm[tab] = []; }
      let checksum = 0;
      const p0 = Array.from(w.model.positions.subarray(0, 3));
      for (let r = 0; r < repetitions; r += 1) {
        // A new mesh version: every per-version cache of the lesson is cold.
        const s = w.state;
        w.ctx.commit({ ...s, tab: 'winged', moved: [{ v: 0, p: [p0[0], p0[1], p0[2] + 1e-3 * (r + 1)] }] }, { history: false });
        await frame();
        await frame();
        for (const phase of ['cold', 'warm']) {
          for (const tab of tabs) {
            const t = await show(tab);
            times[phase][tab].push(t);
            checksum += document.querySelectorAll(`#tabpanel-${tab} tr`).length;
          }
          await show('winged');
        }
      }
      hooks.update = update;
      return { tabs, times, checksum };
    }, REPETITIONS);
    if (page.problems.length) throw new Error(page.problems.join('\n'));
    return result;
  } finally {
    await browser.close();
    await site.close();
  }
}

if (wants(TASK)) {
  for (const [sphere, { label, root }] of [...SPHERES, null].flatMap((x) => benchSites('WINGSPLINE_TAB_SITES').map((site) => [x, site]))) {
    const { tabs, times, checksum } = await measure(root, sphere);
    const input = sphere ? `sphere_${2 * sphere[0] * (sphere[1] - 1)}` : 'lecture';
    const site = label ? { site: label } : {};
    for (const phase of ['cold', 'warm']) {
      for (const tab of tabs) {
        const t = times[phase][tab];
        const panels = t.map((x) => x.panels).sort((a, b) => a - b);
        report({ task: TASK, build: 'browser', input: `${input} ${tab} ${phase}${label ? ` (${label})` : ''}`, n: 1, seconds: t.map((x) => x.total), checksum, unit: 'ms',
          tab, phase, panels_ms_median: panels[Math.floor(panels.length / 2)], ...site });
      }
      const largest = times[phase][tabs[0]].map((_, r) => Math.max(...tabs.map((tab) => times[phase][tab][r].total)));
      report({ task: TASK, build: 'browser', input: `${input} largest ${phase}${label ? ` (${label})` : ''}`, n: 1, seconds: largest, checksum, unit: 'ms', tab: 'largest', phase, ...site });
    }
  }
}
