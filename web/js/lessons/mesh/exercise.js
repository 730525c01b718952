// @ts-check
// The mesh lesson's exercises (docs/exercises.md): fill in a table for the mesh
// drawn (kind 1: the winged-edge tables, or the half-edge tables when the Half-edge tab is
// open), predict the CCW walk (kind 2: of edges, or of half-edges from the Half-edge tab), and
// write the rows an edit rewrites (edit).
// The subject is the mesh as loaded (with the slide's numbering where it has one: lecture
// 000's edges e1..e9) and the state's edits; the mesh the table and walk are asked of is the
// one drawn, the edits replayed in the core, so the drawing's labels and the checks agree.
import { sourceOf } from '../../ui/mesh/mesh-choice.js';
import { editedMeshSubject } from '../../exercise/subjects.js';

// The operations of the edit panel an edit exercise can ask (not a move, not compact).
const isQuestion = (op) => op && op.op !== 'move-vertex' && op.op !== 'compact';

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const meshExercise = {
  kinds: ['table', 'walk', 'edit'],
  subject(view, model, state, ctx) {
    return editedMeshSubject(ctx.api, sourceOf(state, ctx.api), state.ops);
  },
  // The drawing follows the walk being predicted: its element, at its start (the walk's own
  // panel, which would tell the next edge, is hidden by the exercise).
  showWalk(ctx, around, element) {
    const s = ctx.state;
    if (s.walk === around && s[around] === element && s.step === 0) return;
    ctx.commit({ ...s, walk: around, [around]: element, step: 0 }, { history: false });
  },
  suggest(kind, state) {
    const halfEdge = state.tab === 'half-edge';
    if (kind === 'walk') {
      const around = state.walk;
      const element = (around === 'vertex' ? state.vertex : state.face) + 1;
      const where = around === 'vertex' ? `around v${element}` : `along F${element}`;
      if (halfEdge) {
        return {
          check: { kind: 'walk', around, element, structure: 'half-edge' },
          hide: ['walk-panel', 'tables-panel'],
          question: `Walk the half-edges counter-clockwise ${where}, starting at the half-edge the ${around} table stores (${around === 'vertex' ? 'h → twin(prev(h))' : 'h → next(h)'}). At each step, which half-edge comes next?`,
        };
      }
      return {
        check: { kind: 'walk', around, element },
        hide: ['walk-panel', 'tables-panel'],
        question: `Walk counter-clockwise ${where}, starting at the edge the ${around} table stores. At each step, which edge comes next?`,
      };
    }
    if (kind === 'edit') {
      // The last edit is the question, the exercise's drawing the mesh before it; with no
      // edit made yet, splitting e1 (which every mesh allows) stands in until one is.
      const ops = state.ops ?? [];
      const last = ops[ops.length - 1];
      const asked = isQuestion(last);
      const op = asked ? Object.fromEntries(Object.entries(last).map(([k, v]) => [k, k === 'op' || k === 't' ? v : v + 1])) : { op: 'split-edge', e: 1, t: 0.5 };
      return {
        state: asked ? { ...state, ops: ops.slice(0, -1) } : state,
        check: { kind: 'edit', op },
        hide: ['edit-panel'],
        question: 'Here is the mesh before the operation. Write every row of the winged-edge tables that the operation rewrites, as it reads after it: existing rows keep their labels; give each new element a label of your choice that no element has yet; mark a removed element\'s row as removed.',
      };
    }
    if (halfEdge) {
      return {
        check: { kind: 'table', table: 'half-edge' },
        hide: ['tables-panel', 'walk-panel'],
        question: 'Fill in the half-edge tables of this mesh, numbering the half-edges as you like (h1, h2, …): for every half-edge its origin, its face ("none" on the boundary), next, prev and twin; then for every vertex one half-edge leaving it (on the boundary, the boundary one) and for every face one of its half-edges.',
      };
    }
    return {
      check: { kind: 'table', table: 'winged-edge', given: ['start', 'end'] },
      hide: ['tables-panel', 'walk-panel'],
      question: 'Fill in the winged-edge tables of this mesh: for every edge its faces L and R and its four wings, then an edge for every vertex and every face. Write "none" where there is no face.',
    };
  },
};
