// The tables described once: every representation read through the one generic
// reader (mesh.tables + web/js/core/tables.js) gives the rows an independent recomputation
// from the face list gives, here in the test (half-edges, boundary loops, the documented
// orders); docs/api-mesh.md lists every descriptor's columns.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadWingspline } from 'wingspline';
import { describedTablesMarkdown } from '../../../scripts/doc-tables.mjs';

const api = await loadWingspline();
const KEYS = ['independent-faces', 'vertex-face-tables', 'adjacency-lists', 'partial-adjacency-lists', 'edge-list', 'winged-edge'];

// Everything from {positions, faces, edges?}: the edge numbering (given, or by first
// appearance walking the faces, oriented as first traversed: docs/api-mesh.md), half-edges
// with their loop successor (face loops, and boundary loops made of the missing twins).
function recompute({ positions, faces, edges: given }) {
  const V = positions.length / 3;
  const key = (a, b) => `${Math.min(a, b)},${Math.max(a, b)}`;
  const edges = [];
  const edgeOf = new Map();
  for (const [s, e] of given ?? []) { edgeOf.set(key(s, e), edges.length); edges.push([s, e]); }
  const side = (f, i) => [faces[f][i], faces[f][(i + 1) % faces[f].length]];
  faces.forEach((face, f) => face.forEach((_, i) => {
    const [a, b] = side(f, i);
    if (!edgeOf.has(key(a, b))) { edgeOf.set(key(a, b), edges.length); edges.push([a, b]); }
  }));
  const E = edges.length;
  // Half-edge a->b: its face (-1 = boundary), and the next half-edge of its loop.
  const face = new Map();
  const next = new Map();
  const prev = new Map();
  const h = (a, b) => `${a}>${b}`;
  faces.forEach((fc, f) => fc.forEach((_, i) => {
    const [a, b] = side(f, i);
    const [, c] = side(f, (i + 1) % fc.length);
    face.set(h(a, b), f);
    next.set(h(a, b), h(b, c));
    prev.set(h(b, c), h(a, b));
  }));
  const boundaryFrom = new Map(); // boundary half-edge b->a (the twin of a face side a->b) by its start b
  for (const [s, e] of edges) {
    for (const [a, b] of [[s, e], [e, s]]) if (!face.has(h(a, b))) { face.set(h(a, b), -1); boundaryFrom.set(a, h(a, b)); }
  }
  for (const [hb, f] of face) {
    if (f !== -1) continue;
    const b = Number(hb.split('>')[1]);
    next.set(hb, boundaryFrom.get(b));
    prev.set(boundaryFrom.get(b), hb);
  }
  const edgeOfHalf = (he) => { const [a, b] = he.split('>').map(Number); return edgeOf.get(key(a, b)); };
  const xyz = (v) => Array.from(positions.slice(3 * v, 3 * v + 3));
  const sideEdges = faces.map((fc, f) => fc.map((_, i) => edgeOf.get(key(...side(f, i)))));
  const L = (e) => face.get(h(...edges[e]));
  const R = (e) => face.get(h(edges[e][1], edges[e][0]));
  const VE = Array.from({ length: V }, (_, v) => edges.flatMap(([s, t], e) => (s === v || t === v ? [e] : [])));
  const VF = Array.from({ length: V }, (_, v) => faces.flatMap((fc, f) => fc.filter((x) => x === v).map(() => f)));
  const other = (e, v) => (edges[e][0] === v ? edges[e][1] : edges[e][0]);
  const FF = faces.map((fc, f) => sideEdges[f].map((e) => (L(e) === f ? R(e) : L(e))));
  return {
    V, E, F: faces.length, edges, sideEdges, VE,
    rows: {
      'independent-faces': { faces: faces.map((fc) => ({ corners: fc.map(xyz) })) },
      'vertex-face-tables': {
        vertices: Array.from({ length: V }, (_, v) => { const [x, y, z] = xyz(v); return { x, y, z }; }),
        faces: faces.map((fc) => ({ vertices: [...fc] })),
      },
      'adjacency-lists': {
        vertices: Array.from({ length: V }, (_, v) => ({ position: xyz(v), vertices: VE[v].map((e) => other(e, v)), edges: VE[v], faces: VF[v] })),
        edges: edges.map(([s, t], e) => ({
          vertices: [s, t], faces: [L(e), R(e)], edges: [...VE[s].filter((x) => x !== e), ...VE[t].filter((x) => x !== e)],
        })),
        faces: faces.map((fc, f) => ({ vertices: [...fc], edges: sideEdges[f], faces: FF[f] })),
      },
      'partial-adjacency-lists': {
        vertices: Array.from({ length: V }, (_, v) => ({ position: xyz(v), edges: VE[v] })),
        edges: edges.map(([s, t], e) => ({ vertices: [s, t], faces: [L(e), R(e)] })),
        faces: faces.map((_, f) => ({ edges: sideEdges[f] })),
      },
      'edge-list': {
        vertices: Array.from({ length: V }, (_, v) => ({ position: xyz(v) })),
        edges: edges.map(([s, t], e) => {
          const both = [L(e), R(e)].filter((x) => x >= 0).sort((a, b) => a - b);
          return { v1: s, v2: t, p1: both[0], p2: both[1] ?? -1 };
        }),
        polygons: sideEdges.map((list) => {
          const k = list.indexOf(Math.min(...list));
          return { edges: [...list.slice(k), ...list.slice(0, k)] };
        }),
      },
      'winged-edge': {
        // Wing X-Y: the other edge at X of the loop on side Y (the boundary loop on a boundary side).
        edges: edges.map(([s, t], e) => ({
          start: s, end: t, left: L(e), right: R(e),
          startLeft: edgeOfHalf(prev.get(h(s, t))), endLeft: edgeOfHalf(next.get(h(s, t))),
          startRight: edgeOfHalf(next.get(h(t, s))), endRight: edgeOfHalf(prev.get(h(t, s))),
        })),
      },
    },
  };
}

