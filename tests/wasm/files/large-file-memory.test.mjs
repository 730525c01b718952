// Reading a large mesh file must cost about the file and the face set, not a string per
// number: a 61 MB OFF once grew the wasm memory by 435 MB. Its own file, so that the
// module is fresh (node --test runs each file in its own process) and the growth of the
// linear memory is this parse's alone.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();

// An n x n grid of quads, two triangles each, written as OFF with 6 decimals (docs/benchmarks.md style).
function gridOff(n) {
  const lines = ['OFF', `${(n + 1) ** 2} ${2 * n * n} 0`];
  for (let j = 0; j <= n; j += 1) {
    for (let i = 0; i <= n; i += 1) {
      lines.push(`${(i / n).toFixed(6)} ${(j / n).toFixed(6)} ${(0.1 * Math.sin(i) * Math.cos(j)).toFixed(6)}`);
    }
  }
  const v = (i, j) => j * (n + 1) + i;
  for (let j = 0; j < n; j += 1) {
    for (let i = 0; i < n; i += 1) {
      lines.push(`3 ${v(i, j)} ${v(i + 1, j)} ${v(i + 1, j + 1)}`, `3 ${v(i, j)} ${v(i + 1, j + 1)} ${v(i, j + 1)}`);
    }
  }
  return lines.join('\n') + '\n';
}

test('parsing a 6 MB OFF grows the wasm memory by less than 2.5 times the file', () => {
  const n = 300;
  const text = gridOff(n);
  const before = api.memoryUsage();
  const mesh = api.parseMesh(text, { format: 'off', layout: 'csr' });
  const after = api.memoryUsage();
  // What was read is the file: every face, and the first and last coordinates.
  assert.equal(mesh.faceOffsets.length - 1, 2 * n * n);
  assert.equal(mesh.positions.length, 3 * (n + 1) ** 2);
  assert.deepEqual(Array.from(mesh.faceVertices.subarray(0, 3)), [0, 1, n + 2]);
  assert.equal(mesh.positions[mesh.positions.length - 3], 1);
  const growth = after.linearBytes - before.linearBytes;
  assert.ok(growth < 2.5 * text.length, `memory grew by ${(growth / 2 ** 20).toFixed(1)} MB for a ${(text.length / 2 ** 20).toFixed(1)} MB file`);
  // Nothing is left allocated once the arrays are out.
  assert.ok(after.heapInUse - before.heapInUse < 64 * 1024, `heap in use grew by ${after.heapInUse - before.heapInUse} bytes`);
});
