// Offline and hosting: after the first visit dist/ works offline (the service
// worker precaches every file, the wasm included), from any sub-path of a static host, and
// a new build (the manifest's hash changes) replaces the cache.
// Trust: two deployments on one origin keep their own caches; every
// cached file is checked against the SHA-256 in the manifest at install and when served,
// and pages come from the network first.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import crypto from 'node:crypto';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { launchBrowser, startSite, repoRoot, closingContexts } from '../../helpers/browser.mjs';
import { createStaticServer, listen } from '../../../scripts/lib/static-server.mjs';
import { distPages, readyLessons, waitReady, trap } from '../../helpers/classroom.mjs';
import { writeServiceWorkerManifest } from '../../../scripts/lib/site-manifest.mjs';

let browser;
const contexts = closingContexts(() => browser);
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

// The origin's cache names once they equal `expected` (the new worker's activate step deletes
// asynchronously), or as they are after 15 s. (page.waitForFunction does not await a
// promise, so it cannot poll caches.keys().)
function settledCaches(page, expected) {
  return page.evaluate(async (want) => {
    const deadline = Date.now() + 15000;
    let keys = (await caches.keys()).sort();
    while (JSON.stringify(keys) !== want && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 50));
      keys = (await caches.keys()).sort();
    }
    return keys;
  }, JSON.stringify(expected));
}

// A new browser context whose page at `siteUrl` works and is controlled by the worker.
async function openControlled(siteUrl) {
  const context = await contexts.newContext({ serviceWorkers: 'allow' });
  const page = trap(await context.newPage());
  await page.goto(siteUrl);
  await pageWorks(page, 'index.html');
  await waitControlled(page);
  return { context, page };
}

// A page works when its core answered: the landing page shows the version, a lesson is ready.
async function pageWorks(page, file) {
  if (file === 'index.html') {
    await page.waitForSelector('[data-core-status][data-state=ready]', { timeout: 15000 });
  } else {
    await waitReady(page);
    // The lesson the file names is running and its core computed a model.
    const shown = await page.evaluate(() => ({ lesson: window.wingspline.lesson, computed: window.wingspline.model !== null && window.wingspline.model !== undefined }));
    assert.equal(`${shown.lesson}.html`, file.split('/').pop());
    assert.ok(shown.computed, `${file}: the core computed the lesson`);
  }
}

async function offlineRoundTrip(siteUrl, prefixPath) {
  const context = await contexts.newContext({ serviceWorkers: 'allow' });
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
    const context = await contexts.newContext({ serviceWorkers: 'allow' });
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
  await onDeployment(async (site, root) => {
    const { context, page } = await openControlled(site.url);
    const first = writeServiceWorkerManifest(root).version;
    assert.deepEqual(await page.evaluate(() => caches.keys()), [`wingspline:/:${first}`]);
    // Caches of older workers were named by version only: the one holding this
    // scope's start page is this site's and goes with the update, any other stays.
    await page.evaluate(async () => {
      const mine = await caches.open('wingspline-0123456789abcdef');
      await mine.put(new URL('./', location.href), new Response('old build'));
      const theirs = await caches.open('wingspline-fedcba9876543210');
      await theirs.put(new URL('/elsewhere/', location.href), new Response('another site'));
    });
    // Deploy: a changed stylesheet, a new manifest hash.
    fs.appendFileSync(path.join(root, 'css', 'site.css'), '\n.deployed-marker { color: inherit; }\n');
    const second = writeServiceWorkerManifest(root).version;
    assert.notEqual(second, first, 'a changed file changes the manifest version');
    const changed = page.evaluate(() => new Promise((resolve) => navigator.serviceWorker.addEventListener('controllerchange', resolve, { once: true })));
    await page.evaluate(async () => { await (await navigator.serviceWorker.getRegistration()).update(); });
    await changed;
    const expected = [`wingspline-fedcba9876543210`, `wingspline:/:${second}`].sort();
    assert.deepEqual(await settledCaches(page, expected), expected);
    // Offline, the new stylesheet is what the cache serves.
    await context.setOffline(true);
    await page.reload();
    await pageWorks(page, 'index.html');
    const css = await page.evaluate(async () => (await fetch('css/site.css')).text());
    assert.match(css, /deployed-marker/);
    assert.deepEqual(page.problems, []);
  });
});

function readManifest(root) {
  const text = fs.readFileSync(path.join(root, 'sw-manifest.js'), 'utf8');
  return JSON.parse(text.slice(text.indexOf('{'), text.lastIndexOf('}') + 1));
}

