// One project command at a time per build output. `npm start` while `npm test` runs would
// otherwise run two CMake builds in one build folder (each rewriting the other's objects
// and its CMakeCache.txt) or mirror web/ into dist/ twice over each other. Every step that
// writes build/<name> or dist/ runs inside withBuildLock(name, step): a second command
// waits for the first, saying once "waiting for another build (pid N) to finish".
//
// The lock is the file build/locks/<name>.lock holding the holder's pid and a token of its
// own. It is made with link(2) from a file already written, so it never exists without its
// holder's pid (an exclusive create, then a write, would leave a window where it is empty).
// A lock whose holder is no longer running (a command killed mid-build: Ctrl+C, a closed
// terminal) is stale and taken over: renamed away (one rename wins when two commands find
// it at once), then made again. A lock is released only by its holder's own token.
import fs from 'node:fs';
import path from 'node:path';
import { AsyncLocalStorage } from 'node:async_hooks';
import { repoRoot, log } from './run.mjs';

export const locksDir = path.join(repoRoot, 'build', 'locks');

// How often a waiting command looks again. A CMake step takes seconds to minutes.
const POLL_MS = 500;

// The locks the current step runs inside: a step that asks again for a lock it already
// holds would wait for itself forever, so it is refused instead. (Two steps of one command
// that run side by side wait for each other like two commands.)
const held = new AsyncLocalStorage();

const sleep = (ms) => new Promise((resolve) => { setTimeout(resolve, ms); });
const uniqueSuffix = () => `${process.pid}.${Date.now().toString(36)}.${Math.random().toString(36).slice(2, 10)}`;

// Whether the lock's holder still runs. A pid the system has handed to another program since
// (on Linux: one that is not node) is not the holder.
function running(pid) {
  if (!Number.isInteger(pid) || pid <= 0) return false;
  try {
    process.kill(pid, 0);
  } catch (err) {
    return err.code === 'EPERM'; // it runs, as another user
  }
  try {
    return /node/.test(fs.readFileSync(`/proc/${pid}/cmdline`, 'utf8'));
  } catch {
    return true; // no /proc here: trust the signal
  }
}

// The lock's holder { pid, token }, or null when there is no lock (any more).
function holderOf(file) {
  let text;
  try {
    text = fs.readFileSync(file, 'utf8');
  } catch (err) {
    if (err.code === 'ENOENT') return null;
    throw err;
  }
  const [pid, token] = text.trim().split(/\s+/);
  return { pid: Number(pid), token: token ?? '' };
}

// Moves a stale lock away, unless another command took it over meanwhile and holds it now:
// a lock moved by mistake (its token is not the stale one) is put back at once.
function takeOver(file, stale) {
  const aside = `${file}.stale.${uniqueSuffix()}`;
  try {
    fs.renameSync(file, aside);
  } catch (err) {
    if (err.code === 'ENOENT') return; // another command moved it first
    throw err;
  }
  try {
    if (holderOf(aside)?.token !== stale.token) fs.linkSync(aside, file);
  } catch {
    // (a new lock already stands: its holder goes on)
  } finally {
    fs.rmSync(aside, { force: true });
  }
}

/**
 * Runs `step` while holding the lock on build output `name` ('native', 'wasm', 'dist', ...);
 * resolves to what `step` resolves to. The lock is released however the step ends.
 * @template T
 * @param {string} name
 * @param {() => Promise<T> | T} step
 * @param {{ dir?: string, pollMs?: number, say?: (text: string) => void }} [options]
 *   `dir`: where the lock files live (tests use a folder of their own); `say`: the waiting line
 * @returns {Promise<T>}
 */
export async function withBuildLock(name, step, { dir = locksDir, pollMs = POLL_MS, say = log } = {}) {
  fs.mkdirSync(dir, { recursive: true });
  const file = path.join(dir, `${name}.lock`);
  const outer = held.getStore() ?? [];
  if (outer.includes(file)) throw new Error(`build/${name} is already locked by the step this one runs in`);
  const token = uniqueSuffix();
  const written = path.join(dir, `${name}.lock.${token}.new`);
  fs.writeFileSync(written, `${process.pid} ${token}\n`);
  try {
    let waitingFor = null;
    for (;;) {
      try {
        fs.linkSync(written, file);
        break;
      } catch (err) {
        if (err.code !== 'EEXIST') throw err;
      }
      const holder = holderOf(file);
      if (holder === null) continue; // released just now
      if (!running(holder.pid)) {
        say(`build/${name}: taking over the lock of pid ${holder.pid}, which is no longer running`);
        takeOver(file, holder);
        continue;
      }
      if (waitingFor !== holder.pid) {
        say(`build/${name}: waiting for another build (pid ${holder.pid}) to finish`);
        waitingFor = holder.pid;
      }
      await sleep(pollMs);
    }
  } finally {
    fs.rmSync(written, { force: true });
  }
  try {
    return await held.run([...outer, file], step);
  } finally {
    if (holderOf(file)?.token === token) fs.rmSync(file, { force: true });
  }
}
