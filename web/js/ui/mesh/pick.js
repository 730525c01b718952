// @ts-check
// Picking: the element of a mesh under a point of the canvas.
// Offers: pickElement(model, x, y, zoom) -> {kind: 'vertex'|'edge'|'face', index} or null.
// Needs: a model with projected, weShown.edges, edgeGap, faceOffsets, faceVertices, and for
//   a big mesh the live core mesh (model.mesh.pick, edgesOfFace), rotation, centre, mode3d.
import { faceCount, cornersOf } from './faces.js';

// The element under a canvas point (world coordinates of the view plane): an edge within
// a few pixels, else the front-most face containing the point.
// On a big mesh the core answers which faces are near the point (mesh.pick: the face the
// line of sight passes through, nearest the viewer, and the faces within VERTEX_PICK_PX of it),
// and only their corners and sides are measured: a vertex within VERTEX_PICK_PX, else an
// edge within 6 px, else the face under the point. A small mesh is searched whole, below.
const VERTEX_PICK_PX = 8;
const CORE_PICK_EDGES = 2000; // from this size the core finds the candidates
export function pickElement(model, x, y, zoom) {
  const E = model.weShown.edges.length / 8;
  if (E > CORE_PICK_EDGES) return pickInCore(model, x, y, zoom);
  const P = model.projected;
  const tolerance = 6 / zoom;
  let best = null;
  let bestD = tolerance;
  for (let e = 0; e < E; e += 1) {
    if (model.edgeGap?.[e]) continue;
    const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
    const ax = P[3 * s]; const ay = P[3 * s + 1]; const dx = P[3 * t] - ax; const dy = P[3 * t + 1] - ay;
    const len2 = dx * dx + dy * dy;
    const u = len2 > 0 ? Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / len2)) : 0;
    const d = Math.hypot(ax + u * dx - x, ay + u * dy - y);
    if (d < bestD) { bestD = d; best = { kind: 'edge', index: e }; }
  }
  if (best) return best;
  let face = null;
  let faceDepth = -Infinity;
  for (let index = 0; index < faceCount(model); index += 1) {
    const f = cornersOf(model, index);
    if (!f.length) continue;
    let inside = false;
    for (let i = 0, j = f.length - 1; i < f.length; j = i, i += 1) {
      const xi = P[3 * f[i]]; const yi = P[3 * f[i] + 1]; const xj = P[3 * f[j]]; const yj = P[3 * f[j] + 1];
      if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
    }
    if (!inside) continue;
    const depth = f.reduce((s, v) => s + P[3 * v + 2], 0) / f.length;
    if (depth > faceDepth) { faceDepth = depth; face = { kind: 'face', index }; }
  }
  return face;
}

function pickInCore(model, x, y, zoom) {
  // The view-plane point (x, y) back to the world: R^T ((x, y, 0) - c) + c (in 2D, R = I).
  const R = model.rotation;
  const c = model.mode3d ? model.centre : [0, 0, 0];
  const dx = x - c[0]; const dy = y - c[1]; const dz = -c[2];
  const point = [R[0] * dx + R[3] * dy + R[6] * dz + c[0], R[1] * dx + R[4] * dy + R[7] * dz + c[1], R[2] * dx + R[5] * dy + R[8] * dz + c[2]];
  const { face, near } = model.mesh.pick(point, [R[6], R[7], R[8]], { radius: VERTEX_PICK_PX / zoom, max: 12 });
  if (!near.length) return null;
  const P = model.points;
  let best = null;
  let bestD = VERTEX_PICK_PX;
  for (const { face: f } of near) {
    for (let i = model.faceOffsets[f]; i < model.faceOffsets[f + 1]; i += 1) {
      const v = model.faceVertices[i];
      const d = Math.hypot(P[3 * v] - x, P[3 * v + 1] - y) * zoom;
      if (d < bestD) { bestD = d; best = { kind: 'vertex', index: v }; }
    }
  }
  if (best) return best;
  bestD = 6;
  for (const { face: f } of near) {
    for (const e of model.mesh.edgesOfFace(f)) {
      if (model.edgeGap?.[e]) continue;
      const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
      if (s < 0 || t < 0) continue;
      const ax = P[3 * s]; const ay = P[3 * s + 1]; const ex = P[3 * t] - ax; const ey = P[3 * t + 1] - ay;
      const len2 = ex * ex + ey * ey;
      const u = len2 > 0 ? Math.max(0, Math.min(1, ((x - ax) * ex + (y - ay) * ey) / len2)) : 0;
      const d = Math.hypot(ax + u * ex - x, ay + u * ey - y) * zoom;
      if (d < bestD) { bestD = d; best = { kind: 'edge', index: e }; }
    }
  }
  if (best) return best;
  return face >= 0 ? { kind: 'face', index: face } : null;
}
