// @ts-check
// The history of the person's saved work, per lesson (docs/state-format.md, "The history"):
// every time saved work is replaced (a link opened, Reset, an import, an exercise's Start
// again, a restore from the history, another tab's later save) the work it replaced is kept
// here, with its time and a one-line summary, and one click brings it back. Saved work this
// version cannot read goes here too, as it was (never written over).
//
// Where: the `history` store of the IndexedDB database (idb.js), with the imported meshes
// the entries refer to kept in the content store; without IndexedDB (some private modes),
// local storage under `wingspline:history`, which keeps only entries without large imported
// meshes (the page says so). Work set aside while a page goes away (no time for IndexedDB)
// waits in local storage under `wingspline:aside:<time>-<random>` and is moved here on the
// next start of any lesson page.
//
// The budget, all lessons together: BUDGET_CHARS characters of text (the entries and the
// imported meshes only they refer to; the meshes saved work refers to count too, and are
// never dropped), at most MAX_PER_LESSON entries a lesson and MAX_ENTRIES in all; past it the
// oldest entries go first, and the meshes only they referred to with them.
import { localStore, recordRefs, savedLessons, readRecord, parseRecord } from './saved-record.js';
import { request, done } from './idb.js';

export const MAX_PER_LESSON = 40;
export const MAX_ENTRIES = 240;
export const BUDGET_CHARS = 100 * 2 ** 20;
// Local storage, without IndexedDB: what a few megabytes hold.
export const LOCAL_MAX_ENTRIES = 60;
export const LOCAL_MAX_ENTRY_CHARS = 100000;
export const LOCAL_BUDGET_CHARS = 2000000;

const LOCAL_KEY = 'wingspline:history';
// Entries of no one lesson (progress of an exercise whose lesson is unknown): listed with every lesson's.
export const EXERCISES = 'exercise';
const ASIDE_PREFIX = 'wingspline:aside:';
const REASONS = ['link', 'reset', 'import', 'restore', 'exercise', 'clash', 'other-tab', 'unreadable'];

/** What an entry's reason says in the History list. */
export const reasonText = {
  link: 'replaced by a link',
  reset: 'before Reset',
  import: 'replaced by an import',
  restore: 'replaced by a restore from the history',
  exercise: 'an exercise drawing, before Start again',
  clash: 'set aside by a later save in another tab',
  'other-tab': 'replaced by a later save in another tab',
  unreadable: 'kept as it was: save it as a file',
};

const entryText = (e) => e.code ?? e.json ?? e.raw ?? '';

/**
 * Work set aside synchronously (a page going away, an entry that cannot be read): kept in
 * local storage under a key of its own, never over another, until the next sweep.
 * @returns {boolean} whether it was kept
 */
export function setAsideNow(storage, entry) {
  if (!storage) return false;
  const key = `${ASIDE_PREFIX}${Date.now().toString(36)}-${Math.random().toString(36).slice(2, 10)}`;
  try {
    storage.setItem(key, JSON.stringify({ ...entry, time: entry.time ?? Date.now() }));
    return true;
  } catch {
    return false;
  }
}

/**
 * An entry as kept: its lesson, time, reason, summary, title, and one of code, json or raw.
 * @param {any} e
 * @returns {{lesson: string, time: number, reason: string, summary: string, title?: string, code?: string, json?: string, raw?: string} | null}
 */
function cleanEntry(e) {
  if (!e || typeof e !== 'object' || typeof e.lesson !== 'string' || !/^[a-z][a-z0-9-]{0,39}$/.test(e.lesson)) return null;
  const text = ['code', 'json', 'raw'].find((k) => typeof e[k] === 'string');
  if (!text) return null;
  return {
    lesson: e.lesson,
    time: Number.isFinite(e.time) ? e.time : Date.now(),
    reason: REASONS.includes(e.reason) ? e.reason : 'unreadable',
    summary: typeof e.summary === 'string' ? e.summary.slice(0, 200) : '',
    ...(typeof e.title === 'string' ? { title: e.title.slice(0, 120) } : {}),
    [text]: e[text],
  };
}

/**
 * @param {{ db: { open(): Promise<IDBDatabase> }, contents: any, storage?: Storage | null, budgetChars?: number }} parts
 */
