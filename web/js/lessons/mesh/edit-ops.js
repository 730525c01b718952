// The mesh edits of issue 15 as the lesson offers them: which element each one starts
// from, how it changes the counts, and how an operation of the state is made from the
// selection. The algorithm's lines come with each change record (record.phases, the core's
// own comments), so the pseudocode shown is the code that ran. Whether an edit may
// run, and what it does, is the core's (mesh.check / mesh.apply); nothing here decides it.
import { vLabel, eLabel, fLabel } from './labels.js';

// One entry per operation, in the order of the panel's buttons. `needs`: the selected
// element's kind. `counts`: what it does to V, E, F (Euler's formula keeps V - E + F).
// `key`: its keyboard shortcut when an element of that kind is selected.
export const EDIT_OPS = [
  {
    op: 'split-edge', label: 'Split edge', needs: 'edge', key: 's', counts: 'V+1, E+1',
    what: (op) => `split ${eLabel(op.e)} at t = ${op.t}`,
    make: (index, options) => ({ op: 'split-edge', e: index, t: options.t }),
  },
  {
    op: 'flip-edge', label: 'Flip edge', needs: 'edge', key: 'f', counts: 'V, E, F unchanged',
    what: (op) => `flip ${eLabel(op.e)}`,
    make: (index) => ({ op: 'flip-edge', e: index }),
  },
  {
    op: 'collapse-edge', label: 'Collapse edge', needs: 'edge', key: 'c', counts: 'V−1, E−1 (−1 more per triangle side)',
    what: (op) => `collapse ${eLabel(op.e)} at t = ${op.t}`,
    make: (index, options) => ({ op: 'collapse-edge', e: index, t: options.t }),
  },
  {
    op: 'join-faces', label: 'Join faces', needs: 'edge', key: 'j', counts: 'E−1, F−1',
    what: (op) => `join the faces of ${eLabel(op.e)}`,
    make: (index) => ({ op: 'join-faces', e: index }),
  },
  {
    op: 'split-face', label: 'Split face', needs: 'face', key: 'd', counts: 'E+1, F+1',
    what: (op) => `split ${fLabel(op.f)} by ${vLabel(op.a)}–${vLabel(op.b)}`,
    make: (index, options) => ({ op: 'split-face', f: index, a: options.a, b: options.b }),
  },
  {
    op: 'poke-face', label: 'Poke face', needs: 'face', key: 'k', counts: 'V+1, E+n, F+n−1',
    what: (op) => `poke ${fLabel(op.f)}`,
    make: (index) => ({ op: 'poke-face', f: index }),
  },
];

export const EDIT_OP = Object.fromEntries(EDIT_OPS.map((o) => [o.op, o]));

// The arguments mesh.check(op, ...args) takes for an operation of the state.
export function checkArgs(operation) {
  switch (operation.op) {
    case 'split-edge': case 'collapse-edge': return [operation.e, operation.t];
    case 'flip-edge': case 'join-faces': return [operation.e];
    case 'split-face': return [operation.f, operation.a, operation.b];
    case 'poke-face': return [operation.f];
    default: return [];
  }
}

// The state after an edit: the pending vertex moves (state.moved, applied after every
// operation) become move-vertex operations first, so the edit runs on the positions the
// person sees and a replay (undo, a link, reload) gives the same mesh.
export function withEdit(state, operation) {
  const moves = state.moved.map((m) => ({ op: 'move-vertex', v: m.v, p: m.p.slice() }));
  return { ...state, ops: [...state.ops, ...moves, operation], moved: [], step: 0, editStep: -1 };
}
