// Through the JS API: the Euler operations (splitEdge, splitFace, joinFaces,
// flipEdge, collapseEdge, pokeFace), mesh.check, change records read by their descriptor,
// gaps and compact(), the exported file. Expected tables of the lecture example are worked
// out by hand from lecture 000's conventions (the same as tests/native/test_mesh_euler.cpp).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from 'wingspline';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline();

function withMesh(input, body) {
  const mesh = api.buildMesh(input);
  try {
    return body(mesh);
  } finally {
    mesh.dispose();
  }
}
const withLecture = (body) => withMesh(api.lectureExample(), body);

const errors = (mesh) => mesh.validate().problems.filter((p) => p.severity === 'error');

// The slide's edge row "e3: v2 v3 F1 F2 e2 e5 e1 e4" (S E L R SL SR EL ER), 1-based labels.
function rowText(r, e) {
  const lab = (p, i) => (i === -1 ? '-' : `${p}${i + 1}`);
  return `e${e + 1}: ${lab('v', r.start)} ${lab('v', r.end)} ${lab('F', r.left)} ${lab('F', r.right)} ` +
    `${lab('e', r.startLeft)} ${lab('e', r.startRight)} ${lab('e', r.endLeft)} ${lab('e', r.endRight)}`;
}
const edgeRows = (mesh) => mesh.wingedEdge().edges.map(rowText);

function snapshot(mesh) {
  const a = mesh.wingedEdgeArrays();
  const gaps = mesh.gaps();
  return JSON.stringify({
    positions: Array.from(a.positions), vertexEdge: Array.from(a.vertexEdge), edges: Array.from(a.edges), faceEdge: Array.from(a.faceEdge),
    gaps: [Array.from(gaps.vertices), Array.from(gaps.edges), Array.from(gaps.faces)], version: mesh.coreVersion(),
  });
}

test('the operations and the change record are described once by the core', () => {
  const names = api.meshOperations.operations.map((o) => o.name);
  assert.deepEqual(names, ['split-edge', 'flip-edge', 'collapse-edge', 'join-faces', 'split-face', 'poke-face', 'split-vertex',
    'set-vertex-edge', 'set-face-edge']);
  const split = api.meshOperations.operations[0];
  assert.deepEqual(split.arguments.map((a) => [a.name, a.kind, a.optional]), [['e', 'edge', false], ['t', null, true]]);
  assert.equal(split.arguments[1].default, 0.5);
  // one key per operation the edit panel offers; the stored-edge choices have none
  const keys = api.meshOperations.operations.map((o) => o.shortcut).filter(Boolean);
  assert.equal(new Set(keys).size, keys.length);
  assert.deepEqual(api.meshOperations.operations.filter((o) => !o.shortcut).map((o) => o.name), ['set-vertex-edge', 'set-face-edge']);
  // every argument after the first that names an element says where its candidates come
  // from: a query of the first element's kind that the mesh answers
  withLecture((mesh0) => {
    for (const o of api.meshOperations.operations) {
      assert.ok(o.arguments[0].kind, o.name);
      for (const a of o.arguments.slice(1)) if (a.kind) assert.ok(mesh0.adjacency(a.choices, 0).length > 0, `${o.name}.${a.name}`);
    }
  });
  assert.deepEqual(api.meshOperations.tables, ['vertex', 'edge', 'face']);
  assert.ok(Object.isFrozen(api.meshOperations));
});

test('the declarations name the same operations as the registry, with its arguments', () => {
  const text = fs.readFileSync(new URL('../../../types/wingspline.d.ts', import.meta.url), 'utf8');
  const union = text.slice(text.indexOf('export type MeshOperation ='), text.indexOf('export type MeshOperationName'));
  const declared = [...union.matchAll(/\{ op: '([a-z-]+)';([^}]*)\}/g)].map((m) => [m[1],
    [...m[2].matchAll(/(\w+)(\?)?: number/g)].map((a) => `${a[1]}${a[2] ?? ''}`)]);
  const registry = api.meshOperations.operations.map((o) => [o.name, o.arguments.map((a) => `${a.name}${a.optional ? '?' : ''}`)]);
  assert.deepEqual(declared, registry);
});

