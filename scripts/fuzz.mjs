// Longer fuzzing sessions by hand (npm test runs a few seconds per target):
//   node scripts/fuzz.mjs                   every target, the default budget
//   node scripts/fuzz.mjs obj_reader 600    one target for ten minutes
// Anything found lands in test-results/fuzz/<target>/; turn it into a regression test in
// tests/native/files/test_*_corpus.cpp and add it to tests/fuzz/corpus/<target>/ as a seed.
import { buildFuzz, fuzzTargets, runFuzzTarget, defaultSecondsPerTarget } from './lib/fuzz.mjs';
import { log } from './lib/run.mjs';

const [only, secondsText] = process.argv.slice(2);
const seconds = secondsText ? Number.parseInt(secondsText, 10) : defaultSecondsPerTarget;
if (!Number.isInteger(seconds) || seconds < 1) {
  process.stderr.write(`[wingspline] the budget must be a whole number of seconds, not '${secondsText}'\n`);
  process.exit(1);
}
const targets = fuzzTargets();
if (only && !targets.includes(only)) {
  process.stderr.write(`[wingspline] no fuzz target '${only}'; there are: ${targets.join(', ')}\n`);
  process.exit(1);
}
try {
  await buildFuzz();
} catch (err) {
  process.stderr.write(`[wingspline] ${err.message}\n`);
  process.exit(1);
}
let failed = 0;
for (const name of only ? [only] : targets) {
  log(`fuzzing ${name} for ${seconds} s`);
  const r = await runFuzzTarget(name, seconds);
  if (!r.ok) {
    failed += 1;
    process.stdout.write(r.output.split('\n').slice(-60).join('\n') + '\n');
  }
  log(`${name}: ${r.ok ? 'no crash' : 'CRASH (reproducer under test-results/fuzz/' + name + '/)'}, ${r.runs} inputs`);
}
process.exit(failed > 0 ? 1 : 0);
