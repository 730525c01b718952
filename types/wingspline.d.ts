// TypeScript declarations of the Wingspline core's public API: what
// `import { loadWingspline, WingsplineError } from 'wingspline'` gives (dist/js/core/wingspline.js,
// mesh-api.js, curves-api.js, errors.js, tables.js). Hand-written, nothing generated at run
// time. Checked by `npm test` (the `types` layer: tsc over examples/ and a file of deliberate
// misuses, tests/package/types/misuse.ts) and against the running module by
// tests/package/declarations.test.mjs (every function and method the API object and a Mesh
// carry is declared here, and nothing declared here is missing from them).
// Conventions (docs/api-mesh.md, docs/api-curves.md): 0-based indices, -1 = none; points are
// flat, points[dim * i + k]; results are plain objects of numbers and typed arrays.

// ------------------------------------------------------------------ common

/** A typed array of numbers (not a DataView). */
export type TypedNumbers = Float64Array | Float32Array | Int32Array | Uint32Array | Int16Array | Uint16Array
  | Int8Array | Uint8Array | Uint8ClampedArray;
/** Numbers as an array or a typed array (copied into the module once). */
export type NumberList = readonly number[] | TypedNumbers;
/** [x, y, z] */
export type Vec3 = readonly [number, number, number] | readonly number[] | Float64Array;

/**
 * The stable error codes (`err.code`): the core's one list (core/include/wingspline/error_codes.h,
 * `api.errorCodes` with each code's meaning; docs/errors.md). A test compares this union with it.
 */
export type WingsplineErrorCode =
  // loading and arguments (every part)
  | 'core-load-failed' | 'part-not-loaded' | 'internal-error' | 'out-of-memory' | 'invalid-argument' | 'disposed'
  // mesh files
  | 'parse-error' | 'truncated-file' | 'line-too-long' | 'unknown-format' | 'index-out-of-range'
  // the mesh limits (meshLimits), wherever a mesh comes from: a file, a face set or an edit
  | 'face-too-large' | 'too-large' | 'coordinate-out-of-range'
  // building a mesh (validateMesh problems; buildMesh throws the first)
  | 'empty-mesh' | 'non-finite-coordinate' | 'too-few-vertices' | 'repeated-vertex' | 'non-manifold-edge'
  | 'inconsistent-orientation' | 'duplicate-face' | 'non-manifold-vertex' | 'isolated-vertex'
  | 'invalid-edge-list' | 'invalid-vertex-edge' | 'invalid-face-edge' | 'edge-not-incident' | 'edge-not-on-face'
  | 'face-first-corner-not-on-face'
  // structure invariants (mesh.validate())
  | 'invalid-reference' | 'edge-without-face' | 'wing-mismatch' | 'face-edge-not-incident'
  | 'vertex-edge-not-incident' | 'open-vertex-ring' | 'open-face-loop' | 'half-edge-broken'
  // queries, tables, representations
  | 'unknown-query' | 'invalid-element' | 'deleted-element' | 'mismatched-face-set' | 'representations-not-built'
  | 'unknown-representation' | 'unknown-table' | 'unknown-column' | 'unknown-mesh' | 'unknown-task'
  // changing a mesh
  | 'unknown-operation' | 'invalid-parameter' | 'same-vertex' | 'not-a-corner' | 'not-a-neighbour' | 'adjacent-corners' | 'edge-exists'
  | 'boundary-edge' | 'same-face' | 'faces-touch-elsewhere' | 'would-duplicate-face' | 'not-triangles'
  | 'would-pinch' | 'hole-too-small' | 'degenerate-vertex' | 'link-condition' | 'link-condition-face' | 'cannot-undo'
  // subdivision
  | 'unknown-scheme' | 'not-a-triangle-mesh' | 'mesh-has-gaps'
  // checking a student's tables (exercise kind 1) and walk steps (kind 2)
  | 'invalid-answer' | 'invalid-faces' | 'invalid-step' | 'no-walk' | 'no-exact-mask'
  // curves
  | 'unknown-curve-kind' | 'unknown-basis' | 'unknown-form' | 'unsupported-curve-kind' | 'invalid-dimension' | 'invalid-points'
  | 'non-finite-input' | 'non-finite-result' | 'too-few-points' | 'degree-out-of-range' | 'wrong-knot-count'
  | 'decreasing-knots' | 'knot-multiplicity-exceeded' | 'empty-domain' | 'wrong-weight-count'
  | 'invalid-weight' | 'weight-ratio-out-of-range' | 'wrong-tangent-count' | 'wrong-node-count'
  | 'nodes-not-increasing' | 'nodes-too-close' | 'nodes-out-of-range' | 'vandermonde-out-of-range'
  | 'parameter-out-of-range' | 'segment-out-of-range' | 'dimension-mismatch' | 'length-overflow'
  | 'not-converged' | 'wrong-point-count' | 'singular-matrix' | 'perspective-behind-eye' | 'overflow'
  // curve exercises (kinds 3-5)
  | 'unknown-quantity' | 'unknown-property' | 'degenerate-curve';

/** Every error the API throws: a stable `code` and a message a student understands. */
export class WingsplineError extends Error {
  constructor(code: WingsplineErrorCode, message: string, details?: readonly MeshProblem[]);
  readonly name: 'WingsplineError';
  code: WingsplineErrorCode;
  /** buildMesh: every problem of the refused face set. */
  details?: readonly MeshProblem[];
  /** parseMesh: the 1-based line of the file the error is on. */
  line?: number;
}

/**
 * The core's modules, one per lesson group: 'mesh' (meshes, tables, walks, edits),
 * 'subdivision' (the same with mesh subdivision and curve sampling), 'curves', 'exercises'
 * (the exercise checkers).
 */
export type CorePart = 'mesh' | 'subdivision' | 'curves' | 'exercises';

/**
 * Loads the wasm modules once each (the `.wasm` next to the glue: a file read in Node, a
 * fetch in a page). Without options every part is loaded and every function below is there;
 * with `parts` only those modules are fetched and the object holds only their functions
 * (a lesson page asks for its own part). Unknown parts: 'invalid-argument'.
 */
export function loadWingspline(options?: { parts?: readonly CorePart[] }): Promise<WingsplineApi>;

/** The check of an operation: allowed, or the refusal it would throw. */
export type CheckResult = { ok: true } | { ok: false; code: WingsplineErrorCode; message: string };

// ------------------------------------------------------------------ meshes in and out

export type ElementKind = 'vertex' | 'edge' | 'face';
export type Representation = 'independent-faces' | 'vertex-face-tables' | 'adjacency-lists'
  | 'partial-adjacency-lists' | 'edge-list' | 'winged-edge';
export type QueryKind = 'faces-around-vertex' | 'edges-around-vertex' | 'edges-of-face' | 'faces-of-edge' | 'neighbours-of-face';
export type MeshFileFormat = 'off' | 'obj';

/** An indexed face set: positions x, y, z per vertex; one list of vertex indices per face. */
export interface IndexedFaceSet {
  positions: NumberList;
  faces: ReadonlyArray<NumberList>;
}
/** The bulk form: faces as CSR (face f's corners are faceVertices[faceOffsets[f] .. faceOffsets[f+1]-1]). */
export interface IndexedFaceSetCsr {
  positions: NumberList;
  faceOffsets: Int32Array;
  faceVertices: Int32Array;
}
export type MeshInput = IndexedFaceSet | IndexedFaceSetCsr;

/** What buildMesh takes: a face set and, optionally, the numbering of a slide. */
export type MeshBuildInput = MeshInput & {
  /** The edge numbering and orientation, [start, end] per edge (or flat pairs). */
  edges?: ReadonlyArray<readonly [number, number]> | Int32Array;
  /** The edge each vertex row stores (incident to the vertex). */
  vertexEdges?: NumberList;
  /** The edge each face row stores (a side of the face). */
  faceEdges?: NumberList;
};

