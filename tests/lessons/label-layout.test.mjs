// The label layout's "asked again" rule (web/js/app/label-layout.js): a label asked again
// with the same text at the same anchor (within half a pixel) replaces the first request and
// keeps its place in the order; anything else is a new request. The layout indexes requests
// by text so that a frame of tens of thousands of labels (a 40,000-edge walk) is not
// quadratic; checked here against the rule written out as a plain scan, on random asks.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { LabelLayout } from '../../web/js/app/label-layout.js';

// The rule as a linear scan over the requests so far.
function reference(asks) {
  const requests = [];
  for (const [text, ax, ay, opts] of asks) {
    const same = requests.findIndex((r) => r.text === text && Math.abs(r.ax - ax) < 0.5 && Math.abs(r.ay - ay) < 0.5);
    const request = { text, ax, ay, opts, order: same >= 0 ? requests[same].order : requests.length };
    if (same >= 0) requests[same] = request; else requests.push(request);
  }
  return requests;
}

function seeded(seed) {
  let s = seed >>> 0;
  return () => { s = (s * 1664525 + 1013904223) >>> 0; return s / 2 ** 32; };
}

test('a label asked again at the same anchor replaces the first and keeps its order', () => {
  const layout = new LabelLayout(400, 300);
  layout.ask('e1', 100, 100, { px: 14, fill: 'a' });
  layout.ask('e2', 200, 100, { px: 14 });
  layout.ask('e1', 100.3, 99.8, { px: 14, fill: 'b' });
  layout.ask('e1', 150, 100, { px: 14 });
  assert.equal(layout.requests.length, 3);
  assert.equal(layout.requests[0].opts.fill, 'b', 'the second ask of e1 at (100, 100) replaced the first');
  assert.equal(layout.requests[0].order, 0);
  assert.equal(layout.requests[2].ax, 150, 'e1 at another anchor is a label of its own');
  const placed = layout.place();
  assert.deepEqual(placed.map((p) => p.text), ['e1', 'e2', 'e1']);
});

test('3,000 random frames of asks give the requests the plain scan gives', () => {
  const random = seeded(20261128);
  for (let frame = 0; frame < 3000; frame += 1) {
    const asks = [];
    const n = 1 + Math.floor(random() * 40);
    for (let k = 0; k < n; k += 1) {
      // Few texts and a coarse grid of anchors, so repeats (and near repeats) are common.
      const text = `e${1 + Math.floor(random() * 6)}`;
      const ax = Math.floor(random() * 4) * 10 + (random() < 0.3 ? random() * 0.9 - 0.45 : 0);
      const ay = Math.floor(random() * 3) * 10 + (random() < 0.3 ? random() * 0.9 - 0.45 : 0);
      asks.push([text, ax, ay, { px: 14, id: k }]);
    }
    const layout = new LabelLayout(800, 600);
    for (const [text, ax, ay, opts] of asks) layout.ask(text, ax, ay, opts);
    assert.deepEqual(layout.requests, reference(asks), `frame ${frame}`);
  }
});
