// @ts-check
// What every kind's pure grading function returns (the shared contract): a result
// { correct, partial?, incomplete?, findings: [{ text, hint? }], note? } where a finding's text
// says where the answer is wrong and the rule to re-read, never the right value (the core's
// value-free `message`), and hint is a value-free nudge the player shows only at feedback
// level hint or worked. The answer graded may come from a file: a shape that cannot be read
// is a result, never an exception.

/**
 * @typedef {{ text: string, hint?: string }} Finding
 * @typedef {{ correct: boolean, partial?: boolean, incomplete?: boolean, findings: Finding[], note?: string }} GradeResult
 */

/** @param {string} text @param {string} [hint] @returns {Finding} */
export function findingOf(text, hint) {
  return hint ? { text, hint } : { text };
}

/** An answer whose shape is not the kind's. @param {string} expected what the kind's answer is @returns {GradeResult} */
export function unreadable(expected) {
  return { correct: false, incomplete: true, findings: [{ text: `The answer could not be read: ${expected} was expected.` }] };
}

/** A student's answer that is not yet complete enough to check. @param {string} text @returns {GradeResult} */
export function incomplete(text) {
  return { correct: false, incomplete: true, findings: [{ text }] };
}

export const isPlainObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
