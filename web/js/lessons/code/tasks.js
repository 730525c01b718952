// @ts-check
// The tasks of "Program the structure": each is a function the student writes over the
// lecture's tables, with the lecture's statement, a starter, the argument it is called with
// on the lecture mesh, and what the core says the answer is (expected) and how many table
// entries the lecture's own rule reads for it (referenceReads). The core is the judge: a
// task never computes an answer itself.
//
// A task: {id, title, structure ('winged-edge' | 'half-edge'), entry (the function's name),
// params (what each argument is: 'vertex' | 'face' | 'edge'), answer ('edges' | 'faces' |
// 'half-edges' | 'number': what the returned value lists; 'position': a point [x, y, z] of the
// core's subdivision step by `scheme`; 'edit': the tables the function leaves), statement
// (paragraphs, the lecture's words),
// rule (the lecture's rule, one line per step), starter (the code a student starts from),
// lectureArgs (the arguments on the lecture mesh, 0-based), pick (which element of a hidden
// mesh a case asks about: 'boundary' prefers a boundary vertex, 'largest' the face with most
// sides), expected(mesh, args, api) and referenceReads(mesh, args): answers of the core
// (null where the core has no counting reader for the rule: the subdivision points).

/** @typedef {'vertex' | 'face' | 'edge'} ParamKind */
/**
 * @typedef {{
 *   id: string, title: string, structure: 'winged-edge' | 'half-edge', entry: string,
 *   params: ParamKind[], answer: 'edges' | 'faces' | 'half-edges' | 'number' | 'edit' | 'position',
 *   lecture: string, statement: string[], rule: string[], starter: string,
 *   lectureArgs: number[], writable?: boolean, op?: string, opArgs?: Object<string, number>, editName?: string, positionRule?: string,
 *   scheme?: 'loop' | 'catmull-clark',
 *   expected: (mesh: any, args: number[], api: any) => any,
 *   referenceReads: (mesh: any, args: number[], expected: any) => number | null,
 * }} Task
 */

const list = (a) => Array.from(a);

