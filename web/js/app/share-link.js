// @ts-check
// The lesson state as text: a versioned envelope {format, lesson, version, state}, written
// as JSON (numbers round-trip exactly: JSON keeps the shortest text that reads back to the
// same double), compressed with deflate-raw and base64url-encoded into the URL fragment
// (#s=...), so a static host never sees it and the link stays short.
// Reading goes: decode -> parse -> check the envelope -> migrate older versions -> validate
// field by field. Every failure becomes one sentence for the message line.
// A large field that the lesson declares in `lesson.contentFields` (the mesh lesson's
// imported mesh) travels by reference: {"$content": "sha256-<hex>", "label": "..."}, its
// text kept in a content store (content-store.js, IndexedDB) by its SHA-256; values of at
// most INLINE_CONTENT_MAX_CHARS characters of JSON still travel inline, so a link to a
// small mesh works on any machine (docs/state-format.md, "Large fields").
import { validatePartial, nestingProblem } from './schema.js';

export const FORMAT = 'wingspline';
export const MAX_LINK_CHARS = 200000;
// The most a link may unpack to. A real state compresses well under 10:1, so a link of
// MAX_LINK_CHARS (about 150 KB of deflate) unpacks to under 1.5 MB; a compressed bomb
// (deflate reaches about 1000:1) is stopped here while it inflates.
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

// 16 KiB of JSON: the lecture's meshes, a cube, a few hundred faces (about 300 vertices
// with full-precision coordinates). Compressed, such a link stays under about 8,000
// characters, which chat programs and mail clients carry whole.
export const INLINE_CONTENT_MAX_CHARS = 16384;
const CONTENT_REF = /^sha256-[0-9a-f]{64}$/;
const LABEL_MAX_CHARS = 120;

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

// Any text as a link code (deflate-raw, base64url), and back: the state's codec, also used
// for exercises (exercise/link.js). unpackText refuses a code that unpacks past `cap` bytes.
export async function packText(textValue) {
  return toBase64Url(await pipe(new TextEncoder().encode(textValue), new CompressionStream('deflate-raw')));
}
export async function unpackText(code, cap = MAX_STATE_BYTES) {
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(await inflateCapped(fromBase64Url(code), cap));
  } catch (err) {
    throw new Error(err.message.startsWith('it ') ? err.message : 'it is truncated or damaged (it does not decompress)');
  }
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

// The content store's key of a text: 'sha256-' + the hex SHA-256 of its UTF-8 bytes.
export async function sha256(textValue) {
  const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', new TextEncoder().encode(textValue)));
  return `sha256-${Array.from(digest, (b) => b.toString(16).padStart(2, '0')).join('')}`;
}

// Per value object (a large field rides unchanged from state to state, spread copies share
// it): its JSON text's length and, once computed, its hash; so a save after a walk step
// does not serialise and hash 600,000 numbers again.
const contentCache = new WeakMap();
function contentText(value) {
  let entry = contentCache.get(value);
  if (!entry) {
    const json = stringifyExact(value);
    entry = { json, chars: json.length, hash: null };
    contentCache.set(value, entry);
  }
  return entry;
}

// A value whose JSON text was written, hashed and stored elsewhere (the import worker, issue
// 17: a million faces are not serialised on the page): its length and hash are remembered,
// so externalize refers to it without writing it again. Only for a text already in the
// content store (json: null, nothing left to put).
export function rememberContent(value, { chars, hash }) {
  if (!CONTENT_REF.test(hash) || !Number.isSafeInteger(chars)) throw new Error('rememberContent needs the text\'s hash and length');
  contentCache.set(value, { json: null, chars, hash });
}

// The SHA-256 reference of a value's text when known (remembered or computed), else null.
export function contentHashOf(value) {
  return contentCache.get(value)?.hash ?? null;
}

function contentLabel(lesson, key, value) {
  const label = lesson.contentFields[key].label?.(value);
  return typeof label === 'string' ? label.slice(0, LABEL_MAX_CHARS) : key;
}

// The state as written to a link: large content fields replaced by references. With
// `contents`, the text is stored there first (a field whose store refuses it stays
// inline); without it, only fields whose hash is already known are replaced (the
// synchronous write on pagehide). Resolves to { state, refs: [{ key, label, hash }], unstored: [keys] }.
export async function externalize(lesson, state, contents) {
  const refs = [];
  const unstored = [];
  if (!lesson.contentFields || !state) return { state, refs, unstored };
  const out = { ...state };
  for (const key of Object.keys(lesson.contentFields)) {
    const value = state[key];
    if (value === null || typeof value !== 'object') continue;
    const entry = contentText(value);
    if (entry.chars <= INLINE_CONTENT_MAX_CHARS) continue;
    if (contents) {
      try {
        entry.hash = entry.hash ?? await sha256(entry.json);
        if (entry.json !== null) await contents.put(entry.hash, entry.json);
      } catch {
        unstored.push(key);
        continue;
      }
    } else if (!entry.hash) {
      continue;
    }
    const label = contentLabel(lesson, key, value);
    out[key] = { $content: entry.hash, label };
    refs.push({ key, label, hash: entry.hash });
  }
  return { state: out, refs, unstored };
}

