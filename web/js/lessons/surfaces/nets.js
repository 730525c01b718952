// @ts-check
// The geometry of the patches (lecture 002) as the lesson stores it, and where its handles
// sit. A net is 16 entries [x, y, z], entry 4i + j = row i, column j of the 4x4 geometry
// matrix P of p(u, v) = u^T M P M^T v:
//  Bezier: the control points p_ij (i along u, j along v).
//  Hermite: rows [p(0,.), p(1,.), p_u(0,.), p_u(1,.)], columns [.(.,0), .(.,1), ._v(.,0), ._v(.,1)]:
//    corner points top-left, v-tangents top-right, u-tangents bottom-left, twists bottom-right.
// Hermite handles are drawn where the equivalent Bezier control points are (lecture 002:
// p_u(0,0) = 3 (p10 - p00), p_v = 3 (p01 - p00), p_uv = 9 (p00 - p01 - p10 + p11)), so both
// nets look alike and a vector entry is dragged by its tip.

// Which corner, and which derivative, a Hermite entry belongs to.
export function hermiteRole(i, j) {
  const ui = i % 2; // corner u = 0 or 1
  const vj = j % 2;
  const du = i >= 2;
  const dv = j >= 2;
  const corner = 4 * ui + vj; // entry of the corner point itself
  const what = du && dv ? 'twist p_uv' : du ? 'u-tangent p_u' : dv ? 'v-tangent p_v' : 'corner p';
  return { ui, vj, du, dv, corner, what };
}

// Bezier-equivalent position of a Hermite entry: corner + (sign) p_u/3 + (sign) p_v/3 + p_uv/9.
export function hermiteHandle(net, i, j) {
  const r = hermiteRole(i, j);
  const su = r.ui === 0 ? 1 : -1; // towards the inside of the patch
  const sv = r.vj === 0 ? 1 : -1;
  const p = net[r.corner];
  const pu = net[4 * (2 + r.ui) + r.vj];
  const pv = net[4 * r.ui + 2 + r.vj];
  const puv = net[4 * (2 + r.ui) + 2 + r.vj];
  const out = p.slice();
  for (let k = 0; k < 3; k += 1) {
    if (r.du) out[k] += su * pu[k] / 3;
    if (r.dv) out[k] += sv * pv[k] / 3;
    if (r.du && r.dv) out[k] += su * sv * puv[k] / 9;
  }
  return out;
}

// The entry value that puts the handle of Hermite entry (i, j) at `target`.
export function hermiteEntryFromHandle(net, i, j, target) {
  const r = hermiteRole(i, j);
  const su = r.ui === 0 ? 1 : -1;
  const sv = r.vj === 0 ? 1 : -1;
  if (!r.du && !r.dv) return target.slice();
  const p = net[r.corner];
  const pu = net[4 * (2 + r.ui) + r.vj];
  const pv = net[4 * r.ui + 2 + r.vj];
  if (r.du && !r.dv) return target.map((t, k) => su * 3 * (t - p[k]));
  if (!r.du && r.dv) return target.map((t, k) => sv * 3 * (t - p[k]));
  return target.map((t, k) => su * sv * 9 * (t - p[k] - (su * pu[k]) / 3 - (sv * pv[k]) / 3));
}

export function entryName(kind, i, j) {
  if (kind === 'bezier') return `p${i}${j}`;
  const r = hermiteRole(i, j);
  return `${r.what}(${r.ui},${r.vj})`;
}

// A gently curved Bezier net over [0,3] x [0,3] (x along u, y along v, z up).
export function defaultBezierNet() {
  const z = [[0, 0.4, 0.4, 0], [0.3, 1.4, 0.9, 0.2], [0.2, 1.0, 1.6, 0.4], [0, 0.3, 0.6, 0.1]];
  const net = [];
  for (let i = 0; i < 4; i += 1) for (let j = 0; j < 4; j += 1) net.push([i - 1.5, j - 1.5, z[i][j]]);
  return net;
}

// The handle position of entry (i, j) in either kind.
export function handleOf(kind, net, i, j) {
  return kind === 'bezier' ? net[4 * i + j] : hermiteHandle(net, i, j);
}

// Joins patch B to patch A across A's u = 1 edge (B's u = 0 edge), as continuity `mode`:
// C0 shares the boundary row; C1 also matches p_u there. Bezier: B row 0 = A row 3,
// B row 1 = 2 A row 3 - A row 2 (lecture 001's collinear equal legs, column by column).
// Hermite: B p(0,.) = A p(1,.), B p_v(0,.) = A p_v(1,.); C1: B p_u(0,.) = A p_u(1,.) and
// B p_uv(0,.) = A p_uv(1,.). `master` says which patch keeps its values.
export function joinPatches(kind, a, b, mode, master = 'a') {
  const A = a.map((p) => p.slice());
  const B = b.map((p) => p.slice());
  const pairs = kind === 'bezier'
    ? [[3, 0]]
    : [[1, 0]];
  for (let j = 0; j < 4; j += 1) {
    for (const [ra, rb] of pairs) {
      if (master === 'a') B[4 * rb + j] = A[4 * ra + j].slice(); else A[4 * ra + j] = B[4 * rb + j].slice();
    }
    if (mode !== 'C1') continue;
    if (kind === 'bezier') {
      if (master === 'a') B[4 + j] = A[12 + j].map((v, k) => 2 * v - A[8 + j][k]);
      else A[8 + j] = B[j].map((v, k) => 2 * v - B[4 + j][k]);
    } else if (master === 'a') {
      B[8 + j] = A[12 + j].slice();
    } else {
      A[12 + j] = B[8 + j].slice();
    }
  }
  return { a: A, b: B };
}

// Entries of B that coincide with A's (hidden as handles while joined).
export function sharedEntriesOfB(kind) {
  return kind === 'bezier' ? [0, 1, 2, 3] : [0, 1, 2, 3];
}
