// @ts-check
// Mesh part of the API: plain values, 0-based indices, -1 = none.
// A built mesh lives in the core's registry; the Mesh object below holds only its integer
// handle, and mesh.dispose() frees it at once (a FinalizationRegistry is only a safety net
// for a forgotten dispose, never the mechanism). See docs/api-mesh.md.
import { WingsplineError, unwrap, fail, integerIn, isNumberArray, elementIndex, INT32_MAX } from './errors.js';
import { elementLabel } from './element-labels.js';
import { readTable, findDescriptor } from './tables.js';

// Three numbers [x, y, z] (whether they are finite is the core's check, with its message).
function vector3(value, what) {
  if (!isNumberArray(value) || value.length !== 3) fail('invalid-argument', `${what} must be three numbers [x, y, z]`);
  return value;
}

// Mesh files cross into the module as UTF-8 bytes, copied once (see meshParse).
const utf8 = new TextEncoder();


function checkPositions(positions) {
  if (!isNumberArray(positions)) fail('invalid-argument', 'positions must be an array or Float64Array of numbers (x, y, z per vertex)');
  if (positions.length % 3 !== 0) {
    fail('invalid-argument', `positions must hold x, y, z for each vertex; ${positions.length} numbers is not a multiple of 3`);
  }
  return positions instanceof Float64Array ? positions : Float64Array.from(positions);
}

function checkIndex(value, what) {
  if (!Number.isInteger(value)) fail('invalid-argument', `${what} must be a whole number, not ${String(value).slice(0, 40)}`);
  if (value > INT32_MAX || value < -INT32_MAX) fail('index-out-of-range', `${what} = ${value} is far outside the mesh`);
  return value;
}

// faces: number[][] (one array of vertex indices per face) -> CSR typed arrays.
export function facesToCsr(faces) {
  if (!Array.isArray(faces)) fail('invalid-argument', 'faces must be an array with one array of vertex indices per face');
  const faceOffsets = new Int32Array(faces.length + 1);
  let total = 0;
  faces.forEach((face, f) => {
    if (!Array.isArray(face) && !(ArrayBuffer.isView(face) && !(face instanceof DataView))) {
      fail('invalid-argument', `faces[${f}] (${elementLabel('face', f)}) must be an array of vertex indices`);
    }
    total += face.length;
    faceOffsets[f + 1] = total;
  });
  const faceVertices = new Int32Array(total);
  let k = 0;
  faces.forEach((face, f) => {
    for (let i = 0; i < face.length; i += 1) faceVertices[k++] = checkIndex(face[i], `faces[${f}][${i}] (corner ${i + 1} of ${elementLabel('face', f)})`);
  });
  return { faceOffsets, faceVertices };
}

function csrToFaces(faceOffsets, faceVertices) {
  const faces = new Array(faceOffsets.length - 1);
  for (let f = 0; f + 1 < faceOffsets.length; f += 1) faces[f] = Array.from(faceVertices.subarray(faceOffsets[f], faceOffsets[f + 1]));
  return faces;
}

// Accepts {positions, faces} or the bulk form {positions, faceOffsets, faceVertices}.
function indexedInput(input) {
  if (input === null || typeof input !== 'object') fail('invalid-argument', 'expected a mesh object {positions, faces}');
  const positions = checkPositions(input.positions);
  if (input.faces === undefined && input.faceOffsets !== undefined) {
    if (!(input.faceOffsets instanceof Int32Array) || !(input.faceVertices instanceof Int32Array)) {
      fail('invalid-argument', 'faceOffsets and faceVertices must be Int32Arrays');
    }
    return { positions, faceOffsets: input.faceOffsets, faceVertices: input.faceVertices };
  }
  return { positions, ...facesToCsr(input.faces) };
}

// An optional numbering: one entry per element of `kind` (a [start, end] pair per edge for
// the edge list), each named by its array position and the element's label.
function optionalInts(value, what, kind, pairs = false) {
  if (value === undefined || value === null) return new Int32Array(0);
  const flat = pairs && Array.isArray(value) ? value.flatMap((p, i) => {
    if (!Array.isArray(p) || p.length !== 2) fail('invalid-argument', `${what}[${i}] (${elementLabel(kind, i)}) must be a [start, end] pair`);
    return p;
  }) : value;
  if (!isNumberArray(flat)) fail('invalid-argument', `${what} must be an array of whole numbers`);
  const out = new Int32Array(flat.length);
  for (let i = 0; i < flat.length; i += 1) {
    const at = pairs ? `${what}[${i >> 1}][${i & 1}] (${elementLabel(kind, i >> 1)})` : `${what}[${i}] (${elementLabel(kind, i)})`;
    out[i] = checkIndex(flat[i], at);
  }
  return out;
}

// What the core's build reads of a buildMesh input: positions, the CSR face set and the
// optional numbering (edges as [start, end] pairs, vertex and face edges).
function buildArguments(input) {
  const { positions, faceOffsets, faceVertices } = indexedInput(input);
  return [positions, faceOffsets, faceVertices, optionalInts(input.edges, 'edges', 'edge', true),
    optionalInts(input.vertexEdges, 'vertexEdges', 'vertex'), optionalInts(input.faceEdges, 'faceEdges', 'face')];
}

function indexedOutput(r, layout) {
  const out = layout === 'csr'
    ? { positions: r.positions, faceOffsets: r.faceOffsets, faceVertices: r.faceVertices }
    : { positions: r.positions, faces: csrToFaces(r.faceOffsets, r.faceVertices) };
  return out;
}

function deepFreeze(x) {
  if (x !== null && typeof x === 'object') {
    for (const v of Object.values(x)) deepFreeze(v);
    Object.freeze(x);
  }
  return x;
}

function pairs(flat) {
  const out = [];
  for (let i = 0; i + 1 < flat.length; i += 2) out.push([flat[i], flat[i + 1]]);
  return out;
}

const safetyNet = typeof FinalizationRegistry === 'function'
  ? new FinalizationRegistry(({ raw, handle }) => raw.meshDispose(handle))
  : null;

// The six representations of lectures 000/001, in the core's order; the JS keys.
export const REPRESENTATIONS = Object.freeze([
  'independent-faces', 'vertex-face-tables', 'adjacency-lists', 'partial-adjacency-lists', 'edge-list', 'winged-edge',
]);
export const QUERY_KINDS = Object.freeze([
  'faces-around-vertex', 'edges-around-vertex', 'edges-of-face', 'faces-of-edge', 'neighbours-of-face',
]);

function storageValue(s) {
  return {
    entries: s.entries,
    bytes: s.bytes,
    arrays: s.arrays.map((a) => ({ name: a.name, entries: a.entries, bytesPerEntry: a.bytesPerEntry, bytes: a.entries * a.bytesPerEntry })),
  };
}

