// Trust, for meshes, through the JS API: neighbours are a set in every
// representation, planes() uses the face's own first three corners and says which,
// BOM and CRLF files read, and one set of limits (api.meshLimits) enforced where a
// value enters. Over-limit files are refused without growing the wasm memory: in
// files/over-limit-memory.test.mjs (its own process, so the memory figures are its own).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();
const REPS = ['independent-faces', 'vertex-face-tables', 'adjacency-lists', 'partial-adjacency-lists', 'edge-list', 'winged-edge'];

test('neighbours-of-face: two quads sharing two edges are each other\'s only neighbour, once, in every representation', () => {
  const mesh = api.buildMesh({
    positions: [0, 0, 0, 2, 0, 0, 1, 1, 0, 0, 2, 0, 3, 3, 0],
    faces: [[0, 1, 2, 3], [3, 2, 1, 4]],
  });
  try {
    for (const f of [0, 1]) {
      const answers = mesh.query('neighbours-of-face', f);
      for (const key of REPS) assert.deepEqual(Array.from(answers[key].answer), [1 - f], `${key} F${f + 1}`);
      assert.deepEqual(Array.from(mesh.faceNeighbours(f)), [1 - f]);
    }
  } finally {
    mesh.dispose();
  }
});

test('planes(): cross product from the face\'s own first three corners, reported, whatever the stored face edge', () => {
  // Non-planar quad P1 (0,0,0) P2 (1,0,0) P3 (1,1,1) P4 (0,1,0): P1P2 x P1P3 = (0, -1, 1), D = 0.
  const input = { positions: [0, 0, 0, 1, 0, 0, 1, 1, 1, 0, 1, 0], faces: [[0, 1, 2, 3]] };
  const probe = api.buildMesh(input);
  const edges = probe.wingedEdge().edges;
  probe.dispose();
  for (let side = 0; side < 4; side += 1) {
    const [a, b] = [side, (side + 1) % 4];
    const e = edges.findIndex((r) => (r.start === a && r.end === b) || (r.start === b && r.end === a));
    const mesh = api.buildMesh({ ...input, faceEdges: [e] });
    try {
      const [plane] = mesh.planes();
      assert.deepEqual(plane.cross.map((x) => x + 0), [0, -1, 1, 0], `stored side ${side}`);
      assert.deepEqual(plane.crossCorners, [0, 1, 2]);
    } finally {
      mesh.dispose();
    }
  }
});

test('planeArrays({offset, limit}): any range of faces equals the same rows of the whole; the normals are Newell\'s unit normals; a range past the faces is refused', () => {
  const mesh = api.buildMesh(api.generateMesh('sphere', { slices: 12, stacks: 6 }));
  try {
    mesh.apply({ op: 'join-faces', e: 20 }); // a gap and a quad among the triangles
    const whole = mesh.planeArrays();
    const normals = mesh.normals();
    const F = whole.residual.length;
    const rnd = random(7);
    for (let k = 0; k < 200; k += 1) {
      const offset = Math.floor(rnd() * F);
      const limit = Math.floor(rnd() * (F - offset + 1));
      const part = mesh.planeArrays({ offset, limit });
      assert.deepEqual(Array.from(part.cross), Array.from(whole.cross.subarray(4 * offset, 4 * (offset + limit))), `${offset}+${limit} cross`);
      assert.deepEqual(Array.from(part.newell), Array.from(whole.newell.subarray(4 * offset, 4 * (offset + limit))), `${offset}+${limit} newell`);
      assert.deepEqual(Array.from(part.residual), Array.from(whole.residual.subarray(offset, offset + limit)));
      assert.deepEqual(Array.from(part.crossCorners), Array.from(whole.crossCorners.subarray(3 * offset, 3 * (offset + limit))));
    }
    // Unit length, and the direction of mesh.normals() (the faces' walk order may differ in
    // the last bits: within 1e-12 of unit vectors).
    for (let f = 0; f < F; f += 1) {
      const n = whole.normals.subarray(3 * f, 3 * f + 3);
      if (whole.residual[f] === 0 && n[0] === 0 && n[1] === 0 && n[2] === 0) continue; // the gap
      for (let k = 0; k < 3; k += 1) assert.ok(Math.abs(n[k] - normals[3 * f + k]) < 1e-12, `F${f + 1}`);
    }
    assert.throws(() => mesh.planeArrays({ offset: F - 1, limit: 2 }), (e) => e.code === 'invalid-element' && new RegExp(`it has ${F}\\)`).test(e.message));
    assert.throws(() => mesh.planeArrays({ offset: -1, limit: 2 }), (e) => e.code === 'invalid-argument');
  } finally {
    mesh.dispose();
  }
});

