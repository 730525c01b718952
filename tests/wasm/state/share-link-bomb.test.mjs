// A compressed bomb in a share link (a short link that inflates to
// hundreds of MB) is refused while it is being decompressed, once MAX_STATE_BYTES have come
// out, instead of being inflated whole and then parsed. The decoder is JavaScript
// (web/js/app/share-link.js), run here in Node 20 as in the browser.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { decodeState, MAX_LINK_CHARS, MAX_STATE_BYTES } from '../../../web/js/app/share-link.js';

const lesson = { id: 'fixture', title: 'Fixture', stateVersion: 1, schema: { x: (v) => v }, defaultState: () => ({ x: '' }) };

async function deflate(bytes) {
  const out = new Response(new Blob([bytes]).stream().pipeThrough(new CompressionStream('deflate-raw')));
  return new Uint8Array(await out.arrayBuffer());
}

function base64url(bytes) {
  return Buffer.from(bytes).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

test('a link that inflates to 120 MB is refused during decompression, naming the cap', async () => {
  // Valid JSON all the way: a state whose one string is 150 MB of spaces.
  const inflated = 120 * 2 ** 20;
  const json = new Uint8Array(inflated).fill(0x20);
  json.set(new TextEncoder().encode('{"format":"wingspline","lesson":"fixture","version":1,"state":{"x":"'), 0);
  json.set(new TextEncoder().encode('"}}'), inflated - 3);
  const link = base64url(await deflate(json));
  assert.ok(link.length <= MAX_LINK_CHARS, `the bomb fits in a link (${link.length} characters)`);
  assert.ok(MAX_STATE_BYTES < inflated);
  await assert.rejects(decodeState(lesson, link), (err) => {
    assert.match(err.message, /unpacks to more than \d+ MB/);
    return true;
  });
});

test('a link under the cap still decodes', async () => {
  const json = new TextEncoder().encode('{"format":"wingspline","lesson":"fixture","version":1,"state":{"x":"kept"}}');
  const { state, problems } = await decodeState(lesson, base64url(await deflate(json)));
  assert.deepEqual(state, { x: 'kept' });
  assert.deepEqual(problems, []);
});
