// @ts-check
// The lesson toolbar and the keys that go with it: undo and redo, share link, the Export
// menu, Import, theme, presentation mode, the key map and reset; print (a clean figure on
// white paper) and the system theme following. Presentation mode keeps the essentials
// (undo, present, keys, reset); the rest is .advanced.
import { h } from './dom.js';
import { cycleTheme, currentTheme, isPresenting, setPresenting } from './theme.js';
import { embedUrl, embedSnippet } from './share-link.js';

/**
 * @param {{
 *   header: HTMLElement,
 *   lesson: import('./contract.js').Lesson,
 *   store: any,
 *   persister: any,
 *   keymap: import('./contract.js').Keymap,
 *   message: import('./contract.js').MessageLine,
 *   announceStatus: (text: string) => void,
 *   ui: import('./contract.js').Ctx['ui'],
 *   files: { exportItems: import('./contract.js').ExportItem[], runExport: (item: import('./contract.js').ExportItem) => Promise<void>, fileInput: HTMLInputElement },
 *   recolor: (options?: { now?: boolean }) => void,
 *   reset: () => void,
 *   fitView: () => void,
 *   makeExercise?: (() => void) | null,
 *   openHistory?: (() => Promise<HTMLDialogElement>) | null,
 * }} parts
 * @returns {{ update(): void }}
 */