const sphere = api.generateMesh('sphere', { slices: 7, stacks: 5 });
const MESHES = {
  lecture: api.lectureExample(),
  foley: api.foleyExample(),
  tetrahedron: api.generateMesh('tetrahedron'),
  cube: api.generateMesh('cube'),
  fan: api.generateMesh('fan', { n: 5 }),
  grid: api.generateMesh('grid', { nx: 5, ny: 3 }),
  sphere,
};

for (const [name, input] of Object.entries(MESHES)) {
  test(`${name}: every table read through the generic reader is the recomputation from the face list`, () => {
    const mesh = api.buildMesh(input);
    try {
      const want = recompute(input);
      const c = mesh.counts();
      assert.deepEqual([c.vertices, c.edges, c.faces], [want.V, want.E, want.F]);
      for (const key of KEYS) {
        const tables = mesh.tables(key);
        const names = api.tableDescriptors.filter((d) => d.representation === key).map((d) => d.name);
        assert.deepEqual(Object.keys(tables), names, key);
        for (const [tableName, t] of Object.entries(tables)) {
          assert.equal(t.total, { vertex: want.V, edge: want.E, face: want.F }[t.kind], `${key}/${tableName} rows`);
          const expected = want.rows[key][tableName];
          if (!expected) continue; // winged vertices and faces: below
          const got = t.rows();
          assert.equal(got.length, expected.length);
          expected.forEach((row, i) => assert.deepEqual(got[i], row, `${key}/${tableName} row ${i}`));
          // Cell by column name agrees with the row.
          for (const col of t.columns) assert.deepEqual(t.cell(t.total - 1, col.name), got[t.total - 1][col.name]);
        }
      }
      // The winged edge's vertex table: its coordinates, an incident edge (the lowest-numbered
      // one at an interior vertex, docs/api-mesh.md); the face table: the face's first side.
      const we = mesh.tables('winged-edge');
      for (let v = 0; v < want.V; v += 1) {
        const row = we.vertices.row(v);
        assert.deepEqual([row.x, row.y, row.z], Array.from(input.positions.slice(3 * v, 3 * v + 3)));
        assert.ok(want.VE[v].includes(row.edge), `v${v + 1} stores an incident edge`);
        const interior = want.VE[v].every((e) => want.rows['winged-edge'].edges[e].left >= 0 && want.rows['winged-edge'].edges[e].right >= 0);
        if (interior && !input.vertexEdges?.length) assert.equal(row.edge, Math.min(...want.VE[v]), `v${v + 1}`);
        if (input.vertexEdges?.length) assert.equal(row.edge, input.vertexEdges[v]);
      }
      for (let f = 0; f < want.F; f += 1) {
        const expected = input.faceEdges?.length ? input.faceEdges[f] : want.sideEdges[f][0];
        assert.equal(we.faces.row(f).edge, expected, `F${f + 1}`);
      }
      // The compatibility shapes are the same rows: wingedEdge(), representations().
      const reps = mesh.representations();
      assert.deepEqual(mesh.wingedEdge().edges, want.rows['winged-edge'].edges);
      assert.deepEqual(reps['adjacency-lists'].faces, want.rows['adjacency-lists'].faces);
      assert.deepEqual(reps['edge-list'].totals, { vertices: want.V, edges: want.E, polygons: want.F });
    } finally {
      mesh.dispose();
    }
  });
}

