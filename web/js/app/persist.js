// @ts-check
// Keeps a lesson's state in the page URL (#s=...) and in local storage, and restores it.
// The URL is updated with replaceState, so the back button undoes navigation, not edits.
// Large fields (an imported mesh) are kept in IndexedDB by content hash and the link refers
// to them (share-link.js, content-store.js). docs/state-format.md describes the formats,
// docs/classroom.md the rules below as a person meets them.
//
// Nothing saved is lost:
// - A link that cannot be used shows the saved work instead; a link that can replaces it as
//   one undoable step, and the replaced work goes into the history (work-history.js), as
//   it does for Reset, an import, a restore and a clash between tabs.
// - Saved work this page cannot read is set aside into the history, as it was, before
//   anything is written over it.
// - Tabs: each save carries a revision (saved-record.js); a tab writes only over the
//   revision it last read. A tab that notices a later save of another tab (storage events,
//   and again when it is shown) takes it, unless it has an edit of its own not yet saved; a
//   change of the view alone (pan, zoom) never writes over a later drawing. When two tabs
//   edited the same revision, the later save is the current work, the earlier goes into the
//   history, and the tab whose work was set aside says so, with one click to bring it back.
// - A tab closed right after an edit: the edit not yet written is written to local storage
//   synchronously on pagehide (as JSON: compression is asynchronous), by the same rule.
// - A page shown inside another page's frame, and an embed, read and write nothing of it.
// - A state the reader would refuse (longer than a link may be: an imported mesh kept inline
//   where IndexedDB is missing) is never saved: the earlier work stays, and the page says so.
import { decodeState, externalize, externalizeKnown, compressEnvelope, envelope, stringifyExact, MAX_LINK_CHARS } from './share-link.js';
import { localStore, readRecord, writeRecord, decodeRecord, storageKey, textHash } from './saved-record.js';

// The content hashes a state (as written to a link) refers to.
const contentRefsOf = (written) => Object.values(written ?? {})
  .filter((v) => v && typeof v === 'object' && !Array.isArray(v) && typeof v.$content === 'string').map((v) => v.$content);
import { setAsideNow } from './work-history.js';

const legacyPendingKey = (lesson) => `wingspline:${lesson.id}:pending`;
// The longest JSON text written as a page goes away (a link code is about a third as long).
const PAGEHIDE_MAX_CHARS = 2 * MAX_LINK_CHARS;
// The link codes this tab last put in its address bar (session storage survives a reload of
// the tab): an address that is this tab's own is not a link to open over newer saved work.
// Several, not the last one only: a reload starts from the address it was asked at, and a
// write under way may put (and keep) a newer code before the page goes away. Seen in CI at
// load 13: the reload opened the previous code as a link over the edit just saved.
const ownCodeKey = (lesson) => `wingspline:${lesson.id}:own-code`;
const OWN_CODES = 8;
function ownCodes(lesson) {
  try {
    const text = sessionStore()?.getItem(ownCodeKey(lesson)) ?? null;
    if (text === null) return [];
    // An earlier build kept one code as it was.
    const list = text.startsWith('[') ? JSON.parse(text) : [text];
    return Array.isArray(list) ? list.filter((c) => typeof c === 'string') : [];
  } catch {
    return [];
  }
}
function addOwnCode(lesson, code) {
  try {
    const list = [code, ...ownCodes(lesson).filter((c) => c !== code)].slice(0, OWN_CODES);
    sessionStore()?.setItem(ownCodeKey(lesson), JSON.stringify(list));
  } catch {
    // storage disabled
  }
}

function sessionStore() {
  try {
    return window.sessionStorage;
  } catch {
    return null;
  }
}

/** Whether this page is shown inside another page (a frame of any origin). */
export function isFramed() {
  try {
    return window.self !== window.top;
  } catch {
    return true;
  }
}

export function readHashCode(hash = window.location.hash) {
  const params = new URLSearchParams(hash.slice(1));
  return params.get('s');
}

// The drawing of a state: its text without the view (pan and zoom), as a short hash.
function drawingOf(lesson, written) {
  const { view, ...drawing } = written ?? {};
  return textHash(stringifyExact(envelope(lesson, drawing)));
}