test('splitEdge(e3): hand-worked tables, every assignment in order, v6 at the midpoint', () => withLecture((mesh) => {
  assert.deepEqual(mesh.check('split-edge', 2), { ok: true });
  const c = mesh.splitEdge(2);
  assert.deepEqual(edgeRows(mesh), ['e1: v1 v3 - F1 e2 e2 e4 e8', 'e2: v1 v2 F1 - e1 e1 e3 e6', 'e3: v2 v6 F1 F2 e2 e5 e8 e8',
    'e4: v3 v4 - F2 e1 e8 e7 e5', 'e5: v2 v4 F2 F3 e3 e6 e4 e7', 'e6: v2 v5 F3 - e5 e2 e7 e7', 'e7: v4 v5 - F3 e4 e5 e6 e6',
    'e8: v6 v3 F1 F2 e3 e3 e1 e4']);
  const w = mesh.wingedEdge();
  assert.deepEqual(w.vertices.map((v) => v.edge), [0, 5, 7, 4, 5, 7]);
  assert.deepEqual([w.vertices[5].x, w.vertices[5].y, w.vertices[5].z], [1, 1, 0]);
  assert.equal(c.op, 'split-edge');
  assert.deepEqual(Array.from(c.added.vertices), [5]);
  assert.deepEqual(Array.from(c.added.edges), [7]);
  assert.equal(c.steps.length, 15);
  // Each step names the algorithm's line that made it (c.phases, four lines for a split).
  assert.deepEqual(c.steps[0], { table: 'vertex', row: 5, field: 'edge', before: -1, after: 7, phase: 0 });
  assert.deepEqual(c.steps.at(-1), { table: 'vertex', row: 2, field: 'edge', before: 2, after: 7, phase: 3 });
  assert.equal(c.phases.length, 4);
  assert.deepEqual(c.steps.slice(9, 12).map((s) => `${s.row} ${s.field} ${s.before}->${s.after}`),
    ['2 end 2->5', '2 endLeft 0->7', '2 endRight 3->7']);
  assert.deepEqual(c.positions, [{ vertex: 5, before: [1, 1, 0], after: [1, 1, 0], step: 0 }]);
  assert.deepEqual(c.after, { topology: 1, geometry: 1 });
  assert.deepEqual(mesh.version, mesh.coreVersion());
  assert.deepEqual(mesh.counts().euler, 1);
  assert.deepEqual(errors(mesh), []);
}));

