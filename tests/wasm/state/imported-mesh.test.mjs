// The imported mesh of a lesson state (web/js/app/imported-mesh.js): the flat form
// an import writes and the faces form older states hold are both read, checked field by
// field with messages naming the entry, and give the same face set to the core.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { importedMesh, importedCsr, importedFaceCount, flatImportedValue } from '../../../web/js/app/imported-mesh.js';

const check = importedMesh({ maxVertices: 10, maxFaces: 4, maxCorners: 5 });
const positions = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0];
const facesForm = { name: 'two.off', positions, faces: [[0, 1, 2, 3], [1, 4, 2]] };
const flatForm = { name: 'two.off', positions, faceSizes: [4, 3], faceVertices: [0, 1, 2, 3, 1, 4, 2] };

test('both forms are accepted and returned as they are; they give the same faces to the core', () => {
  assert.equal(check(facesForm, 'imported'), facesForm);
  assert.equal(check(flatForm, 'imported'), flatForm);
  const a = importedCsr(facesForm);
  const b = importedCsr(flatForm);
  assert.deepEqual(Array.from(a.faceOffsets), [0, 4, 7]);
  assert.deepEqual(Array.from(b.faceOffsets), [0, 4, 7]);
  assert.deepEqual(Array.from(a.faceVertices), Array.from(b.faceVertices));
  assert.deepEqual(Array.from(a.positions), positions);
  assert.equal(importedFaceCount(facesForm), 2);
  assert.equal(importedFaceCount(flatForm), 2);
  // What an import writes from the core's CSR arrays is the flat form above.
  assert.deepEqual(flatImportedValue('two.off', Float64Array.from(positions), Int32Array.from([0, 4, 7]), Int32Array.from([0, 1, 2, 3, 1, 4, 2])), flatForm);
  // Unknown keys are dropped (a copy without them), as the schema's objects do.
  assert.deepEqual(check({ ...flatForm, extra: 1 }, 'imported'), flatForm);
});

test('a damaged flat form is refused naming the entry and what was expected', () => {
  const refused = (value, path, message) => assert.throws(() => check(value, 'imported'), (err) => {
    assert.equal(err.path, path);
    assert.match(err.message, message);
    return true;
  });
  refused({ ...flatForm, faceSizes: [4, 2] }, 'imported.faceSizes[1]', /3 to 5, not 2/);
  refused({ ...flatForm, faceSizes: [4, 6] }, 'imported.faceSizes[1]', /3 to 5, not 6/);
  refused({ ...flatForm, faceSizes: [4, 3.5] }, 'imported.faceSizes[1]', /whole number/);
  refused({ ...flatForm, faceVertices: [0, 1, 2, 3, 1, 4] }, 'imported.faceVertices', /must have 7 entries .* not 6/);
  refused({ ...flatForm, faceVertices: [0, 1, 2, 3, 1, 10, 2] }, 'imported.faceVertices[5]', /between 0 and 9, not 10/);
  refused({ ...flatForm, faceVertices: [0, 1, 2, 3, 1, -1, 2] }, 'imported.faceVertices[5]', /between 0 and 9, not -1/);
  refused({ ...flatForm, faceSizes: [3, 3, 3, 3, 3] }, 'imported.faceSizes', /1 to 4 entries, not 5/);
  refused({ name: 'x.off', positions, faceVertices: [0, 1, 2] }, 'imported.faceSizes', /is missing/);
  refused({ ...flatForm, faceSizes: 'four' }, 'imported.faceSizes', /must be a list/);
  refused({ ...flatForm, positions: [0, 0, NaN, 1, 0, 0, 0, 1, 0] }, 'imported.positions[2]', /finite number/);
  refused({ ...facesForm, faces: [[0, 1]] }, 'imported.faces[0]', /3 to 5 entries/);
  refused(null, 'imported', /must be an object/);
});
