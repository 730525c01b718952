// @ts-check
// Playing an edit back one pointer assignment at a time. The core's change record
// lists every assignment in the order its algorithm made them ({table, row, field, before,
// after}); this file turns them into frames and into the winged-edge tables as they stood
// after frame k (the final tables with the later assignments taken back). No geometry and
// no topology is decided here: every number is one the core wrote.
import { EDGE_FIELDS, FIELD_HEADINGS, assignmentText } from '../../ui/mesh/assignments.js';

export { EDGE_FIELDS };

// The steps a person sees: the assignments of the three tables of lecture 000 (the face
// table's bookkeeping field firstCorner, which no slide shows, is left out).
export function visibleSteps(record) {
  return (record?.steps ?? []).filter((s) => Object.hasOwn(FIELD_HEADINGS, s.field));
}

// One line per step: "edge table, e9 · E:L: e3 → e10" (ui/mesh/assignments.js).
export const stepText = assignmentText;

// The winged-edge arrays ({positions, vertexEdge, edges, faceEdge}, as wingedEdgeArrays
// gives them) as they were after `shown` visible steps of the record (0: before the edit,
// steps.length: after it). The final arrays are not changed: changed ones are copied.
export function arraysAtStep(we, record, shown) {
  const steps = visibleSteps(record);
  if (shown >= steps.length) return we;
  const out = { ...we, edges: Int32Array.from(we.edges), vertexEdge: Int32Array.from(we.vertexEdge), faceEdge: Int32Array.from(we.faceEdge) };
  for (let i = steps.length - 1; i >= shown; i -= 1) {
    const s = steps[i];
    if (s.table === 'edge') out.edges[8 * s.row + EDGE_FIELDS.indexOf(s.field)] = s.before;
    else if (s.table === 'vertex') out.vertexEdge[s.row] = s.before;
    else out.faceEdge[s.row] = s.before;
  }
  return out;
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