/** @type {Task[]} */
export const TASKS = [
  {
    id: 'edges-around-vertex',
    title: 'The edges around a vertex (winged edge)',
    structure: 'winged-edge',
    entry: 'edgesAroundVertex',
    params: ['vertex'],
    answer: 'edges',
    lecture: '000',
    statement: [
      'Find the CCW edges adjacent to vertex v (lecture 000, the winged-edge example around v₂).',
      'Start with the edge the vertex table stores for v, mesh.vertex(v).edge. At each edge, the next edge counter-clockwise around v is a wing: startLeft when v is the edge\'s start, endRight when v is its end. Stop when you come back to the first edge.',
      'Return the edges in the order you meet them, the first one first: on the slide\'s mesh, edgesAroundVertex(mesh, 1) (that is v₂) returns [5, 4, 2, 1], the edges e₆ e₅ e₃ e₂.',
    ],
    rule: ['Initialize: choose the edge the vertex stores', 'Do: iterate CCW around v (startLeft if v = S, endRight if v = E)', 'While: you have not cycled back to the start edge'],
    starter: 'function edgesAroundVertex(mesh, v) {\n  const edges = [];\n  const first = mesh.vertex(v).edge;\n  // Walk counter-clockwise around v until you are back at `first`.\n\n  return edges;\n}\n',
    lectureArgs: [1],
    expected: (mesh, [v]) => list(mesh.edgesAroundVertex(v)),
    referenceReads: (mesh, [v]) => mesh.query('edges-around-vertex', v)['winged-edge'].entriesRead,
  },
  {
    id: 'edges-of-face',
    title: 'The edges of a face (winged edge)',
    structure: 'winged-edge',
    entry: 'edgesOfFace',
    params: ['face'],
    answer: 'edges',
    lecture: '000',
    statement: [
      'List the edges of face f in order around it (lecture 000: each face stores one edge; the edge records hold the rest).',
      'Start with mesh.face(f).edge. When f is the edge\'s left face, the next edge around f is endLeft; when f is its right face, the next is startRight. Stop when you are back at the first edge.',
      'On the slide\'s mesh, edgesOfFace(mesh, 0) (F₁) returns [0, 1, 2]: e₁ e₂ e₃.',
    ],
    rule: ['Initialize: the edge the face stores', 'Do: endLeft if f is the left face, startRight if it is the right face', 'While: not back at the start edge'],
    starter: 'function edgesOfFace(mesh, f) {\n  const edges = [];\n  const first = mesh.face(f).edge;\n  // Walk around f until you are back at `first`.\n\n  return edges;\n}\n',
    lectureArgs: [0],
    expected: (mesh, [f]) => list(mesh.edgesOfFace(f)),
    referenceReads: (mesh, [f]) => mesh.query('edges-of-face', f)['winged-edge'].entriesRead,
  },
  {
    id: 'faces-around-vertex',
    title: 'The faces around a vertex (winged edge)',
    structure: 'winged-edge',
    entry: 'facesAroundVertex',
    params: ['vertex'],
    answer: 'faces',
    lecture: '000',
    statement: [
      'List the faces around vertex v, in the order the CCW walk around v meets them (lecture 000).',
      'Walk the edges around v as in the first task. At an edge whose start is v, the face counter-clockwise of it is the edge\'s left face; at an edge whose end is v, its right face. On the boundary one of them is none (-1): skip it.',
      'On the slide\'s mesh, facesAroundVertex(mesh, 1) (v₂) returns [2, 1, 0]: F₃ F₂ F₁.',
    ],
    rule: ['Walk the edges around v', 'At each: L if v = S, R if v = E', 'Skip none (a boundary)'],
    starter: 'function facesAroundVertex(mesh, v) {\n  const faces = [];\n  // Walk the edges around v; at each, add the face on its counter-clockwise side.\n\n  return faces;\n}\n',
    lectureArgs: [1],
    expected: (mesh, [v]) => list(mesh.facesAroundVertex(v)),
    referenceReads: (mesh, [v]) => mesh.query('faces-around-vertex', v)['winged-edge'].entriesRead,
  },
  {
    id: 'euler-characteristic',
    title: 'The Euler characteristic',
    structure: 'winged-edge',
    entry: 'eulerCharacteristic',
    params: [],
    answer: 'number',
    lecture: '003',
    statement: [
      'Return V − E + F of the mesh, counted from its tables (2 for a closed mesh like a cube, 1 for a disc like the slide\'s mesh).',
      'mesh.vertexCount, mesh.edgeCount and mesh.faceCount are the numbers of rows. An edit can remove an element and leave its row behind, every entry none (-1): such a row is not an element, so count only the rows that hold one. (Counting every row happens to give the same number after the lecture\'s Euler operations, since each keeps V − E + F; count the elements all the same.)',
      'Careful: element 0 is an element. A test like if (mesh.vertex(v).edge) skips the vertices that store edge 0.',
    ],
    rule: ['Count the vertex rows whose edge is not none', 'the edge rows whose start is not none', 'the face rows whose edge is not none'],
    starter: 'function eulerCharacteristic(mesh) {\n  let V = 0, E = 0, F = 0;\n  // Count the rows that hold an element.\n\n  return V - E + F;\n}\n',
    lectureArgs: [],
    expected: (mesh) => mesh.counts().euler,
    // One entry per row: a vertex's edge, an edge's start, a face's edge.
    referenceReads: (mesh) => {
      const w = mesh.wingedEdgeArrays();
      return w.vertexEdge.length + w.edges.length / 8 + w.faceEdge.length;
    },
  },
  {
    id: 'half-edges-around-vertex',
    title: 'The half-edges leaving a vertex (half-edge)',
    structure: 'half-edge',
    entry: 'halfEdgesAroundVertex',
    params: ['vertex'],
    answer: 'half-edges',
    lecture: '000',
    statement: [
      'The same walk on the half-edge structure: each edge is two half-edges, h and its twin, each with an origin, a face, and the next and previous half-edge around that face.',
      'Start with mesh.vertex(v).halfEdge, a half-edge leaving v. The next half-edge leaving v counter-clockwise is twin(prev(h)): mesh.halfEdge(mesh.halfEdge(h).prev).twin. Stop when you are back at the first.',
      'Return the half-edges leaving v in the order you meet them. On the slide\'s mesh, halfEdgesAroundVertex(mesh, 1) returns [3, 10, 8, 4].',
    ],
    rule: ['Initialize: the half-edge the vertex stores', 'Do: h = twin(prev(h))', 'While: not back at the first'],
    starter: 'function halfEdgesAroundVertex(mesh, v) {\n  const out = [];\n  const first = mesh.vertex(v).halfEdge;\n  // h -> twin(prev(h)) until you are back at `first`.\n\n  return out;\n}\n',
    lectureArgs: [1],
    expected: (mesh, [v]) => mesh.halfEdgeTraversalSteps(v).map((s) => s.halfedge),
    referenceReads: (mesh, [v]) => mesh.halfEdgeQuery('edges-around-vertex', v).entriesRead,
  },
  {
    id: 'half-edges-of-face',
    title: 'The half-edges of a face (half-edge)',
    structure: 'half-edge',
    entry: 'halfEdgesOfFace',
    params: ['face'],
    answer: 'half-edges',
    lecture: '000',
    statement: [
      'Walk around face f on the half-edge structure: start with mesh.face(f).halfEdge and follow next until you are back at the first.',
      'Every half-edge you meet has f as its face. On the slide\'s mesh, halfEdgesOfFace(mesh, 0) returns [1, 2, 4].',
    ],
    rule: ['Initialize: the half-edge the face stores', 'Do: h = next(h)', 'While: not back at the first'],
    starter: 'function halfEdgesOfFace(mesh, f) {\n  const out = [];\n  // Follow next from mesh.face(f).halfEdge.\n\n  return out;\n}\n',
    lectureArgs: [0],
    expected: (mesh, [f]) => mesh.halfEdgeFaceSteps(f).map((s) => s.halfedge),
    referenceReads: (mesh, [f]) => mesh.halfEdgeQuery('edges-of-face', f).entriesRead,
  },
  {
    id: 'flip-edge',
    title: 'Flip an edge (winged edge, an edit)',
    structure: 'winged-edge',
    entry: 'flipEdge',
    params: ['edge'],
    answer: 'edit',
    writable: true,
    op: 'flip-edge',
    editName: 'flip',
    lecture: '000',
    statement: [
      'Flip edge e, the edge between two triangles: it turns to join the two corners opposite it. Edge e keeps its row and its number; only pointers change (no element is added or removed).',
      'Before: e runs from S to E, the triangle L on its left has the corner c opposite e, the triangle R on its right the corner d. After: e runs from d to c, L is (c, S, d) and R is (d, E, c). Every record that pointed across the old e, the wings of the four sides around it, L, R, S and E, may need new values.',
      'Write them with the setters: mesh.edge(x).startLeft = y, mesh.edge(e).start = d, mesh.face(f).edge = x, mesh.vertex(v).edge = x. Reads after a write see it. When your function returns, the whole table is checked as the winged edge of the flipped mesh (any consistent choice of the stored edges is right); only then is it applied: the mesh is never left half-edited.',
    ],
    // The core's own phases of its flip (euler_ops.cpp), as the mesh lesson's edit player shows them.
    rule: ['e\'s row: d → c; its wings are the two sides at d and the two at c', 'L becomes (c, S, d): the side S → d moves into L', 'R becomes (d, E, c): the side E → c moves into R', 'S and E stop storing e; L and R store an edge of their own'],
    starter: 'function flipEdge(mesh, e) {\n  const r = mesh.edge(e);\n  const S = r.start, E = r.end, L = r.left, R = r.right;\n  // The corners opposite e: c in L, d in R (the other ends of its wings).\n\n  // Rewrite e\'s row, the four sides\' wings, and what L, R, S and E store.\n}\n',
    lectureArgs: [2],
    // The core's flip of the same mesh: its faces after (the check's reference) and how many
    // entries the core's flip writes (its playback's assignments).
    expected: (mesh, [e]) => {
      const record = mesh.apply({ op: 'flip-edge', e });
      const after = mesh.faceSet();
      return { faceOffsets: Int32Array.from(after.faceOffsets), faceVertices: Int32Array.from(after.faceVertices), vertexCount: mesh.counts().vertices, written: record.steps.length };
    },
    referenceReads: (mesh, args, expected) => expected.written,
  },
  {
    id: 'split-edge',
    title: 'Split an edge (winged edge, an edit)',
    structure: 'winged-edge',
    entry: 'splitEdge',
    params: ['edge'],
    answer: 'edit',
    writable: true,
    op: 'split-edge',
    opArgs: { t: 0.5 },
    editName: 'split',
    positionRule: 'the midpoint of e\'s start and end, (S + E) / 2',
    lecture: '000',
    statement: [
      'Split edge e at its midpoint: a new vertex m halfway between its start S and its end E, and a new edge n from m to E. The faces on either side, L and R, keep their rows and gain m as a corner (one side more each).',
      'Add the new rows: m = mesh.addVertex([x, y, z]) with m at (S + E) / 2, n = mesh.addEdge(); each returns its new row\'s number, every entry none (-1) until you write it. Then e runs from S to m, n from m to E with the same faces; at m the two edges are each other\'s wings; at E, n takes over the wings e had there, and every record at E that pointed at e now points at n.',
      'When your function returns, the whole table is checked as the winged edge of the split mesh and m\'s position as the midpoint; only then is it applied: the mesh is never left half-edited.',
    ],
    // The core's own phases of its split (euler_ops.cpp), as the mesh lesson's edit player shows them.
    rule: ['A new vertex m at (S + E) / 2 and a new edge n; m stores n', 'n: m → E, the faces L and R of e; its wings at m are e on both sides, at E the wings e had there', 'e now ends at m; its wings at its end are n on both sides', 'The edges at E that pointed at e now point at n (and E stores n if it stored e)'],
    starter: 'function splitEdge(mesh, e) {\n  const r = mesh.edge(e);\n  const S = r.start, E = r.end;\n  const [sx, sy, sz] = mesh.vertex(S).position, [ex, ey, ez] = mesh.vertex(E).position;\n  // A new vertex at the midpoint and a new edge: mesh.addVertex([x, y, z]), mesh.addEdge().\n\n  // Write n\'s row, e\'s new end and wings, and what pointed at e at E.\n}\n',
    lectureArgs: [2],
    // The core's split of the same mesh: its faces after, the new vertex's position (the
    // check's references) and how many entries the core's split writes.
    expected: (mesh, [e]) => {
      const record = mesh.apply({ op: 'split-edge', e, t: 0.5 });
      const after = mesh.faceSet();
      const { positions } = mesh.wingedEdgeArrays();
      const m = mesh.counts().vertices - 1; // the new vertex: the last row (the case has no gaps)
      return {
        faceOffsets: Int32Array.from(after.faceOffsets), faceVertices: Int32Array.from(after.faceVertices), vertexCount: mesh.counts().vertices,
        newPositions: [Array.from(positions.subarray(3 * m, 3 * m + 3))], written: record.steps.length,
      };
    },
    referenceReads: (mesh, args, expected) => expected.written,
  },
  {
    id: 'loop-edge-point',
    title: 'Loop\'s new edge point',
    structure: 'winged-edge',
    entry: 'loopEdgePoint',
    params: ['edge'],
    answer: 'position',
    scheme: 'loop',
    lecture: '000',
    statement: [
      'One step of Loop\'s subdivision puts a new point on every edge (the Subdivision lesson shows its mask). For edge e from S to E between two triangles, the edge point is 3/8 (S + E) + 1/8 (c + d), where c and d are the corners opposite e: c in its left triangle L, d in its right triangle R. On the boundary (L or R is none) it is the midpoint (S + E) / 2.',
      'Find c and d from the wings: the wing at S on the left, startLeft, is the side of L from S to c, so c is its other end; startRight gives d in R. Read the positions with mesh.vertex(v).position and return [x, y, z].',
      'The core computes the same point in its own subdivision step; each coordinate must agree within 1e-9 of the mesh\'s size (its largest coordinate). (On the slide\'s mesh the corners opposite an inner edge add up to S + E, so its edge points are midpoints as well: the hidden meshes tell the rules apart.)',
    ],
    rule: ['S, E, L, R from e\'s row', 'c: the other end of startLeft (in L); d: the other end of startRight (in R)', 'interior: 3/8 (S + E) + 1/8 (c + d); boundary: (S + E) / 2'],
    starter: 'function loopEdgePoint(mesh, e) {\n  const r = mesh.edge(e);\n  const S = mesh.vertex(r.start).position, E = mesh.vertex(r.end).position;\n  // On the boundary (r.left or r.right is -1): the midpoint. Inside: find the opposite corners c and d.\n\n  return [0, 0, 0];\n}\n',
    lectureArgs: [2],
    // The edge point of e is vertex V + e of the core's Loop step (subdivision.h).
    expected: (mesh, [e], api) => newPoint(api, mesh, 'loop', mesh.counts().vertices + e),
    referenceReads: () => null,
  },
  {
    id: 'loop-vertex-point',
    title: 'Loop\'s new vertex point',
    structure: 'winged-edge',
    entry: 'loopVertexPoint',
    params: ['vertex'],
    answer: 'position',
    scheme: 'loop',
    lecture: '000',
    statement: [
      'Loop\'s step also moves every old vertex v. Inside the mesh, with n neighbours: (1 − nβ) v + β (the sum of the neighbours), β = (1/n)(5/8 − (3/8 + cos(2π/n)/4)²) (Loop\'s own weight). On the boundary: 1/8 a + 6/8 v + 1/8 b, where a and b are v\'s two neighbours along the boundary.',
      'Walk the edges around v (the first task\'s walk) to meet its neighbours; an edge with no face on one side (left or right is -1) is on the boundary. Return [x, y, z].',
      'The core computes the same point in its own subdivision step; each coordinate must agree within 1e-9 of the mesh\'s size (its largest coordinate).',
    ],
    rule: ['Walk the edges around v; each edge\'s other end is a neighbour', 'inside: β = (1/n)(5/8 − (3/8 + cos(2π/n)/4)²), (1 − nβ) v + β Σ neighbours', 'boundary: 1/8 a + 6/8 v + 1/8 b (its two boundary neighbours)'],
    starter: 'function loopVertexPoint(mesh, v) {\n  const P = mesh.vertex(v).position;\n  const neighbours = [];\n  // Walk the edges around v; collect the other ends, and note the boundary ones.\n\n  return P;\n}\n',
    lectureArgs: [1],
    // Old vertex v keeps its number in the core's Loop step: its new position is the vertex point.
    expected: (mesh, [v], api) => newPoint(api, mesh, 'loop', v),
    referenceReads: () => null,
  },
  {
    id: 'catmull-clark-face-point',
    title: 'Catmull-Clark\'s face point',
    structure: 'winged-edge',
    entry: 'faceCentroid',
    params: ['face'],
    answer: 'position',
    scheme: 'catmull-clark',
    lecture: '000',
    statement: [
      'One step of Catmull-Clark\'s subdivision puts a new point in every face: the face point, the average (centroid) of the face\'s corners. A face may have any number of sides.',
      'Walk the edges of f (the second task\'s walk): the corner where each side starts, as you go around f, is the edge\'s start when f is its left face and its end when f is its right face. Average the corners\' positions and return [x, y, z].',
      'The core computes the same point in its own subdivision step; each coordinate must agree within 1e-9 of the mesh\'s size (its largest coordinate).',
    ],
    rule: ['Walk the edges of f', 'the corner at each: start if f is the left face, end if it is the right face', 'the face point: the sum of the corners / their number'],
    starter: 'function faceCentroid(mesh, f) {\n  let x = 0, y = 0, z = 0, n = 0;\n  // Walk around f and add each corner\'s position.\n\n  return [x / n, y / n, z / n];\n}\n',
    lectureArgs: [0],
    // The face point of f is vertex V + E + f of the core's Catmull-Clark step (subdivision.h).
    expected: (mesh, [f], api) => { const c = mesh.counts(); return newPoint(api, mesh, 'catmull-clark', c.vertices + c.edges + f); },
    referenceReads: () => null,
  },
];

