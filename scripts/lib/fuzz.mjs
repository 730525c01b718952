// The libFuzzer layer: build/fuzz holds one executable per tests/fuzz/fuzz_<name>.cpp,
// compiled with Debian's clang++-14 and -fsanitize=fuzzer,address,undefined (a separate
// CMake project, tests/fuzz/CMakeLists.txt, because the main build uses g++).
//
// Each target runs for a short fixed budget, starting from its checked-in seed corpus
// tests/fuzz/corpus/<name>/ (read only: new inputs go to a scratch folder under
// build/fuzz/work/, so a test run never changes the repository). A crash, a sanitizer report,
// a leak or a timeout fails the layer and leaves the reproducer under test-results/fuzz/;
// it then becomes a regression test (tests/native/files/test_*_corpus.cpp) and a seed.
//
//   node scripts/fuzz.mjs                 every target, the default budget
//   node scripts/fuzz.mjs off_reader 300  one target for five minutes (a longer local session)
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot, log, must, capture } from './run.mjs';
import { withBuildLock } from './build-lock.mjs';

export const fuzzSource = path.join(repoRoot, 'tests', 'fuzz');
export const fuzzBuild = path.join(repoRoot, 'build', 'fuzz');

// Seconds of fuzzing per target inside npm test. Six targets x 6 s keeps the layer well
// under a minute on two cores; longer sessions are for scripts/fuzz.mjs by hand.
export const defaultSecondsPerTarget = 6;

export function fuzzTargets() {
  return fs.readdirSync(fuzzSource)
    .filter((f) => /^fuzz_[a-z0-9_]+\.cpp$/.test(f))
    .map((f) => f.slice('fuzz_'.length, -'.cpp'.length))
    .sort();
}

export function buildFuzz() {
  return withBuildLock('fuzz', async () => {
    if (!fs.existsSync(path.join(fuzzBuild, 'CMakeCache.txt'))) {
      log('configuring build/fuzz (clang++-14, libFuzzer + ASan + UBSan)');
      await must('cmake', ['-S', fuzzSource, '-B', fuzzBuild, '-DCMAKE_CXX_COMPILER=clang++-14',
        '-DCMAKE_BUILD_TYPE=RelWithDebInfo']);
    }
    log('building build/fuzz');
    await must('cmake', ['--build', fuzzBuild, '-j', '2']);
  });
}

// Runs one target; resolves to { name, ok, runs, output }.
export async function runFuzzTarget(name, seconds = defaultSecondsPerTarget) {
  const seeds = path.join(fuzzSource, 'corpus', name);
  const work = path.join(fuzzBuild, 'work', name);
  const artifacts = path.join(repoRoot, 'test-results', 'fuzz', name);
  fs.rmSync(work, { recursive: true, force: true });
  fs.mkdirSync(work, { recursive: true });
  fs.mkdirSync(artifacts, { recursive: true });
  const args = [
    `-max_total_time=${seconds}`,
    '-timeout=10',              // one input taking 10 s is a hang, reported as a crash
    '-rss_limit_mb=2048',
    '-malloc_limit_mb=1024',    // one allocation above 1 GB is a bug (e.g. an unchecked count)
    '-max_len=65536',
    '-print_final_stats=1',
    `-artifact_prefix=${artifacts}${path.sep}`,
    work,                       // first folder: where new inputs are written
    ...(fs.existsSync(seeds) ? [seeds] : []),
  ];
  const r = await capture(path.join(fuzzBuild, `fuzz_${name}`), args,
    { env: { ...process.env, ASAN_OPTIONS: 'detect_leaks=1', UBSAN_OPTIONS: 'print_stacktrace=1' } });
  const runs = Number((r.stderr.match(/stat::number_of_executed_units:\s*(\d+)/) ?? [0, 0])[1]);
  return { name, ok: r.code === 0, runs, output: r.stderr };
}

// The test layer: { code, pass, fail, skip }, one test per target.
export async function fuzzLayer({ seconds = defaultSecondsPerTarget } = {}) {
  await buildFuzz();
  let pass = 0;
  let fail = 0;
  for (const name of fuzzTargets()) {
    const r = await runFuzzTarget(name, seconds);
    if (r.ok && r.runs > 0) {
      pass += 1;
      process.stdout.write(`ok - fuzz ${name}: ${r.runs} inputs in ${seconds} s, no crash\n`);
    } else {
      fail += 1;
      process.stdout.write(`not ok - fuzz ${name}\n${r.output.split('\n').slice(-60).join('\n')}\n` +
        `reproducer under test-results/fuzz/${name}/; run it with build/fuzz/fuzz_${name} <file>\n`);
    }
  }
  return { code: fail > 0 ? 1 : 0, pass, fail, skip: 0 };
}
