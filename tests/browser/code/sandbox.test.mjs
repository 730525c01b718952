// The code sandbox in Chromium, on a lesson page of the built site (mesh.html) with the
// lesson pages' CSP both as the page's meta tag and, on every response, as a header (so the
// module worker, whose policy comes from its own response, runs under the same one): a
// correct walk through the worker, an infinite loop stopped by the budget with the loop's
// line while the page keeps drawing frames, a worker that never loads its engine ended when
// the load time is up and replaced on the next run, and no CSP violation anywhere.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import crypto from 'node:crypto';
import path from 'node:path';
import { useSiteAndBrowser, repoRoot } from '../../helpers/browser.mjs';
import { createStaticServer, listen } from '../../../scripts/lib/static-server.mjs';
import { lectureWinged, CCW_WALK } from '../../helpers/lecture-code.mjs';

const template = fs.readFileSync(path.join(repoRoot, 'web', 'templates', 'lesson.html'), 'utf8');
const LESSON_CSP = template.match(/<meta http-equiv="Content-Security-Policy" content="([^"]+)">/)[1];

async function startSiteWithCspHeader() {
  const dist = createStaticServer(path.join(repoRoot, 'dist'));
  const handler = dist.listeners('request')[0];
  dist.removeAllListeners('request');
  dist.on('request', (req, res) => {
    res.setHeader('content-security-policy', LESSON_CSP);
    handler(req, res);
  });
  const { server, url } = await listen(dist);
  return { url, close: () => new Promise((resolve) => { server.closeAllConnections?.(); server.close(resolve); }) };
}

const env = useSiteAndBrowser(startSiteWithCspHeader);

// Lecture 000's winged-edge tables as plain arrays for the page: the CCW walk around v2 is
// e6 e5 e3 e2 = [5, 4, 2, 1] (worked out in tests/lessons/code-sandbox.test.mjs).
const winged = lectureWinged();
const LECTURE = { positions: Array.from(winged.positions), vertexEdge: Array.from(winged.vertexEdge),
  edges: Array.from(winged.edges), faceEdge: Array.from(winged.faceEdge) };
const LOOP = 'function edgesAroundVertex(mesh, v) {\n  let i = 0;\n  while (true) {\n    i++;\n  }\n}';

