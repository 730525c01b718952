// @ts-check
// The mesh lesson (lectures 000, 001, 003): one mesh, every representation of it
// live, the winged-edge walks around a vertex and along a face animated as the slide tells
// them, the representations' query costs and storage, and plane equations and normals.
// The state is plain JSON (schema below); the model is what the core returned for it.
import { number, integer, boolean, oneOf, text, list, object, nullable, viewSchema, SchemaError } from '../../app/schema.js';
import { MAX_MESH_VERTICES, MAX_MESH_FACES, MAX_FACE_CORNERS } from '../../app/limits.js';
import { importedMesh } from '../../app/imported-mesh.js';
import { createMeshSource, cacheKeys } from '../../ui/mesh/mesh-source.js';
import { faceCsr } from '../../ui/mesh/mesh-choice.js';
import { MESH_KINDS, MESH_SIZES, IMPORTED_CONTENT } from './choices.js';
import { playedArrays, playedToEnd, visibleSteps, playbackSteps, wingedStepAt } from './edit-playback.js';
import { normaliseSteps, walkFrames } from '../../ui/mesh/walk.js';
import { followEdit, followFaces, followRows, recordEdges } from '../../ui/mesh/winged-arrays.js';
import { drawMesh, createBaseCache } from '../../ui/mesh/draw.js';
import { LABEL_LIMIT } from '../../ui/mesh/label-plan.js';
import { viewRotation, projectAll, unprojectDelta, facesAway, fitProjected } from '../../ui/mesh/view.js';
import { setupPanels } from './panels.js';
import { meshExports } from './exports.js';
import { vLabel, fLabel, eLabel } from './labels.js';
import { meshExercise } from './exercise.js';
import { dropStale } from './live-elements.js';

export const TABS = ['winged', 'faces', 'vertex-face', 'adjacency', 'edge-list', 'half-edge', 'queries', 'storage', 'planes'];
export const QUERY_KINDS = ['faces-around-vertex', 'edges-around-vertex', 'edges-of-face', 'neighbours-of-face', 'faces-of-edge'];
// The state format's bounds on an imported mesh: app/limits.js, which equals the core's file
// limits (api.meshLimits; tests/wasm/mesh-trust.test.mjs checks that they agree).
const MAX_IMPORT_VERTICES = MAX_MESH_VERTICES;
const MAX_IMPORT_FACES = MAX_MESH_FACES;

// The mesh operations a state may hold, replayed in order on the built mesh.
// Each is checked for shape here; whether it fits the mesh (an edge of that vertex or face)
// is the core's check when it is replayed, which names the operation if it refuses.
const MAX_OPS = 1000;
const elementIndex = integer({ min: 0, max: 10000000 });
const opName = text({ maxLength: 40 });
// An operation of the core's registry ({op: 'flip-edge', e: 4}, {op: 'split-face', f, a, b},
// ...) is checked here for shape only: a name and up to four arguments, each a number.
// Which names and values an operation takes is the core's (its registry and its check,
// when the state is replayed; a refusal names the operation), so a new operation of the
// core needs nothing here. The lesson's own steps have their shapes below.
const argument = number({ min: 0, max: 10000000 });
const coreOperation = (v, path) => {
  if (v === null || typeof v !== 'object' || Array.isArray(v)) throw new SchemaError(path, 'must be an object such as {"op": "flip-edge", "e": 3}');
  const keys = Object.keys(v);
  if (keys.length > 5) throw new SchemaError(path, 'has more than four arguments');
  /** @type {Record<string, any>} */
  const out = { op: opName(v.op, `${path}.op`) };
  for (const k of keys) {
    if (k === 'op') continue;
    if (!/^[a-z][A-Za-z]{0,15}$/.test(k)) throw new SchemaError(`${path}`, `has an argument named "${k.slice(0, 20)}", which no operation takes`);
    out[k] = argument(v[k], `${path}.${k}`);
  }
  return out;
};
const LESSON_STEPS = {
  // A vertex moved before a later edit (edit-ops.js withEdit), and the renumbering step.
  'move-vertex': object({ op: opName, v: elementIndex, p: list(number(), { min: 3, max: 3 }) }),
  compact: object({ op: opName }),
};
const operation = (v, path) => (Object.hasOwn(LESSON_STEPS, v?.op) ? LESSON_STEPS[v.op](v, path) : coreOperation(v, path));

