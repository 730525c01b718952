// @ts-check
// What the page says to the person: the message line under the toolbar (info, warnings,
// errors, one offered action) and the live region that announces handle positions and
// status changes to screen readers.
import { h, setChildren } from './dom.js';

// One line of at most this many characters: a long or multi-line message (a file name, a
// lesson's error text) never pushes the page down.
const MESSAGE_MAX_CHARS = 300;
export const oneLine = (text) => {
  const flat = String(text).replace(/\s+/g, ' ').trim();
  return flat.length > MESSAGE_MAX_CHARS ? `${flat.slice(0, MESSAGE_MAX_CHARS - 1)}…` : flat;
};

// Coordinates in announcements and messages.
export const coordinate = (x) => (Object.is(x, -0) ? '0' : String(Number(x.toFixed(3))));

// A refusal with a stable code carries words for a student; anything else is a bug, said so.
export function errorText(err) {
  return err?.code ? err.message : `Something went wrong: ${err?.message ?? err}`;
}

/** @returns {import('./contract.js').MessageLine} */
export function createMessageLine(el) {
  let timer = null;
  // A message goes when it goes stale. Every message shown gets the next serial
  // number; epoch() is the serial of the next one, and clearIfBefore(e) clears a message
  // shown before e (a refusal or a warning about a state that a later accepted change
  // replaced), never one shown since (a warning about the change just accepted).
  let serial = 0;
  let shown = -1;
  // action: { label, run } adds one button (an offer: "Restore your previous work").
  function show(kind, text, { code = undefined, action = null, sticky = kind !== 'info' || !!action } = {}) {
    clearTimeout(timer);
    shown = serial;
    serial += 1;
    el.dataset.kind = kind;
    if (code) el.dataset.code = code; else delete el.dataset.code;
    el.setAttribute('role', kind === 'error' ? 'alert' : 'status');
    const close = h('button', { type: 'button', class: 'message-close', 'aria-label': 'Dismiss message', onclick: clear }, '×');
    const offer = action && h('button', { type: 'button', class: 'message-action tool', 'data-message-action': action.id ?? 'action', onclick: () => { clear(); action.run(); } }, action.label);
    setChildren(el, h('span', { class: 'message-text' }, oneLine(text)), offer, close); // offer may be null: no "null" text
    el.hidden = false;
    if (!sticky) timer = setTimeout(clear, 4000);
  }
  function clear() {
    el.hidden = true;
    el.replaceChildren();
    delete el.dataset.kind;
    delete el.dataset.code;
  }
  return {
    info: (text, options) => show('info', text, options),
    warn: (text, options) => show('warn', text, options),
    error: (text, code) => show('error', text, { code }),
    clear,
    epoch: () => serial,
    clearIfBefore(epoch) { if (!el.hidden && shown < epoch) clear(); },
    get text() { return el.hidden ? '' : (el.querySelector('.message-text')?.textContent ?? ''); },
  };
}

// Handle positions are announced separately from the lesson's description, which the next
// redraw rewrites ("control point 2 at (1.5, 2)").
export function createAnnouncer(description) {
  let el = document.getElementById('stage-announce');
  if (!el && description) {
    el = h('p', { id: 'stage-announce', class: 'visually-hidden', role: 'status', 'aria-live': 'polite' });
    description.after(el);
  }
  return {
    handle(handle) {
      if (handle && el) el.textContent = `${handle.label} at (${coordinate(handle.x)}, ${coordinate(handle.y)})`;
    },
    status(text) {
      if (el) el.textContent = oneLine(text);
    },
  };
}