/** A face set as the core returns it. */
export interface FaceSet {
  positions: Float64Array;
  faces: number[][];
}
export interface FaceSetCsr {
  positions: Float64Array;
  faceOffsets: Int32Array;
  faceVertices: Int32Array;
}
/** A lecture's mesh with the slide's numbering, ready for buildMesh. */
export interface SlideMesh extends FaceSet {
  edges: [number, number][];
  vertexEdges: number[];
  faceEdges: number[];
}

export interface ParseMeshOptions {
  format?: MeshFileFormat;
  /** false lifts meshLimits' vertex and face counts. */
  checkCounts?: boolean;
}

export type GeneratedMeshKind = 'tetrahedron' | 'cube' | 'fan' | 'grid' | 'sphere';
export interface GenerateMeshOptions {
  /** fan: triangles around the hub (default 6). */
  n?: number;
  /** grid: cells across and down (default 4 x 3). */
  nx?: number;
  ny?: number;
  /** sphere: default 12 slices, 6 stacks. */
  slices?: number;
  stacks?: number;
}

export interface MeshProblem {
  code: WingsplineErrorCode;
  severity: 'error' | 'warning';
  message: string;
  elements: { vertices: ArrayLike<number>; edges: ArrayLike<number>; faces: ArrayLike<number> };
}
export interface ValidationReport {
  ok: boolean;
  problems: MeshProblem[];
}

export interface MeshLimits {
  readonly maxCoordinate: number;
  readonly maxFaceCorners: number;
  readonly maxVertices: number;
  readonly maxFaces: number;
}

// ------------------------------------------------------------------ tables (tables.js)

export interface TableArrayDescriptor {
  readonly name: string;
  readonly type: 'int32' | 'float64';
  readonly role: string;
  readonly stride: number;
  readonly offsets?: string;
}
export interface TableColumn {
  readonly name: string;
  readonly label: string;
  /** The header above the label ('S', 'E'), or ''. */
  readonly group: string;
  /** The element kind the cells refer to, or null for numbers (positions). */
  readonly refers: ElementKind | null;
  readonly type: 'int32' | 'float64';
  readonly layout: 'fixed' | 'csr';
  readonly array: string;
  readonly offsets?: string;
  readonly stride: number;
  readonly first: number;
  readonly width: number;
}
export interface TableDescriptor {
  readonly representation: Representation;
  readonly name: string;
  readonly title: string;
  /** One row per element of this kind. */
  readonly rows: ElementKind;
  readonly arrays: readonly TableArrayDescriptor[];
  readonly columns: readonly TableColumn[];
}
/** A cell: a number, [x, y, z]-like numbers, or for a list column its items. */
export type TableCell = number | number[] | Array<number | number[]>;
/** One table of a representation, read by the generic reader (rows by index, cells by column name). */
export interface MeshTable {
  readonly descriptor: TableDescriptor;
  readonly representation: Representation;
  readonly name: string;
  readonly title: string;
  readonly kind: ElementKind;
  readonly columns: readonly TableColumn[];
  readonly arrays: Record<string, Int32Array | Float64Array>;
  /** The table's full row count. */
  readonly total: number;
  /** The first row held (the window's start) and how many rows are held. */
  readonly first: number;
  readonly count: number;
  column(name: string): TableColumn;
  cell(row: number, column: string): TableCell;
  row(row: number): Record<string, TableCell>;
  rows(): Array<Record<string, TableCell>>;
}

export interface WingedEdgeTables {
  vertices: Array<{ x: number; y: number; z: number; edge: number }>;
  edges: Array<{
    start: number; end: number; left: number; right: number;
    startLeft: number; startRight: number; endLeft: number; endRight: number;
  }>;
  faces: Array<{ edge: number }>;
}
export interface WingedEdgeArrays {
  positions: Float64Array;
  vertexEdge: Int32Array;
  /** 8 per edge, in edgeFields order. */
  edges: Int32Array;
  faceEdge: Int32Array;
  edgeFields: string[];
}

export interface StorageOfRepresentation {
  entries: number;
  bytes: number;
  arrays: Array<{ name: string; entries: number; bytesPerEntry: number; bytes: number }>;
}

// ------------------------------------------------------------------ changing a mesh

export interface MeshVersion {
  readonly topology: number;
  readonly geometry: number;
}
export interface ElementLists {
  vertices: ArrayLike<number>;
  edges: ArrayLike<number>;
  faces: ArrayLike<number>;
}
export interface ChangedRow {
  table: string;
  row: number;
  fields: Array<{ field: string; before: number; after: number }>;
}
/** What an operation changed: enough to replay it and to undo it (docs/api-mesh.md). */
/** What an edit cost one representation (edit_costs.h): entries read to find what to change, entries written. */
export interface EditCost { reads: number; writes: number }
export interface ChangeRecord {
  op: string;
  added: ElementLists;
  removed: ElementLists;
  rows: ChangedRow[];
  before: MeshVersion;
  after: MeshVersion;
  /** Euler operations: every assignment in the algorithm's order. */
  steps?: Array<{ table: string; row: number; field: string; before: number; after: number; phase: number }>;
  /** Euler operations: the algorithm's lines; steps[i].phase indexes them. */
  phases?: string[];
  positions?: Array<{ vertex: number; before: number[]; after: number[]; step: number }>;
  /** With apply(op, {costs: true}): the entries each representation read to find what to change and the entries it wrote; with {costs: 'winged-edge'}, the winged edge's alone. */
  costs?: Partial<Record<Representation, EditCost>>;
  /** With apply(op, {halfEdge: true}): the same edit in half-edge terms (lastHalfEdgeChange()). */
  halfEdge?: HalfEdgeChange | null;
}
/**
 * One entry of the half-edge tables an edit changed, shaped as a winged-edge step. `step`:
 * the winged-edge step (index into ChangeRecord.steps) that first names its edge, vertex or
 * face, -1 when none does; `phase`: that step's line, -1 without one.
 */
export interface HalfEdgeAssignment {
  table: 'halfedge' | 'vertex' | 'face';
  row: number;
  /** origin, face, next, prev of a half-edge; halfedge of a vertex or face (the twin is h ^ 1, never written). */
  field: 'origin' | 'face' | 'next' | 'prev' | 'halfedge';
  before: number;
  after: number;
  step: number;
  phase: number;
}
/** An edit in half-edge terms: each changed entry once, and the entries each structure wrote. */
export interface HalfEdgeChange {
  steps: HalfEdgeAssignment[];
  /** 'winged-edge': its pointer assignments (an entry written twice counts twice); 'half-edge': steps.length. */
  written: { 'winged-edge': number; 'half-edge': number };
}
/**
 * One operation of the core's registry (api.meshOperations) as a lesson state holds it, its
 * arguments by name. tests/wasm/mesh/edit.test.mjs checks this union against the registry:
 * the same operations, each with the registry's arguments (optional where it has a default).
 */
export type MeshOperation =
  | { op: 'split-edge'; e: number; t?: number }
  | { op: 'flip-edge'; e: number }
  | { op: 'collapse-edge'; e: number; t?: number }
  | { op: 'join-faces'; e: number }
  | { op: 'split-face'; f: number; a: number; b: number }
  | { op: 'poke-face'; f: number }
  | { op: 'split-vertex'; v: number; a: number; b: number; t?: number }
  | { op: 'set-vertex-edge'; v: number; e: number }
  | { op: 'set-face-edge'; f: number; e: number };
export type MeshOperationName = MeshOperation['op'];
/** The operations that change the counts (every one but the stored-edge choices). */
export type EulerOperationName = Exclude<MeshOperationName, 'set-vertex-edge' | 'set-face-edge'>;

