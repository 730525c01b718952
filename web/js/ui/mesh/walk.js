// @ts-check
// The two winged-edge walks of lecture 000 as animation frames: the CCW edges around a
// vertex ("Initialize: choose the vertex's edge. Do: if v is the Start, the next CCW edge is
// on the Left of e, coming out of the Start; otherwise on the Right of e, coming out of the
// End. While: haven't cycled back to the start edge") and, the same way, the edges of a
// face. The steps (edge, which side was met, the edge read) come from the core; this file
// only says which pseudocode line, table row and column each frame shows.
// Offers: walkFrames(kind, element, steps), normaliseSteps(raw, kind), foundEdges(frame, last),
//   PSEUDOCODE, EDGE_COLUMNS, VERTEX_EDGE_COLUMN, FACE_EDGE_COLUMN. No DOM.
// Needs: the core's steps (mesh.traversalSteps(v) or mesh.faceEdgeSteps(f)).
import { vLabel, eLabel, fLabel } from '../element-labels.js';

// Column positions in the rendered tables (0 is the row header).
export const EDGE_COLUMNS = { S: 1, E: 2, L: 3, R: 4, SL: 5, SR: 6, EL: 7, ER: 8 };
export const VERTEX_EDGE_COLUMN = 4;
export const FACE_EDGE_COLUMN = 1;

export const PSEUDOCODE = {
  vertex: [
    'Initialize: e₀ ← edge of v (vertex table); e ← e₀',
    'Do: report e',
    '  if v = S(e): e ← S:L(e)  (left wing, Start)',
    '  otherwise:   e ← E:R(e)  (right wing, End)',
    'While: e ≠ e₀ (not back at the first edge)',
    'Done: all edges around v, CCW',
  ],
  face: [
    'Initialize: e₀ ← edge of F (face table); e ← e₀',
    'Do: report e',
    '  if F = L(e): e ← E:L(e)  (left wing, End)',
    '  otherwise:   e ← S:R(e)  (right wing, Start)',
    'While: e ≠ e₀ (not back at the first edge)',
    'Done: all edges of F, CCW',
  ],
};

// The core's steps ({edge, role: 'start'|'end', next} around a vertex; {edge, side:
// 'left'|'right', next} along a face) as {edge, metAtFirst, next}: metAtFirst = v is the
// Start / F is the Left face, the case that reads the first wing rule.
export function normaliseSteps(raw, kind) {
  return raw.map((s) => ({ edge: s.edge, metAtFirst: kind === 'vertex' ? s.role === 'start' : s.side === 'left', next: s.next }));
}

const LIST_LIMIT = 12;
// The first labels of a list of `total` (only the first LIST_LIMIT + 1 are needed).
function shortList(labels, total) {
  return total <= LIST_LIMIT ? labels.join(', ') : `${labels.slice(0, LIST_LIMIT).join(', ')}, … (${total - LIST_LIMIT} more)`;
}

// The edges found by frame `frame`, in the order found (a copy of at most the last `last`).
export function foundEdges(frame, last = Infinity) {
  return frame.order.slice(Math.max(0, frame.foundCount - last), frame.foundCount);
}

// Frame 0: initialise (the vertex or face table row and its edge column are read).
// Frames 1..n: at edge k the test column (S or L) and the wing column are read, the edge
// is reported (found) and the next edge is known. Frame n+1: the While test sees e₀ again.
// "Found so far" is one list for the whole walk (`order`, every frame holds the same
// array) and a count per frame: a copy per frame made memory grow with the square of the
// steps, and a 40,000-triangle fan's walk crashed the tab.
export function walkFrames(kind, element, steps) {
  const frames = [];
  const order = steps.map((s) => s.edge);
  const label = kind === 'vertex' ? vLabel(element) : fLabel(element);
  const first = steps.length ? steps[0].edge : -1;
  frames.push({
    line: 0, table: kind, row: element, read: kind === 'vertex' ? VERTEX_EDGE_COLUMN : FACE_EDGE_COLUMN, compared: null,
    current: first, next: first, order, foundCount: 0,
    text: steps.length ? `Initialize: the ${kind} table stores ${eLabel(first)} for ${label}; start there.` : `${label} has no edge: nothing to walk.`,
  });
  steps.forEach((s, k) => {
    let line;
    let read;
    let compared;
    let why;
    if (kind === 'vertex') {
      line = s.metAtFirst ? 2 : 3;
      compared = s.metAtFirst ? EDGE_COLUMNS.S : EDGE_COLUMNS.E;
      read = s.metAtFirst ? EDGE_COLUMNS.SL : EDGE_COLUMNS.ER;
      why = s.metAtFirst ? `${label} is the Start of ${eLabel(s.edge)}, so read S:L` : `${label} is the End of ${eLabel(s.edge)}, so read E:R`;
    } else {
      line = s.metAtFirst ? 2 : 3;
      compared = s.metAtFirst ? EDGE_COLUMNS.L : EDGE_COLUMNS.R;
      read = s.metAtFirst ? EDGE_COLUMNS.EL : EDGE_COLUMNS.SR;
      why = s.metAtFirst ? `${label} is the Left face of ${eLabel(s.edge)}, so read E:L` : `${label} is the Right face of ${eLabel(s.edge)}, so read S:R`;
    }
    frames.push({
      line, table: 'edge', row: s.edge, read, compared, current: s.edge, next: s.next, order, foundCount: k + 1,
      text: `Found ${eLabel(s.edge)}. ${why}: the next edge is ${eLabel(s.next)}.`,
    });
  });
  if (steps.length) {
    frames.push({
      line: 4, table: 'edge', row: first, read: null, compared: null, current: first, next: first, order, foundCount: order.length,
      text: `Back at ${eLabel(first)} = e₀: the loop ends after ${steps.length} edges: ${shortList(order.slice(0, LIST_LIMIT + 1).map(eLabel), order.length)}.`,
      done: true,
    });
  }
  return frames;
}
