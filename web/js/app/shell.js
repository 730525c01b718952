// @ts-check
// The lesson skeleton: runLesson(lesson, options) wires one lesson object to the page frame
// (web/templates/lesson.html). The lesson contract (the Lesson, Ctx and Painter types, what
// each hook receives and when it runs) is written once, in app/contract.js.
//
// This file is the page's lifecycle (start-up, ready) and the one compute path; its parts
// live beside it: render-loop.js (frames on demand, panels when the state changed),
// handles.js (the lesson's handles on the canvas), saved-work.js (the person's saved work,
// other tabs, the History menu), follow-address.js (a link pasted into the open tab),
// embed.js (a page embedded in another), toolbar.js (buttons, export menu, share, theme,
// presentation, reset), inspector.js (exact coordinates of the selected handle),
// import-export.js (files in and out), presenter.js (presenter-remote keys), message-line.js
// (messages and announcements). What sits above the skeleton (the exercise wiring, the
// WebGL2 renderer) comes in through `options` (contract.js, ShellOptions), composed by the
// page entry (web/js/pages/lesson-page.js).
//
// Changing state: every change is computed before it is accepted (accept/commit below, the
// one place lesson.compute runs); if the core refuses the new state (bad knots, a zero
// weight...) the message line says why and the old state stays.
//
// Classroom features every lesson gets from the shell: the state in the link and local
// storage, undo, JSON/SVG/PNG export and JSON import (file picker and drop), the handle
// inspector, live announcements of handle positions, presentation mode (class .advanced
// hides a control there), themes, print, offline. Markup from files and links is only ever
// set as text.
import { loadWingspline } from '../core/wingspline.js';
import { createStore } from './store.js';
import { isFramed } from './persist.js';
import { applyEmbed, showEmbedPanels, passKeysToHost } from './embed.js';
import { openWorkStores, readOwnWork, createSavedWork } from './saved-work.js';
import { createAddressFollower } from './follow-address.js';
import { createHandles } from './handles.js';
import { createRenderLoop } from './render-loop.js';
import { checkChange } from './schema.js';
import { createStage } from './stage.js';
import { labelRects } from './label-layout.js';
import { legendRects, withLegendBand } from './canvas-legend.js';
import { createKeymap } from './keymap.js';
import { applyStoredTheme, isPresenting } from './theme.js';
import { registerServiceWorker } from './sw-register.js';
import { createMessageLine, createAnnouncer, errorText } from './message-line.js';
import { createPresenter } from './presenter.js';
import { createInspector } from './inspector.js';
import { createImportExport } from './import-export.js';
import { createToolbar, createEmbedToolbar } from './toolbar.js';

// Reasons of a whole new state that replaces the saved work (the replaced work goes into the
// history): a link, Reset, an import, a restore, an exercise's Start again.
const REPLACING = ['link', 'reset', 'import', 'restore', 'exercise'];

/**
 * @typedef {import('./contract.js').Lesson} Lesson
 * @typedef {import('./contract.js').State} State
 * @typedef {import('./contract.js').Ctx} Ctx
 * @param {Lesson} lesson
 * @param {import('./contract.js').ShellOptions} [options]
 * @returns {Promise<Ctx | null>}
 */
