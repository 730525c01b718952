// The test layers npm test runs, in order. Each resolves to { code, pass, fail, skip }.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { repoRoot, capture } from './run.mjs';
import { buildNative, buildWasm } from '../build.mjs';
import { fuzzLayer } from './fuzz.mjs';

// Every *.test.mjs under dir, in its subject folders at any depth (tests/browser/mesh/...),
// relative to the repository, sorted.
export function testFiles(dir) {
  const full = path.join(repoRoot, dir);
  return fs.readdirSync(full, { recursive: true })
    .filter((f) => f.endsWith('.test.mjs'))
    .map((f) => path.join(dir, f))
    .sort();
}

// The browser test files that take longest, started first so that two files running side
// by side finish together (measured: tampered links about 130 s, saved work about 150 s, state
// about 75 s).
const SLOWEST_FIRST = ['tests/browser/shell/tampered-links.test.mjs', 'tests/browser/shell/saved-work.test.mjs', 'tests/browser/shell/state.test.mjs'];

// concurrency: how many test files run at once, each in its own process (a browser file
// has its own server and browser, so two files never share a page).
async function nodeTests(dir, { concurrency = 1, extraEnv = {} } = {}) {
  const rank = (f) => { const i = SLOWEST_FIRST.indexOf(f); return i < 0 ? SLOWEST_FIRST.length : i; };
  const files = testFiles(dir).sort((a, b) => rank(a) - rank(b));
  return runNodeTests(files, { concurrency, env: { ...process.env, ...extraEnv } });
}

const COUNT_REPORTER = pathToFileURL(path.join(repoRoot, 'scripts', 'lib', 'count-reporter.mjs')).href;

// NODE_OPTIONS without --test-reporter / --test-reporter-destination: the run names its
// own reporters, and Node refuses a run whose reporters and destinations do not pair up.
export function withoutReporterOptions(nodeOptions = '') {
  return nodeOptions.split(/\s+/).filter((option, i, all) => {
    if (/^--test-reporter(-destination)?(=|$)/.test(option)) return false;
    const previous = all[i - 1] ?? '';
    return !/^--test-reporter(-destination)?$/.test(previous);
  }).join(' ').trim();
}

