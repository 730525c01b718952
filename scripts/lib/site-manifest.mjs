// The service worker's precache list (dist/sw-manifest.js): every file of dist/ with the SHA-256
// of its bytes. The worker checks each file against it when caching and when serving,
// and the version (a hash of the list and of sw.js) names the cache,
// so a new deployment (any changed byte) installs a new cache and an unchanged one costs nothing.
import crypto from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';

function listFiles(dir, base = dir) {
  const out = [];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...listFiles(full, base));
    else out.push(path.relative(base, full).split(path.sep).join('/'));
  }
  return out;
}

const sha256 = (bytes) => crypto.createHash('sha256').update(bytes).digest('hex');

export function writeServiceWorkerManifest(dist) {
  const names = listFiles(dist).filter((f) => f !== 'sw-manifest.js' && f !== 'sw.js').sort();
  const files = Object.fromEntries(names.map((f) => [f, sha256(fs.readFileSync(path.join(dist, f)))]));
  // sw.js is not precached but is part of the version: a changed worker installs into a cache
  // of its own, so a refused install can delete it without touching the active worker's.
  const worker = fs.existsSync(path.join(dist, 'sw.js')) ? sha256(fs.readFileSync(path.join(dist, 'sw.js'))) : '';
  const version = sha256(JSON.stringify({ files, worker })).slice(0, 16);
  const manifest = { version, files };
  // A script, not JSON: the browser byte-compares importScripts() files when it checks the
  // service worker for updates, so a new build is noticed although sw.js is unchanged.
  const target = path.join(dist, 'sw-manifest.js');
  const text = `self.WINGSPLINE_MANIFEST = ${JSON.stringify(manifest, null, 1)};\n`;
  if (!fs.existsSync(target) || fs.readFileSync(target, 'utf8') !== text) fs.writeFileSync(target, text);
  return manifest;
}
