// @ts-check
// A tiny DOM builder. Children that are strings become text nodes, so nothing from a
// file, a link or the user is ever parsed as HTML.
//   h('button', { class: 'x', onclick: fn, 'aria-label': 'Undo' }, 'Undo')

export function h(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs ?? {})) {
    if (value === undefined || value === null || value === false) continue;
    if (key.startsWith('on') && typeof value === 'function') node.addEventListener(key.slice(2), value);
    else if (key === 'class') node.className = value;
    else if (key === 'dataset') Object.assign(node.dataset, value);
    else if (key === 'text') node.textContent = value;
    else if (value === true) node.setAttribute(key, '');
    else node.setAttribute(key, String(value));
  }
  append(node, children);
  return node;
}

// node.replaceChildren(...) with h()'s rules: DOM's own replaceChildren turns a null or
// undefined child into the text "null" / "undefined", this skips them.
export function setChildren(node, ...children) {
  node.replaceChildren();
  append(node, children);
  return node;
}

function append(node, children) {
  for (const child of children) {
    if (child === null || child === undefined || child === false) continue;
    if (Array.isArray(child)) append(node, child);
    else node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
}

// A labelled section of the side panel; returns its body element.
export function panel(container, { id, title, open = true }) {
  const body = h('div', { class: 'panel-body' });
  const details = h('details', { class: 'panel', id, open }, h('summary', {}, h('h2', {}, title)), body);
  container.append(details);
  return body;
}

// A table from header rows and body rows (arrays of strings/numbers/Nodes).
/** @param {{ caption?: string, head?: any[][], rows?: any[][], className?: string }} options */
export function table({ caption, head = [], rows = [], className = 'data-table' }) {
  const thead = h('thead', {}, head.map((row) => h('tr', {}, row.map((cell) =>
    typeof cell === 'object' && cell !== null && !(cell instanceof Node)
      ? h('th', { colspan: cell.colspan, scope: cell.scope ?? 'col' }, cell.text)
      : h('th', { scope: 'col' }, cell)))));
  const tbody = h('tbody', {}, rows.map((row) => h('tr', {}, row.map((cell, i) =>
    i === 0 ? h('th', { scope: 'row' }, cell) : h('td', {}, cell)))));
  return h('table', { class: className }, caption ? h('caption', {}, caption) : null, thead, tbody);
}

// Scrollable boxes (wide tables, long formulas) must be reachable by keyboard to scroll
// them (WCAG 2.1.1; axe rule scrollable-region-focusable). A ResizeObserver makes a box a
// focusable, labelled region only while its content overflows, so boxes that fit add no
// tab stops. watchScrollRegions(root) is cheap to call after every panel update: boxes
// already watched are skipped.
const SCROLL_BOXES = '.panel-body, .formula, .table-scroll, .formula-out, math[display=block]';
const watched = new WeakSet();
// Presentation mode (projector): a formula a little wider than its column is set
// smaller until it fits, never below FORMULA_FLOOR_PX (nor 80% of its size); wider ones
// still scroll, with the edge shadows. Outside presentation mode formulas keep their size.
const FORMULA_FLOOR_PX = 15;
function fitFormula(target) {
  if (!target.matches('.formula, math[display=block]')) return;
  if (target.style.fontSize) target.style.fontSize = '';
  if (!document.documentElement.hasAttribute('data-present')) return;
  const ratio = target.clientWidth / target.scrollWidth;
  if (!(ratio < 1)) return;
  const size = parseFloat(getComputedStyle(target).fontSize);
  const fitted = Math.max(0.98 * ratio * size, Math.min(size, Math.max(FORMULA_FLOOR_PX, 0.8 * size)));
  if (fitted < size) target.style.fontSize = `${fitted}px`;
}

// Marks one box: a focusable, labelled region while its content overflows, and
// data-scrolls-x while it scrolls sideways (site.css then shows edge shadows; a
// phone hides the scroll bar).
function markOverflow(target) {
  fitFormula(target);
  const sideways = target.scrollWidth > target.clientWidth + 1;
  const overflows = sideways || target.scrollHeight > target.clientHeight + 1;
  if (sideways) target.dataset.scrollsX = ''; else delete target.dataset.scrollsX;
  if (overflows && !target.hasAttribute('tabindex')) {
    target.tabIndex = 0;
    target.dataset.scrollRegion = '';
    // A <math> keeps its own role (math); any other box becomes a region. Each gets a name
    // of its own: its section's heading, and which of the section's scrolling boxes it is
    // when there are several (two regions must not share one name).
    if (!target.hasAttribute('role') && target.localName !== 'math') target.setAttribute('role', 'region');
    if (!target.hasAttribute('aria-label') && !target.hasAttribute('aria-labelledby')) {
      const section = target.closest('details, section');
      const heading = section?.querySelector('h2, h3');
      const boxes = section ? [...section.querySelectorAll(SCROLL_BOXES)].filter((b) => !b.hasAttribute('aria-labelledby') && (!b.hasAttribute('aria-label') || b.dataset.scrollRegion !== undefined)) : [target];
      const which = boxes.length > 1 ? `, ${boxes.indexOf(target) + 1} of ${boxes.length}` : '';
      target.setAttribute('aria-label', `${heading?.textContent ?? 'Content'} (scrolls${which})`);
    }
  } else if (!overflows && target.dataset.scrollRegion !== undefined) {
    target.removeAttribute('tabindex');
    delete target.dataset.scrollRegion;
  }
}

// A box is checked when it or its first child resizes (a box's first child can be a box
// itself: a block <math> in a .formula), and after every panel update (content can grow
// inside a box that keeps its size: a wider matrix in a .formula of fixed width).
const overflowObserver = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver((entries) => {
  const boxes = new Set();
  for (const entry of entries) {
    if (entry.target.matches(SCROLL_BOXES)) boxes.add(entry.target);
    if (entry.target.parentElement?.matches(SCROLL_BOXES)) boxes.add(entry.target.parentElement);
  }
  for (const target of boxes) markOverflow(target);
});
let recheck = 0;

/** @param {ParentNode} [root] */
export function watchScrollRegions(root = document) {
  if (!overflowObserver) return;
  for (const box of root.querySelectorAll(SCROLL_BOXES)) {
    if (watched.has(box)) continue;
    watched.add(box);
    overflowObserver.observe(box);
    // Content can grow without the box resizing; observe its first child too.
    if (box.firstElementChild) overflowObserver.observe(box.firstElementChild);
  }
  // And look at every box once the update is laid out (one read for all, next frame).
  if (!recheck) {
    recheck = requestAnimationFrame(() => {
      recheck = 0;
      for (const box of root.querySelectorAll(SCROLL_BOXES)) markOverflow(box);
    });
  }
}

// Scrolls the boxes between `el` and the page (a table's scroller, the side column), never
// the page itself, so that `el` is in view: a walk's row stays on screen at every step
// (projector) and a phone's page is not pulled away from the drawing. `context`
// (a table's caption and head) is brought into view with it when both fit in the box.
// `inset`: pixels at the top of a box covered by a sticky table head.
/** @param {Element | null | undefined} el @param {{ context?: Element | null, margin?: number, inset?: number }} [options] */
export function revealInBoxes(el, { context = null, margin = 8, inset = 0 } = {}) {
  if (!el) return;
  for (let box = el.parentElement; box && box !== document.body && box !== document.documentElement; box = box.parentElement) {
    if (box.scrollHeight <= box.clientHeight + 1) continue;
    const overflow = getComputedStyle(box).overflowY;
    if (overflow !== 'auto' && overflow !== 'scroll') continue;
    const r = el.getBoundingClientRect();
    const b = box.getBoundingClientRect();
    let top = r.top;
    const c = context && box.contains(context) ? context.getBoundingClientRect() : null;
    let above = margin + inset;
    if (c && c.top < top && r.bottom - c.top <= b.height - 2 * margin) { top = c.top; above = margin; }
    if (top < b.top + above) box.scrollTop -= b.top + above - top;
    else if (r.bottom > b.bottom - margin) box.scrollTop += Math.min(r.bottom - (b.bottom - margin), top - (b.top + above));
  }
}
