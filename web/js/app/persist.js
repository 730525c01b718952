// Keeps a lesson's state in the page URL (#s=...) and in local storage, and restores it.
// The URL is updated with replaceState, so the back button undoes navigation, not edits.
import { encodeState, decodeState } from './share-link.js';

const storageKey = (lesson) => `wingspline:${lesson.id}:state`;

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
  let lastCode = null;
  const storage = safeStorage();

  async function flush() {
    timer = null;
    const state = pending;
    pending = null;
    const code = await encodeState(lesson, state);
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
      }
    },
    async shareUrl(state) {
      const url = new URL(window.location.href);
      url.hash = `s=${await encodeState(lesson, state)}`;
      return url.href;
    },
  };
}
