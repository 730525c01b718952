// types/wingspline.d.ts declares the whole public API. tsc checks the declarations
// against examples/ and deliberate misuses (the `types` layer); this file checks them against
// the running module, so they cannot drift from it: every function and method the API object
// and a Mesh carry is declared, nothing declared is missing at run time, and every error code
// the core and the JS layer can throw is in WingsplineErrorCode.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { loadWingspline, WingsplineError } from 'wingspline';
import { repoRoot } from '../helpers/browser.mjs';

// The declarations without their comments (a comment's '->' or ';' is not syntax).
const dts = fs.readFileSync(path.join(repoRoot, 'types', 'wingspline.d.ts'), 'utf8')
  .replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/[^\n]*/g, '');

// The member names of `interface <name> { ... }` (top-level members only: methods, overloads
// and properties at the body's first level of nesting).
function declaredMembers(name) {
  const start = dts.indexOf(`export interface ${name} {`);
  assert.ok(start >= 0, `interface ${name} is declared`);
  let depth = 0;
  const names = new Set();
  let lineStart = true;
  let i = dts.indexOf('{', start);
  for (; i < dts.length; i += 1) {
    const ch = dts[i];
    if (ch === '\n') { lineStart = true; continue; }
    if (ch === '{' || ch === '(' || ch === '<') depth += 1;
    else if (ch === '}' || ch === ')' || ch === '>') { depth -= 1; if (depth === 0) break; }
    if (lineStart && depth === 1 && /\S/.test(ch)) {
      lineStart = false;
      const m = dts.slice(i).match(/^(?:readonly\s+)?([A-Za-z_$][\w$]*)\??\s*[(:<]/);
      if (m) names.add(m[1]);
    } else if (/\S/.test(ch)) {
      lineStart = false;
    }
  }
  return names;
}

function runtimeMembers(object, prototype = false) {
  const keys = prototype ? Object.getOwnPropertyNames(object).filter((k) => k !== 'constructor') : Object.keys(object);
  return new Set(keys);
}

const api = await loadWingspline();

test('every member of the API object is declared in WingsplineApi, and every declared member exists', () => {
  const declared = declaredMembers('WingsplineApi');
  const actual = runtimeMembers(api);
  assert.deepEqual([...actual].filter((k) => !declared.has(k)).sort(), [], 'undeclared API members');
  assert.deepEqual([...declared].filter((k) => !actual.has(k)).sort(), [], 'declared but missing at run time');
  assert.ok(actual.size > 50, `${actual.size} members: the object's keys were read`);
});

test('every method and getter of a Mesh is declared in Mesh, and every declared member exists', () => {
  const mesh = api.buildMesh(api.lectureExample());
  try {
    const declared = declaredMembers('Mesh');
    const actual = runtimeMembers(Object.getPrototypeOf(mesh), true);
    assert.deepEqual([...actual].filter((k) => !declared.has(k)).sort(), [], 'undeclared Mesh members');
    assert.deepEqual([...declared].filter((k) => !actual.has(k)).sort(), [], 'declared but missing at run time');
  } finally {
    mesh.dispose();
  }
});

test('the module exports exactly what the declarations export as values: loadWingspline and WingsplineError', async () => {
  const module = await import('wingspline');
  const declaredValues = [...dts.matchAll(/^export (?:declare )?(?:function|class|const) ([\w$]+)/gm)].map((m) => m[1]).sort();
  assert.deepEqual(Object.keys(module).sort(), declaredValues);
  assert.equal(new WingsplineError('disposed', 'x').name, 'WingsplineError');
});

test('every error code the core (C++) and the JS layer throw is in WingsplineErrorCode', () => {
  const union = dts.slice(dts.indexOf('export type WingsplineErrorCode ='), dts.indexOf(';', dts.indexOf('export type WingsplineErrorCode =')));
  const declared = new Set([...union.matchAll(/'([a-z0-9-]+)'/g)].map((m) => m[1]));
  const sources = [];
  const walk = (dir) => {
    for (const entry of fs.readdirSync(path.join(repoRoot, dir), { withFileTypes: true })) {
      const rel = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(rel);
      else if (/\.(cpp|h|js)$/.test(entry.name)) sources.push(fs.readFileSync(path.join(repoRoot, rel), 'utf8'));
    }
  };
  ['core/src', 'core/include', 'core/bindings', 'web/js/core'].forEach(walk);
  const text = sources.join('\n');
  // Codes as the sources raise them: Error("code", ...), require(cond, "code", ...),
  // problem/verdict helpers with a code argument, fail('code', ...), new WingsplineError('code', ...).
  const thrown = new Set([
    ...[...text.matchAll(/\b(?:Error|ParseError|InvalidMesh|require|refuse|deny|problem|add_problem|no)\w*\(\s*(?:[^,()"]*,\s*)?"([a-z0-9]+(?:-[a-z0-9]+)+)"/g)].map((m) => m[1]),
    ...[...text.matchAll(/\b(?:fail|WingsplineError)\(\s*'([a-z0-9]+(?:-[a-z0-9]+)+)'/g)].map((m) => m[1]),
  ]);
  assert.ok(thrown.size > 50, `${thrown.size} codes found in the sources`);
  assert.deepEqual([...thrown].filter((c) => !declared.has(c)).sort(), [], 'codes thrown but not in WingsplineErrorCode');
});
