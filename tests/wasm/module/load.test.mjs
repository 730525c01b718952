// The package entry loads the wasm core in Node and answers.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from 'wingspline';

const pkg = JSON.parse(fs.readFileSync(new URL('../../../package.json', import.meta.url), 'utf8'));

test('loadWingspline resolves to the API object with the package version', async () => {
  const api = await loadWingspline();
  assert.equal(api.version, pkg.version);
  assert.equal(await loadWingspline(), api, 'the module is loaded once');
});

test('the Hermite matrix is the inverse of the lecture 000 constraint matrix', async () => {
  const api = await loadWingspline();
  const { constraints, matrix } = api.hermiteFromConstraints();
  // constraints . M_H = I (row-major 4x4)
  for (let i = 0; i < 4; i += 1) {
    for (let j = 0; j < 4; j += 1) {
      let s = 0;
      for (let k = 0; k < 4; k += 1) s += constraints[4 * i + k] * matrix[4 * k + j];
      assert.ok(Math.abs(s - (i === j ? 1 : 0)) < 1e-14, `entry ${i},${j} of A.M_H is ${s}`);
    }
  }
  assert.deepEqual(Array.from(api.basisMatrix('hermite')), [2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0]);
});

test('an unknown basis is an Error with a code, and the module keeps working', async () => {
  const api = await loadWingspline();
  for (let i = 0; i < 1000; i += 1) {
    assert.throws(() => api.basisMatrix('bezir'), (err) => err.code === 'unknown-basis' && /bezir/.test(err.message));
  }
  assert.equal(api.basisMatrix('bezier')[0], -1);
});