export function createWorkHistory({ db, contents, storage = localStore(), budgetChars = BUDGET_CHARS }) {
  // 'indexeddb'; 'local' (a browser without IndexedDB: local storage); 'none' (no storage at
  // all); 'unavailable' (the database exists but cannot be opened now: nothing is moved or
  // kept elsewhere meanwhile, and the next call asks again).
  let modeAsked = null;
  function mode() {
    if (!modeAsked) {
      modeAsked = db.open().then(() => 'indexeddb', (err) => {
        modeAsked = null;
        if (err?.unavailable) return 'unavailable';
        return storage ? 'local' : 'none';
      });
    }
    return modeAsked;
  }
  const local = async () => ['local', 'none'].includes(await mode());

  // ------------------------------------------------------------ local storage (no IndexedDB)
  function readLocal() {
    try {
      const list = JSON.parse(storage?.getItem(LOCAL_KEY) ?? '[]');
      return Array.isArray(list) ? list.filter((e) => cleanEntry(e) && Number.isSafeInteger(e.id)) : [];
    } catch {
      return [];
    }
  }
  function writeLocal(list) {
    // Newest first, within the local budget; the oldest go when storage refuses.
    list.sort((a, b) => b.time - a.time);
    const perLesson = new Map();
    let chars = 0;
    let kept = list.filter((e) => {
      const n = (perLesson.get(e.lesson) ?? 0) + 1;
      perLesson.set(e.lesson, n);
      chars += entryText(e).length;
      return n <= MAX_PER_LESSON && chars <= LOCAL_BUDGET_CHARS;
    }).slice(0, LOCAL_MAX_ENTRIES);
    for (;;) {
      try {
        if (kept.length) storage?.setItem(LOCAL_KEY, JSON.stringify(kept)); else storage?.removeItem(LOCAL_KEY);
        return kept;
      } catch {
        if (!kept.length) return kept;
        kept = kept.slice(0, -1);
      }
    }
  }

  // ------------------------------------------------------------ IndexedDB
  async function allEntries(idb) {
    return request(idb.transaction('history').objectStore('history').getAll());
  }

  // The hashes saved work (every lesson's, in local storage) refers to.
  async function savedRefs() {
    const refs = new Set();
    for (const id of savedLessons(storage)) {
      const record = readRecord(storage, id);
      if (record) for (const h of await recordRefs(record)) refs.add(h);
    }
    // Work set aside and not yet swept into the history.
    for (const key of asideKeys()) {
      try {
        const e = JSON.parse(storage?.getItem(key) ?? 'null');
        const rec = typeof e?.code === 'string' ? { code: e.code } : typeof e?.json === 'string' ? { json: e.json } : parseRecord(typeof e?.raw === 'string' ? e.raw : null);
        if (rec) for (const h of await recordRefs(rec)) refs.add(h);
      } catch {
        // not ours to read: nothing it refers to is known
      }
    }
    return refs;
  }
  function asideKeys() {
    const keys = [];
    try {
      for (let i = 0; i < (storage?.length ?? 0); i += 1) {
        const key = storage?.key(i) ?? '';
        if (key.startsWith(ASIDE_PREFIX)) keys.push(key);
      }
    } catch {
      // storage disabled
    }
    return keys;
  }

  const history = {
    mode,
    /** The hashes that saved work and the history refer to (the content store keeps them). */
    async referenced() {
      const refs = await savedRefs();
      if (await mode() !== 'indexeddb') throw new Error('the history cannot be read now'); // (nothing is dropped)
      for (const e of await allEntries(await db.open())) for (const h of e.refs ?? []) refs.add(h);
      return refs;
    },

    /**
     * Keeps an entry: { lesson, reason, summary, code | json | raw }. The same text of the same
     * lesson is kept once (its time renewed). Resolves to the entry's id, or null when it could
     * not be kept (no IndexedDB and too big for local storage, storage refused).
     */
    async add(raw, { prune = true } = {}) {
      const entry = cleanEntry({ ...raw, time: raw.time ?? Date.now() });
      if (!entry) return null;
      const text = entryText(entry);
      const where = await mode();
      if (where === 'unavailable') return null;
      if (where !== 'indexeddb') {
        if (text.length > LOCAL_MAX_ENTRY_CHARS) return null;
        const list = readLocal();
        const same = list.find((e) => e.lesson === entry.lesson && entryText(e) === text);
        const id = same?.id ?? list.reduce((m, e) => Math.max(m, e.id), 0) + 1;
        const kept = writeLocal([...list.filter((e) => e !== same), { ...entry, id }]);
        return kept.some((e) => e.id === id) ? id : null;
      }
      // (raw: saved work this version could not read; the meshes it names are kept with it)
      const refs = await recordRefs(entry.raw !== undefined ? parseRecord(entry.raw) ?? { code: '' } : entry);
      const idb = await db.open();
      const tx = idb.transaction('history', 'readwrite');
      const store = tx.objectStore('history');
      const same = (await request(store.index('lesson').getAll(entry.lesson))).find((e) => entryText(e) === text);
      const id = await request(store.put({ ...entry, refs, chars: text.length, ...(same ? { id: same.id } : {}) }));
      await done(tx);
      if (prune) await history.prune().catch(() => {});
      return /** @type {number} */ (id);
    },

    /** A lesson's entries, newest first. */
    async list(lessonId) {
      const mine = (e) => e.lesson === lessonId || e.lesson === EXERCISES;
      if (await mode() === 'unavailable') return [];
      if (await local()) return readLocal().filter(mine).sort((a, b) => b.time - a.time);
      const idb = await db.open();
      const index = idb.transaction('history').objectStore('history').index('lesson');
      const list = [...await request(index.getAll(lessonId)), ...(lessonId === EXERCISES ? [] : await request(index.getAll(EXERCISES)))];
      return list.sort((a, b) => b.time - a.time || b.id - a.id);
    },

    async get(id) {
      if (await local()) return readLocal().find((e) => e.id === id) ?? null;
      const idb = await db.open();
      return (await request(idb.transaction('history').objectStore('history').get(id))) ?? null;
    },

    /** Keeps the budget (see the top of this file); resolves to the ids dropped. */
    async prune() {
      if (await mode() !== 'indexeddb') return [];
      // The saved work first: a replacement writes its history entry before its record, so an
      // entry read after the records cannot miss a mesh both refer to.
      const counted = await savedRefs();
      const idb = await db.open();
      const entries = (await allEntries(idb)).sort((a, b) => b.time - a.time || b.id - a.id);
      const sizes = await contents.sizes();
      let used = [...counted].reduce((sum, h) => sum + (sizes.get(h) ?? 0), 0);
      const perLesson = new Map();
      const kept = new Set(counted);
      const drop = [];
      let keptCount = 0;
      for (const e of entries) {
        const n = (perLesson.get(e.lesson) ?? 0) + 1;
        const fresh = (e.refs ?? []).filter((h) => !kept.has(h));
        const extra = (e.chars ?? entryText(e).length) + fresh.reduce((sum, h) => sum + (sizes.get(h) ?? 0), 0);
        if (n > MAX_PER_LESSON || keptCount >= MAX_ENTRIES || used + extra > budgetChars) {
          drop.push(e.id);
          continue;
        }
        perLesson.set(e.lesson, n);
        keptCount += 1;
        used += extra;
        for (const h of fresh) kept.add(h);
      }
      if (drop.length) {
        const tx = idb.transaction('history', 'readwrite');
        for (const id of drop) tx.objectStore('history').delete(id);
        await done(tx);
      }
      await contents.collect(kept).catch(() => {});
      return drop;
    },

    /**
     * Moves what was set aside synchronously (and the unreadable entries of earlier versions)
     * into the history; each is removed from local storage only once kept. Resolves to the
     * number moved.
     */
    async sweep() {
      if (!storage || await mode() === 'unavailable') return 0;
      const keys = [];
      try {
        for (let i = 0; i < storage.length; i += 1) {
          const key = storage.key(i) ?? '';
          if (key.startsWith(ASIDE_PREFIX) || /^wingspline:[a-z][a-z0-9-]{0,39}:unreadable$/.test(key) || /^wingspline:exercise:.+:unreadable-\d+$/.test(key)) keys.push(key);
        }
      } catch {
        return 0;
      }
      let moved = 0;
      for (const key of keys) {
        const value = storage.getItem(key);
        if (value === null) continue;
        let entry;
        if (key.startsWith(ASIDE_PREFIX)) {
          try { entry = JSON.parse(value); } catch { entry = { lesson: EXERCISES, reason: 'unreadable', raw: value }; }
        } else if (key.startsWith('wingspline:exercise:')) {
          // A shipped exercise's id starts with its lesson's (mesh-walk-around-v2).
          const site = /^wingspline:exercise:site:([a-z][a-z0-9]*)-/.exec(key);
          entry = { lesson: site ? site[1] : EXERCISES, reason: 'unreadable', summary: 'exercise progress this version could not read', raw: value };
        } else {
          entry = { lesson: key.split(':')[1], reason: 'unreadable', summary: 'saved work an earlier version could not read', raw: value };
        }
        const id = await history.add(entry, { prune: false }).catch(() => null);
        if (id !== null) {
          storage.removeItem(key);
          moved += 1;
        }
      }
      if (moved) await history.prune().catch(() => {});
      return moved;
    },

    /** Forget my work on this computer: the history, every lesson's saved work, the progress. */
    async forgetAll() {
      const where = await mode();
      if (where === 'unavailable') throw new Error('this site\'s storage in this browser cannot be opened now (close other Wingspline tabs, reload, and try again)');
      if (where === 'indexeddb') {
        const idb = await db.open();
        const tx = idb.transaction('history', 'readwrite');
        tx.objectStore('history').clear();
        await done(tx);
        await contents.clear();
      }
      const keys = [];
      for (let i = 0; i < (storage?.length ?? 0); i += 1) {
        const key = storage?.key(i) ?? '';
        // The theme is a setting of the browser, not work.
        if (key.startsWith('wingspline:') && key !== 'wingspline:theme') keys.push(key);
      }
      for (const key of keys) storage?.removeItem(key);
    },
  };
  return history;
}