test('flipEdge(e3) and collapseEdge(e4) and pokeFace(F1): hand-worked rows', () => {
  withLecture((mesh) => {
    mesh.flipEdge(2);
    assert.deepEqual(edgeRows(mesh).slice(0, 5), ['e1: v1 v3 - F2 e2 e3 e4 e4', 'e2: v1 v2 F1 - e3 e1 e5 e6',
      'e3: v4 v1 F1 F2 e5 e4 e2 e1', 'e4: v3 v4 - F2 e1 e1 e7 e3', 'e5: v2 v4 F1 F3 e2 e6 e3 e7']);
  });
  withLecture((mesh) => {
    const c = mesh.collapseEdge(3);
    const rows = edgeRows(mesh);
    assert.deepEqual([rows[0], rows[2], rows[5], rows[6]], ['e1: v1 v3 - F1 e2 e2 e7 e3', 'e3: v2 v3 F1 F3 e2 e6 e1 e7',
      'e6: v2 v5 F3 - e3 e2 e7 e7', 'e7: v3 v5 - F3 e1 e3 e6 e6']);
    assert.deepEqual(Array.from(c.removed.vertices), [3]);
    assert.deepEqual(Array.from(c.removed.edges), [3, 4]);
    assert.deepEqual(Array.from(c.removed.faces), [1]);
    const gaps = mesh.gaps();
    assert.deepEqual([Array.from(gaps.vertices), Array.from(gaps.edges), Array.from(gaps.faces)], [[3], [3, 4], [1]]);
    const k = mesh.counts();
    assert.deepEqual([k.vertices, k.edges, k.faces, k.euler], [4, 5, 2, 1]);
    // the other representations keep the winged edge's numbers: F2 is a face with no corners
    const reps = mesh.representations();
    assert.deepEqual(reps['vertex-face-tables'].faces.map((f) => f.vertices), [[0, 1, 2], [], [1, 4, 2]]);
    // queries and adjacency refuse a gap by name
    assert.throws(() => mesh.facesOfEdge(3), (e) => e.code === 'deleted-element' && /e4 was removed/.test(e.message));
    assert.throws(() => mesh.query('edges-around-vertex', 3), (e) => e.code === 'deleted-element');
    assert.equal(mesh.planes().length, 3);
    assert.deepEqual(Array.from(mesh.normals().subarray(3, 6)), [0, 0, 0]); // the gap has no normal
    // a file has no room for gaps: four vertices, two faces, numbered as compact() would
    const off = api.parseMesh(mesh.format());
    assert.deepEqual(off.faces, [[0, 1, 2], [1, 3, 2]]);
    const map = mesh.compact();
    assert.deepEqual(Array.from(map.vertices), [0, 1, 2, -1, 3]);
    assert.deepEqual(Array.from(map.faces), [0, -1, 1]);
    assert.deepEqual(mesh.representations()['vertex-face-tables'].faces.map((f) => f.vertices), off.faces);
    assert.deepEqual(errors(mesh), []);
  });
  withLecture((mesh) => {
    const c = mesh.pokeFace(0);
    assert.deepEqual(edgeRows(mesh).slice(7), ['e8: v6 v3 F1 F5 e9 e10 e1 e3', 'e9: v6 v1 F4 F1 e10 e8 e2 e1',
      'e10: v6 v2 F5 F4 e8 e9 e3 e2']);
    assert.deepEqual(Array.from(c.added.faces), [3, 4]);
    assert.equal(mesh.counts().euler, 1);
  });
});

test('refusals: a reason naming the elements, the same from check and from the operation, nothing changed', () => {
  withMesh(api.generateMesh('tetrahedron'), (mesh) => {
    const before = snapshot(mesh);
    const verdict = mesh.check('flip-edge', 0);
    assert.equal(verdict.ok, false);
    assert.equal(verdict.code, 'edge-exists');
    assert.match(verdict.message, /^flipping e1 would create an edge v\d-v\d that already exists \(e\d\)$/);
    assert.throws(() => mesh.flipEdge(0), (e) => e.code === 'edge-exists' && e.message === verdict.message);
    assert.throws(() => mesh.apply({ op: 'collapse-edge', e: 0, t: 0.5 }), (e) => e.code === 'degenerate-vertex');
    assert.equal(snapshot(mesh), before);
  });
  withLecture((mesh) => {
    const before = snapshot(mesh);
    assert.deepEqual(mesh.check('join-faces', 0).code, 'boundary-edge');
    // F1 is a triangle (lecture 000: v1 v2 v3): no two corners that are not neighbours, whichever are chosen.
    assert.match(mesh.check('split-face', 0, 0, 1).message, /^F1 is a triangle: every two of its corners are joined by a side/);
    assert.deepEqual(mesh.check('split-edge', 2, 1.5).code, 'invalid-parameter');
    assert.throws(() => mesh.splitEdge(2, Number.NaN), (e) => e.code === 'invalid-argument');
    assert.throws(() => mesh.splitEdge(1.5), (e) => e.code === 'invalid-argument');
    assert.throws(() => mesh.check('explode', 1), (e) => e.code === 'unknown-operation');
    assert.throws(() => mesh.apply({ op: 'explode' }), (e) => e.code === 'unknown-operation' && /split-edge/.test(e.message));
    assert.equal(snapshot(mesh), before);
  });
});

