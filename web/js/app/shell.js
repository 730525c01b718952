// @ts-check
// The lesson skeleton: runLesson(lesson) wires one lesson object to the page frame
// (web/templates/lesson.html). The lesson contract (the Lesson, Ctx and Painter types, what
// each hook receives and when it runs) is written once, in app/contract.js.
//
// This file wires the store, the stage, the render loop and the lesson's hooks; its parts
// live beside it: toolbar.js (buttons, export menu, share, theme, presentation, reset),
// inspector.js (exact coordinates of the selected handle), import-export.js (files in and
// out), presenter.js (presenter-remote keys), message-line.js (messages and announcements).
//
// Changing state: every change is computed before it is accepted (accept/commit below, the
// one place lesson.compute runs); if the core refuses the new state (bad knots, a zero
// weight...) the message line says why and the old state stays.
//
// Classroom features every lesson gets from the shell (issue 8): the state in the link and
// local storage, undo, JSON/SVG/PNG export and JSON import (file picker and drop), the
// handle inspector, live announcements of handle positions, presentation mode (class
// .advanced hides a control there), themes, print, offline. Markup from files and links is
// only ever set as text.
import { loadWingspline } from '../core/wingspline.js';
import { createStore } from './store.js';
import { restoreState, restoreLinkOnly, createPersister, readHashCode, readLink, isFramed } from './persist.js';
import { readEmbedOptions, embedProblemsText } from './share-link.js';
import { createContentStore } from './content-store.js';
import { createDatabase } from './idb.js';
import { createWorkHistory, BUDGET_CHARS } from './work-history.js';
import { decodeRecord } from './saved-record.js';
import { createHistoryMenu } from './history-menu.js';
import { checkChange } from './schema.js';
import { createStage } from './stage.js';
import { CanvasPainter, SvgPainter } from './painter.js';
import { labelRects } from './label-layout.js';
import { legendRects, withLegendBand } from './canvas-legend.js';
import { createKeymap } from './keymap.js';
import { applyStoredTheme, setTheme, showPresenting, isPresenting, drawingColors } from './theme.js';
import { registerServiceWorker } from './sw-register.js';
import { watchScrollRegions } from './dom.js';
import { createMessageLine, createAnnouncer, errorText, coordinate } from './message-line.js';
import { createPresenter } from './presenter.js';
import { createInspector } from './inspector.js';
import { createImportExport } from './import-export.js';
import { createToolbar, createEmbedToolbar } from './toolbar.js';
import { openExercise, startExercise } from '../exercise/session.js';
import { readExerciseLink } from '../exercise/link.js';
import { openAuthorDialog } from '../exercise/author.js';

// Reasons of a whole new state that replaces the saved work (the replaced work goes into the
// history): a link, Reset, an import, a restore, an exercise's Start again.
const REPLACING = ['link', 'reset', 'import', 'restore', 'exercise'];

/**
 * @typedef {import('./contract.js').Lesson} Lesson
 * @typedef {import('./contract.js').State} State
 * @typedef {import('./contract.js').Ctx} Ctx
 * @param {Lesson} lesson
 * @returns {Promise<Ctx | null>}
 */