test('every lesson page is in the offline manifest, with the SHA-256 of its bytes', () => {
  const dist = path.join(repoRoot, 'dist');
  const manifest = readManifest(dist);
  for (const file of ['index.html', ...['mesh', 'subdivision', 'curves', 'exercises'].flatMap((m) => [`wasm/wingspline-${m}.wasm`, `wasm/wingspline-${m}.js`]), 'js/bundle/mesh.js', 'css/site.css', ...readyLessons.map((l) => l.page)]) {
    assert.ok(Object.hasOwn(manifest.files, file), `${file} is precached`);
  }
  for (const [file, sha256] of Object.entries(manifest.files)) {
    assert.equal(sha256, crypto.createHash('sha256').update(fs.readFileSync(path.join(dist, file))).digest('hex'), file);
  }
  assert.match(manifest.version, /^[0-9a-f]{16}$/);
});

// dist/ copied to a temporary folder, to be changed the way a deployment changes it.
function deployableCopy() {
  const root = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-deploy-'));
  fs.cpSync(path.join(repoRoot, 'dist'), root, { recursive: true });
  return root;
}

// Runs `use(site, root)` against a fresh deployable copy of dist/ served on a free port,
// then stops the server and removes the copy.
async function onDeployment(use) {
  const root = deployableCopy();
  const site = await startSite({ root });
  try {
    await use(site, root);
  } finally {
    await site.close();
    fs.rmSync(root, { recursive: true, force: true });
  }
}

// One server, several deployments: `roots` maps a path prefix ('/course/') to a folder.
async function startDeployments(roots) {
  const handlers = Object.entries(roots).map(([prefix, root]) => [prefix, createStaticServer(root, { prefix }).listeners('request')[0]]);
  const server = http.createServer((req, res) => {
    const hit = handlers.find(([prefix]) => req.url.startsWith(prefix));
    if (hit) hit[1](req, res);
    else res.writeHead(404).end('not found');
  });
  const { url } = await listen(server);
  return { origin: url, close: () => new Promise((resolve) => { server.closeAllConnections?.(); server.close(resolve); }) };
}

test('two deployments on one origin keep each other\'s offline copies', async () => {
  // Two courses on one host, built at different times (so their manifests differ).
  const course = deployableCopy();
  const course2 = deployableCopy();
  fs.appendFileSync(path.join(course2, 'css', 'site.css'), '\n.course2-marker { color: inherit; }\n');
  writeServiceWorkerManifest(course2);
  const site = await startDeployments({ '/course/': course, '/course2/': course2 });
  try {
    const context = await contexts.newContext({ serviceWorkers: 'allow' });
    const page = trap(await context.newPage());
    for (const prefix of ['/course/', '/course2/']) {
      await page.goto(new URL(prefix, site.origin).href);
      await pageWorks(page, 'index.html');
      await waitControlled(page);
    }
    await context.setOffline(true);
    for (const prefix of ['/course/', '/course2/']) {
      for (const file of distPages) {
        await page.goto(new URL(prefix + file, site.origin).href);
        await pageWorks(page, file);
      }
      const css = await page.evaluate(async () => (await fetch('css/site.css')).text());
      assert.equal(/course2-marker/.test(css), prefix === '/course2/', `${prefix} serves its own build offline`);
    }
    const keys = (await page.evaluate(() => caches.keys())).sort();
    assert.deepEqual(keys.map((k) => k.replace(/[0-9a-f]{16}$/, 'V')), ['wingspline:/course/:V', 'wingspline:/course2/:V']);
    assert.deepEqual(page.problems, []);
  } finally {
    await site.close();
    fs.rmSync(course, { recursive: true, force: true });
    fs.rmSync(course2, { recursive: true, force: true });
  }
});

// The start page, controlled, after a page script (as any same-origin script could)
// rewrote its cached copy (under './' and 'index.html') and the landing script's.
const tamperedPage = '<!doctype html><title>tampered</title><p id="tampered">tampered page</p>';
const tamperedScript = 'window.__pwned = "a tampered cached script ran";';
async function openTampered(siteUrl) {
  const opened = await openControlled(siteUrl);
  await opened.page.evaluate(async ({ html, script }) => {
    const [name] = await caches.keys();
    const cache = await caches.open(name);
    const put = (file, body, type) => cache.put(new URL(file, location.href), new Response(body, { headers: { 'content-type': type } }));
    await put('./', html, 'text/html');
    await put('index.html', html, 'text/html');
    await put('js/pages/landing.js', script, 'text/javascript');
  }, { html: tamperedPage, script: tamperedScript });
  return opened;
}

