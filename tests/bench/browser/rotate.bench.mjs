// ui_rotate (docs/benchmarks.md): ms per pointer move rotating sphere_100000 and
// sphere_1000000 in the mesh lesson's 3D view by pointer drag, 200 moves; median and p95.
// A move is the pointer event's handlers (state change, recompute) plus the page's render
// callback, plus the time until the picture is really drawn: one pixel read back from each
// canvas of the stage forces the 2D rasteriser and the GPU (SwiftShader here) to finish, so
// work the browser defers past the callback is counted too. Never run by npm test.
//
// WINGSPLINE_SITE_ROOT=<dist folder> measures another build (the "before" figures).
import path from 'node:path';
import { wants, report } from '../wasm/harness.mjs';
import { startSite, launchBrowser, openPage } from '../../helpers/browser.mjs';

const TASK = 'ui_rotate';
const MOVES = 200;
const SPHERES = [
  { slices: 250, stacks: 201 },   // sphere_100000
  { slices: 1000, stacks: 501 },  // sphere_1000000
];

async function rotateSphere(browser, site, { slices, stacks }) {
  const page = await openPage(browser, `${site.url}mesh.html`);
  try {
    await page.waitForSelector('body[data-ready=true]', { timeout: 30000 });
    const faces = 2 * slices * (stacks - 1);
    // The sphere by the lesson's own state (a share link), so a generator limit of the page
    // under test does not change the input.
    const ok = await page.evaluate(async ({ s, t }) => {
      const w = window.wingspline.ctx;
      return w.commit({ ...w.state, meshKind: 'sphere', sphere: { slices: s, stacks: t }, mode3d: true, walk: 'vertex', vertex: 0, step: 0 });
    }, { s: slices, t: stacks });
    if (!ok) return { refused: true, faces };
    await page.waitForFunction((f) => window.wingspline.model?.F === f, faces, { timeout: 120000 });
    await page.evaluate(() => window.wingspline.ctx.fitView());
    const box = await page.locator('#stage').boundingBox();
    // Start the drag on empty canvas near a corner (3D: dragging empty space rotates).
    const x0 = box.x + 12; const y0 = box.y + 12;
    await page.mouse.move(x0, y0);
    await page.mouse.down();
    const result = await page.evaluate(async ({ moves, x0, y0 }) => {
      const canvas = document.getElementById('stage');
      const finish = () => {
        for (const c of document.querySelectorAll('.stage canvas')) {
          const gl = c.getContext('webgl2');
          if (gl) { gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4)); continue; }
          const g = c.getContext('2d');
          if (g) g.getImageData(0, 0, 1, 1);
        }
      };
      const times = [];
      for (let i = 1; i <= moves; i += 1) {
        let before = 0;
        requestAnimationFrame(() => { before = performance.now(); });
        await new Promise((resolve) => setTimeout(resolve, 0));
        const t0 = performance.now();
        const event = new PointerEvent('pointermove', { clientX: x0 + 3 * i, clientY: y0 + (i % 40), pointerId: 1, pointerType: 'mouse', buttons: 1, bubbles: true });
        canvas.dispatchEvent(event);
        const inHandler = performance.now() - t0;
        const after = await new Promise((resolve) => requestAnimationFrame(() => { finish(); resolve(performance.now()); }));
        times.push(inHandler + (after - Math.max(before, t0 + inHandler)));
      }
      const rotation = window.wingspline.state.rotation;
      return { times, checksum: rotation.yaw + rotation.pitch };
    }, { moves: MOVES, x0, y0 });
    await page.mouse.up();
    if (page.problems.length) throw new Error(page.problems.join('\n'));
    return { faces, ...result };
  } finally {
    await page.close();
  }
}

if (wants(TASK)) {
  const root = process.env.WINGSPLINE_SITE_ROOT ? path.resolve(process.env.WINGSPLINE_SITE_ROOT) : undefined;
  const site = await startSite(root ? { root } : {});
  const browser = await launchBrowser();
  try {
    for (const sphere of SPHERES) {
      const r = await rotateSphere(browser, site, sphere);
      if (r.refused) {
        process.stdout.write(JSON.stringify({ task: TASK, build: 'browser', input: `sphere_${r.faces}`, refused: 'the page does not accept this sphere' }) + '\n');
        continue;
      }
      const sorted = [...r.times].sort((a, b) => a - b);
      report({
        task: TASK, build: 'browser', unit: 'ms', input: `sphere_${r.faces}`, n: 1, seconds: sorted, checksum: r.checksum,
        median_ms: sorted[Math.floor(sorted.length / 2)], p95_ms: sorted[Math.floor(sorted.length * 0.95)], moves: sorted.length,
        site: root ? path.basename(path.dirname(root)) : 'this build',
      });
    }
  } finally {
    await browser.close();
    await site.close();
  }
}