test('planeArrays(): the planes as flat arrays, per face equal to planes() (the planes table reads rows by window)', () => {
  // The non-planar quad above: cross (0, -1, 1, 0) from P1 P2 P3; Newell (lecture 003, with
  // the 1/2) computed here: A = 1/2 sum (z_i + z_i+1)(y_i - y_i+1) = -1/2, B = -1/2, C = 1.
  const quad = api.buildMesh({ positions: [0, 0, 0, 1, 0, 0, 1, 1, 1, 0, 1, 0], faces: [[0, 1, 2, 3]] });
  try {
    const a = quad.planeArrays();
    assert.deepEqual(Array.from(a.cross, (x) => x + 0), [0, -1, 1, 0]);
    assert.deepEqual(Array.from(a.crossCorners), [0, 1, 2]);
    assert.deepEqual(Array.from(a.newell.subarray(0, 3)), [-0.5, -0.5, 1]);
    assert.equal(a.residual.length, 1);
  } finally {
    quad.dispose();
  }
  const sphere = api.buildMesh(api.generateMesh('sphere', { slices: 12, stacks: 6 }));
  try {
    const a = sphere.planeArrays();
    const planes = sphere.planes();
    assert.equal(a.residual.length, planes.length);
    planes.forEach((p, f) => {
      assert.deepEqual(Array.from(a.cross.subarray(4 * f, 4 * f + 4)), p.cross, `F${f + 1} cross`);
      assert.deepEqual(Array.from(a.newell.subarray(4 * f, 4 * f + 4)), p.newell, `F${f + 1} newell`);
      assert.deepEqual(Array.from(a.crossCorners.subarray(3 * f, 3 * f + 3)), p.crossCorners, `F${f + 1} corners`);
      assert.equal(a.residual[f], p.residual);
    });
  } finally {
    sphere.dispose();
  }
});

test('a UTF-8 byte-order mark and CRLF line ends are read (OFF and OBJ)', () => {
  const off = api.parseMesh('\uFEFFOFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n', { format: 'off' });
  assert.deepEqual(Array.from(off.positions), [0, 0, 0, 1, 0, 0, 0, 1, 0]);
  assert.deepEqual(off.faces, [[0, 1, 2]]);
  const obj = api.parseMesh('\uFEFFv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n', { format: 'obj' });
  assert.deepEqual(obj.faces, [[0, 1, 2]]);
});

test('api.meshLimits: the core\'s one set of mesh limits', () => {
  assert.deepEqual({ ...api.meshLimits }, { maxCoordinate: 1e9, maxFaceCorners: 1000, maxVertices: 2000000, maxFaces: 2000000 });
  assert.ok(Object.isFrozen(api.meshLimits));
});

test('the page\'s limits (web/js/app/limits.js, read by every schema before the core loads) are the core\'s', async () => {
  const limits = await import('../../../web/js/app/limits.js');
  assert.deepEqual({
    maxCoordinate: limits.COORDINATE_BOUND, maxFaceCorners: limits.MAX_FACE_CORNERS,
    maxVertices: limits.MAX_MESH_VERTICES, maxFaces: limits.MAX_MESH_FACES,
  }, { ...api.meshLimits });
});

test('setVertexPosition beyond the coordinate limit is refused, changes nothing, and normals stay finite', () => {
  const mesh = api.buildMesh(api.generateMesh('tetrahedron'));
  try {
    const before = mesh.wingedEdgeArrays().positions;
    for (const x of [1e300, -5e9, api.meshLimits.maxCoordinate * (1 + 2 ** -52) * 2]) {
      assert.throws(() => mesh.setVertexPosition(1, [x, 0, 0]),
        (err) => err.code === 'coordinate-out-of-range' && err.message.includes('v2'), `x = ${x}`);
      assert.deepEqual(mesh.wingedEdgeArrays().positions, before);
      const reps = mesh.representations();
      const v2 = reps['vertex-face-tables'].vertices[1];
      assert.deepEqual([v2.x, v2.y, v2.z], Array.from(before.subarray(3, 6)));
    }
    mesh.setVertexPosition(1, [api.meshLimits.maxCoordinate, 0, 0]);
    assert.ok(Array.from(mesh.normals()).every(Number.isFinite));
  } finally {
    mesh.dispose();
  }
});

test('import: a 1001-corner face or a coordinate beyond 1e9 is refused, naming the line', () => {
  const polygon = (n, x0) => {
    const lines = ['OFF', `${n} 1 0`];
    for (let i = 0; i < n; i += 1) lines.push(`${i === 0 ? x0 : Math.cos((2 * Math.PI * i) / n)} ${Math.sin((2 * Math.PI * i) / n)} 0`);
    lines.push(`${n} ${Array.from({ length: n }, (_, i) => i).join(' ')}`);
    return lines.join('\n') + '\n';
  };
  assert.equal(api.parseMesh(polygon(1000, 1)).faces[0].length, 1000);
  assert.throws(() => api.parseMesh(polygon(1001, 1)),
    (err) => err.code === 'face-too-large' && err.line === 1004 && /1001/.test(err.message) && /1000/.test(err.message));
  assert.throws(() => api.parseMesh(polygon(3, 5e9)),
    (err) => err.code === 'coordinate-out-of-range' && err.line === 3 && err.message.startsWith('line 3:'));
});