const size = (bounds) => integer({ min: bounds[0], max: bounds[1] });
const schema = {
  meshKind: oneOf(...MESH_KINDS.map((k) => k.id)),
  // The sizes' bounds are the chooser's (choices.js MESH_SIZES): up to the benchmarks'
  // sphere_1000000 (1000 x 501) and a little more, which the GPU draws.
  fanSize: size(MESH_SIZES.fan[0]),
  grid: object({ nx: size(MESH_SIZES.grid[0]), ny: size(MESH_SIZES.grid[1]) }),
  sphere: object({ slices: size(MESH_SIZES.sphere[0]), stacks: size(MESH_SIZES.sphere[1]) }),
  // Either form of app/imported-mesh.js (flat in the current format; faces: older states and links).
  imported: nullable(importedMesh({ maxVertices: MAX_IMPORT_VERTICES, maxFaces: MAX_IMPORT_FACES, maxCorners: MAX_FACE_CORNERS })),
  moved: list(object({ v: integer({ min: 0, max: 10000000 }), p: list(number(), { min: 3, max: 3 }) }), { max: 100000 }),
  ops: list(operation, { max: MAX_OPS }),
  walk: oneOf('vertex', 'face'),
  vertex: integer({ min: 0, max: 10000000 }),
  face: integer({ min: 0, max: 10000000 }),
  step: integer({ min: 0, max: 100000 }),
  speed: number({ min: 0.25, max: 20 }),
  tab: oneOf(...TABS),
  query: object({ kind: oneOf(...QUERY_KINDS), vertex: integer({ min: 0, max: 10000000 }), face: integer({ min: 0, max: 10000000 }), edge: integer({ min: 0, max: 10000000 }) }),
  mode3d: boolean(),
  rotation: object({ yaw: number({ min: -100, max: 100 }), pitch: number({ min: -100, max: 100 }) }),
  // The edit panel: t for split and collapse; how many assignments of the last edit are
  // shown (-1: all, the edit done).
  editT: number({ min: 0.1, max: 0.9 }),
  editStep: integer({ min: -1, max: 100000 }),
  view: viewSchema(),
};

function defaultState() {
  return {
    meshKind: 'lecture',
    fanSize: 6,
    grid: { nx: 4, ny: 3 },
    sphere: { slices: 12, stacks: 6 },
    imported: null,
    moved: [],
    ops: [],
    walk: 'vertex',
    vertex: 1, // v2: the slide's example
    face: 0,
    step: 0,
    speed: 1.5,
    tab: 'winged',
    query: { kind: 'faces-around-vertex', vertex: 1, face: 0, edge: 2 },
    mode3d: false,
    rotation: { yaw: 0.6, pitch: 0.45 },
    view: { cx: 1, cy: 0.5, zoom: 150 },
    editT: 0.5,
    editStep: -1,
  };
}

function checkState(state) {
  if (state.meshKind === 'file' && !state.imported) return 'the state names an imported mesh but does not hold it';
  return null;
}

// What compute needs of the lesson view, without the page: the hovered and picked element
// (live-elements.js keeps them to the model's elements), the live mesh and its caches.
// setup adds the panels and the picture; a test in Node computes with this alone.
export function createMeshView() {
  return { selection: { hover: null, pick: null, gone: null }, source: createMeshSource(), derived: createDerived() };
}

// Per-topology and per-version caches (keyed on the mesh's id and version, cacheKeys), so a
// traversal step costs one frame lookup. One per lesson view (setup).
function createDerived() {
  return { topology: null, version: null, viewKey: null, projected: null, zExtent: 0, we: null, played: null, counts: null, steps: new Map(), planes: null, lastChange: null };
}

