// Through the JS API: api.subdivide, api.subdivisionSteps, api.reconnectionPlayback, api.limitPositions,
// api.subdivideCurve. Expected values: the formulas worked by hand (tetrahedron, cube), an
// independent recomputation from the face lists in this file (not the winged edge's
// walks), invariants (counts, chi, validate, symmetry, similarity transforms, masks summing
// to 1) and the existing knot insertion (api.insertKnot).
// Tolerance: |a - b| <= 1e-12 * s, s = the largest coordinate magnitude of the input (its
// own length unit), the same at every scale.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();

function withMeshes(body) {
  const made = [];
  const keep = (m) => { made.push(m); return m; };
  try {
    return body(keep);
  } finally {
    for (const m of made) m.dispose();
  }
}

const at = (p, v) => [p[3 * v], p[3 * v + 1], p[3 * v + 2]];
const add = (a, b) => a.map((x, i) => x + b[i]);
const sub = (a, b) => a.map((x, i) => x - b[i]);
const mul = (a, s) => a.map((x) => x * s);
const len = (a) => Math.hypot(...a);
const scaleOf = (p) => Math.max(...Array.from(p, Math.abs), 1e-300);
function near(a, b, s, rel = 1e-12, what = '') {
  for (let k = 0; k < 3; k += 1) assert.ok(Math.abs(a[k] - b[k]) <= rel * s, `${what}: ${a} vs ${b}`);
}

// The face lists and the positions, read through the API.
function facesOf(mesh) {
  const F = mesh.counts().faces;
  return Array.from({ length: F }, (_, f) => Array.from(mesh.verticesOfFace(f)));
}

// Neighbours, faces at each vertex, boundary neighbours and the faces on each vertex pair,
// by plain loops over the face lists.
function facts(faces, V) {
  const nb = Array.from({ length: V }, () => new Set());
  const fa = Array.from({ length: V }, () => new Set());
  const bn = Array.from({ length: V }, () => new Set());
  const onPair = new Map();
  const key = (a, b) => `${Math.min(a, b)},${Math.max(a, b)}`;
  faces.forEach((c, f) => c.forEach((a, k) => {
    const b = c[(k + 1) % c.length];
    nb[a].add(b); nb[b].add(a); fa[a].add(f);
    onPair.set(key(a, b), [...(onPair.get(key(a, b)) ?? []), f]);
  }));
  for (const [k, fs] of onPair) {
    if (fs.length === 1) { const [a, b] = k.split(',').map(Number); bn[a].add(b); bn[b].add(a); }
  }
  return { nb, fa, bn, onPair, key };
}

const beta = (n) => (5 / 8 - (3 / 8 + Math.cos((2 * Math.PI) / n) / 4) ** 2) / n;
const centroid = (p, c) => mul(c.reduce((s, v) => add(s, at(p, v)), [0, 0, 0]), 1 / c.length);

function expectedVertex(fx, faces, p, v, scheme) {
  const pv = at(p, v);
  const n = fx.nb[v].size;
  if (n === 0) return pv;
  if (fx.bn[v].size > 0) return add(mul(pv, 0.75), mul([...fx.bn[v]].reduce((s, u) => add(s, at(p, u)), [0, 0, 0]), 0.125));
  const sum = [...fx.nb[v]].reduce((s, u) => add(s, at(p, u)), [0, 0, 0]);
  if (scheme === 'loop') return add(mul(pv, 1 - n * beta(n)), mul(sum, beta(n)));
  const fsum = [...fx.fa[v]].reduce((s, f) => add(s, centroid(p, faces[f])), [0, 0, 0]);
  return add(mul(pv, (n - 2) / n), mul(add(sum, fsum), 1 / (n * n)));
}

function expectedEdge(fx, faces, p, a, b, scheme) {
  const fs = fx.onPair.get(fx.key(a, b));
  const ends = add(at(p, a), at(p, b));
  if (fs.length === 1) return mul(ends, 0.5);
  if (scheme === 'catmull-clark') return mul(add(ends, add(centroid(p, faces[fs[0]]), centroid(p, faces[fs[1]]))), 0.25);
  const opp = fs.flatMap((f) => faces[f].filter((c) => c !== a && c !== b)).reduce((s, u) => add(s, at(p, u)), [0, 0, 0]);
  return add(mul(ends, 0.375), mul(opp, 0.125));
}