export async function runLesson(lesson) {
  // An embed (#embed=1&..., docs/embed.md): the canvas and its few controls, fitted to the
  // frame; its theme and presentation mode come from the link and are not remembered; it
  // reads and writes nothing of the person's saved work.
  const embed = readEmbedOptions(window.location.hash);
  applyStoredTheme();
  if (embed) {
    document.documentElement.dataset.embed = '';
    if (embed.controls) document.documentElement.dataset.embedControls = '';
    if (embed.theme) setTheme(embed.theme, { remember: false });
    showPresenting(embed.present);
  }
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

  // A page shown inside another page (a frame without embed=1 too) reads and writes nothing of
  // the person's saved work, whatever its address says: the frame may be hidden, and its
  // offers would be invisible (docs/embed.md).
  const framed = !embed && isFramed();
  const keepsWork = !embed && !framed;
  // Large fields (an imported mesh) live in IndexedDB by content hash; the link refers to
  // them. The history of the person's work lives beside them (work-history.js); the content
  // store never drops a mesh that saved work or the history refers to.
  const database = createDatabase();
  /** @type {any} */
  let history = null;
  const contents = createContentStore({ db: database, referenced: keepsWork ? () => history.referenced() : null, budgetChars: BUDGET_CHARS });
  if (keepsWork) history = createWorkHistory({ db: database, contents });
  // An exercise link (#exercise=<id> or #x=<code>, docs/exercises.md) opens the lesson on the
  // exercise's state; the person's own saved work is neither read nor written meanwhile. A
  // link that cannot be used is said, and the saved work is shown as without it.
  const exercise = embed ? null : await openExercise(lesson);
  const restored = exercise?.ready ? exercise.restored
    : keepsWork ? await restoreState(lesson, { contents }) : await restoreLinkOnly(lesson, { contents });
  // A link that replaced saved work is one undoable step: Undo brings the work back.
  const store = createStore(restored.previous ?? restored.state);
  if (restored.previous) store.replace(restored.state, 'link');
  const persister = createPersister(lesson, {
    contents, history, notify: (kind) => sayKept(kind), keep: keepsWork && !exercise?.ready && !restored.hold,
    base: restored.base, saved: restored.source === 'storage' && !restored.problem ? restored.state : null, summarize: (state) => summaryOf(state), otherTab: (record, info) => takeOtherTab(record, info),
  });
  // Work set aside while a page went away, and unreadable entries of earlier versions, into
  // the history (not awaited: the lesson starts meanwhile).
  history?.sweep().catch(() => {});
  // ui.exercise: the kind of the exercise the page shows (a lesson hides what would answer it).
  const ui = { selected: null, hover: null, hoverPoint: null, present: isPresenting(), exercise: null };
  /** The lesson's view: what its setup returned, handed back to every later hook. */
  let view = {};
  let model = null;
  let modelState = null; // the state `model` was computed from
  /** @type {{ update(): void } | null} */
  let inspector = null; // built after the lesson's own controls
  /** @type {any} */
  let player = null; // the exercise player, when the page shows an exercise
  let autoFit = false; // the default view follows the canvas size until the person pans or zooms
  let frame = 0;
  let colors = drawingColors();

  /** @type {Ctx} */
  const ctx = {
    api,
    get state() { return store.state; },
    get model() { return model; },
    commit,
    setView,
    fitView,
    render: scheduleRender,
    refresh,
    message,
    keymap,
    ui,
    panels: els.panels,
    controls: els.controls,
    get colors() { return colors; },
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

  let needsPanelUpdate = true;
  store.subscribe((state, reason) => {
    // Undo and redo bring back a state without a model; everything else computed first.
    if (reason !== 'view' && state !== modelState) recompute(state);
    if (reason !== 'view') needsPanelUpdate = true;
    // A whole new state from outside replaces the saved work: that goes into the history.
    persister.save(state, { replacing: REPLACING.includes(reason) ? reason : null });
    if (reason !== 'view') player?.stateChanged();
    scheduleRender();
  });

  // ---------------------------------------------------------------- drawing
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
      lesson.update?.(view, model, state, ctx);
      watchScrollRegions(els.panels?.parentElement ?? document);
      const text = player?.description ?? lesson.describe?.(view, model, state);
      if (text && els.description && els.description.textContent !== text) els.description.textContent = text;
      toolbar.update();
    }
    inspector?.update();
    const g = ctx.stage.beginFrame();
    const painter = new CanvasPainter(g, ctx.stage.transform(), { scale: ui.present ? 1.6 : 1, background: colors.background });
    painter.clear();
    lesson.draw(view, painter, model, state, ctx);
    player?.draw(painter, colors);
    painter.finish(); // the labels, placed together (app/label-layout.js), and the legend
    lesson.afterFrame?.(view, model, state, ctx);
  }

  function svgFigure() {
    const painter = new SvgPainter(ctx.stage.transform(), { scale: ui.present ? 1.6 : 1, background: colors.background });
    painter.clear();
    lesson.draw(view, painter, model, store.state, ctx);
    return painter.toString();
  }

  function recolor({ now = false } = {}) {
    colors = drawingColors();
    if (now) renderNow(); else refresh();
  }

  // ---------------------------------------------------------------- stage
  const handleCache = { state: null, model: null, list: [] };
  function handles() {
    if (handleCache.state !== store.state || handleCache.model !== model) {
      handleCache.list = lesson.handles ? lesson.handles(view, model, store.state) : [];
      handleCache.state = store.state;
      handleCache.model = model;
    }
    return handleCache.list;
  }
  const selectedHandle = () => handles().find((x) => x.id === ui.selected);

  // A handle typed into the inspector moves like a drag: moveHandle, then commit.
  function moveTo(handle, x, y) {
    const next = lesson.moveHandle?.(view, store.state, handle.id, x, y, model);
    if (!next || !commit(next)) return false;
    store.endGesture();
    announcer.handle(handles().find((other) => other.id === handle.id) ?? handle);
    return true;
  }

  let dragId = null;
  ctx.stage = createStage(els.canvas, {
    getView: () => store.state.view,
    // A pan or zoom by the person ends the automatic fitting of the default view.
    setView(next) { autoFit = false; setView(next); },
    getHandles: handles,
    getSelected: () => ui.selected,
    handleScale: () => (ui.present ? 1.6 : 1),
    select(id) {
      ui.selected = id;
      const handle = selectedHandle();
      if (handle) {
        message.info(`${handle.label} selected at (${coordinate(handle.x)}, ${coordinate(handle.y)}); arrows move it`);
        announcer.handle(handle);
      }
      lesson.onSelect?.(view, id, ctx);
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
      // An embed keeps fitting to its frame until the person pans or zooms.
      if (!embed) autoFit = false;
      dragId = id;
    },
    drag(id, x, y) {
      const next = lesson.moveHandle?.(view, store.state, id, x, y, model);
      if (next) commit(next, { coalesce: `drag:${id}:${dragId}` });
    },
    dragEnd() {
      dragId = null;
      store.endGesture();
      announcer.handle(selectedHandle());
    },
    click: (x, y, event) => (lesson.click ? lesson.click(view, x, y, ctx, event) : false),
    fitView: lesson.fitView ? () => fitView() : null, // the Fit button on the canvas (none without lesson.fitView)
    // Resizing clears the canvas: redraw at once, so no frame (or screenshot) shows it blank.
    onResize: () => {
      // Until the person moves the view, the lesson's starting view stays fitted to the
      // canvas while the page settles (panels filling in change the canvas's size).
      const fitted = autoFit && fittedView();
      if (fitted) store.set({ ...store.state, view: fitted }, { history: false, reason: 'view' });
      if (model && ctx.stage) renderNow(); else scheduleRender();
    },
  });

  // ---------------------------------------------------------------- files and toolbar
  const files = createImportExport({
    lesson, contents, pngFigure: async () => withLegendBand(ctx.stage.canvas, await ctx.stage.png(), { ink: colors.ink, background: colors.background }), svgFigure, accept, message,
    hookArgs: () => [view, model, store.state, ctx],
    announceStatus: announcer.status,
  });

  // The state an embed's Reset returns to: its link's state as first shown (set at start).
  let prepared = null;
  function reset() {
    if (player) {
      const drawing = store.state;
      if (!accept(player.initialState, 'exercise')) return;
      keepExerciseDrawing(drawing);
      fitView();
      message.info('Back to the exercise\'s starting drawing (Undo brings your changes back).');
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
      makeExercise: lesson.exercise ? () => openAuthorDialog({ ctx, lesson, view, message }) : null,
      openHistory: history ? createHistoryMenu({ lesson, history, restore: restoreEntry, forget: forgetEverything }) : null,
    });

  // ---------------------------------------------------------------- kept work and links
  // What the persister could not keep, said once (issue 13, item 19).
  function sayKept(kind) {
    if (kind === 'storage-full') {
      message.warn('This browser\'s storage for this site is full, so your changes are not saved in this browser any more; they are kept in the link in the address bar (bookmark or copy it).', { code: 'storage-full' });
    } else if (kind === 'content-not-stored') {
      message.warn('The imported file could not be stored in this browser (its storage is full or disabled); keep the file: it may not come back after a reload.', { code: 'content-not-stored' });
    } else if (kind === 'too-long') {
      // An imported mesh kept inline (no IndexedDB here): the reader would refuse it on the
      // next visit, so it is not saved; the earlier work stays saved.
      const field = Object.entries(lesson.contentFields ?? {}).find(([key]) => store.state?.[key]);
      const item = field && files.exportItems.find((x) => x.filename === field[1].export);
      const name = field ? field[1].label?.(store.state[field[0]]) : null;
      message.warn(`${name ? `"${name}"` : 'This state'} is too large to keep in this browser here (it has no IndexedDB: a private window?), so it will be gone after a reload; your earlier saved work is kept. Keep ${field?.[1].file ?? 'the file'} to open it again.`, {
        code: 'too-long-to-keep',
        action: item ? { id: 'export', label: `Export ${field?.[1].file ?? 'the file'}`, run: () => files.runExport(item) } : null,
      });
    }
  }

  // ---------------------------------------------------------------- the history
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
    } else if (byId('message').dataset.code !== 'work-set-aside') {
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

  // An exercise's drawing before Start again / Reset: into the history.
  function keepExerciseDrawing(drawing) {
    if (!history || !exercise?.exercise) return;
    persister.shareLink(drawing).then(({ url }) => history.add({
      lesson: lesson.id, reason: 'exercise', summary: `your drawing in the exercise "${exercise.exercise.title}"`,
      code: new URLSearchParams(new URL(url).hash.slice(1)).get('s'),
    })).catch(() => {});
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

  // A link replaced the work shown before it: say so, offer it back (issue 13, item 18).
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

  // A link pasted into the address bar of this open tab (or back/forward between links):
  // loaded like a link opened in a new tab, as one undoable step (issue 13, item 24).
  let following = null;
  async function followAddress() {
    const code = readHashCode();
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
      if (readHashCode() !== code) return; // another address came meanwhile
      const previous = store.state;
      if (accept(read.state, 'link', refuse)) offerPrevious(previous, read.problem);
    } finally {
      following = null;
    }
  }
  // (An embed shows the link it was given; its address is the host page's business.) An
  // exercise's page, and any page given an exercise link, opens afresh: the exercise's
  // progress is kept, and the lesson's own saved work is read as the page starts.
  // (Edits not yet written are written first, the reload must not drop them; writing puts the
  // state's link in the address bar, so the address that came is put back before reloading.)
  const reloadKeeping = () => {
    const target = window.location.href;
    persister.flushNow().finally(() => {
      window.history.replaceState(window.history.state, '', target);
      window.location.reload();
    });
  };
  if (!embed) {
    const follow = () => (player || readExerciseLink(window.location.hash) ? reloadKeeping() : followAddress());
    window.addEventListener('hashchange', follow);
    window.addEventListener('popstate', follow);
  }

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
    inspector = createInspector({ controls: els.controls, selectedHandle, moveTo, message });
  }
  if (restored.previous) offerPrevious(restored.previous, restored.problem);
  else if (restored.problem) message.warn(restored.problem);
  const embedProblem = embed ? embedProblemsText([...embed.problems, ...showEmbedPanels(embed.panels)]) : null;
  if (embedProblem) message.warn(restored.problem ? `${embedProblem} ${restored.problem}` : embedProblem, { code: 'embed-setting-refused' });
  autoFit = restored.source === 'default' || Boolean(embed) || restored.source === 'exercise';
  if ((restored.source === 'default' || embed || restored.source === 'exercise') && lesson.fitView) {
    // The default view is fitted to the canvas once its size is known.
    await new Promise((resolve) => requestAnimationFrame(resolve));
    const fitted = fittedView();
    if (fitted) store.set({ ...store.state, view: fitted }, { history: false, reason: 'view' });
  }
  if (exercise) {
    player = startExercise(exercise, { ctx, lesson, view: () => view, panels: els.panels, message, reset });
    // An exercise that cannot be played after all (its check does not fit its drawing, the
    // core refused its drawing): the person's own work is shown, and kept again from now on.
    if (!player && exercise.shownOnStart) await returnToOwnWork();
  }
  refresh();
  renderNow();
  prepared = store.state;
  // The URL and storage hold what is shown (a damaged link is replaced by what survived); a
  // link that replaced saved work puts that work into the history.
  persister.save(store.state, { replacing: restored.previous ? 'link' : null });
  if (framed && !message.text) message.info('This lesson is shown inside another page: your saved work is neither read nor changed here. Open the lesson in its own tab to work on it.', { code: 'framed' });

  // The person's own work, as a plain lesson page would show it (with what it would say
  // about it), after an exercise that could not be played; saving resumes. A saved state
  // the core refuses is kept aside first, as at the start, never written over.
  async function returnToOwnWork() {
    // (a framed page reads nothing of the person's work, and keeps nothing)
    const own = keepsWork ? await restoreState(lesson, { contents }) : await restoreLinkOnly(lesson, { contents });
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
    autoFit = own.source === 'default' || state !== own.state;
    if (autoFit) fitView();
  }

  // An embed's side panels: only those its link lists (panels=a,b), by their ids; the names
  // that are no panel of this lesson come back as sentences.
  function showEmbedPanels(ids) {
    const found = [];
    for (const el of /** @type {HTMLElement[]} */ ([...(els.panels?.children ?? [])])) {
      if (el.id && ids.includes(el.id)) { el.dataset.embedShown = ''; found.push(el.id); }
    }
    if (found.length) document.documentElement.dataset.embedPanels = '';
    return ids.filter((id) => !found.includes(id)).map((id) => `panels lists "${id}", which is not a panel of this lesson`);
  }

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
    handles: () => handles().map((x) => ({ id: x.id, label: x.label, world: { x: x.x, y: x.y }, draggable: x.draggable !== false, ...ctx.stage.toClient(x.x, x.y) })),
    toClient: (x, y) => ctx.stage.toClient(x, y),
    shareUrl: () => persister.shareUrl(store.state),
    // This lesson's entries of the history, newest first (work-history.js).
    historyEntries: async () => (history ? history.list(lesson.id) : []),
    flush: () => persister.flushNow(),
    message: () => message.text,
    svg: svgFigure,
    ctx,
    // Every label of the last frame on every canvas, and the legends (issue 18).
    labelRects,
    legendRects,
  };
  document.body.dataset.ready = 'true';
  // ui_load (tests/bench/browser/load.bench.mjs): navigation start to drawn and interactive.
  performance.mark('wingspline-ready');
  return ctx;
}