// Undo from the record's rows alone, on the flat tables (what the lesson may rely on).
function undo(arrays, change) {
  const edges = Array.from(arrays.edges);
  const vertexEdge = Array.from(arrays.vertexEdge);
  const faceEdge = Array.from(arrays.faceEdge);
  const positions = Array.from(arrays.positions);
  for (const row of [...change.rows].reverse()) {
    for (const f of row.fields) {
      if (row.table === 'vertex' && f.field === 'edge') vertexEdge[row.row] = f.before;
      else if (row.table === 'face' && f.field === 'edge') faceEdge[row.row] = f.before;
      else if (row.table === 'edge') edges[8 * row.row + arrays.edgeFields.indexOf(f.field)] = f.before;
    }
  }
  for (const p of change.positions) positions.splice(3 * p.vertex, 3, ...p.before);
  vertexEdge.length -= change.added.vertices.length;
  positions.length = 3 * vertexEdge.length;
  edges.length -= 8 * change.added.edges.length;
  faceEdge.length -= change.added.faces.length;
  return JSON.stringify([positions, vertexEdge, edges, faceEdge]);
}
const flat = (a) => JSON.stringify([Array.from(a.positions), Array.from(a.vertexEdge), Array.from(a.edges), Array.from(a.faceEdge)]);

test('random seeded operation sequences: valid, Euler, rebuilt from the file, refusals unchanged, rows undo', () => {
  const inputs = [api.lectureExample(), api.generateMesh('tetrahedron'), api.generateMesh('cube'), api.generateMesh('sphere', { slices: 6, stacks: 5 }),
    api.generateMesh('grid', { nx: 3, ny: 3 }), api.foleyExample()];
  const ops = api.meshOperations.operations;
  let accepted = 0;
  let refused = 0;
  for (let seed = 1; seed <= 240; seed += 1) {
    const rnd = random(seed);
    withMesh(inputs[seed % inputs.length], (mesh) => {
      const euler = mesh.counts().euler;
      for (let step = 0; step < 25; step += 1) {
        const op = ops[Math.floor(rnd() * ops.length)];
        const k = mesh.counts();
        const total = { vertex: k.vertices + 2, edge: k.edges + 2, face: k.faces + 2 };
        const args = op.arguments.map((a) => (a.kind ? Math.floor(rnd() * total[a.kind]) : [0.5, 0.3, 1.2][Math.floor(rnd() * 3)]));
        const record = { op: op.name, ...Object.fromEntries(op.arguments.map((a, i) => [a.name, args[i]])) };
        const where = `seed ${seed} step ${step} ${JSON.stringify(record)}`;
        const before = snapshot(mesh);
        const arrays = mesh.wingedEdgeArrays();
        const verdict = mesh.check(op.name, ...args);
        assert.equal(snapshot(mesh), before, where);
        if (!verdict.ok) {
          refused += 1;
          assert.throws(() => mesh.apply(record), (e) => e.code === verdict.code && e.message === verdict.message, where);
          assert.equal(snapshot(mesh), before, where);
          continue;
        }
        accepted += 1;
        const change = mesh.apply(record);
        assert.deepEqual(errors(mesh), [], where);
        assert.equal(mesh.counts().euler, euler, where);
        assert.deepEqual(mesh.version, mesh.coreVersion(), where);
        assert.equal(undo(mesh.wingedEdgeArrays(), change), flat(arrays), where);
        // independent: the exported file, parsed and built again, has the same counts
        const rebuilt = api.buildMesh(api.parseMesh(mesh.format()));
        const [a, b] = [mesh.counts(), rebuilt.counts()];
        rebuilt.dispose();
        assert.deepEqual([a.vertices, a.edges, a.faces, a.boundaryLoops], [b.vertices, b.edges, b.faces, b.boundaryLoops], where);
      }
    });
  }
  assert.ok(accepted > 1000 && refused > 300, `accepted ${accepted}, refused ${refused}`);
});

