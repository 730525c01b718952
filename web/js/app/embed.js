// @ts-check
// An embed (#embed=1&..., docs/embed.md): the canvas and its few controls, fitted to the
// frame; its theme and presentation mode come from the link and are not remembered; it
// reads and writes nothing of the person's saved work. share-link.js reads the options;
// this file applies them to the page.
import { readEmbedOptions, embedProblemsText } from './share-link.js';
import { setTheme, showPresenting } from './theme.js';

/**
 * The embed options of an address, applied to the page (after the stored theme, which an
 * embed's own theme overrides); null for a page that is no embed.
 * @param {string} hash
 */
export function applyEmbed(hash) {
  const embed = readEmbedOptions(hash);
  if (embed) {
    document.documentElement.dataset.embed = '';
    if (embed.controls) document.documentElement.dataset.embedControls = '';
    if (embed.theme) setTheme(embed.theme, { remember: false });
    showPresenting(embed.present);
  }
  return embed;
}

/**
 * Shows an embed's side panels: only those its link lists (panels=a,b), by their ids. Says
 * in one text what of its link cannot be used, a listed name that is no panel of this
 * lesson included; null when everything could.
 * @param {NonNullable<ReturnType<typeof readEmbedOptions>>} embed
 * @param {HTMLElement} panels the side column
 */
export function showEmbedPanels(embed, panels) {
  const ids = embed.panels;
  const found = [];
  for (const el of /** @type {HTMLElement[]} */ ([...(panels?.children ?? [])])) {
    if (el.id && ids.includes(el.id)) { el.dataset.embedShown = ''; found.push(el.id); }
  }
  if (found.length) document.documentElement.dataset.embedPanels = '';
  const missing = ids.filter((id) => !found.includes(id)).map((id) => `panels lists "${id}", which is not a panel of this lesson`);
  return embedProblemsText([...embed.problems, ...missing]);
}

// The keys a slide deck or course page moves with, passed on when the embed did nothing with
// them, and the reveal.js command each one is (reveal.js's own keyboard map: arrows move
// right/left/up/down, PageDown/PageUp, Space and n/p next/previous, Home/End the first/last
// slide). Other keys stay in the frame: they are the lesson's, or the browser's.
/** @type {Record<string, { method: string, args?: number[] }>} */
const HOST_KEYS = {
  ArrowRight: { method: 'right' },
  ArrowLeft: { method: 'left' },
  ArrowDown: { method: 'down' },
  ArrowUp: { method: 'up' },
  PageDown: { method: 'next' },
  PageUp: { method: 'prev' },
  ' ': { method: 'next' },
  'Shift+ ': { method: 'prev' },
  n: { method: 'next' },
  p: { method: 'prev' },
  Home: { method: 'slide', args: [0] },
  End: { method: 'slide', args: [Number.MAX_SAFE_INTEGER] },
};
// Keys that scroll a box along one axis: inside a box that scrolls that way they are the box's.
const HORIZONTAL_KEYS = new Set(['ArrowLeft', 'ArrowRight']);
// Focused widgets whose arrows are their own (a tab list, a slider...), even if they let the
// event through.
const ARROW_WIDGETS = '[role=tablist],[role=slider],[role=listbox],[role=menu],[role=menubar],[role=radiogroup],[role=grid],[role=tree],[role=spinbutton]';

/**
 * The host command a key press is, or null when it stays in the frame: a key some handler
 * of the page used (default prevented; handlers that own a key also stop it), a key typed
 * into a field, Space on a button, arrows in a widget or a box that scrolls, any key with
 * Ctrl, Alt or Meta, a key that is no slide key.
 * @param {KeyboardEvent} event
 * @returns {{ method: string, args?: number[] } | null}
 */
export function hostCommandOf(event) {
  if (event.defaultPrevented || event.ctrlKey || event.altKey || event.metaKey || event.isComposing) return null;
  const name = event.key.length === 1 ? event.key.toLowerCase() : event.key;
  const command = HOST_KEYS[event.shiftKey ? `Shift+${name}` : name];
  if (!command) return null;
  // The element the key went to, inside a shadow root too (the code editor's).
  const target = event.composedPath?.()[0] ?? event.target;
  if (!(target instanceof Element)) return command;
  if (target instanceof HTMLElement && target.isContentEditable) return null;
  if (['INPUT', 'TEXTAREA', 'SELECT'].includes(target.tagName)) return null;
  if (name === ' ' && target.closest('button, summary, a[href], [role=button], [role=checkbox], [role=switch], [role=tab]')) return null;
  if (name.startsWith('Arrow') && target.closest(ARROW_WIDGETS)) return null;
  return scrollsWith(target, HORIZONTAL_KEYS.has(name)) ? null : command;
}

// Whether the focused element or a box around it can scroll the key's way (then the key
// scrolls it: a panel column, a long table).
function scrollsWith(/** @type {Element} */ start, /** @type {boolean} */ horizontal) {
  for (let el = start; el && el !== document.documentElement; el = el.parentElement) {
    const overflow = getComputedStyle(el)[horizontal ? 'overflowX' : 'overflowY'];
    if (overflow !== 'auto' && overflow !== 'scroll') continue;
    if (horizontal ? el.scrollWidth > el.clientWidth + 1 : el.scrollHeight > el.clientHeight + 1) return true;
  }
  return false;
}

/**
 * In a framed embed, gives the host page the keys the lesson did not use, and Escape gives
 * the focus back (docs/embed.md, "Keys in a slide"). Each slide key goes to the parent twice,
 * as reveal.js's postMessage API reads it (a JSON string `{"method":"next"}`) and as a plain
 * message for any other host (`{ type: 'wingspline:key', key, code, shiftKey, command }`);
 * Escape blurs the focused element, asks the browser to focus the parent, and posts
 * `{ type: 'wingspline:focus-host' }` so a host can take the focus itself. The messages carry
 * only the key, nothing of the lesson or the person, hence the target origin '*': the host's
 * origin is not known to a frame embedded anywhere.
 * Call it after the page's key map is made, so its listener runs after the key map's.
 * @param {Window} host the parent window
 */
export function passKeysToHost(host) {
  document.addEventListener('keydown', (event) => {
    if (event.key === 'Escape') return;
    const command = hostCommandOf(event);
    if (!command) return;
    event.preventDefault();
    host.postMessage(JSON.stringify(command), '*');
    host.postMessage({ type: 'wingspline:key', key: event.key, code: event.code, shiftKey: event.shiftKey, command: command.method }, '*');
  });
  // Capture: before the canvas's own Escape (which clears the selection and stops there); a
  // dialog open in the frame (the key list) keeps its Escape, which closes it.
  window.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || event.defaultPrevented || document.querySelector('dialog[open]')) return;
    if (document.activeElement instanceof HTMLElement) document.activeElement.blur();
    try { host.focus(); } catch { /* a browser may refuse; the message below lets the host take it */ }
    host.postMessage({ type: 'wingspline:focus-host' }, '*');
  }, true);
}
