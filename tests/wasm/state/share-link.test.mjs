// Property test of the share-link decoder ("fuzzing ... the share-link decoder").
//
// Why not libFuzzer: the decoder is JavaScript (web/js/app/share-link.js: base64url ->
// deflate-raw -> UTF-8 -> JSON -> envelope -> migrations -> schema). libFuzzer drives C/C++
// only, and compiling the decoder's path into the wasm core would fuzz a different program
// from the one pages run. So this test feeds the real module, in Node 20 (which has
// CompressionStream, atob and Blob like the browser), with links generated from a fixed
// seed: valid links mutated byte by byte, truncated, spliced and re-encoded; random
// base64url text; and well-formed compressed JSON carrying hostile values (wrong types,
// huge and non-finite numbers, __proto__ keys, script-bearing strings, deep nesting).
//
// The property, for every input: decodeState either resolves to { state, problems } where
// `state` passes the lesson's full schema and `problems` are one-line sentences, or rejects
// with a plain Error whose message is one sentence. Nothing else may ever happen (no
// TypeError, no RangeError, no non-Error throw, no prototype pollution, no hang).
// The classroom branch's browser tests cover the page's reaction to a dozen named tampered
// links; this test covers the decoder's contract over thousands of generated ones.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { decodeState, encodeState } from '../../../web/js/app/share-link.js';
import { number, integer, boolean, oneOf, text, list, object, nullable } from '../../../web/js/app/schema.js';
import { random } from '../../helpers/seeded-random.mjs';

const SEED = 0x5eed2026;
const MUTATED_LINKS = 2500;
const RANDOM_LINKS = 800;
const HOSTILE_STATES = 600;
const MAX_MESSAGE_CHARS = 400; // one line a student reads in the message bar

// A deterministic generator (mulberry32), so a failure reproduces from the printed case.
const rng = random;

// A lesson shaped like the real ones (points, knots, weights, degree, flags, a label, the
// view), with a migration from version 1 and a cross-field rule, so every stage of the
// decoder is exercised.
const pointShape = object({ x: number(), y: number() });
const schema = {
  kind: oneOf('bezier', 'bspline', 'nurbs'),
  points: list(pointShape, { min: 2, max: 64 }),
  weights: list(number({ min: 1e-6, max: 1e6 }), { max: 64 }),
  knots: list(number(), { max: 80 }),
  degree: integer({ min: 1, max: 10 }),
  u: number({ min: 0, max: 1 }),
  showHull: boolean(),
  label: text({ maxLength: 80 }),
  view: object({ cx: number(), cy: number(), scale: number({ min: 1e-6, max: 1e6 }) }),
};
const fullSchema = object(schema);
const defaultState = () => ({
  kind: 'bspline',
  points: [{ x: 0, y: 0 }, { x: 1, y: 2 }, { x: 3, y: 2 }, { x: 4, y: 0 }],
  weights: [],
  knots: [],
  degree: 3,
  u: 0.5,
  showHull: true,
  label: 'start',
  view: { cx: 2, cy: 1, scale: 80 },
});
const lesson = {
  id: 'curves',
  title: 'Curve explorer',
  stateVersion: 2,
  schema,
  defaultState,
  // Version 1 called the label "name".
  migrations: { 1: (old) => ({ ...old, label: old.name }) },
  checkState: (s) => (s.degree >= s.points.length ? `degree ${s.degree} needs more than ${s.points.length} points` : null),
};

function randomState(next) {
  const n = 2 + Math.floor(next() * 10);
  const points = Array.from({ length: n }, () => ({ x: (next() - 0.5) * 10, y: (next() - 0.5) * 10 }));
  return {
    ...defaultState(),
    kind: ['bezier', 'bspline', 'nurbs'][Math.floor(next() * 3)],
    points,
    weights: points.map(() => 0.5 + next()),
    degree: 1 + Math.floor(next() * (n - 1)),
    u: next(),
    label: `curve ${Math.floor(next() * 1000)}`,
  };
}

const B64 = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_';