export type AdjacencyKind = 'edges-around-vertex' | 'faces-around-vertex' | 'vertices-around-vertex' | 'edges-of-face' | 'vertices-of-face'
  | 'face-neighbours' | 'faces-of-edge';

export interface MeshOperationsDescriptor {
  readonly operations: ReadonlyArray<{
    readonly name: MeshOperationName;
    /** "Split edge" */
    readonly title: string;
    /** What it does to V, E, F: "V+1, E+1". */
    readonly counts: string;
    /** The key the edit panel binds to it; "" for the stored-edge choices (made in the tables). */
    readonly shortcut: string;
    /** One line with {argument} placeholders: "split {e} at t = {t}". */
    readonly describe: string;
    /** What it must find before it writes, {name} as in describe: "the sides of {f}" (edit_costs.h). */
    readonly finds: string;
    readonly arguments: ReadonlyArray<{
      readonly name: string; readonly kind: ElementKind | null; readonly optional: boolean; readonly default: number;
      /** For an element after the first: the adjacency query of the first that lists its candidates. */
      readonly choices: AdjacencyKind | null;
      readonly label: string;
    }>;
  }>;
  readonly tables: readonly string[];
  readonly fields: readonly string[];
  readonly stepStride: number;
  readonly positionStride: number;
}

export interface TraversalStep {
  edge: number;
  /** Whether the vertex is the edge's Start or End. */
  role: 'start' | 'end';
  /** The wing read: startLeft at the Start, endRight at the End. */
  column: 'startLeft' | 'endRight';
  next: number;
}
export interface FaceEdgeStep {
  edge: number;
  side: 'left' | 'right';
  column: 'endLeft' | 'startRight';
  next: number;
}
/**
 * The half-edge view (docs/api-mesh.md, "The half-edge view"): edge e gives half-edge 2e = S -> E
 * (face: e's left) and 2e + 1 = E -> S (face: e's right); twin(h) = h ^ 1. -1 = none: a
 * boundary half-edge's face, every field of a gap left by an edit.
 */
export interface HalfEdgeRow {
  origin: number;
  /** origin of the twin (not stored). */
  target: number;
  face: number;
  next: number;
  prev: number;
  twin: number;
}
export interface HalfEdgeTables {
  halfedges: HalfEdgeRow[];
  /** One outgoing half-edge per vertex; on the boundary the boundary one (its face is -1). */
  vertices: Array<{ halfedge: number }>;
  faces: Array<{ halfedge: number }>;
}
/** The half-edge tables as flat arrays: rows offset .. offset + limit - 1 of each table. */
export interface HalfEdgeArrays {
  offset: number;
  /** Full row counts. */
  halfedges: number;
  vertices: number;
  faces: number;
  /** origin[h - offset] is half-edge h's; one entry per half-edge of the window. */
  origin: Int32Array;
  face: Int32Array;
  next: Int32Array;
  prev: Int32Array;
  vertexHalfedge: Int32Array;
  faceHalfedge: Int32Array;
}
/** One step of a half-edge walk: the field read at `halfedge`, its value, and where the walk goes. */
export interface HalfEdgeStep {
  halfedge: number;
  /** prev around a vertex (next = twin(read)), next along a face (next = read). */
  column: 'prev' | 'next';
  read: number;
  next: number;
}
export interface MeshCounts {
  vertices: number;
  edges: number;
  faces: number;
  boundaryEdges: number;
  boundaryLoops: number;
  isolatedVertices: number;
  euler: number;
}
export interface FacePlane {
  /** [A, B, C, D] from the cross product of crossCorners. */
  cross: number[];
  crossCorners: number[];
  /** [A, B, C, D] by Newell's method. */
  newell: number[];
  residual: number;
}

/** A built mesh; it lives in the core until dispose(). */
export interface Mesh {
  readonly disposed: boolean;
  readonly id: number;
  readonly version: MeshVersion;
  coreVersion(): MeshVersion;
  /** Frees the mesh in the core (idempotent); every other call afterwards throws 'disposed'. */
  dispose(): void;
  wingedEdge(): WingedEdgeTables;
  wingedEdgeArrays(): WingedEdgeArrays;
  /** The faces as the winged edge holds them now (CSR), each from its first corner; a removed face has no corners. `faces`: only those face numbers, in the list's order. */
  faceSet(options?: { faces?: ArrayLike<number> }): { faceOffsets: Int32Array; faceVertices: Int32Array };
  tables(representation: Representation, options?: { limit?: number; offset?: number }): Record<string, MeshTable>;
  edgesAroundVertex(v: number): Int32Array;
  facesAroundVertex(v: number): Int32Array;
  verticesAroundVertex(v: number): Int32Array;
  edgesOfFace(f: number): Int32Array;
  verticesOfFace(f: number): Int32Array;
  faceNeighbours(f: number): Int32Array;
  facesOfEdge(e: number): { left: number; right: number };
  /** The CCW walk around vertex v (lecture 000). */
  traversalSteps(v: number): TraversalStep[];
  /** The walk along face f. */
  faceEdgeSteps(f: number): FaceEdgeStep[];
  counts(): MeshCounts;
  planes(): FacePlane[];
  /** The planes as flat arrays; with {offset, limit} of those faces alone (O(their sides)). */
  planeArrays(options?: { offset?: number; limit?: number }): { cross: Float64Array; crossCorners: Int32Array; newell: Float64Array; residual: Float64Array; normals: Float64Array };
  /** Newell unit normals, 3 per face; `into` (3F numbers) is filled and returned. */
  normals(options?: { into?: Float64Array | null }): Float64Array;
  boundingBox(): { min: number[]; max: number[]; centre: number[] };
  pick(point: Vec3, towards: Vec3, options?: { radius?: number; max?: number }): { face: number; near: Array<{ face: number; distance: number }> };
  displayProxy(targetTriangles: number): { positions: Float64Array; triangles: Int32Array; cell: number };
  vertexNormal(v: number): number[];
  setVertexPosition(v: number, position: Vec3): { changedEntries: Record<Representation, number> };
  checkSetVertexEdge(v: number, e: number): CheckResult;
  setVertexEdge(v: number, e: number): ChangeRecord;
  checkSetFaceEdge(f: number, e: number): CheckResult;
  setFaceEdge(f: number, e: number): ChangeRecord;
  apply(operation: MeshOperation, options?: { costs?: boolean | 'winged-edge'; halfEdge?: boolean }): ChangeRecord;
  splitEdge(e: number, t?: number): ChangeRecord;
  splitFace(f: number, a: number, b: number): ChangeRecord;
  joinFaces(e: number): ChangeRecord;
  flipEdge(e: number): ChangeRecord;
  collapseEdge(e: number, t?: number): ChangeRecord;
  pokeFace(f: number): ChangeRecord;
  /**
   * Whether an operation may run, changing nothing: check({op: 'flip-edge', e: 4}). The
   * positional form check('flip-edge', 4) takes the arguments in the registry's order.
   */
  check(operation: MeshOperation): CheckResult;
  check(op: MeshOperationName, ...args: number[]): CheckResult;
  /** One adjacency query by the core's name (the registry's `choices`). */
  adjacency(kind: AdjacencyKind, element: number): Int32Array;
  /**
   * Takes back the newest edit apply() made (up to the last 1,000; compact() forgets them):
   * the mesh before it, row for row, and its version again. The record's op is 'undo'; its
   * `added` are the elements live again, its `removed` the edit's new elements, gone (not
   * gaps). Throws 'cannot-undo' when there is none.
   */
  undo(): ChangeRecord;
  /** Removes the gaps; old index -> new (-1 = removed). */
  compact(): { vertices: ArrayLike<number>; edges: ArrayLike<number>; faces: ArrayLike<number> };
  format(options?: { format?: MeshFileFormat }): string;
  gaps(): ElementLists;
  storage(): Record<Representation, StorageOfRepresentation>;
  representations(options?: { limit?: number; offset?: number }): Record<Representation, Record<string, unknown> & {
    offset: number; totals: Record<string, number>; storage: StorageOfRepresentation;
  }>;
  query(kind: QueryKind, element: number): Record<Representation, { answer: Int32Array; entriesRead: number }>;
  bytes(): number;
  validate(): ValidationReport;
  /** The half-edge view as rows (-1 = none). */
  halfEdge(): HalfEdgeTables;
  /** The half-edge view as Int32Arrays, a window of rows of each table (default: all). */
  halfEdgeArrays(options?: { offset?: number; limit?: number }): HalfEdgeArrays;
  /** Around v counter-clockwise, h -> twin(prev(h)), from v's half-edge or `start` (a half-edge leaving v). */
  halfEdgeTraversalSteps(v: number, options?: { start?: number }): HalfEdgeStep[];
  /** Along face f, h -> next(h), from the face's half-edge. */
  halfEdgeFaceSteps(f: number): HalfEdgeStep[];
  /** A lecture query on the half-edge arrays, with the entries read. */
  halfEdgeQuery(kind: QueryKind, element: number): { answer: Int32Array; entriesRead: number };
  halfEdgeStorage(): StorageOfRepresentation;
  /** The newest edit or undo in half-edge terms; null when the view was not current then. */
  lastHalfEdgeChange(change?: ChangeRecord | null): HalfEdgeChange | null;
}