function checkStep(mesh, scheme, keep) {
  const before = mesh.wingedEdgeArrays();
  const version = mesh.version;
  const out = keep(api.subdivide(mesh, { scheme }));
  const { vertices: V, edges: E, faces: F } = mesh.counts();
  const faces = facesOf(mesh);
  const corners = faces.reduce((s, c) => s + c.length, 0);
  const c = out.counts();
  if (scheme === 'loop') assert.deepEqual([c.vertices, c.edges, c.faces], [V + E, 2 * E + 3 * F, 4 * F]);
  else assert.deepEqual([c.vertices, c.edges, c.faces], [V + E + F, 2 * E + corners, corners]);
  assert.equal(c.vertices - c.edges + c.faces, V - E + F, 'chi kept');
  assert.deepEqual(out.validate().problems, []);
  // The input is untouched.
  assert.deepEqual(mesh.wingedEdgeArrays(), before);
  assert.equal(mesh.version, version);
  const p = before.positions;
  const q = out.wingedEdgeArrays().positions;
  const s = scaleOf(p);
  const fx = facts(faces, V);
  for (let v = 0; v < V; v += 1) near(at(q, v), expectedVertex(fx, faces, p, v, scheme), s, 1e-12, `vertex ${v}`);
  const ed = before.edges;
  for (let e = 0; e < E; e += 1) near(at(q, V + e), expectedEdge(fx, faces, p, ed[8 * e], ed[8 * e + 1], scheme), s, 1e-12, `edge ${e}`);
  if (scheme === 'catmull-clark') faces.forEach((cs, f) => near(at(q, V + E + f), centroid(p, cs), s, 1e-12, `face ${f}`));
  return out;
}

function jittered(kind, options, seed, keep) {
  const rnd = random(seed);
  const mesh = keep(api.buildMesh(api.generateMesh(kind, options)));
  const p = mesh.wingedEdgeArrays().positions;
  for (let v = 0; v < p.length / 3; v += 1) mesh.setVertexPosition(v, add(at(p, v), [0, 0, 0].map(() => 0.1 * (rnd() - 0.5))));
  return mesh;
}

test('Loop on the tetrahedron by hand: vertex points v/4, edge points (a + b)/4, limit v/5', () => withMeshes((keep) => {
  // beta(3) = 3/16; the corners sum to 0: (1 - 9/16) v + 3/16 (-v) = v/4; 3/8 (a + b) + 1/8 (c + d)
  // = (a + b)/4. Limit: chi = 1/(3/(8 beta) + 3) = 1/5, (1 - 3/5) v - v/5 = v/5.
  const tet = keep(api.buildMesh(api.generateMesh('tetrahedron')));
  const out = checkStep(tet, 'loop', keep);
  const p = tet.wingedEdgeArrays().positions;
  const q = out.wingedEdgeArrays().positions;
  const ed = tet.wingedEdgeArrays().edges;
  for (let v = 0; v < 4; v += 1) near(at(q, v), mul(at(p, v), 1 / 4), 1, 1e-15);
  for (let e = 0; e < 6; e += 1) near(at(q, 4 + e), mul(add(at(p, ed[8 * e]), at(p, ed[8 * e + 1])), 1 / 4), 1, 1e-15);
  const lim = api.limitPositions(tet, { scheme: 'loop' });
  assert.ok(lim instanceof Float64Array);
  for (let v = 0; v < 4; v += 1) near(at(lim, v), mul(at(p, v), 1 / 5), 1, 1e-14);
}));

test('Catmull-Clark on the cube by hand: c + 5/9 (v - c), edge points c + 3/4 (m - c), limit c + (v - c)/2', () => withMeshes((keep) => {
  const cube = keep(api.buildMesh(api.generateMesh('cube')));
  const out = checkStep(cube, 'catmull-clark', keep);
  const p = cube.wingedEdgeArrays().positions;
  const q = out.wingedEdgeArrays().positions;
  const ed = cube.wingedEdgeArrays().edges;
  const c = [0.5, 0.5, 0.5];
  near(at(q, 0), [2 / 9, 2 / 9, 2 / 9], 1, 1e-15);
  for (let v = 0; v < 8; v += 1) near(at(q, v), add(c, mul(sub(at(p, v), c), 5 / 9)), 1, 1e-15);
  for (let e = 0; e < 12; e += 1) {
    const m = mul(add(at(p, ed[8 * e]), at(p, ed[8 * e + 1])), 0.5);
    near(at(q, 8 + e), add(c, mul(sub(m, c), 0.75)), 1, 1e-15);
  }
  const lim = api.limitPositions(cube, { scheme: 'catmull-clark' });
  for (let v = 0; v < 8; v += 1) near(at(lim, v), add(c, mul(sub(at(p, v), c), 0.5)), 1, 1e-14);
  // Symmetric input, symmetric result: after three steps every old vertex is as far from
  // the centre as vertex 0.
  const three = keep(api.subdivide(cube, { scheme: 'catmull-clark', steps: 3 }));
  const q3 = three.wingedEdgeArrays().positions;
  const r0 = len(sub(at(q3, 0), c));
  for (let v = 0; v < 8; v += 1) assert.ok(Math.abs(len(sub(at(q3, v), c)) - r0) <= 1e-13 * r0);
  assert.deepEqual(three.counts().faces, 6 * 4 ** 3);
}));

