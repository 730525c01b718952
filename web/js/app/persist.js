// Keeps a lesson's state in the page URL (#s=...) and in local storage, and restores it.
// The URL is updated with replaceState, so the back button undoes navigation, not edits.
// Writing is debounced (and compression is asynchronous), so an edit made just before a
// reload is also written synchronously to session storage on pagehide, together with the
// link it supersedes; a reload of that same link restores the newer state.
// Large fields (an imported mesh) are kept in IndexedDB by content hash and the link refers
// to them (share-link.js, content-store.js).
//
// The person's saved work is never lost to a link or a state that cannot be read (issue
// 13, items 12 and 18): a link that cannot be used shows the saved work instead; a link
// that can replaces it as one undoable step (restoreState's `previous`); a saved state
// this page cannot read is kept aside under `wingspline:<lesson>:unreadable` before
// anything is written over it.
import { decodeState, readEnvelopeResolved, externalize, externalizeKnown, compressEnvelope, envelope, stringifyExact } from './share-link.js';

const storageKey = (lesson) => `wingspline:${lesson.id}:state`;
const pendingKey = (lesson) => `wingspline:${lesson.id}:pending`;
const unreadableKey = (lesson) => `wingspline:${lesson.id}:unreadable`;

function sessionStore() {
  try {
    return window.sessionStorage;
  } catch {
    return null;
  }
}

// The state this tab had not yet written when it was last hidden, if it belongs to `code`.
async function takePending(lesson, code, contents) {
  const session = sessionStore();
  const raw = session?.getItem(pendingKey(lesson));
  if (!raw) return null;
  session.removeItem(pendingKey(lesson));
  try {
    const record = JSON.parse(raw);
    // The pending edit belongs to the address it was made at; or, when the page was writing
    // its previous state as it went away, to the code that write put in the address bar and
    // in storage just before the reload (the same page's own last write, not another link).
    const ownWrite = record?.writing === true && code !== null && code === safeStorage()?.getItem(storageKey(lesson));
    if (record?.fromCode !== code && !ownWrite) return null;
    const { state, problems } = await readEnvelopeResolved(lesson, JSON.parse(record.json), { contents });
    return problems.length ? null : state;
  } catch {
    return null;
  }
}

export function readHashCode() {
  const params = new URLSearchParams(window.location.hash.slice(1));
  return params.get('s');
}

function safeStorage() {
  try {
    const probe = '__wingspline_probe__';
    window.localStorage.setItem(probe, '1');
    window.localStorage.removeItem(probe);
    return window.localStorage;
  } catch {
    // Private mode, storage disabled, or full to the last byte: reading still works.
    try {
      return window.localStorage ?? null;
    } catch {
      return null;
    }
  }
}

const sameState = (a, b) => {
  try {
    return stringifyExact(a) === stringifyExact(b);
  } catch {
    return false;
  }
};

// A saved state this page cannot read (made by a newer Wingspline, its mesh gone from this
// browser) is moved aside, so the next save does not destroy it.
function keepAside(lesson, storage, code) {
  try {
    storage?.setItem(unreadableKey(lesson), code);
  } catch {
    // storage full: the saved code stays where it is until the next successful save
  }
}

// Resolves to { state, source: 'link'|'storage'|'default', problem, previous }.
// `previous`: the saved work a link replaced (undo returns to it), or null.
export async function restoreState(lesson, { contents } = {}) {
  const code = readHashCode();
  const storage = safeStorage();
  const storedCode = storage?.getItem(storageKey(lesson)) ?? null;
  const pending = await takePending(lesson, code, contents);
  if (pending) return { state: pending, source: code === null ? 'storage' : 'link', problem: null, previous: null };

  let saved = null;
  let savedError = null;
  if (storedCode) {
    try {
      saved = await decodeState(lesson, storedCode, { contents });
    } catch (err) {
      savedError = err.message;
      keepAside(lesson, storage, storedCode);
    }
  }
  const savedProblem = savedError
    ? `Your saved work could not be read (${savedError}); it is kept aside in this browser`
    : saved?.problems.length ? `Part of your saved work was reset (${saved.problems[0]})` : null;

  if (code !== null && code !== storedCode) {
    try {
      const { state, problems } = await decodeState(lesson, code, { contents });
      const previous = saved && !sameState(saved.state, state) ? saved.state : null;
      return {
        state,
        source: 'link',
        problem: problems.length ? `Part of this link was not usable (${problems[0]}); that part was reset.` : null,
        previous,
      };
    } catch (err) {
      if (saved) {
        return { state: saved.state, source: 'storage', problem: `This share link could not be used: ${err.message}. Showing your saved work instead.`, previous: null };
      }
      return { state: lesson.defaultState(), source: 'default', problem: `This share link could not be used: ${err.message}. Showing the lesson's starting point instead.`, previous: null };
    }
  }
  if (saved) return { state: saved.state, source: code === null ? 'storage' : 'link', problem: savedProblem ? `${savedProblem}.` : null, previous: null };
  if (savedError) return { state: lesson.defaultState(), source: 'default', problem: `${savedProblem}; starting fresh.`, previous: null };
  return { state: lesson.defaultState(), source: 'default', problem: null, previous: null };
}

