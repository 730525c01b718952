// Offline support: precache every file of the build (listed with its SHA-256 in
// sw-manifest.js, written by scripts/build.mjs) and replace the cache when a new build is
// deployed. Paths are relative to this file, so the site works from any sub-path of a
// static host. Decisions (docs/hardening.md, "Offline copies"):
// - caches are named by the registration's scope, `wingspline:<scope path>:<version>`, and a
//   worker deletes only its own scope's old caches, so /course/ and /course2/ on one origin
//   keep each other's offline copies;
// - every file is checked against the manifest's SHA-256 when it is cached (install refuses
//   a build whose bytes differ) and again whenever it is served from the cache, so an entry
//   rewritten by a same-origin script is never served;
// - pages (navigations, .html) come from the network first; the cache is the offline
//   fallback. Other files come from the cache first (they are verified either way).
/* global self, caches */
self.importScripts('sw-manifest.js');
const manifest = self.WINGSPLINE_MANIFEST;
const base = new URL('./', self.location.href);
const scopePath = new URL(self.registration.scope).pathname;
const CACHE_PREFIX = `wingspline:${scopePath}:`;
const CACHE = `${CACHE_PREFIX}${manifest.version}`;
const VERSION = /^[0-9a-f]{16}$/;
// Older workers named their caches `wingspline-<version>` whatever the scope.
const LEGACY = /^wingspline-[0-9a-f]{16}$/;

// The file of the manifest a request names ('./' and 'folder/' name their index.html), or null.
function manifestPath(url) {
  const u = new URL(url);
  if (u.origin !== base.origin || !u.pathname.startsWith(base.pathname)) return null;
  let file;
  try {
    file = decodeURIComponent(u.pathname.slice(base.pathname.length));
  } catch {
    return null;
  }
  if (file === '' || file.endsWith('/')) file += 'index.html';
  return Object.hasOwn(manifest.files, file) ? file : null;
}

async function sha256Hex(bytes) {
  const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', bytes));
  return Array.from(digest, (b) => b.toString(16).padStart(2, '0')).join('');
}

// A response holding `bytes` (already verified) with the headers it was served with: the
// page's CSP is a <meta> inside the hashed bytes, and any policy header travels too.
function rebuilt(bytes, response) {
  return new Response(bytes, { status: response.status, statusText: response.statusText, headers: response.headers });
}

// The network's answer for `file`, as bytes checked against the manifest; throws when the
// request fails or the bytes differ.
async function fetchVerified(file, init) {
  const response = await fetch(new Request(new URL(file, base), init));
  if (!response.ok) throw new Error(`${file}: the server answered ${response.status}`);
  const bytes = await response.arrayBuffer();
  const actual = await sha256Hex(bytes);
  if (actual !== manifest.files[file]) {
    throw new Error(`${file}: its SHA-256 is ${actual} but the manifest says ${manifest.files[file]}; not cached`);
  }
  return rebuilt(bytes, response);
}

self.addEventListener('install', (event) => {
  event.waitUntil((async () => {
    // The version covers sw.js too, so this cache is this worker's alone and a refused
    // install can drop it without touching the active worker's copy.
    const cache = await caches.open(CACHE);
    const outcomes = await Promise.allSettled(Object.keys(manifest.files).map(async (file) => {
      await cache.put(new URL(file, base), await fetchVerified(file, { cache: 'reload' }));
    }));
    const refusals = outcomes.filter((o) => o.status === 'rejected').map((o) => o.reason?.message ?? String(o.reason));
    if (refusals.length > 0) {
      // All or nothing: a half-verified copy would look ready and then fail offline.
      await caches.delete(CACHE);
      throw new Error(`offline copy not installed: ${refusals.join('; ')}`);
    }
    await self.skipWaiting();
  })());
});

// A cache of the old naming belongs to this scope when it holds this scope's start page.
async function isOwnLegacyCache(key) {
  return LEGACY.test(key) && !!(await caches.match(base.href, { cacheName: key }));
}

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const key of await caches.keys()) {
      const ownOld = key !== CACHE && key.startsWith(CACHE_PREFIX) && VERSION.test(key.slice(CACHE_PREFIX.length));
      if (ownOld || await isOwnLegacyCache(key)) await caches.delete(key);
    }
    await self.clients.claim();
  })());
});

// The cached copy of `file` if its bytes match the manifest: { response } or { tampered }
// (a copy exists and differs) or {} (no copy). caches.match with cacheName never creates a
// cache: a worker that is being replaced must not bring back a cache the new one deleted.
async function fromCache(file) {
  const hit = await caches.match(new URL(file, base).href, { cacheName: CACHE });
  if (!hit) return {};
  const bytes = await hit.arrayBuffer();
  if (await sha256Hex(bytes) !== manifest.files[file]) return { tampered: true };
  return { response: rebuilt(bytes, hit) };
}

// Puts a network answer that matches the manifest into the cache when the cached copy is
// missing or tampered with (so the next offline visit works again). Only while this
// worker's cache exists.
async function repair(file, response) {
  if (!(await caches.keys()).includes(CACHE) || (await fromCache(file)).response) return;
  const bytes = await response.arrayBuffer();
  if (await sha256Hex(bytes) !== manifest.files[file]) return;
  await (await caches.open(CACHE)).put(new URL(file, base), rebuilt(bytes, response));
}

const escapeHtml = (text) => String(text).replace(/[<>&"']/g, (c) => `&#${c.charCodeAt(0)};`);

// What is answered, offline, instead of a copy whose bytes differ from the manifest.
function refused(file, isPage) {
  const text = `The offline copy of ${file} does not match this site's manifest (its SHA-256 differs), `
    + 'so it was not used. Connect to the network and reload.';
  const headers = { 'x-content-type-options': 'nosniff', 'content-security-policy': "default-src 'none'" };
  const init = { status: 503, statusText: 'Offline copy refused' };
  if (!isPage) return new Response(text, { ...init, headers: { ...headers, 'content-type': 'text/plain; charset=utf-8' } });
  const html = `<!doctype html><html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'">
<title>Offline copy refused · Wingspline</title></head>
<body><h1>This page cannot be shown offline</h1><p>${escapeHtml(text)}</p></body></html>`;
  return new Response(html, { ...init, headers: { ...headers, 'content-type': 'text/html; charset=utf-8' } });
}

async function answer(event) {
  const { request } = event;
  const isPage = request.mode === 'navigate' || request.destination === 'document';
  const named = manifestPath(request.url);
  // An unknown page under the scope falls back to the start page offline.
  const file = named ?? (isPage ? manifestPath(base.href) : null);
  const pageFile = isPage || (file?.endsWith('.html') ?? false);
  let cached = {};
  if (!pageFile && file) {
    cached = await fromCache(file);
    if (cached.response) return cached.response;
  }
  try {
    // Pages: network first. Other files: only when the cache had no good copy.
    const response = await fetch(request);
    if (named && response.ok) event.waitUntil(repair(named, response.clone()).catch(() => {}));
    return response;
  } catch (err) {
    if (pageFile && file) cached = await fromCache(file);
    if (cached.response) return cached.response;
    if (cached.tampered) return refused(file, pageFile);
    throw err;
  }
}

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || !request.url.startsWith(base.href)) return;
  event.respondWith(answer(event));
});
