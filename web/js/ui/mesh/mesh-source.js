// @ts-check
// From the lesson state to a live winged-edge mesh in the core. The mesh handle is kept
// between computes (a traversal step, a hover or a view change must not rebuild a
// 10,000-face structure); it is rebuilt only when the mesh choice changes, and the old one
// is disposed only after the new one was accepted, so a refused file keeps the page's mesh.
// Moved vertices are applied with setVertexPosition, which reports per representation how
// many stored entries had to change (lecture 000: independent faces rewrite every copy).
// The state's operations (state.ops, e.g. {op: 'set-vertex-edge', v, e}) are replayed on
// the built mesh in order. When the list differs from the applied one after a common start
// (undo, redo, another edit after an undo), the applied operations after it are taken back
// by the core's undo, newest first (O(the edits): mesh.undo() from each edit's record), and
// the new ones applied; only when that cannot be (a compact renumbered everything, the core
// kept no record) is the mesh built again and every operation replayed (O(mesh)). Nothing
// here counts versions: the mesh does (mesh.id, mesh.version), and every cache is keyed on
// them (cacheKeys below).
// Offers: createMeshSource() -> { sync(state, api) -> {entry, changes}, live }, cacheKeys(entry);
//   entry.changes: the change records of the last sync's edits and undos, in order (what
//   changed the tables: a lesson follows them rather than reading every row again);
//   entry.lastOperation: the record of the newest edit of the state (the edit player's).
// Needs: a state with a mesh choice (mesh-choice.js), `moved: [{v, p}]` and `ops` (the
//   lesson's checked operations, {op, ...}); the JS API (api.buildMesh, mesh.apply,
//   setVertexPosition, compact).
import { takeImportedMesh } from '../../app/mesh-import.js';
import { sourceKey, sourceOf, faceCsr, createImportedKeys } from './mesh-choice.js';
import { followPositions } from './winged-arrays.js';


const POSITION_EPS = 0; // positions are compared exactly: the state holds the doubles the core got

// The keys every cache of the lesson uses: one mesh state is (mesh id, version). `topology`
// changes with the connectivity (walks, queries, counts), `version` with anything (tables,
// positions); `source` only when another mesh was chosen (the view is fitted again).
export function cacheKeys(entry) {
  const { topology, geometry } = entry.mesh.version;
  return { source: entry.key, topology: `${entry.mesh.id}.${topology}`, version: `${entry.mesh.id}.${topology}.${geometry}` };
}

// Two operations of state.ops are the same when every field is (ops are small flat records:
// element numbers, a parameter t, a position p).
const sameOp = (a, b) => {
  const ka = Object.keys(a);
  return ka.length === Object.keys(b).length && ka.every((k) => (Array.isArray(a[k]) ? Array.isArray(b[k]) && a[k].length === b[k].length && a[k].every((x, i) => x === b[k][i]) : a[k] === b[k]));
};

// Above this many faces the newest edit counts the winged edge's cost alone: counting the
// other representations derives them before and after the edit (a pass over the whole mesh,
// about a second at a million faces), the very cost the lesson warns about. What the same
// edit costs them at every size is the edit panel's chart (edit_costs.h, edit_cost_growth).
export const COUNTED_COSTS_FACES = 100_000;

// One operation of the state on the live mesh; returns the change record the edit player
// shows (a move keeps the previous one; compact has none: it renumbers everything).
// `newest`: false, or how its cost is counted (apply's costs: true or 'winged-edge').
function applyOne(mesh, operation, previous, newest) {
  if (operation.op === 'move-vertex') {
    mesh.setVertexPosition(operation.v, operation.p);
    return previous;
  }
  if (operation.op === 'compact') {
    mesh.compact();
    return null;
  }
  // The newest edit is also stated in half-edge terms (its record's halfEdge, for the player).
  // Above COUNTED_COSTS_FACES only when the half-edge view was already kept (the Half-edge tab
  // was shown): making it is a pass over the mesh, and it holds 8 int32 per edge.
  if (newest === 'winged-edge') {
    const change = mesh.apply(operation, { costs: newest });
    return { ...change, halfEdge: mesh.lastHalfEdgeChange(change) };
  }
  return mesh.apply(operation, { costs: newest, halfEdge: newest === true });
}