function wingedTables(derived, entry, keys) {
  const previous = derived.source === keys.source ? derived.version : null;
  const previousGaps = derived.gaps;
  if (derived.topology !== keys.topology) {
    const sameSource = derived.source === keys.source;
    Object.assign(derived, { source: keys.source, topology: keys.topology, version: null, counts: entry.mesh.counts(), steps: new Map(), planes: null, reps: null, halfEdge: null, storage: null, queryKey: null, query: null, faces: sameSource ? derived.faces : null, follow: null, gaps: null, lastChange: sameSource ? derived.lastChange : null });
  }
  if (derived.version !== keys.version) {
    // The edits and undos since the tables were read (entry.changes, in order: the undos
    // first): only the rows their records name are read again (ui/mesh/winged-arrays.js),
    // from the mesh as it is now; anything else (another mesh, a move, a compact) reads them
    // whole.
    const chain = entry.changes ?? [];
    const id = entry.mesh.id;
    const key = (v) => `${id}.${v.topology}.${v.geometry}`;
    const follows = Boolean(derived.we) && chain.length > 0 && previous === key(chain[0].before) && keys.version === key(chain[chain.length - 1].after)
      && chain.every((c, i) => c.rows && (i === 0 || key(chain[i - 1].after) === key(c.before)));
    derived.version = keys.version;
    derived.we = follows ? chain.reduce((we, c) => followEdit(we, entry.mesh, c), derived.we) : entry.mesh.wingedEdgeArrays();
    // The edit player's tables (edit-playback.js playedArrays) follow the same way, from the
    // end of the edit they played; after a whole read they are made again when next played.
    if (follows && derived.played) derived.played.arrays = chain.reduce((a, c) => followEdit(a, entry.mesh, c), playedToEnd(derived.played).arrays);
    else derived.played = null;
    // The faces the same way: only those the changes can have changed are read again (a face
    // whose corners changed is beside an edge its last change rewrote, in the mesh as it is
    // now: followFaces on the records together). Faces depend on the topology alone; at the
    // topology the mesh was built with they are the source's own.
    const beforeTopology = follows ? `${id}.${chain[0].before.topology}` : null;
    const before = !follows ? null : derived.faces?.topology === beforeTopology ? derived.faces : chain[0].before.topology === 0 ? entry.csr : null;
    derived.follow = null;
    if (before) {
      // The lesson's own faces are rewritten in place where the layout allows (the source's
      // faces never are).
      const all = (part, list) => chain.flatMap((c) => Array.from(c[part][list]));
      const together = {
        rows: chain.flatMap((c) => c.rows),
        added: { vertices: all('added', 'vertices'), edges: all('added', 'edges'), faces: all('added', 'faces') },
        removed: { vertices: all('removed', 'vertices'), edges: all('removed', 'edges'), faces: all('removed', 'faces') },
      };
      const followed = followFaces(before, entry.mesh, derived.we, together, { own: before !== entry.csr });
      derived.faces = { offsets: followed.offsets, vertices: followed.vertices, topology: keys.topology };
      derived.follow = {
        from: previous,
        faces: followed.touched,
        vertices: [...chain.flatMap((c) => c.positions.map((p) => p.vertex)), ...together.added.vertices, ...together.removed.vertices],
        edges: recordEdges(together),
      };
    } else if (derived.faces?.topology !== keys.topology) {
      derived.faces = null;
    }
    // The gaps likewise: the ones before, with the elements an edit removed and without
    // those an undo made live again; the marks per element are made again only when there
    // are gaps.
    derived.gaps = follows && previousGaps ? chain.reduce(followGaps, previousGaps) : null;
    derived.gapMarks = null;
    derived.planes = null;
    derived.reps = null;
    derived.storage = null;
    // After a followed edit the view keeps turning about the centre it had (the edit moved a
    // few vertices; the whole mesh is not measured again).
    if (!derived.follow) derived.centre = null;
    derived.faceNormals = null;
    derived.sideKey = null;
  }
  return derived.we;
}

