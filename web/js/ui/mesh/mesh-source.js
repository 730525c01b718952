// @ts-check
// From the lesson state to a live winged-edge mesh in the core. The mesh handle is kept
// between computes (a traversal step, a hover or a view change must not rebuild a
// 10,000-face structure); it is rebuilt only when the mesh choice changes, and the old one
// is disposed only after the new one was accepted, so a refused file keeps the page's mesh.
// Moved vertices are applied with setVertexPosition, which reports per representation how
// many stored entries had to change (lecture 000: independent faces rewrite every copy).
// The state's operations (state.ops, e.g. {op: 'set-vertex-edge', v, e}) are replayed on
// the built mesh in order; a list that is not the applied list plus new operations at its
// end (undo, a link) rebuilds the mesh and replays it. Nothing here counts versions: the
// mesh does (mesh.id, mesh.version), and every cache is keyed on them (cacheKeys below).
// Offers: createMeshSource() -> { sync(state, api) -> {entry, changes}, live }, cacheKeys(entry).
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
  return mesh.apply(operation, { costs: newest });
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
    live = { key, mesh, base: positions, csr, applied: new Map(), ops: [], lastOperation: null };
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

  // Brings the mesh's operations to state.ops: new ones at the end are applied; any other
  // difference rebuilds the mesh and replays them all. Operations run on the positions the
  // operations before them left (state.moved is applied after all of them, so a lesson
  // that changes the topology first turns its pending moves into move-vertex operations:
  // see the mesh lesson's edit-ops.js withEdit). A refused operation changed nothing in the core (checked mutators) and
  // its error names it; live.ops stays what was applied.
  function applyOps(state, api) {
    const ops = state.ops ?? [];
    const prefix = live.ops.length <= ops.length && live.ops.every((o, i) => sameOp(o, ops[i]));
    if (!prefix) build(state, api, true);
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
        const record = applyOne(live.mesh, ops[i], live.lastOperation, newest);
        if (ops[i].op === 'compact') whole = true;
        else if (ops[i].op === 'move-vertex') live.base.set(ops[i].p, 3 * ops[i].v);
        else if (!whole) live.base = followPositions(live.base, live.mesh, record);
        live.lastOperation = record;
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