export interface MeshBuildJob {
  /** The build's current phase, e.g. 'counting sides'; 'done' at the end. */
  readonly phase: string;
  /** The built mesh once step() has returned true (owned by the caller). */
  readonly mesh: Mesh | null;
  /** Runs one phase; true when the mesh is built. Throws buildMesh's refusal. */
  step(): boolean;
  cancel(): void;
}

export type SubdivisionScheme = 'loop' | 'catmull-clark';
export interface SubdivisionOptions {
  scheme: SubdivisionScheme;
}
/** The reconnection phase of one step as pointer assignments (docs/api-mesh.md, "Subdivision"). */
export interface ReconnectionPlayback {
  /** The algorithm's lines in order; steps[i].phase indexes them. */
  lines: string[];
  /** Every entry of the next level's tables, written once; before is -1 (the tables start empty). */
  steps: Array<{ table: 'vertex' | 'edge' | 'face'; row: number; field: string; before: number; after: number; phase: number }>;
  /** The old edge or face each step belongs to; -1 for the vertex table's steps. */
  sources: Int32Array;
}

export interface SubdivisionSteps {
  scheme: SubdivisionScheme;
  phases: Array<{ name: string; first: number; count: number }>;
  masks: { offsets: Int32Array; vertices: Int32Array; weights: Float64Array };
  rules: Int32Array;
  ruleNames: string[];
  valences: Int32Array;
  positions: Float64Array;
  faceOffsets: Int32Array;
  faceVertices: Int32Array;
  counts: { vertices: number; edges: number; faces: number };
}

// ------------------------------------------------------------------ curves

export type CurveKind = 'bezier' | 'bspline' | 'nurbs' | 'hermite' | 'catmull-rom' | 'cardinal' | 'interpolation';
export type CubicBasis = 'hermite' | 'bezier' | 'bspline' | 'catmull-rom';
export type Dimension = 2 | 3;

interface CurveBase {
  dim: Dimension;
  /** Control points, points[dim * i + k]. */
  points: NumberList;
}
export interface BezierCurve extends CurveBase {
  kind: 'bezier';
  /** A rational Bezier curve: one positive weight per point. */
  weights?: NumberList | null;
}
export interface BSplineCurve extends CurveBase {
  kind: 'bspline';
  /** Default 3. */
  degree?: number;
  /** K + p + 1 non-decreasing values; default uniform. */
  knots?: NumberList | null;
}
export interface NurbsCurve extends CurveBase {
  kind: 'nurbs';
  degree?: number;
  knots?: NumberList | null;
  weights: NumberList;
}
export interface HermiteCurve extends CurveBase {
  kind: 'hermite';
  /** One tangent per point, the same layout as the points. */
  tangents: NumberList;
}
export interface CatmullRomCurve extends CurveBase {
  kind: 'catmull-rom';
}
export interface CardinalCurve extends CurveBase {
  kind: 'cardinal';
  tension?: number;
}
export interface InterpolationCurve extends CurveBase {
  kind: 'interpolation';
  /** Increasing parameters, one per point; default 0, 1, 2, ... */
  nodes?: NumberList | null;
}
/** A curve is a plain object; `kind` says which family. */
export type Curve = BezierCurve | BSplineCurve | NurbsCurve | HermiteCurve | CatmullRomCurve | CardinalCurve | InterpolationCurve;
/** The curves the B-spline algorithms take (deBoor, insertKnot, ...): bezier with its implicit knots, bspline, nurbs. */
export type KnotCurve = BezierCurve | BSplineCurve | NurbsCurve;
/** A curve as the core returns one (arrays as Float64Array). */
export type ComputedNurbs = NurbsCurve & { points: Float64Array; degree: number; knots: Float64Array; weights: Float64Array };

export interface EvaluateOptions {
  /** A Float64Array of the result's length to fill instead of allocating one. */
  out?: Float64Array;
}
/** A matrix as a slide writes it: (1 / denominator) . numerators (row-major integers). */
export interface RationalMatrix {
  denominator: number;
  numerators: Float64Array;
}
/** An exact matrix: entry i is num[i] / den[i], row-major. */
export interface ExactMatrix {
  rows: number;
  cols: number;
  num: Float64Array;
  den: Float64Array;
}
/** How a lecture writes P(u) = ... : descending powers (000, 003), ascending (002: C = M g), transposed (001: Q(t) = G M T). */
export type MatrixForm = 'descending' | 'ascending' | 'transposed';
/** M, G and C of a segment as the chosen lecture writes them. */
export interface SegmentForm {
  form: MatrixForm;
  M: Float64Array;
  G: Float64Array;
  C: Float64Array;
  size: number;
  geometryRows: number;
  geometryColumns: number;
  rational: RationalMatrix | null;
}
export interface SegmentMatrices {
  segment: number;
  segmentCount: number;
  degree: number;
  basis: string;
  /** Row-major (degree+1)^2: P(u) = [u^p .. u 1] M G. */
  M: Float64Array;
  MT: Float64Array;
  rational: RationalMatrix | null;
  G: Float64Array;
  /** C = M G. */
  C: Float64Array;
  columns: number;
  rows: number;
  controlIndices: Int32Array;
  labels: string[];
  start: number;
  end: number;
  localParameter: boolean;
  homogeneous: boolean;
  /** M, G, C in the form asked for (options.form). */
  shown: SegmentForm;
  convention: string;
}
export interface CurveDomain {
  start: number;
  end: number;
  degree: number;
  controlPointCount: number;
  segmentCount: number;
}
export interface JointContinuity {
  /** k of C^k (-1..2); -1: the curves do not meet. */
  parametric: number;
  /** k of G^k (-1..2). */
  geometric: number;
  evidence: {
    tolerance: number;
    a: Float64Array;
    b: Float64Array;
    positionGap: number;
    size: number;
    relativeGap: number;
    d1Gap: number;
    d2Gap: number;
    ratio: number;
    tangentAngle: number;
    curvatureA: number | null;
    curvatureB: number | null;
    curvatureVectorGap: number;
    zeroTangent: boolean;
    zeroTangentA: boolean;
    zeroTangentB: boolean;
    notes: string[];
  };
  wordings: Array<{ id: string; source: string; wording: string; geometric: number; reason: string }>;
}
export interface Guarantees {
  parametric: number;
  geometric: number;
  joints: number;
  interpolated: number[];
}
export type ConstraintMode = 'free' | 'C0' | 'G1' | 'C1' | 'C2';
export interface PlaneMap {
  kind: 'affine' | 'perspective';
  /** Degrees. */
  angle?: number;
  scale?: number;
  shear?: number;
  tx?: number;
  ty?: number;
  px?: number;
  py?: number;
}
export interface PatchInput {
  kind: 'hermite' | 'bezier';
  /** The 4x4 geometry matrix of 3D vectors, points[3 * (4 i + j) + k]. */
  points: NumberList;
}