test('random jittered spheres, grids and fans: every position by the formulas, counts, chi, validate', () => withMeshes((keep) => {
  for (let seed = 1; seed <= 12; seed += 1) {
    const kind = ['sphere', 'grid', 'fan'][seed % 3];
    const options = kind === 'sphere' ? { slices: 4 + (seed % 5), stacks: 3 + (seed % 4) } : kind === 'grid' ? { nx: 2 + (seed % 4), ny: 2 + (seed % 3) } : { n: 3 + (seed % 5) };
    const mesh = jittered(kind, options, seed, keep);
    checkStep(mesh, 'loop', keep);
    checkStep(mesh, 'catmull-clark', keep);
    // After joins (polygons), Catmull-Clark still follows the formulas.
    const e = mesh.counts().edges >> 1;
    if (mesh.check('join-faces', e).ok) { mesh.joinFaces(e); mesh.compact(); checkStep(mesh, 'catmull-clark', keep); }
  }
}));

test('subdivisionSteps: phases in order, every mask sums to 1 and reproduces subdivide', () => withMeshes((keep) => {
  for (const [kind, scheme] of [['sphere', 'loop'], ['grid', 'catmull-clark'], ['cube', 'catmull-clark'], ['tetrahedron', 'loop']]) {
    const mesh = keep(api.buildMesh(api.generateMesh(kind, kind === 'sphere' ? { slices: 7, stacks: 5 } : {})));
    const st = api.subdivisionSteps(mesh, { scheme });
    assert.deepEqual(st.phases.map((p) => p.name), ['face-points', 'edge-points', 'vertex-points', 'reconnection']);
    const out = keep(api.subdivide(mesh, { scheme }));
    const oc = out.counts();
    assert.deepEqual(st.counts, { vertices: oc.vertices, edges: oc.edges, faces: oc.faces });
    const { offsets, vertices, weights } = st.masks;
    const p = mesh.wingedEdgeArrays().positions;
    const q = out.wingedEdgeArrays().positions;
    assert.equal(offsets.length - 1, out.counts().vertices);
    for (let i = 0; i + 1 < offsets.length; i += 1) {
      let sum = 0;
      let point = [0, 0, 0];
      for (let k = offsets[i]; k < offsets[i + 1]; k += 1) { sum += weights[k]; point = add(point, mul(at(p, vertices[k]), weights[k])); }
      assert.ok(Math.abs(sum - 1) <= 1e-14, `mask ${i} sums to ${sum}`);
      near(point, at(q, i), scaleOf(p), 1e-12, `mask ${i}`);
      near(at(st.positions, i), at(q, i), scaleOf(p), 1e-12, `position ${i}`);
    }
    // The rule of every vertex point names its valence's stencil; the result's faces as CSR.
    assert.equal(st.ruleNames[st.rules[0]].startsWith('vertex-'), true);
    assert.equal(st.faceOffsets.length - 1, out.counts().faces);
  }
}));