function stepsOf(derived, entry, kind, element) {
  const key = `${kind}:${element}`;
  if (!derived.steps.has(key)) {
    const raw = kind === 'vertex' ? entry.mesh.traversalSteps(element) : entry.mesh.faceEdgeSteps(element);
    derived.steps.set(key, walkFrames(kind, element, normaliseSteps(raw, kind)));
  }
  return derived.steps.get(key);
}

function compute(view, state, ctx) {
  // Headless (the exercise grader: view {}), the view gets what compute needs of it.
  const { source, derived } = view.source ? view : Object.assign(view, createMeshView());
  const { entry, changes } = source.sync(state, ctx.api);
  const keys = cacheKeys(entry);
  const we = wingedTables(derived, entry, keys);
  if (changes.length) derived.lastChange = changes[changes.length - 1];
  // After an edit the faces are the mesh's own (a removed face is a gap: no corners).
  const edited = entry.ops.length > 0;
  // Faces as CSR (ui/mesh/mesh-choice.js faceCsr); a removed face has no corners.
  // Read from the winged edge (faceSet), not from the vertex and face tables, which would
  // derive every other representation (seconds on a million faces).
  const csr = edited ? (derived.faces ??= { ...faceCsr(entry.mesh.faceSet()), topology: keys.topology }) : entry.csr;
  derived.gaps ??= edited ? entry.mesh.gaps() : { vertices: [], edges: [], faces: [] };
  const gaps = derived.gaps.vertices.length + derived.gaps.edges.length + derived.gaps.faces.length;
  const record = entry.lastOperation;
  // The player's steps are the tab's: on the half-edge tab the edit's half-edge entries, and
  // the picture shows the winged-edge step the current one follows.
  const playback = playbackSteps(record, state.tab);
  const editSteps = playback.length;
  const editStep = state.editStep < 0 || state.editStep > editSteps ? editSteps : state.editStep;
  const halfEdgePlayback = Boolean(record?.halfEdge) && state.tab === 'half-edge';
  const wingedSteps = visibleSteps(record).length;
  const wingedStep = halfEdgePlayback ? (editStep < editSteps ? wingedStepAt(record, editStep) : wingedSteps) : editStep;
  const V = we.vertexEdge.length;
  const F = we.faceEdge.length;
  const E = we.edges.length / 8;
  derived.gapMarks ??= gaps ? { vertex: marks(V, derived.gaps.vertices), edge: marks(E, derived.gaps.edges) } : null;
  const walkKind = state.walk;
  const walkElement = walkKind === 'vertex' ? Math.min(state.vertex, V - 1) : Math.min(state.face, F - 1);
  // 1 where a removed element left its number (drawing and picking skip it); null: no gaps.
  // Made once per mesh version.
  const vertexGap = derived.gapMarks?.vertex ?? null;
  // While the edit player is inside an edit the picture shows the tables as they stood: an
  // edge whose S or E is not written yet is not drawn (like a gap). Only the edit's edges
  // can be so.
  const weShown = record && wingedStep < wingedSteps ? (derived.played = playedArrays(derived.played, we, record, wingedStep)).arrays : we;
  const edgeGap = weShown !== we ? unwritten(weShown, recordEdges(record), derived.gapMarks?.edge.slice() ?? new Uint8Array(E)) : derived.gapMarks?.edge ?? null;
  const step = record && editStep > 0 && editStep < editSteps ? playback[editStep - 1] : null;
  // A half-edge entry marks its edge (a half-edge row) or its vertex or face on the canvas.
  const current = step && halfEdgePlayback ? { table: step.table === 'halfedge' ? 'edge' : step.table, row: step.table === 'halfedge' ? step.row >> 1 : step.row } : step;
  const removed = walkKind === 'vertex' ? vertexGap?.[walkElement] : csr.offsets[walkElement + 1] === csr.offsets[walkElement];
  const frames = walkElement >= 0 && !removed ? stepsOf(derived, entry, walkKind, walkElement) : [];
  const frame = frames[Math.min(state.step, frames.length - 1)] ?? null;
  const R = viewRotation(state);
  const viewKey = `${keys.version}:${state.mode3d}:${R.join(',')}`;
  // The largest |z| (is the mesh flat?), per mesh version: after a followed edit from the
  // vertices it moved or added, otherwise over every vertex.
  if (derived.zVersion !== keys.version) {
    if (derived.follow && derived.zVersion === derived.follow.from) {
      for (const v of derived.follow.vertices) if (v < V) derived.zExtent = Math.max(derived.zExtent, Math.abs(we.positions[3 * v + 2]));
    } else {
      let zExtent = 0;
      for (let v = 0; v < V; v += 1) zExtent = Math.max(zExtent, Math.abs(we.positions[3 * v + 2]));
      derived.zExtent = zExtent;
    }
    derived.zVersion = keys.version;
  }
  if (derived.viewKey !== viewKey) {
    derived.centre ??= entry.mesh.boundingBox().centre;
    // In 2D the positions are shown exactly as they are ((p - c) + c would round them).
    const about = state.mode3d ? derived.centre : [0, 0, 0];
    if (derived.follow && derived.projected && derived.viewKey === `${derived.follow.from}:${state.mode3d}:${R.join(',')}`) {
      // The same view of the mesh before the edit: only the vertices it moved or added.
      const projected = followRows(derived.projected, 3, V, derived.follow.vertices, (v) => projectAll(we.positions.subarray(3 * v, 3 * v + 3), R, about));
      Object.assign(derived, { viewKey, projected });
    } else {
      // Every vertex turned by the view when first read (model.projected): a turn of a big
      // mesh drawn by the GPU reads a few vertices only (model.points), not all of them.
      Object.assign(derived, { viewKey, projected: null });
    }
    derived.projection = { R, about, positions: we.positions };
  }
  // Seen from behind: the walked vertex's normal (faces around it, by area) or the walked
  // face's normal, both from the core, points away from the viewer.
  const sideKey = `${viewKey}:${walkKind}:${walkElement}`;
  if (derived.sideKey !== sideKey) {
    derived.sideKey = sideKey;
    derived.fromBehind = state.mode3d && walkElement >= 0 && !removed
      && facesAway(R, walkKind === 'vertex' ? entry.mesh.vertexNormal(walkElement) : faceNormal(derived, entry.mesh, walkElement));
  }
  const model = {
    mesh: entry.mesh,
    source: keys.source,
    topology: keys.topology,
    version: keys.version,
    positions: we.positions,
    // Every vertex turned by the view (x, y, depth per vertex), made when first read.
    get projected() {
      const { R: r, about, positions } = derived.projection;
      derived.projected ??= projectAll(positions, r, about);
      return derived.projected;
    },
    // The same for reading a few vertices (a walk, a highlight, a pick's candidates): the
    // whole array once made or on a small mesh, otherwise each vertex turned when read.
    get points() {
      if (derived.projected || V <= LAZY_PROJECTION_FROM) return this.projected;
      const { R: r, about, positions } = derived.projection;
      return lazyPoints((v) => projectAll(positions.subarray(3 * v, 3 * v + 3), r, about));
    },
    rotation: R,
    faceOffsets: csr.offsets,
    faceVertices: csr.vertices,
    centre: derived.centre,
    we,
    // The winged-edge tables as the edit player shows them (after editStep assignments).
    weShown,
    editRow: current ? { kind: current.table, index: current.row } : null,
    lastOperation: record,
    lastEdit: lastEditOf(state.ops),
    editStep,
    // How many steps the player has on this tab, and whether they are the half-edge entries.
    editSteps,
    halfEdgePlayback,
    editCount: state.ops.filter((o) => o.op !== 'move-vertex').length,
    editCost: record?.costs ?? null,
    gaps,
    gapLists: derived.gaps,
    vertexGap,
    edgeGap,
    V, E, F,
    counts: derived.counts,
    is3dMesh: derived.zExtent > 0,
    mode3d: state.mode3d,
    walkKind, walkElement, frames, frame,
    // The walk's element is a number an edit removed (a gap): nothing to walk, and said.
    walkRemoved: Boolean(removed),
    walkSeenFromBehind: derived.fromBehind,
    stepIndex: Math.min(state.step, Math.max(0, frames.length - 1)),
    lastChange: derived.lastChange,
    derived,
  };
  // Whatever changed the state (another mesh, undo, redo, an import, a link, an edit), the
  // picked and hovered element are the model's or nothing: the panels and the drawing only
  // ever ask the core about elements it has.
  dropStale(view.selection, model);
  return model;
}