export async function runLesson(lesson, { exercises = null, gpuRenderer = null } = {}) {
  applyStoredTheme();
  // An embed (embed.js) shows the canvas and its few controls, fitted to the frame.
  const embed = applyEmbed(window.location.hash);
  registerServiceWorker();
  const byId = (id) => /** @type {HTMLElement} */ (document.getElementById(id));
  const els = {
    header: byId('lesson-toolbar'),
    canvas: /** @type {HTMLCanvasElement} */ (byId('stage')),
    panels: byId('panels'),
    controls: byId('stage-controls'),
    description: byId('stage-description'),
  };
  const message = createMessageLine(byId('message'));
  const announcer = createAnnouncer(els.description);
  const keymap = createKeymap();
  // A framed embed passes the slide keys the lesson does not use to its host, and Escape
  // gives the host the focus back (docs/embed.md, "Keys in a slide").
  if (embed && isFramed()) {
    passKeysToHost(window.parent);
    keymap.add({ keys: ['ArrowRight', 'ArrowLeft', 'ArrowDown', 'ArrowUp', 'PageDown', 'PageUp', ' ', 'n', 'p', 'Home', 'End'], label: 'to the slides, when the lesson does not use the key', group: 'In a slide' });
    keymap.add({ keys: ['Escape'], label: 'give the keys back to the slides', group: 'In a slide' });
  }

  let api;
  try {
    // Only the core modules the lesson uses are fetched (lesson.core: 'mesh', 'curves').
    api = await loadWingspline({ parts: lesson.core });
  } catch (err) {
    // A 'core-load-failed' error says what is wrong and what to check.
    message.error(errorText(err), err?.code);
    document.body.dataset.ready = 'failed';
    return null;
  } finally {
    // The template's "Loading the geometry core…" status.
    document.querySelector('.core-loading[data-core-status]')?.remove();
  }

  // A page shown inside another page (a frame without embed=1 too) reads and writes nothing of
  // the person's saved work, whatever its address says: the frame may be hidden, and its
  // offers would be invisible (docs/embed.md).
  const framed = !embed && isFramed();
  const keepsWork = !embed && !framed;
  const { contents, history } = openWorkStores({ keepsWork });
  // An exercise link (#exercise=<id> or #x=<code>, docs/exercises.md) opens the lesson on the
  // exercise's state; the person's own saved work is neither read nor written meanwhile. A
  // link that cannot be used is said, and the saved work is shown as without it.
  const exercise = embed || !exercises ? null : await exercises.open(lesson);
  const restored = exercise?.ready ? exercise.restored : await readOwnWork(lesson, { keepsWork, contents });
  // A link that replaced saved work is one undoable step: Undo brings the work back.
  const store = createStore(restored.previous ?? restored.state);
  if (restored.previous) store.replace(restored.state, 'link');
  // ui.exercise: the kind of the exercise the page shows (a lesson hides what would answer it);
  // ui.exerciseStructure: the structure its walk is predicted on ('half-edge'), else null.
  const ui = { selected: null, hover: null, hoverPoint: null, present: isPresenting(), exercise: null, exerciseStructure: null };
  /** The lesson's view: what its setup returned, handed back to every later hook. */
  let view = {};
  let model = null;
  let modelState = null; // the state `model` was computed from
  /** @type {{ update(): void } | null} */
  let inspector = null; // built after the lesson's own controls
  /** @type {import('./contract.js').ExercisePlayer | null} */
  let player = null; // the exercise player, when the page shows an exercise
  let autoFit = false; // the default view follows the canvas size until the person pans or zooms

  /** @type {Ctx} */
  const ctx = {
    api,
    get state() { return store.state; },
    get model() { return model; },
    commit,
    setView,
    fitView,
    render: () => frames.scheduleRender(),
    refresh: () => frames.refresh(),
    message,
    keymap,
    ui,
    panels: els.panels,
    controls: els.controls,
    get colors() { return frames.colors; },
    stage: /** @type {any} */ (null),
    setPresenter: createPresenter(keymap),
    endGesture: () => store.endGesture(),
  };

  // ---------------------------------------------------------------- computing
  const reportError = (err) => message.error(errorText(err), err?.code);

  // The one place lesson.compute runs. On success the model is the new state's; on a
  // refusal `report` says why (by default on the message line) and the model stays.
  function recompute(state, report = reportError) {
    try {
      model = lesson.compute(view, state, ctx);
      modelState = state;
      return true;
    } catch (err) {
      report(err);
      return false;
    }
  }

  // A whole new state from outside (an import, a link, reset): computed first, then one
  // undoable step.
  function accept(next, reason, report = reportError) {
    const epoch = message.epoch();
    if (!recompute(next, report)) return false;
    store.replace(next, reason);
    message.clearIfBefore(epoch); // what was said of the state this one replaces is stale
    return true;
  }

  // Check, recompute, then commit: a value the state format would refuse on reload (the
  // schema, with the limits of limits.js) is refused here with a message, and so is a state
  // the core refuses; either way the old state stays, and the panels show it again.
  function commit(next, { history = true, coalesce = null, recompute: compute = true } = {}) {
    const epoch = message.epoch();
    const refused = checkChange(lesson.schema, next, store.state, lesson.checkState);
    if (refused) {
      message.error(`Not changed: ${refused}.`, 'out-of-limits');
      refresh();
      return false;
    }
    if (compute && !recompute(next)) {
      refresh();
      return false;
    }
    store.set(next, { history, coalesce, reason: compute ? 'edit' : 'view' });
    // A refusal or warning about an earlier state is stale once an edit is accepted.
    if (compute) message.clearIfBefore(epoch);
    return true;
  }

  function setView(next) {
    commit({ ...store.state, view: next }, { history: false, recompute: false });
  }
  const fittedView = () => (model && lesson.fitView ? lesson.fitView(view, model, ctx.stage) : null);
  function fitView() {
    const fitted = fittedView();
    if (fitted) setView(fitted);
  }

  const saved = createSavedWork({
    lesson, store, keepsWork, keep: keepsWork && !exercise?.ready && !restored.hold, contents, history, restored,
    message, recompute, accept, fitView, files: () => files,
  });
  const { persister } = saved;

  const frames = createRenderLoop({
    lesson, ctx, view: () => view, model: () => model, panels: els.panels, description: els.description,
    player: () => player, toolbar: () => toolbar, inspector: () => inspector,
  });
  const { refresh, scheduleRender, renderNow, svgFigure, recolor } = frames;

  store.subscribe((state, reason) => {
    // Undo and redo bring back a state without a model; everything else computed first.
    if (reason !== 'view' && state !== modelState) recompute(state);
    if (reason !== 'view') refresh(); // (the panels follow the state, not the view)
    // A whole new state from outside replaces the saved work: that goes into the history.
    persister.save(state, { replacing: REPLACING.includes(reason) ? reason : null });
    if (reason !== 'view') player?.stateChanged();
    scheduleRender();
  });

  // ---------------------------------------------------------------- stage
  const handles = createHandles({
    lesson, store, ctx, view: () => view, model: () => model, message, announcer,
    // An embed keeps fitting to its frame until the person pans or zooms.
    dragStarted: () => { if (!embed) autoFit = false; },
  });
  ctx.stage = createStage(els.canvas, {
    ...handles.stageHooks,
    getView: () => store.state.view,
    // A pan or zoom by the person ends the automatic fitting of the default view.
    setView(next) { autoFit = false; setView(next); },
    fitView: lesson.fitView ? () => fitView() : null, // the Fit button on the canvas (none without lesson.fitView)
    // Resizing clears the canvas: redraw at once, so no frame (or screenshot) shows it blank.
    onResize: () => {
      // Until the person moves the view, the lesson's starting view stays fitted to the
      // canvas while the page settles (panels filling in change the canvas's size).
      const fitted = autoFit && fittedView();
      if (fitted) store.set({ ...store.state, view: fitted }, { history: false, reason: 'view' });
      if (model && ctx.stage) renderNow(); else scheduleRender();
    },
    gpuRenderer,
  });

  // ---------------------------------------------------------------- files and toolbar
  const files = createImportExport({
    lesson, contents, pngFigure: async () => withLegendBand(ctx.stage.canvas, await ctx.stage.png(), { ink: frames.colors.ink, background: frames.colors.background }), svgFigure, accept, message,
    hookArgs: () => [view, model, store.state, ctx],
    announceStatus: announcer.status,
  });

  // The state an embed's Reset returns to: its link's state as first shown (set at start).
  let prepared = null;
  function reset() {
    if (player) {
      player.reset();
      return;
    }
    if (embed && prepared) {
      if (!accept(prepared, 'reset')) return;
      autoFit = true;
      fitView();
      message.info('Back to the prepared state (Undo brings your changes back).');
      return;
    }
    if (!accept(lesson.defaultState(), 'reset')) return;
    fitView();
    message.info(`Lesson reset to its starting point (Undo brings your work back${history ? '; so does the History' : ''}).`);
  }

  const toolbar = embed
    ? createEmbedToolbar({ header: els.header, store, persister, keymap, recolor, reset, fitView })
    : createToolbar({
      header: els.header, lesson, store, persister, keymap, message, ui, files, recolor, reset, fitView,
      announceStatus: announcer.status,
      makeExercise: lesson.exercise && exercises ? () => exercises.author({ ctx, lesson, view, message }) : null,
      openHistory: saved.openHistory,
    });

  // ---------------------------------------------------------------- the address
  // (An embed shows the link it was given; its address is the host page's business.) An
  // exercise's page, and any page given an exercise link, opens afresh.
  const address = createAddressFollower({
    lesson, store, persister, contents, message, accept,
    opensAfresh: () => Boolean(player) || Boolean(exercises?.named(window.location.hash)),
  });
  if (!embed) address.listen();

  // ---------------------------------------------------------------- start
  // The lesson builds its panels first; its view is handed to every later hook.
  view = lesson.setup(ctx) ?? {};
  let startProblem = null;
  if (!recompute(store.state, (err) => { startProblem = err; })) {
    // A restored state the current core refuses: the work a link replaced if there is one,
    // else the default, and the saved code is kept aside, not written over.
    const fallback = restored.previous ?? lesson.defaultState();
    if (exercise?.ready) {
      // (the person's own work comes back below, as for any exercise that cannot be shown)
      exercise.refuse(`its drawing cannot be shown (${errorText(startProblem)})`);
    } else {
      message.warn(`The ${restored.source === 'link' ? 'link' : 'saved state'} could not be shown (${errorText(startProblem)}); showing ${restored.previous ? 'your previous work' : 'the starting point'}.`);
      if (!restored.previous && restored.source === 'storage') persister.keepSavedAside(errorText(startProblem));
    }
    recompute(fallback);
    store.set(fallback, { history: false, reason: 'view' });
    restored.previous = null;
    restored.problem = null;
  }
  if (lesson.inspector !== false && els.controls && lesson.moveHandle) {
    inspector = createInspector({ controls: els.controls, selectedHandle: handles.selected, moveTo: handles.moveTo, message });
  }
  if (restored.previous) address.offerPrevious(restored.previous, restored.problem);
  else if (restored.problem) message.warn(restored.problem);
  const embedProblem = embed ? showEmbedPanels(embed, els.panels) : null;
  if (embedProblem) message.warn(restored.problem ? `${embedProblem} ${restored.problem}` : embedProblem, { code: 'embed-setting-refused' });
  autoFit = restored.source === 'default' || Boolean(embed) || restored.source === 'exercise';
  if ((restored.source === 'default' || embed || restored.source === 'exercise') && lesson.fitView) {
    // The default view is fitted to the canvas once its size is known.
    await new Promise((resolve) => requestAnimationFrame(resolve));
    const fitted = fittedView();
    if (fitted) store.set({ ...store.state, view: fitted }, { history: false, reason: 'view' });
  }
  if (exercise) {
    player = exercise.start({ ctx, lesson, view: () => view, panels: els.panels, message, accept, keepInHistory: saved.keepInHistory });
    // An exercise that cannot be played after all (its check does not fit its drawing, the
    // core refused its drawing): the person's own work is shown, and kept again from now on.
    if (!player && exercise.shownOnStart) autoFit = await saved.returnToOwnWork();
  }
  refresh();
  renderNow();
  prepared = store.state;
  // The URL and storage hold what is shown (a damaged link is replaced by what survived); a
  // link that replaced saved work puts that work into the history.
  persister.save(store.state, { replacing: restored.previous ? 'link' : null });
  if (framed && !message.text) message.info('This lesson is shown inside another page: your saved work is neither read nor changed here. Open the lesson in its own tab to work on it.', { code: 'framed' });

  // What tests and students' scripts may ask the page (never used by the page itself).
  // `hooks` is the lesson object, for benchmarks that time its hooks (read when called).
  /** @type {any} */ (window).wingspline = {
    api,
    lesson: lesson.id,
    hooks: lesson,
    get state() { return structuredClone(store.state); },
    get model() { return model; },
    get selected() { return ui.selected; },
    // The lesson's view (what setup returned), for tests that ask what a lesson shows.
    get view() { return view; },
    // x, y: page (client) position to drag with page.mouse; world: the handle's coordinates.
    handles: () => handles.list().map((x) => ({ id: x.id, label: x.label, world: { x: x.x, y: x.y }, draggable: x.draggable !== false, ...ctx.stage.toClient(x.x, x.y) })),
    toClient: (x, y) => ctx.stage.toClient(x, y),
    shareUrl: () => persister.shareUrl(store.state),
    // This lesson's entries of the history, newest first (work-history.js).
    historyEntries: async () => (history ? history.list(lesson.id) : []),
    flush: () => persister.flushNow(),
    message: () => message.text,
    svg: svgFigure,
    ctx,
    // Every label of the last frame on every canvas, and the legends.
    labelRects,
    legendRects,
  };
  document.body.dataset.ready = 'true';
  // ui_load (tests/bench/browser/load.bench.mjs): navigation start to drawn and interactive.
  performance.mark('wingspline-ready');
  return ctx;
}