test('mesh.undo() takes the edits back newest first: every earlier mesh again, its version, gaps and validate() clean; none left is refused', () => {
  const inputs = [api.lectureExample(), api.generateMesh('cube'), api.generateMesh('sphere', { slices: 6, stacks: 5 }), api.generateMesh('grid', { nx: 3, ny: 3 })];
  const ops = api.meshOperations.operations;
  let undone = 0;
  let withGaps = 0;
  for (let seed = 1; seed <= 80; seed += 1) {
    const rnd = random(seed);
    withMesh(inputs[seed % inputs.length], (mesh) => {
      const states = [];
      for (let step = 0; step < 20; step += 1) {
        const op = ops[Math.floor(rnd() * ops.length)];
        const k = mesh.counts();
        const total = { vertex: k.vertices, edge: k.edges, face: k.faces };
        const args = op.arguments.map((a) => (a.kind ? Math.floor(rnd() * total[a.kind]) : 0.5));
        if (!mesh.check(op.name, ...args).ok) continue;
        const before = snapshot(mesh);
        const change = mesh.apply({ op: op.name, ...Object.fromEntries(op.arguments.map((a, i) => [a.name, args[i]])) });
        if (change.after.topology !== change.before.topology) states.push({ before, change });
        // Now and then take a run of edits back.
        while (states.length && rnd() < 0.25) {
          const { before: was, change: c } = states.pop();
          const u = mesh.undo();
          const where = `seed ${seed} step ${step} undo ${c.op}`;
          assert.equal(snapshot(mesh), was, where);
          assert.deepEqual(errors(mesh), [], where);
          assert.deepEqual(mesh.version, c.before, where);
          assert.deepEqual(mesh.version, mesh.coreVersion(), where);
          assert.equal(u.op, 'undo');
          assert.deepEqual([Array.from(u.removed.vertices), Array.from(u.removed.edges), Array.from(u.removed.faces)],
            [Array.from(c.added.vertices), Array.from(c.added.edges), Array.from(c.added.faces)], where);
          assert.deepEqual([Array.from(u.added.edges), Array.from(u.added.faces)], [Array.from(c.removed.edges), Array.from(c.removed.faces)], where);
          if (c.removed.edges.length) withGaps += 1;
          undone += 1;
        }
      }
      while (states.length) {
        const { before: was } = states.pop();
        mesh.undo();
        assert.equal(snapshot(mesh), was);
        undone += 1;
      }
      const before = snapshot(mesh);
      assert.throws(() => mesh.undo(), (e) => e.code === 'cannot-undo' && /no edit to take back/.test(e.message));
      assert.equal(snapshot(mesh), before);
    });
  }
  assert.ok(undone > 400 && withGaps > 30, `undone ${undone}, with gaps ${withGaps}`);
});

test('mesh.undo() after compact() is refused: the renumbering forgot the records', () => withLecture((mesh) => {
  mesh.apply({ op: 'collapse-edge', e: 3 });
  mesh.compact();
  const before = snapshot(mesh);
  assert.throws(() => mesh.undo(), (e) => e.code === 'cannot-undo');
  assert.equal(snapshot(mesh), before);
}));

test('the benchmark hook flips what the public API flips (docs/benchmarks.md mesh_edit_flip) and leaves the mesh alone', async () => {
  const { loadBenchCore } = await import('../../bench/wasm/bench-core.mjs');
  const bench = await loadBenchCore();
  const { hooks } = bench;
  const mesh = bench.api.buildMesh(api.generateMesh('sphere', { slices: 12, stacks: 7 }));
  try {
    const before = snapshot(mesh);
    const r = hooks.timeEditInCore(mesh, 'mesh_edit_flip', 2);
    assert.equal(snapshot(mesh), before);
    const E = mesh.counts().edges;
    assert.equal(r.n, Math.ceil(E / 3));
    let flips = 0;
    for (let e = 0; e < E; e += 3) {
      if (mesh.check('flip-edge', e).ok) {
        mesh.flipEdge(e);
        flips += 1;
      }
    }
    assert.equal(r.checksum, flips + E + mesh.wingedEdge().edges[E - 1].start);
  } finally {
    mesh.dispose();
  }
});

