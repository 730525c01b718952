// @ts-check
// "Which edge does the table store?" (lecture 000: the vertex table and the face table hold
// one incident edge each, and the walk starts there). A small control in the winged-edge
// tab: a select of the walked vertex's (or face's) own edges; choosing one appends the
// operation {op: 'set-vertex-edge', v, e} (or 'set-face-edge', f) to state.ops, which the
// mesh source replays on the built mesh, so undo, share links and reload keep it. The
// edges offered come from the core (the walk's frames list them); the core checks again.
import { h } from '../../app/dom.js';
import { vLabel, fLabel, eLabel } from './labels.js';

// The operations of the state after choosing edge e for the element: an earlier choice
// for the same row is superseded, so choosing back and forth does not grow the list. Only
// a choice after the last edit of the mesh is: set-*-edge operations commute
// with each other, not with an edit, whose result can depend on the edge a row stores.
export function withStoredEdge(ops, kind, element, e) {
  const op = kind === 'vertex' ? { op: 'set-vertex-edge', v: element, e } : { op: 'set-face-edge', f: element, e };
  const sameRow = (o) => o.op === op.op && (kind === 'vertex' ? o.v === element : o.f === element);
  let tail = ops.length;
  while (tail > 0 && (ops[tail - 1].op === 'set-vertex-edge' || ops[tail - 1].op === 'set-face-edge')) tail -= 1;
  return [...ops.slice(0, tail), ...ops.slice(tail).filter((o) => !sameRow(o)), op];
}

// A change record as one sentence: "vertex table, row v2: edge e6 → e3".
export function describeOperation(change) {
  if (!change || !change.rows.length) return '';
  const rowLabel = { vertex: vLabel, face: fLabel, edge: eLabel };
  return change.rows.map((r) => `${r.table} table, row ${rowLabel[r.table](r.row)}: ${r.fields
    .map((f) => `${f.field} ${eLabel(f.before)} → ${eLabel(f.after)}`).join(', ')}`).join('; ');
}

export function createStoredEdgeControl(ctx) {
  const select = h('select', { id: 'stored-edge', 'aria-describedby': 'stored-edge-note' });
  const label = h('label', { for: 'stored-edge' }, 'Edge stored for v');
  const note = h('p', { class: 'hint', id: 'stored-edge-note', 'aria-live': 'polite' });
  const root = h('div', { class: 'stored-edge' }, label, ' ', select, note);
  let shown = null; // {kind, element, stored} of the options on screen

  select.addEventListener('change', () => {
    const state = ctx.state;
    if (!shown) return;
    const e = Number(select.value);
    if (e === shown.stored) return;
    ctx.commit({ ...state, ops: withStoredEdge(state.ops, shown.kind, shown.element, e), step: 0 });
  });

  return {
    root,
    update(model) {
      const kind = model.walkKind;
      const element = model.walkElement;
      const frames = model.frames;
      if (element < 0 || !frames.length || !frames[0].order.length) {
        root.hidden = true;
        shown = null;
        return;
      }
      root.hidden = false;
      const stored = frames[0].current; // the walk starts at the stored edge
      const what = kind === 'vertex' ? vLabel(element) : fLabel(element);
      // Redrawn when what it offers changed, not on every edit elsewhere in the mesh.
      const edges = [...frames[0].order].sort((a, b) => a - b);
      const key = edges.join(',');
      if (!shown || shown.kind !== kind || shown.element !== element || shown.stored !== stored || shown.key !== key) {
        label.textContent = `Edge stored for ${what}:`;
        select.replaceChildren(...edges.map((e) => h('option', { value: String(e) }, eLabel(e))));
        select.value = String(stored);
        shown = { kind, element, stored, key };
      }
      const last = describeOperation(model.lastOperation);
      const text = `The ${kind} table stores one of ${what}'s ${edgesWord(kind)}; the walk starts there. Choose another to change the table row (undo restores it).${last ? ` Last change: ${last}.` : ''}`;
      if (note.textContent !== text) note.textContent = text;
    },
  };
}

const edgesWord = (kind) => (kind === 'vertex' ? 'edges' : 'sides');
