// `npm test`, `npm start` and `npm run bench` on a clean clone import their modules before
// setup() has installed the npm packages, so nothing those commands import statically may
// name a package from node_modules (a package is imported where it is used, after setup).
// Here the scripts/ folder is copied to a folder with no node_modules above it and each
// module the commands load first is imported there: a static `import ... from 'esbuild'`
// fails with ERR_MODULE_NOT_FOUND, as it did on CI's clean clone.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';

const repo = path.resolve(import.meta.dirname, '../..');
// The commands' entry files run when imported, so their imports are listed instead
// (tests/scripts can read them: the list is checked against the entries below).
const ENTRIES = ['test.mjs', 'start.mjs', 'bench.mjs'];

function localImports(file) {
  const text = fs.readFileSync(file, 'utf8');
  return [...text.matchAll(/^import\s[^;]*?from\s+'([^']+)'/gms)].map((m) => m[1]);
}

test('every module the commands import before setup loads without node_modules', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-before-setup-'));
  try {
    fs.cpSync(path.join(repo, 'scripts'), path.join(dir, 'scripts'), { recursive: true });
    fs.copyFileSync(path.join(repo, 'package.json'), path.join(dir, 'package.json'));
    const modules = new Set();
    for (const entry of ENTRIES) {
      for (const spec of localImports(path.join(repo, 'scripts', entry))) {
        assert.ok(spec.startsWith('node:') || spec.startsWith('.'),
          `scripts/${entry} imports '${spec}' before setup() can install it`);
        if (spec.startsWith('.')) modules.add(`./scripts/${path.posix.normalize(spec)}`);
      }
    }
    assert.ok(modules.has('./scripts/build.mjs') && modules.has('./scripts/setup.mjs'));
    const code = `for (const m of ${JSON.stringify([...modules])}) await import(m);`;
    const r = spawnSync(process.execPath, ['--input-type=module', '-e', code], { cwd: dir, encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
