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
//   }
//
// ctx (what a lesson may use): api, state (getter), commit(next, opts), setView(view),
// render(), message, keymap, ui {selected, hover, present}, stage, colors, panels, controls.
// Changing state: ctx.commit(next) recomputes the model first; if the core refuses the new
// state (bad knots, a zero weight...) the message line says why and the old state stays.
import { loadWingspline } from '../core/wingspline.js';
import { createStore } from './store.js';
import { restoreState, createPersister } from './persist.js';
import { readEnvelope, envelope } from './share-link.js';
import { createStage } from './stage.js';
import { CanvasPainter, SvgPainter } from './painter.js';
import { createKeymap } from './keymap.js';
import { download, installImport } from './file-io.js';
import { applyStoredTheme, cycleTheme, currentTheme, isPresenting, setPresenting, drawingColors } from './theme.js';
import { registerServiceWorker } from './sw-register.js';
import { h } from './dom.js';

function createMessageLine(el) {
  let timer = null;
  function show(kind, text, { code, sticky = kind !== 'info' } = {}) {
    clearTimeout(timer);
    el.dataset.kind = kind;
    if (code) el.dataset.code = code; else delete el.dataset.code;
    el.setAttribute('role', kind === 'error' ? 'alert' : 'status');
    const close = h('button', { type: 'button', class: 'message-close', 'aria-label': 'Dismiss message', onclick: clear }, '×');
    el.replaceChildren(h('span', { class: 'message-text' }, text), close);
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
    info: (text) => show('info', text),
    warn: (text) => show('warn', text),
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
  };
  const message = createMessageLine(els.message);
  const keymap = createKeymap();

  let api;
  try {
    api = await loadWingspline();
  } catch (err) {
    message.error(`The WebAssembly core could not be loaded (${err.message}). Try reloading the page.`);
    document.body.dataset.ready = 'failed';
    return null;
  }

  const restored = await restoreState(lesson);
  const store = createStore(restored.state);
  const persister = createPersister(lesson);
  const ui = { selected: null, hover: null, hoverPoint: null, present: isPresenting() };
  let model = null;
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

  // Recompute first; only a state the core accepts is committed.
  function commit(next, { history = true, coalesce = null, recompute = true } = {}) {
    if (recompute) {
      try {
        model = lesson.compute(next, ctx);
      } catch (err) {
        message.error(errorText(err), err?.code);
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
    if (reason === 'undo' || reason === 'redo' || reason === 'import') {
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
      const text = lesson.describe?.(model, state);
      if (text && els.description && els.description.textContent !== text) els.description.textContent = text;
      updateToolbar();
    }
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
    setView,
    getHandles: handles,
    getSelected: () => ui.selected,
    handleScale: () => (ui.present ? 1.6 : 1),
    select(id) {
      ui.selected = id;
      const handle = handles().find((x) => x.id === id);
      if (handle) message.info(`${handle.label} selected at (${handle.x.toFixed(3)}, ${handle.y.toFixed(3)}); arrows move it`);
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
    dragStart(id) { dragId = id; },
    drag(id, x, y) {
      const next = lesson.moveHandle?.(store.state, id, x, y, model);
      if (next) commit(next, { coalesce: `drag:${id}:${dragId}` });
    },
    dragEnd() {
      dragId = null;
      store.endGesture();
      const handle = handles().find((x) => x.id === ui.selected);
      if (handle && els.description) els.description.textContent = `${handle.label} at (${handle.x.toFixed(3)}, ${handle.y.toFixed(3)})`;
    },
    click: lesson.click ? (x, y, event) => lesson.click(x, y, ctx, event) : null,
    // Resizing clears the canvas: redraw at once, so no frame (or screenshot) shows it blank.
    onResize: () => { if (model && ctx.stage) renderNow(); else scheduleRender(); },
  });

  // ---------------------------------------------------------------- toolbar
  const buttons = {};
  function toolButton(key, label, onclick, title) {
    buttons[key] = h('button', { type: 'button', class: 'tool', onclick, title: title ?? label, 'data-action': key }, label);
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
      make: () => JSON.stringify(envelope(lesson, store.state), null, 2) + '\n' },
    { label: 'Figure (SVG)', filename: `${lesson.id}.svg`, type: 'image/svg+xml', make: svgFigure },
    { label: 'Figure (PNG)', filename: `${lesson.id}.png`, type: 'image/png',
      make: () => new Promise((resolve) => els.canvas.toBlob(resolve, 'image/png')) },
    ...(lesson.exports ?? []),
  ];
  const exportMenu = h('details', { class: 'menu' }, h('summary', { class: 'tool' }, 'Export'),
    h('div', { class: 'menu-items', role: 'menu' }, exportItems.map((item) => h('button', {
      type: 'button', role: 'menuitem', 'data-export': item.filename,
      async onclick() {
        exportMenu.open = false;
        try {
          const content = await item.make(model, store.state, ctx);
          download(typeof item.filename === 'function' ? item.filename(store.state) : item.filename, content, item.type);
        } catch (err) {
          message.error(`Export failed: ${errorText(err)}`);
        }
      },
    }, item.label))));

  const importTypes = ['.json', ...Object.keys(lesson.importers ?? {}).map((ext) => `.${ext}`)];
  const fileInput = h('input', { type: 'file', accept: importTypes.join(','), class: 'visually-hidden', id: 'import-file', 'aria-label': 'Import a file' });

  function importFile({ name, text }) {
    const ext = name.toLowerCase().split('.').pop();
    try {
      let next;
      if (ext === 'json') {
        let data;
        try { data = JSON.parse(text); } catch { throw new Error(`${name} is not valid JSON`); }
        const { state, problems } = readEnvelope(lesson, data);
        if (problems.length) throw new Error(`${name} does not hold a valid state: ${problems[0]}`);
        next = state;
      } else if (lesson.importers?.[ext]) {
        next = lesson.importers[ext](text, store.state, name, ctx);
      } else {
        throw new Error(`${name}: this lesson imports ${importTypes.join(', ')} files`);
      }
      const newModel = lesson.compute(next, ctx);
      model = newModel;
      store.replace(next);
      message.info(`Imported ${name}`);
    } catch (err) {
      message.error(`${name} was not imported: ${errorText(err)}`, err?.code ?? 'import-error');
    }
  }
  installImport({ input: fileInput, dropTarget: document.body, onFile: importFile, onError: (text) => message.error(text, 'import-error') });

  async function share() {
    const url = await persister.shareUrl(store.state);
    try {
      await navigator.clipboard.writeText(url);
      message.info('Link copied: it opens this lesson exactly as you see it now.');
    } catch {
      message.info('The address bar holds the link to this exact state; copy it from there.');
    }
    return url;
  }

  async function togglePresent() {
    ui.present = !isPresenting();
    await setPresenting(ui.present);
    colors = drawingColors();
    refresh();
  }

  els.header.replaceChildren(
    toolButton('undo', 'Undo', () => store.undo(), 'Undo (Ctrl+Z)'),
    toolButton('redo', 'Redo', () => store.redo(), 'Redo (Ctrl+Shift+Z)'),
    toolButton('share', 'Share link', share),
    exportMenu,
    h('label', { class: 'tool', for: 'import-file' }, 'Import'), fileInput,
    toolButton('theme', 'Theme', () => { cycleTheme(); colors = drawingColors(); refresh(); }),
    toolButton('present', 'Present', togglePresent, 'Presentation mode (P)'),
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
  keymap.add({ keys: ['p'], label: 'presentation mode on / off', group: 'View', action: togglePresent });
  keymap.add({ keys: ['t'], label: 'theme: system, light, dark', group: 'View', action: () => { cycleTheme(); colors = drawingColors(); refresh(); } });
  keymap.add({ keys: ['0'], label: 'fit the drawing to the window', group: 'View', action: () => { if (lesson.fitView) setView(lesson.fitView(model, ctx.stage)); } });
  keymap.add({ keys: ['?'], label: 'show this key map', group: 'View', action: () => keymap.showDialog() });
  window.matchMedia?.('(prefers-color-scheme: dark)').addEventListener?.('change', () => { colors = drawingColors(); refresh(); });

  // ---------------------------------------------------------------- start
  try {
    model = lesson.compute(store.state, ctx);
  } catch (err) {
    // A stored state the current core refuses: fall back to the default, say so.
    message.warn(`The saved state could not be shown (${errorText(err)}); showing the starting point.`);
    const fresh = lesson.defaultState();
    model = lesson.compute(fresh, ctx);
    store.set(fresh, { history: false, reason: 'view' });
  }
  lesson.setup(ctx);
  if (restored.problem) message.warn(restored.problem);
  if (restored.source === 'default' && lesson.fitView) {
    // The default view is fitted to the canvas once its size is known.
    await new Promise((resolve) => requestAnimationFrame(resolve));
    store.set({ ...store.state, view: lesson.fitView(model, ctx.stage) }, { history: false, reason: 'view' });
  }
  refresh();
  renderNow();

  // What tests and students' scripts may ask the page (never used by the page itself).
  window.wingspline = {
    api,
    lesson: lesson.id,
    get state() { return structuredClone(store.state); },
    get model() { return model; },
    get selected() { return ui.selected; },
    handles: () => handles().map((x) => ({ id: x.id, label: x.label, x: x.x, y: x.y, ...ctx.stage.toClient(x.x, x.y) })),
    toClient: (x, y) => ctx.stage.toClient(x, y),
    shareUrl: () => persister.shareUrl(store.state),
    flush: () => persister.flushNow(),
    message: () => message.text,
    svg: svgFigure,
    ctx,
  };
  document.body.dataset.ready = 'true';
  return ctx;
}
