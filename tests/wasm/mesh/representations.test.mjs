// The JS contract of the representation tables, storage and per-representation queries.
// Expected values come from lecture 000's and 001's tables and from counting.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { withValidMesh } from '../../helpers/wasm-mesh.mjs';

const api = await loadWingspline();
const KEYS = ['independent-faces', 'vertex-face-tables', 'adjacency-lists', 'partial-adjacency-lists', 'edge-list', 'winged-edge'];
const KINDS = ['faces-around-vertex', 'edges-around-vertex', 'edges-of-face', 'faces-of-edge', 'neighbours-of-face'];

const withMesh = (input, body) => withValidMesh(api, input, body);

const sortedList = (a) => Array.from(a).sort((x, y) => x - y);
// Rows are objects keyed by the descriptors' column names: one column of them.
const column = (rows, name) => rows.map((row) => row[name]);
const xyz = (rows) => rows.map(({ x, y, z }) => [x, y, z]);

test('lecture 000: the slide\'s face tables in the independent-faces and vertex-face tables', () => {
  const input = api.lectureExample();
  withMesh(input, (mesh) => {
    const reps = mesh.representations();
    assert.deepEqual(Object.keys(reps).sort(), [...KEYS].sort());
    const x = (i) => Array.from(input.positions.subarray(3 * (i - 1), 3 * i)); // slide's (x_i, y_i, z_i)
    // F1 (x1)(x2)(x3), F2 (x2)(x4)(x3), F3 (x2)(x5)(x4).
    assert.deepEqual(column(reps['independent-faces'].faces, 'corners'), [[x(1), x(2), x(3)], [x(2), x(4), x(3)], [x(2), x(5), x(4)]]);
    assert.deepEqual(column(reps['vertex-face-tables'].faces, 'vertices'), [[0, 1, 2], [1, 3, 2], [1, 4, 3]]);
    assert.deepEqual(xyz(reps['vertex-face-tables'].vertices), [1, 2, 3, 4, 5].map(x));
    assert.deepEqual(reps['vertex-face-tables'].totals, { vertices: 5, faces: 3 });
    // v2's full adjacency: edges e2 e3 e5 e6, faces F1 F2 F3; partial keeps only the edges.
    const v2 = reps['adjacency-lists'].vertices[1];
    assert.deepEqual(v2.edges, [1, 2, 4, 5]);
    assert.deepEqual(v2.faces, [0, 1, 2]);
    assert.deepEqual(sortedList(v2.vertices), [0, 2, 3, 4]);
    assert.deepEqual(reps['partial-adjacency-lists'].vertices[1], { position: x(2), edges: [1, 2, 4, 5] });
    assert.deepEqual(reps['adjacency-lists'].edges[2].faces, [0, 1]); // e3: L = F1, R = F2
    assert.equal(reps['winged-edge'].edges[2].left, 0);
  });
});

test('lecture 001: Foley\'s edge list E = (V1, V2, P1, P2), polygons as edge lists', () => {
  withMesh(api.foleyExample(), (mesh) => {
    const list = mesh.representations()['edge-list'];
    // E1 = (V1,V2,P1,l) E2 = (V2,V3,P2,l) E3 = (V3,V4,P2,l) E4 = (V4,V2,P1,P2) E5 = (V4,V1,P1,l), 0-based, l = -1.
    assert.deepEqual(list.edges, [
      { v1: 0, v2: 1, p1: 0, p2: -1 }, { v1: 1, v2: 2, p1: 1, p2: -1 }, { v1: 2, v2: 3, p1: 1, p2: -1 },
      { v1: 3, v2: 1, p1: 0, p2: 1 }, { v1: 3, v2: 0, p1: 0, p2: -1 },
    ]);
    assert.deepEqual(column(list.polygons, 'edges'), [[0, 3, 4], [1, 2, 3]]); // P1 = (E1, E4, E5), P2 = (E2, E3, E4)
  });
});