function mutate(link, next) {
  const chars = [...link];
  const op = Math.floor(next() * 7);
  const at = Math.floor(next() * chars.length);
  switch (op) {
    case 0: chars[at] = B64[Math.floor(next() * 64)]; break;                 // one character changed
    case 1: return link.slice(0, at);                                          // truncated
    case 2: chars.splice(at, 0, ...B64.slice(0, 1 + Math.floor(next() * 8))); break; // inserted
    case 3: chars.splice(at, 1 + Math.floor(next() * 20)); break;              // a piece removed
    case 4: return link + link.slice(0, at);                                   // spliced with itself
    case 5: chars[at] = String.fromCharCode(Math.floor(next() * 0x3000)); break; // outside the alphabet
    default: for (let k = 0; k < 4; k += 1) chars[Math.floor(next() * chars.length)] = B64[Math.floor(next() * 64)];
  }
  return chars.join('');
}

async function compress(json) {
  const stream = new Blob([new TextEncoder().encode(json)]).stream().pipeThrough(new CompressionStream('deflate-raw'));
  const bytes = new Uint8Array(await new Response(stream).arrayBuffer());
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

const hostileValues = [
  null, true, 0, -0, 1e308, -1e308, 5e-324, 2 ** 53 + 1, 'NaN', 'Infinity', '1e999', '',
  '<img src=x onerror="globalThis.__pwned=1">', '</script><script>globalThis.__pwned=1</script>',
  'javascript:globalThis.__pwned=1', '\u202e\u0000\ud800', [], {}, [[[[[[[[[[]]]]]]]]]],
  { __proto__: { polluted: true } }, 'x'.repeat(5000), Array(100000).fill(0),
];

// A JSON text with hostile values in random places of an otherwise plausible envelope.
function hostileJson(next) {
  const pick = () => hostileValues[Math.floor(next() * hostileValues.length)];
  const state = defaultState();
  const keys = Object.keys(state);
  for (let k = 0; k < 1 + Math.floor(next() * 3); k += 1) state[keys[Math.floor(next() * keys.length)]] = pick();
  if (next() < 0.3 && Array.isArray(state.points) && state.points.length > 0) state.points[Math.floor(next() * state.points.length)] = { x: pick(), y: pick() };
  if (next() < 0.2) state.view = { cx: pick(), cy: 0, scale: pick() };
  const env = { format: 'wingspline', lesson: 'curves', version: 2, state };
  const which = Math.floor(next() * 8);
  if (which === 0) env.format = pick();
  if (which === 1) env.lesson = pick();
  if (which === 2) env.version = [1, 2, 3, 0, -1, 1.5, 1e300, '2', null][Math.floor(next() * 9)];
  if (which === 3) env.state = pick();
  let json = JSON.stringify(env);
  // JSON.stringify cannot write these: splice them in as text, as a tampering person would.
  if (which === 4) json = json.replace('"u":0.5', `"u":${['NaN', '1e999', '-Infinity', '0x10', '.5'][Math.floor(next() * 5)]}`);
  if (which === 5) json = json.replace('{', '{"__proto__":{"polluted":true},"constructor":{"prototype":{"polluted":true}},');
  if (which === 6) json = json.slice(0, Math.floor(next() * json.length));
  return json;
}

function isOneSentence(message) {
  return typeof message === 'string' && message.length > 0 && message.length <= MAX_MESSAGE_CHARS &&
    !/[\r\n]/.test(message) && !/[.!?]\s+[A-Z]/.test(message);
}

// Decodes `link` and checks the property; returns 'state' or 'error' for the tallies.
async function checkDecoder(link, description) {
  let result;
  try {
    result = await decodeState(lesson, link);
  } catch (err) {
    assert.ok(err instanceof Error, `${description}: threw a non-Error ${String(err)}`);
    assert.equal(err.constructor, Error, `${description}: threw ${err.name} (${err.message}), not a plain Error`);
    assert.ok(isOneSentence(err.message), `${description}: the message is not one sentence: ${JSON.stringify(err.message)}`);
    return 'error';
  }
  assert.ok(result && typeof result === 'object', `${description}: resolved to ${String(result)}`);
  assert.doesNotThrow(() => fullSchema(result.state, ''), `${description}: the decoded state breaks the schema`);
  assert.equal(lesson.checkState(result.state), null, `${description}: the decoded state breaks the lesson's rule`);
  assert.ok(Array.isArray(result.problems), `${description}: problems is not a list`);
  for (const p of result.problems) assert.ok(isOneSentence(p), `${description}: a problem is not one sentence: ${JSON.stringify(p)}`);
  return 'state';
}

function assertNothingRan() {
  assert.equal(globalThis.__pwned, undefined, 'a string in a link was executed');
  assert.equal(Object.prototype.polluted, undefined, 'a link polluted Object.prototype');
  assert.equal({}.polluted, undefined, 'a link polluted Object.prototype');
}

test('valid links decode to exactly the state that was encoded (the generator is sound)', async () => {
  const next = rng(SEED);
  for (let i = 0; i < 50; i += 1) {
    const state = randomState(next);
    const { state: back, problems } = await decodeState(lesson, await encodeState(lesson, state));
    assert.deepEqual(problems, []);
    assert.deepEqual(back, state);
  }
});

test(`${MUTATED_LINKS} mutated links: a valid state or a one-sentence Error, nothing else`, async () => {
  const next = rng(SEED + 1);
  const tally = { state: 0, error: 0 };
  for (let i = 0; i < MUTATED_LINKS; i += 1) {
    const original = await encodeState(lesson, randomState(next));
    let link = mutate(original, next);
    if (next() < 0.3) link = mutate(link, next);
    tally[await checkDecoder(link, `mutated link #${i} ${JSON.stringify(link.slice(0, 120))}`)] += 1;
  }
  assertNothingRan();
  // Both outcomes must occur, or the mutations are not reaching the decoder's stages.
  assert.ok(tally.error > 0 && tally.state > 0, JSON.stringify(tally));
});

test(`${RANDOM_LINKS} random texts as links: a one-sentence Error or a valid state`, async () => {
  const next = rng(SEED + 2);
  for (let i = 0; i < RANDOM_LINKS; i += 1) {
    const length = Math.floor(next() ** 3 * 3000);
    const alphabet = next() < 0.8 ? B64 : B64 + '=+/%#&? \n"<>';
    let link = '';
    for (let k = 0; k < length; k += 1) link += alphabet[Math.floor(next() * alphabet.length)];
    await checkDecoder(link, `random link #${i} ${JSON.stringify(link.slice(0, 80))}`);
  }
  await assert.rejects(decodeState(lesson, 'A'.repeat(250000)), (err) => err.constructor === Error && isOneSentence(err.message));
  assertNothingRan();
});

test(`${HOSTILE_STATES} well-formed links carrying hostile values: the valid part is kept, the rest reported`, async () => {
  const next = rng(SEED + 3);
  const tally = { state: 0, error: 0 };
  for (let i = 0; i < HOSTILE_STATES; i += 1) {
    const json = hostileJson(next);
    tally[await checkDecoder(await compress(json), `hostile state #${i} ${json.slice(0, 160)}`)] += 1;
  }
  assertNothingRan();
  assert.ok(tally.state > 0 && tally.error > 0, `both outcomes occur: ${JSON.stringify(tally)}`);
});

test('a partly damaged link never yields a state that breaks a cross-field rule', async () => {
  // points is damaged (falls back to the 4 default points) while degree 5 is valid on its
  // own: keeping both would give a degree-5 curve on 4 points.
  const state = { ...defaultState(), points: 'not a list', degree: 5 };
  const link = await compress(JSON.stringify({ format: 'wingspline', lesson: 'curves', version: 2, state }));
  const kind = await checkDecoder(link, 'damaged points with a degree that needs more of them');
  assert.equal(kind, 'state');
});

test('an older link is migrated, and a migration that meets a malformed old state does not escape', async () => {
  const old = { ...defaultState(), name: 'from version 1' };
  delete old.label;
  const link = await compress(JSON.stringify({ format: 'wingspline', lesson: 'curves', version: 1, state: old }));
  const { state, problems } = await decodeState(lesson, link);
  assert.equal(state.label, 'from version 1');
  assert.deepEqual(problems, []);
  for (const bad of [null, 7, 'text', []]) {
    await checkDecoder(await compress(JSON.stringify({ format: 'wingspline', lesson: 'curves', version: 1, state: bad })),
      `version-1 state ${JSON.stringify(bad)}`);
  }
});

// A large field (an imported mesh) travels by reference. The link holds
// {"$content": "sha256-<hex>", "label"} and the text lives in a content store (IndexedDB in
// the page; a Map here). What is checked: the link stays small, the reference resolves to
// the identical state, the store is keyed by the SHA-256 of the text (computed here with
// node:crypto, independently of the page's crypto.subtle), a missing or tampered entry is a
// one-sentence Error naming the file, and small values still travel inline.
const nullableMesh = nullable(object({
  name: text({ maxLength: 120 }),
  positions: list(number(), { min: 9, max: 600000 }),
  faces: list(list(integer({ min: 0, max: 200000 }), { min: 3, max: 1000 }), { min: 1, max: 200000 }),
}));

test('a large field is stored by its SHA-256 and the link only refers to it', async () => {
  const { createHash } = await import('node:crypto');
  const meshLesson = {
    id: 'mesh',
    title: 'Mesh representations',
    stateVersion: 1,
    schema: {
      imported: nullableMesh,
      view: object({ cx: number(), cy: number(), zoom: number({ min: 1, max: 1e5 }) }),
    },
    defaultState: () => ({ imported: null, view: { cx: 0, cy: 0, zoom: 50 } }),
    contentFields: { imported: { label: (v) => v.name } },
  };
  const store = new Map();
  const contents = { get: async (hash) => store.get(hash) ?? null, put: async (hash, textValue) => { store.set(hash, textValue); } };
  const next = rng(SEED + 4);
  const n = 3000;
  const big = {
    name: 'big <b>grid</b>.off',
    positions: Array.from({ length: 3 * n }, () => (next() - 0.5) * 1e3),
    faces: Array.from({ length: n - 2 }, (_, i) => [0, i + 1, i + 2]),
  };
  const state = { imported: big, view: { cx: 0.1 + 0.2, cy: -0, zoom: 64 } };
  const link = await encodeState(meshLesson, state, { contents });
  assert.ok(link.length < 400, `the link refers to the mesh (${link.length} characters)`);
  assert.equal(store.size, 1);
  const [[hash, stored]] = store;
  assert.equal(hash, `sha256-${createHash('sha256').update(stored, 'utf8').digest('hex')}`, 'keyed by the SHA-256 of its text');
  assert.deepEqual(JSON.parse(stored), big);
  const back = await decodeState(meshLesson, link, { contents });
  assert.deepEqual(back.problems, []);
  assert.deepEqual(back.state, state);
  assert.ok(Object.is(back.state.view.cy, -0));

  // Another browser: the reference cannot be resolved. One sentence that names the file.
  const empty = { get: async () => null, put: async () => {} };
  for (const where of [empty, undefined]) {
    await assert.rejects(decodeState(meshLesson, link, { contents: where }), (err) => {
      assert.equal(err.constructor, Error);
      assert.ok(isOneSentence(err.message), err.message);
      assert.match(err.message, /big <b>grid<\/b>\.off/);
      assert.match(err.message, /only stored in the browser/);
      return true;
    });
  }
  // A store entry whose text does not match its hash is not used.
  const tampered = { get: async () => stored.replace(/\d/, '7'), put: async () => {} };
  await assert.rejects(decodeState(meshLesson, link, { contents: tampered }), (err) => err.constructor === Error && isOneSentence(err.message));
  // Hostile references: never a TypeError, never a fetch of something else.
  for (const ref of [{ $content: 'md5-00' }, { $content: 7, label: 'x' }, { $content: `sha256-${'0'.repeat(64)}`, label: { toString: 1 } }, { $content: 'sha256-../../etc', label: 'x' }]) {
    const bad = await compress(JSON.stringify({ format: 'wingspline', lesson: 'mesh', version: 1, state: { imported: ref, view: state.view } }));
    try {
      const result = await decodeState(meshLesson, bad, { contents });
      assert.equal(result.state.imported, null);
      assert.ok(result.problems.length > 0);
    } catch (err) {
      assert.equal(err.constructor, Error);
      assert.ok(isOneSentence(err.message), err.message);
    }
  }

  // A small mesh (a few hundred numbers) travels inline: the link works between machines.
  const small = { name: 'tet.off', positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], faces: [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]] };
  const smallLink = await encodeState(meshLesson, { ...state, imported: small }, { contents: empty });
  assert.deepEqual((await decodeState(meshLesson, smallLink)).state.imported, small);
});