test('the sandbox runs a walk in its worker, stops an infinite loop at its line while the page stays responsive, and recovers', async () => {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (err) => problems.push(`pageerror: ${err.message}`));
  page.on('console', (msg) => { if (msg.type() === 'error') problems.push(`console: ${msg.text()}`); });
  await page.addInitScript(() => {
    window.__cspViolations = [];
    document.addEventListener('securitypolicyviolation', (e) => window.__cspViolations.push(`${e.violatedDirective} ${e.blockedURI}`));
    // Counts the workers the page starts, to see the watchdog's replacement.
    const Original = window.Worker;
    window.__workersStarted = 0;
    window.Worker = class extends Original {
      constructor(...args) { super(...args); window.__workersStarted++; }
    };
  });
  await page.goto(`${env.site.url}mesh.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  assert.match(await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content'), /script-src 'self' 'wasm-unsafe-eval';/);

  const out = await page.evaluate(async ({ LECTURE, CCW_WALK, LOOP }) => {
    const { createSandbox } = await import(new URL('js/code/sandbox.js', location.href).href);
    const mesh = () => ({ winged: {
      positions: new Float64Array(LECTURE.positions), vertexEdge: new Int32Array(LECTURE.vertexEdge),
      edges: new Int32Array(LECTURE.edges), faceEdge: new Int32Array(LECTURE.faceEdge),
      edgeFields: ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'] } });
    const request = (source) => ({ source, entry: 'edgesAroundVertex', cases: [{ args: [1], mesh: mesh() }] });
    const sandbox = createSandbox();
    const walk = await sandbox.run(request(CCW_WALK));

    let frames = 0;
    let ticks = 0;
    let running = true;
    const frame = () => { frames++; if (running) requestAnimationFrame(frame); };
    requestAnimationFrame(frame);
    const interval = setInterval(() => { ticks++; }, 10);
    const started = performance.now();
    const pending = sandbox.run(request(LOOP));
    const busy = await sandbox.run(request(CCW_WALK));
    const loop = await pending;
    const loopMs = performance.now() - started;
    running = false;
    clearInterval(interval);
    const again = await sandbox.run(request(CCW_WALK));
    // The worker's host stack must outlast QuickJS's own stack limit: a clean error, not a crash.
    const deep = await sandbox.run(request('function edgesAroundVertex(mesh, v) {\n  return 1 + edgesAroundVertex(mesh, v + 1);\n}'));
    sandbox.dispose();

    // A worker that never answers (a module with no message handler): the watchdog ends it
    // after budgetMs + 1.5 s and the next run starts another.
    // A worker that never says its engine is loaded (the runner module alone: it answers
    // nothing): the run ends when the load time is up, and the next run starts a fresh worker.
    const silent = createSandbox({ url: new URL('js/code/runner.js', location.href), loadMs: 1500 });
    const before = window.__workersStarted;
    const t0 = performance.now();
    const hung = await silent.run({ ...request(CCW_WALK), budgetMs: 200 });
    const hungMs = performance.now() - t0;
    const hungAgain = await silent.run({ ...request(CCW_WALK), budgetMs: 200 });
    const startedForSilent = window.__workersStarted - before;
    silent.dispose();
    return { walk: walk.results?.[0] ?? walk, loop: loop.results?.[0] ?? loop, busy, again: again.results?.[0] ?? again,
      deep: deep.results?.[0] ?? deep, loopMs, frames, ticks, hung, hungMs, hungAgain, startedForSilent, violations: window.__cspViolations };
  }, { LECTURE, CCW_WALK, LOOP });

  assert.equal(out.walk.ok, true, JSON.stringify(out.walk));
  assert.deepEqual(out.walk.value, [5, 4, 2, 1]);
  assert.equal(out.walk.reads, 9);
  assert.equal(out.walk.trace.count, 9);
  assert.equal(out.busy.error.kind, 'busy', 'a second run while one is going is refused at once');

  assert.equal(out.loop.ok, false, JSON.stringify(out.loop));
  assert.equal(out.loop.error.kind, 'timeout');
  assert.equal(out.loop.error.line, 3, 'the while loop\'s line');
  assert.ok(out.loopMs < 2500, `the loop was stopped after ${Math.round(out.loopMs)} ms`);
  // At 60 frames a second, 1.5 s is about 90 frames and 150 ticks; a blocked page has none.
  assert.ok(out.frames >= 20, `the page drew ${out.frames} frames during the run`);
  assert.ok(out.ticks >= 40, `the page's timer fired ${out.ticks} times during the run`);

  assert.equal(out.again.ok, true, JSON.stringify(out.again));
  assert.deepEqual(out.again.value, [5, 4, 2, 1]);

  assert.deepEqual([out.deep.ok, out.deep.error?.kind, out.deep.error?.line, out.deep.engineFailed], [false, 'runtime', 2, undefined], JSON.stringify(out.deep.error));
  assert.match(out.deep.error.message, /too much recursion/);

  assert.equal(out.hung.error.kind, 'engine');
  assert.match(out.hung.error.message, /^the sandbox's engine did not load within 1\.5 s/);
  assert.ok(out.hungMs >= 1400 && out.hungMs < 4000, `the wait ended after ${Math.round(out.hungMs)} ms`);
  assert.equal(out.hungAgain.error.kind, 'engine');
  assert.equal(out.startedForSilent, 2, 'the run after the watchdog started a fresh worker');

  assert.deepEqual(out.violations, []);
  assert.deepEqual(problems, []);
});

test('the service worker precaches the sandbox\'s worker bundle and QuickJS\'s wasm, byte for byte', () => {
  const text = fs.readFileSync(path.join(repoRoot, 'dist', 'sw-manifest.js'), 'utf8');
  const manifest = JSON.parse(text.slice(text.indexOf('{'), text.lastIndexOf('}') + 1));
  for (const file of ['js/code/sandbox-worker.js', 'js/code/sandbox.js', 'wasm/quickjs.wasm']) {
    const bytes = fs.readFileSync(path.join(repoRoot, 'dist', file));
    assert.equal(manifest.files[file], crypto.createHash('sha256').update(bytes).digest('hex'), file);
  }
  // The wasm is the npm package's, unchanged.
  const shipped = fs.readFileSync(path.join(repoRoot, 'node_modules', '@jitl', 'quickjs-wasmfile-release-sync', 'dist', 'emscripten-module.wasm'));
  assert.ok(fs.readFileSync(path.join(repoRoot, 'dist', 'wasm', 'quickjs.wasm')).equals(shipped));
  // The bundle is self-contained: no bare import left, no code built from text.
  const bundle = fs.readFileSync(path.join(repoRoot, 'dist', 'js', 'code', 'sandbox-worker.js'), 'utf8');
  assert.doesNotMatch(bundle, /\bimport\s*\(?\s*["'][^./]|\bfrom\s*["'][^./]/);
  assert.doesNotMatch(bundle, /\beval\s*\(|new\s+Function\s*\(/);
});
