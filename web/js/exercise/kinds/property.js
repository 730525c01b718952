// @ts-check
// Kind 5: move control points until a property holds (make a joint C^1 but not C^2; make a
// Bezier curve pass through a point). The drawing is the answer: the student drags the
// lesson's handles; the core says after every change whether the property holds and what is
// missing (api.checkCurveProperty). The target point of "passes through" is drawn.
import { h } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { findingOf } from './grading.js';

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

function measure(api, property, subject) {
  const { joint, ...rest } = property;
  return api.checkCurveProperty(propertySubject(property, subject), rest);
}

/**
 * Grades the drawing (the subject asked of the student's lesson state; the page's answer is
 * null: the drawing is the answer). Pure: no DOM. What is missing names the present state of
 * the drawing, never a target value.
 * @param {{ api: any, check: any, subject: any, answer?: unknown }} parts
 * @returns {import('./grading.js').GradeResult}
 */
export function gradeProperty({ api, check, subject }) {
  const r = measure(api, check.property, subject);
  return { correct: r.holds, findings: r.holds ? [] : [findingOf(r.reason)], note: r.holds ? r.reason : undefined };
}

/** @param {{ api: any, check: any, subject: any }} parts */
export function workedProperty({ api, check, subject }) {
  const r = measure(api, check.property, subject);
  return { lines: [r.reason, check.property.kind === 'joint-class' ? 'Lecture 000: a joint is Cᵏ when the derivatives up to order k agree there; Gᵏ when they agree after reparametrisation (same directions, lengths may differ).' : 'Move the nearest part of the curve towards the point: drag the control points that weigh most there (the blending functions at that u).'] };
}

/** @param {any} parts */
export function createPropertyKind({ api, check, subject }) {
  const { property } = check;
  measure(api, property, subject());
  const now = h('p', { class: 'exercise-live', 'aria-live': 'polite' });
  const root = h('div', { class: 'exercise-property' },
    h('p', { class: 'hint' }, 'Drag the control points in the drawing (or select one and use the arrow keys), then check.'), now);
  return {
    root,
    answer: () => null,
    restore() {},
    stateChanged() {
      try {
        const r = measure(api, property, subject());
        now.textContent = r.holds ? 'It holds now: check it.' : `Not yet: ${r.reason}`;
      } catch (err) {
        now.textContent = err.message;
      }
    },
    check: () => gradeProperty({ api, check, subject: subject() }),
    worked: () => workedProperty({ api, check, subject: subject() }),
    // The target point on the drawing (world coordinates), for "passes through".
    draw(painter, colors) {
      if (property.kind !== 'passes-through') return;
      const [x, y] = property.point;
      painter.circle(x, y, 9, { stroke: colors.highlight, width: 3 });
      painter.text(x, y, `target (${x}, ${y})`, { fill: colors.ink, font: 14, dx: 12, dy: -12, halo: colors.background });
    },
  };
}
