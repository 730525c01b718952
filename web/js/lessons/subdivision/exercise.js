// @ts-check
// The subdivision lesson's exercises: fill in a table of the mesh at the level
// shown (kind 1), e.g. the face table after one Loop step; predict a CCW walk on it (kind
// 2); one step by hand (kind subdivide): the mask and exact weights of a new point, or the
// counts V, E, F after a step. The numbering is the core's subdivision numbering, shown in the
// drawing (the subject carries the edges' too, so a walk's edges are the drawing's); a
// table's edges are numbered freely, the subdivide kind marks the edge it asks about.
import { numberedMeshOf, meshSubjectOf } from '../../exercise/subjects.js';
import { drawAskedPoint } from './draw.js';

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const subdivisionExercise = {
  kinds: ['table', 'walk', 'subdivide'],
  usesModel: true,
  // mesh: the mesh shown (the table and walk kinds); subdivision: the old mesh of the step
  // shown (the level's own mesh, even once the step is reconnected) and its scheme (the
  // subdivide kind).
  subject(view, model) {
    return { mesh: numberedMeshOf(model.mesh), subdivision: { mesh: meshSubjectOf(model.levelMesh), scheme: model.scheme } };
  },
  // The drawing marks the new point asked about where the old mesh is drawn (its vertex, the
  // edge's middle, the face's middle), without its position or its mask.
  markSubdividePoint(ctx, painter, colors, asked) {
    if (ctx.model) drawAskedPoint(painter, ctx.model, colors, asked);
  },
  suggest(kind, state, asked) {
    if (kind === 'subdivide') return suggestSubdivide(state, asked);
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

const SCHEME_NAMES = { loop: 'Loop', 'catmull-clark': 'Catmull-Clark' };

// The new point whose mask the drawing shows (as the lesson's compute picks it: the point
// chosen, state.focus, if its phase is shown, else the first point of the newest phase
// shown), numbered as the core numbers one step's result (vertex points 0..V-1, edge points
// V + e, face points V + E + f); the counts when no new point is shown.
function suggestSubdivide(state, { api, subject }) {
  const { mesh, scheme } = subject.subdivision;
  const name = SCHEME_NAMES[scheme];
  const hide = ['step-panel', 'tables-panel'];
  const old = api.subdivisionCounts(mesh, { scheme, steps: 0 });
  // The phases in the core's order (face points, edge points, vertex points): first point, count.
  const phases = [[old.vertices + old.edges, scheme === 'loop' ? 0 : old.faces], [old.vertices, old.edges], [0, old.vertices]];
  const shown = phases.slice(0, state.phase).filter(([, count]) => count > 0);
  const chosen = shown.some(([first, count]) => state.focus >= first && state.focus < first + count);
  const f = chosen ? state.focus : shown.length ? shown[shown.length - 1][0] : -1;
  if (f >= 0) {
    const point = f < old.vertices ? { type: 'vertex', element: f + 1 }
      : f < old.vertices + old.edges ? { type: 'edge', element: f - old.vertices + 1 }
        : { type: 'face', element: f - old.vertices - old.edges + 1 };
    const label = `${{ vertex: 'v', edge: 'e', face: 'F' }[point.type]}${point.element}`;
    return {
      check: { kind: 'subdivide', scheme, ask: 'mask', point },
      hide,
      question: `One ${name} step makes a new ${point.type} point from ${label} (marked in the drawing). Which mask makes it, and what is it as exact fractions of the old points? Name each old point as the drawing labels it.`,
    };
  }
  return {
    check: { kind: 'subdivide', scheme, ask: 'counts' },
    hide,
    question: `How many vertices, edges and faces does the mesh drawn have after one ${name} step?`,
  };
}
