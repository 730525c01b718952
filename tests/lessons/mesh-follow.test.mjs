// The mesh lesson after an edit reads again only what the edit changed (the faces, the
// projected positions and the gaps follow the change record: ui/mesh/winged-arrays.js), and
// what it shows equals what a whole read of the core gives: driven through its compute hook
// in Node over the real core.
//  * thousands of random edits on small meshes, in 2D and 3D: after each, the model's faces
//    equal mesh.faceSet(), its projected positions equal projectAll of the core's positions,
//    its gap marks equal mesh.gaps();
//  * the same after going back to an earlier state (undo: the core takes the edits back from
//    their records) and editing on from there;
//  * on spheres of 1,200 and 120,000 faces the same edits, and undoing them, read no whole
//    table of the core (faceSet(), wingedEdgeArrays(), gaps(), boundingBox(), normals(), a
//    table without a limit), build no mesh, and read the same number of faces again at both
//    sizes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../helpers/seeded-random.mjs';
import { meshLesson, createMeshView } from '../../web/js/lessons/mesh/lesson.js';
import { editOps, withEdit } from '../../web/js/lessons/mesh/edit-ops.js';
import { projectAll } from '../../web/js/ui/mesh/view.js';
import { arraysAtStep, visibleSteps } from '../../web/js/lessons/mesh/edit-playback.js';

const api = await loadWingspline();
const EDIT_OPS = editOps(api.meshOperations);
const operationOf = (entry, index, a, b) => entry.make(index, {
  ...Object.fromEntries(entry.numbers.map((n) => [n.name, 0.5])),
  ...(entry.choices.length === 2 ? { [entry.choices[0].name]: a, [entry.choices[1].name]: b } : {}),
});

// An edit the core accepts on the model's mesh at a random element, or null.
function anEdit(rnd, model) {
  const total = { vertex: model.V, edge: model.E, face: model.F };
  for (let tries = 0; tries < 30; tries += 1) {
    const entry = EDIT_OPS[Math.floor(rnd() * EDIT_OPS.length)];
    const index = Math.floor(rnd() * total[entry.needs]);
    let a = 0; let b = 0;
    if (entry.choices.length === 2) {
      try {
        const list = Array.from(model.mesh.adjacency(entry.choices[0].choices, index));
        a = list[0]; b = list[Math.min(2, list.length - 1)];
      } catch { continue; }
    }
    const operation = operationOf(entry, index, a, b);
    if (model.mesh.check(operation).ok) return operation;
  }
  return null;
}

