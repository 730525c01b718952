// @ts-check
// The person's saved work of one lesson, in local storage under `wingspline:<lesson>:state`
// (docs/state-format.md, "Saved work and its revision"):
//
//   {"v":2,"rev":7,"tab":"t-1k2…","at":1764250000000,"drawing":"d-…","summary":"…","code":"<link code>"}
//
// `rev` counts the saves of that lesson in this browser: a tab writes only over the revision
// it last read (persist.js); `drawing` is a hash of the state without its view, so a change
// of the view alone is told from an edit; `json` (the envelope's JSON text) replaces `code`
// when the tab wrote it synchronously as it went away (compression is asynchronous);
// `setAside` {"tab","rev"} names the save this one replaced from another tab (that tab says
// so, with one click to bring its work back). A value that is not a record is a link code
// written before revisions: revision 0.
import { decodeState, readEnvelopeResolved, unpackText, MAX_LINK_CHARS, MAX_STATE_BYTES } from './share-link.js';

export const RECORD_VERSION = 2;
export const storageKey = (lessonId) => `wingspline:${lessonId}:state`;
const CONTENT_REF = /"\$content":"(sha256-[0-9a-f]{64})"/g;

/** Local storage, or null where the browser refuses it (reading may still work). */
export function localStore() {
  try {
    return window.localStorage ?? null;
  } catch {
    return null;
  }
}

/**
 * The record of a lesson's saved work: null when there is none; `{ unreadable: raw }`-style
 * records are never returned: a value that is neither a record nor a code is read as a code
 * (and refused by the reader with its own sentence).
 * @returns {null | { rev: number, tab: string | null, at: number | null, drawing: string | null, summary: string | null, code?: string, json?: string, setAside?: { tab: string, rev: number } | null, raw: string }}
 */
export function readRecord(storage, lessonId) {
  let raw = null;
  try {
    raw = storage?.getItem(storageKey(lessonId)) ?? null;
  } catch {
    raw = null;
  }
  return parseRecord(raw);
}

export function parseRecord(raw) {
  if (raw === null || raw === '') return null;
  if (raw[0] !== '{') return { rev: 0, tab: null, at: null, drawing: null, summary: null, code: raw, raw };
  let r;
  try {
    r = JSON.parse(raw);
  } catch {
    r = null;
  }
  const text = (x, max = 200) => (typeof x === 'string' ? x.slice(0, max) : null);
  if (!r || typeof r !== 'object' || !Number.isSafeInteger(r.rev) || r.rev < 0 || (typeof r.code !== 'string' && typeof r.json !== 'string')) {
    // Not ours to read (a damaged or a future record): the reader refuses it and it is kept
    // aside before anything is written over it.
    return { rev: Number.isSafeInteger(r?.rev) && r.rev >= 0 ? r.rev : 0, tab: null, at: null, drawing: null, summary: null, code: raw, raw };
  }
  const setAside = r.setAside && typeof r.setAside.tab === 'string' && Number.isSafeInteger(r.setAside.rev) ? { tab: r.setAside.tab, rev: r.setAside.rev } : null;
  return {
    rev: r.rev, tab: text(r.tab, 64), at: Number.isFinite(r.at) ? r.at : null, drawing: text(r.drawing, 64), summary: text(r.summary),
    ...(typeof r.code === 'string' ? { code: r.code } : { json: r.json }), setAside, raw,
  };
}

/** Writes a record (throws when storage refuses it: full, disabled). */
/**
 * @param {Storage} storage
 * @param {string} lessonId
 * @param {{rev: number, tab: string, drawing: string, summary: string, code?: string, json?: string, setAside?: {tab: string, rev: number}|null}} record
 */
export function writeRecord(storage, lessonId, { rev, tab, drawing, summary, code, json, setAside = null }) {
  const record = { v: RECORD_VERSION, rev, tab, at: Date.now(), drawing, summary, ...(code !== undefined ? { code } : { json }), ...(setAside ? { setAside } : {}) };
  const raw = JSON.stringify(record);
  storage.setItem(storageKey(lessonId), raw);
  return parseRecord(raw);
}

/** The state a record holds: { state, problems }, or throws an Error of one sentence. */
/**
 * @param {any} lesson
 * @param {any} record
 * @param {{contents?: any}} [options]
 */
export async function decodeRecord(lesson, record, { contents } = {}) {
  if (record.code !== undefined) return decodeState(lesson, record.code, { contents });
  if (record.json.length > MAX_STATE_BYTES) throw new Error('it is far longer than any lesson state');
  let data;
  try {
    data = JSON.parse(record.json);
  } catch {
    throw new Error('it is damaged (its contents are not valid JSON)');
  }
  return readEnvelopeResolved(lesson, data, { contents });
}

/** The envelope's JSON text of a record (or of a bare code), for the content references in it. */
export async function recordText(record) {
  if (record.json !== undefined) return record.json;
  if (record.code.length > MAX_LINK_CHARS) return '';
  try {
    return await unpackText(record.code, MAX_STATE_BYTES);
  } catch {
    return '';
  }
}

/** The content hashes (imported meshes) a record's state refers to. */
export async function recordRefs(record) {
  return [...new Set([...(await recordText(record)).matchAll(CONTENT_REF)].map((m) => m[1]))];
}

/**
 * A short, synchronous hash of a text (53-bit, cyrb53): tells two drawings apart, nothing
 * more (not for security).
 */
export function textHash(s) {
  let h1 = 0xdeadbeef;
  let h2 = 0x41c6ce57;
  for (let i = 0; i < s.length; i += 1) {
    const c = s.charCodeAt(i);
    h1 = Math.imul(h1 ^ c, 2654435761);
    h2 = Math.imul(h2 ^ c, 1597334677);
  }
  h1 = Math.imul(h1 ^ (h1 >>> 16), 2246822507) ^ Math.imul(h2 ^ (h2 >>> 13), 3266489909);
  h2 = Math.imul(h2 ^ (h2 >>> 16), 2246822507) ^ Math.imul(h1 ^ (h1 >>> 13), 3266489909);
  return `d-${(4294967296 * (2097151 & h2) + (h1 >>> 0)).toString(36)}`;
}

/** Every lesson id that has saved work in this storage. */
export function savedLessons(storage) {
  const ids = [];
  try {
    for (let i = 0; i < (storage?.length ?? 0); i += 1) {
      const m = /^wingspline:([a-z][a-z0-9-]{0,39}):state$/.exec(storage.key(i) ?? '');
      if (m) ids.push(m[1]);
    }
  } catch {
    // storage disabled
  }
  return ids;
}
