// @ts-check
// The mesh lesson's exercises (docs/exercises.md): fill in a table for the mesh
// drawn (kind 1) and predict the CCW walk (kind 2). The subject is the mesh as loaded, with
// the slide's numbering where it has one (lecture 000's edges e1..e9), so the drawing's labels
// and the checks agree.
import { sourceOf } from '../../ui/mesh/mesh-choice.js';
import { refuseEdited } from '../../exercise/subjects.js';

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const meshExercise = {
  kinds: ['table', 'walk'],
  subject(view, model, state, ctx) {
    refuseEdited(state);
    return { mesh: sourceOf(state, ctx.api) };
  },
  // The drawing follows the walk being predicted: its element, at its start (the walk's own
  // panel, which would tell the next edge, is hidden by the exercise).
  showWalk(ctx, around, element) {
    const s = ctx.state;
    if (s.walk === around && s[around] === element && s.step === 0) return;
    ctx.commit({ ...s, walk: around, [around]: element, step: 0 }, { history: false });
  },
  suggest(kind, state) {
    if (kind === 'walk') {
      const around = state.walk;
      const element = (around === 'vertex' ? state.vertex : state.face) + 1;
      return {
        check: { kind: 'walk', around, element },
        hide: ['walk-panel', 'tables-panel'],
        question: `Walk counter-clockwise ${around === 'vertex' ? `around v${element}` : `along F${element}`}, starting at the edge the ${around} table stores. At each step, which edge comes next?`,
      };
    }
    return {
      check: { kind: 'table', table: 'winged-edge', given: ['start', 'end'] },
      hide: ['tables-panel', 'walk-panel'],
      question: 'Fill in the winged-edge tables of this mesh: for every edge its faces L and R and its four wings, then an edge for every vertex and every face. Write "none" where there is no face.',
    };
  },
};
