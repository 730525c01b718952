// The classroom server (scripts/lib/static-server.mjs) by the bytes on the wire: the wasm
// and the scripts go out compressed when the client takes it (and byte for byte the file
// when decompressed), as they are when it does not; every response can be revalidated
// (ETag, Last-Modified, 304 without a body); a changed file is sent again, not a stale
// compressed copy. Raw HTTP (node:http), so nothing decompresses behind the test's back.
// The files are written by the test into a temporary folder: a wasm-like binary, a script,
// a PNG (already compressed: sent as it is), a tiny file.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import crypto from 'node:crypto';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { createStaticServer, listen, chooseEncoding } from '../../scripts/lib/static-server.mjs';
import { repoRoot } from '../helpers/browser.mjs';

// The figure: the served wasm compressed is under 40% of its raw size (gzip makes
// about 25%). Asked of the real wasm when dist/ is built, and of the test's own file always.
const MAX_COMPRESSED_SHARE = 0.4;

let dir;
let site;
let server;
const files = {};

// A wasm-shaped file with the redundancy of real code: a seeded stream of a few hundred
// distinct "instructions", so it compresses like a module does, not like zeros.
function codeLikeBytes(length, seed) {
  const out = Buffer.alloc(length);
  const words = Array.from({ length: 300 }, (_, i) => crypto.createHash('sha256').update(`${seed}:${i}`).digest().subarray(0, 6));
  let state = seed;
  for (let at = 0; at < length;) {
    state = (state * 1103515245 + 12345) >>> 0;
    const w = words[state % words.length];
    w.copy(out, at, 0, Math.min(w.length, length - at));
    at += w.length;
  }
  return out;
}

before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-server-'));
  fs.mkdirSync(path.join(dir, 'wasm'));
  files['/wasm/core.wasm'] = Buffer.concat([Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]), codeLikeBytes(600_000, 7)]);
  files['/js/app.js'] = Buffer.from(Array.from({ length: 400 }, (_, i) => `export const value${i} = ${i} * 2; // line ${i}\n`).join(''));
  files['/index.html'] = Buffer.from(`<!doctype html><title>Test</title>${'<p>paragraph</p>'.repeat(100)}`);
  files['/tiny.txt'] = Buffer.from('ok\n');
  files['/picture.png'] = Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47]), crypto.randomBytes(4000)]);
  for (const [name, bytes] of Object.entries(files)) {
    fs.mkdirSync(path.dirname(path.join(dir, name)), { recursive: true });
    fs.writeFileSync(path.join(dir, name), bytes);
  }
  ({ server, url: site } = await listen(createStaticServer(dir)));
});

after(async () => {
  server.closeAllConnections?.();
  await new Promise((resolve) => server.close(resolve));
  fs.rmSync(dir, { recursive: true, force: true });
});

// One raw request: status, headers and the body bytes exactly as sent.
function request(pathname, headers = {}, { method = 'GET', base = site } = {}) {
  return new Promise((resolve, reject) => {
    const req = http.request(new URL(pathname.replace(/^\//, ''), base), { method, headers, agent: false }, (res) => {
      const chunks = [];
      res.on('data', (c) => chunks.push(c));
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body: Buffer.concat(chunks) }));
    });
    req.on('error', reject);
    req.end();
  });
}

const decode = (res) => {
  const enc = res.headers['content-encoding'];
  if (enc === 'gzip') return zlib.gunzipSync(res.body);
  if (enc === 'br') return zlib.brotliDecompressSync(res.body);
  assert.equal(enc, undefined, `an encoding the test knows: ${enc}`);
  return res.body;
};

test('Accept-Encoding is read by its q-values: brotli first, then gzip, nothing refused is chosen', () => {
  assert.equal(chooseEncoding(undefined), null);
  assert.equal(chooseEncoding(''), null);
  assert.equal(chooseEncoding('gzip, deflate, br, zstd'), 'br'); // Chromium's
  assert.equal(chooseEncoding('gzip, deflate'), 'gzip');
  assert.equal(chooseEncoding('br;q=0, gzip;q=0.5'), 'gzip');
  assert.equal(chooseEncoding('br;q=0, gzip;q=0'), null);
  assert.equal(chooseEncoding('identity'), null);
  assert.equal(chooseEncoding('*'), 'br');
  assert.equal(chooseEncoding('*;q=0.1, br;q=0'), 'gzip');
  assert.equal(chooseEncoding('GZIP'), 'gzip');
});

