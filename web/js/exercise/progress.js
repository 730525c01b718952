// @ts-check
// Progress kept in this browser: per exercise, whether it was solved, how many
// checks it took, the answer as last typed and, for the kinds where the drawing is the answer,
// the lesson state. Keyed by the exercise: a shipped one by its id, any other by a hash of
// its text, so two different exercises never share an entry. An entry this page cannot read
// is set aside for the History (never written over) and the exercise starts fresh. A page
// shown inside another page's frame reads and writes no progress (nor any saved work).
import { stringifyExact, sha256 } from '../app/share-link.js';
import { isFramed } from '../app/persist.js';
import { setAsideNow } from '../app/work-history.js';
import { checkNesting } from '../app/schema.js';

const PREFIX = 'wingspline:exercise:';
const PROGRESS_VERSION = 1;

function storage() {
  try {
    return isFramed() ? null : window.localStorage;
  } catch {
    return null;
  }
}

/** The key of an exercise's progress: 'site:<id>' for a shipped one, 'x:<hash>' otherwise. */
export async function progressKey(exercise, { shipped }) {
  if (shipped) return `site:${exercise.id}`;
  return `x:${(await sha256(stringifyExact(exercise))).slice(7, 7 + 24)}`;
}

/**
 * What a page records of an attempt. `id`, `hash` (the exercise's content hash) and `kind` say
 * which exercise it was, for a submission file; entries saved before they existed lack them.
 * @typedef {{ version: number, status: 'started' | 'solved', checks: number, answer: any, state: any, solvedAt: string | null, title: string, lesson: string,
 *   id?: string | null, hash?: string | null, kind?: string, feedback?: string, sawWorked?: boolean, hintsShown?: number }} Progress
 */

function parse(raw) {
  const p = JSON.parse(raw);
  checkNesting(p, 'progress'); // an entry nested past MAX_NESTING levels is unreadable
  if (!p || typeof p !== 'object' || p.version !== PROGRESS_VERSION || !['started', 'solved'].includes(p.status) || !Number.isSafeInteger(p.checks)) throw new Error('shape');
  return p;
}

function readRaw(key) {
  try {
    return storage()?.getItem(PREFIX + key) ?? null;
  } catch {
    return null;
  }
}

/**
 * Reads an exercise's progress. An entry that cannot be read is set aside for the History
 * (work-history.js: a key of its own, never over an earlier one) and the exercise starts fresh.
 * @param {string} key
 * @param {{ lesson?: string }} [options] the exercise's lesson, whose History lists the entry
 * @returns {{ progress: Progress | null, problem: string | null, stuck?: boolean }}
 */
export function readProgress(key, { lesson = 'exercise' } = {}) {
  const raw = readRaw(key);
  if (raw === null) return { progress: null, problem: null };
  try {
    return { progress: parse(raw), problem: null };
  } catch {
    const store = storage();
    if (!setAsideNow(store, { lesson, reason: 'unreadable', summary: 'exercise progress this version could not read', raw })) {
      // storage refuses: the entry stays as it is and is not written over (see writeProgress)
      return { progress: null, stuck: true, problem: 'Your earlier progress on this exercise could not be read; it is kept as it was, and this attempt is not saved.' };
    }
    try {
      store?.removeItem(PREFIX + key);
    } catch {
      // (set aside already: the next write replaces it)
    }
    return { progress: null, problem: 'Your earlier progress on this exercise could not be read; it is kept in the History as it was, and the exercise starts fresh.' };
  }
}

/** An exercise's status without changing anything (the gallery): null when none or unreadable. */
export function peekStatus(key) {
  const raw = readRaw(key);
  if (raw === null) return null;
  try {
    return parse(raw).status;
  } catch {
    return null;
  }
}

/** @returns {boolean} whether it was kept */
export function writeProgress(key, progress) {
  if (!storage()) return false;
  try {
    // An entry that could not be read nor moved aside is never written over.
    const raw = readRaw(key);
    if (raw !== null) {
      try { parse(raw); } catch { return false; }
    }
    storage()?.setItem(PREFIX + key, JSON.stringify({ ...progress, version: PROGRESS_VERSION }));
    return true;
  } catch {
    return false;
  }
}

export function clearProgress(key, { lesson = 'exercise', version = 1 } = {}) {
  try {
    // The attempt goes into the History first (a drawing as the lesson state it is).
    const raw = readRaw(key);
    if (raw !== null) {
      /** @type {{ raw?: string, json?: string }} */
      let entry = { raw };
      let summary = 'an exercise attempt';
      try {
        const p = parse(raw);
        summary = `your attempt at "${p.title}" (${p.checks} check${p.checks === 1 ? '' : 's'}${p.status === 'solved' ? ', solved' : ''})`;
        if (p.state && typeof p.state === 'object') entry = { json: JSON.stringify({ format: 'wingspline', lesson, version, state: p.state }) };
      } catch {
        // kept as it was
      }
      setAsideNow(storage(), { lesson, reason: 'exercise', summary, ...entry });
    }
    storage()?.removeItem(PREFIX + key);
  } catch {
    // nothing to do: storage disabled
  }
}

/** Every shipped exercise's status, for the gallery: { [id]: 'started' | 'solved' }. */
export function siteStatuses(ids) {
  const out = {};
  for (const id of ids) {
    const status = peekStatus(`site:${id}`);
    if (status) out[id] = status;
  }
  return out;
}

/**
 * Every exercise's progress kept in this browser, for a submission file (submission.js):
 * [{ key, progress }] in key order, entries that cannot be read left out (and left alone).
 * @returns {Array<{ key: string, progress: Progress }>}
 */
export function listProgress() {
  const store = storage();
  if (!store) return [];
  const out = [];
  try {
    for (let i = 0; i < store.length; i += 1) {
      const name = store.key(i);
      if (!name?.startsWith(PREFIX)) continue;
      try {
        out.push({ key: name.slice(PREFIX.length), progress: parse(store.getItem(name) ?? '') });
      } catch {
        // unreadable: the exercise's page sets it aside when it is opened
      }
    }
  } catch {
    return [];
  }
  return out.sort((a, b) => a.key.localeCompare(b.key));
}