// ------------------------------------------------------------------ exercises

/** The mesh of a winged-edge exercise: its faces (vertex and face numbers fixed) and vertex count (or positions). */
export type ExerciseMesh = ({ faces: ReadonlyArray<NumberList> } | { faceOffsets: Int32Array; faceVertices: Int32Array })
  & ({ vertexCount: number } | { positions: NumberList });
/**
 * A student's winged-edge table, cells 0-based; an edge is the student's row number.
 * -1 = none (a boundary side), -2 = blank (answerCells).
 */
export interface WingedEdgeAnswer {
  /** 8 per row: edges[8*r + k], k: S E L R S:L S:R E:L E:R. */
  edges: NumberList;
  /** One edge per vertex (the vertex table). */
  vertexEdges: NumberList;
  /** One edge per face (the face table). */
  faceEdges: NumberList;
}
export type WingedEdgeField = 'start' | 'end' | 'left' | 'right' | 'startLeft' | 'startRight' | 'endLeft' | 'endRight' | 'edge' | '';
export type WingedEdgeFindingCode = 'blank' | 'unknown-label' | 'not-an-edge' | 'duplicate-edge' | 'missing-edge'
  | 'swapped-ends' | 'wrong-face' | 'wrong-wing' | 'not-incident' | 'not-on-face';
/** One thing wrong in the answer: the row (the student's; -1 for a missing edge), the column, the value given and the right one. */
export interface WingedEdgeFinding {
  table: ElementKind;
  row: number;
  field: WingedEdgeField;
  given: number;
  expected: number;
  code: WingedEdgeFindingCode;
  /** Names the row and column and says why, from the definition (lecture 000), with the values (the worked answer's words). */
  reason: string;
  /** Value-free (feedback levels check and hint): where, as the question's grid counts (row e3, column S:L), and the rule to re-read; never the right value. */
  message: string;
  /** A value-free nudge, shown at feedback level hint after the author's number of tries. */
  hint: string;
}
export interface WingedEdgeCheck {
  correct: boolean;
  findings: WingedEdgeFinding[];
  /** Per student row: the mesh edge (core numbering) it was matched to, -1 none. */
  rowEdges: Int32Array;
  /** Per student row: true where it runs the mesh edge from End to Start. */
  rowReversed: boolean[];
}
export interface WorkedWingedEdgeAnswer {
  edges: Int32Array;
  vertexEdges: Int32Array;
  faceEdges: Int32Array;
}

/** The masks of one subdivision step, as the core names them. */
export type SubdivideMask = 'face-point' | 'edge-interior' | 'edge-boundary' | 'vertex-interior' | 'vertex-boundary';
/** A new point of one step: the vertex (edge, face) point of old element `element` (0-based). */
export interface SubdividePoint { type: 'vertex' | 'edge' | 'face'; element: number }
/** A stencil: weights[i] (exact, lowest terms, den > 0) of old vertex vertices[i]; they sum to 1. */
export interface SubdivideStencil {
  rule: SubdivideMask;
  vertices: Int32Array;
  weights: Array<{ num: number; den: number }>;
  /** why vertices[i] is in it: "an end of e3" */
  roles: string[];
}
/** One thing wrong: code no-mask | wrong-mask | not-a-vertex | repeated-point | not-in-stencil | wrong-weight | missing-point | wrong-count; row (0-based, -1 none), vertex (-1 none), count (0 V, 1 E, 2 F; -1 none). */
export interface SubdivideFinding { code: string; row: number; vertex: number; count: number; text: string; hint: string }
export interface SubdivideCheck { correct: boolean; findings: SubdivideFinding[] }

/** The tables checkMeshTableAnswer checks (exercise kind 1). */
export type MeshExerciseTable = 'winged-edge' | 'faces' | 'edge-list' | 'adjacency' | 'half-edge';
/** Lecture 000's face table: per face (the mesh's numbering) its corners, counter-clockwise, any first. -2 = blank. */
export interface FacesAnswer { faces: ReadonlyArray<NumberList> }
/** Lecture 001's edge list: 4 per row (V1 V2 P1 P2; -1 = λ, -2 = blank) and per polygon the student's edge (row) numbers. */
export interface EdgeListAnswer { edges: NumberList; polygons: ReadonlyArray<NumberList> }
/** Lecture 000's adjacency lists, per vertex its neighbours (any order). */
export interface AdjacencyAnswer { vertexVertices: ReadonlyArray<NumberList> }
/** The half-edge table: 5 per row (origin face next prev twin; rows are the student's half-edges, any numbering), per vertex and per face one row (0-based; -1 = none, -2 = blank). */
export interface HalfEdgeAnswer { halfedges: NumberList; vertexHalfedges: NumberList; faceHalfedges: NumberList }
export interface MeshTableAnswers {
  'winged-edge': WingedEdgeAnswer;
  faces: FacesAnswer;
  'edge-list': EdgeListAnswer;
  adjacency: AdjacencyAnswer;
  'half-edge': HalfEdgeAnswer;
}
/** The right answer in the answer's own shape (plain arrays), in the student's numbering where rows match. */
export interface MeshTableWorked {
  'winged-edge': { edges: number[]; vertexEdges: number[]; faceEdges: number[] };
  faces: { faces: number[][] };
  'edge-list': { edges: number[]; polygons: number[][] };
  adjacency: { vertexVertices: number[][] };
  'half-edge': { halfedges: number[]; vertexHalfedges: number[]; faceHalfedges: number[] };
}
export type MeshTableFindingCode = WingedEdgeFindingCode | 'clockwise' | 'wrong-vertex' | 'wrong-order' | 'missing-vertex'
  | 'extra-vertex' | 'not-adjacent' | 'wrong-origin' | 'wrong-next' | 'wrong-prev' | 'wrong-twin' | 'not-outgoing' | 'not-boundary';