export function createToolbar({ header, lesson, store, persister, keymap, message, announceStatus, ui, files, recolor, reset, fitView, makeExercise = null, openHistory = null }) {
  const { exportItems, runExport, fileInput } = files;
  const buttons = {};
  function toolButton(key, label, onclick, title = label, { advanced = false } = {}) {
    buttons[key] = h('button', { type: 'button', class: advanced ? 'tool advanced' : 'tool', onclick, title, 'data-action': key }, label);
    return buttons[key];
  }

  // A disclosure of plain buttons (not an ARIA menu, which would promise arrow-key roving).
  const exportMenu = /** @type {HTMLDetailsElement} */ (h('details', { class: 'menu advanced' }, h('summary', { class: 'tool' }, 'Export'),
    h('div', { class: 'menu-items' }, exportItems.map((item) => h('button', {
      type: 'button', 'data-export': typeof item.filename === 'function' ? item.label : item.filename,
      onclick() {
        exportMenu.open = false;
        return runExport(item);
      },
    }, item.label)),
    h('button', { type: 'button', 'data-action': 'embed-code', onclick() {
      exportMenu.open = false;
      return copyEmbedCode();
    } }, 'Copy embed code'))));

  // A link to a state with a large field (an imported mesh) only refers to it: it opens on
  // this browser only, and the person is offered the file to send with it.
  async function share() {
    const { url, refs } = await persister.shareLink(store.state);
    let copied = true;
    try {
      await navigator.clipboard.writeText(url);
    } catch {
      copied = false;
    }
    const field = refs.length ? lesson.contentFields?.[refs[0].key] : null;
    const item = field && exportItems.find((x) => x.filename === field.export);
    if (field) {
      message.warn(`This link refers to ${field.what ?? 'an imported file'} ("${refs[0].label}") that is only stored in this browser; share ${field.file ?? 'the file'} with it.`, {
        code: 'link-refers-to-local-content',
        action: item ? { id: 'export', label: `Export ${field.file ?? 'the file'}`, run: () => runExport(item) } : null,
      });
    } else if (copied) {
      message.info('Link copied: it opens this lesson exactly as you see it now.');
    } else {
      message.info('The address bar holds the link to this exact state; copy it from there.');
    }
    return url;
  }

  // "Copy embed code" (docs/embed.md): an iframe snippet of the embed link of this state.
  // Where the clipboard is refused, the snippet is shown in a dialog to copy by hand (as
  // text: the URL is never parsed as markup).
  async function copyEmbedCode() {
    const { url, refs } = await persister.shareLink(store.state);
    const snippet = embedSnippet(embedUrl(url), lesson.title);
    const local = refs.length ? ` It refers to "${refs[0].label}", which is only stored in this browser: the frame shows it on this browser only.` : '';
    try {
      await navigator.clipboard.writeText(snippet);
      message.info(`Embed code copied: paste it into a web page, a slide or a course page.${local}`);
    } catch {
      showSnippet(snippet);
      message.info(`The clipboard refused the embed code: copy it from the dialog.${local}`);
    }
    return snippet;
  }
  function showSnippet(snippet) {
    const area = /** @type {HTMLTextAreaElement} */ (h('textarea', { readonly: true, rows: 5, cols: 60, 'aria-labelledby': 'embed-code-title', spellcheck: 'false' }));
    area.value = snippet;
    const dialog = /** @type {HTMLDialogElement} */ (h('dialog', { class: 'keymap-dialog embed-code-dialog', 'aria-labelledby': 'embed-code-title' },
      h('h2', { id: 'embed-code-title' }, 'Embed code'),
      h('p', {}, 'Copy this into your page (Ctrl+C); it shows the lesson as you see it now.'),
      area,
      h('p', {}, h('button', { type: 'button', onclick: () => dialog.close() }, 'Close'))));
    dialog.addEventListener('close', () => dialog.remove());
    document.body.append(dialog);
    dialog.showModal();
    area.focus();
    area.select();
  }

  async function togglePresent(on = !isPresenting()) {
    ui.present = on;
    await setPresenting(on);
    recolor();
  }
  // Leaving full screen (Escape in the browser) also leaves presentation mode.
  document.addEventListener('fullscreenchange', () => {
    if (!document.fullscreenElement && isPresenting()) togglePresent(false);
  });

  function changeTheme() {
    cycleTheme();
    recolor();
    announceStatus(`Theme: ${currentTheme()}`);
  }

  // Print: a clean figure on white paper whatever the screen theme, with its tables.
  let printTheme = null;
  window.addEventListener('beforeprint', () => {
    printTheme = document.documentElement.dataset.theme ?? null;
    document.documentElement.dataset.theme = 'light';
    recolor({ now: true });
  });
  window.addEventListener('afterprint', () => {
    if (printTheme) document.documentElement.dataset.theme = printTheme; else delete document.documentElement.dataset.theme;
    printTheme = null;
    recolor();
  });
  window.matchMedia?.('(prefers-color-scheme: dark)').addEventListener?.('change', () => recolor());

  header.replaceChildren(
    toolButton('undo', 'Undo', () => store.undo(), 'Undo (Ctrl+Z)'),
    toolButton('redo', 'Redo', () => store.redo(), 'Redo (Ctrl+Shift+Z)'),
    toolButton('share', 'Share link', share, undefined, { advanced: true }),
    exportMenu,
    toolButton('import', 'Import', () => fileInput.click(), 'Import a state (JSON) or a lesson file; dropping a file on the page works too', { advanced: true }),
    // "Make an exercise from this view" (exercise/author.js).
    makeExercise ? toolButton('make-exercise', 'Make an exercise', makeExercise, 'Make an exercise from this view: choose what to hide, write the question, export the JSON and a link', { advanced: true }) : '',
    fileInput,
    // The work links, Reset, imports and other tabs replaced, and Forget (app/history-menu.js).
    openHistory ? toolButton('history', 'History', () => openHistory(), 'Your earlier work in this lesson, to bring back; forget your work on this computer', { advanced: true }) : '',
    toolButton('theme', 'Theme', changeTheme, 'Theme: system, light, dark (T)', { advanced: true }),
    toolButton('present', 'Present', () => togglePresent(), 'Presentation mode (P)'),
    toolButton('keys', 'Keys ?', () => keymap.showDialog(), 'Keyboard map (?)'),
    toolButton('reset', 'Reset lesson', reset, 'Back to the lesson\'s starting point'),
  );

  keymap.add({ keys: ['Ctrl+z'], label: 'undo', group: 'Editing', action: () => store.undo() });
  keymap.add({ keys: ['Ctrl+Shift+z', 'Ctrl+y'], label: 'redo', group: 'Editing', action: () => store.redo() });
  // Handled by the focused canvas (stage.js); listed here so the key map shows them.
  keymap.add({ keys: ['[', ']'], label: 'select the previous / next handle (canvas focused)', group: 'Editing' });
  keymap.add({ keys: ['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown'], label: 'move the selected handle (Shift: finer)', group: 'Editing' });
  keymap.add({ keys: ['p'], label: 'presentation mode on / off', group: 'View', action: () => togglePresent() });
  keymap.add({ keys: ['Escape'], label: 'leave presentation mode', group: 'View', when: () => isPresenting() && !document.querySelector('dialog[open]'), action: () => togglePresent(false) });
  keymap.add({ keys: ['t'], label: 'theme: system, light, dark', group: 'View', action: changeTheme });
  keymap.add({ keys: ['0'], label: 'fit the drawing to the window', group: 'View', action: fitView });
  keymap.add({ keys: ['?'], label: 'show this key map', group: 'View', action: () => keymap.showDialog() });

  return {
    update() {
      buttons.undo.disabled = !store.canUndo;
      buttons.redo.disabled = !store.canRedo;
      buttons.theme.textContent = `Theme: ${currentTheme()}`;
      buttons.present.setAttribute('aria-pressed', String(ui.present));
    },
  };
}

