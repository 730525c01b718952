// @ts-check
// What a lesson hands a check (its `exercise.subject`), built from what it already computed:
//   { mesh }    an indexed face set api.buildMesh takes (and the mesh checkers)
//   { curve }   one curve spec (curves-api.js)     { curves: { family: spec } }
//   { joints }  [{ a, b }] the segments meeting at each joint, in order
//   { patch }   { kind, points } a bicubic patch (surfaces API)
//   { subdivision } { mesh, scheme } the old mesh of the step shown and its scheme (kind subdivide)
// Only data is arranged here; every value is the core's.
import { ExerciseError, MAX_EXERCISE_ELEMENTS } from './format.js';

/** A core mesh as the indexed face set it holds now (positions and faces, CSR). */
export function meshSubjectOf(mesh) {
  const t = mesh.tables('vertex-face-tables');
  return { positions: t.vertices.arrays.positions, faceOffsets: t.faces.arrays.faceOffsets, faceVertices: t.faces.arrays.faceVertices };
}

/** A lesson state's mesh operations refuse mesh exercises: the numbering would not be the drawing's. */
export function refuseEdited(state) {
  const n = state.ops?.length ?? 0;
  if (n) throw new ExerciseError(`the mesh has ${n} edit${n === 1 ? '' : 's'}; a mesh exercise uses a mesh as loaded (undo the edits, or choose the mesh again)`, 'exercise.state.ops');
}

/** A mesh subject small enough to be worked by hand (before anything is built for it). */
export function refuseLargeMesh(mesh) {
  const faces = mesh.faces ? mesh.faces.length : mesh.faceOffsets.length - 1;
  const vertices = mesh.vertexCount ?? Math.floor(mesh.positions.length / 3);
  if (faces > MAX_EXERCISE_ELEMENTS || vertices > MAX_EXERCISE_ELEMENTS) {
    throw new ExerciseError(`its mesh has ${vertices} vertices and ${faces} faces; a mesh exercise has at most ${MAX_EXERCISE_ELEMENTS} of each, to be worked by hand`, 'exercise.state');
  }
  return mesh;
}