/** One thing wrong: as WingedEdgeFinding, plus index, the position in a list column (-1: a fixed column, or an item missing). */
export interface MeshTableFinding {
  /** The kind of row; 'halfedge' for a row of the half-edge table. */
  table: ElementKind | 'halfedge';
  row: number;
  /** The column as the table descriptors name it: 'vertices' (faces, adjacency), 'v1' | 'v2' | 'p1' | 'p2' | 'edges' (edge list), a winged-edge field, or 'origin' | 'face' | 'next' | 'prev' | 'twin' | 'halfedge' (half-edge table). */
  field: string;
  index: number;
  given: number;
  expected: number;
  code: MeshTableFindingCode;
  reason: string;
  /** Value-free (feedback levels check and hint): where, as the question's grid counts (row e3, column S:L), and the rule to re-read; never the right value. */
  message: string;
  /** A value-free nudge, shown at feedback level hint after the author's number of tries. */
  hint: string;
}
export interface MeshTableCheck<T extends MeshExerciseTable> {
  correct: boolean;
  findings: MeshTableFinding[];
  worked: MeshTableWorked[T];
}
/** The mesh of a walk exercise: an ExerciseMesh, optionally with a slide's numbering (as lectureExample() returns it). */
export type WalkExerciseMesh = ExerciseMesh & { edges?: ReadonlyArray<readonly [number, number]>; vertexEdges?: NumberList; faceEdges?: NumberList };
/** Step k (from 1) of the CCW walk around a vertex (along a face): the student's edge for the walk's edge k. */
export interface WalkStepQuestion {
  around: 'vertex' | 'face';
  element: number;
  step: number;
  given: number;
  /** 'half-edge': the half-edge walk (around v h -> twin(prev(h)), along f h -> next(h)); given and expected are half-edges. Default 'winged-edge'. */
  structure?: 'winged-edge' | 'half-edge';
}
/** The edit exercise: one table of the answer, the listed rows then the new rows (docs/exercises.md, kind edit). */
export interface EditTableAnswer {
  /** 8 per edge row (S E L R S:L S:R E:L E:R), 1 per vertex or face row (its edge); 0-based, -1 = none, -2 = blank. */
  cells: NumberList;
  /** One per row: the row is marked removed. */
  removed: ReadonlyArray<boolean | number>;
  /** The new rows' labels, the student's choice (0-based; -2 = not given). */
  labels: NumberList;
}
export interface EditAnswer { vertices: EditTableAnswer; edges: EditTableAnswer; faces: EditTableAnswer }
export interface EditQuestion {
  /** Per table, the existing rows the operation rewrites or removes (0-based, ascending). */
  rows: { vertices: number[]; edges: number[]; faces: number[] };
  /** Per table, how many new rows the operation adds. */
  added: { vertices: number; edges: number; faces: number };
  /** The operation as the edit panel writes it: 'flip e3'. */
  operation: string;
}
export type EditFindingCode = 'blank' | 'unknown-label' | 'removed-element' | 'wrong-vertex' | 'wrong-face' | 'wrong-wing'
  | 'not-incident' | 'not-on-face' | 'removed' | 'kept' | 'new-removed' | 'blank-label' | 'used-label' | 'duplicate-label';
/** As MeshTableFinding: index is the row's position in its table of the answer; field 'removed' or 'label' for those marks. */
export interface EditFinding extends Omit<MeshTableFinding, 'code'> { code: EditFindingCode }
/** The half-edge edit exercise's answer: cells 4 per half-edge row (origin, face, next, prev), 1 per vertex or face row (its half-edge); labels empty. */
export interface HalfEdgeEditAnswer { vertices: EditTableAnswer; halfedges: EditTableAnswer; faces: EditTableAnswer }
export interface HalfEdgeEditQuestion {
  /** Per table, the rows of the half-edge view the operation changes, existing then new (0-based, ascending). */
  rows: { vertices: number[]; halfedges: number[]; faces: number[] };
  /** Per table, the row count before the operation: a row at or past it is new, numbered as the core numbers it. */
  beforeCount: { vertices: number; halfedges: number; faces: number };
  operation: string;
}
export type HalfEdgeEditFindingCode = 'blank' | 'wrong-origin' | 'wrong-face' | 'wrong-next' | 'wrong-prev' | 'not-leaving' | 'not-on-face' | 'removed' | 'kept';
export interface HalfEdgeEditCheck {
  correct: boolean;
  /** table 'edge' for a half-edge row; field 'origin', 'face', 'next', 'prev', 'halfedge' or 'removed'. */
  findings: Array<Omit<MeshTableFinding, 'code'> & { code: HalfEdgeEditFindingCode }>;
  /** The right answer: the view's own values after the operation. */
  worked: { vertices: { cells: number[]; removed: boolean[]; labels: number[] }; halfedges: { cells: number[]; removed: boolean[]; labels: number[] }; faces: { cells: number[]; removed: boolean[]; labels: number[] } };
}
export interface EditCheck {
  correct: boolean;
  findings: EditFinding[];
  /** The right answer in the student's labels. */
  worked: { vertices: { cells: number[]; removed: boolean[]; labels: number[] }; edges: { cells: number[]; removed: boolean[]; labels: number[] }; faces: { cells: number[]; removed: boolean[]; labels: number[] } };
}
export interface WalkStepCheck {
  correct: boolean;
  /** The edge (half-edge) the step starts from: the walk's element k - 1, shown to the student. */
  from: number;
  /** The edge the lecture's rule reads (0-based). */
  expected: number;
  /** expected is the walk's first edge again: the walk is closed. */
  done: boolean;
  /** The rule applied to this step, e.g. "e5: v2 is the Start of e6, so the CCW walk around v2 reads its S:L column, e5". */
  reason: string;
  /** Value-free, '' for a right step: the step, the edge it starts from and the rule; never the expected edge. */
  message: string;
  /** Value-free nudge: which column of the current edge the rule reads. */
  hint: string;
}

/** The object loadWingspline() resolves to. */
export interface WingsplineApi {
  readonly version: string;
  memoryUsage(): { linearBytes: number; heapInUse: number };
  /** Every error code the API can give, with where it comes from and what it means. */
  readonly errorCodes: ReadonlyArray<{ readonly code: WingsplineErrorCode; readonly group: string; readonly meaning: string }>;

  // ---- meshes (docs/api-mesh.md)
  buildMesh(input: MeshBuildInput): Mesh;
  buildMeshInSteps(input: MeshBuildInput): MeshBuildJob;
  validateMesh(input: MeshInput): ValidationReport;
  readonly meshLimits: MeshLimits;
  readonly tableDescriptors: readonly TableDescriptor[];
  readonly meshOperations: MeshOperationsDescriptor;
  /** Query `kind` at the middle element of grids of n x n quads (F = 2 n²), one per even n of `sizes` (2..4000): the entries each representation reads, and the half-edge view's (`'half-edge'`). */
  queryCostGrowth(kind: QueryKind, sizes: number[]): { sizes: Array<{ n: number; faces: number }>; reads: Array<Record<Representation | 'half-edge', number>> };
  /** Operation `name` on grids of n x n quads (F = 2 n²), one per even n of `sizes`: what it costs each representation. */
  editCostGrowth(name: MeshOperation['op'], sizes: number[]): { sizes: Array<{ n: number; faces: number }>; costs: Array<Record<Representation, EditCost>> };
  parseMesh(text: string, options: ParseMeshOptions & { layout: 'csr' }): FaceSetCsr;
  parseMesh(text: string, options?: ParseMeshOptions & { layout?: 'faces' }): FaceSet;
  formatMesh(input: MeshInput, options?: { format?: MeshFileFormat }): string;
  liveMeshCount(): number;
  /** Lecture 000's mesh with the slide's numbering. */
  lectureExample(): SlideMesh;
  /** Lecture 001's two polygons with Foley's edge order. */
  foleyExample(): SlideMesh;
  generateMesh(kind: GeneratedMeshKind, options: GenerateMeshOptions & { layout: 'csr' }): FaceSetCsr;
  generateMesh(kind: GeneratedMeshKind, options?: GenerateMeshOptions & { layout?: 'faces' }): FaceSet;
  subdivide(mesh: Mesh, options: SubdivisionOptions & { steps?: number }): Mesh;
  subdivisionSteps(mesh: Mesh, options: SubdivisionOptions): SubdivisionSteps;
  reconnectionPlayback(mesh: Mesh, options: SubdivisionOptions): ReconnectionPlayback;
  limitPositions(mesh: Mesh, options: SubdivisionOptions): Float64Array;

