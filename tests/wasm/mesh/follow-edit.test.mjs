// The mesh lesson's winged-edge arrays after an edit (web/js/ui/mesh/winged-arrays.js):
// reading again only the rows the change record names gives exactly the tables the core
// holds (wingedEdgeArrays(), read whole), edit after edit, through growth and gaps; and the
// rows read for one edit do not depend on the mesh's size.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { followEdit, followPositions, followFaces } from '../../../web/js/ui/mesh/winged-arrays.js';
import { random } from '../../helpers/seeded-random.mjs';

const api = await loadWingspline({ parts: ['mesh'] });
const flat = (a) => [Array.from(a.positions), Array.from(a.vertexEdge), Array.from(a.edges), Array.from(a.faceEdge)];

// A mesh whose `tables` calls are counted, in rows asked for.
function counting(mesh) {
  const count = { rows: 0, calls: 0 };
  const proxy = new Proxy(mesh, {
    get(target, key) {
      if (key === 'tables') {
        return (representation, options = {}) => {
          count.calls += 1;
          count.rows += options.limit ?? Infinity;
          return target.tables(representation, options);
        };
      }
      const value = Reflect.get(target, key, target);
      return typeof value === 'function' ? value.bind(target) : value;
    },
  });
  return { proxy, count };
}

test('2,000 random edits on six meshes: the followed arrays and faces equal the core\'s tables and face set read whole after every edit', () => {
  const inputs = [api.lectureExample(), api.generateMesh('tetrahedron'), api.generateMesh('cube'), api.generateMesh('sphere', { slices: 8, stacks: 6 }),
    api.generateMesh('grid', { nx: 4, ny: 3 }), api.foleyExample()];
  const ops = api.meshOperations.operations;
  let accepted = 0; let grew = 0; let gaps = 0;
  for (let seed = 1; seed <= 200 && accepted < 2000; seed += 1) {
    const rnd = random(seed);
    const mesh = api.buildMesh(inputs[seed % inputs.length]);
    try {
      let we = mesh.wingedEdgeArrays();
      let positions = Float64Array.from(we.positions);
      const start = mesh.faceSet();
      let csr = { offsets: start.faceOffsets, vertices: start.faceVertices };
      for (let step = 0; step < 40; step += 1) {
        const op = ops[Math.floor(rnd() * ops.length)];
        const k = mesh.counts();
        const total = { vertex: we.vertexEdge.length, edge: we.edges.length / 8, face: we.faceEdge.length };
        const args = op.arguments.map((a) => (a.kind ? Math.floor(rnd() * total[a.kind]) : [0.5, 0.3, 0.8][Math.floor(rnd() * 3)]));
        const operation = { op: op.name, ...Object.fromEntries(op.arguments.map((a, i) => [a.name, args[i]])) };
        if (!mesh.check(operation).ok) continue;
        const record = mesh.apply(operation);
        accepted += 1;
        const before = we.vertexEdge.length + we.edges.length + we.faceEdge.length;
        we = followEdit(we, mesh, record);
        positions = followPositions(positions, mesh, record);
        const previous = [Array.from(csr.offsets), Array.from(csr.vertices)];
        const followed = followFaces(csr, mesh, we, record);
        assert.deepEqual([Array.from(csr.offsets), Array.from(csr.vertices)], previous, 'the faces before the edit are not written');
        csr = followed;
        if (we.vertexEdge.length + we.edges.length + we.faceEdge.length > before) grew += 1;
        if (record.removed.vertices.length + record.removed.edges.length + record.removed.faces.length) gaps += 1;
        const whole = mesh.wingedEdgeArrays();
        const where = `seed ${seed} step ${step} ${JSON.stringify(operation)} (${k.vertices} vertices before)`;
        assert.deepEqual(flat(we), flat(whole), where);
        assert.deepEqual(Array.from(positions), Array.from(whole.positions), where);
        assert.deepEqual(we.edgeFields, whole.edgeFields);
        const faces = mesh.faceSet();
        assert.deepEqual([Array.from(csr.offsets), Array.from(csr.vertices)], [Array.from(faces.faceOffsets), Array.from(faces.faceVertices)], where);
      }
    } finally {
      mesh.dispose();
    }
  }
  assert.ok(accepted >= 2000 && grew > 300 && gaps > 100, `accepted ${accepted}, grew ${grew}, with gaps ${gaps}`);
});