// The reconnection as the API gives it: its steps, played into empty tables, are the next
// level's winged-edge arrays (wingedEdgeArrays of api.subdivide), each entry written once;
// the open grid has boundary work (line 4), the closed meshes none.
test('reconnectionPlayback: played into empty tables it gives the next level\'s tables, each entry once', () => withMeshes((keep) => {
  const FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
  for (const [kind, scheme] of [['tetrahedron', 'loop'], ['cube', 'catmull-clark'], ['grid', 'catmull-clark'], ['sphere', 'loop']]) {
    const mesh = keep(api.buildMesh(api.generateMesh(kind, kind === 'sphere' ? { slices: 6, stacks: 4 } : kind === 'grid' ? { nx: 3, ny: 2 } : {})));
    const r = api.reconnectionPlayback(mesh, { scheme });
    const next = keep(api.subdivide(mesh, { scheme })).wingedEdgeArrays();
    assert.equal(r.lines.length, 6);
    assert.equal(r.sources.length, r.steps.length);
    const edges = new Int32Array(next.edges.length).fill(-1);
    const vertexEdge = new Int32Array(next.vertexEdge.length).fill(-1);
    const faceEdge = new Int32Array(next.faceEdge.length).fill(-1);
    const seen = new Set();
    for (const s of r.steps) {
      const key = `${s.table}:${s.row}:${s.field}`;
      assert.ok(!seen.has(key), `${key} written twice`);
      seen.add(key);
      assert.equal(s.before, -1);
      if (s.table === 'edge') edges[8 * s.row + FIELDS.indexOf(s.field)] = s.after;
      else if (s.table === 'vertex') vertexEdge[s.row] = s.after;
      else faceEdge[s.row] = s.after;
    }
    assert.deepEqual(edges, next.edges, `${kind}: edge table`);
    assert.deepEqual(vertexEdge, next.vertexEdge, `${kind}: vertex table`);
    assert.deepEqual(faceEdge, next.faceEdge, `${kind}: face table`);
    const boundary = r.steps.filter((s) => s.phase === 4).length;
    if (kind === 'grid') assert.ok(boundary > 0, 'the grid has a boundary'); else assert.equal(boundary, 0);
  }
  assert.throws(() => api.reconnectionPlayback(keep(api.buildMesh(api.generateMesh('cube'))), { scheme: 'loop' }), (e) => e.code === 'not-a-triangle-mesh');
}));

test('similarity transforms commute with a step, at scales 1e-6 to 1e6', () => withMeshes((keep) => {
  const rnd = random(77);
  for (const [i, scale] of [1e-6, 1, 1e6].entries()) {
    for (const scheme of ['loop', 'catmull-clark']) {
      const mesh = jittered('sphere', { slices: 6, stacks: 4 }, 10 + i, keep);
      const moved = jittered('sphere', { slices: 6, stacks: 4 }, 10 + i, keep);
      const a = Math.PI * rnd();
      const shift = [rnd(), rnd(), rnd()].map((x) => 10 * scale * x);
      const T = ([x, y, z]) => [scale * (Math.cos(a) * x - Math.sin(a) * y) + shift[0], scale * (Math.sin(a) * x + Math.cos(a) * y) + shift[1], scale * z + shift[2]];
      const p = mesh.wingedEdgeArrays().positions;
      for (let v = 0; v < p.length / 3; v += 1) moved.setVertexPosition(v, T(at(p, v)));
      const qa = keep(api.subdivide(moved, { scheme })).wingedEdgeArrays().positions;
      const qb = keep(api.subdivide(mesh, { scheme })).wingedEdgeArrays().positions;
      const s = scaleOf(qa);
      for (let v = 0; v < qa.length / 3; v += 1) near(at(qa, v), T(at(qb, v)), s, 1e-13, `${scheme} ${scale} vertex ${v}`);
    }
  }
}));

test('refusals: polygons for Loop, gaps, too large (with the count), bad options; nothing leaks', () => withMeshes((keep) => {
  const live = api.liveMeshCount();
  const cube = keep(api.buildMesh(api.generateMesh('cube')));
  assert.throws(() => api.subdivide(cube, { scheme: 'loop' }), (e) => e.code === 'not-a-triangle-mesh' && /F1/.test(e.message));
  assert.throws(() => api.subdivisionSteps(cube, { scheme: 'loop' }), { code: 'not-a-triangle-mesh' });
  assert.throws(() => api.subdivide(cube, { scheme: 'butterfly' }), { code: 'unknown-scheme' });
  assert.throws(() => api.subdivide(cube, { scheme: 'catmull-clark', steps: 1.5 }), { code: 'invalid-argument' });
  assert.throws(() => api.subdivide({}, { scheme: 'loop' }), { code: 'invalid-argument' });
  // 24 * 4^7 = 393,216 faces: above meshLimits.maxFaces (200,000).
  assert.throws(() => api.subdivide(cube, { scheme: 'catmull-clark', steps: 8 }), (e) => e.code === 'too-large' && /393,216 faces/.test(e.message));
  const sphere = keep(api.buildMesh(api.generateMesh('sphere', { slices: 6, stacks: 4 })));
  sphere.collapseEdge(3);
  assert.throws(() => api.subdivide(sphere, { scheme: 'loop' }), { code: 'mesh-has-gaps' });
  assert.throws(() => api.limitPositions(sphere, { scheme: 'loop' }), { code: 'mesh-has-gaps' });
  assert.equal(api.liveMeshCount(), live + 2, 'a refused subdivision makes no mesh');
  const zero = keep(api.subdivide(cube, { scheme: 'catmull-clark', steps: 0 }));
  assert.deepEqual(zero.wingedEdgeArrays(), cube.wingedEdgeArrays());
}));

