// @ts-check
// Validators for lesson state read from a share link, local storage or an imported file.
// Each validator takes (value, path) and returns the clean value or throws a SchemaError
// naming the path ("points[3].x is not a number"). Nothing from outside is used unchecked.
// The same validators check every change the page makes (ctx.commit in shell.js, with
// checkChange below), so the page never holds a value its state format would refuse.
import { COORDINATE_BOUND, MAX_NESTING } from './limits.js';

export class SchemaError extends Error {
  constructor(path, message) {
    super(`${path || 'state'} ${message}`);
    this.path = path;
  }
}

const describe = (v) => {
  if (typeof v === 'string') return `the text "${v.length > 24 ? v.slice(0, 24) + '…' : v}"`;
  if (Array.isArray(v)) return `a list of ${v.length}`;
  if (v === null) return 'null';
  return typeof v === 'object' ? 'an object' : String(v);
};

// Bounds as a person reads them: 1e9 rather than 1000000000.
const bound = (n) => (Math.abs(n) >= 1e6 ? n.toExponential().replace('e+', 'e') : String(n));
const outside = (v, min, max) => `must be between ${bound(min)} and ${bound(max)} (the limits a saved lesson keeps), not ${v}`;

export const number = ({ min = -COORDINATE_BOUND, max = COORDINATE_BOUND } = {}) => (v, path) => {
  if (typeof v !== 'number' || !Number.isFinite(v)) throw new SchemaError(path, `must be a finite number, not ${describe(v)}`);
  if (v < min || v > max) throw new SchemaError(path, outside(v, min, max));
  return v;
};

export const integer = ({ min = 0, max = 1e6 } = {}) => (v, path) => {
  if (!Number.isInteger(v)) throw new SchemaError(path, `must be a whole number, not ${describe(v)}`);
  if (v < min || v > max) throw new SchemaError(path, outside(v, min, max));
  return v;
};

export const boolean = () => (v, path) => {
  if (typeof v !== 'boolean') throw new SchemaError(path, `must be true or false, not ${describe(v)}`);
  return v;
};

export const oneOf = (...choices) => (v, path) => {
  if (!choices.includes(v)) throw new SchemaError(path, `must be one of ${choices.join(', ')}, not ${describe(v)}`);
  return v;
};

export const text = ({ maxLength = 200 } = {}) => (v, path) => {
  if (typeof v !== 'string') throw new SchemaError(path, `must be text, not ${describe(v)}`);
  if (v.length > maxLength) throw new SchemaError(path, `is longer than ${maxLength} characters`);
  return v;
};

export const list = (item, { min = 0, max = 10000 } = {}) => (v, path) => {
  if (!Array.isArray(v)) throw new SchemaError(path, `must be a list, not ${describe(v)}`);
  if (v.length < min || v.length > max) throw new SchemaError(path, `must have ${min} to ${max} entries, not ${v.length}`);
  // A list whose entries all come back as they are is returned itself, not copied, and an
  // entry's path is written only for its error message (the failing entry is checked again
  // with it; validators are pure): checking a million faces allocates nothing.
  let out = null;
  for (let i = 0; i < v.length; i += 1) {
    let clean;
    try {
      clean = item(v[i], path);
    } catch {
      clean = item(v[i], `${path}[${i}]`);
    }
    if (out) out.push(clean);
    else if (clean !== v[i]) { out = v.slice(0, i); out.push(clean); }
  }
  return out ?? v;
};

// A fixed-shape object. Unknown keys are dropped; missing keys take `defaults[key]` when given.
export const object = (shape, { optional = [] } = {}) => (v, path) => {
  if (v === null || typeof v !== 'object' || Array.isArray(v)) throw new SchemaError(path, `must be an object, not ${describe(v)}`);
  const out = {};
  // An object with no other keys whose fields all come back as they are is returned itself
  // (a mesh read back stays the object whose text and hash share-link.js knows).
  let same = true;
  let present = 0;
  for (const [key, check] of Object.entries(shape)) {
    const sub = path ? `${path}.${key}` : key;
    if (!Object.prototype.hasOwnProperty.call(v, key)) {
      if (optional.includes(key)) continue;
      throw new SchemaError(sub, 'is missing');
    }
    out[key] = check(v[key], sub);
    present += 1;
    if (out[key] !== v[key]) same = false;
  }
  return same && Object.keys(v).length === present ? v : out;
};

export const nullable = (inner) => (v, path) => (v === null ? null : inner(v, path));