// `node --test` over the files, counted from node:test's own events: the spec reporter
// prints for people on stdout, and scripts/lib/count-reporter.mjs writes the counts as
// JSON to a temporary file. Nothing is read from a reporter's text, so the counts are the
// same whichever reporter Node would use by default (TAP when piped up to Node 22, spec
// from Node 23). Resolves to { code, pass, fail, skip }: cancelled tests count as failed,
// skipped and todo tests as skipped, never as passed. A run that wrote no counts (Node
// could not start the run) is one failure.
export async function runNodeTests(files, { concurrency = 1, env = process.env, cwd = repoRoot, echo = true } = {}) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-counts-'));
  const countsFile = path.join(dir, 'counts.json');
  try {
    // NODE_TEST_CONTEXT is set inside a test run (a test that runs this): with it, Node
    // would report to its parent instead of to the reporters named here.
    const { NODE_TEST_CONTEXT: _parent, ...ownEnv } = env;
    const nodeOptions = withoutReporterOptions(env.NODE_OPTIONS);
    const r = await capture(process.execPath, ['--test', `--test-concurrency=${concurrency}`,
      '--test-reporter=spec', '--test-reporter-destination=stdout',
      `--test-reporter=${COUNT_REPORTER}`, `--test-reporter-destination=${countsFile}`, ...files],
    { echo, cwd, env: { ...ownEnv, NODE_OPTIONS: nodeOptions } });
    let counts = null;
    try { counts = JSON.parse(fs.readFileSync(countsFile, 'utf8')); } catch { counts = null; }
    if (counts === null) {
      process.stderr.write('[wingspline] node --test reported no counts\n');
      return { code: r.code || 1, pass: 0, fail: 1, skip: 0 };
    }
    return { code: r.code, pass: counts.pass, fail: counts.fail + counts.cancelled, skip: counts.skip + counts.todo };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// Runs a Catch2 test binary directly and reads its summary line. (CTest's
// catch_discover_tests mangles test names with commas, which Catch reads as a list of
// test specs, so a discovered test could silently run nothing; the binary's own count is
// the honest one.)
export async function catchTests(binary, args = [], env = process.env) {
  const r = await capture(binary, ['--order', 'decl', ...args], { echo: true, env });
  const all = r.stdout.match(/All tests passed \((\d+) assertions? in (\d+) test cases?\)/);
  if (all) return { code: r.code, pass: Number(all[2]), fail: 0, skip: 0 };
  const some = r.stdout.match(/test cases?:\s+(\d+)\s*\|\s*(\d+) passed\s*\|\s*(\d+) failed/);
  if (some) return { code: r.code || 1, pass: Number(some[2]), fail: Number(some[3]), skip: 0 };
  const failedOnly = r.stdout.match(/test cases?:\s+(\d+)\s*\|\s*(\d+) failed/);
  if (failedOnly) return { code: r.code || 1, pass: 0, fail: Number(failedOnly[2]), skip: 0 };
  return { code: r.code || 1, pass: 0, fail: 1, skip: 0 };
}

// The Catch2 suite (build/native), built here, not by build(): `npm start` needs only the
// wasm module and the site, and the native tests are most of a fresh build's time.
async function nativeLayer() {
  try {
    await buildNative();
  } catch (err) {
    process.stderr.write(`[wingspline] the native build failed: ${err.message}\n`);
    return { code: 1, pass: 0, fail: 1, skip: 0 };
  }
  return catchTests(path.join(repoRoot, 'build', 'native', 'wingspline_tests'));
}

// The native suite again under AddressSanitizer + UndefinedBehaviorSanitizer:
// build/native-asan (Debug, -fsanitize=address,undefined, -fno-sanitize-recover=all) is
// built here, not up front, so `node scripts/test.mjs native wasm` stays quick. Any report
// (out-of-bounds access, use after free, leak, signed overflow, bad shift...) aborts the
// run, which then reports no summary and counts as failed.
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
  // Test cases tagged [large] (the 50 MB file) are left to the native layer: under ASan at
  // -O0 that one case alone takes minutes on these machines, and every code path it runs
  // is also run by the small corpus cases here.
  return catchTests(path.join(repoRoot, 'build', 'native-asan', 'wingspline_tests'), ['~[large]'], env);
}

async function browserLayer() {
  const { startSharedSiteAndBrowser } = await import(pathToFileURL(path.join(repoRoot, 'tests', 'helpers', 'browser.mjs')).href);
  const shared = await startSharedSiteAndBrowser();
  try {
    return await nodeTests('tests/browser', { concurrency: 2, extraEnv: shared.env });
  } finally {
    await shared.close();
  }
}

