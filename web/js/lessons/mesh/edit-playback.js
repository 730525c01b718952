// @ts-check
// Playing an edit back one pointer assignment at a time. The core's change record
// lists every assignment in the order its algorithm made them ({table, row, field, before,
// after}); this file turns them into frames and into the winged-edge tables as they stood
// after frame k (the final tables with the later assignments taken back). No geometry and
// no topology is decided here: every number is one the core wrote.
import { EDGE_FIELDS, FIELD_HEADINGS, assignmentText } from '../../ui/mesh/assignments.js';

export { EDGE_FIELDS };

// The vertex table's coordinate columns (x, y, z: cells 0..2 of a vertex's position).
export const COORDINATES = ['x', 'y', 'z'];

// The steps a person sees, one per entry the winged edge writes (the core's definition of
// its writes, edit_costs.h playback_writes, counts the same lines): the assignments of the
// three tables of lecture 000 in the algorithm's order (the face table's bookkeeping field
// firstCorner, which no slide shows, is left out; an entry written twice is two lines), and
// where the record sets a position, its coordinates: all three of a new vertex (it had
// none: before is null), the ones a move changed.
export function visibleSteps(record) {
  const raw = record?.steps ?? [];
  const added = new Set(record?.added?.vertices ?? []);
  const byStep = new Map();
  for (const p of record?.positions ?? []) {
    const at = Math.min(p.step, raw.length);
    const fresh = added.has(p.vertex);
    const lines = COORDINATES.map((field, k) => ({ table: 'vertex', row: p.vertex, field, before: fresh ? null : p.before[k], after: p.after[k],
      phase: (raw[at] ?? raw[at - 1])?.phase ?? -1, coordinate: true })).filter((c) => fresh || c.before !== c.after);
    byStep.set(at, [...(byStep.get(at) ?? []), ...lines]);
  }
  const out = [];
  for (let i = 0; i <= raw.length; i += 1) {
    out.push(...(byStep.get(i) ?? []));
    if (i < raw.length && Object.hasOwn(FIELD_HEADINGS, raw[i].field)) out.push(raw[i]);
  }
  return out;
}

// One line per step: "edge table, e9 · E:L: e3 → e10"; "vertex table, v6 · x: — → 1"
// (ui/mesh/assignments.js).
export const stepText = assignmentText;

// The winged-edge arrays ({positions, vertexEdge, edges, faceEdge}, as wingedEdgeArrays
// gives them) as they were after `shown` visible steps of the record (0: before the edit,
// steps.length: after it). The final arrays are not changed: changed ones are copied.
export function arraysAtStep(we, record, shown) {
  const steps = visibleSteps(record);
  if (shown >= steps.length) return we;
  const out = { ...we, positions: Float64Array.from(we.positions), edges: Int32Array.from(we.edges), vertexEdge: Int32Array.from(we.vertexEdge), faceEdge: Int32Array.from(we.faceEdge) };
  for (let i = steps.length - 1; i >= shown; i -= 1) {
    const s = steps[i];
    if (s.coordinate) { if (s.before !== null) out.positions[3 * s.row + COORDINATES.indexOf(s.field)] = s.before; }
    else if (s.table === 'edge') out.edges[8 * s.row + EDGE_FIELDS.indexOf(s.field)] = s.before;
    else if (s.table === 'vertex') out.vertexEdge[s.row] = s.before;
    else out.faceEdge[s.row] = s.before;
  }
  return out;
}

// One visible step's value (`before` or `after`) written into the arrays.
function writeStep(arrays, s, value) {
  if (s.coordinate) { if (value !== null) arrays.positions[3 * s.row + COORDINATES.indexOf(s.field)] = value; }
  else if (s.table === 'edge') arrays.edges[8 * s.row + EDGE_FIELDS.indexOf(s.field)] = value;
  else if (s.table === 'vertex') arrays.vertexEdge[s.row] = value;
  else arrays.faceEdge[s.row] = value;
}

/**
 * The same tables as arraysAtStep, kept from one step to the next: a second set of the
 * winged-edge arrays (`played`, made once by copying `we`), moved to step `shown` by the
 * assignments between the step it was at and that one, O(the steps between); arraysAtStep
 * copies every array at every step, O(mesh): 60 MB at a million faces. `played.record` is
 * the record it plays (null: the arrays equal the tables after the last change; a lesson
 * brings them there with playedToEnd before it follows an edit into them).
 * @param {{ arrays: any, record: any, at: number } | null} played @param {any} we the tables after the edit
 * @param {any} record @param {number} shown
 * @returns {{ arrays: any, record: any, at: number }}
 */
export function playedArrays(played, we, record, shown) {
  const steps = visibleSteps(record);
  if (!played) {
    const copy = (a) => /** @type {any} */ (new a.constructor(a));
    played = { arrays: { ...we, positions: copy(we.positions), edges: copy(we.edges), vertexEdge: copy(we.vertexEdge), faceEdge: copy(we.faceEdge) }, record: null, at: 0 };
  }
  if (played.record !== record) Object.assign(played, { record, at: steps.length });
  const target = Math.max(0, Math.min(shown, steps.length));
  while (played.at > target) { played.at -= 1; writeStep(played.arrays, steps[played.at], steps[played.at].before); }
  while (played.at < target) { writeStep(played.arrays, steps[played.at], steps[played.at].after); played.at += 1; }
  return played;
}

// The played arrays brought to the end of the record they play (the tables after it).
export function playedToEnd(played) {
  if (played?.record) playedArrays(played, null, played.record, Infinity);
  if (played) played.record = null;
  return played;
}

// The rows the record added that no step up to `shown` has written yet: they are not there
// yet in the picture of the tables at that step.
export function rowsNotYetWritten(record, shown) {
  const steps = visibleSteps(record);
  const written = { vertex: new Set(), edge: new Set(), face: new Set() };
  for (let i = 0; i < Math.min(shown, steps.length); i += 1) written[steps[i].table].add(steps[i].row);
  const pending = (kind, list) => Array.from(list ?? []).filter((x) => !written[kind].has(x));
  return {
    vertex: pending('vertex', record?.added?.vertices),
    edge: pending('edge', record?.added?.edges),
    face: pending('face', record?.added?.faces),
  };
}
