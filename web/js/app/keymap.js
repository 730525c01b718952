// @ts-check
// Keyboard map of a page: the lesson and the shell register actions; one listener runs
// them; `?` opens a dialog that lists them (built from the same registry, so the list is
// always right). Keys typed into a form field are left to the field.

export function createKeymap() {
  const bindings = [];
  // Whether each panel a binding belongs to is rendered, as a ResizeObserver last saw it (a
  // panel under display: none has no box: size 0). Asking the element itself
  // (getClientRects, checkVisibility) brings the page's style and layout up to date first: a
  // key pressed before the last frame's marks were laid out (a remote held down) then laid
  // out the whole page in the key handler. Until the observer has seen a panel, it is asked.
  const seenShown = new Map();
  const sizes = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver((entries) => {
    for (const e of entries) seenShown.set(e.target, e.contentRect.width > 0 || e.contentRect.height > 0 || e.target.getClientRects().length > 0);
  });
  const shown = (el) => seenShown.get(el) ?? el.getClientRects().length > 0;
  let dialog = null;
  let opener = null;

  function describeKey(k) {
    return k.replace('ArrowRight', '→').replace('ArrowLeft', '←').replace('ArrowUp', '↑').replace('ArrowDown', '↓')
      .replace(' ', 'Space');
  }

  function matches(binding, event) {
    return binding.keys.some((k) => {
      const parts = k.split('+');
      const key = parts.pop();
      const want = new Set(parts);
      if (want.has('Ctrl') !== (event.ctrlKey || event.metaKey)) return false;
      if (want.has('Shift') && !event.shiftKey) return false;
      if (want.has('Alt') !== event.altKey) return false;
      // 'n' and 'Shift+n' are different keys (next / previous step); '?' needs no Shift+.
      if (!want.has('Shift') && event.shiftKey && /^[a-z]$/i.test(key)) return false;
      return event.key === key || event.key.toLowerCase() === key.toLowerCase() && key.length === 1;
    });
  }

  function onKeyDown(event) {
    // The element the key went to, inside a shadow root too (the code editor's), where
    // event.target is only the shadow root's host.
    const target = event.composedPath?.()[0] ?? event.target;
    if (target instanceof HTMLElement && (target.isContentEditable || ['INPUT', 'TEXTAREA', 'SELECT'].includes(target.tagName))) {
      if (event.key !== 'Escape') return;
    }
    // Buttons keep Space and Enter for themselves.
    if (target instanceof HTMLButtonElement && (event.key === ' ' || event.key === 'Enter')) return;
    for (const b of bindings) {
      if (!b.action || (b.when && !b.when(event))) continue;
      if (!matches(b, event)) continue;
      // A binding of a panel acts only while the panel is shown (an embed without it: the
      // key is then free, for the slides around the embed).
      if (b.shownWith && !shown(b.shownWith)) continue;
      event.preventDefault();
      b.action(event);
      return;
    }
  }

  function showDialog() {
    if (!dialog) {
      dialog = document.createElement('dialog');
      dialog.className = 'keymap-dialog';
      dialog.setAttribute('aria-labelledby', 'keymap-title');
      // Focus goes back to where it was (the canvas, a button) when the dialog closes.
      dialog.addEventListener('close', () => {
        if (opener?.isConnected) opener.focus({ preventScroll: true });
        opener = null;
      });
      document.body.append(dialog);
    }
    if (!dialog.open) opener = document.activeElement instanceof HTMLElement ? document.activeElement : null;
    const groups = new Map();
    for (const b of bindings) {
      if (!b.label) continue;
      if (!groups.has(b.group)) groups.set(b.group, []);
      groups.get(b.group).push(b);
    }
    const title = document.createElement('h2');
    title.id = 'keymap-title';
    title.textContent = 'Keyboard';
    // Close sits beside the title and takes the focus: focusing a button at the end of a
    // long list scrolled the dialog to its bottom and cut its title off (1366 x 768).
    const close = document.createElement('button');
    close.type = 'button';
    close.textContent = 'Close';
    close.addEventListener('click', () => dialog.close());
    const head = document.createElement('div');
    head.className = 'keymap-head';
    head.append(title, close);
    /** @type {HTMLElement[]} */
    const content = [head];
    for (const [group, list] of groups) {
      const h3 = document.createElement('h3');
      h3.textContent = group;
      const dl = document.createElement('dl');
      for (const b of list) {
        const dt = document.createElement('dt');
        for (const k of b.keys) {
          const kbd = document.createElement('kbd');
          kbd.textContent = describeKey(k);
          dt.append(kbd, ' ');
        }
        const dd = document.createElement('dd');
        dd.textContent = b.label;
        dl.append(dt, dd);
      }
      content.push(h3, dl);
    }
    dialog.replaceChildren(...content);
    if (!dialog.open) dialog.showModal();
    close.focus({ preventScroll: true });
    dialog.scrollTop = 0;
  }

  document.addEventListener('keydown', onKeyDown);

  return {
    // keys: ['ArrowRight', 'PageDown'], label shown in the `?` dialog, group heading.
    // Without an action the entry is only listed (keys another element handles). shownWith:
    // the element (a panel) whose keys these are; they act only while it is shown.
    /** @param {{ keys: string[], label: string, group?: string, when?: (event: KeyboardEvent) => boolean, action?: (event: KeyboardEvent) => void, shownWith?: Element }} binding */
    add({ keys, label, action, group = 'Lesson', when, shownWith }) {
      bindings.push({ keys, label, action, group, when, shownWith });
      if (shownWith && sizes && !seenShown.has(shownWith)) sizes.observe(shownWith);
    },
    showDialog,
    list: () => bindings.map(({ keys, label, group }) => ({ keys, label, group })),
  };
}
