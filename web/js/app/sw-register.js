// @ts-check
// Registers the service worker (dist/sw.js) relative to the page, so the site works
// offline after the first visit from whatever sub-path it is hosted at.
export function registerServiceWorker() {
  if (!('serviceWorker' in navigator) || window.location.protocol === 'file:') return;
  navigator.serviceWorker.register(new URL('../../sw.js', import.meta.url), { scope: new URL('../../', import.meta.url).pathname })
    .catch(() => { /* offline support is a bonus; the page works without it */ });
}
