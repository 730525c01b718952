// The lesson state as text: a versioned envelope {format, lesson, version, state}, written
// as JSON (numbers round-trip exactly: JSON keeps the shortest text that reads back to the
// same double), compressed with deflate-raw and base64url-encoded into the URL fragment
// (#s=...), so a static host never sees it and the link stays short.
// Reading goes: decode -> parse -> check the envelope -> migrate older versions -> validate
// field by field. Every failure becomes one sentence for the message line.
import { validatePartial } from './schema.js';

export const FORMAT = 'wingspline';
export const MAX_LINK_CHARS = 200000;
// The most a link may unpack to. A real state compresses well under 10:1, so a link of
// MAX_LINK_CHARS (about 150 KB of deflate) unpacks to under 1.5 MB; a compressed bomb
// (deflate reaches about 1000:1) is stopped here while it inflates (issue 13).
export const MAX_STATE_BYTES = 16 * 2 ** 20;

// Inflates deflate-raw bytes, refusing once more than `cap` bytes have come out.
async function inflateCapped(bytes, cap) {
  const reader = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate-raw')).getReader();
  const chunks = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.length;
    if (total > cap) {
      await reader.cancel().catch(() => {});
      throw new Error(`it unpacks to more than ${cap / 2 ** 20} MB, far more than any lesson state`);
    }
    chunks.push(value);
  }
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) { out.set(c, at); at += c.length; }
  return out;
}

function toBase64Url(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(text) {
  if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error('it contains characters a share link never has');
  const padded = text.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (text.length % 4)) % 4);
  const binary = atob(padded);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i += 1) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

async function pipe(bytes, stream) {
  const out = new Response(new Blob([bytes]).stream().pipeThrough(stream));
  return new Uint8Array(await out.arrayBuffer());
}

export function envelope(lesson, state) {
  return { format: FORMAT, lesson: lesson.id, version: lesson.stateVersion, state };
}

// JSON text of a plain value, exact for every double: JSON.stringify already writes the
// shortest text that reads back to the same double, except for -0, which it writes as "0";
// JSON.parse("-0") is -0, so writing "-0" makes the round trip bit for bit. Non-finite
// numbers have no JSON text and are refused (a state never holds them: the schema says so).
export function stringifyExact(value, indent = 0) {
  const pad = (depth) => (indent ? '\n' + ' '.repeat(indent * depth) : '');
  const sep = indent ? ': ' : ':';
  function write(v, depth) {
    if (typeof v === 'number') {
      if (!Number.isFinite(v)) throw new Error(`the state holds ${v}, which JSON cannot keep`);
      return Object.is(v, -0) ? '-0' : JSON.stringify(v);
    }
    if (v === null || typeof v === 'string' || typeof v === 'boolean') return JSON.stringify(v);
    if (Array.isArray(v)) {
      if (v.length === 0) return '[]';
      return `[${v.map((x) => pad(depth + 1) + write(x === undefined ? null : x, depth + 1)).join(',')}${pad(depth)}]`;
    }
    if (typeof v === 'object') {
      const entries = Object.entries(v).filter(([, x]) => x !== undefined && typeof x !== 'function');
      if (entries.length === 0) return '{}';
      return `{${entries.map(([k, x]) => `${pad(depth + 1)}${JSON.stringify(k)}${sep}${write(x, depth + 1)}`).join(',')}${pad(depth)}}`;
    }
    throw new Error(`the state holds a ${typeof v}, which JSON cannot keep`);
  }
  return write(value, 0);
}

// The exported file (docs/state-format.md): the envelope, indented, newline-terminated.
export function envelopeJson(lesson, state) {
  return stringifyExact(envelope(lesson, state), 2) + '\n';
}

export async function encodeState(lesson, state) {
  const json = stringifyExact(envelope(lesson, state));
  return toBase64Url(await pipe(new TextEncoder().encode(json), new CompressionStream('deflate-raw')));
}

// Checks and upgrades a parsed envelope. Returns { state, problems } (problems: sentences);
// throws an Error whose message is one sentence when nothing of it can be used.
export function readEnvelope(lesson, data) {
  if (data === null || typeof data !== 'object' || Array.isArray(data)) throw new Error('it does not hold a lesson state');
  if (data.format !== FORMAT) throw new Error('it is not a Wingspline state');
  if (data.lesson !== lesson.id) {
    if (typeof data.lesson !== 'string' || !/^[a-z][a-z0-9-]{0,39}$/.test(data.lesson)) throw new Error(`it does not name a lesson, and this is ${lesson.title}`);
    throw new Error(`it belongs to the ${data.lesson} lesson, not to ${lesson.title}`);
  }
  let { version, state } = data;
  if (!Number.isSafeInteger(version) || version < 1) throw new Error('its version number is missing or wrong');
  if (version > lesson.stateVersion) {
    throw new Error(`it was made by a newer Wingspline (state version ${version}; this page reads up to ${lesson.stateVersion})`);
  }
  // Older links keep working: apply each migration from their version up to ours.
  for (; version < lesson.stateVersion; version += 1) {
    const migrate = Object.prototype.hasOwnProperty.call(lesson.migrations ?? {}, version) ? lesson.migrations[version] : null;
    if (!migrate) throw new Error(`state version ${version} can no longer be read`);
    try {
      state = migrate(state);
    } catch {
      // A migration meets an old state of the wrong shape: nothing of it is trusted.
      throw new Error(`its state (version ${version}) could not be upgraded to version ${version + 1}`);
    }
  }
  const defaults = lesson.defaultState();
  const result = validatePartial(lesson.schema, state, defaults);
  if (lesson.checkState) {
    // Cross-field rules the per-field schema cannot express (knot count vs points...).
    let problem;
    try {
      problem = lesson.checkState(result.state);
    } catch (err) {
      problem = `its state breaks a rule of the lesson (${err.message})`;
    }
    if (problem) return { state: defaults, problems: [...result.problems, problem] };
  }
  return result;
}

export async function decodeState(lesson, text) {
  if (typeof text !== 'string' || text.length === 0) throw new Error('it is empty');
  if (text.length > MAX_LINK_CHARS) throw new Error('it is far longer than any lesson state');
  let json;
  try {
    json = new TextDecoder('utf-8', { fatal: true }).decode(await inflateCapped(fromBase64Url(text), MAX_STATE_BYTES));
  } catch (err) {
    throw new Error(err.message.startsWith('it ') ? err.message : 'it is truncated or damaged (it does not decompress)');
  }
  let data;
  try {
    data = JSON.parse(json);
  } catch {
    throw new Error('it is damaged (its contents are not valid JSON)');
  }
  return readEnvelope(lesson, data);
}
