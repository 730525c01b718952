// @ts-check
// Errors from the core arrive as plain {ok:false, code, message} values; this module turns
// them into Error objects with a stable `code`, and checks arguments before they reach
// embind (which would silently turn a string into NaN).

export class WingsplineError extends Error {
  constructor(code, message, details = undefined) {
    super(message);
    this.name = 'WingsplineError';
    this.code = code;
    if (details !== undefined) this.details = details;
  }
}

// Returns the result object when ok, throws a WingsplineError otherwise.
export function unwrap(result) {
  if (result && result.ok) return result;
  const code = result?.code ?? 'internal-error';
  const message = result?.message ?? 'the core returned no result';
  throw new WingsplineError(code, message, result?.details);
}

export function fail(code, message) {
  throw new WingsplineError(code, message);
}

export function isNumberArray(value) {
  return ArrayBuffer.isView(value) && !(value instanceof DataView)
    ? true
    : Array.isArray(value) && value.every((x) => typeof x === 'number');
}

export function integerIn(value, what, min, max) {
  if (!Number.isInteger(value) || value < min || value > max) {
    fail('invalid-argument', `${what} must be a whole number from ${min} to ${max}, not ${String(value).slice(0, 40)}`);
  }
  return value;
}

// The largest index the core takes (int32).
export const INT32_MAX = 2147483647;

// An element's index as the API takes it (0-based: 0 is the first vertex, v1). Any whole
// number reaches the core, which names the element by its 1-based label and says which
// ones exist ("there is no F6: the mesh has faces F1 to F4").
export function elementIndex(value, kind) {
  if (!Number.isInteger(value)) {
    fail('invalid-argument', `${kind} must be a whole number, the ${kind}'s index (0 is the first ${kind}), not ${String(value).slice(0, 40)}`);
  }
  if (Math.abs(value) > INT32_MAX) fail('invalid-argument', `${kind} ${value} is far beyond any mesh (an index is at most ${INT32_MAX})`);
  return value;
}