test('a tampered cached page or script is not served: online the network answers', async () => {
  await onDeployment(async (site) => {
    const { context, page } = await openTampered(site.url);
    for (const url of [site.url, new URL('index.html', site.url).href]) {
      await page.goto(url);
      await pageWorks(page, 'index.html');
      assert.equal(await page.locator('#tampered').count(), 0, `${url}: the tampered page is not shown`);
      assert.equal(await page.evaluate(() => window.__pwned ?? null), null, `${url}: the tampered script did not run`);
      assert.equal(await page.locator('meta[http-equiv="Content-Security-Policy" i]').count(), 1, 'the page keeps its CSP');
    }
    assert.deepEqual(page.problems, []);
  });
});

test('a tampered cached page or script is not served: offline it is refused with a clear page', async () => {
  await onDeployment(async (site) => {
    const { context, page } = await openTampered(site.url);
    await context.setOffline(true);
    const response = await page.goto(new URL('index.html', site.url).href);
    assert.equal(response.status(), 503);
    assert.equal(await page.locator('#tampered').count(), 0, 'the tampered page is not shown');
    assert.match(await page.textContent('body'), /offline copy of index\.html does not match .*SHA-256.*Connect to the network and reload/s);
    // A lesson page that nobody touched still works offline, and the tampered script is
    // refused rather than handed to it.
    const lesson = readyLessons[0].page;
    await page.goto(new URL(lesson, site.url).href);
    await pageWorks(page, lesson);
    const script = await page.evaluate(async () => {
      try {
        const r = await fetch('js/pages/landing.js');
        return { status: r.status, body: await r.text() };
      } catch (err) {
        return { status: 0, body: err.message };
      }
    });
    assert.equal(script.status, 503);
    assert.doesNotMatch(script.body, /__pwned/);
    assert.equal(await page.evaluate(() => window.__pwned ?? null), null);
  });
});

test('pages come from the network first, the cached copy only offline', async () => {
  await onDeployment(async (site, root) => {
    const { context, page } = await openControlled(site.url);
    // The server's page changes (a hot fix) while the worker and its cache stay as they are.
    const file = path.join(root, 'index.html');
    fs.writeFileSync(file, fs.readFileSync(file, 'utf8').replace('<main id="main">', '<main id="main"><p id="hot-fix">hot fix</p>'));
    await page.reload();
    await pageWorks(page, 'index.html');
    assert.equal(await page.locator('#hot-fix').count(), 1, 'online, the page is the server\'s');
    assert.ok(await page.evaluate(() => !!navigator.serviceWorker.controller), 'the worker answered');
    await context.setOffline(true);
    await page.reload();
    await pageWorks(page, 'index.html');
    assert.equal(await page.locator('#hot-fix').count(), 0, 'offline, the cached (verified) copy');
    assert.deepEqual(page.problems, []);
  });
});

test('install refuses a file whose bytes differ from the manifest, and caches nothing', async () => {
  await onDeployment(async (site, root) => {
    // Changed after the manifest was written: the deployment is inconsistent (or tampered).
    fs.appendFileSync(path.join(root, 'css', 'site.css'), '\n.not-in-the-manifest { color: red; }\n');
    const context = await contexts.newContext({ serviceWorkers: 'allow' });
    const page = trap(await context.newPage());
    await page.addInitScript(() => {
      const register = navigator.serviceWorker.register.bind(navigator.serviceWorker);
      navigator.serviceWorker.register = (...args) => { window.__registration = register(...args); return window.__registration; };
    });
    await page.goto(site.url);
    await pageWorks(page, 'index.html');
    const outcome = await page.evaluate(async () => {
      while (!window.__registration) await new Promise((r) => setTimeout(r, 20));
      const registration = await window.__registration;
      const worker = registration.installing ?? registration.waiting ?? registration.active
        ?? await new Promise((resolve) => registration.addEventListener('updatefound', () => resolve(registration.installing), { once: true }));
      while (worker.state !== 'redundant' && worker.state !== 'activated') {
        await new Promise((resolve) => worker.addEventListener('statechange', resolve, { once: true }));
      }
      return { state: worker.state, caches: await caches.keys(), controlled: !!navigator.serviceWorker.controller };
    });
    assert.deepEqual(outcome, { state: 'redundant', caches: [], controlled: false });
    // The page itself still works online.
    await page.reload();
    await pageWorks(page, 'index.html');
    assert.deepEqual(page.problems, []);
  });
});
