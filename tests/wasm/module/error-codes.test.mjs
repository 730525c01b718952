// One list of error codes, in the core (error_codes.h, api.errorCodes): the declarations'
// WingsplineErrorCode union, docs/errors.md and every code the core and the JS API throw are
// compared with it, so a code cannot be thrown, declared or documented without the others.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadWingspline } from 'wingspline';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const api = await loadWingspline();
const listed = api.errorCodes.map((c) => c.code);

test('the list holds each code once, each with a group and a meaning', () => {
  assert.equal(new Set(listed).size, listed.length);
  assert.ok(listed.length > 100);
  for (const c of api.errorCodes) {
    assert.match(c.code, /^[a-z]+(-[a-z]+)*$/, c.code);
    assert.ok(c.group.length > 0 && c.meaning.length > 10, c.code);
  }
  assert.ok(Object.isFrozen(api.errorCodes));
});

test('the declarations\' WingsplineErrorCode union is the list', () => {
  const text = fs.readFileSync(path.join(root, 'types', 'wingspline.d.ts'), 'utf8');
  const start = text.indexOf('export type WingsplineErrorCode =');
  const union = text.slice(start, text.indexOf('/** Every error the API throws', start)).replace(/\/\/[^\n]*/g, '');
  const declared = [...union.matchAll(/'([a-z-]+)'/g)].map((m) => m[1]);
  assert.deepEqual([...declared].sort(), [...listed].sort());
});

test('docs/errors.md lists every code with its meaning, in the list\'s order', () => {
  const text = fs.readFileSync(path.join(root, 'docs', 'errors.md'), 'utf8');
  const rows = [...text.matchAll(/^\| `([a-z-]+)` \| ([^|]+) \| ([^|]+) \|$/gm)].map((m) => [m[1], m[2].trim(), m[3].trim()]);
  assert.deepEqual(rows, api.errorCodes.map((c) => [c.code, c.group, c.meaning.replace(/\|/g, '\\|')]));
});

// Every literal code the core or the JS API throws or refuses with: Error("code", ...),
// refuse("code", ...), require(..., "code", ...), error_object("code", ...) in C++;
// fail('code', ...) and new WingsplineError('code', ...) in JS.
function sourceFiles(dir, ext) {
  return fs.readdirSync(path.join(root, dir), { recursive: true }).filter((f) => ext.some((e) => f.endsWith(e))).map((f) => path.join(root, dir, f));
}
test('every code the core and the JS API throw is in the list', () => {
  const thrown = new Map();
  const patterns = [/\b(?:Error|refuse|error_object)\("([a-z][a-z-]*)"/g, /\brequire\([^;]*?,\s*"([a-z][a-z-]*)",/g,
    /\b(?:fail|WingsplineError)\('([a-z][a-z-]*)'/g];
  for (const file of [...sourceFiles('core', ['.cpp', '.h']), ...sourceFiles('web/js/core', ['.js'])]) {
    const text = fs.readFileSync(file, 'utf8');
    for (const p of patterns) for (const m of text.matchAll(p)) thrown.set(m[1], path.relative(root, file));
  }
  assert.ok(thrown.size > 60, `found ${thrown.size}`);
  const missing = [...thrown].filter(([code]) => !listed.includes(code)).map(([code, file]) => `${code} (${file})`);
  assert.deepEqual(missing, []);
});
