// The lesson skeleton. Every lesson page is the same HTML frame plus one lesson module of
// the same shape; runLesson(lesson) wires the rest:
//
//   lesson = {
//     id, title, stateVersion, schema, migrations?, checkState?(state) -> problem|null,
//     defaultState() -> state (with state.view = {cx, cy, zoom}),
//     setup(ctx)                       build panels and controls, register keys
//     compute(state, ctx) -> model     every core call; may throw (bad input)
//     update(model, state, ctx)        refresh the DOM panels (not on pure view changes)
//     draw(painter, model, state, ctx) canvas and SVG drawing, no mathematics
//     handles(model, state) -> [{id, x, y, label, draggable?}]
//     moveHandle(state, id, x, y, model) -> next state | null
//     describe(model, state) -> text for screen readers
//     fitView?(model, stage) -> view; click?(x, y, ctx) -> true if consumed
//     exports?: [{ label, filename, type, make(model, state) }]
//     importers?: { off(text, state, name) -> next state, ... }
//     inspector?: false                 no shell inspector (the lesson has its own inputs)
//     contentFields?: { key: { what, file, export, label(value) } }  large fields kept in
//                                      IndexedDB by content hash (docs/state-format.md)
//   }
//
// ctx (what a lesson may use): api, state (getter), commit(next, opts), setView(view),
// render(), message, keymap, ui {selected, hover, present}, stage, colors, panels, controls,
// setPresenter({ next, prev, playPause, reset, toggleOverlays }) (all optional): binds the
// presenter-remote keys (PageDown/PageUp, Space/k, Home, o/b/.) to the lesson's actions.
// Changing state: ctx.commit(next) recomputes the model first; if the core refuses the new
// state (bad knots, a zero weight...) the message line says why and the old state stays.
//
// Classroom features every lesson gets from the shell (issue 8): the state in the link and
// local storage, undo, JSON/SVG/PNG export and JSON import (file picker and drop), the
// handle inspector (type exact x, y of the selected handle), live announcements of handle
// positions, presentation mode (class .advanced hides a control there), themes, print,
// offline. Markup from files and links is only ever set as text.
import { loadWingspline, WingsplineError } from '../core/wingspline.js';
import { createStore } from './store.js';
import { restoreState, createPersister, readHashCode, readLink } from './persist.js';
import { readEnvelopeResolved, envelopeJson } from './share-link.js';
import { createContentStore } from './content-store.js';
import { checkChange } from './schema.js';
import { createStage } from './stage.js';
import { CanvasPainter, SvgPainter } from './painter.js';
import { createKeymap } from './keymap.js';
import { download, installImport } from './file-io.js';
import { applyStoredTheme, cycleTheme, currentTheme, isPresenting, setPresenting, drawingColors } from './theme.js';
import { registerServiceWorker } from './sw-register.js';
import { h, watchScrollRegions } from './dom.js';

// One line of at most this many characters: a long or multi-line message (a file name, a
// lesson's error text) never pushes the page down.
const MESSAGE_MAX_CHARS = 300;
const oneLine = (text) => {
  const flat = String(text).replace(/\s+/g, ' ').trim();
  return flat.length > MESSAGE_MAX_CHARS ? `${flat.slice(0, MESSAGE_MAX_CHARS - 1)}…` : flat;
};
// Coordinates in announcements and the inspector's placeholder text.
const fmt = (x) => (Object.is(x, -0) ? '0' : String(Number(x.toFixed(3))));

function createMessageLine(el) {
  let timer = null;
  // action: { label, run } adds one button (an offer: "Restore your previous work").
  function show(kind, text, { code, action = null, sticky = kind !== 'info' || !!action } = {}) {
    clearTimeout(timer);
    el.dataset.kind = kind;
    if (code) el.dataset.code = code; else delete el.dataset.code;
    el.setAttribute('role', kind === 'error' ? 'alert' : 'status');
    const close = h('button', { type: 'button', class: 'message-close', 'aria-label': 'Dismiss message', onclick: clear }, '×');
    const offer = action && h('button', { type: 'button', class: 'message-action tool', 'data-message-action': action.id ?? 'action', onclick: () => { clear(); action.run(); } }, action.label);
    el.replaceChildren(h('span', { class: 'message-text' }, oneLine(text)), offer, close);
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
    get text() { return el.hidden ? '' : (el.querySelector('.message-text')?.textContent ?? ''); },
  };
}