// ------------------------------------------------------------------ curves

test('one cubic subdivision step equals api.insertKnot at the middle of every span', () => {
  // A closed polygon P_0..P_(n-1) as the uniform cubic B-spline of W_i = P_(i mod n),
  // i = 0..n+5, knots 0..n+9, domain [3, n+6]. Inserting every span's middle gives points
  // of spacing-1/2 knots; those whose support [t_j, t_(j+4)] lies in the domain are the
  // closed step's points V_2, E_2, V_3, ... (the step lists V_0, E_0, V_1, E_1, ...).
  const rnd = random(16);
  for (const n of [3, 5, 8]) {
    const P = Array.from({ length: 2 * n }, () => rnd() * 2 - 1);
    let curve = { kind: 'bspline', dim: 2, degree: 3, points: Array.from({ length: n + 6 }, (_, i) => [P[2 * (i % n)], P[2 * (i % n) + 1]]).flat(), knots: Array.from({ length: n + 10 }, (_, j) => j) };
    for (let span = 3; span < n + 6; span += 1) curve = api.insertKnot(curve, span + 0.5).curve;
    const S = api.subdivideCurve(P, 2, { scheme: 'cubic-bspline', closed: true });
    assert.equal(S.length, 4 * n);
    for (let k = 0; k <= 2 * n + 2; k += 1) {
      const j = 3 + k;
      const i = (4 + k) % (2 * n);
      assert.ok(Math.abs(curve.points[2 * j] - S[2 * i]) <= 1e-14 && Math.abs(curve.points[2 * j + 1] - S[2 * i + 1]) <= 1e-14, `n ${n} k ${k}`);
    }
  }
});

test('Chaikin: closed polygons approach their quadratic B-spline about 4x per step; open ones shorten by the rule', () => {
  const rnd = random(4);
  const n = 6;
  const P = Array.from({ length: 2 * n }, () => rnd() * 2 - 1);
  const curve = { kind: 'bspline', dim: 2, degree: 2, points: [...P, ...P.slice(0, 4)], knots: Array.from({ length: n + 5 }, (_, j) => j) };
  const params = Float64Array.from({ length: 8001 }, (_, s) => 2 + (n * s) / 8000);
  const samples = api.evaluateCurve(curve, params);
  const distance = (poly) => {
    let worst = 0;
    for (let i = 0; i < poly.length; i += 2) {
      let best = Infinity;
      for (let j = 0; j < samples.length; j += 2) best = Math.min(best, Math.hypot(poly[i] - samples[j], poly[i + 1] - samples[j + 1]));
      worst = Math.max(worst, best);
    }
    return worst;
  };
  let previous = distance(P);
  for (let steps = 1; steps <= 4; steps += 1) {
    const d = distance(api.subdivideCurve(P, 2, { scheme: 'chaikin', closed: true, steps }));
    assert.ok(d < previous / 3, `step ${steps}: ${previous} -> ${d}`);
    if (steps >= 2) assert.ok(d > previous / 5, `step ${steps}: ${previous} -> ${d}`);
    previous = d;
  }
  const open = api.subdivideCurve(P, 2, { scheme: 'chaikin', closed: false });
  assert.equal(open.length, 2 * 2 * (n - 1));
  assert.ok(Math.abs(open[0] - (0.75 * P[0] + 0.25 * P[2])) <= 1e-15);
  assert.throws(() => api.subdivideCurve([0, 0, 1, 1], 2, { scheme: 'chaikin' }), { code: 'too-few-points' });
  assert.throws(() => api.subdivideCurve(P, 2, { scheme: 'loop' }), { code: 'unknown-scheme' });
  assert.throws(() => api.subdivideCurve(P, 2, { scheme: 'chaikin', steps: 21 }), { code: 'invalid-argument' });
});