test('the mesh lesson\'s state format keeps exactly what the core imports (api.meshLimits)', async () => {
  const { meshLesson } = await import('../../../web/js/lessons/mesh/lesson.js');
  const check = meshLesson.schema.imported;
  const L = api.meshLimits;
  const ok = (positions, faces) => { check({ name: 'm', positions, faces }, 'imported'); return true; };
  const corners = (n) => Array.from({ length: n }, (_, i) => i);
  const zeros = (n) => new Array(n).fill(0);
  assert.ok(ok(zeros(3 * L.maxFaceCorners), [corners(L.maxFaceCorners)]));
  assert.throws(() => ok(zeros(3 * (L.maxFaceCorners + 1)), [corners(L.maxFaceCorners + 1)]));
  assert.ok(ok([L.maxCoordinate, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2]]));
  assert.throws(() => ok([L.maxCoordinate * 1.5, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2]]));
  assert.ok(ok(zeros(3 * L.maxVertices), [[0, 1, 2]]));
  assert.throws(() => ok(zeros(3 * (L.maxVertices + 1)), [[0, 1, 2]]));
  assert.throws(() => ok(zeros(9), new Array(L.maxFaces + 1).fill([0, 1, 2])));
});

// A regular n-gon F1 = (v1 ... vn) and a triangle F2 = (v2 v1 x) outside its side e1 = v1-v2:
// joining them across e1 makes a face of n + 1 corners.
function polygonWithEar(n) {
  const positions = [];
  for (let i = 0; i < n; i += 1) positions.push(Math.cos((2 * Math.PI * i) / n), Math.sin((2 * Math.PI * i) / n), 0);
  positions.push(2 * Math.cos(Math.PI / n), 2 * Math.sin(Math.PI / n), 0);
  return { positions, faces: [Array.from({ length: n }, (_, i) => i), [1, 0, n]] };
}

test('joinFaces makes no face over meshLimits.maxFaceCorners: at the limit the export imports back, one over is refused and changes nothing', () => {
  const L = api.meshLimits.maxFaceCorners;
  const atLimit = api.buildMesh(polygonWithEar(L - 1));
  try {
    atLimit.joinFaces(0);
    assert.equal(atLimit.verticesOfFace(0).length, L);
    for (const format of ['off', 'obj']) {
      const back = api.parseMesh(atLimit.format({ format }), { format });
      assert.equal(back.faces[0].length, L);
      assert.equal(api.validateMesh(back).ok, true);
      const rebuilt = api.buildMesh(back);
      try {
        assert.deepEqual(rebuilt.counts(), atLimit.counts());
      } finally {
        rebuilt.dispose();
      }
    }
  } finally {
    atLimit.dispose();
  }
  const over = api.buildMesh(polygonWithEar(L));
  try {
    const tables = JSON.stringify(over.wingedEdge());
    const version = over.version;
    const verdict = over.check('join-faces', 0);
    assert.deepEqual(verdict, { ok: false, code: 'face-too-large',
      message: 'joining F1 and F2 would make a face of 1001 corners; a face may have at most 1000' });
    assert.throws(() => over.joinFaces(0), (err) => err.code === 'face-too-large' && err.message === verdict.message);
    assert.throws(() => over.splitEdge(5), (err) => err.code === 'face-too-large' && err.message.includes('F1 1001 corners'));
    assert.equal(JSON.stringify(over.wingedEdge()), tables);
    assert.equal(over.version, version);
    assert.equal(over.validate().ok, true);
    assert.equal(api.parseMesh(over.format()).faces[0].length, L);
  } finally {
    over.dispose();
  }
});

test('buildMesh and validateMesh refuse a face over meshLimits.maxFaceCorners, as parseMesh does', () => {
  const L = api.meshLimits.maxFaceCorners;
  const input = polygonWithEar(L + 1);
  const report = api.validateMesh(input);
  assert.equal(report.ok, false);
  assert.deepEqual(report.problems.map((p) => [p.code, p.message]), [['face-too-large', 'F1 has 1001 corners; a face may have at most 1000']]);
  assert.throws(() => api.buildMesh(input), (err) => err.code === 'face-too-large' && err.message === 'F1 has 1001 corners; a face may have at most 1000');
  assert.throws(() => api.parseMesh(api.formatMesh(input)), (err) => err.code === 'face-too-large' && err.message.endsWith(': F1 has 1001 corners; a face may have at most 1000'));
});