test('limit cuts every table to its first rows; totals stay whole', () => {
  withMesh(api.generateMesh('grid', { nx: 6, ny: 5 }), (mesh) => {
    const c = mesh.counts();
    const reps = mesh.representations({ limit: 4 });
    for (const key of KEYS) {
      for (const [name, rows] of Object.entries(reps[key])) {
        if (Array.isArray(rows)) assert.ok(rows.length <= 4, `${key}.${name} has ${rows.length} rows`);
      }
    }
    assert.equal(reps['edge-list'].edges.length, 4);
    assert.deepEqual(reps['edge-list'].totals, { vertices: c.vertices, edges: c.edges, polygons: c.faces });
    assert.equal(reps['independent-faces'].faces.length, 4);
    assert.equal(reps['independent-faces'].totals.faces, c.faces);
    const full = mesh.representations();
    assert.deepEqual(reps['adjacency-lists'].faces, full['adjacency-lists'].faces.slice(0, 4));
    assert.throws(() => mesh.representations({ limit: -1 }), (err) => err.code === 'invalid-argument');
  });
});

test('storage: entries from the arrays equal the analytic counts', () => {
  withMesh(api.generateMesh('cube'), (mesh) => {
    const s = mesh.storage();
    const V = 8, E = 12, F = 6, C = 24; // six quads
    assert.equal(s['independent-faces'].entries, 3 * C + F + 1);
    assert.equal(s['independent-faces'].bytes, 8 * 3 * C + 4 * (F + 1));
    assert.equal(s['vertex-face-tables'].entries, 3 * V + F + 1 + C);
    assert.equal(s['edge-list'].entries, 3 * V + 4 * E + F + 1 + C);
    assert.equal(s['winged-edge'].entries, 4 * V + 8 * E + F);
    assert.equal(s['winged-edge'].bytes, mesh.bytes());
    for (const key of KEYS) {
      assert.equal(s[key].arrays.reduce((n, a) => n + a.entries, 0), s[key].entries, key);
      assert.equal(s[key].arrays.reduce((n, a) => n + a.bytes, 0), s[key].bytes, key);
    }
    // Full lists store more than partial lists, which store more than the winged edge here.
    assert.ok(s['adjacency-lists'].entries > s['partial-adjacency-lists'].entries);
  });
});

test('every query gives the same answer set in all six representations', () => {
  const meshes = {
    lecture: api.lectureExample(),
    foley: api.foleyExample(),
    cube: api.generateMesh('cube'),
    grid: api.generateMesh('grid', { nx: 3, ny: 2 }),
    sphere: api.generateMesh('sphere', { slices: 5, stacks: 4 }),
    fan: api.generateMesh('fan', { n: 4 }),
  };
  for (const [name, input] of Object.entries(meshes)) {
    withMesh(input, (mesh) => {
      const c = mesh.counts();
      for (const kind of KINDS) {
        const n = kind.endsWith('vertex') ? c.vertices : kind.endsWith('edge') ? c.edges : c.faces;
        for (let x = 0; x < n; x += 1) {
          const answers = mesh.query(kind, x);
          assert.deepEqual(Object.keys(answers), KEYS);
          const expected = sortedList(answers['winged-edge'].answer);
          assert.ok(expected.length > 0, `${name} ${kind} ${x}`);
          for (const key of KEYS) {
            assert.ok(answers[key].answer instanceof Int32Array);
            assert.deepEqual(sortedList(answers[key].answer), expected, `${name} ${kind} ${x} ${key}`);
            assert.ok(Number.isInteger(answers[key].entriesRead) && answers[key].entriesRead > 0);
          }
        }
      }
      // The winged-edge answers are its own traversals (the lecture's walk around v).
      assert.deepEqual(Array.from(mesh.query('edges-around-vertex', 0)['winged-edge'].answer), Array.from(mesh.edgesAroundVertex(0)));
    });
  }
});

