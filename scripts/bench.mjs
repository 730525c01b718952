// npm run bench: every task of ../shared/BENCH.md, native and wasm (and the interaction
// tasks in headless Chromium). Each benchmark program prints JSON lines; this script
// echoes them, then writes bench-results/latest.jsonl and a Markdown table
// bench-results/latest.md. Timings are never asserted anywhere.
//   npm run bench                 everything
//   npm run bench -- mesh curve   only tasks whose name starts with one of these words
import fs from 'node:fs';
import path from 'node:path';
import { setup } from './setup.mjs';
import { build } from './build.mjs';
import { repoRoot, log, capture } from './lib/run.mjs';

const filters = process.argv.slice(2);
await setup();
await build();

const programs = [];
const nativeBench = path.join(repoRoot, 'build', 'native', 'wingspline_bench');
if (fs.existsSync(nativeBench)) programs.push([nativeBench, []]);
for (const dir of ['tests/bench/wasm', 'tests/bench/browser']) {
  const full = path.join(repoRoot, dir);
  if (!fs.existsSync(full)) continue;
  for (const f of fs.readdirSync(full).filter((f) => f.endsWith('.bench.mjs')).sort()) {
    programs.push([process.execPath, [path.join(full, f)]]);
  }
}

const rows = [];
for (const [cmd, args] of programs) {
  log(`running ${path.relative(repoRoot, args[0] ?? cmd)}`);
  const r = await capture(cmd, [...args, ...filters], { env: { ...process.env, WINGSPLINE_BENCH_FILTER: filters.join(',') } });
  for (const line of r.stdout.split('\n')) {
    if (!line.startsWith('{')) continue;
    try {
      const row = JSON.parse(line);
      if (filters.length && !filters.some((f) => row.task.startsWith(f))) continue;
      rows.push(row);
      process.stdout.write(line + '\n');
    } catch { /* not a result line */ }
  }
  if (r.code !== 0) process.stderr.write(`[wingspline] ${cmd} exited with ${r.code}\n${r.stderr}\n`);
}

const outDir = path.join(repoRoot, 'bench-results');
fs.mkdirSync(outDir, { recursive: true });
fs.writeFileSync(path.join(outDir, 'latest.jsonl'), rows.map((r) => JSON.stringify(r)).join('\n') + '\n');
const fmt = (x) => (typeof x === 'number' ? (Math.abs(x) >= 100 ? x.toFixed(0) : x.toPrecision(3)) : (x ?? ''));
const table = ['| task | build | input | n | min | median | unit |', '| --- | --- | --- | ---: | ---: | ---: | --- |',
  ...rows.map((r) => `| ${r.task} | ${r.build} | ${r.input ?? ''} | ${r.n ?? ''} | ${fmt(r.ns_per_unit_min ?? r.min)} | ` +
    `${fmt(r.ns_per_unit_median ?? r.median)} | ${r.unit ?? 'ns/unit'} |`)];
fs.writeFileSync(path.join(outDir, 'latest.md'), table.join('\n') + '\n');
log(`${rows.length} results; table in bench-results/latest.md`);
