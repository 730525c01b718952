// The import worker's job (web/js/app/mesh-import-job.js) under Node, over the real
// core: a file over the byte limit is refused from its size without being read; an OFF file
// whose header is over the limits is refused from its first piece, the body left unread; a
// good file comes back as flat arrays equal to the core's own parse, with its imported value's
// JSON text (exactly share-link.js's) and SHA-256.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { loadWingspline } from 'wingspline';
import { importMeshFile, MAX_MESH_FILE_BYTES } from '../../../web/js/app/mesh-import-job.js';
import { flatImportedValue } from '../../../web/js/app/imported-mesh.js';
import { stringifyExact } from '../../../web/js/app/share-link.js';

const api = await loadWingspline();
const L = api.meshLimits;

test('a file over the byte limit is refused from its size, naming its size and the limit, unread', async () => {
  let opened = false;
  const file = { size: MAX_MESH_FILE_BYTES + 1, stream() { opened = true; throw new Error('read'); } };
  await assert.rejects(importMeshFile(api, /** @type {any} */ (file), { format: 'off', name: 'big.off' }), (err) => {
    assert.equal(err.code, 'too-large');
    assert.match(err.message, /256\.0 MB/, 'the file size');
    assert.match(err.message, /up to 256\.0 MB/, 'the limit');
    return true;
  });
  assert.equal(opened, false);
});

test('an OFF header over the face limit is refused from the first piece: most of the body is never read', async () => {
  const body = '0.5 0.25 0.125\n'.repeat(400000); // 6 MB
  const file = new Blob([`OFF\n3 ${L.maxFaces + 1} 0\n`, body]);
  const read = [];
  await assert.rejects(importMeshFile(api, file, { format: 'off', name: 'h.off', onProgress: (p) => { if (p.stage === 'reading') read.push(p.done); } }), (err) => {
    assert.equal(err.code, 'too-large');
    assert.equal(err.line, 2);
    assert.match(err.message, new RegExp(`${L.maxFaces + 1}`));
    return true;
  });
  assert.ok(Math.max(...read) < file.size / 4, `read ${Math.max(...read)} of ${file.size} bytes`);
});

test('a good OFF comes back as the core\'s own parse, with its problems and the exact JSON and SHA-256 of the imported value', async () => {
  const g = api.generateMesh('sphere', { slices: 40, stacks: 21, layout: 'csr' });
  const text = api.formatMesh(g, { format: 'off' });
  const stages = [];
  const r = await importMeshFile(api, new Blob([text]), { format: 'off', name: 'ball.off', onProgress: (p) => stages.push(p.stage) });
  const ref = api.parseMesh(text, { layout: 'csr' });
  assert.deepEqual([r.positions, r.faceOffsets, r.faceVertices], [ref.positions, ref.faceOffsets, ref.faceVertices]);
  assert.deepEqual(Array.from(r.positions), Array.from(g.positions), '%.17g round-trips');
  assert.deepEqual(r.problems, api.validateMesh(ref).problems);
  assert.deepEqual([...new Set(stages)], ['reading', 'parsing', 'checking']);
  // The content is the flat form (imported-mesh.js): sizes and corners as plain numbers.
  const value = flatImportedValue('ball.off', ref.positions, ref.faceOffsets, ref.faceVertices);
  assert.equal(value.faceSizes.length, 2 * 40 * 20);
  assert.deepEqual(value.faceVertices.slice(0, value.faceSizes[0]), Array.from(ref.faceVertices.subarray(ref.faceOffsets[0], ref.faceOffsets[1])));
  assert.deepEqual(value.faceVertices, Array.from(ref.faceVertices));
  const json = stringifyExact(value);
  assert.equal(r.content.json, json);
  assert.equal(r.content.chars, json.length);
  assert.equal(r.content.hash, `sha256-${createHash('sha256').update(json).digest('hex')}`);
});

test('a refused mesh (an edge shared by three faces) comes back with its errors and no content', async () => {
  const text = 'OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 1 0 4\n';
  const r = await importMeshFile(api, new Blob([text]), { format: 'off', name: 'bad.off' });
  assert.ok(r.problems.some((p) => p.severity === 'error'));
  assert.equal(r.content, null);
});
