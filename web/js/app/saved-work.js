// @ts-check
// The person's saved work, as a lesson page keeps it: where it lives (local storage, and
// IndexedDB for large fields and the history), the persister that writes what is shown
// (persist.js), what it could not keep said once, another tab's later work taken, and the
// History menu (restore an entry; forget everything on a shared computer). The rules are
// persist.js's and work-history.js's; this file wires them to the page: every state it
// shows goes through the shell's one compute path (`accept`, `recompute`).
import { restoreState, restoreLinkOnly, createPersister } from './persist.js';
import { createContentStore } from './content-store.js';
import { createDatabase } from './idb.js';
import { createWorkHistory, BUDGET_CHARS } from './work-history.js';
import { decodeRecord } from './saved-record.js';
import { createHistoryMenu } from './history-menu.js';

/**
 * @typedef {import('./contract.js').Lesson} Lesson
 * @typedef {import('./contract.js').State} State
 * @typedef {import('./contract.js').MessageLine} MessageLine
 */

/**
 * Where the work lives. Large fields (an imported mesh) live in IndexedDB by content hash;
 * the link refers to them. The history of the person's work lives beside them
 * (work-history.js); the content store never drops a mesh that saved work or the history
 * refers to. A page that keeps no work (an embed, a framed page) has no history.
 * @param {{ keepsWork: boolean }} options
 */
export function openWorkStores({ keepsWork }) {
  const database = createDatabase();
  /** @type {any} */
  let history = null;
  const contents = createContentStore({ db: database, referenced: keepsWork ? () => history.referenced() : null, budgetChars: BUDGET_CHARS });
  if (keepsWork) history = createWorkHistory({ db: database, contents });
  return { contents, history };
}

/**
 * The work a plain lesson page shows: the link, else the saved work, else the lesson's
 * starting point; a page that keeps no work reads only its link.
 * @param {Lesson} lesson
 * @param {{ keepsWork: boolean, contents: any }} options
 */
export function readOwnWork(lesson, { keepsWork, contents }) {
  return keepsWork ? restoreState(lesson, { contents }) : restoreLinkOnly(lesson, { contents });
}

/**
 * @param {{
 *   lesson: Lesson,
 *   store: ReturnType<typeof import('./store.js').createStore>,
 *   keepsWork: boolean,
 *   keep: boolean,
 *   contents: any,
 *   history: any,
 *   restored: any,
 *   message: MessageLine,
 *   recompute: (state: State) => boolean,
 *   accept: (state: State, reason: string) => boolean,
 *   fitView: () => void,
 *   files: () => { exportItems: any[], runExport(item: any): void },
 * }} parts `keep`: the persister writes the person's work from the start (not while an
 *   exercise is shown); `restored`: what the page started on; `files`: the page's exports
 *   (made after this), for the offer to keep a file that cannot be saved
 */
