// @ts-check
// The subdivision lesson's exercises: fill in a table of the mesh at the level
// shown (kind 1), e.g. the face table after one Loop step. The numbering of vertices and
// faces is the core's subdivision numbering, shown in the drawing; edges are numbered freely.
import { meshSubjectOf } from '../../exercise/subjects.js';

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const subdivisionExercise = {
  kinds: ['table'],
  usesModel: true,
  subject(view, model) {
    return { mesh: meshSubjectOf(model.mesh) };
  },
  suggest() {
    return {
      check: { kind: 'table', table: 'adjacency' },
      hide: ['tables-panel'],
      question: 'Write the adjacency list of every vertex of the mesh drawn: the vertices joined to it by an edge, as the drawing numbers them.',
    };
  },
};
