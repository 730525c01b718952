// @ts-check
// The cards both edit kinds (edit.js: the winged-edge tables; edit-half-edge.js: the half-edge
// view) write rows in: one card per row, its cells as plain inputs (data-table, data-row,
// data-col), a "removed" box, and for the winged-edge kind the new rows' labels. What is shared:
// reading the inputs as the answer, putting a saved answer back, marking the cells a check
// named, clearing, and the arrow keys that move along a column.

/** @typedef {{ cells: HTMLInputElement[][], removed: HTMLInputElement[], labels?: HTMLInputElement[] }} CardInputs */

/** The typed answer: per table {cells, removed, labels}. @param {readonly string[]} tables @param {Record<string, CardInputs>} inputs */
export function readCards(tables, inputs) {
  return Object.fromEntries(tables.map((t) => [t, inputs[t]
    ? { cells: inputs[t].cells.map((row) => row.map((i) => i.value)), removed: inputs[t].removed.map((i) => i.checked), labels: (inputs[t].labels ?? []).map((i) => i.value) }
    : { cells: [], removed: [], labels: [] }]));
}

/** Puts a saved answer (already checked to fit) back into the inputs. @param {readonly string[]} tables @param {Record<string, CardInputs>} inputs @param {any} saved */
export function restoreCards(tables, inputs, saved) {
  for (const t of tables) {
    if (!inputs[t]) continue;
    saved[t].cells.forEach((row, i) => row.forEach((v, k) => { inputs[t].cells[i][k].value = v; }));
    saved[t].removed.forEach((v, i) => { inputs[t].removed[i].checked = v; });
    (saved[t].labels ?? []).forEach((v, n) => { if (inputs[t].labels?.[n]) inputs[t].labels[n].value = v; });
  }
}

/** Marks the named cells ([table, row, col]) invalid, the others not. @param {HTMLElement} root @param {Array<[string, number, string]>} cells */
export function markCards(root, cells) {
  for (const input of root.querySelectorAll('input[aria-invalid]')) input.removeAttribute('aria-invalid');
  for (const [t, row, col] of cells) root.querySelector(`input[data-table="${t}"][data-row="${row}"][data-col="${col}"]`)?.setAttribute('aria-invalid', 'true');
}

/** Empties every input. @param {HTMLElement} root */
export function clearCards(root) {
  for (const input of root.querySelectorAll('input')) {
    if (input instanceof HTMLInputElement) { input.value = ''; input.checked = false; input.removeAttribute('aria-invalid'); }
  }
}

/** Up and down move to the same column of the row above or below (a grid, by keyboard). @param {HTMLElement} root */
export function columnArrows(root) {
  root.addEventListener('keydown', (event) => {
    const el = event.target;
    if (!(el instanceof HTMLInputElement) || (event.key !== 'ArrowUp' && event.key !== 'ArrowDown')) return;
    const all = /** @type {HTMLInputElement[]} */ ([...root.querySelectorAll(`input[data-col="${el.dataset.col}"]`)]);
    const next = all[all.indexOf(el) + (event.key === 'ArrowDown' ? 1 : -1)];
    if (next) { event.preventDefault(); next.focus(); }
  });
}
