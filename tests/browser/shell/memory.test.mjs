// Memory over time in the browser: dragging a control point for 10,000 moves on
// the curve explorer, and 1,000 steps of the winged-edge traversal on a 10,000-face mesh,
// leave the wasm heap, the wasm memory, the DOM and the JavaScript heap where they were.
//
// How: the moves are real pointer events dispatched on the canvas inside the page (10,000
// DevTools round trips would measure the protocol, not the page), each going through the
// lesson's own handler: core recompute, panels, and a drawn frame every FRAME_EVERY moves
// (browsers coalesce pointer moves to frames anyway). The traversal steps go through the
// lesson's commit path like its keyboard keys, with a drawn frame every STEP_FRAME_EVERY.
// Both measure in the same state before and after (the drag's circle closes; the walk is
// brought back to the same vertex and step), so a difference is growth, not content.
// Measures, after a warm-up: api.memoryUsage() (malloc bytes in use, exact; linear memory),
// the number of DOM nodes, and the JS heap after a forced garbage collection.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { openLesson } from '../../helpers/classroom.mjs';

const MOVES = 10000;
const STEPS = 1000;
const WARM_UP = 300;
const FRAME_EVERY = 50;        // drag: a drawn frame every 50 moves
const STEP_FRAME_EVERY = 4;    // traversal: a drawn frame every 4 steps (a fast animation)
const HEAP_SLACK_BYTES = 4096;          // malloc bytes in use: a leak of one block per move shows as >= 160 KB
const LINEAR_SLACK_BYTES = 1 << 20;     // wasm memory pages (64 KB each): at most 16 more
const DOM_SLACK_NODES = 50;             // a panel rebuilt per move without removal would add thousands
const JS_HEAP_SLACK_BYTES = 8 << 20;    // after GC; a retained array per move (>= 1 KB) would add 10 MB

const env = useSiteAndBrowser();

async function measure(page) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('HeapProfiler.collectGarbage');
  const { usedSize } = await cdp.send('Runtime.getHeapUsage');
  await cdp.detach();
  const inPage = await page.evaluate(() => ({
    ...window.wingspline.api.memoryUsage(),
    domNodes: document.getElementsByTagName('*').length,
  }));
  return { ...inPage, jsHeap: usedSize };
}

function assertNoGrowth(before0, after0, what) {
  const text = `${what}: before ${JSON.stringify(before0)}, after ${JSON.stringify(after0)}`;
  assert.ok(Math.abs(after0.heapInUse - before0.heapInUse) <= HEAP_SLACK_BYTES, `wasm bytes in use grew. ${text}`);
  assert.ok(after0.linearBytes - before0.linearBytes <= LINEAR_SLACK_BYTES, `wasm memory grew. ${text}`);
  assert.ok(Math.abs(after0.domNodes - before0.domNodes) <= DOM_SLACK_NODES, `the DOM grew. ${text}`);
  assert.ok(after0.jsHeap - before0.jsHeap <= JS_HEAP_SLACK_BYTES, `the JS heap grew. ${text}`);
}

// Drags handle `id` around a circle of `radius` CSS pixels for `moves` pointer moves.
function drag(page, id, moves, radius = 40) {
  return page.evaluate(async ({ id: handleId, moves: n, radius: r, frameEvery }) => {
    const canvas = document.querySelector('canvas');
    const h = window.wingspline.handles().find((x) => x.id === handleId);
    const at = (x, y, type, buttons) => canvas.dispatchEvent(new PointerEvent(type, {
      clientX: x, clientY: y, buttons, button: 0, pointerId: 1, pointerType: 'mouse', isPrimary: true, bubbles: true, cancelable: true,
    }));
    const frame = () => new Promise((resolve) => requestAnimationFrame(() => resolve()));
    const index = Number(handleId.slice(1));
    const start = window.wingspline.state.points[index];
    let farthest = 0;
    at(h.x, h.y, 'pointerdown', 1);
    for (let k = 1; k <= n; k += 1) {
      const a = (2 * Math.PI * k) / 500;
      at(h.x + r * Math.sin(a), h.y + r * (1 - Math.cos(a)), 'pointermove', 1);
      if (k % frameEvery === 0) await frame();
      if (k % 500 === 250) {
        // Half way round the circle: the point is 2r pixels from where it began.
        const p = window.wingspline.state.points[index];
        farthest = Math.max(farthest, Math.hypot(p[0] - start[0], p[1] - start[1]));
      }
    }
    at(h.x, h.y, 'pointerup', 0);
    await frame();
    return { handle: window.wingspline.handles().find((x) => x.id === handleId), farthest };
  }, { id, moves, radius, frameEvery: FRAME_EVERY });
}

test(`${MOVES} control-point moves on the curve explorer do not grow memory`, async () => {
  const page = await env.openLesson(new URL('curves.html', env.site.url).href);
  await drag(page, 'p1', WARM_UP);
  const before0 = await measure(page);
  const { handle, farthest } = await drag(page, 'p1', MOVES);
  const after0 = await measure(page);
  // The drag really moved the point through the core, and the lesson is still whole.
  const moved = await page.evaluate(() => window.wingspline.state.points[1]);
  assert.ok(Number.isFinite(moved[0]) && Number.isFinite(moved[1]));
  assert.ok(handle && Number.isFinite(handle.x), 'the handle is still there');
  assert.ok(farthest > 0.1, `P1 followed the pointer (farthest ${farthest} from its start)`);
  assertNoGrowth(before0, after0, 'curve drag');
  assert.deepEqual(page.problems, []);
});

test(`${STEPS} traversal steps on a 10,000-face sphere do not grow memory`, async () => {
  const page = await env.openLesson(new URL('mesh.html', env.site.url).href);
  // docs/benchmarks.md sphere_10000: 100 slices x 51 stacks.
  await page.evaluate(() => {
    const { ctx } = window.wingspline;
    ctx.commit({ ...ctx.state, meshKind: 'sphere', sphere: { slices: 100, stacks: 51 }, walk: 'vertex', vertex: 0, step: 0 });
  });
  await page.waitForFunction(() => window.wingspline.model?.frames?.length > 1);
  assert.equal(await page.evaluate(() => window.wingspline.model.counts.faces), 10000);
  const walk = (steps) => page.evaluate(async ({ n, frameEvery }) => {
    const { ctx } = window.wingspline;
    const frame = () => new Promise((resolve) => requestAnimationFrame(() => resolve()));
    for (let k = 1; k <= n; k += 1) {
      const s = ctx.state;
      const frames = window.wingspline.model.frames.length;
      // Step forward; at the end of a walk move on to the next vertex, as a student would.
      const next = s.step + 1 < frames ? { ...s, step: s.step + 1 } : { ...s, vertex: (s.vertex + 37) % 5002, step: 0 };
      ctx.commit(next, { history: false });
      if (k % frameEvery === 0) await frame();
    }
    const reached = window.wingspline.model.stepIndex;
    // The reference state for measuring: v2's walk at its first step.
    ctx.commit({ ...ctx.state, vertex: 1, step: 0 }, { history: false });
    await frame();
    await frame();
    return reached;
  }, { n: steps, frameEvery: STEP_FRAME_EVERY });
  await walk(WARM_UP / 3);
  const before0 = await measure(page);
  const last = await walk(STEPS);
  const after0 = await measure(page);
  assert.ok(Number.isInteger(last));
  assertNoGrowth(before0, after0, 'traversal');
  assert.deepEqual(page.problems, []);
});
