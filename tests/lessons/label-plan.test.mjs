// The mesh view's label plan (web/js/ui/mesh/label-plan.js) on big meshes: a walk step, a
// hover or a pick changes only the labels forced on (the touched elements), so once a view is
// planned, the next frame of the same scene and view reads a number of mesh entries that does
// not depend on the mesh's size; and it plans exactly what planning from scratch plans.
// Meshes: triangulated grids made here (nx x ny quads, two triangles each, edges numbered as
// they first appear), projected in 2D at a zoom where labels are not crowded.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { labelPlan, createLabelCache } from '../../web/js/ui/mesh/label-plan.js';
import { Transform } from '../../web/js/app/painter.js';

function grid(nx, ny) {
  const V = (nx + 1) * (ny + 1);
  const projected = new Float64Array(3 * V);
  for (let j = 0; j <= ny; j += 1) for (let i = 0; i <= nx; i += 1) { const v = j * (nx + 1) + i; projected[3 * v] = i; projected[3 * v + 1] = j; }
  const faceVertices = new Int32Array(6 * nx * ny);
  const faceOffsets = new Int32Array(2 * nx * ny + 1);
  const edgeIndex = new Map();
  const ends = [];
  const edge = (a, b) => {
    const k = Math.min(a, b) * V + Math.max(a, b);
    if (!edgeIndex.has(k)) { edgeIndex.set(k, ends.length / 2); ends.push(a, b); }
  };
  let c = 0; let f = 0;
  for (let j = 0; j < ny; j += 1) {
    for (let i = 0; i < nx; i += 1) {
      const v00 = j * (nx + 1) + i; const v10 = v00 + 1; const v01 = v00 + nx + 1; const v11 = v01 + 1;
      for (const tri of [[v00, v10, v11], [v00, v11, v01]]) {
        faceVertices.set(tri, c); c += 3; faceOffsets[++f] = c;
        edge(tri[0], tri[1]); edge(tri[1], tri[2]); edge(tri[2], tri[0]);
      }
    }
  }
  const E = ends.length / 2;
  const edges = new Int32Array(8 * E).fill(-1);
  for (let e = 0; e < E; e += 1) { edges[8 * e] = ends[2 * e]; edges[8 * e + 1] = ends[2 * e + 1]; }
  return { projected, faceOffsets, faceVertices, edges, V, F: 2 * nx * ny, E };
}

// Every numeric index read of the arrays the plan reads, counted.
function counted(array, counter) {
  return new Proxy(array, {
    get(target, key) {
      if (typeof key === 'string' && key.length && key.charCodeAt(0) >= 48 && key.charCodeAt(0) <= 57) counter.reads += 1;
      const value = Reflect.get(target, key, target);
      return typeof value === 'function' ? value.bind(target) : value;
    },
  });
}

function modelOf(g, counter) {
  const edges = counted(g.edges, counter);
  const we = { edges };
  // In 2D the positions are shown as they are: the projection is the positions.
  const projected = counted(g.projected, counter);
  return {
    source: 'grid', topology: 1, version: 1, editStep: -1, mode3d: false, rotation: [1, 0, 0, 0, 1, 0, 0, 0, 1], centre: [0, 0, 0],
    positions: projected, projected, points: projected, faceOffsets: counted(g.faceOffsets, counter), faceVertices: counted(g.faceVertices, counter),
    we, weShown: we, V: g.V, F: g.F, vertexGap: null, edgeGap: null,
  };
}

// A 1280 x 800 view of the grid's middle at 60 px per unit: about 300 vertices on screen,
// whatever the grid's size (not crowded).
const painterOf = (g, nx, ny) => ({ scale: 1, t: new Transform({ cx: nx / 2, cy: ny / 2, zoom: 60, width: 1280, height: 800 }) });

const strip = (plan) => ({ vertices: plan.vertices, faces: plan.faces, edges: plan.edges });

test('a walk step on a planned view reads the same number of mesh entries on a 20,000- and a 500,000-triangle grid, and plans what a fresh plan plans', () => {
  const reads = [];
  for (const [nx, ny] of [[100, 100], [500, 500]]) {
    const g = grid(nx, ny);
    const counter = { reads: 0 };
    const model = modelOf(g, counter);
    const painter = painterOf(g, nx, ny);
    const cache = createLabelCache();
    const centre = (ny / 2) * (nx + 1) + nx / 2;
    // The walk around the centre vertex: each step forces the vertex and the edge it reads.
    const stepsOfWalk = [0, 1, 2, 3, 4, 5].map((k) => [{ kind: 'vertex', index: centre }, { kind: 'edge', index: 3 * (centre - (ny / 2)) + k }]);
    labelPlan(painter, model, {}, stepsOfWalk[0], cache);
    const first = counter.reads;
    assert.ok(first > g.V, `planning a new view reads the mesh (${first} reads for ${g.V} vertices)`);
    let perStep = 0;
    for (const forced of stepsOfWalk.slice(1)) {
      counter.reads = 0;
      const plan = labelPlan(painter, model, {}, forced, cache);
      perStep = Math.max(perStep, counter.reads);
      // The same plan as a plan made from scratch (a fresh cache) for this frame.
      assert.deepEqual(strip(plan), strip(labelPlan(painter, modelOf(g, { reads: 0 }), {}, forced, createLabelCache())));
      assert.ok(plan.vertices.includes(centre) && plan.edges.includes(forced[1].index), 'the walk\'s elements are labelled');
      assert.ok(plan.vertices.length > 20 && plan.faces.length > 20, 'the view is labelled beyond the walk');
    }
    reads.push(perStep);
  }
  // The forced elements only: a handful of entries each, the same on both grids.
  assert.equal(reads[0], reads[1], `reads per step: ${reads.join(' and ')}`);
  assert.ok(reads[1] < 50, `reads per step: ${reads[1]}`);
});

test('a new view, a new mesh version or another edit step plans again', () => {
  const g = grid(120, 120);
  const counter = { reads: 0 };
  const model = modelOf(g, counter);
  const painter = painterOf(g, 120, 120);
  const cache = createLabelCache();
  labelPlan(painter, model, {}, [], cache);
  const fresh = counter.reads;
  for (const change of [
    () => { painter.t = new Transform({ ...painter.t, cx: painter.t.cx + 3 }); },
    () => { model.version += 1; },
    () => { model.editStep = 2; model.weShown = { edges: model.we.edges }; },
    () => { model.mode3d = true; },
  ]) {
    change();
    counter.reads = 0;
    labelPlan(painter, model, {}, [], cache);
    assert.ok(counter.reads >= fresh / 2, `planned again after ${change} (${counter.reads} reads)`);
  }
});