// The synchronous form for pagehide: only hashes already computed are used.
export function externalizeKnown(lesson, state) {
  if (!lesson.contentFields || !state) return state;
  const out = { ...state };
  for (const key of Object.keys(lesson.contentFields)) {
    const value = state[key];
    const entry = value && typeof value === 'object' ? contentCache.get(value) : null;
    if (entry?.hash && entry.chars > INLINE_CONTENT_MAX_CHARS) out[key] = { $content: entry.hash, label: contentLabel(lesson, key, value) };
  }
  return out;
}

const isRef = (v) => v !== null && typeof v === 'object' && !Array.isArray(v) && Object.prototype.hasOwnProperty.call(v, '$content');

// Replaces the references of a parsed envelope's state by their stored values. A reference
// that cannot be resolved (another browser, an entry dropped, a text that no longer has its
// hash) refuses the whole state with one sentence naming the file: the rest of the state
// means little without it, and the person's saved work is shown instead.
async function internalize(lesson, data, contents) {
  const state = data?.state;
  // A state of another lesson or format is refused by readEnvelope with its own sentence.
  if (data?.format !== FORMAT || data?.lesson !== lesson.id) return data;
  if (!lesson.contentFields || state === null || typeof state !== 'object' || Array.isArray(state)) return data;
  let out = null;
  for (const key of Object.keys(lesson.contentFields)) {
    if (!Object.prototype.hasOwnProperty.call(state, key) || !isRef(state[key])) continue;
    const ref = state[key];
    // A malformed reference is a wrong value of the field: the schema names it.
    if (typeof ref.$content !== 'string' || !CONTENT_REF.test(ref.$content) || typeof ref.label !== 'string') continue;
    const label = ref.label.slice(0, LABEL_MAX_CHARS);
    const { what = 'an imported file', file = 'the file' } = lesson.contentFields[key];
    const missing = `it refers to ${what} ("${label}") that is only stored in the browser where the link was made: ask for ${file} and import it`;
    let stored = null;
    try {
      stored = contents ? await contents.get(ref.$content) : null;
    } catch (err) {
      // The database is there but cannot be opened now (an older page holding it, a lost
      // connection): not the same as a mesh this browser does not have; nothing is set aside.
      if (err?.unavailable) throw Object.assign(new Error(`${what} ("${label}") cannot be read now: ${err.message}`), { unavailable: true });
      stored = null;
    }
    if (typeof stored !== 'string') throw new Error(missing);
    if (await sha256(stored) !== ref.$content) throw new Error(`the stored copy of "${label}" in this browser is damaged: import the file again`);
    let value;
    try {
      value = JSON.parse(stored);
    } catch {
      throw new Error(`the stored copy of "${label}" in this browser is damaged: import the file again`);
    }
    out = out ?? { ...state };
    out[key] = value;
    // The value read back is the one stored under this hash: no need to hash it again.
    contentCache.set(value, { json: stored, chars: stored.length, hash: ref.$content });
  }
  return out ? { ...data, state: out } : data;
}

// The envelope of a parsed link, storage entry or file, references resolved, then checked
// as readEnvelope does.
/**
 * @param {any} lesson
 * @param {any} data
 * @param {{contents?: any}} [options]
 */
export async function readEnvelopeResolved(lesson, data, { contents } = {}) {
  return readEnvelope(lesson, await internalize(lesson, data, contents));
}

/**
 * @param {any} lesson
 * @param {any} state
 * @param {{contents?: any}} [options]
 */
export async function encodeState(lesson, state, { contents } = {}) {
  const { state: written } = await externalize(lesson, state, contents);
  return compressEnvelope(lesson, written);
}

// The link code of a state already externalized.
export async function compressEnvelope(lesson, state) {
  return packText(stringifyExact(envelope(lesson, state)));
}

