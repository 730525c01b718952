// The lecture's rules for the tasks of "Program the structure", written as a student would
// write them: the Node tests grade them in the sandbox, the browser tests type them (typed()
// drops the indentation, which the editor adds itself).
export const CORRECT = {
  'edges-around-vertex': `function edgesAroundVertex(mesh, v) {
  const edges = [];
  const first = mesh.vertex(v).edge;
  let e = first;
  do {
    edges.push(e);
    const r = mesh.edge(e);
    e = r.start === v ? r.startLeft : r.endRight;
  } while (e !== first);
  return edges;
}`,
  'edges-of-face': `function edgesOfFace(mesh, f) {
  const edges = [];
  const first = mesh.face(f).edge;
  let e = first;
  do {
    edges.push(e);
    const r = mesh.edge(e);
    e = r.left === f ? r.endLeft : r.startRight;
  } while (e !== first);
  return edges;
}`,
  'faces-around-vertex': `function facesAroundVertex(mesh, v) {
  const faces = [];
  const first = mesh.vertex(v).edge;
  let e = first;
  do {
    const r = mesh.edge(e);
    const atStart = r.start === v;
    const f = atStart ? r.left : r.right;
    if (f !== -1) faces.push(f);
    e = atStart ? r.startLeft : r.endRight;
  } while (e !== first);
  return faces;
}`,
  'euler-characteristic': `function eulerCharacteristic(mesh) {
  let V = 0, E = 0, F = 0;
  for (let v = 0; v < mesh.vertexCount; v++) if (mesh.vertex(v).edge !== -1) V++;
  for (let e = 0; e < mesh.edgeCount; e++) if (mesh.edge(e).start !== -1) E++;
  for (let f = 0; f < mesh.faceCount; f++) if (mesh.face(f).edge !== -1) F++;
  return V - E + F;
}`,
  'half-edges-around-vertex': `function halfEdgesAroundVertex(mesh, v) {
  const out = [];
  const first = mesh.vertex(v).halfEdge;
  let h = first;
  do {
    out.push(h);
    h = mesh.halfEdge(mesh.halfEdge(h).prev).twin;
  } while (h !== first);
  return out;
}`,
  'half-edges-of-face': `function halfEdgesOfFace(mesh, f) {
  const out = [];
  const first = mesh.face(f).halfEdge;
  let h = first;
  do {
    out.push(h);
    h = mesh.halfEdge(h).next;
  } while (h !== first);
  return out;
}`,
  // The flip worked out from the winged-edge record (docs/architecture.md, "The lesson Program
  // the structure"): sides a = S-c and d = E-c in L, b = S-d and c = d-E in R, before.
  'flip-edge': `function flipEdge(mesh, e) {
  const r = mesh.edge(e);
  const S = r.start, E = r.end, L = r.left, R = r.right;
  const a = r.startLeft, b = r.startRight, c = r.endRight, d = r.endLeft;
  const other = (x, v) => { const y = mesh.edge(x); return y.start === v ? y.end : y.start; };
  const cv = other(a, S), dv = other(b, S);
  const setFace = (x, from, to) => { const y = mesh.edge(x); if (y.left === from) y.left = to; else y.right = to; };
  const setWing = (x, v, f, value) => {
    const y = mesh.edge(x);
    if (y.start === v) { if (y.left === f) y.startLeft = value; else y.startRight = value; }
    else { if (y.left === f) y.endLeft = value; else y.endRight = value; }
  };
  setFace(b, R, L);
  setFace(d, L, R);
  setWing(a, S, L, b); setWing(a, cv, L, e);
  setWing(b, S, L, a); setWing(b, dv, L, e);
  setWing(c, E, R, d); setWing(c, dv, R, e);
  setWing(d, E, R, c); setWing(d, cv, R, e);
  r.start = dv; r.end = cv;
  r.startLeft = b; r.startRight = c; r.endLeft = a; r.endRight = d;
  if (mesh.vertex(S).edge === e) mesh.vertex(S).edge = a;
  if (mesh.vertex(E).edge === e) mesh.vertex(E).edge = c;
  if (mesh.face(L).edge === d) mesh.face(L).edge = e;
  if (mesh.face(R).edge === b) mesh.face(R).edge = e;
}`,
  // The split from the record: n takes e's place at E; a = the edge after e in L (e's E:L),
  // b = the edge before e in R (e's E:R) meet n instead of e there.
  'split-edge': `function splitEdge(mesh, e) {
  const r = mesh.edge(e);
  const S = r.start, E = r.end, L = r.left, R = r.right;
  const [sx, sy, sz] = mesh.vertex(S).position, [ex, ey, ez] = mesh.vertex(E).position;
  const m = mesh.addVertex([(sx + ex) / 2, (sy + ey) / 2, (sz + ez) / 2]);
  const n = mesh.addEdge();
  const a = r.endLeft, b = r.endRight;
  const setWing = (x, v, f, value) => {
    const y = mesh.edge(x);
    if (y.start === v) { if (y.left === f) y.startLeft = value; else y.startRight = value; }
    else { if (y.left === f) y.endLeft = value; else y.endRight = value; }
  };
  const rn = mesh.edge(n);
  rn.start = m; rn.end = E; rn.left = L; rn.right = R;
  rn.startLeft = e; rn.startRight = e; rn.endLeft = a; rn.endRight = b;
  setWing(a, E, L, n);
  setWing(b, E, R, n);
  r.end = m; r.endLeft = n; r.endRight = n;
  mesh.vertex(m).edge = n;
  if (mesh.vertex(E).edge === e) mesh.vertex(E).edge = n;
}`,
  // Loop's edge point: c and d are the other ends of the wings at S (startLeft in L,
  // startRight in R); the boundary's edge point is the midpoint.
  'loop-edge-point': `function loopEdgePoint(mesh, e) {
  const r = mesh.edge(e);
  const S = mesh.vertex(r.start).position, E = mesh.vertex(r.end).position;
  if (r.left === -1 || r.right === -1) return [0, 1, 2].map((k) => (S[k] + E[k]) / 2);
  const other = (x, v) => { const y = mesh.edge(x); return y.start === v ? y.end : y.start; };
  const c = mesh.vertex(other(r.startLeft, r.start)).position;
  const d = mesh.vertex(other(r.startRight, r.start)).position;
  return [0, 1, 2].map((k) => 3 / 8 * (S[k] + E[k]) + 1 / 8 * (c[k] + d[k]));
}`,
  // Loop's vertex point: the walk around v gives the neighbours; an edge with a face missing
  // is a boundary edge, and its other end one of the two boundary neighbours.
  'loop-vertex-point': `function loopVertexPoint(mesh, v) {
  const P = mesh.vertex(v).position;
  const ring = [], boundary = [];
  const first = mesh.vertex(v).edge;
  let e = first;
  do {
    const r = mesh.edge(e);
    const u = r.start === v ? r.end : r.start;
    ring.push(mesh.vertex(u).position);
    if (r.left === -1 || r.right === -1) boundary.push(mesh.vertex(u).position);
    e = r.start === v ? r.startLeft : r.endRight;
  } while (e !== first);
  if (boundary.length === 2) return [0, 1, 2].map((k) => boundary[0][k] / 8 + 6 / 8 * P[k] + boundary[1][k] / 8);
  const n = ring.length;
  const beta = (5 / 8 - Math.pow(3 / 8 + Math.cos(2 * Math.PI / n) / 4, 2)) / n;
  return [0, 1, 2].map((k) => (1 - n * beta) * P[k] + beta * ring.reduce((s, q) => s + q[k], 0));
}`,
  'catmull-clark-face-point': `function faceCentroid(mesh, f) {
  let x = 0, y = 0, z = 0, n = 0;
  const first = mesh.face(f).edge;
  let e = first;
  do {
    const r = mesh.edge(e);
    const [px, py, pz] = mesh.vertex(r.left === f ? r.start : r.end).position;
    x += px; y += py; z += pz; n += 1;
    e = r.left === f ? r.endLeft : r.startRight;
  } while (e !== first);
  return [x / n, y / n, z / n];
}`,
};

// A solution as typed into the editor, which indents each new line itself.
export const typed = (source) => source.split('\n').map((line) => line.trimStart()).join('\n');
