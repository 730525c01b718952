// The test layers npm test runs, in order. Each resolves to { code, pass, fail, skip }.
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot, capture } from './run.mjs';

function testFiles(dir) {
  const full = path.join(repoRoot, dir);
  return fs.readdirSync(full).filter((f) => f.endsWith('.test.mjs')).sort().map((f) => path.join(dir, f));
}

async function nodeTests(dir, extraEnv = {}) {
  const files = testFiles(dir);
  const r = await capture(process.execPath, ['--test', '--test-concurrency=1', ...files],
    { echo: true, env: { ...process.env, ...extraEnv } });
  const count = (label) => Number((r.stdout.match(new RegExp(`^# ${label} (\\d+)`, 'm')) ?? [0, 0])[1]);
  // Skipped tests are reported, and a skip is never counted as a pass.
  return { code: r.code, pass: count('pass'), fail: count('fail') + count('cancelled'), skip: count('skipped') + count('todo') };
}

async function ctest(buildDir) {
  const r = await capture('ctest', ['--test-dir', path.join(repoRoot, 'build', buildDir), '-j2', '--output-on-failure'],
    { echo: true });
  const m = r.stdout.match(/(\d+)% tests passed, (\d+) tests failed out of (\d+)/);
  if (!m) return { code: r.code || 1, pass: 0, fail: 1, skip: 0 };
  const total = Number(m[3]);
  const fail = Number(m[2]);
  const skip = Number((r.stdout.match(/(\d+) tests? (?:were )?skipped|Not Run/) ?? [0, 0])[1]) || 0;
  return { code: r.code, pass: total - fail - skip, fail, skip };
}

export const layers = [
  { name: 'native', run: () => ctest('native') },
  { name: 'wasm', run: () => nodeTests('tests/wasm') },
  { name: 'browser', run: () => nodeTests('tests/browser') },
];