  // ---- exercises (docs/api-mesh.md, "Checking a student's winged-edge table")
  readonly answerCells: { readonly none: -1; readonly blank: -2 };
  /** Checks a student's winged-edge table: any consistent edge numbering, either orientation per edge. */
  checkWingedEdgeAnswer(mesh: ExerciseMesh, answer: WingedEdgeAnswer): WingedEdgeCheck;
  /** The right table in the student's numbering where rows match, blanks filled. */
  workedWingedEdgeAnswer(mesh: ExerciseMesh, answer: WingedEdgeAnswer): WorkedWingedEdgeAnswer;
  /** Checks a student's table of kind 1 (any correct answer is accepted; docs/api-mesh.md). */
  checkMeshTableAnswer<T extends MeshExerciseTable>(mesh: ExerciseMesh, table: T, answer: MeshTableAnswers[T]): MeshTableCheck<T>;
  /** Checks one predicted step of the CCW walk (exercise kind 2). */
  checkWalkStep(mesh: WalkExerciseMesh, question: WalkStepQuestion): WalkStepCheck;
  /** The masks a subdivide exercise chooses among (the core's rule names). */
  readonly subdivideMasks: readonly SubdivideMask[];
  /** The exact stencil of one new point of a step (docs/api-mesh.md, "Checking a subdivision step by hand"). */
  subdivideStencil(mesh: ExerciseMesh, question: { scheme: SubdivisionScheme; point: SubdividePoint }): SubdivideStencil;
  /** Checks a student's mask and weights exactly; no finding holds the right value. */
  checkSubdivideMask(mesh: ExerciseMesh, answer: { scheme: SubdivisionScheme; point: SubdividePoint; mask: SubdivideMask | null; rows: ReadonlyArray<{ vertex: number; num: number; den: number }> }): SubdivideCheck;
  /** Checks V, E, F typed for the mesh after `steps` (1..4) steps; null = left blank. */
  checkSubdivideCounts(mesh: ExerciseMesh, answer: { scheme: SubdivisionScheme; steps?: number; vertices: number | null; edges: number | null; faces: number | null }): SubdivideCheck;
  /** V, E, F after `steps` (0..16) steps of the exercise's mesh. */
  subdivisionCounts(mesh: ExerciseMesh, options: { scheme: SubdivisionScheme; steps?: number }): { vertices: number; edges: number; faces: number };
  /** The edit exercise's question: the rows `operation` rewrites on the mesh after `edits` (docs/exercises.md). */
  editQuestion(mesh: WalkExerciseMesh, edits: ReadonlyArray<MeshOperation>, operation: MeshOperation): EditQuestion;
  /** Checks an edit exercise's answer against the operation's change record (new elements under any labels). */
  checkEditAnswer(mesh: WalkExerciseMesh, edits: ReadonlyArray<MeshOperation>, operation: MeshOperation, answer: EditAnswer): EditCheck;
  /** The same edit in half-edge terms: the rows of the half-edge view it changes (docs/exercises.md). */
  halfEdgeEditQuestion(mesh: WalkExerciseMesh, edits: ReadonlyArray<MeshOperation>, operation: MeshOperation): HalfEdgeEditQuestion;
  /** Checks a half-edge edit answer against the view after the operation. */
  checkHalfEdgeEditAnswer(mesh: WalkExerciseMesh, edits: ReadonlyArray<MeshOperation>, operation: MeshOperation, answer: HalfEdgeEditAnswer): HalfEdgeEditCheck;

  // ---- curves (docs/api-curves.md)
  /** form: 'descending' (lectures 000, 003; the default), 'ascending' (002) or 'transposed' (001). */
  basisMatrix(kind: CubicBasis, form?: MatrixForm): Float64Array;
  basisMatrixRational(kind: CubicBasis, form?: MatrixForm): RationalMatrix;
  hermiteFromConstraints(): { constraints: Float64Array; matrix: Float64Array };
  evaluateCurve(curve: Curve, params: NumberList, options?: EvaluateOptions): Float64Array;
  evaluateDerivative(curve: Curve, params: NumberList, order?: number, options?: EvaluateOptions): Float64Array;
  evaluateWithDerivatives(curve: Curve, params: NumberList, maxOrder?: number, options?: EvaluateOptions): Float64Array;
  curveDomain(curve: Curve): CurveDomain;
  sampleCurve(curve: Curve, n?: number): { params: Float64Array; points: Float64Array };
  blendingFunctions(curve: Curve, params: NumberList, order?: number): { count: number; values: Float64Array };
  segmentMatrices(curve: Curve, segmentIndex?: number, options?: { form?: MatrixForm }): SegmentMatrices;
  deCasteljau(points: NumberList, dim: Dimension, t: number, weights?: NumberList | null): {
    degree: number; levels: Float64Array[]; point: Float64Array; levelWeights?: Float64Array[];
  };
  subdivideBezier(points: NumberList, dim: Dimension, t?: number, weights?: NumberList | null): {
    left: Float64Array; right: Float64Array; leftWeights?: Float64Array; rightWeights?: Float64Array;
  };
  bezierSubdivisionMatrices(degree?: number, t?: number): {
    left: Float64Array; right: Float64Array; size: number; leftRational: RationalMatrix | null; rightRational: RationalMatrix | null;
  };
  elevateDegree(points: NumberList, dim: Dimension, weights?: NumberList | null): { points: Float64Array; weights?: Float64Array };
  convertBasis(points: NumberList, dim: Dimension, fromKind: CubicBasis, toKind: CubicBasis): Float64Array;
  deBoor(curve: KnotCurve, u: number): {
    span: number; degree: number; firstIndex: number; levels: Float64Array[]; alphas: Float64Array[];
    point: Float64Array; levelWeights?: Float64Array[];
  };
  /** Boehm's insertion of one knot: the same curve with one more point and knot. */
  insertKnot(curve: KnotCurve, u: number): {
    curve: BSplineCurve | NurbsCurve; span: number; insertedIndex: number;
    recomputed: Int32Array; alphas: Float64Array; newPoints: Int32Array;
  };
  bsplineToBezier(curve: KnotCurve): Array<{ points: Float64Array; weights?: Float64Array; start: number; end: number }>;
  knotMultiplicities(curve: KnotCurve): {
    knots: Float64Array; values: Float64Array; multiplicities: Int32Array; firstIndices: Int32Array;
    interior: Int32Array; continuity: Int32Array;
  };
  segmentAt(curve: Curve, u: number): number;
  clampedKnots(count: number, degree: number): Float64Array;
  uniformKnots(count: number, degree: number): Float64Array;
  unclampedKnots(knots: NumberList, degree: number): Float64Array;
  isClampedKnots(knots: NumberList, degree: number): boolean;
  /** True when the B-spline on these knots is exactly the Bezier curve of its points (lecture 002). */
  isBezierInDisguise(knots: NumberList, degree: number): boolean;
  dragWithConstraint(points: NumberList, dim: Dimension, family: CubicBasis, mode: ConstraintMode, index: number, to: NumberList): Float64Array;
  enforceConstraint(points: NumberList, dim: Dimension, family: CubicBasis, mode: ConstraintMode): Float64Array;
  appendSegment(points: NumberList, dim: Dimension, family: CubicBasis, mode: ConstraintMode): Float64Array;
  nurbsCircle(options?: { center?: NumberList; radius?: number; dim?: Dimension }): ComputedNurbs;
  nurbsArc(options?: { center?: NumberList; radius?: number; startAngle?: number; endAngle?: number; dim?: Dimension }): ComputedNurbs;
  nurbsEllipse(options?: { center?: NumberList; rx?: number; ry?: number; dim?: Dimension }): ComputedNurbs;
  nurbsConic(options: { p0: NumberList; p1: NumberList; p2: NumberList; weight?: number; dim?: Dimension }): {
    curve: ComputedNurbs; conicType: 'ellipse' | 'parabola' | 'hyperbola';
  };
  curvature(curve: Curve, params: NumberList): {
    curvature: Float64Array; signedCurvature: Float64Array; speed: Float64Array; tangent: Float64Array; singular: Uint8Array;
  };
  arcLength(curve: Curve, a?: number, b?: number): number;
  arcLengthParams(curve: Curve, n?: number): { params: Float64Array; lengths: Float64Array; total: number };
  jointContinuity(a: Curve, b: Curve, options?: { tolerance?: number }): JointContinuity;
  cubicDerivation(family: CubicBasis): {
    family: string; size: number; constraint: ExactMatrix; inverse: ExactMatrix; basis: ExactMatrix;
    rhs: ExactMatrix | null; substitution: ExactMatrix | null; conditions: string[];
  };
  interpolatePolynomial(points: NumberList, dim: Dimension, nodes?: NumberList | null): {
    curve: InterpolationCurve & { nodes: Float64Array }; nodes: Float64Array; vandermonde: Float64Array;
    inverse: Float64Array; coefficients: Float64Array;
  };
  curveLimits(): { maxInterpolationPoints: number; maxDegree: number };
  chainGuarantees(options: { basis: CubicBasis; slots: number; maps: ReadonlyArray<NumberList>; isPoint: readonly boolean[] }): Guarantees;
  bsplineGuarantees(options: { knots: NumberList; degree?: number; count: number }): Guarantees;
  samplePatch(options: PatchInput & { nu?: number; nv?: number }): {
    nu: number; nv: number; positions: Float64Array; normals: Float64Array; du: Float64Array; dv: Float64Array; twists: Float64Array;
  };
  convexHull(points: NumberList): { indices: Int32Array; tolerance: number };
  mapPoints(points: NumberList, dim: Dimension, transform: PlaneMap, options?: { what?: string }): { points: Float64Array; w: Float64Array };
  maxDistance(a: NumberList, b: NumberList, dim: 1 | 2 | 3): { distance: number; index: number };
  blendingWeightCheck(segments: readonly Curve[], samples?: number): {
    tangentWeight: number; weightsPoints: boolean; minWeight: number; minWeightAt: number; sumError: number;
    convexHull: boolean; tolerance: number;
  };
  pointCurveDistances(points: NumberList, dim: Dimension, segments: readonly Curve[], samples?: number): {
    distances: Float64Array; interpolated: Int32Array; farthest: number; nearestMissed: number; tolerance: number;
  };
  splitCheck(segments: readonly Curve[]): { error: number; segments: number };
  knotRefinementCheck(curve: KnotCurve, samples?: number): { error: number; inserted: number; pointsBefore: number; pointsAfter: number };
  catmullRomTangents(points: NumberList, dim: Dimension): Float64Array;
  convertPatchBasis(points: NumberList, fromKind: 'hermite' | 'bezier', toKind: 'hermite' | 'bezier'): Float64Array;
  curvatureComb(curve: Curve, params: NumberList): { teeth: Float64Array; maxCurvature: number; singular: number };
  homogeneousLift(points: NumberList, dim: Dimension, weights: NumberList): Float64Array;
  patchCornerCheck(options: PatchInput): { corners: Array<{ entry: number; distance: number; interpolated: boolean }>; tolerance: number };
  patchJoinCheck(options: { kind: 'hermite' | 'bezier'; a: NumberList; b: NumberList; samples?: number }): {
    positionGap: number; duGap: number; c0: boolean; c1: boolean; tolerance: number;
  };
  transformPoints(points: NumberList, dim: Dimension, matrix: NumberList): Float64Array;
  subdivideCurve(points: NumberList, dim: Dimension, options: { scheme: 'chaikin' | 'cubic-bspline'; closed?: boolean; steps?: number }): Float64Array;

