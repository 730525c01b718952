// Booting a page: while the geometry core loads, the page says so in an
// accessible status line; when the wasm file cannot be loaded (missing, not WebAssembly) the
// page says what is wrong and what to check, never Emscripten's raw "Aborted(...)" text.
// The wasm request is answered by playwright's page.route; the service worker is blocked so
// every request reaches the route.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { readyLessons, trap } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();
// Every core module: the landing page loads the curves one, the first lesson its own.
const WASM = '**/wasm/wingspline-*.wasm';
const lessonPage = readyLessons[0].page;

async function openWithWasm(file, answer) {
  const context = await env.newContext({ serviceWorkers: 'block' });
  const page = trap(await context.newPage());
  await page.route(WASM, answer);
  await page.goto(new URL(file, env.site.url).href);
  return page;
}

// What a person reads on the page once it gave up: the lesson's message line, or the
// landing page's core status.
async function failureText(page, file) {
  if (file === 'index.html') {
    await page.waitForSelector('[data-core-status][data-state=error]', { timeout: 15000 });
    return page.textContent('[data-core-status]');
  }
  await page.waitForSelector('body[data-ready=failed]', { timeout: 15000 });
  assert.equal(await page.getAttribute('#message', 'data-code'), 'core-load-failed');
  assert.equal(await page.getAttribute('#message', 'role'), 'alert');
  return page.textContent('#message .message-text');
}

const faults = [
  {
    name: 'a missing wasm file (404)',
    answer: (route) => route.fulfill({ status: 404, contentType: 'text/plain', body: 'not found' }),
    reason: /the server answered 404/,
  },
  {
    name: 'a corrupt wasm file',
    answer: (route) => route.fulfill({ status: 200, contentType: 'application/wasm', body: Buffer.from('<html>this is not WebAssembly</html>') }),
    reason: /not valid WebAssembly/,
  },
];

for (const file of ['index.html', lessonPage]) {
  for (const fault of faults) {
    test(`${file} with ${fault.name} says what is wrong and what to check`, async () => {
      const page = await openWithWasm(file, fault.answer);
      const text = await failureText(page, file);
      assert.match(text, /The geometry core \(wasm\/wingspline-(mesh|curves)\.wasm\) could not be loaded/);
      assert.match(text, fault.reason);
      assert.match(text, /Check that the file is served, with type application\/wasm, and reload/);
      const everything = await page.evaluate(() => document.body.innerText);
      assert.doesNotMatch(everything, /Aborted\(/);
      // Nothing still claims to be loading.
      assert.equal(await page.getByText('Loading the geometry core').count(), 0);
      assert.deepEqual(page.problems.filter((p) => /Aborted\(/.test(p)), [], 'no Emscripten abort in the console');
    });
  }
}

for (const file of [lessonPage, 'index.html']) {
  test(`${file} shows that the core is loading, then removes the notice`, async () => {
    let release;
    const held = new Promise((resolve) => { release = resolve; });
    let requested;
    const asked = new Promise((resolve) => { requested = resolve; });
    const page = await openWithWasm(file, async (route) => {
      requested();
      await held;
      await route.continue();
    });
    try {
      await asked;
      const status = page.getByRole('status').filter({ hasText: 'Loading the geometry core…' });
      await status.waitFor({ state: 'visible', timeout: 5000 });
      assert.equal(await status.count(), 1);
      assert.equal(await status.getAttribute('aria-live'), 'polite');
      release();
      if (file === 'index.html') await page.waitForSelector('[data-core-status][data-state=ready]', { timeout: 15000 });
      else await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
      assert.equal(await page.getByText('Loading the geometry core').count(), 0, 'the loading notice is gone');
      assert.deepEqual(page.problems, []);
    } finally {
      release();
    }
  });
}