// A pending edit left in session storage by a page of an earlier version as it went away
// (it belongs to the address it was made at).
async function takeLegacyPending(lesson, code, contents) {
  const session = sessionStore();
  const raw = session?.getItem(legacyPendingKey(lesson));
  if (!raw) return null;
  session.removeItem(legacyPendingKey(lesson));
  try {
    const record = JSON.parse(raw);
    if (record?.fromCode !== code) return null;
    const { state, problems } = await decodeRecord(lesson, { json: record.json });
    return problems.length ? null : state;
  } catch {
    return null;
  }
}

const sameState = (a, b) => {
  try {
    return stringifyExact(a) === stringifyExact(b);
  } catch {
    return false;
  }
};

/**
 * Saved work this page cannot read (made by a newer Wingspline, its mesh gone from this
 * browser): set aside as it was, for the history, before anything is written over it.
 */
function keepAside(lesson, storage, record, why) {
  if (!record) return true;
  return setAsideNow(storage, { lesson: lesson.id, reason: 'unreadable', summary: `saved work this version could not read: ${why}`.slice(0, 200), raw: record.raw });
}

// Resolves to { state, source: 'link'|'storage'|'default', problem, previous, base }.
// `previous`: the saved work a link replaced (undo returns to it), or null. `base`: the
// revision read, for the persister.
/**
 * @param {any} lesson
 * @param {{contents?: any}} [options] the content store that resolves mesh references
 */
export async function restoreState(lesson, { contents } = {}) {
  const code = readHashCode();
  const storage = localStore();
  const record = readRecord(storage, lesson.id);
  const base = { rev: record?.rev ?? 0, drawing: record?.drawing ?? null };
  const legacy = await takeLegacyPending(lesson, code, contents);
  if (legacy) return { state: legacy, source: code === null ? 'storage' : 'link', problem: null, previous: null, base };

  let saved = null;
  let savedError = null;
  if (record) {
    try {
      saved = await decodeRecord(lesson, record, { contents });
    } catch (err) {
      // Saved work that cannot be read now (its mesh's database held by another page), or
      // that cannot be set aside: shown as the starting point, and this page saves nothing
      // until it is reloaded, so the work stays as it is.
      if (err.unavailable || !keepAside(lesson, storage, record, err.message)) {
        return { state: lesson.defaultState(), source: 'default', hold: true, previous: null, base,
          problem: `Your saved work cannot be read now (${err.message}); it is left as it was, and this page saves nothing until it is reloaded.` };
      }
      savedError = err.message;
    }
  }
  const savedProblem = savedError
    ? `Your saved work could not be read (${savedError}); it is kept in the History as it was`
    : saved?.problems.length ? `Part of your saved work was reset (${saved.problems[0]})` : null;

  // This tab's own address (a reload) or the saved work's own link is not a link to open.
  const own = code !== null && (code === record?.code || ownCodes(lesson).includes(code));
  if (code !== null && !own) {
    try {
      const { state, problems } = await decodeState(lesson, code, { contents });
      const previous = saved && !sameState(saved.state, state) ? saved.state : null;
      return {
        state,
        source: 'link',
        problem: problems.length ? `Part of this link was not usable (${problems[0]}); that part was reset.` : null,
        previous,
        base,
      };
    } catch (err) {
      if (saved) {
        return { state: saved.state, source: 'storage', problem: `This share link could not be used: ${err.message}. Showing your saved work instead.`, previous: null, base };
      }
      return { state: lesson.defaultState(), source: 'default', problem: `This share link could not be used: ${err.message}. Showing the lesson's starting point instead.`, previous: null, base };
    }
  }
  if (saved) return { state: saved.state, source: 'storage', problem: savedProblem ? `${savedProblem}.` : null, previous: null, base };
  if (savedError) return { state: lesson.defaultState(), source: 'default', problem: `${savedProblem}; starting fresh.`, previous: null, base };
  return { state: lesson.defaultState(), source: 'default', problem: null, previous: null, base };
}

// An embed (docs/embed.md), or a page framed by another page, shows its link's state, or
// the lesson's starting point when the link cannot be used, and reads nothing of the
// person's saved work (nor moves anything aside): it never touches that work.
/**
 * @param {any} lesson
 * @param {{contents?: any}} [options]
 */
export async function restoreLinkOnly(lesson, { contents } = {}) {
  const code = readHashCode();
  const base = { rev: 0, drawing: null };
  if (code === null) return { state: lesson.defaultState(), source: 'default', problem: null, previous: null, base };
  try {
    const { state, problem } = await readLink(lesson, code, { contents });
    return { state, source: 'link', problem, previous: null, base };
  } catch (err) {
    return { state: lesson.defaultState(), source: 'default', problem: `This share link could not be used: ${err.message}. Showing the lesson's starting point instead.`, previous: null, base };
  }
}

