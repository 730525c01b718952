// npm run bench: every task of docs/benchmarks.md, native and wasm (and the interaction
// tasks in headless Chromium). Each benchmark program prints JSON lines; this script
// echoes them, then writes bench-results/latest.jsonl and a Markdown table
// bench-results/latest.md. Timings are never asserted anywhere.
//   npm run bench                 everything
//   npm run bench -- mesh curve   only tasks whose name starts with one of these words
//   npm run bench -- --table      only rewrite latest.md from latest.jsonl (no measuring)
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { setup } from './setup.mjs';
import { build, buildNative, buildWasm } from './build.mjs';
import { repoRoot, log, capture, quiet } from './lib/run.mjs';
import { expectedTasks, referenceFor, nativeTwin, missingTasks } from './lib/bench-tasks.mjs';

const tableOnly = process.argv.includes('--table');
const filters = process.argv.slice(2).filter((a) => !a.startsWith('--'));
const outDir = path.join(repoRoot, 'bench-results');
if (!tableOnly) {
  await setup();
  await build();
  await buildNative(); // the native benchmark (build() makes only what serving needs)
  await buildWasm({ bench: true }); // the bench module: the shipped bindings plus core/bench
}

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

const rows = tableOnly
  ? fs.readFileSync(path.join(outDir, 'latest.jsonl'), 'utf8').split('\n').filter(Boolean).map((l) => JSON.parse(l))
  : [];
for (const [cmd, args] of tableOnly ? [] : programs) {
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

fs.mkdirSync(outDir, { recursive: true });
if (!tableOnly) fs.writeFileSync(path.join(outDir, 'latest.jsonl'), rows.map((r) => JSON.stringify(r)).join('\n') + '\n');
const fmt = (x) => (typeof x === 'number' ? (Math.abs(x) >= 100 ? x.toFixed(0) : x.toPrecision(3)) : (x ?? ''));
// Where and what was measured, so a figure can be reproduced and compared honestly (kept
// next to the results, so --table reports the run, not the moment the table is written).
const metaFile = path.join(outDir, 'latest-meta.json');
if (!tableOnly) {
  fs.writeFileSync(metaFile, JSON.stringify({
    when: new Date().toISOString().slice(0, 16).replace('T', ' '),
    machine: `${os.cpus()[0]?.model ?? 'unknown CPU'}, ${os.cpus().length} cores, load ${os.loadavg()[0].toFixed(1)} at the end`,
    node: process.versions.node,
    commit: quiet('git', ['-C', repoRoot, 'rev-parse', '--short', 'HEAD']).stdout.trim() || 'unknown',
    command: `npm run bench${filters.length ? ' -- ' + filters.join(' ') : ''}`,
  }) + '\n');
}
const meta = fs.existsSync(metaFile) ? JSON.parse(fs.readFileSync(metaFile, 'utf8')) : {};
const header = [
  `Measured ${meta.when ?? '(unknown time)'} UTC on ${meta.machine ?? 'an unknown machine'}; Node ${meta.node ?? '?'};` +
  ` commit ${meta.commit ?? 'unknown'}; command \`${meta.command ?? 'npm run bench'}\`.`,
  'Figures are per work unit (ns unless the unit says otherwise); min and median over the repetitions.',
  '"ref" is the other library\'s figure from docs/benchmarks.md for the same task and build (orientation only: it was',
  'measured in another run); "x ref" = min / ref; "wasm / native" = the wasm min over the native min of the',
  'same task and input in this run (`_core` rows: the same work timed inside the module).',
  '',
];
const table = ['| task | build | input | n | min | median | unit | ref | x ref | wasm / native |',
  '| --- | --- | --- | ---: | ---: | ---: | --- | ---: | ---: | ---: |',
  ...rows.map((r) => {
    const min = r.ns_per_unit_min ?? r.min;
    const ref = referenceFor(r);
    return `| ${r.task} | ${r.build} | ${r.input ?? ''} | ${r.n ?? ''} | ${fmt(min)} | ` +
      `${fmt(r.ns_per_unit_median ?? r.median)} | ${r.unit ?? 'ns/unit'} | ${ref ? `${fmt(ref.value)} (${ref.label})` : ''} | ` +
      `${ref && typeof min === 'number' ? (min / ref.value).toFixed(2) : ''} | ` +
      `${(() => { const twin = nativeTwin(r, rows); const m = twin?.ns_per_unit_min; return m ? (min / m).toFixed(2) : ''; })()} |`;
  })];
// Every task of docs/benchmarks.md must appear; a filter run only checks the tasks it asked for.
const wanted = filters.length ? expectedTasks.filter((t) => filters.some((f) => t.task.startsWith(f))) : expectedTasks;
const missing = missingTasks(rows).filter((m) => wanted.some((w) => w.task === m.task && w.build === m.build));
const missingText = missing.length
  ? ['', `Missing (no program produced them): ${missing.map((m) => `${m.task} (${m.build})`).join(', ')}.`]
  : ['', 'Every task of docs/benchmarks.md ran.'];
fs.writeFileSync(path.join(outDir, 'latest.md'), [...header, ...table, ...missingText].join('\n') + '\n');
log(`${rows.length} results; table in bench-results/latest.md`);
if (missing.length) {
  process.stderr.write(`[wingspline] missing benchmark tasks: ${missing.map((m) => `${m.task} (${m.build})`).join(', ')}\n`);
  process.exitCode = 1;
}