export function createSavedWork({ lesson, store, keepsWork, keep, contents, history, restored, message, recompute, accept, fitView, files }) {
  const persister = createPersister(lesson, {
    contents, history, notify: (kind) => sayKept(kind), keep,
    base: restored.base, saved: restored.source === 'storage' && !restored.problem ? restored.state : null, summarize: (state) => summaryOf(state), otherTab: (record, info) => takeOtherTab(record, info),
  });
  // Work set aside while a page went away, and unreadable entries of earlier versions, into
  // the history (not awaited: the lesson starts meanwhile).
  history?.sweep().catch(() => {});

  // What the persister could not keep, said once.
  function sayKept(kind) {
    if (kind === 'storage-full') {
      message.warn('This browser\'s storage for this site is full, so your changes are not saved in this browser any more; they are kept in the link in the address bar (bookmark or copy it).', { code: 'storage-full' });
    } else if (kind === 'content-not-stored') {
      message.warn('The imported file could not be stored in this browser (its storage is full or disabled); keep the file: it may not come back after a reload.', { code: 'content-not-stored' });
    } else if (kind === 'too-long') {
      // An imported mesh kept inline (no IndexedDB here): the reader would refuse it on the
      // next visit, so it is not saved; the earlier work stays saved.
      const field = Object.entries(lesson.contentFields ?? {}).find(([key]) => store.state?.[key]);
      const item = field && files().exportItems.find((x) => x.filename === field[1].export);
      const name = field ? field[1].label?.(store.state[field[0]]) : null;
      message.warn(`${name ? `"${name}"` : 'This state'} is too large to keep in this browser here (it has no IndexedDB: a private window?), so it will be gone after a reload; your earlier saved work is kept. Keep ${field?.[1].file ?? 'the file'} to open it again.`, {
        code: 'too-long-to-keep',
        action: item ? { id: 'export', label: `Export ${field?.[1].file ?? 'the file'}`, run: () => files().runExport(item) } : null,
      });
    }
  }

  // One line of what a state holds, for the History list (the lesson's own words if it has them).
  function summaryOf(state) {
    const own = lesson.summarize?.(state);
    return typeof own === 'string' && own ? own : lesson.title;
  }

  // Another tab saved later work of this lesson and this tab has nothing of its own waiting:
  // this tab shows it (one undoable step). When this tab's work was the one set aside (two
  // tabs edited the same work), it is in the history, and one click brings it back here.
  let taking = 0;
  async function takeOtherTab(record, { setAside }) {
    const asked = ++taking;
    const mine = store.state;
    let read;
    try {
      read = await decodeRecord(lesson, record, { contents });
    } catch {
      return; // unreadable here (a newer Wingspline in the other tab): this tab keeps its own
    }
    // An edit made meanwhile, or a later notice, decides instead.
    if (asked !== taking || store.state !== mine || read.problems.length) return;
    if (!accept(read.state, 'other-tab')) return;
    persister.took(record, read.state); // (before the save accept scheduled runs)
    if (setAside) {
      message.warn('Another tab saved later work of this lesson, so the work shown here before is set aside in the History.', {
        code: 'work-set-aside',
        action: { id: 'bring-back', label: 'Bring my work back', run: () => { if (accept(mine, 'restore')) message.info('Your work is back (the other tab\'s is in the History).'); } },
      });
    } else if (document.getElementById('message')?.dataset.code !== 'work-set-aside') {
      // (an offer to bring this tab's work back stays until it is taken or dismissed)
      message.info('Updated to the work saved in another tab (Undo shows what this tab had).');
    }
  }

  async function restoreEntry(entry) {
    try {
      const read = await decodeRecord(lesson, entry, { contents });
      if (!accept(read.state, 'restore')) return false;
      fitView();
      const when = new Date(entry.time).toLocaleString(undefined, { dateStyle: 'medium', timeStyle: 'short' });
      message.info(`Restored your work of ${when}${read.problems.length ? ` (part of it was reset: ${read.problems[0]})` : ''}. The work it replaced is in the History.`);
      return true;
    } catch (err) {
      message.warn(`That entry of the History could not be restored: ${err.message}.`, { code: 'history-refused' });
      return false;
    }
  }

  // Forget my work on this computer (a shared lab laptop): everything kept for this site in
  // this browser but the theme; the page then starts afresh, with nothing left to write.
  async function forgetEverything() {
    await persister.stop();
    try {
      await history.forgetAll();
    } catch (err) {
      message.error(`Not everything could be forgotten: ${err.message}.`);
      return;
    }
    try { window.sessionStorage.clear(); } catch { /* storage disabled */ }
    window.location.replace(window.location.href.split('#')[0]);
  }

  return {
    persister,
    /** Opens the History dialog; null where the page keeps no work. */
    openHistory: history ? createHistoryMenu({ lesson, history, restore: restoreEntry, forget: forgetEverything }) : null,

    /**
     * A drawing the page is about to replace (an exercise's Start again), into the history.
     * @param {State} state
     * @param {string} summary
     */
    keepInHistory(state, summary) {
      if (!history) return;
      persister.shareLink(state).then(({ url }) => history.add({
        lesson: lesson.id, reason: 'exercise', summary,
        code: new URLSearchParams(new URL(url).hash.slice(1)).get('s'),
      })).catch(() => {});
    },

    /**
     * The person's own work, as a plain lesson page would show it (with what it would say
     * about it), after an exercise that could not be played; saving resumes. A saved state
     * the core refuses is kept aside first, as at the start, never written over. Resolves
     * to whether the view should follow the canvas (a starting point shown); it is fitted.
     * @returns {Promise<boolean>}
     */
    async returnToOwnWork() {
      // (a framed page reads nothing of the person's work, and keeps nothing)
      const own = await readOwnWork(lesson, { keepsWork, contents });
      if (keepsWork && !own.hold) persister.resume(own.base, own.source === 'storage' && !own.problem ? own.state : null);
      let { state } = own;
      let problem = own.problem;
      if (!recompute(state)) {
        if (own.source === 'storage') persister.keepSavedAside('this version could not show it');
        problem = 'Your saved work could not be shown by this version of Wingspline; it is kept in the History as it was, and the lesson starts fresh.';
        state = lesson.defaultState();
        recompute(state);
      }
      store.set(state, { history: false, reason: 'own-work' });
      if (problem) message.warn(`${message.text} ${problem}`);
      const autoFit = own.source === 'default' || state !== own.state;
      if (autoFit) fitView();
      return autoFit;
    },
  };
}
