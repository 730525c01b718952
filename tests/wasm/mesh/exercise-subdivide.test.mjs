// The JS API of the subdivide exercise kind (web/js/core/exercise-subdivide-api.js) through
// the wasm module: shapes, exact fractions, findings, errors. Expected stencils are the
// lecture's masks worked here: Loop's 3/8, 3/8, 1/8, 1/8 for an interior edge, 1/2, 1/2 on the
// boundary, beta(3) = 3/16 on the tetrahedron; the cube's face point 1/4 per corner. Every
// stencil's weights must add up to exactly 1 (checked with integer arithmetic here), and a
// stencil applied to the old positions must be the subdivided mesh's new point.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';

const api = await loadWingspline();
// The lecture's example without the slide's numbering, as the subdivision lesson builds it.
const lecture = (() => { const m = api.lectureExample(); return { positions: m.positions, faces: m.faces }; })();
const cube = api.generateMesh('cube');
const tetrahedron = api.generateMesh('tetrahedron');

// Tolerance for positions: 1e-12 of the mesh's unit size (a few roundings).
const POSITION_TOLERANCE = 1e-12;
const SCALE = 2; // the largest coordinate of the meshes below (the grid spans [0, 2] x [0, 1])

const gcd = (a, b) => (b === 0 ? Math.abs(a) : gcd(b, a % b));
function sumIsOne(weights) {
  let n = 0; let d = 1;
  for (const w of weights) { n = n * w.den + w.num * d; d *= w.den; const g = gcd(n, d); n /= g; d /= g; }
  return n === 1 && d === 1;
}
const edgeOf = (mesh, a, b) => {
  const built = api.buildMesh(mesh);
  try {
    const { edges } = built.wingedEdgeArrays();
    for (let e = 0; 8 * e < edges.length; e += 1) if ((edges[8 * e] === a && edges[8 * e + 1] === b) || (edges[8 * e] === b && edges[8 * e + 1] === a)) return e;
  } finally { built.dispose(); }
  throw new Error('no such edge');
};
const asObject = (s) => Object.fromEntries(Array.from(s.vertices, (v, i) => [`v${v + 1}`, `${s.weights[i].num}/${s.weights[i].den}`]));

test('subdivideStencil: Loop on the lecture\'s mesh, interior and boundary edge, boundary vertex', () => {
  const inner = api.subdivideStencil(lecture, { scheme: 'loop', point: { type: 'edge', element: edgeOf(lecture, 1, 2) } });
  assert.equal(inner.rule, 'edge-interior');
  assert.ok(inner.vertices instanceof Int32Array);
  assert.deepEqual(asObject(inner), { v2: '3/8', v3: '3/8', v1: '1/8', v4: '1/8' });
  assert.equal(inner.roles.length, 4);
  const rim = api.subdivideStencil(lecture, { scheme: 'loop', point: { type: 'edge', element: edgeOf(lecture, 0, 1) } });
  assert.equal(rim.rule, 'edge-boundary');
  assert.deepEqual(asObject(rim), { v1: '1/2', v2: '1/2' });
  const v2 = api.subdivideStencil(lecture, { scheme: 'loop', point: { type: 'vertex', element: 1 } });
  assert.equal(v2.rule, 'vertex-boundary');
  assert.deepEqual(asObject(v2), { v2: '3/4', v1: '1/8', v5: '1/8' });
  const t = api.subdivideStencil(tetrahedron, { scheme: 'loop', point: { type: 'vertex', element: 0 } });
  assert.deepEqual(asObject(t), { v1: '7/16', v2: '3/16', v3: '3/16', v4: '3/16' });
  const face = api.subdivideStencil(cube, { scheme: 'catmull-clark', point: { type: 'face', element: 0 } });
  assert.equal(face.rule, 'face-point');
  assert.deepEqual(Object.values(asObject(face)), ['1/4', '1/4', '1/4', '1/4']);
});

test('every stencil of the cube and a sphere sums to exactly 1 and is subdivide()\'s new point', () => {
  for (const [mesh, scheme] of [[cube, 'catmull-clark'], [api.generateMesh('sphere', { slices: 6, stacks: 4 }), 'catmull-clark'], [api.generateMesh('grid', { nx: 3, ny: 2 }), 'loop']]) {
    const old = api.buildMesh(mesh);
    const next = api.subdivide(old, { scheme, steps: 1 });
    try {
      const P = old.wingedEdgeArrays().positions;
      const Q = next.wingedEdgeArrays().positions;
      const { vertices: V, edges: E, faces: F } = old.counts();
      const points = [...Array.from({ length: V }, (_, i) => ['vertex', i, i]), ...Array.from({ length: E }, (_, i) => ['edge', i, V + i]),
        ...(scheme === 'loop' ? [] : Array.from({ length: F }, (_, i) => ['face', i, V + E + i]))];
      let asked = 0;
      for (const [type, element, at] of points) {
        let s;
        try { s = api.subdivideStencil(mesh, { scheme, point: { type, element } }); } catch (err) { assert.equal(err.code, 'no-exact-mask'); continue; }
        asked += 1;
        assert.ok(sumIsOne(s.weights), `${type} ${element}`);
        for (let k = 0; k < 3; k += 1) {
          let x = 0;
          s.vertices.forEach((v, i) => { x += (s.weights[i].num / s.weights[i].den) * P[3 * v + k]; });
          assert.ok(Math.abs(x - Q[3 * at + k]) <= POSITION_TOLERANCE * SCALE, `${type} ${element}: ${x} vs ${Q[3 * at + k]}`);
        }
      }
      assert.ok(asked > 10);
    } finally { old.dispose(); next.dispose(); }
  }
});

