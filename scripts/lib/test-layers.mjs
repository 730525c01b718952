// The test layers npm test runs, in order. Each resolves to { code, pass, fail, skip }.
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot, capture } from './run.mjs';
import { buildNative } from '../build.mjs';
import { fuzzLayer } from './fuzz.mjs';

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

async function ctest(buildDir, { env = process.env, extraArgs = [] } = {}) {
  const r = await capture('ctest', ['--test-dir', path.join(repoRoot, 'build', buildDir), '-j2', '--output-on-failure',
    ...extraArgs], { echo: true, env });
  const m = r.stdout.match(/(\d+)% tests passed, (\d+) tests failed out of (\d+)/);
  if (!m) return { code: r.code || 1, pass: 0, fail: 1, skip: 0 };
  const total = Number(m[3]);
  const fail = Number(m[2]);
  const skip = Number((r.stdout.match(/(\d+) tests? (?:were )?skipped|Not Run/) ?? [0, 0])[1]) || 0;
  return { code: r.code, pass: total - fail - skip, fail, skip };
}

// The native suite again under AddressSanitizer + UndefinedBehaviorSanitizer (issue 9):
// build/native-asan (Debug, -fsanitize=address,undefined, -fno-sanitize-recover=all) is
// built here, not up front, so `node scripts/test.mjs native wasm` stays quick. Any report
// (out-of-bounds access, use after free, leak, signed overflow, bad shift...) aborts the
// test case, which CTest counts as failed. A case running 120 s is a failure too.
async function asanLayer() {
  try {
    await buildNative({ sanitize: true });
  } catch (err) {
    process.stderr.write(`[wingspline] the sanitizer build failed: ${err.message}\n`);
    return { code: 1, pass: 0, fail: 1, skip: 0 };
  }
  const env = {
    ...process.env,
    ASAN_OPTIONS: 'detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1',
    UBSAN_OPTIONS: 'print_stacktrace=1:halt_on_error=1',
  };
  return ctest('native-asan', { env, extraArgs: ['--timeout', '120'] });
}

export const layers = [
  { name: 'native', run: () => ctest('native') },
  { name: 'wasm', run: () => nodeTests('tests/wasm') },
  { name: 'browser', run: () => nodeTests('tests/browser') },
  { name: 'asan', run: asanLayer },
  { name: 'fuzz', run: () => fuzzLayer() },
];