// From this many vertices a turn of the view does not project every vertex at once (about
// 40 ms at a million faces): what a frame draws over the GPU's picture reads few of them.
// (Up to it, every vertex has a handle to drag: all are read anyway.)
const LAZY_PROJECTION_FROM = 20_000;

// Reads like the projected array (p[3v], p[3v + 1], p[3v + 2]), each vertex turned when
// first read.
function lazyPoints(project) {
  const turned = new Map();
  return new Proxy({}, {
    get(_, key) {
      const i = Number(key);
      if (!Number.isInteger(i) || i < 0) return undefined;
      const v = Math.floor(i / 3);
      let p = turned.get(v);
      if (!p) { p = project(v); turned.set(v, p); }
      return p[i - 3 * v];
    },
  });
}

function unwritten(weShown, edges, out) {
  for (const e of edges) if (e < out.length && (weShown.edges[8 * e] < 0 || weShown.edges[8 * e + 1] < 0)) out[e] = 1;
  return out;
}

// The gaps after an edit: those before it and the elements it removed, increasing.
// The gaps after one change, from those before it (increasing lists): an edit's removed
// elements join them; an undo's live-again elements (its `added`) leave them.
function followGaps(before, record) {
  const undo = record.op === 'undo';
  const next = (a, b) => {
    const changed = new Set(Array.from(b));
    const kept = undo ? Array.from(a).filter((i) => !changed.has(i)) : [...new Set([...Array.from(a), ...changed])];
    return Int32Array.from(kept).sort();
  };
  const by = undo ? record.added : record.removed;
  return { vertices: next(before.vertices, by.vertices), edges: next(before.edges, by.edges), faces: next(before.faces, by.faces) };
}

