// A small static file server for dist/ (used by `npm start` and by the browser tests).
// Sends .wasm as application/wasm (so Chrome stream-compiles it once) and the same
// security headers a careful static host would send. No X-Frame-Options and no
// frame-ancestors: a static teaching site is meant to be embedded in slides and course
// pages (docs/embed.md, "Being framed"); each page's own CSP stays strict.
//
// A classroom pulls the same files thirty times at once, so text, scripts and the wasm go
// out compressed (brotli or gzip, by the request's Accept-Encoding; `Vary: Accept-Encoding`)
// and every response carries an ETag and a Last-Modified: a reload revalidates with a 304
// and no body. The compressed bytes are kept in memory per file, keyed by its mtime and size,
// so the file is compressed once per version, not once per student (docs/classroom.md,
// "What the server sends").
import crypto from 'node:crypto';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import zlib from 'node:zlib';

const types = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.off': 'text/plain; charset=utf-8',
  '.obj': 'text/plain; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
  '.webmanifest': 'application/manifest+json',
};

// Worth compressing: text of any kind and the wasm (about a quarter of its size). PNG is
// compressed already. Files below COMPRESS_MIN_BYTES go out as they are (the encoding's own
// header would eat the gain).
const COMPRESSIBLE = /^(text\/|application\/(wasm|json|manifest\+json)|image\/svg\+xml)/;
const COMPRESS_MIN_BYTES = 512;
// Brotli quality 5: 2 MB of wasm in about half a second, 17% smaller than gzip -9; quality
// 11 takes 12 s for 14% more, too long for the first student of a fresh server to wait.
const BROTLI_QUALITY = 5;
const GZIP_LEVEL = 9;

const encoders = {
  br: (bytes) => zlibAsync(zlib.brotliCompress, bytes, {
    params: { [zlib.constants.BROTLI_PARAM_QUALITY]: BROTLI_QUALITY, [zlib.constants.BROTLI_PARAM_SIZE_HINT]: bytes.length },
  }),
  gzip: (bytes) => zlibAsync(zlib.gzip, bytes, { level: GZIP_LEVEL }),
};

function zlibAsync(fn, bytes, options) {
  return new Promise((resolve, reject) => fn(bytes, options, (err, out) => (err ? reject(err) : resolve(out))));
}

/**
 * The encoding to send for an Accept-Encoding header: 'br' or 'gzip' when the client takes
 * it (q > 0, named or by '*'), brotli first; otherwise null (the bytes as they are).
 * @param {string | undefined} header
 * @returns {'br' | 'gzip' | null}
 */
export function chooseEncoding(header) {
  if (!header) return null;
  const q = new Map();
  for (const part of header.split(',')) {
    const [name, ...params] = part.trim().toLowerCase().split(';');
    if (!name) continue;
    const qParam = params.map((p) => p.trim()).find((p) => p.startsWith('q='));
    const value = qParam ? Number.parseFloat(qParam.slice(2)) : 1;
    q.set(name, Number.isFinite(value) ? value : 0);
  }
  for (const name of /** @type {const} */ (['br', 'gzip'])) {
    const value = q.has(name) ? q.get(name) : q.get('*');
    if (value !== undefined && value > 0) return name;
  }
  return null;
}

