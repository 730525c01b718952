// @ts-check
// The drawing of the case shown: its faces, its edges as arrows S -> E (on a small mesh),
// its vertices, the slide's labels (all of them on a small mesh, only the marked ones on a
// big one), the element the function was asked about and the entry the trace is at. The
// only arithmetic is the view: a mesh in the plane z = 0 is seen from above, any other from
// a fixed turned camera, and labels sit at the mean of their element's corners.
import { elementLabel } from '../../core/element-labels.js';

const YAW = (-35 * Math.PI) / 180;
const PITCH = (25 * Math.PI) / 180;
const SMALL = 60; // up to this many edges every element is labelled and edges get arrows

// Screen-plane positions (x, y, depth) of every vertex of a case.
export function projectCase(c) {
  const p = c.snapshot.winged.positions;
  const n = p.length / 3;
  let flat = true;
  for (let v = 0; v < n; v += 1) if (p[3 * v + 2] !== 0) { flat = false; break; }
  const out = new Float64Array(3 * n);
  const cy = Math.cos(YAW); const sy = Math.sin(YAW); const cp = Math.cos(PITCH); const sp = Math.sin(PITCH);
  for (let v = 0; v < n; v += 1) {
    const x = p[3 * v]; const y = p[3 * v + 1]; const z = p[3 * v + 2];
    if (flat) { out[3 * v] = x; out[3 * v + 1] = y; out[3 * v + 2] = 0; continue; }
    // Turn about the vertical axis (y up in the world: z towards the viewer), then tilt.
    const x1 = cy * x + sy * z; const z1 = -sy * x + cy * z;
    out[3 * v] = x1;
    out[3 * v + 1] = cp * y - sp * z1;
    out[3 * v + 2] = sp * y + cp * z1;
  }
  return out;
}

const mean = (P, vertices) => {
  let x = 0; let y = 0;
  for (const v of vertices) { x += P[3 * v]; y += P[3 * v + 1]; }
  return [x / vertices.length, y / vertices.length];
};

/**
 * @param {any} painter
 * @param {any} c the case shown (cases.js)
 * @param {Float64Array} P projectCase(c)
 * @param {{ vertex: Set<number>, edge: Set<number>, face: Set<number> }} marked elements drawn in the highlight colour
 * @param {{ vertex: Set<number>, edge: Set<number>, face: Set<number> }} asked the element the function was asked about
 * @param {any} colors
 */
export function drawCase(painter, c, P, marked, asked, colors) {
  const w = c.snapshot.winged;
  const E = w.edges.length / 8;
  const small = E <= SMALL;
  const { faceOffsets, faceVertices } = c;
  const F = faceOffsets.length - 1;
  const corners = (f) => Array.from(faceVertices.subarray(faceOffsets[f], faceOffsets[f + 1]));
  // Faces far to near, so nearer faces cover farther ones on a closed mesh.
  const order = [];
  for (let f = 0; f < F; f += 1) if (faceOffsets[f + 1] > faceOffsets[f]) order.push(f);
  const depth = (f) => corners(f).reduce((s, v) => s + P[3 * v + 2], 0) / (faceOffsets[f + 1] - faceOffsets[f]);
  order.sort((a, b) => depth(a) - depth(b));
  for (const f of order) {
    const xy = corners(f).flatMap((v) => [P[3 * v], P[3 * v + 1]]);
    const hot = marked.face.has(f) || asked.face.has(f);
    painter.polygon(xy, { fill: hot ? colors.highlight : colors.series[5], alpha: hot ? 0.35 : 0.12, stroke: undefined });
  }
  for (let e = 0; e < E; e += 1) {
    const s = w.edges[8 * e]; const t = w.edges[8 * e + 1];
    if (s < 0 || t < 0) continue;
    const hot = marked.edge.has(e) || asked.edge.has(e);
    const style = { stroke: hot ? colors.highlight : colors.ink, width: hot ? 3.5 : small ? 1.6 : 0.8, alpha: hot || small ? 1 : 0.55 };
    if (small || hot) painter.arrow(P[3 * s], P[3 * s + 1], P[3 * t], P[3 * t + 1], style);
    else painter.line(P[3 * s], P[3 * s + 1], P[3 * t], P[3 * t + 1], style);
  }
  const V = w.vertexEdge.length;
  for (let v = 0; v < V; v += 1) {
    if (w.vertexEdge[v] < 0) continue;
    const hot = marked.vertex.has(v) || asked.vertex.has(v);
    if (small || hot) painter.circle(P[3 * v], P[3 * v + 1], hot ? 6 : 4, { fill: hot ? colors.highlight : colors.ink });
  }
  // Labels: the asked and marked ones first (placed before the others when they crowd).
  const label = (kind, i, x, y, priority) => painter.text(x, y, elementLabel(kind, i), { font: 13, priority, halo: colors.background, fill: colors.ink, ...(kind === 'vertex' ? { dx: 10, dy: -10 } : {}) });
  /** @type {Array<[string, Set<number>, number]>} */
  const firsts = [['vertex', asked.vertex, 3], ['edge', asked.edge, 3], ['face', asked.face, 3], ['vertex', marked.vertex, 2], ['edge', marked.edge, 2], ['face', marked.face, 2]];
  for (const [kind, set, prio] of firsts) {
    for (const i of set) {
      if (kind === 'vertex') label('vertex', i, P[3 * i], P[3 * i + 1], prio);
      else if (kind === 'face' && faceOffsets[i + 1] > faceOffsets[i]) label('face', i, ...mean(P, corners(i)), prio);
      else if (kind === 'edge' && w.edges[8 * i] >= 0) label('edge', i, ...mean(P, [w.edges[8 * i], w.edges[8 * i + 1]]), prio);
    }
  }
  if (!small) return;
  for (let v = 0; v < V; v += 1) if (w.vertexEdge[v] >= 0) label('vertex', v, P[3 * v], P[3 * v + 1], 1);
  for (let e = 0; e < E; e += 1) if (w.edges[8 * e] >= 0) label('edge', e, ...mean(P, [w.edges[8 * e], w.edges[8 * e + 1]]), 0);
  for (const f of order) label('face', f, ...mean(P, corners(f)), 0);
}
