// Lecture 000's mesh for the code sandbox's tests (tests/lessons/code-sandbox.test.mjs and
// tests/browser/code/sandbox.test.mjs): its winged-edge and half-edge tables written by hand
// from the slides, and a student's CCW walk written by the lecture's rule.
// Lecture 000's mesh: F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4), all CCW.
//
//   v3 ------- v4 ------- v5      v1 (0,0)  v2 (1,0)
//    |  \   F2  |  F3   /         v3 (0,1)  v4 (1,1)  v5 (2,1)
//    |    \     |     /
//    |  F1  \   |   /
//    |        \ | /
//   v1 ------- v2
//
// The lecture's winged-edge table, 0-based (e1 -> 0, v1 -> 0, F1 -> 0, blank -> -1):
//         S   E   L   R  S:L S:R E:L E:R
// e1      v1  v3  -   F1  e2  e2  e4  e3
// e2      v1  v2  F1  -   e1  e1  e3  e6
// e3      v2  v3  F1  F2  e2  e5  e1  e4
// e4      v3  v4  -   F2  e1  e3  e7  e5
// e5      v2  v4  F2  F3  e3  e6  e4  e7
// e6      v2  v5  F3  -   e5  e2  e7  e7
// e7      v4  v5  -   F3  e4  e5  e6  e6
export const EDGE_FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
export const LECTURE_EDGES = [
  [0, 2, -1, 0, 1, 1, 3, 2],
  [0, 1, 0, -1, 0, 0, 2, 5],
  [1, 2, 0, 1, 1, 4, 0, 3],
  [2, 3, -1, 1, 0, 2, 6, 4],
  [1, 3, 1, 2, 2, 5, 3, 6],
  [1, 4, 2, -1, 4, 1, 6, 6],
  [3, 4, -1, 2, 3, 4, 5, 5],
];
export const FACES = [[0, 1, 2], [1, 3, 2], [1, 4, 3]];

export function lectureWinged() {
  return {
    positions: new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0]),
    vertexEdge: new Int32Array([0, 5, 2, 4, 5]), // v1 e1, v2 e6, v3 e3, v4 e5, v5 e6
    edges: new Int32Array(LECTURE_EDGES.flat()),
    faceEdge: new Int32Array([0, 2, 4]), // F1 e1, F2 e3, F3 e5
    edgeFields: EDGE_FIELDS.slice(),
  };
}

// The same mesh as half-edges: pair 2e, 2e+1 for edge e; 2e runs S -> E with L on its left,
// 2e+1 runs E -> S with R on its left. Boundary half-edges (face -1) are chained around the
// outside: h0 v1->v3, h6 v3->v4, h12 v4->v5, h11 v5->v2, h3 v2->v1.
export function lectureHalfEdge() {
  return {
    origin: new Int32Array([0, 2, 0, 1, 1, 2, 2, 3, 1, 3, 1, 4, 3, 4]),
    face: new Int32Array([-1, 0, 0, -1, 0, 1, -1, 1, 1, 2, 2, -1, -1, 2]),
    next: new Int32Array([6, 2, 4, 0, 1, 8, 12, 5, 7, 10, 13, 3, 11, 9]),
    prev: new Int32Array([3, 4, 1, 11, 2, 7, 0, 8, 5, 13, 9, 12, 6, 10]),
    vertexHalfedge: new Int32Array([0, 3, 6, 12, 11]),
    faceHalfedge: new Int32Array([2, 8, 10]),
  };
}

// The lecture's rule: if v is the Start of e, the next CCW edge is S:L; otherwise E:R.
export const CCW_WALK = `function edgesAroundVertex(mesh, v) {
  const first = mesh.vertex(v).edge;
  const ring = [];
  let e = first;
  do {
    ring.push(e);
    if (mesh.edge(e).start === v) e = mesh.edge(e).startLeft;
    else e = mesh.edge(e).endRight;
  } while (e !== first);
  return ring;
}
`;
