// @ts-check
// Kind 5: move control points until a property holds (make a joint C^1 but not C^2; make a
// Bezier curve pass through a point). The drawing is the answer: the student drags the
// lesson's handles; the core says after every change whether the property holds and what is
// missing (api.checkCurveProperty). The target point of "passes through" is drawn.
import { h } from '../../app/dom.js';
import { ExerciseError } from '../format.js';

export function propertySubject(property, subject) {
  if (property.kind === 'joint-class') {
    const joints = subject.joints;
    if (!joints) throw new ExerciseError('this lesson has no joints', 'exercise.check.property.kind');
    if (property.joint > joints.length) throw new ExerciseError(`its field exercise.check.property.joint is ${property.joint}, but the curve has ${joints.length} joint${joints.length === 1 ? '' : 's'}`, 'exercise.check.property.joint');
    return joints[property.joint - 1];
  }
  const curve = property.family !== undefined ? subject.curves?.[property.family] : subject.curve;
  if (!curve) throw new ExerciseError(property.family !== undefined ? `its field exercise.check.property.family names "${property.family}", which this lesson does not draw` : 'this lesson has no curve', 'exercise.check.property');
  return { curve };
}

/** @param {any} parts */
export function createPropertyKind({ api, check, subject }) {
  const { property } = check;
  const measure = () => {
    const { joint, ...rest } = property;
    return api.checkCurveProperty(propertySubject(property, subject()), rest);
  };
  measure();
  const now = h('p', { class: 'exercise-live', 'aria-live': 'polite' });
  const root = h('div', { class: 'exercise-property' },
    h('p', { class: 'hint' }, 'Drag the control points in the drawing (or select one and use the arrow keys), then check.'), now);
  return {
    root,
    answer: () => null,
    restore() {},
    stateChanged() {
      try {
        const r = measure();
        now.textContent = r.holds ? 'It holds now: check it.' : `Not yet: ${r.reason}`;
      } catch (err) {
        now.textContent = err.message;
      }
    },
    check() {
      const r = measure();
      return { correct: r.holds, findings: r.holds ? [] : [r.reason], note: r.holds ? r.reason : undefined };
    },
    worked() {
      const r = measure();
      return { lines: [r.reason, property.kind === 'joint-class' ? 'Lecture 000: a joint is Cᵏ when the derivatives up to order k agree there; Gᵏ when they agree after reparametrisation (same directions, lengths may differ).' : 'Move the nearest part of the curve towards the point: drag the control points that weigh most there (the blending functions at that u).'] };
    },
    // The target point on the drawing (world coordinates), for "passes through".
    draw(painter, colors) {
      if (property.kind !== 'passes-through') return;
      const [x, y] = property.point;
      painter.circle(x, y, 9, { stroke: colors.highlight, width: 3 });
      painter.text(x, y, `target (${x}, ${y})`, { fill: colors.ink, font: 14, dx: 12, dy: -12, halo: colors.background });
    },
  };
}
