// Checking the imported mesh of a state (a million faces) must not copy it. A list
// whose entries are all clean comes back as itself (nothing allocated per face), a list with
// an entry that cleans to something else is copied, and a refusal still names the entry's
// full path.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { list, integer, object, number, text, nullable, validatePartial, SchemaError } from '../../../web/js/app/schema.js';

const faces = list(list(integer({ min: 0, max: 99 }), { min: 3, max: 8 }), { max: 100000 });

test('a list of clean entries is returned as it is, at every depth', () => {
  const value = Array.from({ length: 1000 }, (_, f) => [f % 100, (f + 1) % 100, (f + 2) % 100]);
  const clean = faces(value, 'imported.faces');
  assert.equal(clean, value);
  assert.equal(clean[517], value[517]);
});

test('a list whose entries clean to new values (objects drop unknown keys) is a copy, entries in order', () => {
  const moved = list(object({ v: integer(), p: list(number(), { min: 3, max: 3 }) }));
  const value = [{ v: 1, p: [0, 0, 0], extra: true }, { v: 2, p: [1, 2, 3] }];
  const clean = moved(value, 'moved');
  assert.notEqual(clean, value);
  assert.deepEqual(clean, [{ v: 1, p: [0, 0, 0] }, { v: 2, p: [1, 2, 3] }]);
  assert.equal(clean[0].p, value[0].p, 'a clean inner list is shared');
});

test('a bad entry deep in a big list is named by its full path', () => {
  const value = Array.from({ length: 5000 }, () => [0, 1, 2]);
  value[4321] = [0, 1, 2.5];
  assert.throws(() => faces(value, 'imported.faces'), (err) => {
    assert.ok(err instanceof SchemaError);
    assert.equal(err.path, 'imported.faces[4321][2]');
    assert.match(err.message, /^imported\.faces\[4321\]\[2\] must be a whole number, not 2\.5$/);
    return true;
  });
  value[4321] = [0, 1];
  assert.throws(() => faces(value, 'imported.faces'), { path: 'imported.faces[4321]', message: 'imported.faces[4321] must have 3 to 8 entries, not 2' });
});

test('an object whose fields all come back as they are is returned itself; an extra key makes a copy without it', () => {
  const imported = object({ name: text({ maxLength: 120 }), positions: list(number(), { min: 9, max: 30 }), faces });
  const value = { name: 'tri.off', positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], faces: [[0, 1, 2]] };
  assert.equal(imported(value, 'imported'), value, 'so a mesh read back keeps its remembered hash (share-link contentCache)');
  const extra = { ...value, colour: 'red' };
  const clean = imported(extra, 'imported');
  assert.notEqual(clean, extra);
  assert.deepEqual(clean, value);
  const withOptional = object({ a: integer(), b: integer() }, { optional: ['b'] });
  const partial = { a: 1 };
  assert.equal(withOptional(partial, 'x'), partial);
  assert.deepEqual(withOptional({ a: 1, c: 2 }, 'x'), { a: 1 });
});

test('a state read back (validatePartial) keeps its imported mesh object, not a copy', () => {
  const shape = { imported: nullable(object({ name: text(), faces })), n: integer() };
  const raw = { imported: { name: 'a.off', faces: [[0, 1, 2]] }, n: 3 };
  const { state, problems } = validatePartial(shape, raw, { imported: null, n: 0 });
  assert.deepEqual(problems, []);
  assert.equal(state.imported, raw.imported);
});
