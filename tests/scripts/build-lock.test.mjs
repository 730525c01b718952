// Two project commands at once (npm start while npm test runs) must not write one build
// folder together: every CMake build and the site assembly runs inside withBuildLock
// (scripts/lib/build-lock.mjs). Here the build is a tiny fake step that records when it
// starts and ends, run by separate Node processes as two commands would be, against a
// lock folder of the test's own (build/ is never touched).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawn, spawnSync } from 'node:child_process';
import { pathToFileURL } from 'node:url';
import { withBuildLock } from '../../scripts/lib/build-lock.mjs';

const lockModule = pathToFileURL(path.resolve(import.meta.dirname, '../../scripts/lib/build-lock.mjs')).href;
// How long the fake step holds the lock, and how often a waiting command looks again (ms):
// long enough that two unlocked steps started together would surely overlap.
const STEP_MS = 400;
const POLL_MS = 20;

// One "command": says it is ready and waits for the go file (so that the commands ask at
// the same moment however slowly each Node starts), asks for the lock, then appends
// `start <pid> <ms>` and `end <pid> <ms>` to the log around STEP_MS of work (and `ask` when
// it asked); prints what the lock said while it waited.
const COMMAND = `
import fs from 'node:fs';
import { withBuildLock } from ${JSON.stringify(lockModule)};
const [dir, log, go] = process.argv.slice(2);
const stamp = (what) => fs.appendFileSync(log, \`\${what} \${process.pid} \${performance.timeOrigin + performance.now()}\\n\`);
fs.writeFileSync(\`\${go}.\${process.pid}\`, '');
while (!fs.existsSync(go)) await new Promise((resolve) => setTimeout(resolve, 5));
stamp('ask');
await withBuildLock('fake', async () => {
  stamp('start');
  await new Promise((resolve) => setTimeout(resolve, ${STEP_MS}));
  stamp('end');
}, { dir, pollMs: ${POLL_MS}, say: (text) => console.log(text) });
`;

function tempDir(t) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-lock-'));
  t.after(() => fs.rmSync(dir, { recursive: true, force: true }));
  return dir;
}

function runCommand(script, dir, log, go) {
  return new Promise((resolve, reject) => {
    const child = spawn(process.execPath, [script, dir, log, go], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    child.stdout.on('data', (d) => { out += d; });
    child.stderr.on('data', (d) => { out += d; });
    child.on('error', reject);
    child.on('close', (code) => resolve({ code, out, pid: child.pid }));
  });
}

// Each command's { pid, ask, start, end } times, from the log.
function intervals(log) {
  const lines = fs.readFileSync(log, 'utf8').trim().split('\n').map((l) => l.split(' '));
  const byPid = new Map();
  for (const [what, pid, ms] of lines) {
    const entry = byPid.get(pid) ?? {};
    entry[what] = Number(ms);
    byPid.set(pid, entry);
  }
  return [...byPid].map(([pid, { ask, start, end }]) => ({ pid: Number(pid), ask, start, end }));
}

test('two commands started together: the second waits, says whose build it waits for, and the steps never overlap', async (t) => {
  const dir = tempDir(t);
  const script = path.join(dir, 'command.mjs');
  fs.writeFileSync(script, COMMAND);
  const log = path.join(dir, 'steps.log');
  const locks = path.join(dir, 'locks');
  const go = path.join(dir, 'go');
  const commands = [1, 2, 3].map(() => runCommand(script, locks, log, go));
  while (fs.readdirSync(dir).filter((f) => f.startsWith('go.')).length < commands.length) await new Promise((resolve) => setTimeout(resolve, 10));
  fs.writeFileSync(go, '');
  const runs = await Promise.all(commands);
  for (const r of runs) assert.equal(r.code, 0, r.out);
  const steps = intervals(log).sort((a, b) => a.start - b.start);
  assert.equal(steps.length, 3, fs.readFileSync(log, 'utf8'));
  for (const s of steps) assert.ok(s.end - s.start >= STEP_MS - 5, `a step ran its whole time: ${JSON.stringify(s)}`);
  for (let i = 1; i < steps.length; i++) {
    assert.ok(steps[i].start >= steps[i - 1].end, `step ${i + 1} began after step ${i} ended: ${JSON.stringify(steps)}`);
  }
  // A command that asked before the step ahead of it ended waited, and named a holder.
  const contended = steps.filter((s, i) => i > 0 && s.ask < steps[i - 1].end);
  assert.ok(contended.length >= 1, `the commands asked at once: ${JSON.stringify(steps)}`);
  for (const s of contended) {
    const out = runs.find((r) => r.pid === s.pid).out;
    const named = out.match(/waiting for another build \(pid (\d+)\) to finish/);
    assert.ok(named, `pid ${s.pid} said it waited:\n${out}`);
    assert.ok(steps.some((other) => other.pid === Number(named[1]) && other !== s), 'the pid named is another command\'s');
  }
  assert.deepEqual(fs.readdirSync(locks), [], 'no lock is left behind');
});

test('a lock left by a command that no longer runs is taken over at once', async (t) => {
  const dir = tempDir(t);
  const gone = spawnSync(process.execPath, ['-e', '']).pid; // a pid that has exited
  fs.writeFileSync(path.join(dir, 'fake.lock'), `${gone} left-behind\n`);
  const said = [];
  const started = Date.now();
  const result = await withBuildLock('fake', () => 'built', { dir, pollMs: POLL_MS, say: (text) => said.push(text) });
  assert.equal(result, 'built');
  assert.ok(Date.now() - started < 5000, 'no waiting for a dead holder');
  assert.match(said.join('\n'), new RegExp(`taking over the lock of pid ${gone}`));
  assert.doesNotMatch(said.join('\n'), /waiting for another build/);
  assert.deepEqual(fs.readdirSync(dir), [], 'the stale lock and the new one are both gone');
});

test('a lock held by a running command is waited for, not taken over', async (t) => {
  const dir = tempDir(t);
  // This test's own process is the running holder; another token stands for another command.
  fs.writeFileSync(path.join(dir, 'fake.lock'), `${process.pid} another-command\n`);
  const said = [];
  let done = false;
  const waiting = withBuildLock('fake', () => { done = true; }, { dir, pollMs: POLL_MS, say: (text) => said.push(text) });
  await new Promise((resolve) => setTimeout(resolve, 10 * POLL_MS));
  assert.equal(done, false, 'the step waits while the holder runs');
  assert.match(said.join('\n'), new RegExp(`waiting for another build \\(pid ${process.pid}\\) to finish`));
  fs.rmSync(path.join(dir, 'fake.lock')); // the holder finishes
  await waiting;
  assert.equal(done, true);
});

test('the lock is released when the step fails, and a step cannot wait on a lock it holds', async (t) => {
  const dir = tempDir(t);
  await assert.rejects(withBuildLock('fake', () => { throw new Error('cmake failed'); }, { dir }), /cmake failed/);
  assert.deepEqual(fs.readdirSync(dir), []);
  await assert.rejects(withBuildLock('fake', () => withBuildLock('fake', () => {}, { dir }), { dir }), /already locked by the step this one runs in/);
  assert.deepEqual(fs.readdirSync(dir), []);
  // Other outputs inside a locked step are fine (build() runs wasm, then dist).
  assert.equal(await withBuildLock('wasm', () => withBuildLock('dist', () => 'both', { dir }), { dir }), 'both');
});
