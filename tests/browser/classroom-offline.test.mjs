// Offline and hosting (issue 8): after the first visit dist/ works offline (the service
// worker precaches every file, the wasm included), from any sub-path of a static host, and
// a new build (the manifest's hash changes) replaces the cache.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchBrowser, startSite, repoRoot } from '../helpers/browser.mjs';
import { distPages, readyLessons, waitReady, trap } from '../helpers/classroom.mjs';
import { writeServiceWorkerManifest } from '../../scripts/lib/site-manifest.mjs';

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); });

// The page is controlled by the service worker once it has installed and claimed it.
async function waitControlled(page) {
  await page.evaluate(async () => {
    await navigator.serviceWorker.ready;
    if (!navigator.serviceWorker.controller) {
      await new Promise((resolve) => navigator.serviceWorker.addEventListener('controllerchange', resolve, { once: true }));
    }
  });
}

// A page works when its core answered: the landing page shows the version, a lesson is ready.
async function pageWorks(page, file) {
  if (file === 'index.html') {
    await page.waitForSelector('[data-core-status][data-state=ready]', { timeout: 15000 });
  } else {
    await waitReady(page);
    assert.ok((await page.evaluate(() => window.wingspline.handles().length)) >= 0);
  }
}

async function offlineRoundTrip(siteUrl, prefixPath) {
  const context = await browser.newContext();
  const page = trap(await context.newPage());
  await page.goto(siteUrl);
  await pageWorks(page, 'index.html');
  await waitControlled(page);
  const scope = await page.evaluate(async () => (await navigator.serviceWorker.ready).scope);
  assert.equal(new URL(scope).pathname, prefixPath, 'the worker covers the site folder');
  await context.setOffline(true);
  for (const file of distPages) {
    await page.goto(new URL(file, siteUrl).href);
    await pageWorks(page, file);
    const wasm = await page.evaluate(() => performance.getEntriesByType('resource').filter((e) => e.name.endsWith('.wasm')).length);
    assert.ok(wasm >= 1, `${file} loaded the wasm offline`);
  }
  await page.reload();
  await pageWorks(page, distPages.at(-1));
  assert.deepEqual(page.problems, []);
  await context.close();
}

test('the site works offline after the first visit', async () => {
  const site = await startSite();
  try {
    await offlineRoundTrip(site.url, '/');
  } finally {
    await site.close();
  }
});

test('the site works from a sub-path of a static host, online and offline', async () => {
  const prefix = '/some/sub/path/';
  const site = await startSite({ prefix });
  try {
    assert.ok(site.url.endsWith(prefix));
    const context = await browser.newContext();
    const page = trap(await context.newPage());
    assert.equal((await fetch(site.origin)).status, 404, 'nothing is served outside the sub-path');
    for (const file of distPages) {
      await page.goto(new URL(file, site.url).href);
      await pageWorks(page, file);
    }
    // Every request stayed inside the sub-path.
    const outsideRequests = await page.evaluate((p) => performance.getEntriesByType('resource')
      .map((e) => new URL(e.name).pathname).filter((x) => !x.startsWith(p)), prefix);
    assert.deepEqual(outsideRequests, []);
    assert.deepEqual(page.problems, []);
    await context.close();
    await offlineRoundTrip(site.url, prefix);
  } finally {
    await site.close();
  }
});

test('a new build replaces the offline cache', async () => {
  // A deployable copy of dist/ in a temporary folder, changed the way a new build changes it.
  const root = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-deploy-'));
  fs.cpSync(path.join(repoRoot, 'dist'), root, { recursive: true });
  const site = await startSite({ root });
  try {
    const context = await browser.newContext();
    const page = trap(await context.newPage());
    await page.goto(site.url);
    await pageWorks(page, 'index.html');
    await waitControlled(page);
    const first = writeServiceWorkerManifest(root).version;
    assert.deepEqual(await page.evaluate(() => caches.keys()), [`wingspline-${first}`]);
    // Deploy: a changed stylesheet, a new manifest hash.
    fs.appendFileSync(path.join(root, 'css', 'site.css'), '\n.deployed-marker { color: inherit; }\n');
    const second = writeServiceWorkerManifest(root).version;
    assert.notEqual(second, first, 'a changed file changes the manifest version');
    const changed = page.evaluate(() => new Promise((resolve) => navigator.serviceWorker.addEventListener('controllerchange', resolve, { once: true })));
    await page.evaluate(async () => { await (await navigator.serviceWorker.getRegistration()).update(); });
    await changed;
    await page.waitForFunction((key) => caches.keys().then((keys) => keys.length === 1 && keys[0] === key), `wingspline-${second}`, { timeout: 15000 });
    // Offline, the new stylesheet is what the cache serves.
    await context.setOffline(true);
    await page.reload();
    await pageWorks(page, 'index.html');
    const css = await page.evaluate(async () => (await fetch('css/site.css')).text());
    assert.match(css, /deployed-marker/);
    assert.deepEqual(page.problems, []);
    await context.close();
  } finally {
    await site.close();
    fs.rmSync(root, { recursive: true, force: true });
  }
});

test('every lesson page is in the offline manifest', () => {
  const text = fs.readFileSync(path.join(repoRoot, 'dist', 'sw-manifest.js'), 'utf8');
  const manifest = JSON.parse(text.slice(text.indexOf('{'), text.lastIndexOf('}') + 1));
  for (const file of ['index.html', 'wasm/wingspline-core.wasm', 'wasm/wingspline-core.js', 'css/site.css', ...readyLessons.map((l) => l.page)]) {
    assert.ok(manifest.files.includes(file), `${file} is precached`);
  }
  assert.match(manifest.version, /^[0-9a-f]{16}$/);
});
