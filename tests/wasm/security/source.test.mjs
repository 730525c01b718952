// Security of a static site, on the source, complementing
// tests/browser/security/sinks.test.mjs (which bans the HTML sinks and eval/new
// Function in web/ and the glue, and checks each page's CSP directives). Here, what that
// file does not cover:
//  * code built from text by other routes: string timers, javascript: URLs;
//  * remote origins referenced by a page (src/href), and inline event handlers in any case;
//  * the CSP checker shared with the live test (tests/helpers/csp.mjs) rejects what it must,
//    and every page passes it (the browser test tests/browser/security/csp.test.mjs then
//    proves the policy is enforced in Chromium);
//  * the scans themselves are not dead (each pattern catches a sample).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { cspProblems } from '../../helpers/csp.mjs';
import { filesUnder } from '../../helpers/files.mjs';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const webRoot = path.join(repoRoot, 'web');

// Comments may name the sinks (to say they are not used); code may not.
function stripJsComments(source) {
  return source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:'"`\\])\/\/.*$/gm, '$1');
}

// What security/sinks.test.mjs does not scan for.
const codeFromText = [
  [/\bset(Timeout|Interval)\s*\(\s*['"`]/, 'a string timer'],
  [/javascript:/i, 'a javascript: URL'],
  [/\bsetHTMLUnsafe\b|\bparseHTMLUnsafe\b/, 'setHTMLUnsafe'],
  [/\bFunction\s*\(\s*['"`]/, 'Function("...")'],
];

const jsFiles = filesUnder(webRoot, ['.js', '.mjs']);
const htmlFiles = filesUnder(webRoot, ['.html']);

test('the scan sees the site (pages and modules exist)', () => {
  assert.ok(htmlFiles.some((f) => f.endsWith('index.html')), 'web/index.html');
  assert.ok(jsFiles.some((f) => f.endsWith(path.join('app', 'dom.js'))), 'web/js/app/dom.js');
});

test('no web/ module builds code from text by a string timer, a javascript: URL or Function("...")', () => {
  const found = [];
  for (const file of jsFiles) {
    const code = stripJsComments(fs.readFileSync(file, 'utf8'));
    code.split('\n').forEach((line, i) => {
      for (const [pattern, name] of codeFromText) {
        if (pattern.test(line)) found.push(`${path.relative(repoRoot, file)}:${i + 1} uses ${name}: ${line.trim()}`);
      }
    });
  }
  assert.deepEqual(found, []);
});

test('the scan would catch each pattern (the patterns are not dead)', () => {
  const sample = 'a.href = "javascript:go()"; el.setHTMLUnsafe(s); Function("a", b); setTimeout("go()", 1);';
  const hits = codeFromText.filter(([p]) => p.test(sample)).map(([, n]) => n);
  assert.deepEqual(hits, ['a string timer', 'a javascript: URL', 'setHTMLUnsafe', 'Function("...")']);
  assert.equal(stripJsComments('// setTimeout("x")\nconst a = "http://x";').includes('setTimeout'), false);
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
