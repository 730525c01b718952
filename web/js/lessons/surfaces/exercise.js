// @ts-check
// The surface patches' exercises: compute a point p(u, v) of patch A by hand
// (kind 4), from its 16 control entries (lecture 002: p(u, v) = uᵀ M P Mᵀ v).

/** @type {import('../../app/contract.js').ExerciseSupport} */
export const surfacesExercise = {
  kinds: ['value'],
  subject(view, model, state) {
    return { patch: { kind: state.kind, points: state.a.flatMap((p) => p) } };
  },
  suggest() {
    return {
      check: { kind: 'value', quantity: 'patch-point', u: 0.5, v: 0.5, tolerance: 0.01 },
      hide: ['formula-panel', 'inspector-panel'],
      question: 'Compute by hand the point p(0.5, 0.5) of patch A, to within 0.01 (x, y, z).',
    };
  },
};
