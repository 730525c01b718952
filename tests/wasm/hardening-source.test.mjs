// Security of a static site, checked on the source (issue 9). The browser test
// tests/browser/hardening-csp.test.mjs checks the same pages live in Chromium.
//  * No HTML is ever built from text: web/ never uses an HTML sink (innerHTML, outerHTML,
//    insertAdjacentHTML, document.write, createContextualFragment, DOMParser, srcdoc);
//    text goes into the DOM through textContent / text nodes (web/js/app/dom.js).
//  * No code is built from text: no eval, new Function, string timers, javascript: URLs.
//  * Every page carries the Content Security Policy: scripts only from the site itself, no
//    'unsafe-inline', no 'unsafe-eval' (the wasm glue is linked with -sDYNAMIC_EXECUTION=0,
//    so embind needs no new Function; checked below on the built glue), no remote origin;
//    'wasm-unsafe-eval' is the one extra, which compiles WebAssembly and nothing else.
//  * No page has an inline script or an inline event handler (the CSP would block them).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { cspProblems } from '../helpers/csp.mjs';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const webRoot = path.join(repoRoot, 'web');

function filesUnder(dir, ext) {
  const out = [];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...filesUnder(full, ext));
    else if (ext.some((e) => entry.name.endsWith(e))) out.push(full);
  }
  return out.sort();
}

// Comments may name the sinks (to say they are not used); code may not.
function stripJsComments(source) {
  return source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:'"`\\])\/\/.*$/gm, '$1');
}

const htmlSinks = [
  [/\.innerHTML\b/, 'innerHTML'],
  [/\.outerHTML\b/, 'outerHTML'],
  [/\binsertAdjacentHTML\b/, 'insertAdjacentHTML'],
  [/\bdocument\.write(ln)?\b/, 'document.write'],
  [/\bcreateContextualFragment\b/, 'createContextualFragment'],
  [/\bDOMParser\b/, 'DOMParser'],
  [/\bsrcdoc\b/, 'srcdoc'],
  [/\bsetHTMLUnsafe\b|\bparseHTMLUnsafe\b/, 'setHTMLUnsafe'],
];
const codeFromText = [
  [/\beval\s*\(/, 'eval('],
  [/\bnew\s+Function\s*\(/, 'new Function('],
  [/\bFunction\s*\(\s*['"`]/, 'Function("...")'],
  [/\bset(Timeout|Interval)\s*\(\s*['"`]/, 'a string timer'],
  [/javascript:/i, 'a javascript: URL'],
];

const jsFiles = filesUnder(webRoot, ['.js', '.mjs']);
const htmlFiles = filesUnder(webRoot, ['.html']);

test('the scan sees the site (pages and modules exist)', () => {
  assert.ok(htmlFiles.some((f) => f.endsWith('index.html')), 'web/index.html');
  assert.ok(jsFiles.some((f) => f.endsWith(path.join('app', 'dom.js'))), 'web/js/app/dom.js');
});

test('no web/ module builds HTML or code from text', () => {
  const found = [];
  for (const file of jsFiles) {
    const code = stripJsComments(fs.readFileSync(file, 'utf8'));
    code.split('\n').forEach((line, i) => {
      for (const [pattern, name] of [...htmlSinks, ...codeFromText]) {
        if (pattern.test(line)) found.push(`${path.relative(repoRoot, file)}:${i + 1} uses ${name}: ${line.trim()}`);
      }
    });
  }
  assert.deepEqual(found, []);
});

test('the scan would catch a sink (the patterns are not dead)', () => {
  const sample = 'el.innerHTML = name; x.insertAdjacentHTML("beforeend", s); new Function("a", b); setTimeout("go()", 1);';
  const hits = [...htmlSinks, ...codeFromText].filter(([p]) => p.test(sample)).map(([, n]) => n);
  assert.deepEqual(hits, ['innerHTML', 'insertAdjacentHTML', 'new Function(', 'Function("...")', 'a string timer']);
  assert.equal(stripJsComments('// el.innerHTML = x\nconst a = "http://x";').includes('innerHTML'), false);
});

function cspOf(html) {
  const m = html.match(/<meta\s+http-equiv=["']Content-Security-Policy["']\s+content=(?:"([^"]*)"|'([^']*)')/i);
  return m ? (m[1] ?? m[2]) : null;
}

test('the CSP rules reject what they must (the checker is not dead)', () => {
  const good = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; object-src 'none'; base-uri 'none'";
  assert.deepEqual(cspProblems(good), []);
  assert.ok(cspProblems(good.replace("'wasm-unsafe-eval'", "'unsafe-eval'")).length > 0);
  assert.ok(cspProblems(good.replace("'self' 'wasm", "'self' 'unsafe-inline' 'wasm")).length > 0);
  assert.ok(cspProblems(good + '; img-src https://cdn.example.org').length > 0);
  assert.ok(cspProblems(good.replace("script-src 'self'", 'script-src cdn.example.org')).length > 0);
  assert.ok(cspProblems('').length > 0);
});

for (const file of htmlFiles) {
  const name = path.relative(webRoot, file);
  test(`${name}: a strict CSP, no inline script, no inline handler, nothing remote`, () => {
    const html = fs.readFileSync(file, 'utf8');
    const csp = cspOf(html);
    assert.ok(csp, `${name} has no <meta http-equiv="Content-Security-Policy">`);
    assert.deepEqual(cspProblems(csp), []);
    assert.ok(html.search(/<meta\s+http-equiv=["']Content-Security-Policy/i) < html.search(/<script\b/i) || !/<script\b/i.test(html),
      'the CSP comes before the first script');
    const scripts = [...html.matchAll(/<script\b([^>]*)>([\s\S]*?)<\/script>/gi)];
    for (const [, attrs, body] of scripts) {
      assert.match(attrs, /\bsrc=/, `${name} has an inline script: <script${attrs}>`);
      assert.equal(body.trim(), '', `${name} has a script with both src and a body`);
      const src = attrs.match(/\bsrc=["']([^"']+)["']/)[1];
      assert.ok(!/^(https?:)?\/\//i.test(src), `${name} loads a remote script ${src}`);
    }
    assert.deepEqual(html.match(/\son[a-z]+\s*=/gi) ?? [], [], `${name} has inline event handlers`);
    assert.deepEqual(html.match(/\b(?:src|href)=["'](?:https?:)?\/\/[^"']+/gi) ?? [], [], `${name} references a remote origin`);
  });
}

test('the built wasm glue never builds code from text (-sDYNAMIC_EXECUTION=0)', () => {
  const glue = fs.readFileSync(path.join(repoRoot, 'dist', 'wasm', 'wingspline-core.js'), 'utf8');
  assert.doesNotMatch(glue, /\bnew Function\s*\(/);
  assert.doesNotMatch(glue, /\beval\s*\(/);
});