// The embed's controls (docs/embed.md): Reset (back to the prepared state of the link) and
// "Open in Wingspline" (the full lesson, in a new tab, at the state shown), and the keys that
// change nothing outside the frame (no theme or presentation keys: those are the link's).
/**
 * @param {{
 *   header: HTMLElement,
 *   store: any,
 *   persister: any,
 *   keymap: import('./contract.js').Keymap,
 *   recolor: (options?: { now?: boolean }) => void,
 *   reset: () => void,
 *   fitView: () => void,
 * }} parts
 * @returns {{ update(): void }}
 */
export function createEmbedToolbar({ header, store, persister, keymap, recolor, reset, fitView }) {
  const open = /** @type {HTMLAnchorElement} */ (h('a', { class: 'tool', 'data-action': 'open', target: '_blank', rel: 'noopener noreferrer',
    title: 'Open this lesson in Wingspline, in a new tab, as you see it now', href: window.location.href.split('#')[0] }, 'Open in Wingspline'));
  header.replaceChildren(
    h('button', { type: 'button', class: 'tool', 'data-action': 'reset', title: 'Back to the prepared state', onclick: reset }, 'Reset'),
    open,
  );
  // The link follows the state shown; links resolve in order, so an older one never wins.
  let shownFor = null;
  let asked = 0;
  async function follow() {
    const state = store.state;
    if (state === shownFor) return;
    shownFor = state;
    asked += 1;
    const mine = asked;
    try {
      const { url } = await persister.shareLink(state);
      if (mine === asked) open.href = url;
    } catch {
      // a state that cannot be written keeps the last link
    }
  }
  keymap.add({ keys: ['Ctrl+z'], label: 'undo', group: 'Editing', action: () => store.undo() });
  keymap.add({ keys: ['Ctrl+Shift+z', 'Ctrl+y'], label: 'redo', group: 'Editing', action: () => store.redo() });
  keymap.add({ keys: ['0'], label: 'fit the drawing to the frame', group: 'View', action: fitView });
  keymap.add({ keys: ['?'], label: 'show this key map', group: 'View', action: () => keymap.showDialog() });
  window.matchMedia?.('(prefers-color-scheme: dark)').addEventListener?.('change', () => recolor());
  return { update() { follow(); } };
}
