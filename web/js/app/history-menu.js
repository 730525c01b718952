// @ts-check
// The History dialog of a lesson page: the person's earlier work in this lesson (what a
// link, Reset, an import, a restore or another tab replaced; saved work this version could
// not read), newest first, each with its time and summary and one click to bring it back
// (or, for work that cannot be read, to save it as a file); and, for shared lab computers,
// "Forget my work on this computer" after a confirmation. work-history.js keeps the entries.
import { h, setChildren } from './dom.js';
import { download } from './file-io.js';
import { reasonText, LOCAL_MAX_ENTRY_CHARS } from './work-history.js';

/**
 * @param {{
 *   lesson: import('./contract.js').Lesson,
 *   history: any,
 *   restore: (entry: any) => Promise<boolean>,
 *   forget: () => Promise<void>,
 * }} parts
 * @returns {() => Promise<HTMLDialogElement>} opens the dialog
 */
export function createHistoryMenu({ lesson, history, restore, forget }) {
  const when = (time) => new Date(time).toLocaleString(undefined, { dateStyle: 'medium', timeStyle: 'short' });

  function entryItem(entry, dialog) {
    const readable = entry.code !== undefined || entry.json !== undefined;
    const action = readable
      ? h('button', { type: 'button', 'data-history-restore': String(entry.id), 'aria-label': `Restore the work of ${when(entry.time)}: ${entry.summary || 'saved work'}`, async onclick() {
        if (await restore(entry)) dialog.close();
      } }, 'Restore')
      : h('button', { type: 'button', 'data-history-save': String(entry.id), 'aria-label': `Save the work of ${when(entry.time)} as a file`, onclick() {
        download(`wingspline-${lesson.id}-kept-${new Date(entry.time).toISOString().slice(0, 19).replace(/:/g, '-')}.txt`, entry.raw);
      } }, 'Save as file');
    return h('li', { 'data-history-entry': String(entry.id) },
      h('span', { class: 'history-when' }, h('time', { datetime: new Date(entry.time).toISOString() }, when(entry.time))),
      h('span', { class: 'history-what' }, entry.summary || 'saved work', h('span', { class: 'history-why' }, ` (${reasonText[entry.reason] ?? entry.reason})`)),
      action);
  }

  return async function open() {
    const list = h('ol', { class: 'history-list', 'aria-labelledby': 'history-title' });
    const note = h('p', { class: 'history-note' });
    const confirm = h('div', { class: 'history-confirm', hidden: true },
      h('p', {}, 'This removes from this browser your saved work in every lesson, its history and your exercise progress. It cannot be undone; export anything you want to keep first.'),
      h('p', {},
        h('button', { type: 'button', 'data-action': 'forget-confirm', class: 'danger', async onclick() {
          await forget();
          dialog.close();
        } }, 'Forget everything'),
        ' ',
        h('button', { type: 'button', 'data-action': 'forget-cancel', onclick() { confirm.hidden = true; ask.focus(); } }, 'Cancel')));
    const ask = h('button', { type: 'button', 'data-action': 'forget', onclick() {
      confirm.hidden = false;
      /** @type {HTMLElement | null} */ (confirm.querySelector('[data-action=forget-cancel]'))?.focus();
    } }, 'Forget my work on this computer…');
    const dialog = /** @type {HTMLDialogElement} */ (h('dialog', { class: 'keymap-dialog history-dialog', 'aria-labelledby': 'history-title' },
      h('h2', { id: 'history-title' }, `History: ${lesson.title}`),
      note,
      list,
      h('h3', {}, 'A shared computer?'),
      h('p', {}, ask),
      confirm,
      h('p', {}, h('button', { type: 'button', 'data-action': 'history-close', onclick: () => dialog.close() }, 'Close'))));
    dialog.addEventListener('close', () => dialog.remove());
    document.body.append(dialog);
    dialog.showModal();

    const mode = await history.mode();
    const entries = await history.list(lesson.id).catch(() => []);
    setChildren(note,
      'The work a link, Reset, an import, a restore or another tab replaced, newest first; kept in this browser only.',
      mode === 'local' ? ` This browser offers no IndexedDB here (a private window?), so the history is kept in local storage and holds only work of up to ${LOCAL_MAX_ENTRY_CHARS.toLocaleString('en')} characters: large imported meshes are not kept in it.` : '',
      mode === 'none' ? ' This browser keeps nothing for this site here (storage is disabled), so there is no history.' : '');
    if (entries.length) setChildren(list, ...entries.map((e) => entryItem(e, dialog)));
    else setChildren(list, h('li', { class: 'history-empty' }, 'Nothing yet: when a link, Reset or an import replaces your work, the work it replaced is kept here.'));
    return dialog;
  };
}
