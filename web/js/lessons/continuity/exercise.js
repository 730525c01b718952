// @ts-check
// The continuity lab's exercises (issue 19): classify a joint, C^k and G^k, and say why
// (kind 3); move control points until a joint is exactly of a class, e.g. C^1 but not C^2
// (kind 5). The joints are the lab's own: consecutive segments, in order.

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const continuityExercise = {
  kinds: ['joint', 'property'],
  keepsState: ['property'],
  subject(view, model) {
    return { joints: model.segments.slice(1).map((b, i) => ({ a: model.segments[i].curve, b: b.curve })) };
  },
  suggest(kind) {
    if (kind === 'property') {
      return {
        check: { kind: 'property', property: { kind: 'joint-class', joint: 1, parametric: 1 } },
        hide: ['joints-panel'],
        question: 'Move the control points until the first joint is C¹ but not C².',
      };
    }
    return {
      check: { kind: 'joint', joint: 1 },
      hide: ['joints-panel', 'plots-panel'],
      question: 'Classify the first joint: which Cᵏ and which Gᵏ is it? Tick the statements that say why.',
    };
  },
};
