// @ts-check
// The mesh edits as the lesson offers them, read from the core's registry of operations
// (api.meshOperations): which element each one starts from, how it changes the counts, its
// key, the choices it needs besides the picked element, and how an operation of the state
// is made from the selection. The algorithm's lines come with each change record
// (record.phases, the core's own comments), so the pseudocode shown is the code that ran.
// Whether an edit may run, and what it does, is the core's (mesh.check / mesh.apply);
// nothing here decides it, and a new operation of the registry appears here by itself.
import { vLabel, eLabel, fLabel } from './labels.js';

/** @type {Record<string, (i: number) => string>} */
const LABEL = { vertex: vLabel, edge: eLabel, face: fLabel };

/**
 * @typedef {{name: string, kind: string|null, optional: boolean, default: number, choices: string|null, label: string}} OperationArgument
 * @typedef {{name: string, title: string, counts: string, shortcut: string, describe: string, finds?: string, arguments: OperationArgument[]}} OperationEntry
 * @typedef {{op: string, label: string, needs: string, key: string, counts: string,
 *   choices: OperationArgument[], numbers: OperationArgument[],
 *   what: (operation: Record<string, any>) => string,
 *   finds: (operation: Record<string, any>) => string,
 *   make: (index: number, options: Record<string, number>) => Record<string, any>}} EditOp
 */

/**
 * One entry per operation the panel offers (those with a key; the stored-edge choices are
 * made in the tables), in the registry's order.
 * @param {{operations: readonly OperationEntry[]}} meshOperations
 * @returns {EditOp[]}
 */
export function editOps(meshOperations) {
  return meshOperations.operations.filter((o) => o.shortcut).map((o) => {
    const [first, ...rest] = o.arguments;
    return {
      op: o.name,
      label: o.title,
      needs: /** @type {string} */ (first.kind),
      key: o.shortcut,
      counts: o.counts,
      choices: rest.filter((a) => a.kind && a.choices),
      numbers: rest.filter((a) => !a.kind),
      what: (operation) => describeOperation(o, operation),
      // What the edit must find before it writes (the registry's `finds`: "the faces on both
      // sides of e3 and their sides"), which the cost table's words name.
      finds: (operation) => describeOperation({ ...o, describe: o.finds ?? '' }, operation),
      make: (index, options) => ({ op: o.name, [first.name]: index, ...Object.fromEntries(rest.map((a) => [a.name, options[a.name]])) }),
    };
  });
}

/**
 * The registry's one line for an operation: "split e3 at t = 0.5", elements as the slides label them.
 * @param {OperationEntry} entry
 * @param {Record<string, any>} operation
 */
export function describeOperation(entry, operation) {
  return entry.describe.replace(/\{(\w+)\}/g, (whole, name) => {
    const a = entry.arguments.find((x) => x.name === name);
    if (!a) return whole;
    const v = operation[name] ?? a.default;
    return a.kind ? LABEL[a.kind](v) : String(v);
  });
}

/**
 * The state after an edit: the pending vertex moves (state.moved, applied after every
 * operation) become move-vertex operations first, so the edit runs on the positions the
 * person sees and a replay (undo, a link, reload) gives the same mesh.
 * @param {any} state
 * @param {Record<string, any>} operation
 */
export function withEdit(state, operation) {
  const moves = state.moved.map((/** @type {{v: number, p: number[]}} */ m) => ({ op: 'move-vertex', v: m.v, p: m.p.slice() }));
  return { ...state, ops: [...state.ops, ...moves, operation], moved: [], step: 0, editStep: -1 };
}