function errorText(err) {
  return err?.code ? err.message : `Something went wrong: ${err?.message ?? err}`;
}

export async function runLesson(lesson) {
  applyStoredTheme();
  registerServiceWorker();
  const els = {
    header: document.getElementById('lesson-toolbar'),
    message: document.getElementById('message'),
    canvas: document.getElementById('stage'),
    panels: document.getElementById('panels'),
    controls: document.getElementById('stage-controls'),
    description: document.getElementById('stage-description'),
    announce: document.getElementById('stage-announce'),
  };
  if (!els.announce && els.description) {
    // Handle positions are announced separately from the lesson's description, which the
    // next redraw rewrites ("control point 2 at (1.5, 2)").
    els.announce = h('p', { id: 'stage-announce', class: 'visually-hidden', role: 'status', 'aria-live': 'polite' });
    els.description.after(els.announce);
  }
  const message = createMessageLine(els.message);
  const keymap = createKeymap();

  let api;
  try {
    api = await loadWingspline();
  } catch (err) {
    // A 'core-load-failed' error says what is wrong and what to check (issue 13, item 14).
    message.error(errorText(err), err?.code);
    document.body.dataset.ready = 'failed';
    return null;
  } finally {
    // The template's "Loading the geometry core…" status.
    document.querySelector('.core-loading[data-core-status]')?.remove();
  }

  // Large fields (an imported mesh) live in IndexedDB by content hash; the link refers to them.
  const contents = createContentStore();
  const restored = await restoreState(lesson, { contents });
  // A link that replaced saved work is one undoable step: Undo brings the work back.
  const store = createStore(restored.previous ?? restored.state);
  if (restored.previous) store.replace(restored.state, 'link');
  const persister = createPersister(lesson, { contents, notify: (kind) => sayKept(kind) });
  const ui = { selected: null, hover: null, hoverPoint: null, present: isPresenting() };
  let model = null;
  let autoFit = false; // the default view follows the canvas size until the person pans or zooms
  let frame = 0;
  let colors = drawingColors();

  const ctx = {
    api,
    lesson,
    get state() { return store.state; },
    get model() { return model; },
    commit,
    setView,
    render: scheduleRender,
    refresh,
    message,
    keymap,
    ui,
    panels: els.panels,
    controls: els.controls,
    get colors() { return colors; },
    stage: null,
    store,
  };

  // Check, recompute, then commit: a value the state format would refuse on reload (the
  // schema, with the limits of limits.js) is refused here with a message, and so is a state
  // the core refuses; either way the old state stays, and the panels show it again.
  function commit(next, { history = true, coalesce = null, recompute = true } = {}) {
    const refused = checkChange(lesson.schema, next, store.state, lesson.checkState);
    if (refused) {
      message.error(`Not changed: ${refused}.`, 'out-of-limits');
      refresh();
      return false;
    }
    if (recompute) {
      try {
        model = lesson.compute(next, ctx);
      } catch (err) {
        message.error(errorText(err), err?.code);
        refresh();
        return false;
      }
    }
    store.set(next, { history, coalesce, reason: recompute ? 'edit' : 'view' });
    return true;
  }

  function setView(view) {
    commit({ ...store.state, view }, { history: false, recompute: false });
  }

  let needsPanelUpdate = true;
  store.subscribe((state, reason) => {
    if (reason === 'undo' || reason === 'redo' || reason === 'import' || reason === 'link') {
      try {
        model = lesson.compute(state, ctx);
      } catch (err) {
        message.error(errorText(err), err?.code);
      }
    }
    if (reason !== 'view') needsPanelUpdate = true;
    persister.save(state);
    scheduleRender();
  });

  function refresh() {
    needsPanelUpdate = true;
    scheduleRender();
  }

  function scheduleRender() {
    if (frame) return;
    frame = requestAnimationFrame(renderNow);
  }

  function renderNow() {
    frame = 0;
    const state = store.state;
    if (needsPanelUpdate) {
      needsPanelUpdate = false;
      lesson.update?.(model, state, ctx);
      watchScrollRegions(els.panels?.parentElement ?? document);
      const text = lesson.describe?.(model, state);
      if (text && els.description && els.description.textContent !== text) els.description.textContent = text;
      updateToolbar();
    }
    updateInspector();
    const g = ctx.stage.beginFrame();
    const painter = new CanvasPainter(g, ctx.stage.transform(), { scale: ui.present ? 1.6 : 1, background: colors.background });
    painter.clear();
    lesson.draw(painter, model, state, ctx);
  }

  function svgFigure() {
    const painter = new SvgPainter(ctx.stage.transform(), { scale: ui.present ? 1.6 : 1, background: colors.background });
    painter.clear();
    lesson.draw(painter, model, store.state, ctx);
    return painter.toString();
  }

  // ---------------------------------------------------------------- stage
  const handleCache = { state: null, model: null, list: [] };
  function handles() {
    if (handleCache.state !== store.state || handleCache.model !== model) {
      handleCache.list = lesson.handles ? lesson.handles(model, store.state) : [];
      handleCache.state = store.state;
      handleCache.model = model;
    }
    return handleCache.list;
  }
  let dragId = null;
  ctx.stage = createStage(els.canvas, {
    getView: () => store.state.view,
    // A pan or zoom by the person ends the automatic fitting of the default view.
    setView(view) { autoFit = false; setView(view); },
    getHandles: handles,
    getSelected: () => ui.selected,
    handleScale: () => (ui.present ? 1.6 : 1),
    select(id) {
      ui.selected = id;
      const handle = handles().find((x) => x.id === id);
      if (handle) {
        message.info(`${handle.label} selected at (${fmt(handle.x)}, ${fmt(handle.y)}); arrows move it`);
        announce(handle);
      }
      lesson.onSelect?.(id, ctx);
      refresh();
    },
    hover(id, x, y) {
      const changed = ui.hover !== id;
      ui.hover = id;
      ui.hoverPoint = x === undefined ? null : [x, y];
      // Lessons that tint by the point under the mouse redraw on every move; others only
      // when the hovered handle changes.
      if (changed || lesson.usesHoverPoint) scheduleRender();
    },
    dragStart(id) {
      autoFit = false;
      dragId = id;
    },
    drag(id, x, y) {
      const next = lesson.moveHandle?.(store.state, id, x, y, model);
      if (next) commit(next, { coalesce: `drag:${id}:${dragId}` });
    },
    dragEnd() {
      dragId = null;
      store.endGesture();
      announce(handles().find((x) => x.id === ui.selected));
    },
    // Read when the click happens: a lesson may set its hook in setup, after the stage exists.
    click: (x, y, event) => (lesson.click ? lesson.click(x, y, ctx, event) : false),
    // Resizing clears the canvas: redraw at once, so no frame (or screenshot) shows it blank.
    onResize: () => {
      // Until the person moves the view, the lesson's starting view stays fitted to the
      // canvas while the page settles (panels filling in change the canvas's size).
      if (autoFit && model && lesson.fitView) {
        store.set({ ...store.state, view: lesson.fitView(model, ctx.stage) }, { history: false, reason: 'view' });
      }
      if (model && ctx.stage) renderNow(); else scheduleRender();
    },
  });

  function announce(handle) {
    if (handle && els.announce) els.announce.textContent = `${handle.label} at (${fmt(handle.x)}, ${fmt(handle.y)})`;
  }

  // ---------------------------------------------------------------- inspector
  // The selected handle's exact coordinates as two number fields: keyboard users and
  // homework answers need exact values, not only nudges. Typing goes through moveHandle
  // and commit like a drag, so the core may refuse it with a message.
  const inspector = { root: null, label: null, x: null, y: null };
  function buildInspector() {
    if (lesson.inspector === false || !els.controls || !lesson.moveHandle) return;
    const field = (axis) => h('input', {
      type: 'number', step: 'any', id: `inspect-${axis}`, 'data-axis': axis, disabled: true,
      onchange: () => moveFromInspector(),
      onkeydown: (event) => { if (event.key === 'Enter') moveFromInspector(); },
    });
    inspector.x = field('x');
    inspector.y = field('y');
    inspector.label = h('legend', {}, 'Selected: none');
    inspector.root = h('fieldset', { class: 'handle-inspector', 'aria-describedby': 'inspect-hint' },
      inspector.label,
      h('label', { for: 'inspect-x' }, 'x'), inspector.x,
      h('label', { for: 'inspect-y' }, 'y'), inspector.y,
      h('span', { id: 'inspect-hint', class: 'hint advanced' }, 'Select a point on the drawing ([ and ] on the canvas), then type its coordinates.'));
    els.controls.append(inspector.root);
  }
  function moveFromInspector() {
    const handle = handles().find((x) => x.id === ui.selected);
    if (!handle) return;
    const x = inspector.x.valueAsNumber;
    const y = inspector.y.valueAsNumber;
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      message.error(`${handle.label}: type two numbers for x and y`, 'inspector-not-a-number');
      return;
    }
    if (x === handle.x && y === handle.y) return;
    const next = lesson.moveHandle(store.state, handle.id, x, y, model);
    if (next && commit(next)) {
      store.endGesture();
      const moved = handles().find((h2) => h2.id === handle.id) ?? handle;
      announce(moved);
    } else {
      // Refused: the fields show the handle's value again (the message says why).
      inspector.x.value = String(handle.x);
      inspector.y.value = String(handle.y);
    }
  }
  function updateInspector() {
    if (!inspector.root) return;
    const handle = handles().find((x) => x.id === ui.selected);
    const editable = !!handle && handle.draggable !== false;
    inspector.label.textContent = handle ? `Selected: ${handle.label}` : 'Selected: none';
    for (const [input, value] of [[inspector.x, handle?.x], [inspector.y, handle?.y]]) {
      input.disabled = !editable;
      input.setAttribute('aria-label', `${handle?.label ?? 'selected point'} ${input.dataset.axis}`);
      // Never overwrite what a person is typing.
      if (document.activeElement !== input) input.value = value === undefined ? '' : String(value);
    }
  }

  // ---------------------------------------------------------------- toolbar
  const buttons = {};
  // Presentation mode keeps the essentials (undo, present, keys, reset); the rest is .advanced.
  function toolButton(key, label, onclick, title, { advanced = false } = {}) {
    buttons[key] = h('button', { type: 'button', class: advanced ? 'tool advanced' : 'tool', onclick, title: title ?? label, 'data-action': key }, label);
    return buttons[key];
  }
  function updateToolbar() {
    buttons.undo.disabled = !store.canUndo;
    buttons.redo.disabled = !store.canRedo;
    buttons.theme.textContent = `Theme: ${currentTheme()}`;
    buttons.present.setAttribute('aria-pressed', String(ui.present));
  }

  const exportItems = [
    { label: 'Lesson state (JSON)', filename: `${lesson.id}-state.json`, type: 'application/json',
      make: () => envelopeJson(lesson, store.state) },
    { label: 'Figure (SVG)', filename: `${lesson.id}.svg`, type: 'image/svg+xml', make: svgFigure },
    { label: 'Figure (PNG)', filename: `${lesson.id}.png`, type: 'image/png',
      make: () => new Promise((resolve) => els.canvas.toBlob(resolve, 'image/png')) },
    ...(lesson.exports ?? []),
  ];
  // A disclosure of plain buttons (not an ARIA menu, which would promise arrow-key roving).
  const exportMenu = h('details', { class: 'menu advanced' }, h('summary', { class: 'tool' }, 'Export'),
    h('div', { class: 'menu-items' }, exportItems.map((item) => h('button', {
      type: 'button', 'data-export': typeof item.filename === 'function' ? item.label : item.filename,
      onclick() {
        exportMenu.open = false;
        return runExport(item);
      },
    }, item.label))));
  async function runExport(item) {
    try {
      const content = await item.make(model, store.state, ctx);
      download(typeof item.filename === 'function' ? item.filename(store.state) : item.filename, content, item.type);
    } catch (err) {
      message.error(`Export failed: ${errorText(err)}`);
    }
  }

  const importTypes = ['.json', ...Object.keys(lesson.importers ?? {}).map((ext) => `.${ext}`)];
  // The picker is opened by a real button (visible focus, keyboard); the input stays hidden.
  const fileInput = h('input', { type: 'file', accept: importTypes.join(','), hidden: true, id: 'import-file', tabindex: '-1', 'aria-label': 'Import a file' });

  // Import: the file is read, checked and computed before anything changes; a refusal
  // names the file (as text) and the reason, and the lesson keeps what it had.
  async function importFile({ name, text }) {
    const ext = name.toLowerCase().split('.').pop();
    const refuse = (reason) => { throw new WingsplineError('import-error', reason); };
    try {
      let next;
      if (ext === 'json') {
        let data;
        try { data = JSON.parse(text); } catch { refuse('it is not valid JSON'); }
        let read;
        try { read = await readEnvelopeResolved(lesson, data, { contents }); } catch (err) { refuse(err.message); }
        if (read.problems.length) refuse(`it does not hold a valid state (${read.problems[0]})`);
        next = read.state;
      } else if (lesson.importers?.[ext]) {
        next = lesson.importers[ext](text, store.state, name, ctx);
      } else {
        refuse(`this lesson imports ${importTypes.join(', ')} files`);
      }
      // The same limits as a link read back (a face of 1001 corners, a coordinate of 5e9).
      const outside = checkChange(lesson.schema, next, store.state, lesson.checkState);
      if (outside) refuse(outside);
      const newModel = lesson.compute(next, ctx);
      model = newModel;
      store.replace(next);
      message.info(`Imported ${name}`);
      announceStatus(`Imported ${name}`);
    } catch (err) {
      message.error(`${name} was not imported: ${errorText(err)}`, err?.code ?? 'import-error');
    }
  }
  installImport({ input: fileInput, dropTarget: document.body, onFile: importFile, onError: (text) => message.error(text, 'import-error') });

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
    const field = refs.length ? lesson.contentFields[refs[0].key] : null;
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

  // ---------------------------------------------------------------- kept work
  // What the persister could not keep, said once (issue 13, item 19).
  function sayKept(kind) {
    if (kind === 'storage-full') {
      message.warn('This browser\'s storage for this site is full, so your changes are not saved in this browser any more; they are kept in the link in the address bar (bookmark or copy it).', { code: 'storage-full' });
    } else if (kind === 'content-not-stored') {
      message.warn('The imported file could not be stored in this browser (its storage is full or disabled); keep the file: it may not come back after a reload.', { code: 'content-not-stored' });
    }
  }

  // A link replaced the work shown before it: say so, offer it back (issue 13, item 18).
  function offerPrevious(previous, problem) {
    const text = `${problem ? `${problem} ` : 'Opened the shared link. '}Your previous work is kept: Undo brings it back.`;
    message[problem ? 'warn' : 'info'](text, {
      code: 'previous-work-kept',
      action: { id: 'restore', label: 'Restore your previous work', run: () => restorePrevious(previous) },
    });
  }
  function restorePrevious(previous) {
    try {
      model = lesson.compute(previous, ctx);
      store.replace(previous, 'import');
      message.info('Your previous work is back (Undo shows the link again).');
    } catch (err) {
      message.error(errorText(err), err?.code);
    }
  }

  // A link pasted into the address bar of this open tab (or back/forward between links):
  // loaded like a link opened in a new tab, as one undoable step (issue 13, item 24).
  let following = null;
  async function followAddress() {
    const code = readHashCode();
    if (code === null || code === persister.lastCode || code === following) return;
    following = code;
    try {
      const { state, problem } = await readLink(lesson, code, { contents });
      if (readHashCode() !== code) return; // another address came meanwhile
      const previous = store.state;
      model = lesson.compute(state, ctx);
      store.replace(state, 'link');
      offerPrevious(previous, problem);
    } catch (err) {
      message.warn(`This share link could not be used: ${err.message}. Your work is unchanged.`, { code: 'link-refused' });
      persister.rewrite(store.state);
    } finally {
      following = null;
    }
  }
  window.addEventListener('hashchange', followAddress);
  window.addEventListener('popstate', followAddress);

  function announceStatus(text) {
    if (els.announce) els.announce.textContent = oneLine(text);
  }

  async function togglePresent(on = !isPresenting()) {
    ui.present = on;
    await setPresenting(on);
    colors = drawingColors();
    refresh();
  }
  // Leaving full screen (Escape in the browser) also leaves presentation mode.
  document.addEventListener('fullscreenchange', () => {
    if (!document.fullscreenElement && isPresenting()) togglePresent(false);
  });

  function changeTheme() {
    cycleTheme();
    colors = drawingColors();
    refresh();
    announceStatus(`Theme: ${currentTheme()}`);
  }

  // Print: a clean figure on white paper whatever the screen theme, with its tables.
  let printTheme = null;
  window.addEventListener('beforeprint', () => {
    printTheme = document.documentElement.dataset.theme ?? null;
    document.documentElement.dataset.theme = 'light';
    colors = drawingColors();
    renderNow();
  });
  window.addEventListener('afterprint', () => {
    if (printTheme) document.documentElement.dataset.theme = printTheme; else delete document.documentElement.dataset.theme;
    printTheme = null;
    colors = drawingColors();
    refresh();
  });

  els.header.replaceChildren(
    toolButton('undo', 'Undo', () => store.undo(), 'Undo (Ctrl+Z)'),
    toolButton('redo', 'Redo', () => store.redo(), 'Redo (Ctrl+Shift+Z)'),
    toolButton('share', 'Share link', share, undefined, { advanced: true }),
    exportMenu,
    toolButton('import', 'Import', () => fileInput.click(), 'Import a state (JSON) or a lesson file; dropping a file on the page works too', { advanced: true }),
    fileInput,
    toolButton('theme', 'Theme', changeTheme, 'Theme: system, light, dark (T)', { advanced: true }),
    toolButton('present', 'Present', () => togglePresent(), 'Presentation mode (P)'),
    toolButton('keys', 'Keys ?', () => keymap.showDialog(), 'Keyboard map (?)'),
    toolButton('reset', 'Reset lesson', () => {
      const fresh = lesson.defaultState();
      try {
        model = lesson.compute(fresh, ctx);
        store.replace({ ...fresh, view: lesson.fitView?.(model, ctx.stage) ?? fresh.view }, 'import');
        message.info('Lesson reset to its starting point (Undo brings your work back).');
      } catch (err) {
        message.error(errorText(err), err?.code);
      }
    }, 'Back to the lesson\'s starting point'),
  );

  keymap.add({ keys: ['Ctrl+z'], label: 'undo', group: 'Editing', action: () => store.undo() });
  keymap.add({ keys: ['Ctrl+Shift+z', 'Ctrl+y'], label: 'redo', group: 'Editing', action: () => store.redo() });
  // Handled by the focused canvas (stage.js); listed here so the key map shows them.
  keymap.add({ keys: ['[', ']'], label: 'select the previous / next handle (canvas focused)', group: 'Editing' });
  keymap.add({ keys: ['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown'], label: 'move the selected handle (Shift: finer)', group: 'Editing' });
  keymap.add({ keys: ['p'], label: 'presentation mode on / off', group: 'View', action: () => togglePresent() });
  keymap.add({ keys: ['Escape'], label: 'leave presentation mode', group: 'View', when: () => isPresenting() && !document.querySelector('dialog[open]'), action: () => togglePresent(false) });
  keymap.add({ keys: ['t'], label: 'theme: system, light, dark', group: 'View', action: changeTheme });
  keymap.add({ keys: ['0'], label: 'fit the drawing to the window', group: 'View', action: () => { if (lesson.fitView) setView(lesson.fitView(model, ctx.stage)); } });
  keymap.add({ keys: ['?'], label: 'show this key map', group: 'View', action: () => keymap.showDialog() });
  window.matchMedia?.('(prefers-color-scheme: dark)').addEventListener?.('change', () => { colors = drawingColors(); refresh(); });

  // ---------------------------------------------------------------- presenter remote
  // A presenter remote sends PageDown/PageUp (next/previous), often F5/Escape (start/stop)
  // and b or . (blank screen); these keys reach the lesson's step actions when it has them.
  // Arrows are not bound here: on the focused canvas they move the selected handle.
  let presenterBound = false;
  const presenter = {};
  ctx.setPresenter = (actions) => {
    Object.assign(presenter, actions);
    if (presenterBound) return;
    presenterBound = true;
    const bind = (name, keys, label, when) => keymap.add({ keys, label, group: 'Presenter', when: (e) => !!presenter[name] && (!when || when(e)), action: () => presenter[name]?.() });
    bind('next', ['PageDown', 'n'], 'next step');
    bind('prev', ['PageUp', 'Shift+n'], 'previous step');
    bind('playPause', [' ', 'k'], 'play / pause', (e) => !(e.target instanceof HTMLCanvasElement));
    bind('reset', ['Home'], 'back to the first step', (e) => !(e.target instanceof HTMLCanvasElement));
    bind('toggleOverlays', ['o', 'b', '.'], 'overlays on / off');
  };

  // ---------------------------------------------------------------- start
  try {
    model = lesson.compute(store.state, ctx);
  } catch (err) {
    // A restored state the current core refuses: the work a link replaced if there is one,
    // else the default, and the saved code is kept aside, not written over.
    const fallback = restored.previous ?? lesson.defaultState();
    message.warn(`The ${restored.source === 'link' ? 'link' : 'saved state'} could not be shown (${errorText(err)}); showing ${restored.previous ? 'your previous work' : 'the starting point'}.`);
    if (!restored.previous && restored.source === 'storage') persister.keepSavedAside();
    model = lesson.compute(fallback, ctx);
    store.set(fallback, { history: false, reason: 'view' });
    restored.previous = null;
    restored.problem = null;
  }
  lesson.setup(ctx);
  buildInspector();
  if (restored.previous) offerPrevious(restored.previous, restored.problem);
  else if (restored.problem) message.warn(restored.problem);
  autoFit = restored.source === 'default';
  if (restored.source === 'default' && lesson.fitView) {
    // The default view is fitted to the canvas once its size is known.
    await new Promise((resolve) => requestAnimationFrame(resolve));
    store.set({ ...store.state, view: lesson.fitView(model, ctx.stage) }, { history: false, reason: 'view' });
  }
  refresh();
  renderNow();
  // The URL and storage hold what is shown (a damaged link is replaced by what survived).
  persister.save(store.state);

  // What tests and students' scripts may ask the page (never used by the page itself).
  window.wingspline = {
    api,
    lesson: lesson.id,
    get state() { return structuredClone(store.state); },
    get model() { return model; },
    get selected() { return ui.selected; },
    // x, y: page (client) position to drag with page.mouse; world: the handle's coordinates.
    handles: () => handles().map((x) => ({ id: x.id, label: x.label, world: { x: x.x, y: x.y }, draggable: x.draggable !== false, ...ctx.stage.toClient(x.x, x.y) })),
    toClient: (x, y) => ctx.stage.toClient(x, y),
    shareUrl: () => persister.shareUrl(store.state),
    flush: () => persister.flushNow(),
    message: () => message.text,
    svg: svgFigure,
    ctx,
  };
  document.body.dataset.ready = 'true';
  // ui_load (tests/bench/browser/load.bench.mjs): navigation start to drawn and interactive.
  performance.mark('wingspline-ready');
  return ctx;
}
