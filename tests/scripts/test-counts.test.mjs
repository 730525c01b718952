// npm test's count of a node:test layer (scripts/lib/test-layers.mjs, runNodeTests) is read
// from node:test's events, not from a reporter's text: Node 23 and later print the spec
// reporter by default even when piped, where Node 20 printed TAP's "# pass N". Each run
// below makes Node's default reporter something other than TAP (NODE_OPTIONS), over a small
// folder of tests whose results are known by construction, and the counts must be exact:
// skipped and todo tests are reported and never passes, a cancelled test is a failure.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { runNodeTests, withoutReporterOptions } from '../../scripts/lib/test-layers.mjs';

// Written as a person would count them:
//   mixed.test.mjs  passes: 'adds', 'outer' and its two subtests, 'in a suite' = 5
//                   (the suite itself is not a test); fails: 'wrong sum' = 1;
//                   cancelled: 'too slow' (timed out) = 1; skipped: 'not here' = 1;
//                   todo: 'later' (failing) and 'later, passing' = 2
//   other.test.mjs  passes: 'one more' = 1
const MIXED = `
import { test, describe, it } from 'node:test';
import assert from 'node:assert/strict';
test('adds', () => { assert.equal(1 + 1, 2); });
test('outer', async (t) => {
  await t.test('first subtest', () => {});
  await t.test('second subtest', () => {});
});
describe('a suite', () => { it('in a suite', () => {}); });
test('wrong sum', () => { assert.equal(1 + 1, 3); });
test('too slow', { timeout: 50 }, () => new Promise((resolve) => { setTimeout(resolve, 2000).unref(); }));
test('not here', { skip: 'skipped on purpose' }, () => { throw new Error('never runs'); });
test('later', { todo: 'not written yet' }, () => { throw new Error('a todo may fail'); });
test('later, passing', { todo: true }, () => {});
`;
const OTHER = `
import { test } from 'node:test';
test('one more', () => {});
`;
const ALL_PASS = `
import { test } from 'node:test';
test('a', () => {});
test('b', () => {});
test('c', { skip: true }, () => {});
`;

function folder(files) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-count-test-'));
  for (const [name, text] of Object.entries(files)) fs.writeFileSync(path.join(dir, name), text);
  return dir;
}

// Node's default reporter made something other than TAP, in each way NODE_OPTIONS allows.
const NOT_TAP = ['--test-reporter=spec', '--test-reporter=dot', '--test-reporter spec --test-reporter-destination stdout'];

for (const nodeOptions of NOT_TAP) {
  test(`mixed results are counted exactly with NODE_OPTIONS="${nodeOptions}"`, async () => {
    const dir = folder({ 'mixed.test.mjs': MIXED, 'other.test.mjs': OTHER });
    try {
      const r = await runNodeTests(['mixed.test.mjs', 'other.test.mjs'], {
        cwd: dir, echo: false, env: { ...process.env, NODE_OPTIONS: nodeOptions },
      });
      assert.deepEqual({ pass: r.pass, fail: r.fail, skip: r.skip }, { pass: 6, fail: 2, skip: 3 });
      assert.notEqual(r.code, 0);
    } finally {
      fs.rmSync(dir, { recursive: true, force: true });
    }
  });
}

test('a folder whose tests all pass exits 0, its skip reported and not a pass', async () => {
  const dir = folder({ 'all.test.mjs': ALL_PASS });
  try {
    const r = await runNodeTests(['all.test.mjs'], {
      cwd: dir, echo: false, env: { ...process.env, NODE_OPTIONS: '--test-reporter=spec' },
    });
    assert.deepEqual(r, { code: 0, pass: 2, fail: 0, skip: 1 });
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

test('a test file that throws while loading counts as one failure', async () => {
  const dir = folder({ 'broken.test.mjs': "throw new Error('broken on purpose');\n", 'other.test.mjs': OTHER });
  try {
    const r = await runNodeTests(['broken.test.mjs', 'other.test.mjs'], {
      cwd: dir, echo: false, env: { ...process.env, NODE_OPTIONS: '--test-reporter=spec' },
    });
    assert.deepEqual({ pass: r.pass, fail: r.fail, skip: r.skip }, { pass: 1, fail: 1, skip: 0 });
    assert.notEqual(r.code, 0);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

test('reporter options in NODE_OPTIONS are removed from the run, other options kept', () => {
  assert.equal(withoutReporterOptions('--test-reporter=spec --max-old-space-size=512'), '--max-old-space-size=512');
  assert.equal(withoutReporterOptions('--test-reporter spec --test-reporter-destination stdout --enable-source-maps'), '--enable-source-maps');
  assert.equal(withoutReporterOptions(undefined), '');
});
