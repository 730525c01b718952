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
export function table({ caption, head = [], rows = [], className = 'data-table' }) {
  const thead = h('thead', {}, head.map((row) => h('tr', {}, row.map((cell) =>
    typeof cell === 'object' && cell !== null && !(cell instanceof Node)
      ? h('th', { colspan: cell.colspan, scope: cell.scope ?? 'col' }, cell.text)
      : h('th', { scope: 'col' }, cell)))));
  const tbody = h('tbody', {}, rows.map((row) => h('tr', {}, row.map((cell, i) =>
    i === 0 ? h('th', { scope: 'row' }, cell) : h('td', {}, cell)))));
  return h('table', { class: className }, caption ? h('caption', {}, caption) : null, thead, tbody);
}
