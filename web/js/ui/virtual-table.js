// @ts-check
// A table that stays fast for 100,000 rows: up to FULL_ROWS rows it is an ordinary table;
// beyond that only the rows in the scrolled window (plus a margin) exist in the DOM, with
// spacer rows above and below so the scroll bar is true to the whole table. Cells are
// built with dom.js (text nodes only). Highlights are kept by row index, so a row scrolled
// into view later still shows them.
import { h } from '../app/dom.js';

const FULL_ROWS = 120;
const WINDOW_MARGIN = 12;
const FALLBACK_ROW_PX = 26;
const SCROLL_KEYS = new Set(['Home', 'End', 'PageUp', 'PageDown', 'ArrowUp', 'ArrowDown', ' ']);

// What a cell shows, as text that differs when the cell would be drawn differently: a cell is
// what h() takes as a child (a string, a number, a node, or a list of them); an element by its
// tag, attributes and children (no markup strings).
const contentKey = (c) => (c == null || c === false ? '' : Array.isArray(c) ? c.map(contentKey).join('\u0001')
  : typeof c !== 'object' ? `t${c}` : `${c.localName}(${Array.from(c.attributes ?? [], (a) => `${a.name}=${a.value}`)})[${Array.from(c.childNodes, contentKey)}]${c.nodeType === 3 ? c.data : ''}`);

// The header rows of a table: `head` is a list of rows, each a list of cells, a cell a string
// or {text, colspan, rowspan, scope, class}. Row k is row k + 1 of the whole table for
// assistive technology (aria-rowindex). Also used for a lone row shown with its table's head
// (the mesh walk's row, lessons/mesh/tabs.js).
export function headRows(head) {
  return head.map((cells, k) => h('tr', { 'aria-rowindex': k + 1 }, cells.map((cell) =>
    typeof cell === 'string' ? h('th', { scope: 'col' }, cell)
      : h('th', { scope: cell.scope ?? 'col', colspan: cell.colspan, rowspan: cell.rowspan, class: cell.class }, cell.text))));
}

// rowKey(i), optional: plain data (JSON) that is the same exactly when row i's cells and
// label are: with it a row's cells are built only when the row changed (without it they
// are built and compared as text);
// rowAttributes(i): extra attributes of row i's <tr> (e.g. data-representation);
// cellClasses[k]: the class of every row's k-th <td>; className: the <table>'s classes.
// onRowEnter, onRowLeave and onRowClick are optional (a table nobody picks from has none).
/**
 * @param {{ id: string, caption: string,
 *   head: Array<Array<string | { text: string, colspan?: number, rowspan?: number, scope?: string, class?: string }>>,
 *   row: (i: number) => unknown[], rowLabel: (i: number) => unknown, rowKey?: ((i: number) => unknown) | null,
 *   onRowEnter?: (i: number) => void, onRowLeave?: () => void, onRowClick?: (i: number) => void,
 *   rowAttributes?: ((i: number) => Record<string, unknown>) | null, cellClasses?: string[], className?: string }} spec
 */