function marks(n, list) {
  const out = new Uint8Array(n);
  for (const i of list) out[i] = 1;
  return out;
}

// The last edit of the state (the one the player shows), its moves aside.
function lastEditOf(ops) {
  for (let i = ops.length - 1; i >= 0; i -= 1) if (ops[i].op !== 'move-vertex') return ops[i];
  return null;
}

function faceNormal(derived, mesh, f) {
  derived.faceNormals ??= mesh.normals(); // once per mesh version, not per frame of a drag
  const n = derived.faceNormals;
  return [n[3 * f], n[3 * f + 1], n[3 * f + 2]];
}

// margin: room for the labels beside the vertices
const fitView = (view, model, stage) => (model ? fitProjected(model.projected, stage, 0.18) : defaultState().view);

// The walk on a big mesh: when the walk's element changes (or the walk starts
// on a new mesh) and the ring it walks would be a speck (under WALK_MIN_PX across) or off
// the canvas, the view centres on it at WALK_ZOOM_FRACTION of the canvas. Once per element:
// a person who then zooms out or pans keeps their view while the walk steps. The first
// frame of a page records only (a saved or linked view stays).
const WALK_MIN_PX = 80;
const WALK_ZOOM_FRACTION = 0.4;
function zoomToWalk(view, model, state, ctx) {
  if (!model?.frames.length || model.E <= LABEL_LIMIT) return;
  const key = `${model.source}:${state.walk}:${model.walkElement}:${model.stepIndex > 0}`;
  const first = view.walkZoomKey === undefined;
  if (view.walkZoomKey === key) return;
  view.walkZoomKey = key;
  if (first) return;
  // The ring: the ends of every edge the whole walk meets (its last frame), in the view plane.
  const P = model.points;
  let minX = Infinity; let minY = Infinity; let maxX = -Infinity; let maxY = -Infinity;
  for (const e of model.frames[model.frames.length - 1].order) {
    for (const v of [model.we.edges[8 * e], model.we.edges[8 * e + 1]]) {
      minX = Math.min(minX, P[3 * v]); maxX = Math.max(maxX, P[3 * v]);
      minY = Math.min(minY, P[3 * v + 1]); maxY = Math.max(maxY, P[3 * v + 1]);
    }
  }
  if (!Number.isFinite(minX)) return;
  const { width, height } = ctx.stage.size;
  const v = state.view;
  const extent = Math.max(maxX - minX, maxY - minY, 1e-12);
  const [sx, sy] = ctx.stage.transform().toScreen((minX + maxX) / 2, (minY + maxY) / 2);
  const onCanvas = sx >= 0 && sx <= width && sy >= 0 && sy <= height;
  if (onCanvas && extent * v.zoom >= WALK_MIN_PX) return;
  const zoom = Math.min(1e5, Math.max(1, (WALK_ZOOM_FRACTION * Math.min(width, height)) / extent));
  ctx.setView({ cx: (minX + maxX) / 2, cy: (minY + maxY) / 2, zoom: Math.max(zoom, v.zoom) });
}

