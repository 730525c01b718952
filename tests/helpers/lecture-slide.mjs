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


// Lecture 000's mesh as half-edges, worked out by hand from the slide's edge table above: edge
// e_k gives h(2k-1) = S -> E (its face L) and h(2k) = E -> S (its face R); the boundary loop
// v1 -> v3 -> v4 -> v5 -> v2 -> v1 is h1, h7, h13, h12, h4. Rows h1..h14: origin, face, next,
// prev, twin. Every vertex is on the boundary and stores its boundary half-edge; each face
// stores the side along it of the edge the slide's face table gives (e1 -> h2, e3 -> h6, e5 -> h10).
export const SLIDE_HALF_EDGES = Object.freeze([
  ['v1', 'none', 'h7', 'h4', 'h2'], ['v3', 'F1', 'h3', 'h5', 'h1'], ['v1', 'F1', 'h5', 'h2', 'h4'], ['v2', 'none', 'h1', 'h12', 'h3'],
  ['v2', 'F1', 'h2', 'h3', 'h6'], ['v3', 'F2', 'h9', 'h8', 'h5'], ['v3', 'none', 'h13', 'h1', 'h8'], ['v4', 'F2', 'h6', 'h9', 'h7'],
  ['v2', 'F2', 'h8', 'h6', 'h10'], ['v4', 'F3', 'h11', 'h14', 'h9'], ['v2', 'F3', 'h14', 'h10', 'h12'], ['v5', 'none', 'h4', 'h13', 'h11'],
  ['v4', 'none', 'h12', 'h7', 'h14'], ['v5', 'F3', 'h10', 'h11', 'h13'],
].map((r) => Object.freeze(r)));
export const SLIDE_HALF_EDGE_VERTICES = Object.freeze(['h1', 'h4', 'h7', 'h13', 'h12']);
export const SLIDE_HALF_EDGE_FACES = Object.freeze(['h2', 'h6', 'h10']);
