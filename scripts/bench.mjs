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
import os from 'node:os';
import { repoRoot, log, capture, quiet } from './lib/run.mjs';
import { expectedTasks, referenceFor, missingTasks } from './lib/bench-tasks.mjs';

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
// Where and what was measured, so a figure can be reproduced and compared honestly.
const commit = quiet('git', ['-C', repoRoot, 'rev-parse', '--short', 'HEAD']).stdout.trim();
const machine = `${os.cpus()[0]?.model ?? 'unknown CPU'}, ${os.cpus().length} cores, load ${os.loadavg()[0].toFixed(1)}`;
const header = [
  `Measured ${new Date().toISOString().slice(0, 16).replace('T', ' ')} UTC on ${machine}; Node ${process.versions.node};` +
  ` commit ${commit || 'unknown'}; command \`npm run bench${filters.length ? ' -- ' + filters.join(' ') : ''}\`.`,
  'Figures are per work unit (ns unless the unit says otherwise); min and median over the repetitions.',
  '"ref" is the other library\'s figure from BENCH.md for the same task (orientation only: it was measured',
  'in another run); "x ref" = min / ref.',
  '',
];
const table = ['| task | build | input | n | min | median | unit | ref | x ref |',
  '| --- | --- | --- | ---: | ---: | ---: | --- | ---: | ---: |',
  ...rows.map((r) => {
    const min = r.ns_per_unit_min ?? r.min;
    const ref = referenceFor(r);
    return `| ${r.task} | ${r.build} | ${r.input ?? ''} | ${r.n ?? ''} | ${fmt(min)} | ` +
      `${fmt(r.ns_per_unit_median ?? r.median)} | ${r.unit ?? 'ns/unit'} | ${ref ? `${fmt(ref.value)} (${ref.label})` : ''} | ` +
      `${ref && typeof min === 'number' ? (min / ref.value).toFixed(2) : ''} |`;
  })];
// Every task of BENCH.md must appear; a filter run only checks the tasks it asked for.
const wanted = filters.length ? expectedTasks.filter((t) => filters.some((f) => t.task.startsWith(f))) : expectedTasks;
const missing = missingTasks(rows).filter((m) => wanted.some((w) => w.task === m.task && w.build === m.build));
const missingText = missing.length
  ? ['', `Missing (no program produced them): ${missing.map((m) => `${m.task} (${m.build})`).join(', ')}.`]
  : ['', 'Every task of BENCH.md ran.'];
fs.writeFileSync(path.join(outDir, 'latest.md'), [...header, ...table, ...missingText].join('\n') + '\n');
log(`${rows.length} results; table in bench-results/latest.md`);
if (missing.length) {
  process.stderr.write(`[wingspline] missing benchmark tasks: ${missing.map((m) => `${m.task} (${m.build})`).join(', ')}\n`);
  process.exitCode = 1;
}
