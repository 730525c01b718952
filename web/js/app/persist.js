// Keeps a lesson's state in the page URL (#s=...) and in local storage, and restores it.
// The URL is updated with replaceState, so the back button undoes navigation, not edits.
// Writing is debounced (and compression is asynchronous), so an edit made just before a
// reload is also written synchronously to session storage on pagehide, together with the
// link it supersedes; a reload of that same link restores the newer state.
import { encodeState, decodeState, envelope, readEnvelope, stringifyExact } from './share-link.js';

const storageKey = (lesson) => `wingspline:${lesson.id}:state`;
const pendingKey = (lesson) => `wingspline:${lesson.id}:pending`;

function sessionStore() {
  try {
    return window.sessionStorage;
  } catch {
    return null;
  }
}

// The state this tab had not yet written when it was last hidden, if it belongs to `code`.
function takePending(lesson, code) {
  const session = sessionStore();
  const raw = session?.getItem(pendingKey(lesson));
  if (!raw) return null;
  session.removeItem(pendingKey(lesson));
  try {
    const record = JSON.parse(raw);
    if (record?.fromCode !== code) return null;
    const { state, problems } = readEnvelope(lesson, JSON.parse(record.json));
    return problems.length ? null : state;
  } catch {
    return null;
  }
}

function readHashCode() {
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
    return null; // private mode or storage disabled: the URL still keeps the state
  }
}

// Resolves to { state, source: 'link'|'storage'|'default', problem }.
export async function restoreState(lesson) {
  const code = readHashCode();
  const pending = takePending(lesson, code);
  if (pending) return { state: pending, source: code === null ? 'storage' : 'link', problem: null };
  if (code !== null) {
    try {
      const { state, problems } = await decodeState(lesson, code);
      return {
        state,
        source: 'link',
        problem: problems.length ? `Part of this link was not usable (${problems[0]}); that part was reset.` : null,
      };
    } catch (err) {
      return { state: lesson.defaultState(), source: 'default', problem: `This share link could not be used: ${err.message}. Showing the lesson's starting point instead.` };
    }
  }
  const stored = safeStorage()?.getItem(storageKey(lesson));
  if (stored) {
    try {
      const { state, problems } = await decodeState(lesson, stored);
      return { state, source: 'storage', problem: problems.length ? `Part of your saved work was reset (${problems[0]}).` : null };
    } catch (err) {
      return { state: lesson.defaultState(), source: 'default', problem: `Your saved work could not be read (${err.message}); starting fresh.` };
    }
  }
  return { state: lesson.defaultState(), source: 'default', problem: null };
}

// Returns a function save(state) that writes URL and storage, debounced.
export function createPersister(lesson, { delayMs = 200 } = {}) {
  let timer = null;
  let pending = null;
  let lastCode = readHashCode();
  const storage = safeStorage();

  // Synchronous last word before the page goes away (reload, navigation, tab closed).
  function keepPending() {
    if (!pending) return;
    try {
      sessionStore()?.setItem(pendingKey(lesson), JSON.stringify({ fromCode: readHashCode(), json: stringifyExact(envelope(lesson, pending)) }));
    } catch {
      // storage disabled or full: the debounced write is all there is
    }
  }
  window.addEventListener('pagehide', keepPending);

  let inflight = Promise.resolve();
  function flush() {
    timer = null;
    inflight = inflight.then(write).catch(() => { /* the next save tries again */ });
    return inflight;
  }

  // Writes run one after the other, so a slow compression can never let an older state
  // overwrite a newer one, and flushNow() can wait for the one under way.
  async function write() {
    const state = pending;
    if (state === null) return;
    const code = await encodeState(lesson, state);
    if (pending === state) pending = null;
    if (code === lastCode) return;
    lastCode = code;
    const url = new URL(window.location.href);
    url.hash = `s=${code}`;
    window.history.replaceState(window.history.state, '', url);
    try {
      storage?.setItem(storageKey(lesson), code);
    } catch {
      // storage full: the link still holds the state
    }
  }

  return {
    save(state) {
      pending = state;
      if (!timer) timer = setTimeout(flush, delayMs);
    },
    async flushNow() {
      if (timer) {
        clearTimeout(timer);
        await flush();
      } else {
        await inflight;
      }
    },
    async shareUrl(state) {
      const url = new URL(window.location.href);
      url.hash = `s=${await encodeState(lesson, state)}`;
      return url.href;
    },
  };
}
