// Shared set-up for the browser tests: dist/ served on a free port, Debian's Chromium
// through playwright-core, console errors collected, screenshots under test-results/.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { before, after, afterEach } from 'node:test';
import { chromium } from 'playwright-core';
import { createStaticServer, listen } from '../../scripts/lib/static-server.mjs';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const resultsDir = path.join(repoRoot, 'test-results');

export const chromiumArgs = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

// One site and one browser for the whole browser layer: scripts/lib/test-layers.mjs serves
// dist/ once and starts one Chromium (a playwright browser server) before the files run,
// and hands both to every file through these variables. A file run on its own (node --test
// file) starts its own, as before. A file that needs a site of its own (another root, a
// prefix, overlays) always starts one.
const SHARED_SITE = process.env.WINGSPLINE_TEST_SITE ?? '';
const SHARED_BROWSER = process.env.WINGSPLINE_TEST_BROWSER ?? '';

// Options as createStaticServer: { root (default dist/), prefix, overlays }.
export async function startSite({ root = path.join(repoRoot, 'dist'), ...options } = {}) {
  if (SHARED_SITE && root === path.join(repoRoot, 'dist') && Object.keys(options).length === 0) {
    return { url: SHARED_SITE, origin: SHARED_SITE, close: async () => {} };
  }
  const { server, url } = await listen(createStaticServer(root, options));
  const base = new URL((options.prefix ?? '/').slice(1), url).href;
  return {
    url: base,
    origin: url,
    close: () => new Promise((resolve) => { server.closeAllConnections?.(); server.close(resolve); }),
  };
}

// Connected to the layer's browser when there is one (closing it then only disconnects:
// the contexts this file opened go with it), else a browser of its own.
export async function launchBrowser() {
  if (SHARED_BROWSER) return chromium.connect(SHARED_BROWSER);
  return chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
}

// The layer's site and browser (scripts/lib/test-layers.mjs): {env, close}.
export async function startSharedSiteAndBrowser() {
  const site = await startSite();
  const server = await chromium.launchServer({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
  return {
    env: { WINGSPLINE_TEST_SITE: site.url, WINGSPLINE_TEST_BROWSER: server.wsEndpoint() },
    async close() {
      await server.close();
      await site.close();
    },
  };
}

// A new page whose console errors and page errors are collected into `page.problems`.
// A page in a new context that the caller closes (the benchmarks, which close their
// browser); tests use the closing env.openPage below.
export async function openPage(browser, url, contextOptions = {}) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, ...contextOptions });
  return collectProblemsAndGo(await context.newPage(), url);
}

async function collectProblemsAndGo(page, url) {
  page.problems = [];
  page.on('console', (msg) => { if (msg.type() === 'error') page.problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (err) => page.problems.push(`pageerror: ${err.message}`));
  await page.goto(url);
  return page;
}

// The bytes of a playwright download, read through its stream (download.path() is not
// available when the browser is the layer's shared one, reached over a connection).
export async function downloadedBytes(download) {
  const chunks = [];
  for await (const chunk of await download.createReadStream()) chunks.push(chunk);
  return Buffer.concat(chunks);
}

export async function waitReady(page) {
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
}

// A lesson page in `context`, ready, its dialogs and errors trapped.
export async function openLesson(context, url) {
  const page = await context.newPage();
  trap(page);
  await page.goto(url);
  await waitReady(page);
  return page;
}

// Dialogs (alert/confirm/prompt) are recorded and dismissed; page errors and console errors
// collected into page.problems.
export function trap(page) {
  page.dialogs = [];
  page.problems = page.problems ?? [];
  page.on('dialog', (dialog) => { page.dialogs.push(dialog.message()); dialog.dismiss().catch(() => {}); });
  page.on('pageerror', (err) => page.problems.push(`pageerror: ${err.message}`));
  page.on('console', (msg) => { if (msg.type() === 'error') page.problems.push(`console: ${msg.text()}`); });
  return page;
}

export async function screenshot(page, name) {
  fs.mkdirSync(resultsDir, { recursive: true });
  const file = path.join(resultsDir, `${name}.png`);
  await page.screenshot({ path: file, fullPage: true });
  return file;
}

// Pages that always close. Every browser context opened through `tracker.newContext` is
// closed after the test that opened it, whether the test passed or failed (node:test's
// afterEach runs for every test of the file, nested ones too), so a failing assertion never
// leaks a context into the next test. No test closes its own context; a test closes a page
// or a context itself only when closing is part of what it checks (a tab closed, then the
// link opened in another).
export function closingContexts(getBrowser) {
  const open = new Set();
  afterEach(async () => {
    const contexts = [...open];
    open.clear();
    await Promise.all(contexts.map((context) => context.close()));
  });
  const tracker = {
    // A fresh context (playwright's options) without the service worker unless the options
    // say `serviceWorkers: 'allow'`: the worker's install fetches and hashes the whole site
    // (about 270 files) in every fresh context, beside the page under test; only the tests of
    // the offline copy need it.
    async newContext(options = {}) {
      const context = await getBrowser().newContext({ serviceWorkers: 'block', ...options });
      open.add(context);
      context.on('close', () => open.delete(context));
      return context;
    },
    // A page in a fresh 1280 x 800 context, console and page errors collected into
    // `page.problems`, opened at url.
    async openPage(url, contextOptions = {}) {
      const context = await tracker.newContext({ viewport: { width: 1280, height: 800 }, ...contextOptions });
      return collectProblemsAndGo(await context.newPage(), url);
    },
    // A lesson page in a fresh 1280 x 800 context, ready (body[data-ready]), dialogs and
    // errors trapped (as openLesson).
    async openLesson(url, contextOptions = {}) {
      const context = await tracker.newContext({ viewport: { width: 1280, height: 800 }, ...contextOptions });
      return openLesson(context, url);
    },
  };
  return tracker;
}

// One site and one browser for a whole test file, opened before its first test and closed
// after its last: `const env = useSiteAndBrowser();` then `env.site.url`, `env.browser`, and
// the closing pages of closingContexts: `env.openPage(url)`, `env.openLesson(url)`,
// `env.newContext(options)`. `start` serves the site (default: dist/ as startSite does).
export function useSiteAndBrowser(start = startSite) {
  const env = { site: null, browser: null };
  before(async () => {
    env.site = await start();
    env.browser = await launchBrowser();
  });
  after(async () => {
    await env.browser?.close();
    await env.site?.close();
  });
  return Object.assign(env, closingContexts(() => env.browser));
}