// Decodes a link pasted into the address bar of the open page (hashchange): resolves to
// { state, problem } or rejects with an Error of one sentence.
/**
 * @param {any} lesson
 * @param {string} code
 * @param {{contents?: any}} [options]
 */
export async function readLink(lesson, code, { contents } = {}) {
  const { state, problems } = await decodeState(lesson, code, { contents });
  return { state, problem: problems.length ? `Part of this link was not usable (${problems[0]}); that part was reset.` : null };
}

// Navigator locks, where the browser has them: one tab at a time reads and writes a lesson's
// record (local storage has no compare-and-set of its own).
function withLock(name, fn) {
  const locks = /** @type {any} */ (globalThis.navigator)?.locks;
  return locks?.request ? locks.request(name, fn) : fn();
}

/**
 * Returns a persister: save(state, { replacing }) writes URL and storage, debounced.
 * notify(kind, detail) is called once per kind when something cannot be kept:
 * 'storage-full' (local storage refuses the state: the link still holds it),
 * 'content-not-stored' (a large field could not be put in IndexedDB) and 'too-long' (the
 * state is longer than a link may be: it is not saved, the earlier work stays).
 * otherTab(record, { setAside }) is called when another tab saved later work and this tab
 * has nothing of its own waiting (the shell shows it; `setAside`: this tab's work was the
 * one replaced).
 * keep: false (an embed, a framed page, an exercise): nothing is written, neither the
 * address bar nor local storage; shareLink still makes the full lesson's link.
 * @param {any} lesson
 * @param {{ delayMs?: number, contents?: any, history?: any, notify?: (kind: string, detail?: any) => void, keep?: boolean,
 *   base?: { rev: number, drawing: string | null }, saved?: any, summarize?: (state: any) => string, otherTab?: (record: any, info: { setAside: boolean }) => void }} options
 */
