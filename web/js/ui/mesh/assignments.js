// @ts-check
// One pointer assignment of the winged-edge tables in the slides' words, for every playback
// of assignments (an edit's change record in the mesh lesson, a subdivision step's
// reconnection in the subdivision lesson): "edge table, e9 · E:L: e3 → e10", and an edit's
// coordinates: "vertex table, v6 · x: — → 1". No DOM.
// Offers: EDGE_FIELDS, FIELD_HEADINGS, assignmentText(step), columnOfField(table, field).
// Needs: steps as the core gives them ({table, row, field, before, after}).
import { vLabel, eLabel, fLabel } from '../element-labels.js';
import { VERTEX_EDGE_COLUMN, FACE_EDGE_COLUMN } from './walk.js';

// The winged-edge columns as the edge table's descriptor names them, in the order of the
// flat edge record (8 numbers per edge: S, E, L, R, S:L, S:R, E:L, E:R).
export const EDGE_FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
export const FIELD_HEADINGS = { start: 'S', end: 'E', left: 'L', right: 'R', startLeft: 'S:L', startRight: 'S:R', endLeft: 'E:L', endRight: 'E:R', edge: 'edge' };
const REFERS = { start: vLabel, end: vLabel, left: fLabel, right: fLabel, startLeft: eLabel, startRight: eLabel, endLeft: eLabel, endRight: eLabel, edge: eLabel };
const ROW_LABEL = { vertex: vLabel, edge: eLabel, face: fLabel };
const none = (label) => (x) => (x < 0 ? '—' : label(x));

const coordinate = (x) => (x === null ? '—' : String(Number(x.toFixed(6))));

// One line per step: "edge table, e9 · E:L: e3 → e10" (— for none); a coordinate set by an
// edit ({coordinate: true, field: 'x' | 'y' | 'z'}): "vertex table, v6 · x: — → 1".
export function assignmentText(s) {
  if (s.coordinate) return `vertex table, ${vLabel(s.row)} · ${s.field}: ${coordinate(s.before)} → ${coordinate(s.after)}`;
  const label = none(REFERS[s.field] ?? String);
  return `${s.table} table, ${ROW_LABEL[s.table](s.row)} · ${FIELD_HEADINGS[s.field]}: ${label(s.before)} → ${label(s.after)}`;
}

// The column of the rendered winged-edge table (0 is the row header) that holds `field`.
export function columnOfField(table, field) {
  if (table === 'edge') { const i = EDGE_FIELDS.indexOf(field); return i < 0 ? -1 : 1 + i; }
  return table === 'vertex' ? VERTEX_EDGE_COLUMN : FACE_EDGE_COLUMN;
}
