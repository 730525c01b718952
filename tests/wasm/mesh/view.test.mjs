// The 3D view's questions to the core through the JS API: the bounding box
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
      assert.throws(() => mesh.vertexNormal(8), (e) => e.code === 'invalid-element' && /there is no v9/.test(e.message));
      assert.throws(() => mesh.vertexNormal(-1), (e) => e.code === 'invalid-argument' || e.code === 'invalid-element');
    } finally {
      mesh.dispose();
    }
  }
});

// The face under the pointer, asked through the API (argument order, the near list,
// errors). A grid of unit squares built here, face j nx + i = [i, i+1] x [j, j+1] in z = 0.
function squares(nx, ny) {
  const positions = [];
  const faces = [];
  for (let j = 0; j <= ny; j += 1) for (let i = 0; i <= nx; i += 1) positions.push(i, j, 0);
  const id = (i, j) => j * (nx + 1) + i;
  for (let j = 0; j < ny; j += 1) for (let i = 0; i < nx; i += 1) faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
  return { positions, faces };
}

test('pick: the face under a point of a square grid, from the front and from behind, and the faces beside it', () => {
  const mesh = api.buildMesh(squares(3, 2));
  try {
    for (let j = 0; j < 2; j += 1) {
      for (let i = 0; i < 3; i += 1) {
        assert.equal(mesh.pick([i + 0.3, j + 0.6, 7], [0, 0, 1]).face, 3 * j + i);
        assert.equal(mesh.pick([i + 0.3, j + 0.6, -7], [0, 0, -2]).face, 3 * j + i);
      }
    }
    // 0.25 right of the grid, level with face 5 = [2,3] x [1,2]: nothing hit; face 5 is the
    // only face within 0.3, at 0.25.
    const beside = mesh.pick([3.25, 1.5, 0], [0, 0, 1], { radius: 0.3 });
    assert.equal(beside.face, -1);
    assert.deepEqual(beside.near.map((n) => n.face), [5]);
    assert.ok(Math.abs(beside.near[0].distance - 0.25) <= 1e-12);
    assert.deepEqual(mesh.pick([3.25, 1.5, 0], [0, 0, 1], { radius: 0.2 }).near, []);
    // 0.05 right of the side x = 1 between faces 0 and 1, radius 0.1: face 1 is hit and
    // comes first; face 0 is near, at 0.05.
    const side = mesh.pick([1.05, 0.5, 0], [0, 0, 1], { radius: 0.1 });
    assert.equal(side.face, 1);
    assert.deepEqual(side.near.map((n) => n.face), [1, 0]);
    assert.ok(Math.abs(side.near[1].distance - 0.05) <= 1e-12);
    assert.throws(() => mesh.pick([0, 0, 0], [0, 0, 0]), (e) => e.code === 'invalid-argument' && /direction/.test(e.message));
    assert.throws(() => mesh.pick([0, 0], [0, 0, 1]), (e) => e.code === 'invalid-argument' && /point/.test(e.message));
  } finally {
    mesh.dispose();
  }
});

test('displayProxy: a small mesh is its own fan triangles; a big one about the target with valid indices', () => {
  const small = api.buildMesh(squares(3, 2));
  const big = api.buildMesh(squares(200, 100));
  try {
    const own = small.displayProxy(100);
    assert.equal(own.cell, 0);
    assert.equal(own.triangles.length, 3 * 12);
    assert.deepEqual(Array.from(own.positions), squares(3, 2).positions);
    const proxy = big.displayProxy(4000);
    const T = proxy.triangles.length / 3;
    assert.ok(T >= 1000 && T <= 6000, `${T} triangles for a target of 4000`);
    assert.ok(proxy.cell > 0);
    const V = proxy.positions.length / 3;
    assert.ok(Array.from(proxy.triangles).every((v) => v >= 0 && v < V));
    // Every proxy vertex is a mean of grid points: inside [0, 200] x [0, 100], z = 0.
    for (let v = 0; v < V; v += 1) {
      assert.ok(proxy.positions[3 * v] >= 0 && proxy.positions[3 * v] <= 200 && proxy.positions[3 * v + 1] >= 0 && proxy.positions[3 * v + 1] <= 100);
      assert.equal(proxy.positions[3 * v + 2], 0);
    }
  } finally {
    small.dispose();
    big.dispose();
  }
});