export function createPersister(lesson, {
  delayMs = 200, contents = null, history = null, notify = () => {}, keep = true,
  base = { rev: 0, drawing: null }, saved = null, summarize = () => '', otherTab = () => {},
} = {}) {
  const tab = `t-${Date.now().toString(36)}-${Math.random().toString(36).slice(2, 10)}`;
  const lockName = `wingspline:${lesson.id}:save`;
  let timer = null;
  let pending = null;
  let replacing = null; // why the next write replaces the saved work (it goes into the history)
  let inflightState = null; // taken by a write that has not reached storage yet
  let inflightWhy = null; // and why it replaces the saved work, if it does
  let syncWrites = 0; // records written on pagehide: a write under way since then is older
  let lastCode = readHashCode();
  let adopted = null; // a state taken from another tab: already saved, not written again
  let readRev = base.rev; // the revision of the saved work this tab last read or wrote
  let readDrawing = base.drawing;
  let savedState = saved; // the state object known to be the saved work: never written again
  const storage = localStore();
  const said = new Set();
  const sayOnce = (kind, detail) => {
    if (said.has(kind)) return;
    said.add(kind);
    notify(kind, detail);
  };
  const summaryOf = (state) => {
    try {
      return String(summarize(state) ?? '').slice(0, 200);
    } catch {
      return '';
    }
  };

  // The history entry of `record` (the saved work about to be replaced).
  const entryOf = (record, reason) => ({ lesson: lesson.id, reason, summary: record.summary ?? 'saved work', time: record.at ?? Date.now(), ...(record.code !== undefined ? { code: record.code } : { json: record.json }) });

  // Keeps `record` in the history (or, where it cannot be reached now, set aside for it).
  async function keepInHistory(record, reason) {
    const entry = entryOf(record, reason);
    const id = history ? await history.add(entry, { prune: false }).catch(() => null) : null;
    if (id === null && !setAsideNow(storage, entry)) return false;
    return true;
  }

  // The rule of tabs, shared by the asynchronous write and the one on pagehide: what to do
  // with the saved record `now` when this tab writes a state whose drawing is `drawing`.
  function decide(now, drawing) {
    const stale = (now?.rev ?? 0) !== readRev;
    if (!stale) return { write: true, clash: false };
    // Only the view changed here since the saved work was read: never rewrite a later drawing.
    if (drawing === readDrawing) return { write: now?.drawing === drawing, clash: false, take: now?.drawing !== drawing };
    if (now?.drawing === drawing) return { write: true, clash: false };
    return { write: true, clash: true };
  }

  // Synchronous last word before the page goes away (reload, navigation, tab closed): the
  // edit not yet written reaches local storage, as JSON, under the same rule.
  function keepPending() {
    const state = pending ?? inflightState;
    if (!keep || !state || state === savedState) return;
    try {
      let written = externalizeKnown(lesson, state);
      // A reference to a mesh this page has not seen stored (IndexedDB refused it) would
      // name nothing on the next visit: such a state is written whole, or not at all.
      if (contentRefsOf(written).some((h) => !contents?.has?.(h))) written = state;
      const json = stringifyExact(envelope(lesson, written));
      // Only an imported mesh kept inline (no IndexedDB) makes a state this long: never saved.
      if (json.length > PAGEHIDE_MAX_CHARS) return;
      const why = pending ? replacing : inflightWhy;
      const drawing = drawingOf(lesson, written);
      const now = readRecord(storage, lesson.id);
      if (now?.json === json) return;
      const { write, clash } = decide(now, drawing);
      if (!write) return;
      const aside = Boolean(now && (clash || (why && now.drawing !== drawing)));
      // What is replaced is kept first; where it cannot be kept, it is not written over.
      if (aside && !setAsideNow(storage, entryOf(now, clash ? 'clash' : why))) return;
      const rec = writeRecord(storage, lesson.id, { rev: (now?.rev ?? 0) + 1, tab, drawing, summary: summaryOf(state), json, setAside: aside && now?.tab && now.tab !== tab ? { tab: now.tab, rev: now.rev } : null });
      readRev = rec.rev;
      readDrawing = drawing;
      savedState = state;
      syncWrites += 1; // a write under way (back from the page cache) must not write its older state over this
      // The address bar holds what this tab last put there: a write under way may have put its
      // (older) state's link there without yet marking it as this tab's own. Marked now, a
      // reload opens the work just written, not that link over it.
      const shown = readHashCode();
      if (shown !== null) addOwnCode(lesson, shown);
      if (pending === state) {
        pending = null;
        replacing = null;
      }
    } catch {
      // storage disabled or full: the debounced write was all there is
    }
  }
  const listen = () => {
    window.addEventListener('pagehide', keepPending);
    window.addEventListener('storage', (event) => { if (event.key === storageKey(lesson.id) || event.key === null) noticeOtherTab(); });
    document.addEventListener('visibilitychange', () => { if (document.visibilityState === 'visible') noticeOtherTab(); });
  };
  if (keep) listen();

  // Another tab may have saved: take its work when this tab has nothing of its own waiting
  // (a write under way or due decides by the rule above instead).
  function noticeOtherTab() {
    if (!keep) return;
    const now = readRecord(storage, lesson.id);
    if (!now || now.rev === readRev || now.tab === tab) return;
    if (now.drawing !== null && now.drawing === readDrawing) {
      readRev = now.rev; // only the other tab's view changed: this tab keeps its own
      return;
    }
    if (pending || inflightState || timer) return;
    otherTab(now, { setAside: now.setAside?.tab === tab });
  }

  let inflight = Promise.resolve();
  function flush() {
    timer = null;
    inflight = inflight.then(write).catch(() => { /* the next save tries again */ });
    return inflight;
  }

  async function linkOf(state) {
    const { state: written, refs, unstored } = await externalize(lesson, state, contents);
    return { code: await compressEnvelope(lesson, written), refs, unstored, written };
  }

  // Writes run one after the other, so a slow compression can never let an older state
  // overwrite a newer one, and flushNow() can wait for the one under way.
  async function write() {
    const state = pending;
    if (state === null || !keep) return;
    const why = replacing; // the reason goes with the state it came with
    inflightState = state;
    inflightWhy = why;
    pending = null;
    replacing = null;
    const started = syncWrites;
    let kept = false;
    try {
      const { code, refs, unstored, written } = await linkOf(state);
      if (unstored.length) sayOnce('content-not-stored', unstored);
      // The reader refuses a link this long on the next visit: the earlier work stays saved.
      if (code.length > MAX_LINK_CHARS) {
        sayOnce('too-long', { chars: code.length });
        return;
      }
      said.delete('too-long');
      contents?.pin?.(refs.map((r) => r.hash));
      if (code !== lastCode) {
        lastCode = code;
        const url = new URL(window.location.href);
        url.hash = `s=${code}`;
        window.history.replaceState(window.history.state, '', url);
      }
      if (adopted === state) {
        adopted = null;
        kept = true;
        return;
      }
      const drawing = drawingOf(lesson, written);
      await withLock(lockName, async () => {
        for (let attempt = 0; attempt < 3; attempt += 1) {
          // Written synchronously as the page went away meanwhile (and came back): newer.
          if (!keep || syncWrites !== started) return;
          const now = readRecord(storage, lesson.id);
          if (now?.code === code) {
            readRev = now.rev;
            readDrawing = now.drawing;
            savedState = state;
            kept = true;
            return;
          }
          const { write: go, clash } = decide(now, drawing);
          if (!go) return; // (the other tab's later work is taken after this write)
          // The work replaced goes into the history first; when it was another tab's, that
          // tab says so. Where it cannot be kept, it is not written over.
          const aside = Boolean(now && (clash || (why && now.drawing !== drawing)));
          if (aside && !await keepInHistory(now, clash ? 'clash' : why)) {
            sayOnce('storage-full');
            return;
          }
          // Another tab (without locks, or on its way out) may have written meanwhile.
          if (aside && readRecord(storage, lesson.id)?.raw !== now.raw) continue;
          try {
            const rec = writeRecord(storage, lesson.id, { rev: (now?.rev ?? 0) + 1, tab, drawing, summary: summaryOf(state), code, setAside: aside && now?.tab && now.tab !== tab ? { tab: now.tab, rev: now.rev } : null });
            readRev = rec.rev;
            readDrawing = drawing;
            savedState = state;
            kept = true;
            said.delete('storage-full'); // room again: a later shortage is said again
            // The budget, now that the saved work refers to what it does.
            if (aside) history?.prune().catch(() => {});
          } catch {
            // Storage full (another page of the origin, a big import): the link holds the state.
            if (storage) sayOnce('storage-full');
          }
          return;
        }
      });
      // This tab's own address is the saved work's only once it is saved: a reload of an
      // address that could not be saved opens it as a link, over the older saved work.
      if (kept) {
        addOwnCode(lesson, code);
      }
    } finally {
      if (!kept && why && !replacing) replacing = why; // the next write keeps the replaced work
      if (inflightState === state) {
        inflightState = null;
        inflightWhy = null;
      }
      // A later save of another tab noticed meanwhile (and left to this write) is reconsidered.
      setTimeout(noticeOtherTab, 0);
    }
  }

  return {
    tab,
    save(state, { replacing: why = null } = {}) {
      if (!keep) return;
      if (state !== adopted) adopted = null;
      pending = state;
      if (why && !replacing) replacing = why;
      if (!timer) timer = setTimeout(flush, delayMs);
    },
    // The work of another tab, now shown here: saved already, so not written again.
    took(record, state) {
      readRev = record.rev;
      readDrawing = record.drawing;
      adopted = state;
      savedState = state;
    },
    // Keeps from now on (a page that opened as an exercise and shows the person's own work
    // after all: app/shell.js), from the revision `base` the shell has just read.
    resume(from = null, shown = null) {
      if (keep) return;
      keep = true;
      if (from) {
        readRev = from.rev;
        readDrawing = from.drawing;
      }
      savedState = shown;
      listen();
    },
    // Nothing more is written from now on (the person's work was forgotten).
    // Resolves once a write under way has given up.
    stop() {
      keep = false;
      pending = null;
      inflightState = null;
      if (timer) clearTimeout(timer);
      timer = null;
      return inflight;
    },
    get keeping() { return keep; },
    // The saved work could not be shown (the core refuses it): set aside as it was, for the
    // history, so the next save does not destroy it.
    keepSavedAside(why = 'this version could not show it') {
      if (!keep) return;
      keepAside(lesson, storage, readRecord(storage, lesson.id), why);
    },
    async flushNow() {
      if (timer) {
        clearTimeout(timer);
        await flush();
      } else {
        await inflight;
      }
    },
    // The code this page last wrote to the address bar: a hash change to anything else
    // came from outside (a pasted link, back/forward).
    get lastCode() { return lastCode; },
    // Writes the state to the address bar again even if unchanged (after a refused link).
    rewrite(state) {
      lastCode = null;
      this.save(state);
    },
    // { url, refs }: refs name the large fields the link only refers to.
    async shareLink(state) {
      const { code, refs } = await linkOf(state);
      const url = new URL(window.location.href);
      url.hash = `s=${code}`;
      return { url: url.href, refs };
    },
    async shareUrl(state) {
      return (await this.shareLink(state)).url;
    },
  };
}
