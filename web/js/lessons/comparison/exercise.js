// @ts-check
// The comparison lab's exercises: compute a value by hand (kind 4) of one family
// drawn on the polygon: the exercise names the family; the curve asked of is that family's
// first segment (P0..P3 for Bezier, P0, P1 with their tangents for Hermite), or the whole
// non-uniform B-spline.
import { FAMILY_IDS, familySegments } from './families.js';

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const comparisonExercise = {
  kinds: ['value', 'property'],
  keepsState: ['property'],
  subject(view, model, state, ctx) {
    const own = state.hermite.tangents === 'own' ? state.hermite.own : null;
    const curves = {};
    for (const family of FAMILY_IDS) curves[family] = familySegments(ctx.api, family, state.points, family === 'hermite' ? own : null)[0];
    return { curves };
  },
  suggest(kind, state) {
    if (kind === 'property') {
      const point = state.points[1].map((x) => Math.round(x * 100) / 100);
      return {
        check: { kind: 'property', property: { kind: 'passes-through', family: 'bezier', point, tolerance: 0.005 } },
        hide: ['table-panel'],
        question: `Move the control points until the first Bezier segment passes through the target (${point.join(', ')}).`,
      };
    }
    return {
      check: { kind: 'value', quantity: 'point', family: 'bezier', u: 0.5, tolerance: 0.01 },
      hide: ['table-panel', 'blending-panel'],
      question: 'Compute by hand the point P(0.5) of the first Bezier segment (P0 to P3), to within 0.01.',
    };
  },
};