test('apply(op, {costs: true}): the entries each representation wrote for a split of e3 (counted by hand)', () => withLecture((mesh) => {
  const plain = api.buildMesh(api.lectureExample());
  try {
    const c = mesh.apply({ op: 'split-edge', e: 2, t: 0.5 }, { costs: true });
    // Winged edge: the 15 assignments and v6's three coordinates. Independent faces: F1's
    // last two corners (6 numbers) and F2's new corner (3). Vertex and face tables: v6's
    // xyz (3), F1's list from its third entry (2) and F2's new entry (1).
    assert.equal(c.costs['winged-edge'].writes, 18);
    assert.equal(c.costs['independent-faces'].writes, 9);
    assert.equal(c.costs['vertex-face-tables'].writes, 6);
    assert.deepEqual(Object.keys(c.costs).sort(), ['adjacency-lists', 'edge-list', 'independent-faces', 'partial-adjacency-lists', 'vertex-face-tables', 'winged-edge']);
    // Without the option the record has no count (it would cost O(mesh) per replayed edit).
    assert.equal(plain.apply({ op: 'split-edge', e: 2, t: 0.5 }).costs, undefined);
  } finally {
    plain.dispose();
  }
}));

test('apply(flip e3, {costs: true}): the reads each representation makes to find the faces around e3, counted by hand on the slide', () => withLecture((mesh) => {
  // e3 = v2 -> v3, L = F1, R = F2; F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4). A flip
  // first finds the faces on both sides of e3, then the sides of each (edit_costs.h).
  const c = mesh.apply({ op: 'flip-edge', e: 2 }, { costs: true });
  // Winged edge: e3's L and R (2); each face: its edge (1), then per side the edge's L, to
  // know which way it runs, and the next wing (2 x 3) = 7; 2 + 7 + 7.
  assert.equal(c.costs['winged-edge'].reads, 16);
  // Vertex and face tables: the face table has no way back from an edge, so all F = 3 faces
  // are scanned: the 4 offsets, and per face its first corner and the next ones until the
  // pair v2 v3 appears (F1: v1 v2 v3, 3; F2: v2 v4 v3 and the wrap v3 -> v2, 3 reads; F3 is
  // read whole, 3): 4 + 9 = 13. Then the sides of F1 and F2: 2 offsets + 3 corners each: 10.
  assert.equal(c.costs['vertex-face-tables'].reads, 23);
  // Independent faces: the same scan, comparing coordinates until one differs (v2 = (1,0),
  // v3 = (1,2)): a corner at v1, v4 or v5 costs 1 read against each end (2), v2 3, v3 2 + 3 = 5.
  // F1: 2 + 3 + 5, F2: 3 + 2 + 5, F3: 3 + 2 + 2; with the 4 offsets: 31. Sides of F1 and F2:
  // 2 offsets + 3 corners x 3 coordinates each: 22.
  assert.equal(c.costs['independent-faces'].reads, 53);
  // Adjacency lists, partial adjacency lists, Foley's edge list: e3's two faces are stored
  // with it (2), each face's side list is 2 offsets + 3 entries (10).
  for (const rep of ['adjacency-lists', 'partial-adjacency-lists', 'edge-list']) assert.equal(c.costs[rep].reads, 12, rep);
  // The writes of the winged edge are the assignments (flip: no entry written twice, no
  // coordinate): the entries that differ between the slide's tables and the flipped ones
  // (tests/helpers/lecture-slide.mjs FLIP_E3, by hand): v3's edge, F1's edge, and in e1..e5
  // 3 + 2 + 6 + 2 + 3 fields = 18.
  assert.equal(c.costs['winged-edge'].writes, 18);
  // The face table: F1 (v1 v2 v3) becomes (v1 v2 v4) and F2's three corners are listed anew.
  assert.equal(c.costs['vertex-face-tables'].writes, 4);
}));

