// @ts-check
// Playing an edit back one pointer assignment at a time. The core's change record
// lists every assignment in the order its algorithm made them ({table, row, field, before,
// after}); this file turns them into frames and into the winged-edge tables as they stood
// after frame k (the final tables with the later assignments taken back); on the half-edge
// tab, the same edit's half-edge entries (the core's second record, mesh.apply's halfEdge).
// No geometry and no topology is decided here: every number is one the core wrote.
import { EDGE_FIELDS, FIELD_HEADINGS, assignmentText } from '../../ui/mesh/assignments.js';
import { vLabel, fLabel } from '../../ui/element-labels.js';

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
      phase: (raw[at] ?? raw[at - 1])?.phase ?? -1, coordinate: true, at })).filter((c) => fresh || c.before !== c.after);
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

// ---------------------------------------------------------------- in half-edge terms
// The same edit as the core states it in the half-edge tables (mesh.apply's halfEdge:
// {table: 'halfedge' | 'vertex' | 'face', row, field, before, after, step, phase}, each
// changed entry once); the player plays these on the half-edge tab.
export function halfEdgeSteps(record) {
  return record?.halfEdge?.steps ?? [];
}

// The steps the edit player plays on tab `tab`: the half-edge record's on the half-edge tab
// (when the edit has one), the winged edge's everywhere else.
export function playbackSteps(record, tab) {
  return tab === 'half-edge' && record?.halfEdge ? halfEdgeSteps(record) : visibleSteps(record);
}

// How many winged-edge steps the picture shows while the half-edge playback has made `shown`
// entries: up to the winged-edge step the last one made follows (its `step`, an index into
// record.steps), every one for an entry that follows none; none before the first. O(the edit).
export function wingedStepAt(record, shown) {
  const steps = halfEdgeSteps(record);
  const all = visibleSteps(record);
  if (shown <= 0 || !steps.length) return shown <= 0 ? 0 : all.length;
  const follows = steps[Math.min(shown, steps.length) - 1].step;
  if (follows < 0) return all.length;
  const rawIndex = new Map((record.steps ?? []).map((x, i) => [x, i]));
  let n = 0;
  for (const line of all) {
    if ((line.coordinate ? line.at : rawIndex.get(line)) > follows) break;
    n += 1;
  }
  return n;
}

const HALF_EDGE_FIELD_NAMES = { origin: 'origin', face: 'face', next: 'next', prev: 'prev', halfedge: 'half-edge' };
const halfEdgeLabel = (i) => (i < 0 ? '—' : `h${i + 1}`);
const HALF_EDGE_REFERS = { origin: vLabel, face: fLabel, next: halfEdgeLabel, prev: halfEdgeLabel, halfedge: halfEdgeLabel };
const HALF_EDGE_ROWS = { halfedge: ['half-edge table', halfEdgeLabel], vertex: ['vertex table', vLabel], face: ['face table', fLabel] };

// One line per half-edge entry: "half-edge table, h5 · origin: v2 → v4" (— for none).
export function halfEdgeStepText(s) {
  const [table, row] = HALF_EDGE_ROWS[s.table];
  const label = (x) => (x < 0 ? '—' : HALF_EDGE_REFERS[s.field](x));
  return `${table}, ${row(s.row)} · ${HALF_EDGE_FIELD_NAMES[s.field]}: ${label(s.before)} → ${label(s.after)}`;
}

// A playback step's line, whichever structure it is of.
export const playbackStepText = (s) => (s.table === 'halfedge' || s.field === 'halfedge' ? halfEdgeStepText(s) : assignmentText(s));

/**
 * The half-edge cells the playback has not reached at step `shown`, with the value they held
 * before the edit: "table:row:field" -> before (what the half-edge tab shows over the view's
 * final rows while an edit plays). O(the edit).
 * @returns {Map<string, number>}
 */
export function halfEdgeUnmade(record, shown) {
  const steps = halfEdgeSteps(record);
  const out = new Map();
  for (let i = Math.max(0, shown); i < steps.length; i += 1) out.set(`${steps[i].table}:${steps[i].row}:${steps[i].field}`, steps[i].before);
  return out;
}
