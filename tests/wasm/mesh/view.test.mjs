// The 3D view's questions to the core through the JS API (issue 13 item 11): the bounding box
// it turns about and the vertex normal that tells which side of the CCW walk is seen.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();
const REL_TOL = 1e-12; // unitless, relative to the size of the compared value
// Storing a + s rounds it by up to eps |a + s|: relative to the box's size s, the input box is
// already off a cube by that much (1e-9 for |a| = 5, s = 1e-6), and so is its normal.
const inputRounding = (a, s) => 16 * Number.EPSILON * (Math.max(...a.map(Math.abs)) + s) / s;

// A box with corners a and b = a + s (1, 1, 1) as six CCW-from-outside quads (built here, not
// by the core's generator): min a, max b, centre a + s/2; corner normals (+-1, +-1, +-1)/sqrt 3.
function box(a, s) {
  const positions = [];
  for (let v = 0; v < 8; v += 1) positions.push(a[0] + s * (v & 1), a[1] + s * ((v >> 1) & 1), a[2] + s * ((v >> 2) & 1));
  const faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
  return { positions, faces };
}

test('boundingBox and vertexNormal of a moved, scaled box', () => {
  for (const s of [1e-6, 1, 1e6]) {
    const a = [5, -2, 0.5];
    const input = box(a, s);
    const mesh = api.buildMesh(input);
    try {
      const b = mesh.boundingBox();
      for (let k = 0; k < 3; k += 1) {
        const size = Math.abs(a[k]) + s;
        assert.ok(Math.abs(b.min[k] - a[k]) <= REL_TOL * size, `min[${k}] at scale ${s}`);
        assert.ok(Math.abs(b.max[k] - (a[k] + s)) <= REL_TOL * size, `max[${k}] at scale ${s}`);
        assert.ok(Math.abs(b.centre[k] - (a[k] + s / 2)) <= REL_TOL * size, `centre[${k}] at scale ${s}`);
      }
      for (let v = 0; v < 8; v += 1) {
        const n = mesh.vertexNormal(v);
        const bits = [v & 1, (v >> 1) & 1, (v >> 2) & 1];
        bits.forEach((bit, k) => assert.ok(Math.abs(n[k] - (bit ? 1 : -1) / Math.sqrt(3)) <= REL_TOL + inputRounding(a, s), `normal of v${v}[${k}] at scale ${s}`));
      }
      assert.throws(() => mesh.vertexNormal(8), (e) => e.code === 'invalid-element' && /vertex index 8/.test(e.message));
      assert.throws(() => mesh.vertexNormal(-1), (e) => e.code === 'invalid-argument' || e.code === 'invalid-element');
    } finally {
      mesh.dispose();
    }
  }
});