test('one edit reads the same rows of a 1,200-face and a 120,000-face sphere: the rows its record names, one at a time', () => {
  const rowsRead = [];
  for (const [slices, stacks] of [[30, 21], [300, 201]]) {
    const mesh = api.buildMesh(api.generateMesh('sphere', { slices, stacks }));
    try {
      const we = mesh.wingedEdgeArrays();
      // The same operations at the same place relative to the equator's middle vertex.
      const v = 1 + (Math.floor((stacks - 1) / 2) - 1) * slices + slices / 2;
      const e = mesh.adjacency('edges-around-vertex', v)[0];
      const f = mesh.adjacency('faces-around-vertex', v)[0];
      const counts = [];
      let current = we;
      for (const operation of [{ op: 'flip-edge', e }, { op: 'split-edge', e, t: 0.5 }, { op: 'poke-face', f }]) {
        const record = mesh.apply(operation);
        const { proxy, count } = counting(mesh);
        current = followEdit(current, proxy, record);
        assert.equal(count.rows, count.calls, 'every read asks for one row');
        counts.push(count.rows);
      }
      assert.deepEqual(flat(current), flat(mesh.wingedEdgeArrays()));
      rowsRead.push(counts);
    } finally {
      mesh.dispose();
    }
  }
  assert.deepEqual(rowsRead[0], rowsRead[1], `rows read per edit: ${JSON.stringify(rowsRead)}`);
  assert.ok(rowsRead[1].every((n) => n < 40), JSON.stringify(rowsRead));
});

test('one edit reads again the same number of faces of a 1,200-face and a 120,000-face sphere', () => {
  const facesRead = [];
  for (const [slices, stacks] of [[30, 21], [300, 201]]) {
    const mesh = api.buildMesh(api.generateMesh('sphere', { slices, stacks }));
    try {
      let we = mesh.wingedEdgeArrays();
      const start = mesh.faceSet();
      let csr = { offsets: start.faceOffsets, vertices: start.faceVertices };
      const v = 1 + (Math.floor((stacks - 1) / 2) - 1) * slices + slices / 2;
      const e = mesh.adjacency('edges-around-vertex', v)[0];
      const f = mesh.adjacency('faces-around-vertex', v)[0];
      const counts = [];
      for (const operation of [{ op: 'flip-edge', e }, { op: 'split-edge', e, t: 0.5 }, { op: 'poke-face', f }, { op: 'collapse-edge', e, t: 0.5 }]) {
        const record = mesh.apply(operation);
        we = followEdit(we, mesh, record);
        let read = 0;
        const proxy = new Proxy(mesh, {
          get(target, key) {
            if (key === 'faceSet') return (options) => { read += options?.faces?.length ?? Infinity; return target.faceSet(options); };
            const value = Reflect.get(target, key, target);
            return typeof value === 'function' ? value.bind(target) : value;
          },
        });
        csr = followFaces(csr, proxy, we, record);
        counts.push(read);
      }
      const whole = mesh.faceSet();
      assert.deepEqual([Array.from(csr.offsets), Array.from(csr.vertices)], [Array.from(whole.faceOffsets), Array.from(whole.faceVertices)]);
      facesRead.push(counts);
    } finally {
      mesh.dispose();
    }
  }
  assert.deepEqual(facesRead[0], facesRead[1], `faces read per edit: ${JSON.stringify(facesRead)}`);
  assert.ok(facesRead[1].every((n) => n > 0 && n < 20), JSON.stringify(facesRead));
});

test('faceSet() is the vertex and face tables\' face list, read from the winged edge, after every one of 600 random edits (gaps as faces with no corners)', () => {
  const ops = api.meshOperations.operations;
  let compared = 0; let withGaps = 0;
  for (let seed = 300; seed < 400 && compared < 600; seed += 1) {
    const rnd = random(seed);
    const mesh = api.buildMesh([api.lectureExample(), api.generateMesh('cube'), api.generateMesh('grid', { nx: 3, ny: 3 })][seed % 3]);
    try {
      for (let step = 0; step < 20; step += 1) {
        const op = ops[Math.floor(rnd() * ops.length)];
        const we = mesh.wingedEdgeArrays();
        const total = { vertex: we.vertexEdge.length, edge: we.edges.length / 8, face: we.faceEdge.length };
        const args = op.arguments.map((a) => (a.kind ? Math.floor(rnd() * total[a.kind]) : 0.5));
        const operation = { op: op.name, ...Object.fromEntries(op.arguments.map((a, i) => [a.name, args[i]])) };
        if (!mesh.check(operation).ok) continue;
        mesh.apply(operation);
        const { faceOffsets, faceVertices } = mesh.faceSet();
        const tables = mesh.tables('vertex-face-tables').faces.arrays;
        assert.deepEqual([Array.from(faceOffsets), Array.from(faceVertices)], [Array.from(tables.faceOffsets), Array.from(tables.faceVertices)], `seed ${seed} ${JSON.stringify(operation)}`);
        if (mesh.gaps().faces.length) withGaps += 1;
        compared += 1;
      }
    } finally {
      mesh.dispose();
    }
  }
  assert.ok(compared >= 600 && withGaps > 50, `compared ${compared}, with removed faces ${withGaps}`);
});