// The lesson contract (web/js/app/contract.js) checked by TypeScript over the JSDoc types:
// `tsc --noEmit -p jsconfig.json` over the files that carry `// @ts-check` (the shell, its
// parts, every lesson.js). One pass per checked file without an error, one failure per
// file with errors (tsc's messages are printed); a lesson.js without `// @ts-check` or
// without its `@type {...Lesson}` annotation is a failure too, so no lesson leaves the
// contract unchecked.
export async function typesLayer() {
  const config = JSON.parse(fs.readFileSync(path.join(repoRoot, 'jsconfig.json'), 'utf8'));
  const checked = config.include.flatMap((pattern) => globFiles(pattern))
    .filter((file) => fs.readFileSync(path.join(repoRoot, file), 'utf8').startsWith('// @ts-check'));
  const unchecked = ['web/js/lessons', 'tests/fixtures/site/js/lessons'].flatMap((dir) => globFiles(`${dir}/*/lesson.js`))
    .filter((file) => {
      const text = fs.readFileSync(path.join(repoRoot, file), 'utf8');
      return !text.startsWith('// @ts-check') || !/@type \{import\('[./]*app\/contract\.js'\)\.Lesson\}/.test(text);
    });
  for (const file of unchecked) process.stdout.write(`${file}: a lesson.js starts with // @ts-check and annotates its lesson /** @type {import('../../app/contract.js').Lesson} */\n`);
  const tsc = path.join(repoRoot, 'node_modules', 'typescript', 'bin', 'tsc');
  const r = await capture(process.execPath, [tsc, '--noEmit', '--pretty', 'false', '-p', 'jsconfig.json'], { echo: true });
  const withErrors = new Set([...r.stdout.matchAll(/^(\S[^(\n]*)\(\d+,\d+\): error/gm)].map((m) => m[1]));
  const fail = withErrors.size + unchecked.length + (r.code !== 0 && withErrors.size === 0 ? 1 : 0);
  const pass = checked.filter((f) => !withErrors.has(f)).length;
  // The package's declarations (types/wingspline.d.ts) against examples/ and a
  // file of deliberate misuses, each marked @ts-expect-error (an unused one is an error).
  const examples = await declarationsCheck(tsc);
  return { code: fail + examples.fail ? 1 : 0, pass: pass + examples.pass, fail: fail + examples.fail, skip: 0 };
}

// `tsc --noEmit -p tsconfig.examples.json`: one pass per included file without an error.
async function declarationsCheck(tsc) {
  const config = JSON.parse(fs.readFileSync(path.join(repoRoot, 'tsconfig.examples.json'), 'utf8'));
  const files = config.include.flatMap((pattern) => globFiles(pattern));
  const r = await capture(process.execPath, [tsc, '--noEmit', '--pretty', 'false', '-p', 'tsconfig.examples.json'], { echo: true });
  const withErrors = new Set([...r.stdout.matchAll(/^(\S[^(\n]*)\(\d+,\d+\): error/gm)].map((m) => m[1]));
  const fail = withErrors.size + (r.code !== 0 && withErrors.size === 0 ? 1 : 0);
  return { pass: files.filter((f) => !withErrors.has(f)).length, fail };
}

// The files a jsconfig include pattern names ('dir/*.js', 'dir/*/name.js'), relative, sorted.
function globFiles(pattern) {
  const parts = pattern.split('/');
  let found = [''];
  for (const part of parts) {
    const re = new RegExp(`^${part.replace(/[.]/g, '\\.').replace(/\*/g, '[^/]*')}$`);
    found = found.flatMap((dir) => {
      const full = path.join(repoRoot, dir);
      if (!fs.existsSync(full) || !fs.statSync(full).isDirectory()) return [];
      return fs.readdirSync(full).filter((name) => re.test(name)).map((name) => (dir ? `${dir}/${name}` : name));
    });
  }
  return found.sort();
}

export const layers = [
  { name: 'types', run: typesLayer },
  // The project scripts themselves: how a node:test layer is counted (tests/scripts).
  { name: 'scripts', run: () => nodeTests('tests/scripts') },
  { name: 'native', run: nativeLayer },
  // The wasm layer also loads the bench module (the benchmark's hooks, tested there).
  { name: 'wasm', run: async () => { await buildWasm({ bench: true }); return nodeTests('tests/wasm'); } },
  { name: 'lessons', run: () => nodeTests('tests/lessons') },
  // Npm pack -> install in an empty folder -> import in Node and in a page; the
  // examples/ scripts; npm start's HOST (tests/package).
  { name: 'package', run: () => nodeTests('tests/package') },
  // Two browser files at once: on the 2-core machines the layer takes about half the time
  // (each file waits on its page most of the time); see docs/architecture.md, "Tests".
  // One site and one Chromium for the whole layer (tests/helpers/browser.mjs): each file
  // connects to them instead of starting its own.
  { name: 'browser', run: () => browserLayer() },
  { name: 'asan', run: asanLayer },
  { name: 'fuzz', run: () => fuzzLayer() },
];