export function createMeshSource() {
  let live = null; // { key, mesh, base: Float64Array, csr: {offsets, vertices}, applied: Map<v, [x,y,z]>, ops: [], lastOperation }
  const importedKey = createImportedKeys();

  function build(state, api, force = false) {
    const key = sourceKey(state, importedKey);
    if (live && live.key === key && !force) return live;
    const source = sourceOf(state, api);
    // An imported mesh's flat arrays, when the import worker left them, are what the core
    // builds from; otherwise the faces are turned into CSR once here.
    const csr = faceCsr(source);
    const positions = Float64Array.from(source.positions);
    const spec = { positions, faceOffsets: csr.offsets, faceVertices: csr.vertices };
    for (const field of ['edges', 'vertexEdges', 'faceEdges']) {
      if (source[field] && source[field].length) spec[field] = source[field];
    }
    // A fresh import's mesh was built in steps by the import (app/mesh-import.js).
    const mesh = (state.meshKind === 'file' && !force ? takeImportedMesh(state.imported) : null) ?? api.buildMesh(spec);
    const previous = live;
    // done[i]: what operation i left: its record (a move keeps the one before) and, for a
    // move, where the vertex was (what undoing it puts back).
    live = { key, mesh, base: positions, csr, applied: new Map(), ops: [], done: [], lastOperation: null, changes: [] };
    previous?.mesh.dispose();
    return live;
  }

  // The position of v before state.moved: where the file or the operations put it.
  const baseOf = (v) => [live.base[3 * v], live.base[3 * v + 1], live.base[3 * v + 2]];

  // Brings the core's positions to base + state.moved; returns the change reports.
  function applyMoves(state) {
    const wanted = new Map(state.moved.map((m) => [m.v, m.p]));
    const changes = [];
    const vertexCount = live.base.length / 3;
    for (const v of wanted.keys()) {
      if (v >= vertexCount) throw Object.assign(new Error(`moved vertex v${v + 1} does not exist in this mesh (it has ${vertexCount} vertices)`), { code: 'invalid-element' });
    }
    const targets = new Set([...wanted.keys(), ...live.applied.keys()]);
    for (const v of targets) {
      const p = wanted.get(v) ?? baseOf(v);
      const now = live.applied.get(v) ?? baseOf(v);
      if (Math.abs(p[0] - now[0]) <= POSITION_EPS && Math.abs(p[1] - now[1]) <= POSITION_EPS && Math.abs(p[2] - now[2]) <= POSITION_EPS) continue;
      changes.push({ vertex: v, changed: live.mesh.setVertexPosition(v, p) });
      if (wanted.has(v)) live.applied.set(v, p.slice()); else live.applied.delete(v);
    }
    return changes;
  }

  // Takes the applied operations back to the first n by the core's undo, newest first;
  // false (the mesh part-way back: the caller builds it again) when one cannot be: a compact
  // (it renumbered everything), an edit whose record the core no longer keeps.
  function undoTo(n) {
    if (live.ops.slice(n).some((o) => o.op === 'compact')) return false;
    applyMoves({ moved: [] });
    while (live.ops.length > n) {
      const operation = live.ops[live.ops.length - 1];
      const done = live.done[live.done.length - 1];
      if (operation.op === 'move-vertex') {
        live.mesh.setVertexPosition(operation.v, done.from);
        live.base.set(done.from, 3 * operation.v);
      } else {
        let record;
        try { record = live.mesh.undo(); } catch { return false; }
        live.base = followPositions(live.base, live.mesh, record);
        live.changes.push(record);
      }
      live.ops.pop();
      live.done.pop();
    }
    live.lastOperation = live.done.at(-1)?.record ?? null;
    return true;
  }

  // Brings the mesh's operations to state.ops: after the start both lists share, the applied
  // ones are taken back (undoTo) and the new ones applied. Operations run on the positions the
  // operations before them left (state.moved is applied after all of them, so a lesson
  // that changes the topology first turns its pending moves into move-vertex operations:
  // see the mesh lesson's edit-ops.js withEdit). A refused operation changed nothing in the core (checked mutators) and
  // its error names it; live.ops stays what was applied.
  function applyOps(state, api) {
    const ops = state.ops ?? [];
    live.changes = [];
    let common = 0;
    while (common < live.ops.length && common < ops.length && sameOp(live.ops[common], ops[common])) common += 1;
    if (common < live.ops.length && !undoTo(common)) build(state, api, true);
    // The newest edit left after an undo shows its cost as when it was made: an edit replayed
    // from a link was not counted, so it is taken back and made again, counted (O(the edit)).
    if (ops.length === live.ops.length && live.lastOperation && !live.lastOperation.costs && live.ops.at(-1)?.op !== 'move-vertex'
      && live.ops.at(-1)?.op !== 'compact' && undoTo(live.ops.length - 1) === false) build(state, api, true);
    if (live.ops.length === ops.length) return;
    // Take the moves back first: the new operations run where the older ones left the mesh.
    applyMoves({ moved: [] });
    // The positions before the moves follow each edit's record (the vertices it moved or
    // added), not a copy of the whole table per edit; a compact renumbers everything.
    let whole = false;
    for (let i = live.ops.length; i < ops.length; i += 1) {
      try {
        // The newest edit also counts what each representation rewrote (the panel shows it).
        const newest = i === ops.length - 1 && (live.csr.offsets.length - 1 > COUNTED_COSTS_FACES ? 'winged-edge' : true);
        const from = ops[i].op === 'move-vertex' ? Array.from(live.base.subarray(3 * ops[i].v, 3 * ops[i].v + 3)) : null;
        const record = applyOne(live.mesh, ops[i], live.lastOperation, newest);
        if (ops[i].op === 'compact') whole = true;
        else if (ops[i].op === 'move-vertex') live.base.set(ops[i].p, 3 * ops[i].v);
        else if (!whole) live.base = followPositions(live.base, live.mesh, record);
        if (record && ops[i].op !== 'move-vertex') live.changes.push(record);
        live.lastOperation = record;
        live.done.push({ record, from });
      } catch (err) {
        err.message = `Operation ${i + 1} (${ops[i].op}) was refused: ${err.message}`;
        live.base = Float64Array.from(live.mesh.wingedEdgeArrays().positions);
        throw err;
      }
      live.ops.push(structuredClone(ops[i]));
    }
    if (whole) live.base = Float64Array.from(live.mesh.wingedEdgeArrays().positions);
  }

  return {
    // The live mesh for this state (built or reused, operations replayed, moves applied).
    sync(state, api) {
      build(state, api);
      applyOps(state, api);
      const changes = applyMoves(state);
      return { entry: live, changes };
    },
    get live() { return live; },
  };
}