test('walks cost the output, scans cost the mesh (two grid sizes)', () => {
  const cost = (nx) => withMesh(api.generateMesh('grid', { nx, ny: nx }), (mesh) => {
    const v = 4 * (nx + 1) + 4; // grid vertex (4, 4): interior, valence 6
    const q = mesh.query('faces-around-vertex', v);
    assert.equal(q['winged-edge'].answer.length, 6);
    return { q, faces: mesh.counts().faces };
  });
  const small = cost(8);
  const large = cost(16);
  assert.equal(large.faces, 4 * small.faces);
  for (const key of ['winged-edge', 'adjacency-lists', 'partial-adjacency-lists']) {
    assert.equal(large.q[key].entriesRead, small.q[key].entriesRead, key);
  }
  assert.equal(small.q['winged-edge'].entriesRead, 1 + 3 * 6); // vertex edge, then S, face, wing per step
  for (const key of ['independent-faces', 'vertex-face-tables', 'edge-list']) {
    assert.ok(small.q[key].entriesRead >= small.faces, key);
    assert.ok(large.q[key].entriesRead > 3 * small.q[key].entriesRead, key);
  }
});

test('setVertexPosition rewrites the stored copies and the scans find the new point', () => {
  withMesh(api.generateMesh('cube'), (mesh) => {
    const before = mesh.storage();
    const r = mesh.setVertexPosition(0, [-1, -2, -3]);
    assert.deepEqual(r.changedEntries, {
      'independent-faces': 3, 'vertex-face-tables': 1, 'adjacency-lists': 1, 'partial-adjacency-lists': 1, 'edge-list': 1, 'winged-edge': 1,
    });
    const reps = mesh.representations();
    const copies = column(reps['independent-faces'].faces, 'corners').flat().filter((p) => p.join() === '-1,-2,-3').length;
    assert.equal(copies, 3);
    assert.deepEqual(reps['vertex-face-tables'].vertices[0], { x: -1, y: -2, z: -3 });
    assert.deepEqual(reps['edge-list'].vertices[0], { position: [-1, -2, -3] });
    assert.deepEqual(reps['adjacency-lists'].vertices[0].position, [-1, -2, -3]);
    assert.deepEqual(sortedList(mesh.query('faces-around-vertex', 0)['independent-faces'].answer), [0, 2, 4]);
    assert.deepEqual(mesh.storage(), before); // moving a point never changes the storage
  });
});

test('query errors are coded; representations do not leak across build/dispose', () => {
  withMesh(api.lectureExample(), (mesh) => {
    assert.throws(() => mesh.query('faces-of-vertex', 0), (err) => err.code === 'unknown-query');
    assert.throws(() => mesh.query('faces-of-edge', 7), (err) => err.code === 'invalid-element' && /edges e1 to e7/.test(err.message));
    assert.throws(() => mesh.query('edges-of-face', 1.5), (err) => err.code === 'invalid-argument');
    assert.equal(mesh.query('faces-of-edge', 6)['edge-list'].answer.length, 1); // e7 is on the boundary
  });
  const input = api.generateMesh('sphere', { slices: 6, stacks: 4 });
  const cycle = () => {
    const mesh = api.buildMesh(input);
    assert.equal(mesh.validate().ok, true);
    mesh.representations({ limit: 3 });
    mesh.query('faces-around-vertex', 0);
    mesh.setVertexPosition(1, [0, 0, 2]);
    mesh.dispose();
    assert.throws(() => mesh.storage(), (err) => err.code === 'disposed');
  };
  cycle();
  const before = api.memoryUsage();
  for (let i = 0; i < 200; i += 1) cycle();
  const after = api.memoryUsage();
  assert.equal(after.heapInUse, before.heapInUse);
  assert.equal(api.liveMeshCount(), 0);
});

test('the winged edge\'s bytes stay its own: the other representations are built on first use', () => {
  const input = api.generateMesh('grid', { nx: 20, ny: 20, layout: 'csr' });
  const before = api.memoryUsage().heapInUse;
  const mesh = api.buildMesh(input);
  try {
    const built = api.memoryUsage().heapInUse - before;
    assert.equal(mesh.validate().ok, true);
    const own = mesh.bytes();
    mesh.storage(); // first use: now the four others exist in the core
    const withOthers = api.memoryUsage().heapInUse - before;
    const s = mesh.storage();
    const others = KEYS.slice(0, 5).reduce((n, key) => n + s[key].bytes, 0);
    assert.equal(mesh.bytes(), own);
    assert.ok(built < own + others / 2, `build alone grew the heap by ${built} bytes`);
    assert.ok(withOthers - built >= others, `the others hold ${others} bytes of arrays`);
  } finally {
    mesh.dispose();
  }
});

