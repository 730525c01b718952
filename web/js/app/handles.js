// @ts-check
// The lesson's handles on the canvas: the list (asked of the lesson once per state and
// model), selecting one, hovering, dragging (one undo step per drag), a click on empty
// canvas, and a handle moved to typed coordinates (the inspector). The stage (stage.js)
// finds the handle under a pointer or a key; every move is the lesson's moveHandle, then
// the shell's commit (the one compute path).
import { coordinate } from './message-line.js';

/**
 * @typedef {import('./contract.js').Handle} Handle
 * @param {{
 *   lesson: import('./contract.js').Lesson,
 *   store: ReturnType<typeof import('./store.js').createStore>,
 *   ctx: import('./contract.js').Ctx,
 *   view: () => import('./contract.js').View,
 *   model: () => import('./contract.js').Model,
 *   message: import('./contract.js').MessageLine,
 *   announcer: ReturnType<typeof import('./message-line.js').createAnnouncer>,
 *   dragStarted: () => void,
 * }} parts `dragStarted`: a drag by the person began (the shell stops fitting the view)
 */
export function createHandles({ lesson, store, ctx, view, model, message, announcer, dragStarted }) {
  const { ui } = ctx;
  const cache = { state: null, model: null, list: /** @type {Handle[]} */ ([]) };
  function list() {
    if (cache.state !== store.state || cache.model !== model()) {
      cache.list = lesson.handles ? lesson.handles(view(), model(), store.state) : [];
      cache.state = store.state;
      cache.model = model();
    }
    return cache.list;
  }
  const selected = () => list().find((x) => x.id === ui.selected);

  // A handle typed into the inspector moves like a drag: moveHandle, then commit.
  function moveTo(handle, x, y) {
    const next = lesson.moveHandle?.(view(), store.state, handle.id, x, y, model());
    if (!next || !ctx.commit(next)) return false;
    store.endGesture();
    announcer.handle(list().find((other) => other.id === handle.id) ?? handle);
    return true;
  }

  let dragId = null;
  // What the stage asks and tells about handles (stage.js hooks).
  const stageHooks = {
    getHandles: list,
    getSelected: () => ui.selected,
    handleScale: () => (ui.present ? 1.6 : 1),
    select(id) {
      ui.selected = id;
      const handle = selected();
      if (handle) {
        message.info(`${handle.label} selected at (${coordinate(handle.x)}, ${coordinate(handle.y)}); arrows move it`);
        announcer.handle(handle);
      }
      lesson.onSelect?.(view(), id, ctx);
      ctx.refresh();
    },
    hover(id, x, y) {
      const changed = ui.hover !== id;
      ui.hover = id;
      ui.hoverPoint = x === undefined ? null : [x, y];
      // Lessons that tint by the point under the mouse redraw on every move; others only
      // when the hovered handle changes.
      if (changed || lesson.usesHoverPoint) ctx.render();
    },
    dragStart(id) {
      dragStarted();
      dragId = id;
    },
    drag(id, x, y) {
      const next = lesson.moveHandle?.(view(), store.state, id, x, y, model());
      if (next) ctx.commit(next, { coalesce: `drag:${id}:${dragId}` });
    },
    dragEnd() {
      dragId = null;
      store.endGesture();
      announcer.handle(selected());
    },
    click: (x, y, event) => (lesson.click ? lesson.click(view(), x, y, ctx, event) : false),
  };

  return { list, selected, moveTo, stageHooks };
}
