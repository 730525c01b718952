// @ts-check
// A presenter remote sends PageDown/PageUp (next/previous), often F5/Escape (start/stop)
// and b or . (blank screen); these keys reach the lesson's step actions when it has them
// (ctx.setPresenter in the lesson's setup). Arrows are not bound here: on the focused
// canvas they move the selected handle.

/**
 * @param {import('./contract.js').Keymap} keymap
 * @returns {(actions: import('./contract.js').PresenterActions) => void}
 */
export function createPresenter(keymap) {
  let bound = false;
  /** @type {import('./contract.js').PresenterActions} */
  const actions = {};
  return (more) => {
    Object.assign(actions, more);
    if (bound) return;
    bound = true;
    const bind = (name, keys, label, when = null) => keymap.add({ keys, label, group: 'Presenter', when: (e) => !!actions[name] && (!when || when(e)), action: () => actions[name]?.() });
    bind('next', ['PageDown', 'n'], 'next step');
    bind('prev', ['PageUp', 'Shift+n'], 'previous step');
    bind('playPause', [' ', 'k'], 'play / pause', (e) => !(e.target instanceof HTMLCanvasElement));
    bind('reset', ['Home'], 'back to the first step', (e) => !(e.target instanceof HTMLCanvasElement));
    bind('toggleOverlays', ['o', 'b', '.'], 'overlays on / off');
  };
}