test('apply(collapse e6, {costs: true}): the winged edge\'s writes are its assignments, an entry written twice counted twice, plus the coordinates that moved', () => withLecture((mesh) => {
  const c = mesh.apply({ op: 'collapse-edge', e: 5, t: 0.5 }, { costs: true });
  const assignments = c.steps.filter((s) => s.field !== 'firstCorner');
  const written = new Set(assignments.map((s) => `${s.table}:${s.row}:${s.field}`));
  assert.ok(written.size < assignments.length, 'collapse e6 writes one entry twice (e2\'s E:R)');
  // v2 moves from (1, 0) to the middle of e6, (1.5, -0.5): x and y change, z stays 0.
  assert.deepEqual(c.positions.map((p) => [p.vertex, p.after]), [[1, [1.5, -0.5, 0]]]);
  assert.equal(c.costs['winged-edge'].writes, assignments.length + 2);
}));

test('editCostGrowth: the same flip on grids of 1k to 1M faces; the winged edge flat, the face table\'s search 4F + O(1), the smallest size equal to a real counted flip', () => {
  const g = api.editCostGrowth('flip-edge', [22, 70, 224, 708]);
  assert.deepEqual(g.sizes.map((s) => s.faces), [968, 9800, 100352, 1002528]);
  const at = (rep, kind) => g.costs.map((c) => c[rep][kind]);
  // The winged edge reads the records around the edge whatever the size: 2 + 7 + 7, as on the slide.
  assert.deepEqual(at('winged-edge', 'reads'), [16, 16, 16, 16]);
  assert.equal(new Set(at('winged-edge', 'writes')).size, 1);
  // The face table's scan: F + 1 offsets and a triangle's 3 corners each (the wrap to the first
  // corner is not read again), less at most one per face that has the edge (2 faces), then
  // the two faces' sides (2 x 5): between 4F + 9 and 4F + 11.
  g.sizes.forEach(({ faces }, k) => {
    const r = at('vertex-face-tables', 'reads')[k];
    assert.ok(r >= 4 * faces + 9 && r <= 4 * faces + 11, `F = ${faces}: ${r}`);
  });
  // The smallest size is the flip itself on a real grid: the middle vertex's edge to its right.
  const n = 22;
  withMesh(api.generateMesh('grid', { nx: n, ny: n }), (mesh) => {
    const v = (n / 2) * (n + 1) + n / 2;
    const edges = mesh.wingedEdgeArrays().edges; // 8 per edge: S, E, ...
    const e = Array.from(mesh.edgesAroundVertex(v)).find((x) => edges[8 * x] + edges[8 * x + 1] === 2 * v + 1);
    assert.notEqual(e, undefined);
    const c = mesh.apply({ op: 'flip-edge', e }, { costs: true });
    for (const rep of Object.keys(c.costs)) assert.deepEqual(c.costs[rep], g.costs[0][rep], rep);
  });
  assert.throws(() => api.editCostGrowth('split-face', [22]), { code: 'adjacent-corners' });
  assert.throws(() => api.editCostGrowth('flip-edge', [21]), { code: 'invalid-argument' });
});