// Validates `raw` field by field against an object shape; a field that fails falls back to
// the default's value and is reported, so a partly damaged link keeps its valid part.
export function validatePartial(shape, raw, defaults) {
  const problems = [];
  if (raw === null || typeof raw !== 'object' || Array.isArray(raw)) {
    return { state: structuredClone(defaults), problems: ['the state is not an object'] };
  }
  const state = {};
  const keys = Object.keys(shape);
  const missing = keys.filter((key) => !Object.prototype.hasOwnProperty.call(raw, key));
  // Every saved state has every field (migrations add new ones), so a missing field means
  // a damaged or hand-made state: it is reset, and said.
  for (const [key, check] of Object.entries(shape)) {
    if (missing.includes(key)) {
      state[key] = structuredClone(defaults[key]);
      continue;
    }
    try {
      state[key] = check(raw[key], key);
    } catch (err) {
      // A validator that fails in an unforeseen way still only costs this one field.
      problems.push(err instanceof SchemaError ? err.message : `${key} could not be checked`);
      state[key] = structuredClone(defaults[key]);
    }
  }
  // Wrong values first (they say most about what is wrong), then missing fields.
  if (missing.length === keys.length) problems.push("it holds none of this lesson's settings");
  else for (const key of missing) problems.push(`${key} is missing`);
  return { state, problems };
}

// Checks a change before it is committed: the fields of `next` that are not the very same
// value as in `previous` (states are spread copies, so untouched fields are shared and were
// checked when they entered) go through the schema, then the lesson's cross-field rule.
// Returns null, or one sentence naming the field and the limit.
export function checkChange(shape, next, previous, checkState) {
  for (const [key, check] of Object.entries(shape)) {
    if (previous && next[key] === previous[key]) continue;
    try {
      check(next[key], key);
    } catch (err) {
      return err instanceof SchemaError ? err.message : `${key} could not be checked`;
    }
  }
  try {
    return checkState?.(next) ?? null;
  } catch (err) {
    return `the change breaks a rule of the lesson (${err.message})`;
  }
}

// A value parsed from outside nests at most `limit` levels of objects and lists (the
// outermost is level 1), or a SchemaError names the path to the first level too deep
// ("exercise.state.extra.a.a.a… nests deeper than 64 levels"). Measured without recursion,
// with a stack of at most `limit` entries, before any recursive walk (validators, copies,
// JSON.stringify) sees the value. `root` names the outermost value in the path.
export function checkNesting(value, root = '', limit = MAX_NESTING) {
  if (value === null || typeof value !== 'object') return value;
  // One entry per open level: the container, its keys (objects) and the next position.
  const nodes = [value];
  const keyLists = [Array.isArray(value) ? null : Object.keys(value)];
  const positions = [0];
  const path = [];
  while (nodes.length) {
    const level = nodes.length - 1;
    const node = nodes[level];
    const keys = keyLists[level];
    let i = positions[level];
    let child = null;
    // Numbers and texts are passed over in this loop (a mesh's millions of coordinates).
    if (keys === null) {
      for (; i < node.length; i += 1) {
        const v = node[i];
        if (typeof v === 'object' && v !== null) { child = v; break; }
      }
    } else {
      for (; i < keys.length; i += 1) {
        const v = node[keys[i]];
        if (typeof v === 'object' && v !== null) { child = v; break; }
      }
    }
    if (child === null) {
      nodes.pop(); keyLists.pop(); positions.pop(); path.pop();
      continue;
    }
    positions[level] = i + 1;
    const key = keys === null ? i : keys[i];
    if (nodes.length >= limit) throw new SchemaError(nestingPath(root, [...path, key]), `nests deeper than ${limit} levels`);
    path.push(key);
    nodes.push(child);
    keyLists.push(Array.isArray(child) ? null : Object.keys(child));
    positions.push(0);
  }
  return value;
}

// The same check for a reader whose refusals are sentences about "it" (a link, a file, a
// saved state): the sentence, or null when the value nests within the limit.
export function nestingProblem(value, root = '') {
  try {
    checkNesting(value, root);
    return null;
  } catch (err) {
    if (err instanceof SchemaError) return `its field ${err.message}`;
    throw err;
  }
}

// The path to a too-deep value as a person reads it: the first steps, then "…".
const PATH_STEPS_SHOWN = 6;
const KEY_CHARS_SHOWN = 24;
function nestingPath(root, keys) {
  const step = (key) => {
    if (typeof key === 'number') return `[${key}]`;
    const name = key.length > KEY_CHARS_SHOWN ? `${key.slice(0, KEY_CHARS_SHOWN)}…` : key;
    return /^[A-Za-z_$][\w$]*$/.test(key) ? `.${name}` : `[${JSON.stringify(name)}]`;
  };
  const shown = keys.slice(0, PATH_STEPS_SHOWN).map(step).join('');
  const path = `${root}${shown}`.replace(/^\./, '');
  return keys.length > PATH_STEPS_SHOWN ? `${path}…` : path;
}

// The 2D view a drawing lesson keeps in its state: the centre (world units) and the zoom
// (CSS pixels per world unit).
export const viewSchema = () => object({ cx: number(), cy: number(), zoom: number({ min: 1, max: 1e5 }) });
