// A file over the import limits is refused before it is copied
// into the wasm memory, so refusing it neither takes seconds nor leaves hundreds of MB
// allocated (wasm memory never shrinks). Its own file: node --test runs each file in its
// own process, so the memory figures are this test's alone. The measure is the work done,
// not the wall time: the linear memory must not grow at all, and malloc's bytes in use
// must come back to where they were.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();

const L = api.meshLimits;

// About 55 MB of OFF: a header announcing twice the limit of vertices and faces, then
// vertex lines (the file is refused from its header; the rest is there to be big).
function overLimitOff() {
  const line = '0.123456 0.654321 0.111111\n';
  return `OFF\n${2 * L.maxVertices} ${2 * L.maxFaces} 0\n${line.repeat(Math.ceil((55 * 2 ** 20) / line.length))}`;
}

// At least 55 MB of OBJ with more vertices than the limit (OBJ has no header: refused at
// the first vertex over the limit, after reading only that far).
function overLimitObj() {
  const line = 'v 0.123456 0.654321 0.111111\n';
  return line.repeat(Math.max(Math.ceil((55 * 2 ** 20) / line.length), L.maxVertices + 1)) + 'f 1 2 3\n';
}

for (const [format, make, code, line] of [['off', overLimitOff, 'too-large', 2], ['obj', overLimitObj, 'too-large', L.maxVertices + 1]]) {
  test(`a 55 MB ${format.toUpperCase()} over the import limits is refused with a clear code, and the wasm memory does not grow`, () => {
    const text = make();
    assert.ok(text.length > 55 * 2 ** 20);
    api.parseMesh('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'); // first-use allocations
    const before = api.memoryUsage();
    assert.throws(() => api.parseMesh(text, { format }), (err) => {
      assert.equal(err.code, code);
      assert.equal(err.line, line);
      assert.match(err.message, new RegExp(String(L.maxVertices)), 'names the limit');
      assert.match(err.message, new RegExp(`${format === 'off' ? 2 * L.maxVertices : L.maxVertices + 1} vertices`), 'names the count');
      return true;
    });
    const after = api.memoryUsage();
    assert.equal(after.linearBytes, before.linearBytes, `wasm memory grew by ${(after.linearBytes - before.linearBytes) / 2 ** 20} MB`);
    assert.ok(Math.abs(after.heapInUse - before.heapInUse) < 4096, `heap in use changed by ${after.heapInUse - before.heapInUse} bytes`);
  });
}