// A change record as the core sends it, read by the format (meshChangeFormat):
// steps are `stepStride` int32 each [table, row, field, before, after, phase] naming
// descriptor.tables / descriptor.fields; positions `positionStride` numbers each [vertex,
// before xyz, after xyz, step].
function readSteps(flat, { tables, fields, stepStride }) {
  const steps = [];
  for (let k = 0; k + stepStride <= flat.length; k += stepStride) {
    const [t, row, f, before, after, phase] = flat.subarray(k, k + stepStride);
    steps.push({ table: tables[t], row, field: fields[f], before, after, phase });
  }
  return steps;
}

function readChange(r, descriptor) {
  const { positionStride } = descriptor;
  const steps = readSteps(r.steps, descriptor);
  const positions = [];
  for (let k = 0; k + positionStride <= r.positions.length; k += positionStride) {
    const p = r.positions;
    positions.push({ vertex: p[k], before: [p[k + 1], p[k + 2], p[k + 3]], after: [p[k + 4], p[k + 5], p[k + 6]], step: p[k + 7] });
  }
  return {
    op: r.op,
    added: r.added,
    removed: r.removed,
    steps,
    // The algorithm's lines in order (its source comments); steps[i].phase indexes them.
    phases: Array.from(r.phases ?? []),
    rows: r.rows,
    positions,
    ...(r.costs ? { costs: costsOf(r.costs) } : {}),
    before: { ...r.before },
    after: { ...r.after },
  };
}

// {[representation]: {reads, writes}} as plain numbers (edit_costs.h).
function costsOf(c) {
  return Object.fromEntries(Object.entries(c).map(([rep, { reads, writes }]) => [rep, { reads, writes }]));
}

// A live mesh's handle, read through the class's private field (subdivision below, and the
// benchmark's hooks through meshInternals).
let handleOfMesh;

// One walk as the core sends it (edges, a 1/0 flag per step, next) read into one record per
// step: {edge, [key]: which way the rule met the edge, column: the wing it read, next}.
function walkSteps(r, flagOf, key, [yes, no], [yesColumn, noColumn]) {
  const flags = flagOf(r);
  return Array.from(r.edges, (edge, i) => ({ edge, [key]: flags[i] ? yes : no, column: flags[i] ? yesColumn : noColumn, next: r.next[i] }));
}

const ADJACENCY_KINDS = Object.freeze({
  'edges-around-vertex': 'vertex', 'faces-around-vertex': 'vertex', 'vertices-around-vertex': 'vertex',
  'edges-of-face': 'face', 'vertices-of-face': 'face', 'face-neighbours': 'face', 'faces-of-edge': 'edge',
});

function editNamed(edits, name) {
  const edit = edits?.operations.find((o) => o.name === name);
  if (!edit) {
    const names = (edits?.operations ?? []).map((o) => o.name);
    fail('unknown-operation', `unknown mesh operation ${JSON.stringify(String(name)).slice(0, 60)}; use ${names.join(', ')}`);
  }
  return edit;
}

// The entry of an {op, ...} record in the registry `edits` (meshOperations) and its arguments
// in the entry's order: an element index, or a finite number (its default when left out).
// Keys the entry does not take are refused, so a misspelt argument never goes unnoticed.
export function operationValues(edits, operation) {
  if (operation === null || typeof operation !== 'object') fail('invalid-argument', 'an operation is an object such as {op: \'flip-edge\', e: 4}');
  const edit = editNamed(edits, operation.op);
  const names = edit.arguments.map((a) => a.name);
  for (const key of Object.keys(operation)) {
    if (key !== 'op' && !names.includes(key)) fail('invalid-argument', `${edit.name} takes ${names.join(', ')}; ${String(key).slice(0, 20)} is not one of them`);
  }
  const values = edit.arguments.map((a) => {
    const v = operation[a.name] === undefined && a.optional ? a.default : operation[a.name];
    if (v === undefined) fail('invalid-argument', `${edit.name} needs ${a.name}${a.label ? ` (${a.label})` : a.kind ? ` (a ${a.kind})` : ''}`);
    if (a.kind) return elementIndex(v, a.kind);
    if (typeof v !== 'number' || !Number.isFinite(v)) fail('invalid-argument', `${a.name} must be a finite number, not ${String(v).slice(0, 40)}`);
    return v;
  });
  return [edit, values];
}

export class Mesh {
  static {
    handleOfMesh = (mesh) => mesh.#live();
  }

  #raw;
  #handle;
  #id;
  // {topology, geometry}: the core's MeshVersion, mirrored from every call that may change
  // it (this object is the only owner of its handle, so the mirror cannot go stale; the
  // wasm tests compare it with the core's). Every cache below is keyed on it.
  #version = Object.freeze({ topology: 0, geometry: 0 });
  #faces = { topology: -1, count: 0 }; // F, for the topology it was read at

  #descriptors; // every table's descriptor (the core's, read once per API)
  #edits; // the core's registry of operations (read once per API): see apply

  constructor(raw, handle, descriptors = [], edits = null) {
    this.#raw = raw;
    this.#handle = handle;
    this.#id = handle;
    this.#descriptors = descriptors;
    this.#edits = edits;
    safetyNet?.register(this, { raw, handle }, this);
  }

