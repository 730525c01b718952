// The service worker's precache list (dist/sw-manifest.js): every file of dist/ with a content hash, so a new
// deployment (any changed byte) installs a new cache and an unchanged one costs nothing.
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

export function writeServiceWorkerManifest(dist) {
  const files = listFiles(dist).filter((f) => f !== 'sw-manifest.js' && f !== 'sw.js').sort();
  const hash = crypto.createHash('sha256');
  for (const f of files) {
    hash.update(f);
    hash.update(fs.readFileSync(path.join(dist, f)));
  }
  const manifest = { version: hash.digest('hex').slice(0, 16), files };
  // A script, not JSON: the browser byte-compares importScripts() files when it checks the
  // service worker for updates, so a new build is noticed although sw.js is unchanged.
  const target = path.join(dist, 'sw-manifest.js');
  const text = `self.WINGSPLINE_MANIFEST = ${JSON.stringify(manifest, null, 1)};\n`;
  if (!fs.existsSync(target) || fs.readFileSync(target, 'utf8') !== text) fs.writeFileSync(target, text);
  return manifest;
}
