// Query cost and storage against mesh size (web/js/lessons/mesh/growth.js): the
// series the mesh lesson plots, from the core. Lecture 000's claim as a property of them: on
// grids of about a thousand to a million faces, the winged edge answers "faces around a
// vertex" of an interior vertex (valence 6) reading the same number of entries at every size,
// while the independent faces and the vertex/face tables scan the mesh (entries read grow in
// proportion to F). The series' smallest grid is also built for real and asked with
// mesh.query, so the core's fit is checked against a count it did not fit.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { querySeries, storageSeries, COST_GRIDS } from '../../../web/js/lessons/mesh/growth.js';

const api = await loadWingspline();

test('faces around the middle vertex: constant for the winged edge, proportional to F for the scans, a thousand to a million faces', () => {
  const live = api.liveMeshCount();
  const { sizes, series } = querySeries(api, 'faces-around-vertex');
  assert.deepEqual(sizes.map((s) => s.faces), [968, 9800, 100352, 1002528]);
  // The lecture's walk: the vertex's edge, then per edge of the 6 its record, the face swept
  // and the next wing (1 + 3 x 6); the adjacency list: 2 offsets and the 6 faces.
  assert.deepEqual(series['winged-edge'], [19, 19, 19, 19]);
  assert.deepEqual(series['adjacency-lists'], [8, 8, 8, 8]);
  for (const rep of ['independent-faces', 'vertex-face-tables']) {
    // entries read / F: the same at the two largest sizes within 1% (a fixed part reads the answer).
    const [a, b] = [series[rep].at(-2) / sizes.at(-2).faces, series[rep].at(-1) / sizes.at(-1).faces];
    assert.ok(Math.abs(a - b) <= 0.01 * b, `${rep}: ${a} vs ${b} entries per face`);
    assert.ok(series[rep].at(-1) > 10000 * series['winged-edge'].at(-1), `${rep} scans the mesh`);
  }
  // The smallest grid, built and counted for real.
  const n = COST_GRIDS[0];
  const mesh = api.buildMesh(api.generateMesh('grid', { nx: n, ny: n, layout: 'csr' }));
  const real = mesh.query('faces-around-vertex', (n / 2) * (n + 1) + n / 2);
  mesh.dispose();
  for (const [rep, a] of Object.entries(real)) assert.equal(series[rep][0], a.entriesRead, rep);
  assert.equal(api.liveMeshCount(), live, 'every grid freed');
});

test('storage: bytes grow in proportion to F for every representation', () => {
  const { sizes, series } = storageSeries(api);
  assert.ok(Object.keys(series).length >= 6);
  for (const [rep, bytes] of Object.entries(series)) {
    const [a, b] = [bytes.at(-2) / sizes.at(-2).faces, bytes.at(-1) / sizes.at(-1).faces];
    assert.ok(Math.abs(a - b) <= 0.05 * b, `${rep}: ${a} vs ${b} bytes per face`);
  }
});
