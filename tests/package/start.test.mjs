// `npm start` can listen on another host (HOST) so a classroom network can use it,
// and says what it serves (the folder and every URL it answers on). Runs scripts/start.mjs
// as `npm start` does, on a free port (PORT=0).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import os from 'node:os';
import path from 'node:path';
import { spawn } from 'node:child_process';
import { repoRoot } from '../helpers/browser.mjs';

// Starts the server; resolves to {lines, stop} once it has printed its "serving" line (or
// to {code, lines} when it exits first).
function start(env) {
  const child = spawn(process.execPath, [path.join(repoRoot, 'scripts', 'start.mjs')],
    { cwd: repoRoot, env: { ...process.env, ...env }, stdio: ['ignore', 'pipe', 'pipe'] });
  let out = '';
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => { child.kill(); reject(new Error(`no serving line after 120 s:\n${out}`)); }, 120_000);
    const look = (d) => {
      out += d;
      if (/^\[wingspline\] serving [\s\S]*Ctrl\+C/m.test(out)) {
        clearTimeout(timer);
        resolve({ lines: out.split('\n'), stop: () => new Promise((r) => { child.once('close', r); child.kill('SIGINT'); }) });
      }
    };
    child.stdout.on('data', look);
    child.stderr.on('data', (d) => { out += d; });
    child.on('close', (code) => { clearTimeout(timer); resolve({ code, lines: out.split('\n') }); });
  });
}

const urlsIn = (lines) => lines.flatMap((l) => l.match(/https?:\/\/[^\s)]+/g) ?? []);

async function landingPage(url) {
  const res = await fetch(url);
  assert.equal(res.status, 200, `${url} answers`);
  assert.match(await res.text(), /<title>[^<]*Wingspline/i, `${url} is the landing page`);
}

test('HOST=127.0.0.1 PORT=0: the printed line names the folder and the URL, and the URL serves the landing page', async () => {
  const server = await start({ HOST: '127.0.0.1', PORT: '0' });
  assert.equal(server.code, undefined, server.lines.join('\n'));
  try {
    const urls = urlsIn(server.lines);
    assert.equal(urls.length, 1, server.lines.join('\n'));
    assert.match(urls[0], /^http:\/\/127\.0\.0\.1:\d+\/$/);
    assert.ok(server.lines.some((l) => l.includes(path.join(repoRoot, 'dist'))), `the folder served is named:\n${server.lines.join('\n')}`);
    // npm start builds what serving needs (the wasm module and the site), never the native
    // tests or benchmark (the native test layer and npm run bench build those).
    assert.ok(server.lines.some((l) => /building build\/wasm/.test(l)), `the wasm module is built:\n${server.lines.join('\n')}`);
    assert.ok(!server.lines.some((l) => /build\/native/.test(l)), `nothing native is built:\n${server.lines.join('\n')}`);
    await landingPage(urls[0]);
  } finally {
    await server.stop();
  }
});

test('HOST=0.0.0.0 listens on every interface and prints a URL for each of the machine\'s IPv4 addresses, each serving the page', async () => {
  const addresses = Object.values(os.networkInterfaces()).flat().filter((a) => a.family === 'IPv4' || a.family === 4).map((a) => a.address);
  assert.ok(addresses.includes('127.0.0.1'));
  const server = await start({ HOST: '0.0.0.0', PORT: '0' });
  assert.equal(server.code, undefined, server.lines.join('\n'));
  try {
    const urls = urlsIn(server.lines);
    const hosts = urls.map((u) => new URL(u).hostname).sort();
    assert.deepEqual(hosts, [...addresses].sort(), `one URL per address:\n${server.lines.join('\n')}`);
    for (const url of urls) await landingPage(url);
  } finally {
    await server.stop();
  }
});

test('a HOST that is not an address of this machine stops with a message naming HOST', async () => {
  const server = await start({ HOST: '203.0.113.7', PORT: '0' });
  if (server.stop) await server.stop();
  assert.equal(server.code, 1, server.lines.join('\n'));
  assert.match(server.lines.join('\n'), /HOST/);
});
