// Shared set-up for the browser tests: dist/ served on a free port, Debian's Chromium
// through playwright-core, console errors collected, screenshots under test-results/.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { before, after } from 'node:test';
import { chromium } from 'playwright-core';
import { createStaticServer, listen } from '../../scripts/lib/static-server.mjs';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const resultsDir = path.join(repoRoot, 'test-results');

export const chromiumArgs = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

// Options as createStaticServer: { root (default dist/), prefix, overlays }.
export async function startSite({ root = path.join(repoRoot, 'dist'), ...options } = {}) {
  const { server, url } = await listen(createStaticServer(root, options));
  const base = new URL((options.prefix ?? '/').slice(1), url).href;
  return {
    url: base,
    origin: url,
    close: () => new Promise((resolve) => { server.closeAllConnections?.(); server.close(resolve); }),
  };
}

export async function launchBrowser() {
  return chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
}

// A new page whose console errors and page errors are collected into `page.problems`.
export async function openPage(browser, url, contextOptions = {}) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, ...contextOptions });
  const page = await context.newPage();
  page.problems = [];
  page.on('console', (msg) => { if (msg.type() === 'error') page.problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (err) => page.problems.push(`pageerror: ${err.message}`));
  await page.goto(url);
  return page;
}

export async function screenshot(page, name) {
  fs.mkdirSync(resultsDir, { recursive: true });
  const file = path.join(resultsDir, `${name}.png`);
  await page.screenshot({ path: file, fullPage: true });
  return file;
}

// One site and one browser for a whole test file, opened before its first test and closed
// after its last: `const env = useSiteAndBrowser();` then `env.site.url`, `env.browser`.
// `start` serves the site (default: dist/ as startSite does).
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
  return env;
}
