// @ts-check
// One state object per lesson. The store keeps it, an undo/redo history of edits (view
// changes such as pan and zoom are not edits), and tells subscribers when it changes.
// It knows nothing about the DOM, the URL or the core: the shell wires those.

const HISTORY_LIMIT = 200;

export function createStore(initial) {
  let state = initial;
  let undoStack = [];
  let redoStack = [];
  let lastCoalesce = null;
  const listeners = new Set();

  function notify(reason) {
    for (const fn of listeners) fn(state, reason);
  }

  return {
    get state() { return state; },
    get canUndo() { return undoStack.length > 0; },
    get canRedo() { return redoStack.length > 0; },

    // Replaces the state. history:false for view-only changes; coalesce:'drag-3' merges a
    // gesture's many moves into one undo step.
    set(next, { history = true, coalesce = null, reason = 'edit' } = {}) {
      if (next === state) return;
      if (history) {
        if (!(coalesce && coalesce === lastCoalesce)) {
          undoStack.push(state);
          if (undoStack.length > HISTORY_LIMIT) undoStack.shift();
        }
        redoStack = [];
        lastCoalesce = coalesce;
      }
      state = next;
      notify(reason);
    },

    // Ends a coalesced gesture, so the next drag is its own undo step.
    endGesture() { lastCoalesce = null; },

    undo() {
      if (!undoStack.length) return false;
      redoStack.push(state);
      state = undoStack.pop();
      lastCoalesce = null;
      notify('undo');
      return true;
    },

    redo() {
      if (!redoStack.length) return false;
      undoStack.push(state);
      state = redoStack.pop();
      lastCoalesce = null;
      notify('redo');
      return true;
    },

    // A whole new state from outside (import, share link): one undoable step.
    replace(next, reason = 'import') {
      undoStack.push(state);
      redoStack = [];
      lastCoalesce = null;
      state = next;
      notify(reason);
    },

    subscribe(fn) {
      listeners.add(fn);
      return () => listeners.delete(fn);
    },
  };
}