test('lecture 000: the winged-edge tables through the reader are the slide\'s, headers included', () => {
  const mesh = api.buildMesh(api.lectureExample());
  try {
    const { vertices, edges, faces } = mesh.tables('winged-edge');
    const label = (letter) => (i) => (i >= 0 ? `${letter}${i + 1}` : '');
    const cellText = (t, i) => t.columns.map((c) => (c.refers ? label({ vertex: 'v', edge: 'e', face: 'F' }[c.refers])(t.cell(i, c.name)) : String(t.cell(i, c.name))));
    // The slide (lecture 000, "Winged Edge"), '' = no face on that side.
    assert.deepEqual(Array.from({ length: 7 }, (_, e) => cellText(edges, e)), [
      ['v1', 'v3', '', 'F1', 'e2', 'e2', 'e4', 'e3'], ['v1', 'v2', 'F1', '', 'e1', 'e1', 'e3', 'e6'],
      ['v2', 'v3', 'F1', 'F2', 'e2', 'e5', 'e1', 'e4'], ['v3', 'v4', '', 'F2', 'e1', 'e3', 'e7', 'e5'],
      ['v2', 'v4', 'F2', 'F3', 'e3', 'e6', 'e4', 'e7'], ['v2', 'v5', 'F3', '', 'e5', 'e2', 'e7', 'e7'],
      ['v4', 'v5', '', 'F3', 'e4', 'e5', 'e6', 'e6'],
    ]);
    assert.deepEqual(edges.columns.map((c) => [c.group, c.label]), [['', 'S'], ['', 'E'], ['', 'L'], ['', 'R'], ['S', 'L'], ['S', 'R'], ['E', 'L'], ['E', 'R']]);
    assert.deepEqual(Array.from({ length: 5 }, (_, v) => cellText(vertices, v).at(-1)), ['e1', 'e6', 'e3', 'e5', 'e6']);
    assert.deepEqual(Array.from({ length: 3 }, (_, f) => cellText(faces, f)), [['e1'], ['e3'], ['e5']]);
    assert.deepEqual([vertices.title, edges.title, faces.title], ['VERTEX TABLE', 'EDGE TABLE', 'FACE TABLE']);
    assert.deepEqual([vertices.kind, edges.kind, faces.kind], ['vertex', 'edge', 'face']);
  } finally {
    mesh.dispose();
  }
});