test('the wasm without Accept-Encoding: the file as it is, with its length, type and validators', async () => {
  const res = await request('/wasm/core.wasm');
  assert.equal(res.status, 200);
  assert.equal(res.headers['content-encoding'], undefined);
  assert.equal(res.headers['content-type'], 'application/wasm');
  assert.equal(Number(res.headers['content-length']), files['/wasm/core.wasm'].length);
  assert.ok(res.body.equals(files['/wasm/core.wasm']), 'byte for byte the file');
  assert.match(res.headers.etag, /^"[^"]+"$/, 'a strong ETag');
  assert.ok(Number.isFinite(Date.parse(res.headers['last-modified'])), 'a Last-Modified date');
  assert.equal(res.headers.vary, 'Accept-Encoding', 'caches keep the encodings apart');
  assert.equal(res.headers['x-content-type-options'], 'nosniff');
  assert.equal(res.headers['referrer-policy'], 'no-referrer');
  assert.equal(res.headers['x-frame-options'], undefined, 'lessons may be framed (docs/embed.md)');
});

for (const encoding of ['gzip', 'br']) {
  test(`the wasm and a script with Accept-Encoding: ${encoding}: under ${MAX_COMPRESSED_SHARE * 100}% of the file on the wire, the file byte for byte once decoded`, async () => {
    for (const name of ['/wasm/core.wasm', '/js/app.js', '/index.html']) {
      const res = await request(name, { 'accept-encoding': encoding });
      assert.equal(res.status, 200);
      assert.equal(res.headers['content-encoding'], encoding, name);
      assert.equal(Number(res.headers['content-length']), res.body.length, `${name}: the length of what is sent`);
      assert.ok(res.body.length < MAX_COMPRESSED_SHARE * files[name].length, `${name}: ${res.body.length} bytes sent for ${files[name].length}`);
      assert.ok(decode(res).equals(files[name]), `${name}: decoded it is the file`);
    }
  });
}

test('what gains nothing from compression goes out as it is: a PNG, a file of a few bytes', async () => {
  for (const name of ['/picture.png', '/tiny.txt']) {
    const res = await request(name, { 'accept-encoding': 'gzip, br' });
    assert.equal(res.headers['content-encoding'], undefined, name);
    assert.ok(res.body.equals(files[name]), name);
  }
});

test('revalidation: If-None-Match with the ETag sent, or If-Modified-Since with its date, gives 304 and no body; another tag or an older date the file', async () => {
  for (const enc of [undefined, 'gzip', 'br']) {
    const headers = enc ? { 'accept-encoding': enc } : {};
    const first = await request('/wasm/core.wasm', headers);
    const again = await request('/wasm/core.wasm', { ...headers, 'if-none-match': first.headers.etag });
    assert.equal(again.status, 304, `${enc ?? 'identity'}: 304 for its own tag`);
    assert.equal(again.body.length, 0);
    assert.equal(again.headers.etag, first.headers.etag);
    const weak = await request('/wasm/core.wasm', { ...headers, 'if-none-match': `"other", W/${first.headers.etag}` });
    assert.equal(weak.status, 304, 'a tag in a list, weak or not, matches (weak comparison, RFC 9110)');
    const other = await request('/wasm/core.wasm', { ...headers, 'if-none-match': '"not-this-one"' });
    assert.equal(other.status, 200);
    assert.ok(decode(other).equals(files['/wasm/core.wasm']));
    const since = await request('/wasm/core.wasm', { ...headers, 'if-modified-since': first.headers['last-modified'] });
    assert.equal(since.status, 304, 'If-Modified-Since its own Last-Modified');
    const older = new Date(Date.parse(first.headers['last-modified']) - 60_000).toUTCString();
    assert.equal((await request('/wasm/core.wasm', { ...headers, 'if-modified-since': older })).status, 200);
    // If-None-Match decides when both are sent (RFC 9110 13.2.2).
    const both = await request('/wasm/core.wasm', { ...headers, 'if-none-match': '"not-this-one"', 'if-modified-since': first.headers['last-modified'] });
    assert.equal(both.status, 200);
  }
  const plain = await request('/wasm/core.wasm');
  const gz = await request('/wasm/core.wasm', { 'accept-encoding': 'gzip' });
  assert.notEqual(plain.headers.etag, gz.headers.etag, 'each encoding is its own representation, its own tag');
});

