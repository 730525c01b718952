// Security of the site's sources: no innerHTML/outerHTML/insertAdjacentHTML/
// document.write anywhere in web/ (markup from links and files could otherwise run), and
// every page carries the strict CSP: no inline script or style, no remote origins, no
// 'unsafe-eval' (embind is built with -sDYNAMIC_EXECUTION=0).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot } from '../../helpers/browser.mjs';
import { filesUnder } from '../../helpers/files.mjs';

const webDir = path.join(repoRoot, 'web');
const fixtureDir = path.join(repoRoot, 'tests', 'fixtures', 'site');
const sources = [...filesUnder(webDir, ['.js', '.mjs', '.html']), ...filesUnder(fixtureDir, ['.js', '.html'])];
const pages = [...filesUnder(webDir, ['.html']), ...filesUnder(fixtureDir, ['.html'])];

test('no HTML parsing of strings anywhere in web/', () => {
  assert.ok(sources.length > 10, 'the sources were found');
  const banned = /\.(innerHTML|outerHTML)\b|insertAdjacentHTML|document\.write|createContextualFragment|DOMParser|srcdoc/;
  const hits = [];
  for (const file of sources) {
    fs.readFileSync(file, 'utf8').split('\n').forEach((line, i) => {
      if (banned.test(line)) hits.push(`${path.relative(repoRoot, file)}:${i + 1}: ${line.trim()}`);
    });
  }
  assert.deepEqual(hits, []);
});

test('no eval or Function constructor in the site scripts or the wasm glue', () => {
  const glue = path.join(repoRoot, 'dist', 'wasm', 'wingspline-core.js');
  const hits = [];
  for (const file of [...sources, glue]) {
    const text = fs.readFileSync(file, 'utf8');
    if (/\beval\s*\(|new\s+Function\s*\(/.test(text)) hits.push(path.relative(repoRoot, file));
  }
  assert.deepEqual(hits, []);
});

test('every page has the strict CSP and no inline script or style', () => {
  assert.ok(pages.length >= 2);
  for (const file of pages) {
    const html = fs.readFileSync(file, 'utf8');
    const name = path.relative(repoRoot, file);
    const csp = html.match(/<meta http-equiv="Content-Security-Policy" content="([^"]+)">/)?.[1];
    assert.ok(csp, `${name} has a CSP meta`);
    const rules = Object.fromEntries(csp.split(';').map((r) => r.trim().split(/\s+/)).map(([k, ...v]) => [k, v]));
    assert.deepEqual(rules['default-src'], ["'self'"], name);
    // A page that runs the core may compile wasm; a guide page, which runs none, may not.
    const guide = name.includes('templates/guide.html');
    assert.deepEqual(rules['script-src'], guide ? ["'self'"] : ["'self'", "'wasm-unsafe-eval'"], name);
    assert.deepEqual(rules['style-src'], ["'self'"], name);
    assert.deepEqual(rules['object-src'], ["'none'"], name);
    assert.deepEqual(rules['base-uri'], ["'none'"], name);
    assert.ok(!/unsafe-inline|'unsafe-eval'|https?:|\*/.test(csp), `${name}: no unsafe-inline, unsafe-eval or remote origins`);
    assert.ok(!/<script(?![^>]*\bsrc=)[^>]*>/.test(html), `${name}: no inline script`);
    assert.ok(!/<style\b|\sstyle="|\son[a-z]+="/.test(html), `${name}: no inline style or handler`);
  }
});
