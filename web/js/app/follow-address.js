// @ts-check
// Following the address bar: a share link pasted into this open tab (or back/forward
// between links) is loaded like a link opened in a new tab, as one undoable step, and the
// work it replaced is offered back. A page that must open afresh instead (an exercise's
// page, or any page given an exercise link: the shell's `opensAfresh`) reloads, keeping
// what is not yet written. An embed never listens: its address is the host page's business.
import { readHashCode, readLink } from './persist.js';

/**
 * @typedef {import('./contract.js').State} State
 * @param {{
 *   lesson: import('./contract.js').Lesson,
 *   store: ReturnType<typeof import('./store.js').createStore>,
 *   persister: any,
 *   contents: any,
 *   message: import('./contract.js').MessageLine,
 *   accept: (state: State, reason: string, report?: (err: any) => void) => boolean,
 *   opensAfresh: () => boolean,
 * }} parts
 */
export function createAddressFollower({ lesson, store, persister, contents, message, accept, opensAfresh }) {
  // A link replaced the work shown before it: say so, offer it back.
  function offerPrevious(previous, problem) {
    const text = `${problem ? `${problem} ` : 'Opened the shared link. '}Your previous work is kept: Undo brings it back.`;
    message[problem ? 'warn' : 'info'](text, {
      code: 'previous-work-kept',
      action: { id: 'restore', label: 'Restore your previous work', run: () => restorePrevious(previous) },
    });
  }
  function restorePrevious(previous) {
    if (accept(previous, 'restore')) message.info('Your previous work is back (Undo shows the link again; it is in the History too).');
  }

  let following = null;
  // The code of the last address that came (hashchange, popstate; a fragment pasted fires
  // both): a link that came while another was read wins over it. The page's own writes of
  // the address (replaceState) fire neither, so a write of the work shown before the link,
  // landing while the link is read or before its event is handled, does not hide the link.
  let latest = null;
  /** @param {string} url the address that came (a hashchange's newURL) */
  async function followAddress(url) {
    const code = readHashCode(new URL(url).hash);
    latest = code;
    if (code === null || code === persister.lastCode || code === following) return;
    following = code;
    const refuse = (err) => {
      message.warn(`This share link could not be used: ${err.message}. Your work is unchanged.`, { code: 'link-refused' });
      persister.rewrite(store.state);
    };
    try {
      let read;
      try {
        read = await readLink(lesson, code, { contents });
      } catch (err) {
        refuse(err);
        return;
      }
      if (latest !== code) return; // another address came meanwhile
      const previous = store.state;
      if (accept(read.state, 'link', refuse)) offerPrevious(previous, read.problem);
    } finally {
      following = null;
    }
  }

  // A page that opens afresh keeps its exercise's progress, and the lesson's own saved work is
  // read as the page starts. (Edits not yet written are written first, the reload must not
  // drop them; writing puts the state's link in the address bar, so the address that came is
  // put back before reloading.)
  function reloadKeeping() {
    const target = window.location.href;
    persister.flushNow().finally(() => {
      window.history.replaceState(window.history.state, '', target);
      window.location.reload();
    });
  }

  return {
    offerPrevious,
    /** Follows every later change of the address (hashchange, back and forward). */
    listen() {
      const follow = (/** @type {Event} */ event) => {
        return opensAfresh() ? reloadKeeping() : followAddress(event instanceof HashChangeEvent ? event.newURL : window.location.href);
      };
      window.addEventListener('hashchange', follow);
      window.addEventListener('popstate', follow);
    },
  };
}