test('collapseEdge on a polygon mesh leaves a vertex of valence 2 between two quads, as joinFaces does', () => {
  //   v4 (-1,1)      v5 (1,1)      F1 = (v1 v2 v3), F2 = (v3 v2 v5 v4), F3 = (v3 v4 v6 v1). v3 has
  //        \  F2   /               three edges; collapsing e1 = v1 -> v2 takes F1 and leaves v3 with
  //   F3    v3 --- v2 (1,0)        two, between the quads (v3 v1 v5 v4) and (v3 v4 v6 v1). Joining
  //        /  F1 /                 F1 and F2 across e2 (v2 -> v3) leaves v3 with two edges the same way.
  //   v6 (-1,-1)  v1 (0,-1)
  const input = { positions: [0, -1, 0, 1, 0, 0, 0, 0, 0, -1, 1, 0, 1, 1, 0, -1, -1, 0], faces: [[0, 1, 2], [2, 1, 4, 3], [2, 3, 5, 0]] };
  const cycle = (f) => { const i = f.indexOf(Math.min(...f)); return [...f.slice(i), ...f.slice(0, i)]; };
  withMesh(input, (mesh) => {
    assert.deepEqual(mesh.check('collapse-edge', 0), { ok: true });
    mesh.collapseEdge(0);
    assert.deepEqual(errors(mesh), []);
    assert.deepEqual(mesh.counts(), { vertices: 5, edges: 6, faces: 2, boundaryEdges: 4, boundaryLoops: 1, isolatedVertices: 0, euler: 1 });
    // The file holds the live vertices renumbered (v2 is gone): v3 -> 1, v4 -> 2, v5 -> 3, v6 -> 4.
    const back = api.parseMesh(mesh.format());
    assert.deepEqual(back.faces.map(cycle), [cycle([1, 0, 3, 2]), cycle([1, 2, 4, 0])]);
    assert.equal(api.validateMesh(back).ok, true);
  });
  withMesh(input, (mesh) => {
    mesh.joinFaces(1);
    assert.deepEqual(errors(mesh), []);
    assert.equal(mesh.edgesAroundVertex(2).length, 2);
  });
});

test("apply(op, {costs: 'winged-edge'}): the winged edge's count alone equals its entry of the full count, on 400 random edits; flip e3 reads 16 and writes its playback's lines", () => {
  withLecture((mesh) => {
    const c = mesh.apply({ op: 'flip-edge', e: 2 }, { costs: 'winged-edge' });
    assert.deepEqual(Object.keys(c.costs), ['winged-edge']);
    // The hand count of the full test above: 2 + 7 + 7 reads; one write per assignment (a
    // flip moves no vertex).
    assert.equal(c.costs['winged-edge'].reads, 16);
    assert.equal(c.costs['winged-edge'].writes, c.steps.filter((s) => s.field !== 'firstCorner').length);
    assert.deepEqual(c.positions, []);
  });
  const ops = api.meshOperations.operations;
  let compared = 0;
  for (let seed = 1; seed <= 60 && compared < 400; seed += 1) {
    const rnd = random(seed);
    const input = [api.lectureExample(), api.generateMesh('cube'), api.generateMesh('sphere', { slices: 7, stacks: 5 }), api.generateMesh('grid', { nx: 3, ny: 4 })][seed % 4];
    const a = api.buildMesh(input);
    const b = api.buildMesh(input);
    try {
      for (let step = 0; step < 20; step += 1) {
        const op = ops[Math.floor(rnd() * ops.length)];
        const we = a.wingedEdgeArrays();
        const total = { vertex: we.vertexEdge.length, edge: we.edges.length / 8, face: we.faceEdge.length };
        const args = op.arguments.map((x) => (x.kind ? Math.floor(rnd() * total[x.kind]) : [0.5, 0.25][Math.floor(rnd() * 2)]));
        const operation = { op: op.name, ...Object.fromEntries(op.arguments.map((x, i) => [x.name, args[i]])) };
        if (!a.check(operation).ok) continue;
        const full = a.apply(operation, { costs: true });
        const alone = b.apply(operation, { costs: 'winged-edge' });
        assert.deepEqual(alone.costs, { 'winged-edge': full.costs['winged-edge'] }, `seed ${seed} ${JSON.stringify(operation)}`);
        compared += 1;
      }
    } finally {
      a.dispose();
      b.dispose();
    }
  }
  assert.ok(compared >= 400, `compared ${compared}`);
  withLecture((mesh) => assert.throws(() => mesh.apply({ op: 'flip-edge', e: 2 }, { costs: 'all' }), (e) => e.code === 'invalid-argument'));
});
