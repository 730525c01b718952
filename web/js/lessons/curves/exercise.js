// @ts-check
// The curve explorer's exercises: compute a value by hand (kind 4: a blending
// function, a point, an entry of M G, Boehm's new control point) and move control points
// until the curve passes through a point (kind 5).
import { curveSpec } from './families.js';

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const curvesExercise = {
  kinds: ['value', 'property'],
  keepsState: ['property'],
  subject(view, model, state) {
    return { curve: curveSpec(state) };
  },
  suggest(kind, state) {
    if (kind === 'property') {
      // A point the curve does not pass through: where the second control point is now.
      const point = state.points[Math.min(1, state.points.length - 1)].map((x) => Math.round(x * 100) / 100);
      return {
        check: { kind: 'property', property: { kind: 'passes-through', point, tolerance: 0.005 } },
        hide: [],
        question: `Move the control points until the curve passes through the target (${point.join(', ')}).`,
      };
    }
    const u = Math.round(state.u * 100) / 100;
    return {
      check: { kind: 'value', quantity: 'point', u, tolerance: 0.01 },
      hide: ['panel-inspector', 'panel-matrix', 'panel-construction'],
      question: `Compute the point P(${u}) of this curve by hand, to within 0.01.`,
    };
  },
};
