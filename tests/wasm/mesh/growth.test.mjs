// Query cost and storage against mesh size (web/js/lessons/mesh/growth.js): the
// series the mesh lesson plots, from the core. Lecture 000's claim as a property of them: on
// grids of growing size, the winged edge answers "faces around a vertex" of an interior
// vertex (valence 6) reading the same number of entries at every size, while the independent
// faces and the vertex/face tables scan the mesh (entries read grow in proportion to F).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { growthSeries, GROWTH_SIZES } from '../../../web/js/lessons/mesh/growth.js';

const api = await loadWingspline();

test('faces around the middle vertex: constant for the winged edge, proportional to F for the scans', () => {
  const live = api.liveMeshCount();
  const { sizes, series } = growthSeries(api, 'faces-around-vertex');
  assert.deepEqual(sizes.map((s) => s.faces), GROWTH_SIZES.map((n) => 2 * n * n));
  assert.equal(new Set(series['winged-edge']).size, 1, `winged edge: ${series['winged-edge']}`);
  assert.equal(new Set(series['adjacency-lists']).size, 1, `adjacency lists: ${series['adjacency-lists']}`);
  for (const rep of ['independent-faces', 'vertex-face-tables']) {
    // entries read / F: the same at the two largest sizes within 2% (a fixed part reads the answer).
    const [a, b] = [series[rep].at(-2) / sizes.at(-2).faces, series[rep].at(-1) / sizes.at(-1).faces];
    assert.ok(Math.abs(a - b) <= 0.02 * b, `${rep}: ${a} vs ${b} entries per face`);
    assert.ok(series[rep].at(-1) > 100 * series['winged-edge'].at(-1), `${rep} scans the mesh`);
  }
  assert.equal(api.liveMeshCount(), live, 'every grid freed');
});

test('storage: bytes grow in proportion to F for every representation', () => {
  const { sizes, series } = growthSeries(api, null);
  assert.ok(Object.keys(series).length >= 6);
  for (const [rep, bytes] of Object.entries(series)) {
    const [a, b] = [bytes.at(-2) / sizes.at(-2).faces, bytes.at(-1) / sizes.at(-1).faces];
    assert.ok(Math.abs(a - b) <= 0.05 * b, `${rep}: ${a} vs ${b} bytes per face`);
  }
});