function handles(view, model) {
  if (!model || model.V > 20000) return [];
  const out = [];
  for (let v = 0; v < model.V; v += 1) if (!model.vertexGap?.[v]) out.push({ id: `v${v}`, x: model.projected[3 * v], y: model.projected[3 * v + 1], label: vLabel(v) });
  return out;
}

// A vertex dragged in the view plane moves by R^T (dx, dy, 0) in the world (in 2D: x, y).
function moveHandle(view, state, id, x, y, model) {
  const v = Number(id.slice(1));
  if (!model || !Number.isInteger(v) || v >= model.V || model.vertexGap?.[v]) return null;
  if (view.pressed) view.pressed.dragged = true; // a drag, not a click: the walk keeps its vertex
  const [dx, dy, dz] = unprojectDelta(model.rotation, x - model.projected[3 * v], y - model.projected[3 * v + 1]);
  const p = [model.positions[3 * v] + dx, model.positions[3 * v + 1] + dy, model.positions[3 * v + 2] + dz];
  const moved = state.moved.filter((m) => m.v !== v).concat([{ v, p }]);
  return { ...state, moved };
}

function describe(view, model, state) {
  if (!model) return 'No mesh.';
  const kind = MESH_KINDS.find((k) => k.id === state.meshKind)?.label ?? state.meshKind;
  const labels = model.V <= LABEL_LIMIT ? 'Vertices, directed edges (arrows from S to E) and faces are labelled as on the slides.' : 'Too many elements for labels.';
  const walk = model.frame ? ` Walk ${state.walk === 'vertex' ? `around ${vLabel(model.walkElement)}` : `along ${fLabel(model.walkElement)}`}, step ${model.stepIndex} of ${model.frames.length - 1}: ${model.frame.text}` : '';
  return `${kind}: ${model.V} vertices, ${model.E} edges, ${model.F} faces, ${state.mode3d ? '3D view' : '2D view'}. ${labels}${walk}`;
}

// Importers: the import worker (app/mesh-import.js) has the core parse the file (its message
// names the line; the mesh limits, api.meshLimits, are checked from an OFF header before
// reading on) and report every problem (validateMesh); the page keeps its mesh when one is
// an error, or when building fails, because the shell only replaces the state after compute.
function importMesh(view, { value, problems }, state, name) {
  // Every problem, not only the first: the panel lists them with the elements involved.
  const errors = problems.filter((p) => p.severity === 'error');
  view.panels.showReport(name, problems);
  if (errors.length) {
    throw Object.assign(new Error(`${errors[0].message}${errors.length > 1 ? ` (and ${errors.length - 1} more problem${errors.length > 2 ? 's' : ''}, listed in the validation report)` : ''}`), { code: errors[0].code });
  }
  return { ...state, meshKind: 'file', imported: value, moved: [], ops: [], vertex: 0, face: 0, step: 0, query: { ...state.query, vertex: 0, face: 0, edge: 0 } };
}

