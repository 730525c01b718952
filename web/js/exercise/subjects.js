// @ts-check
// What a lesson hands a check (its `exercise.subject`), built from what it already computed:
//   { mesh }    an indexed face set api.buildMesh takes (and the mesh checkers)
//   { curve }   one curve spec (curves-api.js)     { curves: { family: spec } }
//   { joints }  [{ a, b }] the segments meeting at each joint, in order
//   { patch }   { kind, points } a bicubic patch (surfaces API)
//   { subdivision } { mesh, scheme } the old mesh of the step shown and its scheme (kind subdivide)
//   { mesh, loaded, edits }  the mesh lesson: `mesh` the mesh as drawn after the edits (its
//               numbering included), `loaded` the mesh as loaded and `edits` the lesson
//               state's operations, which the edit kind's check replays in the core
//   { code }    the code lesson: { task, sources } the task shown and the student's code per
//               task (kind code runs the task's code, the starter where there is none)
// Only data is arranged here; every value is the core's.
import { ExerciseError, MAX_EXERCISE_ELEMENTS } from './format.js';

/** A core mesh as the indexed face set it holds now (positions and faces, CSR). */
export function meshSubjectOf(mesh) {
  const t = mesh.tables('vertex-face-tables');
  return { positions: t.vertices.arrays.positions, faceOffsets: t.faces.arrays.faceOffsets, faceVertices: t.faces.arrays.faceVertices };
}

/**
 * A core mesh as a check rebuilds it: its face set with the winged edge's own numbering (each
 * edge's [S, E], the vertex and face tables), so that a check's mesh is numbered as the
 * drawing is (an edited mesh, a subdivided one). A mesh with gaps (elements an edit removed)
 * has no such face set: `gaps` counts them, and refuseLargeMesh refuses it with a sentence.
 */
export function numberedMeshOf(mesh) {
  const g = mesh.gaps();
  const gaps = g.vertices.length + g.edges.length + g.faces.length;
  const t = mesh.wingedEdgeArrays();
  const s = t.edgeFields.indexOf('start');
  const e = t.edgeFields.indexOf('end');
  const stride = t.edgeFields.length;
  const edges = Array.from({ length: t.edges.length / stride }, (_, i) => [t.edges[stride * i + s], t.edges[stride * i + e]]);
  return { ...meshSubjectOf(mesh), edges, vertexEdges: Array.from(t.vertexEdge), faceEdges: Array.from(t.faceEdge), gaps };
}

/**
 * The mesh lesson's subject: the mesh as loaded and the state's edits, with the mesh as drawn
 * after them (built and replayed in the core, so the numbering is the drawing's). A mesh too
 * large to be worked by hand is left as loaded (the kinds refuse it with its figures).
 */
export function editedMeshSubject(api, loaded, ops) {
  const edits = ops ?? [];
  if (!edits.some((op) => op.op !== 'move-vertex') || tooLarge(loaded)) return { mesh: loaded, loaded, edits };
  return { mesh: replayEdits(api, loaded, edits, numberedMeshOf), loaded, edits };
}

/**
 * Builds `loaded` in the core, replays the lesson state's edits on it as the lesson does (a
 * moved vertex changes no table; Compact renumbers), and returns read(mesh) before the mesh
 * is disposed.
 * @template T @param {any} api @param {any} loaded @param {any[]} edits @param {(mesh: any) => T} read @returns {T}
 */
export function replayEdits(api, loaded, edits, read) {
  const built = api.buildMesh(loaded);
  try {
    for (const op of edits) {
      if (op.op === 'compact') built.compact();
      else if (op.op !== 'move-vertex') built.apply(op);
    }
    return read(built);
  } finally {
    built.dispose();
  }
}

const tooLarge = (mesh) => (mesh.faces ? mesh.faces.length : mesh.faceOffsets.length - 1) > MAX_EXERCISE_ELEMENTS
  || (mesh.vertexCount ?? Math.floor(mesh.positions.length / 3)) > MAX_EXERCISE_ELEMENTS;

/**
 * A mesh subject that can be worked by hand (before anything is built for it): small enough,
 * and numbered without gaps. After an edit removed elements the drawing's numbers have gaps
 * (e4 gone, e5 kept), which no table from the faces can show: the lesson's Compact renumbers
 * them first (docs/exercises.md, "An exercise from any view").
 */
export function refuseLargeMesh(mesh) {
  if (mesh.gaps) {
    throw new ExerciseError(`the edits removed elements and left ${mesh.gaps} gap${mesh.gaps === 1 ? '' : 's'} in the numbering; use Compact in the edit panel first (it renumbers the tables as the drawing will show them), or ask an edit exercise`, 'exercise.state.ops');
  }
  const faces = mesh.faces ? mesh.faces.length : mesh.faceOffsets.length - 1;
  const vertices = mesh.vertexCount ?? Math.floor(mesh.positions.length / 3);
  if (faces > MAX_EXERCISE_ELEMENTS || vertices > MAX_EXERCISE_ELEMENTS) {
    throw new ExerciseError(`its mesh has ${vertices} vertices and ${faces} faces; a mesh exercise has at most ${MAX_EXERCISE_ELEMENTS} of each, to be worked by hand`, 'exercise.state');
  }
  return mesh;
}
