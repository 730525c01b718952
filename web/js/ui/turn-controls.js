// @ts-check
// Turn and tilt sliders for a lesson's 3D view (mesh and subdivision lessons). A finger on
// the canvas scrolls the page (app/stage.js), so a phone turns the view with
// these; a mouse may still drag empty space, and the sliders take arrow keys.
import { h } from '../app/dom.js';

const TURN = 3.14; // the turn slider's ends, on its 0.01 grid (so a turn of 0.6 stays 0.6)
export const MAX_TILT = 1.55;

// onTurn({yaw, pitch}): the person moved a slider; onEnd(): they let go of it (one undo
// step per slide where the lesson keeps turns in its history). Returns {root, sync(rotation, enabled)}.
export function createTurnControls(onTurn, { onEnd = () => {} } = {}) {
  const slider = (id, min, max, label) => h('input', { type: 'range', id, min, max, step: 0.01, 'aria-label': label });
  const turn = slider('view-turn', -TURN, TURN, 'Turn the 3D view (radians about the vertical axis)');
  const tilt = slider('view-tilt', -MAX_TILT, MAX_TILT, 'Tilt the 3D view (radians)');
  const label = (text, input) => h('label', {}, text, ' ', input);
  const root = h('span', { class: 'turn-controls' }, label('turn', turn), label('tilt', tilt));
  const changed = () => onTurn({ yaw: Number(turn.value), pitch: Number(tilt.value) });
  turn.addEventListener('input', changed);
  tilt.addEventListener('input', changed);
  turn.addEventListener('change', () => onEnd());
  tilt.addEventListener('change', () => onEnd());
  return {
    root,
    // enabled: false in a 2D view; the sliders stay in place (disabled) so that switching
    // to 3D does not change the canvas's size.
    sync(rotation, enabled = true) {
      turn.disabled = !enabled;
      tilt.disabled = !enabled;
      // The slider shows the turn in (-pi, pi]; a mouse drag may have turned past it.
      turn.value = String(rotation.yaw - 2 * Math.PI * Math.round(rotation.yaw / (2 * Math.PI)));
      tilt.value = String(rotation.pitch);
    },
  };
}
