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
    // The drawing labels vertices, not edges: the walk is read off the winged-edge table
    // (the tables panel stays), by the lecture's rule, as on the slide "Find CCW edges".
    if (kind === 'walk') {
      return {
        check: { kind: 'walk', around: 'vertex', element: 1 },
        hide: [],
        question: 'Walk counter-clockwise around v1 of the mesh drawn, using its winged-edge tables (the panel "Winged-edge tables of the mesh shown"): start at the edge the vertex table stores for v1; from each edge, read S:L if v1 is its Start, E:R if it is its End. At each step, which edge comes next?',
      };
    }
    return {
      check: { kind: 'table', table: 'adjacency' },
      hide: ['tables-panel'],
      question: 'Write the adjacency list of every vertex of the mesh drawn: the vertices joined to it by an edge, as the drawing numbers them.',
    };
  },
};
