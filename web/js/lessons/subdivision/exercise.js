// @ts-check
// The subdivision lesson's exercises: fill in a table of the mesh at the level
// shown (kind 1), e.g. the face table after one Loop step, or predict a CCW walk on it (kind
// 2). The numbering is the core's subdivision numbering, shown in the drawing (the subject
// carries the edges' too, so a walk's edges are the drawing's); a table's edges are
// numbered freely.
import { numberedMeshOf } from '../../exercise/subjects.js';

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const subdivisionExercise = {
  kinds: ['table', 'walk'],
  subject(view, model) {
    return { mesh: numberedMeshOf(model.mesh) };
  },
  suggest(kind) {
    if (kind === 'walk') {
      return {
        check: { kind: 'walk', around: 'vertex', element: 1 },
        hide: ['tables-panel'],
        question: 'Walk counter-clockwise around v1 of the mesh drawn, starting at the edge its vertex table stores. At each step, which edge comes next?',
      };
    }
    return {
      check: { kind: 'table', table: 'adjacency' },
      hide: ['tables-panel'],
      question: 'Write the adjacency list of every vertex of the mesh drawn: the vertices joined to it by an edge, as the drawing numbers them.',
    };
  },
};
