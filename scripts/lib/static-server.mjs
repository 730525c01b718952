// A small static file server for dist/ (used by `npm start` and by the browser tests).
// Sends .wasm as application/wasm (so Chrome stream-compiles it once) and the same
// security headers a careful static host would send. No X-Frame-Options and no
// frame-ancestors: a static teaching site is meant to be embedded in slides and course
// pages (docs/embed.md, "Being framed"); each page's own CSP stays strict.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

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

// Options (for the tests): `prefix` serves the site under a sub-path ('/some/sub/path/')
// and answers 404 elsewhere, like a static host's project folder; `overlays` are folders
// looked in before `root` (test fixtures that must never be part of dist/).
export function createStaticServer(root, { prefix = '/', overlays = [] } = {}) {
  const roots = [...overlays, root].map((dir) => path.resolve(dir));
  function locate(pathname) {
    for (const dir of roots) {
      let file = path.resolve(dir, '.' + pathname);
      if (file !== dir && !file.startsWith(dir + path.sep)) return { forbidden: true };
      if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
      if (fs.existsSync(file)) return { file };
    }
    return { file: null };
  }
  return http.createServer((req, res) => {
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
    fs.readFile(file ?? '', (err, body) => {
      if (err) {
        res.writeHead(404, { 'content-type': 'text/plain; charset=utf-8' }).end('not found');
        return;
      }
      res.writeHead(200, {
        'content-type': types[path.extname(file).toLowerCase()] ?? 'application/octet-stream',
        'cache-control': 'no-cache',
        'x-content-type-options': 'nosniff',
        'referrer-policy': 'no-referrer',
      });
      res.end(body);
    });
  });
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