export function createVirtualTable({ id, caption, head, row, rowLabel, rowKey = null, onRowEnter, onRowLeave, onRowClick,
  rowAttributes = null, cellClasses = [], className = 'data-table mesh-table' }) {
  // Header rows are rows 1..head.length of the whole table for assistive technology; data
  // row i is row head.length + i + 1 (aria-rowindex), the table has head.length + total rows
  // (aria-rowcount), so a windowed row is announced where it sits in the whole table.
  const thead = h('thead', {}, headRows(head));
  const headColumns = Math.max(1, ...head.map((cells) => cells.reduce((n, c) => n + (typeof c === 'string' ? 1 : (c.colspan ?? 1)), 0)));
  const tbody = h('tbody', {});
  const captionEl = h('caption', {}, caption);
  const table = h('table', { class: className, id, 'aria-rowcount': 0 }, captionEl, thead, tbody);
  const scroller = h('div', { class: 'table-scroll', tabindex: 0, 'aria-label': caption }, table);
  const note = h('p', { class: 'hint table-note', hidden: true });
  const root = h('div', { class: 'table-block' }, scroller, note);
  // A head of two rows can stick to the top of a scrolling column (web/css/mesh.css): the
  // second row sticks under the first, at its measured height.
  if (head.length > 1 && typeof ResizeObserver !== 'undefined') {
    new ResizeObserver(([entry]) => table.style.setProperty('--head-row-1', `${entry.borderBoxSize?.[0]?.blockSize ?? entry.contentRect.height}px`))
      .observe(thead.rows[0]);
  }

  let count = 0;
  let rowPx = FALLBACK_ROW_PX;
  let rowMarks = new Map(); // row -> Set of class names (is-highlighted, is-hovered, is-picked)
  let reads = new Map(); // row -> Set of column indices (td index, 1-based after the header cell)
  let compares = new Map();
  let first = 0;
  let last = -1;
  let pending = 0;
  let measured = false;
  let viewHeight = 0;
  let scrollTopSeen = 0;
  let seen = null; // {top, height, scrollHeight} of the scroller when the rows were last drawn
  let useSeen = false;
  const readGeometry = () => ({ top: scroller.scrollTop, height: scroller.clientHeight, scrollHeight: scroller.scrollHeight });

  // The rows drawn, by index, each with the text it was drawn from: new data (an edit, a walk
  // step) rebuilds only the rows whose text changed, so the browser lays out and paints those
  // rows, not every row in view (the page's cost of an edit stays the edit's size).
  let drawn = new Map(); // row -> {el, key}
  const keyOf = (i, label, cells) => JSON.stringify([rowAttributes?.(i) ?? null, contentKey(label), cells.map(contentKey)]);

  function rowFor(i) {
    if (rowKey) {
      // The row's data as a key: a row that did not change is found without building its
      // cells (elements) only to compare them.
      const key = JSON.stringify([rowAttributes?.(i) ?? null, rowKey(i)]);
      const old = drawn.get(i);
      if (old?.key === key) return old;
      return { el: cellsOf(i, rowLabel(i), row(i)), key };
    }
    const cells = row(i);
    const label = rowLabel(i);
    const key = keyOf(i, label, cells);
    const old = drawn.get(i);
    if (old?.key === key) return old;
    return { el: cellsOf(i, label, cells), key };
  }

  function cellsOf(i, label, cells) {
    const rowEl = h('tr', { ...rowAttributes?.(i), 'data-row': i, 'aria-rowindex': head.length + i + 1 },
      h('th', { scope: 'row' }, label),
      cells.map((c, k) => h('td', { class: cellClasses[k] || undefined }, c)));
    for (const name of rowMarks.get(i) ?? []) rowEl.classList.add(name);
    for (const col of reads.get(i) ?? []) rowEl.children[col]?.classList.add('is-read');
    for (const col of compares.get(i) ?? []) rowEl.children[col]?.classList.add('is-compared');
    return rowEl;
  }

  function renderWindow() {
    pending = 0;
    if (count <= FULL_ROWS) {
      first = 0;
      last = count - 1;
      const rows = [];
      for (let i = 0; i < count; i += 1) rows.push(rowFor(i));
      place(rows, []);
      return;
    }
    // The scroll geometry: after a scroll (or a jump) read now, when the layout is fresh; for
    // new data (refresh) the last one seen, so a tab switch forces no layout per table (the
    // browser keeps a hidden table's scroll position; a resize is seen by the observer).
    const g = useSeen && seen ? seen : readGeometry();
    useSeen = false;
    seen = g;
    const top = g.top;
    scrollTopSeen = top;
    viewHeight = g.height || viewHeight || 400;
    const height = viewHeight;
    // Scrolled to the bottom: the last rows, whatever the height of the rows above (a row
    // whose lists wrap is taller than rowPx, and the window would otherwise stop short).
    const atEnd = top > 0 && top + height >= g.scrollHeight - rowPx;
    const shown = Math.ceil(height / rowPx);
    first = Math.max(0, (atEnd ? count - shown : Math.floor(top / rowPx)) - WINDOW_MARGIN);
    last = atEnd ? count - 1 : Math.min(count - 1, Math.ceil((top + height) / rowPx) + WINDOW_MARGIN);
    const rows = [];
    for (let i = first; i <= last; i += 1) rows.push(rowFor(i));
    place(rows, [first * rowPx, (count - 1 - last) * rowPx]);
    if (atEnd) scroller.scrollTop = scroller.scrollHeight; // stays at the bottom if the rows are taller than rowPx
    if (!measured) {
      // One layout read, the first time: every row has the same height (CSS).
      const sample = tbody.children[1];
      if (sample?.offsetHeight) { rowPx = sample.offsetHeight; measured = true; renderWindow(); }
    }
  }

  // Puts `rows` ({el, key} in order) in the body, between two spacer rows of the given heights
  // when `spacers` has them. Rows kept from the last drawing stay where they are when the order
  // is the same (the common case: new data, same window); only replaced rows are swapped.
  let spacerRows = null;
  function place(rows, spacers) {
    const span = rows.reduce((n, r) => Math.max(n, r.el.children.length), headColumns);
    const wantSpacers = spacers.length === 2;
    const same = rows.length === drawn.size && (spacerRows !== null) === wantSpacers
      && (!wantSpacers || spacerRows.every((tr) => tr.firstChild.colSpan === span))
      && rows.every((r, k) => drawn.get(first + k)?.el.parentNode === tbody);
    if (same) {
      rows.forEach((r, k) => {
        const old = drawn.get(first + k);
        if (old.el !== r.el) old.el.replaceWith(r.el);
      });
    } else {
      spacerRows = wantSpacers ? [0, 1].map(() => h('tr', { class: 'spacer', 'aria-hidden': 'true' }, h('td', { colspan: span, class: 'spacer-cell' }))) : null;
      const els = rows.map((r) => r.el);
      tbody.replaceChildren(...(spacerRows ? [spacerRows[0], ...els, spacerRows[1]] : els));
    }
    if (spacerRows) spacerRows.forEach((tr, k) => { const px = `${spacers[k]}px`; if (tr.firstChild.style.height !== px) tr.firstChild.style.height = px; });
    drawn = new Map(rows.map((r, k) => [first + k, r]));
  }

  // The keys that scroll a focused table are the table's: the page's shortcuts (the walk's
  // Home, End, PageUp, PageDown, Space) do not take them, and the browser scrolls.
  // Home and End jump at once (not the browser's smooth scroll over 100,000 rows).
  scroller.addEventListener('keydown', (event) => {
    if (!SCROLL_KEYS.has(event.key) || event.ctrlKey || event.metaKey || event.altKey) return;
    event.stopPropagation();
    if (event.key === 'Home' || event.key === 'End') {
      event.preventDefault();
      scroller.scrollTop = event.key === 'Home' ? 0 : scroller.scrollHeight;
      if (count > FULL_ROWS) renderWindow();
    }
  });
  // A new view height (a resized window, a phone turned, the table shown again): redraw.
  new ResizeObserver(() => {
    if (count > FULL_ROWS && seen && scroller.clientHeight && scroller.clientHeight !== seen.height && !pending) pending = requestAnimationFrame(renderWindow);
  }).observe(scroller);
  scroller.addEventListener('scroll', () => {
    if (count > FULL_ROWS && !pending) pending = requestAnimationFrame(renderWindow);
  });
  const rowOf = (event) => {
    const tr = event.target.closest?.('tr[data-row]');
    return tr ? Number(tr.dataset.row) : null;
  };
  tbody.addEventListener('pointerover', (event) => { const i = rowOf(event); if (i !== null) onRowEnter?.(i); });
  tbody.addEventListener('pointerleave', () => onRowLeave?.());
  tbody.addEventListener('click', (event) => { const i = rowOf(event); if (i !== null) onRowClick?.(i); });

  function rowElement(i) {
    return drawn.get(i)?.el ?? null;
  }

  return {
    root,
    table,
    // New data (same shape): rebuild the rows in view.
    // `total` > `nextCount` when only the first rows were fetched: the note says so.
    refresh(nextCount, total = nextCount) {
      count = nextCount;
      table.setAttribute('aria-rowcount', String(total + head.length));
      note.hidden = count <= FULL_ROWS && total === count;
      const cut = total > count ? ` Showing the first ${count.toLocaleString('en')} of ${total.toLocaleString('en')} rows.` : '';
      if (!note.hidden) note.textContent = (count > FULL_ROWS ? `${count.toLocaleString('en')} rows; only the rows in view are drawn (scroll to see the rest).` : '') + cut;
      // A table that turns virtual (or back) changes its height: the geometry seen is stale.
      useSeen = scroller.classList.contains('is-virtual') === count > FULL_ROWS;
      scroller.classList.toggle('is-virtual', count > FULL_ROWS);
      renderWindow();
    },
    // A caption that says what the rows are now (a query's element, say).
    setCaption(text) {
      if (captionEl.textContent !== text) { captionEl.textContent = text; scroller.setAttribute('aria-label', text); }
    },
    // Rows to tint and cells to outline: {rows: {className: [i...]}, read: [[row, col]...],
    // compared: [[row, col]...]}.
    mark({ rows = {}, read = [], compared = [] } = {}) {
      for (const [i, names] of rowMarks) rowElement(i)?.classList.remove(...names);
      for (const [i, cols] of reads) for (const c of cols) rowElement(i)?.children[c]?.classList.remove('is-read');
      for (const [i, cols] of compares) for (const c of cols) rowElement(i)?.children[c]?.classList.remove('is-compared');
      rowMarks = new Map();
      reads = new Map();
      compares = new Map();
      for (const [name, list] of Object.entries(rows)) for (const i of list) rowMarks.set(i, new Set([...(rowMarks.get(i) ?? []), name]));
      for (const [i, c] of read) reads.set(i, new Set([...(reads.get(i) ?? []), c]));
      for (const [i, c] of compared) compares.set(i, new Set([...(compares.get(i) ?? []), c]));
      for (const [i, names] of rowMarks) rowElement(i)?.classList.add(...names);
      for (const [i, cols] of reads) for (const c of cols) rowElement(i)?.children[c]?.classList.add('is-read');
      for (const [i, cols] of compares) for (const c of cols) rowElement(i)?.children[c]?.classList.add('is-compared');
    },
    // Scrolls the table (only) so that row i is visible; returns the row's element.
    reveal(i) {
      if (i === null || i === undefined || i < 0 || i >= count) return null;
      if (count > FULL_ROWS) {
        // Rows inside the drawn window (margin included) need no layout read at all.
        const topRow = Math.ceil(scrollTopSeen / rowPx);
        const bottomRow = Math.floor((scrollTopSeen + viewHeight) / rowPx) - 1;
        if (i >= topRow && i <= bottomRow && i >= first && i <= last) return rowElement(i);
        scroller.scrollTop = Math.max(0, i * rowPx - viewHeight / 3);
        renderWindow();
        return rowElement(i);
      }
      const el = rowElement(i);
      if (!el) return null;
      const offset = el.offsetTop - scroller.scrollTop;
      if (offset < 0 || offset + el.offsetHeight > scroller.clientHeight) scroller.scrollTop = Math.max(0, el.offsetTop - scroller.clientHeight / 3);
      return el;
    },
  };
}