// Vertex `index` of the core's subdivision step of `mesh` by `scheme`: [x, y, z].
function newPoint(api, mesh, scheme, index) {
  const finer = api.subdivide(mesh, { scheme, steps: 1 });
  try {
    return Array.from(finer.wingedEdgeArrays().positions.subarray(3 * index, 3 * index + 3));
  } finally {
    finer.dispose();
  }
}

export const TASK_IDS = TASKS.map((t) => t.id);

/** @param {string} id @returns {Task} */
export function taskOf(id) {
  const task = TASKS.find((t) => t.id === id);
  if (!task) throw new Error(`no task named ${id}`);
  return task;
}

// What a student's function may read, per structure, for the API reference panel.
export const API_REFERENCE = {
  'winged-edge': [
    ['mesh.vertexCount, mesh.edgeCount, mesh.faceCount', 'the numbers of rows of the three tables'],
    ['mesh.vertex(v).edge', 'the edge the vertex table stores for v'],
    ['mesh.vertex(v).position', '[x, y, z] of v'],
    ['mesh.face(f).edge', 'the edge the face table stores for f'],
    ['mesh.edge(e).start, .end', 'S and E: the edge runs from start to end'],
    ['mesh.edge(e).left, .right', 'L and R: the faces on its left and right (-1: none, a boundary)'],
    ['mesh.edge(e).startLeft, .startRight', 'the wings at S: the next edges around S on the left and right'],
    ['mesh.edge(e).endLeft, .endRight', 'the wings at E'],
  ],
  'half-edge': [
    ['mesh.vertexCount, mesh.faceCount, mesh.halfEdgeCount', 'the numbers of rows'],
    ['mesh.vertex(v).halfEdge', 'a half-edge leaving v'],
    ['mesh.face(f).halfEdge', 'a half-edge of f'],
    ['mesh.halfEdge(h).origin, .target', 'the vertex h leaves and the one it reaches'],
    ['mesh.halfEdge(h).face', 'the face on its left (-1: none, a boundary)'],
    ['mesh.halfEdge(h).next, .prev', 'the next and previous half-edge around that face'],
    ['mesh.halfEdge(h).twin', 'the other half of the same edge: h ^ 1, arithmetic, not a stored entry (shown in the trace, not counted as a read)'],
  ],
};