test('after each of 1,500 random edits and 500 undos the followed tables, faces, projection and gaps, and the edit player\'s tables at 1,000 steps, equal a whole read of the core', () => {
  let edits = 0; let withGaps = 0; let grew = 0; let undos = 0; let undoneEdits = 0; let played = 0;
  for (let seed = 1; seed <= 60 && (edits < 1500 || undos < 500); seed += 1) {
    const rnd = random(seed);
    const view = createMeshView();
    const ctx = { api };
    let state = { ...meshLesson.defaultState(), meshKind: ['sphere', 'cube', 'grid', 'lecture'][seed % 4], sphere: { slices: 7, stacks: 5 }, grid: { nx: 4, ny: 3 }, mode3d: seed % 2 === 0 };
    let model = meshLesson.compute(view, state, ctx);
    const mesh = model.mesh;
    const earlier = [];
    for (let step = 0; step < 40; step += 1) {
      let where;
      if (earlier.length && rnd() < 0.3) {
        // Back to an earlier state, one or more edits back (the shell's undo), then on from there.
        const k = 1 + Math.floor(rnd() * Math.min(3, earlier.length));
        state = earlier.splice(earlier.length - k, k)[0];
        model = meshLesson.compute(view, state, ctx);
        undos += 1; undoneEdits += k;
        where = `seed ${seed} step ${step} undo ${k}`;
        assert.equal(model.mesh, mesh, `${where}: the mesh was not built again`);
      } else {
        const operation = anEdit(rnd, model);
        if (!operation) break;
        const F = model.F;
        earlier.push(state);
        state = withEdit(state, operation);
        model = meshLesson.compute(view, state, ctx);
        edits += 1;
        if (model.F > F) grew += 1;
        where = `seed ${seed} step ${step} ${JSON.stringify(operation)}`;
      }
      const we = model.mesh.wingedEdgeArrays();
      for (const key of ['positions', 'vertexEdge', 'edges', 'faceEdge']) assert.deepEqual(Array.from(model.we[key]), Array.from(we[key]), `${where}: ${key}`);
      const faces = model.mesh.faceSet();
      assert.deepEqual([Array.from(model.faceOffsets), Array.from(model.faceVertices)], [Array.from(faces.faceOffsets), Array.from(faces.faceVertices)], where);
      const positions = model.mesh.wingedEdgeArrays().positions;
      const expected = projectAll(positions, model.rotation, state.mode3d ? model.centre : [0, 0, 0]);
      assert.deepEqual(Array.from(model.projected), Array.from(expected), where);
      const gaps = model.mesh.gaps();
      assert.deepEqual([Array.from(model.gapLists.vertices), Array.from(model.gapLists.edges), Array.from(model.gapLists.faces)], [Array.from(gaps.vertices), Array.from(gaps.edges), Array.from(gaps.faces)], where);
      const vertexMarks = Array.from({ length: model.V }, (_, v) => (gaps.vertices.includes(v) ? 1 : 0));
      assert.deepEqual(Array.from(model.vertexGap ?? new Uint8Array(model.V)), vertexMarks, where);
      if (gaps.vertices.length + gaps.edges.length + gaps.faces.length) withGaps += 1;
      // The edit player stepped back and forth: the tables it shows equal the final ones with
      // the later assignments taken back (arraysAtStep, the copy it replaces).
      const lines = visibleSteps(model.lastOperation).length;
      if (lines && rnd() < 0.5) {
        for (let k = 0; k < 3; k += 1) {
          const shown = Math.floor(rnd() * (lines + 1));
          model = meshLesson.compute(view, { ...state, editStep: shown }, ctx);
          const reference = arraysAtStep(model.we, model.lastOperation, shown);
          for (const key of ['positions', 'vertexEdge', 'edges', 'faceEdge']) assert.deepEqual(Array.from(model.weShown[key]), Array.from(reference[key]), `${where}: step ${shown} ${key}`);
          played += 1;
        }
        model = meshLesson.compute(view, state, ctx);
      }
    }
  }
  assert.ok(edits >= 1500 && withGaps > 200 && grew > 200 && undos >= 500 && undoneEdits > undos && played > 1000, `edits ${edits}, with gaps ${withGaps}, grew ${grew}, undos ${undos} of ${undoneEdits} edits, player steps ${played}`);
});

// The api with every mesh it builds counted: the calls that read a whole table.
function countingApi() {
  const whole = { count: 0, calls: [] };
  const facesRead = [];
  const counted = (mesh) => new Proxy(mesh, {
    get(target, key) {
      const value = Reflect.get(target, key, target);
      if (typeof value !== 'function') return value;
      return (...args) => {
        const wholeRead = ['wingedEdgeArrays', 'gaps', 'boundingBox', 'normals', 'storage', 'representations'].includes(String(key))
          || (key === 'faceSet' && !args[0]?.faces) || (key === 'tables' && args[1]?.limit === undefined);
        if (wholeRead) { whole.count += 1; whole.calls.push(String(key)); }
        if (key === 'faceSet' && args[0]?.faces) facesRead.push(args[0].faces.length);
        return value.apply(target, args);
      };
    },
  });
  const built = { count: 0 };
  return { api: { ...api, buildMesh: (...args) => { built.count += 1; return counted(api.buildMesh(...args)); } }, whole, facesRead, built };
}