  // ---- curve exercises (docs/api-curves.md, "Exercises: joints, values, properties")
  /** Kind 3: the statements about the joint a student ticks as true, in a fixed order. */
  jointReasons(): JointReason[];
  /** The classes a student picks from (k = -1..2; k = 2 reads "C² (or smoother)"). */
  jointClasses(): { parametric: JointClass[]; geometric: JointClass[] };
  /** A field left out of the answer is not checked. tolerance: relative, as jointContinuity (default 1e-9). */
  checkJointAnswer(a: Curve, b: Curve, answer?: JointAnswer, options?: { tolerance?: number }): JointAnswerCheck;
  /** Kind 4: the value asked, its label and the worked lines. */
  workedValue(subject: ValueSubject, ask: ValueAsk): WorkedValue;
  /** tolerance: absolute, in the units of the value; given: 1 number for a scalar, dim for a point. */
  checkValueAnswer(subject: ValueSubject, ask: ValueAsk, given: NumberList | number, tolerance: number): ValueAnswerCheck;
  /** Kind 5: does the property hold now, and what to change. */
  checkCurveProperty(subject: { a: Curve; b: Curve }, property: JointClassProperty): JointClassPropertyCheck;
  checkCurveProperty(subject: { curve: Curve }, property: PassesThroughProperty): PassesThroughPropertyCheck;
}

// ------------------------------------------------------------------ curve exercises (kinds 3-5)

export type JointReasonId = 'meet' | 'equal-first' | 'same-direction' | 'equal-second' | 'equal-curvature';
export type JointClassK = -1 | 0 | 1 | 2;
export interface JointReason {
  id: JointReasonId;
  /** In the lectures' notation: P is the first segment at its end, Q the second at its start. */
  statement: string;
}
export interface JointClass {
  k: JointClassK;
  label: string;
  /** The statements that must all hold for this class. */
  requires: JointReasonId[];
}
export interface JointAnswer {
  parametric?: number;
  geometric?: number;
  /** The statements ticked as true. */
  why?: readonly string[];
}
export type JointAnswerFinding =
  | { field: 'parametric' | 'geometric'; given: number; expected: number; reason: string; message: string; hint: string }
  | { field: JointReasonId; given: boolean; expected: boolean; reason: string; message: string; hint: string };
export interface JointAnswerCheck {
  correct: boolean;
  findings: JointAnswerFinding[];
  worked: { parametric: JointClassK; geometric: JointClassK; why: JointReasonId[]; explanation: string[] };
}
export type ValueSubject = { curve: Curve } | { patch: PatchInput };
export type ValueAsk =
  | { quantity: 'blend'; i: number; u: number }
  | { quantity: 'point'; u: number }
  | { quantity: 'mg'; segment: number; row: number; col: number }
  | { quantity: 'boehm'; u: number; index: number }
  | { quantity: 'patch-point'; u: number; v: number };
export interface WorkedValue {
  expected: number[];
  /** What is asked in the lecture's notation, e.g. "B₁,₃(0.5)". */
  label: string;
  working: string[];
}
export interface ValueAnswerCheck extends WorkedValue {
  correct: boolean;
  /** Euclidean distance of the answer from the expected value. */
  distance: number;
  /** Why the answer is wrong, with the value; '' when it is right. */
  reason: string;
  /** '' when right; 'not-within' the tolerance; 'wrong-count': not as many numbers as the value has (distance Infinity). */
  code: '' | 'not-within' | 'wrong-count';
  /** Value-free: what was asked in the question's terms (first row, first column; u) and the formula; a plain sentence for a wrong count. */
  message: string;
  /** Value-free nudge. */
  hint: string;
}
export interface JointClassProperty {
  kind: 'joint-class';
  parametric?: number;
  geometric?: number;
  /** Relative, as jointContinuity (default 1e-9). */
  tolerance?: number;
}
export interface PassesThroughProperty {
  kind: 'passes-through';
  point: NumberList;
  /** Relative to the control polygon's diameter (the largest distance between two control points). */
  tolerance: number;
}
export interface JointClassPropertyCheck {
  holds: boolean;
  reason: string;
  measured: { parametric: JointClassK; geometric: JointClassK; why: JointReasonId[] };
}
export interface PassesThroughPropertyCheck {
  holds: boolean;
  reason: string;
  measured: { distance: number; relativeDistance: number; size: number; u: number; closest: number[] };
}
