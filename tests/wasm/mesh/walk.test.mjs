// The walk's animation frames (web/js/ui/mesh/walk.js, DOM-free)
// must store the "found so far" list once, not once per frame: memory linear in the
// number of steps. Measured structurally: every list (Array or typed array) a frame holds
// is counted once by identity, and the total number of stored entries over all frames of
// an n-step walk must be at most n + a constant per frame's own fields (here 2n + 16).
// The steps come from the core: the walk around the hub of an open fan of n triangles.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { walkFrames, normaliseSteps, foundEdges } from '../../../web/js/ui/mesh/walk.js';

const api = await loadWingspline();

function storedEntries(frames) {
  const lists = new Set();
  for (const frame of frames) {
    for (const value of Object.values(frame)) if (Array.isArray(value) || ArrayBuffer.isView(value)) lists.add(value);
  }
  let total = 0;
  for (const list of lists) total += list.length;
  return total;
}

function fanWalk(n) {
  const mesh = api.buildMesh(api.generateMesh('fan', { n }));
  try {
    return normaliseSteps(mesh.traversalSteps(0), 'vertex');
  } finally {
    mesh.dispose();
  }
}

for (const n of [2000, 40000]) {
  test(`the walk around the hub of a ${n}-triangle fan stores O(n) found entries, and every frame still knows its found list`, () => {
    const steps = fanWalk(n);
    assert.equal(steps.length, n + 1, 'the hub of an open fan of n triangles has n + 1 edges');
    const frames = walkFrames('vertex', 0, steps);
    assert.equal(frames.length, steps.length + 2);
    const entries = storedEntries(frames);
    assert.ok(entries <= 2 * steps.length + 16, `${entries} entries stored for ${steps.length} steps`);
    // What each frame shows is unchanged: frame k has found the first k edges of the walk.
    for (const k of [0, 1, 2, Math.floor(steps.length / 2), steps.length]) {
      assert.deepEqual(foundEdges(frames[k]), steps.slice(0, k).map((s) => s.edge), `frame ${k}`);
    }
    assert.deepEqual(foundEdges(frames[frames.length - 1], 3), steps.slice(-3).map((s) => s.edge));
  });
}
