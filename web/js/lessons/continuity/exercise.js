// @ts-check
// The continuity lab's exercises: classify a joint, C^k and G^k, and say why
// (kind 3); move control points until a joint is exactly of a class, e.g. C^1 but not C^2
// (kind 5). The joints are the lab's own: consecutive segments, in order.

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const continuityExercise = {
  kinds: ['joint', 'property'],
  keepsState: ['property'],
  usesModel: true,
  subject(view, model) {
    return { joints: model.segments.slice(1).map((b, i) => ({ a: model.segments[i].curve, b: b.curve })) };
  },
  suggest(kind, state, { api, subject }) {
    if (kind === 'property') {
      // One class below what the first joint is now (a C¹ joint: make it C⁰ only), or C¹
      // for a joint that is not C¹: a change the student can make by dragging (with the
      // "while dragging" constraint where it helps).
      const { a, b } = subject.joints[0];
      const now = api.checkCurveProperty({ a, b }, { kind: 'joint-class', parametric: 0 }).measured.parametric;
      const k = now >= 1 ? now - 1 : 1;
      const sup = ['⁰', '¹', '²'];
      return {
        check: { kind: 'property', property: { kind: 'joint-class', joint: 1, parametric: k } },
        hide: ['joints-panel'],
        question: `Move the control points until the first joint is C${sup[k]}${k < 2 ? ` but not C${sup[k + 1]}` : ''}.`,
      };
    }
    return {
      check: { kind: 'joint', joint: 1 },
      hide: ['joints-panel', 'plots-panel'],
      question: 'Classify the first joint: which Cᵏ and which Gᵏ is it? Tick the statements that say why.',
    };
  },
};