test('checkSubdivideMask: right, then each kind of mistake named, no right value in any text', () => {
  const e = edgeOf(lecture, 1, 2);
  const q = { scheme: 'loop', point: { type: 'edge', element: e } };
  const right = [{ vertex: 1, num: 3, den: 8 }, { vertex: 2, num: 6, den: 16 }, { vertex: 0, num: 1, den: 8 }, { vertex: 3, num: 125, den: 1000 }];
  assert.deepEqual(api.checkSubdivideMask(lecture, { ...q, mask: 'edge-interior', rows: right }), { correct: true, findings: [] });
  const r = api.checkSubdivideMask(lecture, { ...q, mask: 'edge-boundary', rows: [right[0], { vertex: 2, num: 1, den: 2 }, { vertex: 4, num: 1, den: 8 }, { vertex: 2, num: 0, den: 1 }] });
  assert.equal(r.correct, false);
  assert.deepEqual(r.findings.map((f) => [f.code, f.row, f.vertex]), [['wrong-mask', -1, -1], ['wrong-weight', 1, 2], ['not-in-stencil', 2, 4], ['repeated-point', 3, 2], ['missing-point', -1, 0], ['missing-point', -1, 3]]);
  for (const f of r.findings) {
    assert.equal(typeof f.hint, 'string');
    for (const value of ['3/8', '1/8', '0.375', '0.125', '6/16']) assert.ok(!f.text.includes(value) && !f.hint.includes(value), f.text);
  }
  assert.equal(api.checkSubdivideMask(lecture, { ...q, mask: null, rows: right }).findings[0].code, 'no-mask');
  assert.equal(api.checkSubdivideMask(lecture, { ...q, mask: 'edge-interior', rows: [{ vertex: 9, num: 0, den: 1 }, ...right] }).findings[0].text, 'Row 1 names v10, but the old mesh has vertices v1 to v5.');
});

test('checkSubdivideCounts and subdivisionCounts: the cube after one and two Catmull-Clark steps', () => {
  assert.deepEqual(api.subdivisionCounts(cube, { scheme: 'catmull-clark' }), { vertices: 26, edges: 48, faces: 24 });
  assert.deepEqual(api.subdivisionCounts(cube, { scheme: 'catmull-clark', steps: 0 }), { vertices: 8, edges: 12, faces: 6 });
  assert.deepEqual(api.checkSubdivideCounts(cube, { scheme: 'catmull-clark', vertices: 26, edges: 48, faces: 24 }), { correct: true, findings: [] });
  assert.equal(api.checkSubdivideCounts(cube, { scheme: 'catmull-clark', steps: 2, vertices: 98, edges: 192, faces: 96 }).correct, true);
  const r = api.checkSubdivideCounts(tetrahedron, { scheme: 'loop', vertices: 10, edges: null, faces: 12 });
  assert.deepEqual(r.findings.map((f) => [f.code, f.count]), [['wrong-count', 1], ['wrong-count', 2]]);
  assert.match(r.findings[0].text, /edges .* is missing/);
  assert.ok(!r.findings[1].text.includes('16'));
});

test('errors: scheme, point, element, Loop face points, beta at valence 5, malformed answers', () => {
  const code = (fn) => { try { fn(); } catch (err) { return err.code; } return 'none'; };
  assert.equal(code(() => api.subdivideStencil(cube, { scheme: 'butterfly', point: { type: 'face', element: 0 } })), 'unknown-scheme');
  assert.equal(code(() => api.subdivideStencil(cube, { scheme: 'catmull-clark', point: { type: 'corner', element: 0 } })), 'invalid-argument');
  assert.equal(code(() => api.subdivideStencil(cube, { scheme: 'catmull-clark', point: { type: 'face', element: 6 } })), 'invalid-element');
  assert.equal(code(() => api.subdivideStencil(tetrahedron, { scheme: 'loop', point: { type: 'face', element: 0 } })), 'no-exact-mask');
  assert.equal(code(() => api.subdivideStencil(cube, { scheme: 'loop', point: { type: 'edge', element: 0 } })), 'not-a-triangle-mesh');
  // The icosahedron-like sphere's poles have valence 5: no fraction for beta(5).
  const sphere = api.generateMesh('sphere', { slices: 5, stacks: 3 });
  assert.equal(code(() => api.subdivideStencil(sphere, { scheme: 'loop', point: { type: 'vertex', element: 0 } })), 'no-exact-mask');
  const q = { scheme: 'loop', point: { type: 'vertex', element: 0 } };
  assert.equal(code(() => api.checkSubdivideMask(tetrahedron, { ...q, mask: 'fancy', rows: [] })), 'invalid-answer');
  assert.equal(code(() => api.checkSubdivideMask(tetrahedron, { ...q, mask: null, rows: [{ vertex: 0, num: 1, den: 0 }] })), 'invalid-answer');
  assert.equal(code(() => api.checkSubdivideMask(tetrahedron, { ...q, mask: null, rows: [{ vertex: 0, num: 0.5, den: 1 }] })), 'invalid-answer');
  assert.equal(code(() => api.checkSubdivideCounts(tetrahedron, { scheme: 'loop', steps: 5, vertices: 1, edges: 1, faces: 1 })), 'invalid-argument');
});
