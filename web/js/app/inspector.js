// @ts-check
// The handle inspector: the selected handle's exact coordinates as two number fields.
// Keyboard users and homework answers need exact values, not only nudges. Typing goes
// through the lesson's moveHandle and commit like a drag (the shell's moveTo), so the core
// may refuse it with a message.
import { h } from './dom.js';

/**
 * @param {{
 *   controls: HTMLElement,
 *   selectedHandle: () => import('./contract.js').Handle | undefined,
 *   moveTo: (handle: import('./contract.js').Handle, x: number, y: number) => boolean,
 *   message: import('./contract.js').MessageLine,
 * }} parts
 * @returns {{ update(): void }}
 */
export function createInspector({ controls, selectedHandle, moveTo, message }) {
  const field = (axis) => h('input', {
    type: 'number', step: 'any', id: `inspect-${axis}`, 'data-axis': axis, disabled: true,
    onchange: () => moveFromInspector(),
    onkeydown: (event) => { if (event.key === 'Enter') moveFromInspector(); },
  });
  const x = /** @type {HTMLInputElement} */ (field('x'));
  const y = /** @type {HTMLInputElement} */ (field('y'));
  const label = h('legend', {}, 'Selected: none');
  controls.append(h('fieldset', { class: 'handle-inspector', 'aria-describedby': 'inspect-hint' },
    label,
    h('label', { for: 'inspect-x' }, 'x'), x,
    h('label', { for: 'inspect-y' }, 'y'), y,
    h('span', { id: 'inspect-hint', class: 'hint advanced' }, 'Select a point on the drawing ([ and ] on the canvas), then type its coordinates.')));

  function moveFromInspector() {
    const handle = selectedHandle();
    if (!handle) return;
    const nx = x.valueAsNumber;
    const ny = y.valueAsNumber;
    if (!Number.isFinite(nx) || !Number.isFinite(ny)) {
      message.error(`${handle.label}: type two numbers for x and y`, 'inspector-not-a-number');
      return;
    }
    if (nx === handle.x && ny === handle.y) return;
    if (!moveTo(handle, nx, ny)) {
      // Refused: the fields show the handle's value again (the message says why).
      x.value = String(handle.x);
      y.value = String(handle.y);
    }
  }

  return {
    update() {
      const handle = selectedHandle();
      const editable = !!handle && handle.draggable !== false;
      label.textContent = handle ? `Selected: ${handle.label}` : 'Selected: none';
      const show = (input, value) => {
        input.disabled = !editable;
        input.setAttribute('aria-label', `${handle?.label ?? 'selected point'} ${input.dataset.axis}`);
        // Never overwrite what a person is typing.
        if (document.activeElement !== input) input.value = value === undefined ? '' : String(value);
      };
      show(x, handle?.x);
      show(y, handle?.y);
    },
  };
}