// Checks and upgrades a parsed envelope. Returns { state, problems } (problems: sentences);
// throws an Error whose message is one sentence when nothing of it can be used.
export function readEnvelope(lesson, data) {
  if (data === null || typeof data !== 'object' || Array.isArray(data)) throw new Error('it does not hold a lesson state');
  // Before anything walks it (migrations, validators, copies): at most MAX_NESTING levels.
  const tooDeep = nestingProblem(data);
  if (tooDeep) throw new Error(tooDeep);
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

/**
 * @param {any} lesson
 * @param {string} text
 * @param {{contents?: any}} [options]
 */
export async function decodeState(lesson, text, { contents } = {}) {
  if (typeof text !== 'string' || text.length === 0) throw new Error('it is empty');
  if (text.length > MAX_LINK_CHARS) throw new Error('it is far longer than any lesson state');
  const json = await unpackText(text, MAX_STATE_BYTES);
  let data;
  try {
    data = JSON.parse(json);
  } catch {
    throw new Error('it is damaged (its contents are not valid JSON)');
  }
  return readEnvelopeResolved(lesson, data, { contents });
}

// ------------------------------------------------------------------ embed
// The embed parameters of a link's fragment, beside the state (docs/embed.md):
//   lesson.html#embed=1&s=<code>[&panels=<id>,<id>][&theme=light|dark][&present=1][&controls=1]
// `embed` present: the page is an embed (a value other than 1 is said, and the page is still
// an embed, so a mistyped flag never turns a frame into the full app writing over the
// person's saved work). Every other parameter is checked like the state: a value that is not
// understood is named in one sentence and left out; the lesson opens with the rest.
export const EMBED_MAX_PANELS = 12;
const PANEL_ID = /^[a-z][a-z0-9-]{0,39}$/;
const EMBED_THEMES = ['light', 'dark'];
// A value from a link, quoted for a message: shown as text only, cut to a few words.
const quoted = (value) => JSON.stringify(value.length > 24 ? `${value.slice(0, 24)}…` : value);

// Resolves a fragment ('#embed=1&s=...', with or without '#') to null (not an embed) or
// { panels: [ids], theme: 'light'|'dark'|null, present, controls, problems: [sentences] }.
export function readEmbedOptions(hash) {
  const params = new URLSearchParams(String(hash ?? '').replace(/^#/, ''));
  if (!params.has('embed')) return null;
  const problems = [];
  const flag = (name) => {
    if (!params.has(name)) return false;
    const value = params.get(name);
    if (value === '1') return true;
    problems.push(`${name}=${quoted(value)} is not understood (${name}=1 turns it on)`);
    return false;
  };
  flag('embed');
  const present = flag('present');
  const controls = flag('controls');
  let theme = null;
  if (params.has('theme')) {
    const value = params.get('theme');
    if (EMBED_THEMES.includes(value)) theme = value;
    else problems.push(`theme=${quoted(value)} is not light or dark, so the usual theme is used`);
  }
  const panels = [];
  if (params.has('panels')) {
    for (const id of params.get('panels').split(',').filter((x) => x !== '')) {
      if (!PANEL_ID.test(id)) problems.push(`panels lists ${quoted(id)}, which is not a panel name`);
      else if (panels.length >= EMBED_MAX_PANELS) problems.push(`panels lists more than ${EMBED_MAX_PANELS} panels`);
      else if (!panels.includes(id)) panels.push(id);
    }
  }
  return { panels, theme, present, controls, problems: [...new Set(problems)] };
}

// The one line an embed says about parameters it could not use (null when all were fine).
export function embedProblemsText(problems) {
  if (!problems.length) return null;
  if (problems.length === 1) return `This embed link's ${problems[0]}; the lesson opens without it.`;
  const names = [...new Set(problems.map((p) => p.match(/^[a-z]+/)?.[0] ?? 'setting'))];
  return `This embed link's ${names.join(', ')} settings were not understood (${problems[0]}); the lesson opens without them.`;
}

// The link of an embed: the lesson's page with embed=1 before the state (the link code of
// `shareUrl`), and the iframe snippet that holds it (attribute values escaped).
export function embedUrl(shareUrl) {
  const url = new URL(shareUrl);
  const code = new URLSearchParams(url.hash.slice(1)).get('s');
  url.hash = code ? `embed=1&s=${code}` : 'embed=1';
  return url.href;
}
const escapeAttribute = (text) => String(text).replace(/[&"<>]/g, (c) => ({ '&': '&amp;', '"': '&quot;', '<': '&lt;', '>': '&gt;' })[c]);
export function embedSnippet(src, title) {
  return `<iframe src="${escapeAttribute(src)}" width="800" height="500" title="${escapeAttribute(`${title} (Wingspline)`)}" loading="lazy" style="border:0"></iframe>`;
}
