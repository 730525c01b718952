// Import: the import limit is raised to the largest mesh a school laptop holds
// (docs/api-mesh.md, "Import limits and memory": 2,000,000 faces and vertices), and a file
// over it is refused from its OFF header, before the body is read.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();
const L = api.meshLimits;

test('the import limit holds a sphere of a million faces (docs/benchmarks.md sphere_1000000: 500,002 vertices)', () => {
  assert.ok(L.maxFaces >= 1000000, `maxFaces ${L.maxFaces}`);
  assert.ok(L.maxVertices >= 500002, `maxVertices ${L.maxVertices}`);
  // The header alone of sphere_1000000: within the limits, so the core reads on and finds
  // the body missing (truncated-file), where an over-limit header is refused as too-large.
  assert.throws(() => api.parseMesh('OFF\n500002 1000000 0\n'), (err) => err.code === 'truncated-file');
});

test('the page\'s limits (web/js/app/limits.js) are the core\'s raised ones', async () => {
  const limits = await import('../../../web/js/app/limits.js');
  assert.deepEqual([limits.MAX_MESH_VERTICES, limits.MAX_MESH_FACES], [L.maxVertices, L.maxFaces]);
});

for (const [what, header] of [['faces', (l) => `OFF\n3 ${l.maxFaces + 1} 0\n`], ['vertices', (l) => `OFF\n${l.maxVertices + 1} 1 0\n`]]) {
  test(`an OFF header with one more ${what} than the limit is refused from the header (too-large, line 2), the body unread`, () => {
    // The body is not an OFF body at all: reading it would be a parse-error on line 3.
    const text = `${header(L)}this is not a vertex line\n${'x y z\n'.repeat(1000)}`;
    assert.throws(() => api.parseMesh(text), (err) => {
      assert.equal(err.code, 'too-large');
      assert.equal(err.line, 2);
      const count = what === 'faces' ? L.maxFaces + 1 : L.maxVertices + 1;
      const limit = what === 'faces' ? L.maxFaces : L.maxVertices;
      assert.match(err.message, new RegExp(String(count)), 'names the count');
      assert.match(err.message, new RegExp(String(limit)), 'names the limit');
      return true;
    });
  });
}