// An embed (docs/embed.md) shows its link's state, or the lesson's starting point when the
// link cannot be used, and reads nothing of the person's saved work (nor takes this tab's
// pending state, nor moves anything aside): an embed never touches that work.
export async function restoreLinkOnly(lesson, { contents } = {}) {
  const code = readHashCode();
  if (code === null) return { state: lesson.defaultState(), source: 'default', problem: null, previous: null };
  try {
    const { state, problem } = await readLink(lesson, code, { contents });
    return { state, source: 'link', problem, previous: null };
  } catch (err) {
    return { state: lesson.defaultState(), source: 'default', problem: `This share link could not be used: ${err.message}. Showing the lesson's starting point instead.`, previous: null };
  }
}

// Decodes a link pasted into the address bar of the open page (hashchange): resolves to
// { state, problem } or rejects with an Error of one sentence.
export async function readLink(lesson, code, { contents } = {}) {
  const { state, problems } = await decodeState(lesson, code, { contents });
  return { state, problem: problems.length ? `Part of this link was not usable (${problems[0]}); that part was reset.` : null };
}

// Returns a persister: save(state) writes URL and storage, debounced.
// notify(kind, detail) is called once per kind when something cannot be kept:
// 'storage-full' (local storage refuses the state: the link still holds it) and
// 'content-not-stored' (a large field could not be put in IndexedDB).
// keep: false (an embed): nothing is written, neither the address bar nor local storage nor
// the pending state of this tab; shareLink still makes the full lesson's link.
export function createPersister(lesson, { delayMs = 200, contents = null, notify = (kind, detail) => {}, keep = true } = {}) {
  let timer = null;
  let pending = null;
  let lastCode = readHashCode();
  const storage = safeStorage();
  const said = new Set();
  const sayOnce = (kind, detail) => {
    if (said.has(kind)) return;
    said.add(kind);
    notify(kind, detail);
  };

  // Synchronous last word before the page goes away (reload, navigation, tab closed).
  function keepPending() {
    if (!pending) return;
    try {
      sessionStore()?.setItem(pendingKey(lesson), JSON.stringify({ fromCode: readHashCode(), writing: writing > 0, json: stringifyExact(envelope(lesson, externalizeKnown(lesson, pending))) }));
    } catch {
      // storage disabled or full: the debounced write is all there is
    }
  }
  if (keep) window.addEventListener('pagehide', keepPending);

  let inflight = Promise.resolve();
  let writing = 0; // writes under way (their code may reach the address bar after a pagehide)
  function flush() {
    timer = null;
    writing += 1;
    inflight = inflight.then(write).catch(() => { /* the next save tries again */ }).finally(() => { writing -= 1; });
    return inflight;
  }

  async function linkOf(state) {
    const { state: written, refs, unstored } = await externalize(lesson, state, contents);
    return { code: await compressEnvelope(lesson, written), refs, unstored };
  }

  // Writes run one after the other, so a slow compression can never let an older state
  // overwrite a newer one, and flushNow() can wait for the one under way.
  async function write() {
    const state = pending;
    if (state === null) return;
    const { code, unstored } = await linkOf(state);
    if (pending === state) pending = null;
    if (unstored.length) sayOnce('content-not-stored', unstored);
    if (code === lastCode) return;
    lastCode = code;
    const url = new URL(window.location.href);
    url.hash = `s=${code}`;
    window.history.replaceState(window.history.state, '', url);
    try {
      storage?.setItem(storageKey(lesson), code);
      said.delete('storage-full'); // room again: a later shortage is said again
    } catch {
      // Storage full (another page of the origin, a big import): the link holds the state.
      if (storage) sayOnce('storage-full');
    }
  }

  return {
    save(state) {
      if (!keep) return;
      pending = state;
      if (!timer) timer = setTimeout(flush, delayMs);
    },
    // Keeps from now on (a page that opened as an exercise and shows the person's own work
    // after all: app/shell.js).
    resume() {
      if (keep) return;
      keep = true;
      window.addEventListener('pagehide', keepPending);
    },
    async flushNow() {
      if (timer) {
        clearTimeout(timer);
        await flush();
      } else {
        await inflight;
      }
    },
    // The saved code is moved aside (the page could not show it): the next save keeps it.
    keepSavedAside() {
      if (!keep) return;
      const code = storage?.getItem(storageKey(lesson));
      if (code) keepAside(lesson, storage, code);
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