test('a window of rows read by the reader is the same rows of the whole table; outside it is refused', () => {
  const mesh = api.buildMesh(sphere);
  try {
    for (const key of KEYS) {
      const whole = mesh.tables(key);
      for (const [offset, limit] of [[0, 4], [9, 7], [30, 500], [1000, 3]]) {
        const part = mesh.tables(key, { offset, limit });
        for (const [name, t] of Object.entries(part)) {
          const all = whole[name];
          assert.equal(t.total, all.total);
          const first = Math.min(offset, all.total);
          assert.equal(t.first, first);
          assert.equal(t.count, Math.min(all.total, offset + limit) - first);
          for (let i = first; i < first + t.count; i += 1) assert.deepEqual(t.row(i), all.row(i), `${key}/${name} row ${i}`);
          if (t.count > 0) assert.throws(() => t.row(first + t.count), { code: 'invalid-element' });
          if (first > 0) assert.throws(() => t.row(first - 1), { code: 'invalid-element' });
        }
      }
    }
    assert.throws(() => mesh.tables('winged-edge').edges.cell(0, 'wing'), { code: 'unknown-column' });
    assert.throws(() => mesh.tables('half-edge'), { code: 'unknown-representation' });
    assert.throws(() => mesh.tables('edge-list', { limit: -1 }), { code: 'invalid-argument' });
  } finally {
    mesh.dispose();
  }
});

test('docs/api-mesh.md lists every table\'s columns exactly as the descriptors give them', () => {
  const docs = readFileSync(new URL('../../../docs/api-mesh.md', import.meta.url), 'utf8');
  const begin = '<!-- tables:begin (generated by node scripts/doc-tables.mjs) -->';
  const end = '<!-- tables:end -->';
  assert.ok(docs.includes(begin) && docs.includes(end), 'the generated block is in the docs');
  const block = docs.slice(docs.indexOf(begin) + begin.length, docs.indexOf(end)).trim();
  assert.equal(block, describedTablesMarkdown(api.tableDescriptors).trim(), 'run node scripts/doc-tables.mjs --write');
  for (const d of api.tableDescriptors) {
    for (const c of d.columns) assert.ok(block.includes(`\`${c.name}\``), `${d.representation}/${d.name}.${c.name} is documented`);
  }
});

test('the lesson\'s CSV and LaTeX exports, drawn from the descriptors, are the slide\'s edge table', async () => {
  const { wingedCsv, wingedLatex } = await import('../../../web/js/lessons/mesh/exports.js');
  const mesh = api.buildMesh(api.lectureExample());
  try {
    const csv = wingedCsv({ mesh });
    const edgeSection = csv.split('# EDGE TABLE')[1].split('\n# ')[0].trim().split('\n').slice(1);
    assert.deepEqual(edgeSection, [
      'edge,S,E,L,R,S:L,S:R,E:L,E:R',
      'e1,v1,v3,,F1,e2,e2,e4,e3', 'e2,v1,v2,F1,,e1,e1,e3,e6', 'e3,v2,v3,F1,F2,e2,e5,e1,e4', 'e4,v3,v4,,F2,e1,e3,e7,e5',
      'e5,v2,v4,F2,F3,e3,e6,e4,e7', 'e6,v2,v5,F3,,e5,e2,e7,e7', 'e7,v4,v5,,F3,e4,e5,e6,e6',
    ]);
    assert.match(csv, /# VERTEX TABLE\nvertex,x,y,z,edge\nv1,0,1,0,e1\nv2,1,0,0,e6\n/);
    assert.match(csv, /# FACE TABLE\nface,edge\nF1,e1\nF2,e3\nF3,e5/);
    // The slide's two header lines: S E L R, then L R under S and L R under E.
    const tex = wingedLatex({ mesh });
    assert.ok(tex.includes('\\begin{tabular}{c|cccc|cc|cc}'));
    assert.ok(tex.includes('\\multicolumn{5}{c|}{} & \\multicolumn{2}{c|}{S} & \\multicolumn{2}{c}{E} \\\\'));
    assert.ok(tex.includes('  $e_{3}$ & $v_{2}$ & $v_{3}$ & $F_{1}$ & $F_{2}$ & $e_{2}$ & $e_{5}$ & $e_{1}$ & $e_{4}$ \\\\'));
  } finally {
    mesh.dispose();
  }
});