/** @type {import('../../app/contract.js').Lesson} */
export const meshLesson = {
  id: 'mesh',
  title: 'Mesh representations',
  // The core modules the page loads (docs/architecture.md, "Module size").
  core: ['mesh'],
  stateVersion: 3,
  exercise: meshExercise,
  // Version 2 holds the mesh operations; a version 1 state had none. Version 3
  // adds the edit panel's t and playback step.
  migrations: { 1: (old) => ({ ...old, ops: [] }), 2: (old) => ({ ...old, editT: 0.5, editStep: -1 }) },
  schema,
  defaultState,
  checkState,
  contentFields: IMPORTED_CONTENT,
  compute,
  // The view: the panels, the live mesh (source), the caches derived from it and the
  // picture cache of a big mesh, the hovered and picked element; nothing of the lesson lives at module level.
  setup: (ctx) => {
    const { selection, source, derived } = createMeshView(); // selection: the hovered and picked element ({kind, index})
    // walkZoomKey: the walk (element, step) the view last followed (zoomToWalk; undefined until
    // the first frame); pressed: the vertex under a pressed pointer, until it is released.
    // pointer.down: a pointer is pressed (seen first, in the capture phase), so onSelect
    // tells a press from a selection by [ and ].
    const pointer = { down: false };
    window.addEventListener('pointerdown', () => { pointer.down = true; }, true);
    for (const type of ['pointerup', 'pointercancel']) window.addEventListener(type, () => { pointer.down = false; }, true);
    return { selection, panels: setupPanels(ctx, selection), source, derived, baseCache: createBaseCache(), walkZoomKey: undefined, pressed: null, pointer };
  },
  update: (view, model, state) => view.panels.update(model, state),
  afterFrame: zoomToWalk,
  draw: (view, painter, model, state, ctx) => drawMesh(view.baseCache, view.selection, painter, model, state, ctx),
  handles,
  moveHandle,
  describe,
  // One line for the History: which mesh, and what was done to it.
  summarize: (state) => {
    const mesh = state.meshKind === 'file' ? `"${state.imported?.name ?? 'an imported mesh'}"`
      : state.meshKind === 'grid' ? `grid ${state.grid.nx} x ${state.grid.ny}` : state.meshKind === 'fan' ? `fan of ${state.fanSize}`
        : state.meshKind === 'sphere' ? `sphere ${state.sphere.slices} x ${state.sphere.stacks}` : `${state.meshKind} mesh`;
    const edits = state.ops?.length ?? 0;
    const moved = state.moved?.length ?? 0;
    return `${mesh}, ${edits} edit${edits === 1 ? '' : 's'}, ${moved} moved ${moved === 1 ? 'vertex' : 'vertices'}`;
  },
  fitView,
  // A vertex pressed with the pointer becomes the walk's vertex when it is released without
  // being dragged (dragging a vertex must not silently change the walk's vertex);
  // chosen with [ and ] it is only selected, for the arrow keys.
  onSelect(view, id, ctx) {
    if (id === null) return;
    const v = Number(String(id).slice(1));
    view.selection.pick = { kind: 'vertex', index: v }; // the edit panel's element too
    if (!view.pointer.down) return; // [ or ]: selected for the arrow keys only
    view.pressed = { v, dragged: false };
    // A second finger down before the release makes it a pinch (the view), not a choice.
    const secondPointer = () => { if (view.pressed) view.pressed.dragged = true; };
    window.addEventListener('pointerdown', secondPointer, { capture: true });
    window.addEventListener('pointerup', () => {
      window.removeEventListener('pointerdown', secondPointer, { capture: true });
      const pressed = view.pressed;
      view.pressed = null;
      const state = ctx.state;
      if (pressed && !pressed.dragged && state.walk === 'vertex' && state.vertex !== pressed.v && ctx.ui.exercise !== 'walk') ctx.commit({ ...state, vertex: pressed.v, step: 0 }, { history: false });
    }, { once: true });
  },
  click(view, x, y, ctx, event) {
    return view.panels.canvasClick(x, y, event);
  },
  exports: meshExports,
  meshImporters: { off: importMesh, obj: importMesh },
};