  get disposed() { return this.#handle === 0; }

  // Which mesh this is: unique among the meshes built by one module, never reused. A
  // version is comparable only within one mesh, so a cache key is (id, version).
  get id() { return this.#id; }

  // Which state of this mesh this is: {topology, geometry}. topology moves on by one with
  // every operation that changed the connectivity tables, geometry with every position change.
  get version() { return this.#version; }

  #setVersion(v) {
    if (v.topology !== this.#version.topology || v.geometry !== this.#version.geometry) {
      this.#version = Object.freeze({ topology: v.topology, geometry: v.geometry });
    }
  }

  // The core's own count, for tests of the mirror above.
  coreVersion() {
    const { topology, geometry } = unwrap(this.#raw.meshVersion(this.#live()));
    return { topology, geometry };
  }

  // Frees the mesh in the core. Idempotent; every other call afterwards throws 'disposed'.
  dispose() {
    if (this.#handle === 0) return;
    safetyNet?.unregister(this);
    this.#raw.meshDispose(this.#handle);
    this.#handle = 0;
  }

  #live() {
    if (this.#handle === 0) throw new WingsplineError('disposed', 'this mesh has been disposed; build it again with buildMesh()');
    return this.#handle;
  }

  #adjacency(kind, element, what) {
    elementIndex(element, what);
    return unwrap(this.#raw.meshAdjacency(this.#live(), kind, element)).indices;
  }

  // The lecture's three tables as rows: {vertices: [{x, y, z, edge}], edges: [{start, end,
  // left, right, startLeft, startRight, endLeft, endRight}], faces: [{edge}]}.
  wingedEdge() {
    return Object.fromEntries(Object.entries(this.tables('winged-edge')).map(([name, t]) => [name, t.rows()]));
  }

  // The same tables as flat typed arrays (their descriptors' array names): positions (3
  // per vertex), vertexEdge, edges (8 per edge, in edgeFields order), faceEdge.
  wingedEdgeArrays() {
    const tables = this.tables('winged-edge');
    return { ...tables.vertices.arrays, ...tables.edges.arrays, ...tables.faces.arrays, edgeFields: tables.edges.columns.map((c) => c.name) };
  }

  // The tables of one representation, each read by the generic reader (tables.js):
  // {[tableName]: Table}; rows offset .. offset + limit - 1 of each (default: all rows).
  tables(representation, options = {}) {
    if (!REPRESENTATIONS.includes(representation)) {
      fail('unknown-representation', `unknown representation '${String(representation).slice(0, 40)}'; use ${REPRESENTATIONS.join(', ')}`);
    }
    const { limit = INT32_MAX, offset = 0 } = options ?? {};
    integerIn(limit, 'limit', 0, INT32_MAX);
    integerIn(offset, 'offset', 0, INT32_MAX);
    const r = unwrap(this.#raw.meshTables(this.#live(), representation, offset, limit));
    return Object.fromEntries(r.tables.map((data) => [data.name, readTable(findDescriptor(this.#descriptors, representation, data.name), data)]));
  }

  // One adjacency query by the core's name: 'edges-around-vertex', 'vertices-around-vertex',
  // 'faces-around-vertex' (v); 'edges-of-face', 'vertices-of-face', 'face-neighbours' (f);
  // 'faces-of-edge' (e). The registry names these as an argument's choices.
  adjacency(kind, element) {
    const what = ADJACENCY_KINDS[kind];
    if (!what) fail('unknown-query', `unknown adjacency query ${JSON.stringify(String(kind)).slice(0, 40)}; use ${Object.keys(ADJACENCY_KINDS).join(', ')}`);
    return this.#adjacency(kind, element, what);
  }

  edgesAroundVertex(v) { return this.#adjacency('edges-around-vertex', v, 'vertex'); }
  facesAroundVertex(v) { return this.#adjacency('faces-around-vertex', v, 'vertex'); }
  verticesAroundVertex(v) { return this.#adjacency('vertices-around-vertex', v, 'vertex'); }
  edgesOfFace(f) { return this.#adjacency('edges-of-face', f, 'face'); }
  verticesOfFace(f) { return this.#adjacency('vertices-of-face', f, 'face'); }
  faceNeighbours(f) { return this.#adjacency('face-neighbours', f, 'face'); }
  facesOfEdge(e) {
    const lr = this.#adjacency('faces-of-edge', e, 'edge');
    return { left: lr[0], right: lr[1] };
  }

  // The CCW walk around v as steps: the lecture's rule reads startLeft when v is the
  // edge's Start, endRight when it is its End.
  traversalSteps(v) {
    elementIndex(v, 'vertex');
    return walkSteps(unwrap(this.#raw.meshTraversalSteps(this.#live(), v)), (r) => r.atStart, 'role', ['start', 'end'], ['startLeft', 'endRight']);
  }

  // The walk along face f: if f is the edge's Left face the next edge is endLeft,
  // otherwise (f is its Right face) startRight.
  faceEdgeSteps(f) {
    elementIndex(f, 'face');
    return walkSteps(unwrap(this.#raw.meshFaceEdgeSteps(this.#live(), f)), (r) => r.faceIsLeft, 'side', ['left', 'right'], ['endLeft', 'startRight']);
  }

  // {vertices, edges, faces, boundaryEdges, boundaryLoops, isolatedVertices, euler}
  counts() {
    const { ok, ...c } = unwrap(this.#raw.meshCounts(this.#live()));
    return c;
  }

  // Plane equations per face: [{cross: [A, B, C, D], crossCorners: [P1, P2, P3], newell:
  // [A, B, C, D], residual}]. The cross product uses the face's own first three corners (as
  // given, whatever its stored face edge), named in crossCorners.
  planes() {
    const r = unwrap(this.#raw.meshPlanes(this.#live(), 0, -1));
    return Array.from(r.residual, (residual, f) => ({
      cross: Array.from(r.cross.subarray(4 * f, 4 * f + 4)),
      crossCorners: Array.from(r.crossCorners.subarray(3 * f, 3 * f + 3)),
      newell: Array.from(r.newell.subarray(4 * f, 4 * f + 4)),
      residual,
    }));
  }

  // The same planes as flat typed arrays, nothing converted per face: {cross, newell
  // (Float64Array, 4 per face: A B C D), crossCorners (Int32Array, 3 per face), residual
  // (Float64Array, 1 per face)}; a table reads only the rows it shows.
  // planeArrays({offset, limit}): faces offset .. offset + limit - 1 alone (O(their sides):
  // the planes table asks for the rows it shows), each array's entries for the first face
  // first; with `normals` (Float64Array, 3 per face: Newell's unit normal).
  planeArrays({ offset = 0, limit = -1 } = {}) {
    if (limit !== -1 && !(Number.isInteger(offset) && Number.isInteger(limit) && offset >= 0 && limit >= 0)) {
      fail('invalid-argument', 'planeArrays({offset, limit}) needs whole numbers, offset >= 0 and limit >= 0');
    }
    const { cross, crossCorners, newell, residual, normals } = unwrap(this.#raw.meshPlanes(this.#live(), offset, limit));
    return { cross, crossCorners, newell, residual, normals };
  }

  // Newell unit normals, normals[3*f + k], in a new Float64Array, or copied into `into`
  // (a Float64Array of 3F numbers, returned) so repeated calls allocate nothing.
  normals({ into = null } = {}) {
    if (into !== null && !(into instanceof Float64Array && into.length === 3 * this.#faceCount())) {
      fail('invalid-argument', 'normals({into}) needs a Float64Array with 3 numbers per face');
    }
    return unwrap(this.#raw.meshNormals(this.#live(), into)).normals;
  }

  // The axis-aligned bounding box {min, max, centre} ([x, y, z] each): a 3D view turns
  // about its centre.
  boundingBox() {
    const r = unwrap(this.#raw.meshBoundingBox(this.#live()));
    return { min: Array.from(r.min), max: Array.from(r.max), centre: Array.from(r.centre) };
  }

  // Picking in an orthographic view: the faces seen along `towards` (from the
  // mesh to the viewer) on the line through `point`. {face: the nearest face the line passes
  // through (-1: none), near: [{face, distance}]: faces within `radius` (world units in the
  // view plane) of the line, the hit face first, then faces turned towards the viewer by
  // distance, at most `max`}. Moving, turning or scaling everything together changes nothing.
  pick(point, towards, { radius = 0, max = 16 } = {}) {
    const p = vector3(point, 'point');
    const t = vector3(towards, 'towards');
    integerIn(max, 'max', 0, 1024);
    if (typeof radius !== 'number') fail('invalid-argument', 'radius must be a number >= 0 (world units)');
    // A module that edits meshes carries the big-mesh pick grid (the same answer, a few cells
    // per pick once made for the view); the subdivision lesson's picks by the whole pass.
    const pickIn = this.#raw.meshPickGrid ?? this.#raw.meshPick;
    const r = unwrap(pickIn(this.#live(), p[0], p[1], p[2], t[0], t[1], t[2], radius, max));
    return { face: r.face, near: Array.from(r.near, (face, i) => ({ face, distance: r.distance[i] })) };
  }

  // A lighter picture of the mesh for drawing while the view moves (vertex clustering, about
  // `targetTriangles` triangles; the mesh's own fan triangles when it has no more):
  // {positions: Float64Array (xyz), triangles: Int32Array (3 per triangle), cell (0: itself)}.
  displayProxy(targetTriangles) {
    integerIn(targetTriangles, 'targetTriangles', 1, INT32_MAX);
    return unwrap(this.#raw.meshDisplayProxy(this.#live(), targetTriangles));
  }

  // The unit normal at vertex v, [x, y, z]: the faces around v weighted by their area
  // ([0, 0, 0] for an isolated vertex). Its side tells whether the CCW walk is seen from the front.
  vertexNormal(v) {
    elementIndex(v, 'vertex');
    return Array.from(unwrap(this.#raw.meshVertexNormal(this.#live(), v)).normal);
  }

  #faceCount() {
    if (this.#faces.topology !== this.#version.topology) {
      this.#faces = { topology: this.#version.topology, count: unwrap(this.#raw.meshCounts(this.#live())).faces };
    }
    return this.#faces.count;
  }

  // Moves vertex v in every representation; {changedEntries: {[representation]: xyz copies
  // rewritten}}: independent faces one per face corner at v, every other one exactly 1.
  setVertexPosition(v, position) {
    elementIndex(v, 'vertex');
    if (!isNumberArray(position) || position.length !== 3 || !Array.from(position).every(Number.isFinite)) {
      fail('invalid-argument', 'the position must be three finite numbers [x, y, z]');
    }
    const r = unwrap(this.#raw.meshSetVertexPosition(this.#live(), v, position[0], position[1], position[2]));
    this.#setVersion(r.version);
    return { changedEntries: { ...r.changedEntries } };
  }

  // ---------------------------------------------------------------- changing the mesh
  // Every operation of the core's registry (meshOperations(), docs/api-mesh.md "Changing a
  // mesh"), as the lesson state stores it: {op: 'flip-edge', e: 4}, {op: 'split-face', f, a,
  // b}, {op: 'set-vertex-edge', v, e}, ... check(op) changes nothing and returns {ok: true}
  // or {ok: false, code, message}; apply(op) refuses the same way (throws a WingsplineError
  // with that code, the mesh unchanged) or returns its change record {op, added, removed:
  // {vertices, edges, faces}, steps: [{table, row, field, before, after, phase}] (every
  // assignment in the algorithm's order), phases (its lines), rows: [{table, row, fields:
  // [{field, before, after}]}] (per changed row), positions: [{vertex, before, after,
  // step}], before, after: {topology, geometry}}. New elements take the next numbers;
  // removed ones stay as gaps (gaps()) until compact().
  // With {costs: true} the record also says what the edit cost each representation,
  // costs: {[representation]: {reads, writes}} (edit_costs.h: the entries read to find what
  // to change; the entries written, the winged edge's one per line of the playback). The
  // others are compared whole, O(mesh): ask it for one edit, not for a replayed list.
  // {costs: 'winged-edge'} counts the winged edge alone ({'winged-edge': {reads, writes}}),
  // O(the edit): what a page does on a mesh too big to derive the others after every edit.
  // With {halfEdge: true} it also says what the edit changed in the half-edge view:
  // halfEdge, as lastHalfEdgeChange() gives it (the view is made first if it is not current,
  // O(mesh) once; every later edit updates it, O(the edit)).
  /** @param {any} operation @param {{ costs?: boolean | 'winged-edge', halfEdge?: boolean }} [options] */
  apply(operation, { costs = false, halfEdge = false } = {}) {
    const raw = this.#editing();
    const [edit, values] = this.#operationValues(operation);
    if (costs !== true && costs !== false && costs !== 'winged-edge') fail('invalid-argument', "costs must be true, false or 'winged-edge'");
    if (halfEdge) this.#halfEdgeArrays(0, 0);
    const r = unwrap(raw.meshEdit(this.#live(), edit.name, Float64Array.from(values), false, costs === 'winged-edge' ? 2 : costs ? 1 : 0));
    this.#setVersion(r.after);
    const change = readChange(r, this.#edits);
    return halfEdge ? { ...change, halfEdge: this.lastHalfEdgeChange(change) } : change;
  }

  // check({op: 'flip-edge', e: 4}); the positional form check('flip-edge', 4) takes the
  // arguments in the registry's order (check('split-face', f, a, b)).
  check(operation, ...args) {
    const raw = this.#editing();
    const [edit, values] = this.#operationValues(typeof operation === 'string' ? this.#positional(operation, args) : operation);
    const r = unwrap(raw.meshEdit(this.#live(), edit.name, Float64Array.from(values), true, 0));
    return r.allowed ? { ok: true } : { ok: false, code: r.code, message: r.message };
  }

  // The module's edit bindings: the subdivision lesson's module (wingspline-subdivision)
  // has none, so that its page stays light (docs/architecture.md, "Module size").
  #editing() {
    if (typeof this.#raw.meshEdit !== 'function') {
      fail('part-not-loaded', 'this mesh was built by the subdivision part of the core, which does not edit meshes: '
        + "load the core with the mesh part, loadWingspline({ parts: ['mesh'] }) or loadWingspline(), to edit it");
    }
    return this.#raw;
  }

  #positional(name, args) {
    const edit = editNamed(this.#edits, name);
    return Object.fromEntries([['op', name], ...edit.arguments.map((a, k) => [a.name, args[k]]).filter(([, v]) => v !== undefined)]);
  }

  #operationValues(operation) {
    return operationValues(this.#edits, operation);
  }

  // Named methods for the operations that had them before every operation became a value
  // of the registry: each is apply (or check) with the arguments in the registry's order.
  // Operations added since (split-vertex, ...) are reached through apply({op, ...}) only.
  setVertexEdge(v, e) { return this.apply({ op: 'set-vertex-edge', v, e }); }
  checkSetVertexEdge(v, e) { return this.check({ op: 'set-vertex-edge', v, e }); }
  setFaceEdge(f, e) { return this.apply({ op: 'set-face-edge', f, e }); }
  checkSetFaceEdge(f, e) { return this.check({ op: 'set-face-edge', f, e }); }
  splitEdge(e, t = 0.5) { return this.apply({ op: 'split-edge', e, t }); }
  splitFace(f, a, b) { return this.apply({ op: 'split-face', f, a, b }); }
  joinFaces(e) { return this.apply({ op: 'join-faces', e }); }
  flipEdge(e) { return this.apply({ op: 'flip-edge', e }); }
  collapseEdge(e, t = 0.5) { return this.apply({ op: 'collapse-edge', e, t }); }
  pokeFace(f) { return this.apply({ op: 'poke-face', f }); }

  // Takes back the newest edit apply() made (the core's undo from its change record, O(the
  // edit)): the mesh is the one before it, row for row, gaps included, and its version that
  // mesh's version again. Returns the undo's record, shaped as apply's: op 'undo', rows (each
  // field as the edit left it, before, and as it is again, after), added (the elements live
  // again), removed (the elements the edit added, gone: the tables end where they ended
  // before it, not gaps), positions (the vertices moved back), no steps. Up to the last 1,000
  // edits, newest first; compact() forgets them. Refuses 'cannot-undo' when there is none.
  undo() {
    const r = unwrap(this.#editing().meshUndo(this.#live()));
    this.#setVersion(r.after);
    return readChange(r, this.#edits);
  }

  // Removes the gaps left by join-faces and collapse-edge: every table renumbered keeping
  // the order of what remains. Returns {vertices, edges, faces}: old index -> new (-1 = removed).
  compact() {
    const r = unwrap(this.#editing().meshCompact(this.#live()));
    this.#setVersion(r.version);
    return { vertices: r.renumbering.vertices, edges: r.renumbering.edges, faces: r.renumbering.faces };
  }

  // The mesh as it is now as OFF or OBJ text: a file has no room for gaps, so its vertices
  // and faces are the live ones numbered in order (as compact() would number them).
  format({ format = 'off' } = {}) { return unwrap(this.#raw.meshExport(this.#live(), String(format))).text; }

  // The faces as the winged edge holds them now: {faceOffsets, faceVertices} (Int32Array, CSR),
  // each face from its first corner, a removed face with no corners (a gap keeps its number).
  // The face set the other representations are derived from, without deriving them.
  // faceSet({faces}): the same for the listed face numbers only, in the list's order (a
  // removed face with no corners): what a page reads again for the faces an edit changed.
  /** @param {{ faces?: ArrayLike<number> }} [options] */
  faceSet({ faces } = {}) {
    if (faces === undefined) {
      const r = unwrap(this.#raw.meshFaceSet(this.#live(), null, true));
      return { faceOffsets: r.faceOffsets, faceVertices: r.faceVertices };
    }
    if (!isNumberArray(faces)) fail('invalid-argument', 'faces must be an array of face numbers');
    for (const f of Array.from(faces)) elementIndex(f, 'face');
    const r = unwrap(this.#raw.meshFaceSet(this.#live(), Float64Array.from(faces), false));
    return { faceOffsets: r.faceOffsets, faceVertices: r.faceVertices };
  }

  // The gaps: {vertices, edges, faces}, the removed indices (Int32Array, increasing).
  gaps() { return unwrap(this.#raw.meshGaps(this.#live())); }

  // Storage of each representation, from its real arrays: {[representation]: {entries,
  // bytes, arrays: [{name, entries, bytesPerEntry, bytes}]}}; an entry is one array element
  // (a double coordinate or an int32 index).
  storage() {
    const r = unwrap(this.#raw.meshStorage(this.#live()));
    return Object.fromEntries(REPRESENTATIONS.map((key) => [key, storageValue(r.storage[key])]));
  }

  // Plain-value tables of all six representations: {[key]: {offset, [tableName]: rows
  // (one object per row, keyed by column name), totals: {[tableName]: full row count},
  // storage}}; rows offset .. offset + limit - 1 of every table (docs/api-mesh.md).
  representations(options = {}) {
    const { offset = 0 } = options ?? {};
    const storage = this.storage();
    return Object.fromEntries(REPRESENTATIONS.map((key) => {
      const tables = Object.values(this.tables(key, options));
      const rows = Object.fromEntries(tables.map((t) => [t.name, t.rows()]));
      const totals = Object.fromEntries(tables.map((t) => [t.name, t.total]));
      return [key, { offset, ...rows, totals, storage: storage[key] }];
    }));
  }

  // One adjacency query answered by every representation: {[representation]: {answer:
  // Int32Array, entriesRead}}; entriesRead counts the array entries the algorithm read.
  query(kind, element) {
    if (!QUERY_KINDS.includes(kind)) fail('unknown-query', `unknown query '${String(kind).slice(0, 40)}'; use ${QUERY_KINDS.join(', ')}`);
    elementIndex(element, kind.endsWith('vertex') ? 'vertex' : kind.endsWith('edge') ? 'edge' : 'face');
    const r = unwrap(this.#raw.meshQuery(this.#live(), kind, element));
    return Object.fromEntries(REPRESENTATIONS.map((key) => [key, { answer: r.answers[key].answer, entriesRead: r.answers[key].entriesRead }]));
  }

  // Bytes held by the winged-edge tables (vertex, edge and face tables).
  bytes() { return unwrap(this.#raw.meshBytes(this.#live())).bytes; }

  // {ok, problems: [{code, severity, message, elements: {vertices, edges, faces}}]}
  validate() {
    const r = unwrap(this.#raw.meshValidate(this.#live()));
    return { ok: r.valid, problems: r.problems };
  }

  // ---------------------------------------------------------------- the half-edge view
  // The half-edge structure derived from the winged edge (docs/api-mesh.md, "The half-edge
  // view"): edge e gives half-edge 2e = S -> E (face: e's left) and 2e + 1 = E -> S (face: its
  // right); twin(h) = h ^ 1. The core keeps it per topology version and updates it with every
  // edit and undo, O(the edit); -1 = none (a boundary half-edge's face; every field of a gap).

  // Every row as plain values: {halfedges: [{origin, target, face, next, prev, twin}],
  // vertices: [{halfedge}], faces: [{halfedge}]}.
  halfEdge() {
    const r = this.#halfEdgeArrays(0, -1);
    const halfedges = Array.from(r.origin, (origin, h) => ({
      origin, target: r.origin[h ^ 1], face: r.face[h], next: r.next[h], prev: r.prev[h], twin: h ^ 1,
    }));
    // A gap's twin is a gap too: its row says none everywhere, the twin included.
    for (const row of halfedges) if (row.origin === -1) row.twin = -1;
    return {
      halfedges,
      vertices: Array.from(r.vertexHalfedge, (halfedge) => ({ halfedge })),
      faces: Array.from(r.faceHalfedge, (halfedge) => ({ halfedge })),
    };
  }

  // The same as flat Int32Arrays, rows offset .. offset + limit - 1 of each table (default:
  // every row): {offset, halfedges, vertices, faces (the full row counts), origin, face,
  // next, prev (one entry per half-edge: origin[h - offset] is half-edge h's),
  // vertexHalfedge, faceHalfedge (one per vertex / face of the same window)}. The target is
  // origin[twin]; twin(h) = h ^ 1 is not stored.
  halfEdgeArrays({ offset = 0, limit = -1 } = {}) {
    integerIn(offset, 'offset', 0, INT32_MAX);
    if (limit !== -1) integerIn(limit, 'limit', 0, INT32_MAX);
    return { offset, ...this.#halfEdgeArrays(offset, limit) };
  }

  #halfEdgeArrays(offset, limit) {
    const { ok, ...r } = unwrap(this.#halfEdgeRaw().meshHalfEdge(this.#live(), 'arrays', 0, offset, limit));
    return r;
  }

  // The walk around v in half-edge terms, counter-clockwise: h -> twin(prev(h)), from v's own
  // half-edge (on the boundary its boundary half-edge, so the walk meets the whole fan) or from
  // `start`, a half-edge leaving v. One step per half-edge: {halfedge, column: 'prev', read:
  // prev(halfedge), next: twin of it}. Empty for an isolated vertex.
  halfEdgeTraversalSteps(v, { start = -1 } = {}) {
    elementIndex(v, 'vertex');
    if (start !== -1) integerIn(start, 'start', 0, INT32_MAX);
    return halfEdgeSteps(unwrap(this.#halfEdgeRaw().meshHalfEdge(this.#live(), 'vertex-walk', v, start, 0)), 'prev');
  }

  // The walk along face f: h -> next(h) from the face's half-edge; {halfedge, column: 'next',
  // read: next(halfedge), next} per step.
  halfEdgeFaceSteps(f) {
    elementIndex(f, 'face');
    return halfEdgeSteps(unwrap(this.#halfEdgeRaw().meshHalfEdge(this.#live(), 'face-walk', f, -1, 0)), 'next');
  }

  // One lecture query (QUERY_KINDS) answered on the half-edge arrays: {answer: Int32Array,
  // entriesRead} counted as query() counts each representation's reads (twin and a
  // half-edge's edge are arithmetic, not reads). The vertex queries go CCW from v's half-edge.
  halfEdgeQuery(kind, element) {
    if (!QUERY_KINDS.includes(kind)) fail('unknown-query', `unknown query '${String(kind).slice(0, 40)}'; use ${QUERY_KINDS.join(', ')}`);
    elementIndex(element, kind.endsWith('vertex') ? 'vertex' : kind.endsWith('edge') ? 'edge' : 'face');
    const { answer, entriesRead } = unwrap(this.#halfEdgeRaw().meshHalfEdge(this.#live(), kind, element, 0, 0));
    return { answer, entriesRead };
  }

  // The newest edit or undo in half-edge terms, shaped as its winged-edge steps: {steps:
  // [{table: 'halfedge' | 'vertex' | 'face', row, field: 'origin' | 'face' | 'next' | 'prev'
  // (a half-edge's) | 'halfedge' (a vertex's or face's), before, after, step, phase}], written:
  // {'winged-edge': its pointer assignments, 'half-edge': steps.length}}. Each entry whose value
  // changed, once; -1 for none (a gap's fields, a row before the edit added it). In an order a
  // student can follow: per step of the winged-edge record, the first time it names an edge,
  // vertex or face, that element's rows (an edge's: 2e then 2e + 1); `step` is that step's index
  // in `change.steps` and `phase` its line; then the rows that read a changed neighbour (step
  // -1). Null when the view was not current at the edit (apply's {halfEdge: true} makes it so).
  // `change`: the record it belongs to, for the phases (optional).
  lastHalfEdgeChange(change = null) {
    const r = unwrap(this.#halfEdgeRaw().meshHalfEdge(this.#live(), 'change', 0, 0, 0));
    if (!r.followed) return null;
    const e = r.entries;
    const steps = [];
    for (let k = 0; k + 6 <= e.length; k += 6) {
      const step = e[k + 5];
      steps.push({ table: HALF_EDGE_TABLES[e[k]], row: e[k + 1], field: HALF_EDGE_FIELDS[e[k + 2]], before: e[k + 3], after: e[k + 4],
        step, phase: change?.steps[step]?.phase ?? -1 });
    }
    return { steps, written: { 'winged-edge': r.wingedAssignments, 'half-edge': steps.length } };
  }

  // Its storage as storage() gives each representation's: vertex coordinates, then origin,
  // face, next, prev (one int32 per half-edge each), vertex half-edge, face half-edge.
  halfEdgeStorage() {
    return storageValue(unwrap(this.#halfEdgeRaw().meshHalfEdge(this.#live(), 'storage', 0, 0, 0)));
  }

  // The half-edge bindings are in the modules that edit meshes (the mesh lesson's, and the
  // whole mesh API), which keep the view in step with each edit.
  #halfEdgeRaw() {
    if (typeof this.#raw.meshHalfEdge !== 'function') {
      fail('part-not-loaded', 'the half-edge view is in the mesh part of the core, not the subdivision part: '
        + "load the core with the mesh part, loadWingspline({ parts: ['mesh'] }) or loadWingspline()");
    }
    return this.#raw;
  }
}

// The core's HalfEdgeTable and HalfEdgeField (half_edge.h) by number; 6 int32 per entry.
const HALF_EDGE_TABLES = Object.freeze(['halfedge', 'vertex', 'face']);
const HALF_EDGE_FIELDS = Object.freeze(['origin', 'face', 'next', 'prev', 'halfedge']);

// A half-edge walk as the core sends it (steps: 3 int32 per step, [halfedge, read, next]) as
// one record per step.
function halfEdgeSteps({ steps }, column) {
  return Array.from({ length: steps.length / 3 }, (_, i) => ({ halfedge: steps[3 * i], column, read: steps[3 * i + 1], next: steps[3 * i + 2] }));
}

// For the benchmark's hooks (tests/bench/wasm/bench-core.mjs), which call the bench module's
// own entry points on meshes this API built; wingspline.js does not export it and nothing
// on the api object reaches it.
export const meshInternals = Object.freeze({
  handleOf(mesh) {
    if (!(mesh instanceof Mesh)) fail('invalid-argument', 'expected a mesh built by buildMesh()');
    return handleOfMesh(mesh);
  },
  indexedInput,
});

// Subdivision (docs/api-mesh.md "Subdivision"): the scheme and step count as the
// core takes them; the mesh's handle through the class's private field.
const SUBDIVISION_SCHEMES = Object.freeze(['loop', 'catmull-clark']);
function subdivisionArgs(mesh, options, what) {
  if (!(mesh instanceof Mesh)) fail('invalid-argument', `${what} needs a mesh built by buildMesh()`);
  const o = options ?? {};
  if (!SUBDIVISION_SCHEMES.includes(o.scheme)) {
    fail('unknown-scheme', `${what}: scheme must be 'loop' (triangle meshes) or 'catmull-clark' (any polygons), not ${JSON.stringify(o.scheme)?.slice(0, 40)}`);
  }
  return { handle: handleOfMesh(mesh), scheme: o.scheme };
}

// The grid sizes a cost against mesh size is asked at, as the core takes them: even whole
// numbers of quads across, 2 to 4000.
function costGridSizes(sizes) {
  if (!Array.isArray(sizes) || !sizes.every((n) => Number.isInteger(n) && n >= 2 && n <= 4000 && n % 2 === 0)) {
    fail('invalid-argument', 'sizes must be even whole numbers of quads across, 2 to 4000');
  }
  return Float64Array.from(sizes);
}

// withSubdivision: the module carries mesh subdivision (wingspline-subdivision,
// wingspline-meshes, the bench module); the mesh lesson's module (wingspline-mesh) does not,
// and its API has no subdivide. withEdits: the module edits meshes (all but
// wingspline-subdivision, whose API has no editCostGrowth nor queryCostGrowth and whose meshes refuse apply,
// check and compact with 'part-not-loaded').
export function createMeshApi(raw, { withSubdivision = true, withEdits = true } = {}) {
  const { maxCoordinate, maxFaceCorners, maxVertices, maxFaces } = unwrap(raw.meshLimits());
  const meshLimits = Object.freeze({ maxCoordinate, maxFaceCorners, maxVertices, maxFaces });
  // Every table's descriptor (core/src/mesh/tables.cpp), read once: see tables.js.
  const tableDescriptors = deepFreeze(unwrap(raw.meshTableDescriptors()).tables);
  // The operations' registry (none in a module that does not edit) and the change record's
  // wire form (core/src/mesh/euler_ops.cpp), read once.
  const format = unwrap(raw.meshChangeFormat());
  const meshOperations = deepFreeze({
    operations: withEdits ? unwrap(raw.meshOperationDescriptors()).operations : [],
    tables: format.tables, fields: format.fields, stepStride: format.stepStride, positionStride: format.positionStride,
  });
  function named(name, a = 0, b = 0) {
    return unwrap(raw.meshNamed(name, a, b));
  }
  function slideMesh(name) {
    const r = named(name);
    return {
      positions: r.positions,
      faces: csrToFaces(r.faceOffsets, r.faceVertices),
      edges: pairs(r.edges),
      vertexEdges: Array.from(r.vertexEdges),
      faceEdges: Array.from(r.faceEdges),
    };
  }
  const meshApi = {
    // Builds the winged edge (and the other representations) from an indexed face set.
    // Refuses what a winged edge cannot hold: error.code = the first problem's code,
    // error.details = every problem (as validateMesh reports them).
    buildMesh(input) {
      // The core keeps each face's first corner as given (chosen face edges may start its
      // walk elsewhere), so the other representations are derived from the core alone.
      const r = unwrap(raw.meshBuild(...buildArguments(input)));
      return new Mesh(raw, r.handle, tableDescriptors, meshOperations);
    },
    // The same build in steps: {phase, step(), cancel(), mesh}. step() runs one
    // phase of the core's build (about an eighth of it) and returns true when the mesh is
    // built; `mesh` is then the Mesh (owned by the caller, as buildMesh's). A page builds a
    // million faces this way with a task of its own per phase. A refusal is thrown by the
    // step that finds it, exactly as buildMesh throws it, and ends the build.
    buildMeshInSteps(input) {
      const started = unwrap(raw.meshBuildStart(...buildArguments(input)));
      let phase = started.phase;
      let mesh = null;
      let over = false;
      return {
        get phase() { return phase; },
        get mesh() { return mesh; },
        step() {
          if (mesh) return true;
          if (over) fail('invalid-argument', 'this build is over (refused or cancelled)');
          let r;
          try {
            r = unwrap(raw.meshBuildStep(started.job));
          } catch (err) {
            over = true;
            throw err;
          }
          phase = r.phase;
          if (r.done) mesh = new Mesh(raw, r.handle, tableDescriptors, meshOperations);
          return r.done;
        },
        cancel() {
          if (!mesh && !over) unwrap(raw.meshBuildCancel(started.job));
          over = true;
        },
      };
    },
    // Every problem of an indexed face set, without building: {ok, problems}.
    validateMesh(input) {
      const { positions, faceOffsets, faceVertices } = indexedInput(input);
      const r = unwrap(raw.meshValidateIndexed(positions, faceOffsets, faceVertices));
      return { ok: r.valid, problems: r.problems };
    },
    // The one set of mesh limits (the core's limits.h), for the page and the state format:
    // {maxCoordinate, maxFaceCorners, maxVertices, maxFaces}.
    meshLimits,
    // The descriptors of every representation's tables (frozen): {representation, name,
    // title, rows: 'vertex'|'edge'|'face', arrays, columns}; read a table with tables.js.
    tableDescriptors,
    // The core's registry of operations (frozen): {operations: [{name, title, counts,
    // shortcut, describe, arguments: [{name, kind: 'vertex'|'edge'|'face'|null (a number),
    // optional, default, choices, label}]}], tables, fields, stepStride, positionStride}:
    // what mesh.check(op) and mesh.apply(op) accept, one entry per operation (none in the
    // subdivision part, which does not edit).
    meshOperations,
    // Text -> {positions, faces}. Errors: 'parse-error', 'truncated-file',
    // 'index-out-of-range', 'coordinate-out-of-range', 'face-too-large', 'too-large' (more
    // vertices or faces than meshLimits; checkCounts: false lifts that) with error.line
    // (1-based) and the line in the message. A file over the limits is refused before it
    // is copied into the module's memory.
    /** @param {string} text @param {{ format?: string, layout?: 'faces' | 'csr', checkCounts?: boolean }} [options] */
    parseMesh(text, { format = 'off', layout, checkCounts = true } = {}) {
      if (typeof text !== 'string') fail('invalid-argument', 'parseMesh needs the file contents as a string');
      const r = raw.meshParse(utf8.encode(text), String(format), checkCounts !== false);
      if (!r.ok) {
        // WingsplineError declares no `line`: only parseMesh's errors carry one.
        const err = /** @type {WingsplineError & { line?: number }} */ (new WingsplineError(r.code, r.message));
        if (r.line !== undefined) err.line = r.line;
        throw err;
      }
      return indexedOutput(r, layout);
    },
    // {positions, faces} -> OFF or OBJ text; numbers as %.17g, so reading it back is exact.
    formatMesh(input, { format = 'off' } = {}) {
      const { positions, faceOffsets, faceVertices } = indexedInput(input);
      return unwrap(raw.meshFormat(positions, faceOffsets, faceVertices, String(format))).text;
    },
    // How many built meshes have not been disposed (for leak tests).
    liveMeshCount() {
      return unwrap(raw.meshLiveCount()).count;
    },
    // Lecture 000's mesh with the slide's numbering: {positions, faces, edges, vertexEdges, faceEdges}.
    lectureExample() { return slideMesh('lecture'); },
    // Lecture 001's two polygons with Foley's edge order E1..E5.
    foleyExample() { return slideMesh('foley'); },
    // 'tetrahedron' | 'cube' | 'fan' ({n}) | 'grid' ({nx, ny}) | 'sphere' ({slices, stacks}).
    // {layout: 'csr'} returns {positions, faceOffsets, faceVertices} instead of faces.
    generateMesh(kind, options = {}) {
      if (typeof kind !== 'string') fail('invalid-argument', 'generateMesh needs a kind: tetrahedron, cube, fan, grid or sphere');
      const o = options ?? {};
      const int = (name, dflt) => (o[name] === undefined ? dflt : integerIn(o[name], name, 0, INT32_MAX));
      let r;
      if (kind === 'fan') r = named('fan', int('n', 6));
      else if (kind === 'grid') r = named('grid', int('nx', 4), int('ny', 3));
      else if (kind === 'sphere') r = named('sphere', int('slices', 12), int('stacks', 6));
      else if (kind === 'lecture' || kind === 'foley') fail('unknown-mesh', `use lectureExample() or foleyExample() for '${kind}'`);
      else r = named(kind);
      return indexedOutput(r, o.layout);
    },
  };
  if (withEdits) {
    // What query `kind` (faces-around-vertex, ...) reads from each representation on grids of
    // n x n quads (F = 2 n²), one per n in `sizes` (even, 2..4000), at the grid's middle
    // element: {sizes: [{n, faces}], reads: [{[representation]: entries}]}, measured by the core
    // on small grids and exact at every size (queries.h, query_cost_growth).
    meshApi.queryCostGrowth = (kind, sizes) => {
      const n = costGridSizes(sizes);
      const r = unwrap(raw.meshQueryCostGrowth(String(kind), n));
      return { sizes: r.sizes.map((s) => ({ n: s.n, faces: s.faces })), reads: r.reads.map((x) => ({ ...x })) };
    };
    // What operation `name` costs each representation on grids of n x n quads (F = 2 n²),
    // one per n in `sizes` (even, 2..4000): {sizes: [{n, faces}], costs: [{[representation]:
    // {reads, writes}}]}, measured by the core on small grids and exact at every size
    // (edit_costs.h, edit_cost_growth). Refusals as check gives them (a triangle grid has
    // no face to split: 'adjacent-corners').
    meshApi.editCostGrowth = (name, sizes) => {
      const n = costGridSizes(sizes);
      editNamed(meshOperations, name);
      const r = unwrap(raw.meshEditCostGrowth(String(name), n));
      return { sizes: r.sizes.map((s) => ({ n: s.n, faces: s.faces })), costs: r.costs.map(costsOf) };
    };
  }
  if (!withSubdivision) return meshApi;
  // A new mesh `steps` subdivision steps finer (the input is untouched). Numbering of one
  // step: old vertices keep 0..V-1, edge points V + e, Catmull-Clark face points V + E + f.
  // Errors: 'unknown-scheme', 'not-a-triangle-mesh' (Loop; names the face), 'mesh-has-gaps'
  // (compact first), 'too-large' (above meshLimits; says how many faces), 'invalid-argument'.
  meshApi.subdivide = (mesh, options = {}) => {
    const { handle, scheme } = subdivisionArgs(mesh, options, 'subdivide');
    const steps = options?.steps === undefined ? 1 : integerIn(options.steps, 'steps', 0, 16);
    return new Mesh(raw, unwrap(raw.meshSubdivide(handle, scheme, steps)).handle, tableDescriptors, meshOperations);
  };
  // One step as phases with every new point's mask (old vertices and weights, CSR):
  // {scheme, phases: [{name, first, count}], masks: {offsets, vertices, weights}, rules,
  // ruleNames, valences, positions, faceOffsets, faceVertices, counts}.
  meshApi.subdivisionSteps = (mesh, options = {}) => {
    const { handle, scheme } = subdivisionArgs(mesh, options, 'subdivisionSteps');
    const r = unwrap(raw.meshSubdivisionSteps(handle, scheme));
    return {
      scheme,
      phases: Array.from(r.phases, ({ name, first, count }) => ({ name, first, count })),
      masks: { offsets: r.maskOffsets, vertices: r.maskVertices, weights: r.maskWeights },
      rules: r.rules,
      ruleNames: Array.from(r.ruleNames),
      valences: r.valences,
      positions: r.positions,
      faceOffsets: r.faceOffsets,
      faceVertices: r.faceVertices,
      counts: { vertices: r.positions.length / 3, edges: r.edges, faces: r.faceOffsets.length - 1 },
    };
  };
  // The reconnection phase of one step as pointer assignments, for playback as an edit is
  // played: {lines: [the algorithm's lines], steps: [{table, row, field, before, after,
  // phase}] (phase indexes lines; before is -1: the next level's tables start empty),
  // sources: Int32Array (the old edge or face each step belongs to, -1 for the vertex
  // table)}. Every entry of the next level's tables is written once. Errors as subdivisionSteps.
  meshApi.reconnectionPlayback = (mesh, options = {}) => {
    const { handle, scheme } = subdivisionArgs(mesh, options, 'reconnectionPlayback');
    const r = unwrap(raw.meshReconnectionPlayback(handle, scheme));
    return { lines: Array.from(r.lines), steps: readSteps(r.steps, meshOperations), sources: r.sources };
  };
  // Where each vertex goes in the limit: Float64Array, x, y, z per vertex.
  meshApi.limitPositions = (mesh, options = {}) => {
    const { handle, scheme } = subdivisionArgs(mesh, options, 'limitPositions');
    return unwrap(raw.meshLimitPositions(handle, scheme)).positions;
  };
  return meshApi;
}