test('HEAD: the headers of a GET (its length, its encoding) and no body', async () => {
  for (const enc of [undefined, 'gzip']) {
    const headers = enc ? { 'accept-encoding': enc } : {};
    const get = await request('/js/app.js', headers);
    const head = await request('/js/app.js', headers, { method: 'HEAD' });
    assert.equal(head.status, 200);
    assert.equal(head.body.length, 0);
    for (const h of ['content-length', 'content-encoding', 'etag', 'content-type']) assert.equal(head.headers[h], get.headers[h], h);
  }
  const post = await request('/js/app.js', {}, { method: 'POST' });
  assert.equal(post.status, 405);
  assert.equal(post.headers.allow, 'GET, HEAD');
});

test('a file changed on disk is sent anew (new bytes, new tag), not the compressed copy kept of the old one', async () => {
  const name = '/js/changing.js';
  const v1 = Buffer.from('export const version = 1;\n'.repeat(100));
  fs.writeFileSync(path.join(dir, name), v1);
  const first = await request(name, { 'accept-encoding': 'gzip' });
  assert.ok(decode(first).equals(v1));
  const v2 = Buffer.from('export const version = 2; // longer\n'.repeat(100));
  fs.writeFileSync(path.join(dir, name), v2);
  const second = await request(name, { 'accept-encoding': 'gzip', 'if-none-match': first.headers.etag });
  assert.equal(second.status, 200, 'the old tag no longer matches');
  assert.notEqual(second.headers.etag, first.headers.etag);
  assert.ok(decode(second).equals(v2));
});

test('30 students at once: every one gets the same compressed bytes, all of them the file', async () => {
  const responses = await Promise.all(Array.from({ length: 30 }, () => request('/wasm/core.wasm', { 'accept-encoding': 'gzip, deflate, br' })));
  for (const res of responses) {
    assert.equal(res.status, 200);
    assert.ok(res.body.equals(responses[0].body));
  }
  assert.ok(decode(responses[0]).equals(files['/wasm/core.wasm']));
});

test('prefix and overlays still hold, and nothing outside the folders is served', async () => {
  const overlay = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-overlay-'));
  fs.writeFileSync(path.join(overlay, 'tiny.txt'), 'from the overlay\n');
  const { server: s2, url } = await listen(createStaticServer(dir, { prefix: '/course/wingspline/', overlays: [overlay] }));
  try {
    assert.equal((await request('/tiny.txt', {}, { base: url })).status, 404, 'outside the prefix');
    const over = await request('/course/wingspline/tiny.txt', {}, { base: url });
    assert.equal(over.body.toString(), 'from the overlay\n');
    const index = await request('/course/wingspline/', { 'accept-encoding': 'gzip' }, { base: url });
    assert.ok(decode(index).equals(files['/index.html']), 'a folder serves its index.html');
    assert.equal((await request('/course/wingspline/..%2f..%2f..%2fetc/passwd', {}, { base: url })).status, 403);
  } finally {
    s2.closeAllConnections?.();
    await new Promise((resolve) => s2.close(resolve));
    fs.rmSync(overlay, { recursive: true, force: true });
  }
});

test('the real wasm, when dist/ is built: compressed on the wire under 40% of its size, decoded byte for byte', async (t) => {
  const wasm = path.join(repoRoot, 'dist', 'wasm', 'wingspline-mesh.wasm');
  if (!fs.existsSync(wasm)) { t.skip('dist/ is not built'); return; }
  const { server: s2, url } = await listen(createStaticServer(path.join(repoRoot, 'dist')));
  try {
    const bytes = fs.readFileSync(wasm);
    for (const enc of ['gzip', 'br']) {
      const res = await request('/wasm/wingspline-mesh.wasm', { 'accept-encoding': enc }, { base: url });
      assert.equal(res.headers['content-encoding'], enc);
      assert.ok(res.body.length < MAX_COMPRESSED_SHARE * bytes.length, `${enc}: ${res.body.length} of ${bytes.length} bytes`);
      assert.ok(decode(res).equals(bytes));
      t.diagnostic(`wasm ${bytes.length} bytes raw, ${res.body.length} as ${enc}`);
    }
  } finally {
    s2.closeAllConnections?.();
    await new Promise((resolve) => s2.close(resolve));
  }
});
