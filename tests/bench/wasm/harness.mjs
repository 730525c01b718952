// Wasm benchmark harness (docs/benchmarks.md), the twin of tests/bench/native/bench.h:
// R >= 5 repetitions, one JSON line per task with min and median ns per work unit.
import { performance } from 'node:perf_hooks';

const filters = process.argv.slice(2).filter((a) => !a.startsWith('-'));

export function wants(task) {
  return filters.length === 0 || filters.some((f) => task.startsWith(f));
}

// V8 compiles wasm in two tiers: the first calls run baseline (Liftoff) code while the
// optimised (TurboFan) code is compiled in the background. Native code has no such start,
// so every task first runs untimed until the steady state (>= 2 calls and >= 0.3 s).
// body(r) gets the repetition index, -1 during the warm-up (fold checksums only for r >= 0).
export const WARM_UP_SECONDS = 0.3;

export function timeRuns(repetitions, body, { warmUp = true } = {}) {
  const warmStart = performance.now();
  for (let w = 0; warmUp && (w < 2 || performance.now() - warmStart < WARM_UP_SECONDS * 1000); w += 1) body(-1);
  const seconds = [];
  for (let r = 0; r < repetitions; r += 1) {
    const t0 = performance.now();
    body(r);
    seconds.push((performance.now() - t0) / 1000);
  }
  return seconds;
}

export function report({ task, input, n, seconds, checksum, unit = 'ns', build = 'wasm', ...extra }) {
  const sorted = [...seconds].sort((a, b) => a - b);
  const scale = unit === 'ns' ? 1e9 : 1;
  const row = {
    task, build, input, n, repetitions: sorted.length,
    ns_per_unit_min: (sorted[0] * scale) / n,
    ns_per_unit_median: (sorted[Math.floor(sorted.length / 2)] * scale) / n,
    checksum, ...(unit === 'ns' ? {} : { unit }), ...extra,
  };
  process.stdout.write(JSON.stringify(row) + '\n');
  return row;
}
