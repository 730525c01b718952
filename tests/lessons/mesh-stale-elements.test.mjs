// The mesh lesson's references to elements after any change of state (another mesh, an
// edit, undo or redo to an earlier state, compact), driven through its compute hook in Node
// over the real core, with picks and hovers chosen at random, some on the mesh before the
// change and some on no mesh at all. The property, after every compute: the picked and
// hovered element are elements of the new mesh or nothing, and a pick the new mesh has is
// kept; the walk's element is one of the mesh's numbers; reading what the panels read (the
// picked face's corners, the query, the description) never throws.
//
// Whether an element exists is decided here from the core alone: its number is below the
// length of its winged-edge table and not in the core's list of gaps (mesh.gaps()).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { random } from '../helpers/seeded-random.mjs';
import { meshLesson, createMeshView, QUERY_KINDS } from '../../web/js/lessons/mesh/lesson.js';
import { editOps, withEdit } from '../../web/js/lessons/mesh/edit-ops.js';
import { queryTarget } from '../../web/js/lessons/mesh/live-elements.js';

const api = await loadWingspline();
const ctx = { api };
const EDIT_OPS = editOps(api.meshOperations);
const KINDS = ['vertex', 'edge', 'face'];
const QUERY_ELEMENT = { 'faces-around-vertex': 'vertex', 'edges-around-vertex': 'vertex', 'edges-of-face': 'face', 'neighbours-of-face': 'face', 'faces-of-edge': 'edge' };

// The oracle: the numbers of each kind the core's mesh has, and those that are gaps.
function coreElements(mesh) {
  const we = mesh.wingedEdgeArrays();
  const gaps = mesh.gaps();
  return {
    count: { vertex: we.vertexEdge.length, edge: we.edges.length / 8, face: we.faceEdge.length },
    gap: { vertex: new Set(gaps.vertices), edge: new Set(gaps.edges), face: new Set(gaps.faces) },
  };
}
const isElement = (core, e) => e.index >= 0 && e.index < core.count[e.kind] && !core.gap[e.kind].has(e.index);

function anotherMesh(rnd, state) {
  const int = (lo, hi) => lo + Math.floor(rnd() * (hi - lo + 1));
  const kinds = ['lecture', 'foley', 'tetrahedron', 'cube', 'fan', 'grid', 'sphere'];
  const meshKind = kinds[int(0, kinds.length - 1)];
  // The walk's and the query's numbers are left as they were, or chosen past the new mesh's
  // end: compute keeps them to the mesh.
  return {
    ...state, meshKind, moved: [], ops: [], step: int(0, 5), editStep: -1,
    fanSize: int(1, 8), grid: { nx: int(1, 5), ny: int(1, 4) }, sphere: { slices: int(3, 6), stacks: int(3, 5) },
    walk: rnd() < 0.5 ? 'vertex' : 'face', vertex: int(0, 40), face: int(0, 40),
    query: { kind: QUERY_KINDS[int(0, QUERY_KINDS.length - 1)], vertex: int(0, 40), face: int(0, 40), edge: int(0, 60) },
  };
}

// An edit the core accepts on the model's mesh, from a random element, or null.
function anEdit(rnd, model, core) {
  for (let tries = 0; tries < 20; tries += 1) {
    const entry = EDIT_OPS[Math.floor(rnd() * EDIT_OPS.length)];
    const index = Math.floor(rnd() * core.count[entry.needs]);
    let a = 0; let b = 0;
    // The two choices (split face: corners of the face; split vertex: its neighbours), from
    // the registry's query, as the edit panel offers them.
    if (entry.choices.length === 2 && isElement(core, { kind: entry.needs, index })) {
      const list = Array.from(model.mesh.adjacency(entry.choices[0].choices, index));
      a = list[0]; b = list[Math.min(2, list.length - 1)];
    }
    const operation = entry.make(index, { t: 0.5, a, b });
    if (model.mesh.check(operation).ok) return operation;
  }
  return null;
}

// A pick or hover as a person could have made it on some mesh: any kind, any number up to
// a little past this mesh's end.
function anElement(rnd, core) {
  const kind = KINDS[Math.floor(rnd() * 3)];
  return { kind, index: Math.floor(rnd() * (core.count[kind] + 4)) };
}

test('after any change of mesh, edit, undo or redo, every reference is to an element of the mesh shown', () => {
  const rnd = random(0x57a1e);
  const view = createMeshView();
  let state = meshLesson.defaultState();
  let model = meshLesson.compute(view, state, ctx);
  const history = [state];
  let dropped = 0;
  let kept = 0;
  for (let step = 0; step < 400; step += 1) {
    // A pick and a hover made on the mesh shown now (or on none).
    const before = coreElements(model.mesh);
    view.selection.pick = rnd() < 0.85 ? anElement(rnd, before) : null;
    view.selection.hover = rnd() < 0.5 ? anElement(rnd, before) : null;
    const r = rnd();
    let next;
    if (r < 0.35) next = anotherMesh(rnd, state);
    else if (r < 0.65) {
      const operation = anEdit(rnd, model, before);
      next = operation ? withEdit(state, operation) : anotherMesh(rnd, state);
    } else if (r < 0.72 && state.ops.length) next = withEdit(state, { op: 'compact' });
    else next = history[Math.floor(rnd() * history.length)]; // undo or redo to a state of the history
    const pick = view.selection.pick && { ...view.selection.pick };
    const hover = view.selection.hover && { ...view.selection.hover };
    model = meshLesson.compute(view, next, ctx);
    state = next;
    history.push(state);
    const core = coreElements(model.mesh);
    const where = `step ${step}: ${state.meshKind}, ${state.ops.length} operations`;
    for (const [name, was, now] of [['pick', pick, view.selection.pick], ['hover', hover, view.selection.hover]]) {
      if (now) assert.ok(isElement(core, now), `${where}: the ${name} ${now.kind} ${now.index} is not an element of the mesh`);
      if (was && isElement(core, was)) {
        assert.deepEqual(now, was, `${where}: the ${name} ${was.kind} ${was.index} exists and is kept`);
        kept += 1;
      } else if (was) {
        assert.equal(now, null, `${where}: the ${name} ${was.kind} ${was.index} is dropped`);
        dropped += 1;
      }
    }
    // What the panels read of the model, none of which may throw.
    const walkCount = core.count[model.walkKind];
    assert.ok(model.walkElement >= 0 && model.walkElement < walkCount, `${where}: walk element ${model.walkElement} of ${walkCount}`);
    assert.equal(model.walkRemoved, core.gap[model.walkKind].has(model.walkElement), `${where}: the walk's element is said removed exactly when it is a gap`);
    if (!model.walkRemoved) assert.ok(model.frames.length > 0, `${where}: a walk of an element that exists has frames`);
    if (view.selection.pick?.kind === 'face') assert.ok(model.mesh.verticesOfFace(view.selection.pick.index).length >= 3);
    const kind = QUERY_ELEMENT[state.query.kind];
    const target = queryTarget(model, state.query, kind);
    assert.ok(target.index >= 0 && target.index < core.count[kind], `${where}: the query's ${kind}`);
    assert.equal(target.removed, core.gap[kind].has(target.index));
    if (!target.removed) model.mesh.query(state.query.kind, target.index);
    assert.equal(typeof meshLesson.describe(view, model, state), 'string');
  }
  // The run met both cases many times.
  assert.ok(dropped > 50 && kept > 50, `dropped ${dropped}, kept ${kept}`);
});