test('an edit and its undo on a 120,000-face sphere read no whole table and as many faces as on a 1,200-face sphere', () => {
  const perSize = [];
  for (const [slices, stacks] of [[30, 21], [300, 201]]) {
    const counting = countingApi();
    const view = createMeshView();
    const ctx = { api: counting.api };
    let state = { ...meshLesson.defaultState(), meshKind: 'sphere', sphere: { slices, stacks }, mode3d: true };
    let model = meshLesson.compute(view, state, ctx);
    const v = 1 + (Math.floor((stacks - 1) / 2) - 1) * slices + slices / 2;
    const e = model.mesh.adjacency('edges-around-vertex', v)[0];
    const f = model.mesh.adjacency('faces-around-vertex', v)[0];
    const elsewhere = model.mesh.adjacency('edges-around-vertex', v + 3)[0];
    // The first edit reads the faces once as the mesh then is (the source's faces are the
    // unedited mesh's); what is counted is each edit after it.
    state = withEdit(state, { op: 'flip-edge', e });
    model = meshLesson.compute(view, state, ctx);
    const reads = [];
    const states = [state];
    for (const operation of [{ op: 'split-edge', e, t: 0.5 }, { op: 'poke-face', f }, { op: 'flip-edge', e: elsewhere }, { op: 'collapse-edge', e: elsewhere, t: 0.5 }]) {
      counting.whole.count = 0; counting.whole.calls = []; counting.facesRead.length = 0;
      state = withEdit(state, operation);
      states.push(state);
      model = meshLesson.compute(view, state, ctx);
      assert.equal(counting.whole.count, 0, `${JSON.stringify(operation)} read whole: ${counting.whole.calls.join(', ')}`);
      reads.push(counting.facesRead.reduce((a, b) => a + b, 0));
    }
    const faces = model.mesh.faceSet();
    assert.deepEqual([Array.from(model.faceOffsets), Array.from(model.faceVertices)], [Array.from(faces.faceOffsets), Array.from(faces.faceVertices)]);
    // The edit player's steps move one set of arrays (no copy of the tables per step).
    const shownArrays = [0, 3, 1].map((shown) => meshLesson.compute(view, { ...state, editStep: shown }, ctx).weShown);
    assert.ok(shownArrays.every((a) => a.edges === shownArrays[0].edges && a.positions === shownArrays[0].positions && a.edges !== model.we.edges));
    model = meshLesson.compute(view, state, ctx);
    // Undo, one edit at a time back to the first (the shell gives the earlier state back).
    counting.built.count = 0;
    for (let k = states.length - 2; k >= 0; k -= 1) {
      counting.whole.count = 0; counting.whole.calls = []; counting.facesRead.length = 0;
      model = meshLesson.compute(view, states[k], ctx);
      assert.equal(counting.whole.count, 0, `undo to state ${k} read whole: ${counting.whole.calls.join(', ')}`);
      reads.push(counting.facesRead.reduce((a, b) => a + b, 0));
    }
    assert.equal(counting.built.count, 0, 'no mesh was built again to undo');
    const back = model.mesh.faceSet();
    assert.deepEqual([Array.from(model.faceOffsets), Array.from(model.faceVertices)], [Array.from(back.faceOffsets), Array.from(back.faceVertices)]);
    perSize.push({ faces: model.F, reads });
    model.mesh.dispose();
  }
  assert.ok(perSize[1].faces > 100 * perSize[0].faces / 2, JSON.stringify(perSize));
  assert.deepEqual(perSize[0].reads, perSize[1].reads, JSON.stringify(perSize));
  assert.ok(perSize[1].reads.every((n) => n > 0 && n < 20), JSON.stringify(perSize));
});

test('a turn of the view on a 200,000-face sphere projects no vertex until one is read; the few read and the whole projection equal projectAll of the core\'s positions', () => {
  const view = createMeshView();
  const ctx = { api };
  let state = { ...meshLesson.defaultState(), meshKind: 'sphere', sphere: { slices: 500, stacks: 201 }, mode3d: true };
  let model = meshLesson.compute(view, state, ctx);
  assert.ok(model.V > 100_000, `V = ${model.V}`);
  for (let turn = 1; turn <= 3; turn += 1) {
    state = { ...state, rotation: { yaw: 0.6 + 0.1 * turn, pitch: 0.45 - 0.05 * turn } };
    model = meshLesson.compute(view, state, ctx);
    assert.equal(view.derived.projected, null, `turn ${turn}: nothing projected yet`);
    const expected = projectAll(model.mesh.wingedEdgeArrays().positions, model.rotation, model.centre);
    const P = model.points;
    for (const v of [0, 1, 777, model.V - 1]) {
      for (let k = 0; k < 3; k += 1) assert.equal(P[3 * v + k], expected[3 * v + k], `turn ${turn} v${v + 1}`);
    }
    assert.equal(view.derived.projected, null, `turn ${turn}: a few points read, the whole not made`);
    assert.deepEqual(Array.from(model.projected), Array.from(expected), `turn ${turn}: the whole projection`);
    assert.equal(model.points, model.projected, 'once made, the points are the whole array');
  }
  model.mesh.dispose();
});
