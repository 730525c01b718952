// Lecture 000's winged-edge EDGE TABLE as the slide prints it, one string per row:
// e  S  E  L  R, then the wings S:L S:R E:L E:R ('-': no face). Tests compare against it.
export const SLIDE_EDGE_TABLE = Object.freeze([
  'e1 v1 v3 - F1 e2 e2 e4 e3',
  'e2 v1 v2 F1 - e1 e1 e3 e6',
  'e3 v2 v3 F1 F2 e2 e5 e1 e4',
  'e4 v3 v4 - F2 e1 e3 e7 e5',
  'e5 v2 v4 F2 F3 e3 e6 e4 e7',
  'e6 v2 v5 F3 - e5 e2 e7 e7',
  'e7 v4 v5 - F3 e4 e5 e6 e6',
]);

// The slide's VERTEX TABLE and FACE TABLE edges (lecture 000, "Winged Edge (Example)").
export const SLIDE_VERTEX_EDGES = Object.freeze(['e1', 'e6', 'e3', 'e5', 'e6']);
export const SLIDE_FACE_EDGES = Object.freeze(['e1', 'e3', 'e5']);

// The slide's edge table as objects: { e, S, E, L, R, SL, SR, EL, ER } ('-' kept).
export function slideRows() {
  return SLIDE_EDGE_TABLE.map((row) => {
    const [e, S, E, L, R, SL, SR, EL, ER] = row.split(' ');
    return { e, S, E, L, R, SL, SR, EL, ER };
  });
}

// The lecture's walk, read off the slide's tables by its own rule: around a vertex, "if v is
// the Start, the next CCW edge is on the Left of e, coming out of the Start (S:L); otherwise
// on the Right, coming out of the End (E:R)"; along a face, E:L when the face is the edge's
// Left, S:R when it is its Right. Returns the edges until the walk is back at its first.
export function slideWalk(around, element) {
  const rows = Object.fromEntries(slideRows().map((r) => [r.e, r]));
  const first = around === 'vertex' ? SLIDE_VERTEX_EDGES[Number(element.slice(1)) - 1] : SLIDE_FACE_EDGES[Number(element.slice(1)) - 1];
  const out = [first];
  for (let e = first; ;) {
    const r = rows[e];
    e = around === 'vertex' ? (r.S === element ? r.SL : r.ER) : (r.L === element ? r.EL : r.SR);
    if (e === first) return out;
    out.push(e);
  }
}

// Lecture 001, "Pointers to an Edge List" (Foley): the edge list and polygon table as printed.
export const FOLEY_EDGE_LIST = Object.freeze([
  ['V1', 'V2', 'P1', 'λ'],
  ['V2', 'V3', 'P2', 'λ'],
  ['V3', 'V4', 'P2', 'λ'],
  ['V4', 'V2', 'P1', 'P2'],
  ['V4', 'V1', 'P1', 'λ'],
]);
export const FOLEY_POLYGONS = Object.freeze([['E1', 'E4', 'E5'], ['E2', 'E3', 'E4']]);

// flip e3 (by hand): v3 now stores e1; e1..e5 rewritten; F1 stores e3.
export const FLIP_E3 = {
  vertices: [['e1']],
  edges: [['v1', 'v3', 'none', 'F2', 'e2', 'e3', 'e4', 'e4'], ['v1', 'v2', 'F1', 'none', 'e3', 'e1', 'e5', 'e6'],
    ['v4', 'v1', 'F1', 'F2', 'e5', 'e4', 'e2', 'e1'], ['v3', 'v4', 'none', 'F2', 'e1', 'e1', 'e7', 'e3'],
    ['v2', 'v4', 'F1', 'F3', 'e2', 'e6', 'e3', 'e7']],
  faces: [['e3']],
};