// Options (for the tests): `prefix` serves the site under a sub-path ('/some/sub/path/')
// and answers 404 elsewhere, like a static host's project folder; `overlays` are folders
// looked in before `root` (test fixtures that must never be part of dist/).
export function createStaticServer(root, { prefix = '/', overlays = [] } = {}) {
  const roots = [...overlays, root].map((dir) => path.resolve(dir));
  // file -> { key: mtime and size, raw bytes, tag, variants: encoding -> Promise<Buffer> }.
  // One server's files (dist/ is a few MB); an entry is replaced when its file changes.
  const files = new Map();

  function locate(pathname) {
    for (const dir of roots) {
      let file = path.resolve(dir, '.' + pathname);
      if (file !== dir && !file.startsWith(dir + path.sep)) return { forbidden: true };
      if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
      if (fs.existsSync(file)) return { file };
    }
    return { file: null };
  }

  // The file's entry, read again only when its mtime or size changed.
  async function entryFor(file) {
    const stat = await fs.promises.stat(file);
    const key = `${stat.mtimeMs}:${stat.size}`;
    const known = files.get(file);
    if (known && known.key === key) return known;
    const raw = await fs.promises.readFile(file);
    // Strong validator from the bytes themselves: the same file gets the same tag after a
    // rebuild that did not change it, or from another server process.
    const tag = crypto.createHash('sha256').update(raw).digest('base64url').slice(0, 22);
    const entry = { key, raw, tag, modified: new Date(Math.floor(stat.mtimeMs / 1000) * 1000), variants: new Map() };
    files.set(file, entry);
    return entry;
  }

  function encoded(entry, encoding) {
    if (!entry.variants.has(encoding)) entry.variants.set(encoding, encoders[encoding](entry.raw));
    return entry.variants.get(encoding);
  }

  async function serve(req, res, file) {
    let entry;
    try {
      entry = await entryFor(file);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain; charset=utf-8' }).end('not found');
      return;
    }
    const type = types[path.extname(file).toLowerCase()] ?? 'application/octet-stream';
    const compressible = COMPRESSIBLE.test(type) && entry.raw.length >= COMPRESS_MIN_BYTES;
    const encoding = compressible ? chooseEncoding(req.headers['accept-encoding']) : null;
    // Each encoding is its own representation, so its own strong ETag.
    const etag = `"${entry.tag}${encoding ? `-${encoding}` : ''}"`;
    const headers = {
      'content-type': type,
      'cache-control': 'no-cache',
      etag,
      'last-modified': entry.modified.toUTCString(),
      'x-content-type-options': 'nosniff',
      'referrer-policy': 'no-referrer',
      ...(compressible ? { vary: 'Accept-Encoding' } : {}),
    };
    if (notModified(req, etag, entry.modified)) {
      res.writeHead(304, headers).end();
      return;
    }
    const body = encoding ? await encoded(entry, encoding) : entry.raw;
    res.writeHead(200, { ...headers, ...(encoding ? { 'content-encoding': encoding } : {}), 'content-length': body.length });
    res.end(req.method === 'HEAD' ? undefined : body);
  }

  return http.createServer((req, res) => {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.writeHead(405, { allow: 'GET, HEAD', 'content-type': 'text/plain; charset=utf-8' }).end('method not allowed');
      return;
    }
    let pathname;
    try {
      pathname = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    } catch {
      res.writeHead(400).end('bad request');
      return;
    }
    if (!pathname.startsWith(prefix)) {
      res.writeHead(404, { 'content-type': 'text/plain; charset=utf-8' }).end('not found');
      return;
    }
    const { file, forbidden } = locate('/' + pathname.slice(prefix.length));
    if (forbidden) {
      res.writeHead(403).end('forbidden');
      return;
    }
    if (!file) {
      res.writeHead(404, { 'content-type': 'text/plain; charset=utf-8' }).end('not found');
      return;
    }
    serve(req, res, file).catch((err) => {
      if (!res.headersSent) res.writeHead(500, { 'content-type': 'text/plain; charset=utf-8' });
      res.end(`cannot send ${pathname}: ${err.message}`);
    });
  });
}

// RFC 9110 section 13.1: If-None-Match decides when present (weak comparison: W/ is ignored),
// If-Modified-Since only without it; both for GET and HEAD.
function notModified(req, etag, modified) {
  const inm = req.headers['if-none-match'];
  if (inm !== undefined) {
    if (inm.trim() === '*') return true;
    return inm.split(',').map((t) => t.trim().replace(/^W\//, '')).includes(etag);
  }
  const ims = req.headers['if-modified-since'];
  if (ims === undefined) return false;
  const since = Date.parse(ims);
  return Number.isFinite(since) && modified.getTime() <= since;
}

// Listens on host:port (port 0 = any free port); resolves to { server, url }.
export function listen(server, { host = '127.0.0.1', port = 0 } = {}) {
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      const { port: actual } = server.address();
      resolve({ server, url: `http://${host}:${actual}/` });
    });
  });
}
