// Offline support: precache every file of the build (listed with a content hash in
// sw-manifest.js, written by scripts/build.mjs), answer from the cache, and replace the
// cache when a new build is deployed. Paths are relative to this file, so the site works
// from any sub-path of a static host.
/* global self, caches */
self.importScripts('sw-manifest.js');
const manifest = self.WINGSPLINE_MANIFEST;
const CACHE = `wingspline-${manifest.version}`;
const base = new URL('./', self.location.href);

self.addEventListener('install', (event) => {
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    await cache.addAll(['./', ...manifest.files].map((f) => new Request(new URL(f, base), { cache: 'reload' })));
    await self.skipWaiting();
  })());
});

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const key of await caches.keys()) {
      if (key.startsWith('wingspline-') && key !== CACHE) await caches.delete(key);
    }
    await self.clients.claim();
  })());
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || !request.url.startsWith(base.href)) return;
  event.respondWith((async () => {
    // The URL fragment (share link) never reaches the server; the query is not used either.
    // caches.match with cacheName never creates a cache: a worker that is being replaced
    // must not bring back the old build's cache that the new worker just deleted.
    const hit = await caches.match(request, { ignoreSearch: true, cacheName: CACHE })
      ?? await caches.match(request, { ignoreSearch: true });
    if (hit) return hit;
    try {
      return await fetch(request);
    } catch (err) {
      if (request.mode === 'navigate') {
        const page = await caches.match(new URL('index.html', base), { cacheName: CACHE });
        if (page) return page;
      }
      throw err;
    }
  })());
});
