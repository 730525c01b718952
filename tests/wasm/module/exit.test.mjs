// A student's script must exit when its output goes to a file (issue "Nothing lost, ever"):
// tests/fixtures/scripts/subdivision-homework.mjs runs as a child process with stdout
// redirected to a file, six times, two at a time (as a class shares a machine), each with a
// timeout; it must exit by itself with code 0, its output complete and right.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const script = fileURLToPath(new URL('../../fixtures/scripts/subdivision-homework.mjs', import.meta.url));
const TIMEOUT_MS = 60000; // a run takes about a second; a script that does not exit never ends

// Runs the script with stdout written straight into `file` (the child's fd 1 is the file, as
// with `node script.mjs > file`); resolves to {code, signal, timedOut, stderr}.
function runToFile(file) {
  const fd = fs.openSync(file, 'w');
  try {
    const child = spawn(process.execPath, [script], { stdio: ['ignore', fd, 'pipe'] });
    let stderr = '';
    child.stderr.on('data', (d) => { stderr += d; });
    return new Promise((resolve) => {
      const timer = setTimeout(() => {
        child.kill('SIGKILL');
        resolve({ code: null, signal: 'SIGKILL', timedOut: true, stderr });
      }, TIMEOUT_MS);
      child.on('exit', (code, signal) => {
        clearTimeout(timer);
        resolve({ code, signal, timedOut: false, stderr });
      });
    });
  } finally {
    fs.closeSync(fd);
  }
}

// The faces of one level, from the input alone: Loop makes 4 triangles of each triangle;
// Catmull-Clark one quad per corner of each face, then 4 quads of each quad.
const faces = (scheme, F, corners, level) => (scheme === 'loop' ? F * 4 ** level : corners * 4 ** (level - 1));

test('a homework script that subdivides 16 meshes exits by itself with its output in a file (6 runs, 2 at a time)', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-exit-'));
  try {
    for (let round = 0; round < 3; round += 1) {
      const files = [0, 1].map((k) => path.join(dir, `run-${round}-${k}.txt`));
      const results = await Promise.all(files.map(runToFile));
      results.forEach((r, k) => {
        assert.equal(r.timedOut, false, `run ${2 * round + k + 1} had not exited after ${TIMEOUT_MS / 1000} s`);
        assert.deepEqual([r.code, r.signal, r.stderr], [0, null, ''], `run ${2 * round + k + 1}`);
        const lines = fs.readFileSync(files[k], 'utf8').trimEnd().split('\n');
        assert.equal(lines.at(-1), 'done: 16 meshes, 0 left undisposed');
        const levels = lines.slice(0, -1).map((l) => l.split('\t'));
        assert.equal(levels.length, 3 * (16 + 15), 'three levels of Catmull-Clark for every mesh, of Loop for the 15 triangle meshes');
        for (const [name, F, corners, scheme, level, stepFaces, fineFaces] of levels) {
          assert.equal(Number(stepFaces), faces(scheme, Number(F), Number(corners), 1), `${name} ${scheme} step`);
          assert.equal(Number(fineFaces), faces(scheme, Number(F), Number(corners), Number(level)), `${name} ${scheme} level ${level}`);
        }
      });
    }
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