test('faces are read back from the winged edge: the tables show the faces as given', () => {
  // Triangles and quads, each listed from an arbitrary corner. The mesh keeps no copy of
  // the face set: the tables are read back from the winged edge, whose default face edge
  // is each face's first side, so each face must come back from its first corner.
  const positions = new Float64Array([0, 0, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 0, 1, 0, 1, 2, 0, 2.5, 0.5, 0]);
  const faces = [[4, 0, 1], [1, 2, 3, 4], [3, 6, 5, 4], [7, 3, 2]];
  const faceOffsets = new Int32Array([0, 3, 7, 11, 14]);
  const faceVertices = new Int32Array(faces.flat());
  const mesh = api.buildMesh({ positions, faceOffsets, faceVertices });
  try {
    assert.equal(mesh.validate().ok, true);
    const reps = mesh.representations();
    assert.deepEqual(column(reps['vertex-face-tables'].faces, 'vertices'), faces);
    // Each face's edge in the winged-edge table is its first side (first two corners).
    const { edges, faces: faceRows } = mesh.wingedEdge();
    faceRows.forEach(({ edge }, f) => {
      const side = edges[edge].left === f ? [edges[edge].start, edges[edge].end] : [edges[edge].end, edges[edge].start];
      assert.deepEqual(side, faces[f].slice(0, 2), `F${f + 1}`);
    });
  } finally {
    mesh.dispose();
  }
});

test('with chosen face edges the mesh keeps its own copy of the faces: the caller may reuse its arrays', () => {
  // The lecture's mesh with the slide's face edges (F2's walk starts at e3, not at its first
  // corner), built from typed arrays the caller overwrites before the tables are first built.
  const ex = api.lectureExample();
  const faceOffsets = new Int32Array([0, 3, 6, 9]);
  const faceVertices = new Int32Array(ex.faces.flat());
  const mesh = api.buildMesh({ positions: ex.positions, faceOffsets, faceVertices, edges: ex.edges, vertexEdges: ex.vertexEdges, faceEdges: ex.faceEdges });
  try {
    faceVertices.set([4, 3, 2, 1, 0, 4, 3, 2, 1]);
    assert.deepEqual(column(mesh.representations()['vertex-face-tables'].faces, 'vertices'), [[0, 1, 2], [1, 3, 2], [1, 4, 3]]);
  } finally {
    mesh.dispose();
  }
});

test('a window of rows (offset, limit) is the same rows of the whole tables', () => {
  withMesh(api.generateMesh('grid', { nx: 7, ny: 5 }), (mesh) => {
    const whole = mesh.representations();
    const tables = (reps) => ({
      'independent-faces': [reps['independent-faces'].faces],
      'vertex-face-tables': [reps['vertex-face-tables'].vertices, reps['vertex-face-tables'].faces],
      'adjacency-lists': ['vertices', 'edges', 'faces'].map((k) => reps['adjacency-lists'][k]),
      'partial-adjacency-lists': ['vertices', 'edges', 'faces'].map((k) => reps['partial-adjacency-lists'][k]),
      'edge-list': ['vertices', 'edges', 'polygons'].map((k) => reps['edge-list'][k]),
      'winged-edge': ['vertices', 'edges', 'faces'].map((k) => reps['winged-edge'][k]),
    });
    const all = tables(whole);
    // Windows at the start, in the middle, across the end and wholly past the end.
    for (const [offset, limit] of [[0, 3], [11, 6], [40, 100], [500, 5]]) {
      const part = mesh.representations({ offset, limit });
      const got = tables(part);
      for (const key of KEYS) {
        all[key].forEach((rows, i) => assert.deepEqual(got[key][i], rows.slice(offset, offset + limit), `${key} table ${i} at ${offset}+${limit}`));
      }
    }
    assert.throws(() => mesh.representations({ offset: -1 }), { code: 'invalid-argument' });
  });
});
