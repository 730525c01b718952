// Wasm benchmark harness (../shared/BENCH.md), the twin of tests/bench/native/bench.h:
// R >= 5 repetitions, one JSON line per task with min and median ns per work unit.
import { performance } from 'node:perf_hooks';

const filters = process.argv.slice(2).filter((a) => !a.startsWith('-'));

export function wants(task) {
  return filters.length === 0 || filters.some((f) => task.startsWith(f));
}

export function timeRuns(repetitions, body) {
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
