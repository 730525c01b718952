// Drawing the mesh: faces, directed edges S -> E, vertices, each labelled as on the slides,
// and the overlays of the walk (found edges in order, the current edge, the next one) and
// of the element under the mouse. Nothing here computes geometry of the mesh; the only
// arithmetic is the view: the 2D view shows (x, y), the 3D view an orthographic picture
// rotated by the state's yaw and pitch (rotate by dragging empty canvas in 3D).
import { CanvasPainter } from '../../app/painter.js';
import { vLabel, eLabel, fLabel } from './labels.js';

export const LABEL_LIMIT = 400; // more elements than this: no labels (they would overlap)
const CACHE_EDGES = 2000;        // from this size the still mesh is drawn once into a bitmap

// The view's rotation and projection (shared with the subdivision lesson): ui/mesh-view.js.

function faceOrder(model, P) {
  const order = [];
  model.faces.forEach((face, f) => { if (face.length) order.push(f); }); // a removed face has no corners
  if (!model.mode3d) return order;
  const depth = model.faces.map((face) => face.reduce((s, v) => s + P[3 * v + 2], 0) / Math.max(1, face.length));
  return order.sort((a, b) => depth[a] - depth[b]);
}

function faceXY(face, P) {
  const xy = new Float64Array(2 * face.length);
  face.forEach((v, i) => { xy[2 * i] = P[3 * v]; xy[2 * i + 1] = P[3 * v + 1]; });
  return xy;
}

function centroid(face, P) {
  let x = 0; let y = 0;
  for (const v of face) { x += P[3 * v]; y += P[3 * v + 1]; }
  return [x / face.length, y / face.length];
}

// The part of an edge that is drawn: shortened at both ends so the arrow head stays
// visible next to the vertex disc.
function edgeEnds(model, P, e, zoom, insetPx = 11) {
  const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
  const ax = P[3 * s]; const ay = P[3 * s + 1]; const bx = P[3 * t]; const by = P[3 * t + 1];
  const len = Math.hypot(bx - ax, by - ay);
  const k = len > 0 ? Math.min(0.3, insetPx / zoom / len) : 0;
  return [ax + (bx - ax) * k, ay + (by - ay) * k, bx - (bx - ax) * k, by - (by - ay) * k];
}

// In 3D a face whose projected corners run clockwise faces away (faces are CCW seen from
// outside); large meshes then skip the edges of the far side, so the picture stays legible.
function frontFacing(model, P) {
  return model.faces.map((face) => {
    if (!model.mode3d) return true;
    let area = 0;
    for (let i = 0, j = face.length - 1; i < face.length; j = i, i += 1) area += P[3 * face[j]] * P[3 * face[i] + 1] - P[3 * face[i]] * P[3 * face[j] + 1];
    return area >= 0;
  });
}

function edgeSeen(model, front, e) {
  const left = model.weShown.edges[8 * e + 2]; const right = model.weShown.edges[8 * e + 3];
  return left < 0 || right < 0 || front[left] || front[right];
}

// Screen direction (x right, y up) for each vertex label: away from the faces around it, so
// the label sits outside the mesh and off its edges.
function labelDirections(model, P) {
  const dir = new Float64Array(2 * (P.length / 3));
  for (const face of model.faces) {
    if (!face.length) continue;
    const [cx, cy] = centroid(face, P);
    for (const v of face) { dir[2 * v] += P[3 * v] - cx; dir[2 * v + 1] += P[3 * v + 1] - cy; }
  }
  for (let v = 0; 2 * v < dir.length; v += 1) {
    const len = Math.hypot(dir[2 * v], dir[2 * v + 1]);
    if (len > 1e-12) { dir[2 * v] /= len; dir[2 * v + 1] /= len; } else { dir[2 * v] = Math.SQRT1_2; dir[2 * v + 1] = Math.SQRT1_2; }
  }
  return dir;
}

// A mesh too big for face and edge labels: faces and visible edges drawn as batched paths
// (faces turned away first, as they are farther on average) instead of one call each, which
// took about 350 ms per frame for 100k faces. A path is kept to BATCH shapes: the
// rasteriser's cost grows faster than linearly with the number of subpaths in one path.
// One fill per batch means translucent faces overlapping on screen darken once inside a
// batch, not once per face: the shading of such a big mesh is a hint of its shape only.
const BATCH = 256;

function drawBaseBatched(painter, model, colors) {
  const P = model.projected;
  const front = frontFacing(model, P);
  for (const facing of [false, true]) {
    const style = { fill: colors.series[5], alpha: facing ? 0.16 : 0.06, stroke: undefined };
    let xy = [];
    let offsets = [0];
    model.faces.forEach((face, f) => {
      if (front[f] !== facing || !face.length) return;
      for (const v of face) xy.push(P[3 * v], P[3 * v + 1]);
      offsets.push(xy.length / 2);
      if (offsets.length > BATCH) {
        painter.polygons(xy, offsets, style);
        xy = [];
        offsets = [0];
      }
    });
    if (offsets.length > 1) painter.polygons(xy, offsets, style);
  }
  const E = model.weShown.edges.length / 8;
  const edgeStyle = { stroke: colors.ink, width: 0.8, alpha: 0.7 };
  let segments = [];
  for (let e = 0; e < E; e += 1) {
    if (model.edgeGap?.[e] || (model.mode3d && !edgeSeen(model, front, e))) continue;
    const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
    segments.push(P[3 * s], P[3 * s + 1], P[3 * t], P[3 * t + 1]);
    if (segments.length >= 4 * BATCH) {
      painter.segments(segments, edgeStyle);
      segments = [];
    }
  }
  if (segments.length) painter.segments(segments, edgeStyle);
}

function drawBase(painter, model, state, colors) {
  const P = model.projected;
  const zoom = state.view.zoom;
  const labels = model.faces.length <= LABEL_LIMIT;
  if (!labels && model.weShown.edges.length / 8 > LABEL_LIMIT) {
    drawBaseBatched(painter, model, colors);
    drawVertices(painter, model, colors); // a grid of 450 faces has only 256 vertices: labelled
    return;
  }
  const faceFill = colors.series[5];
  const front = frontFacing(model, P);
  for (const f of faceOrder(model, P)) {
    painter.polygon(faceXY(model.faces[f], P), { fill: faceFill, alpha: front[f] ? 0.16 : 0.06, stroke: undefined });
  }
  const E = model.weShown.edges.length / 8;
  const arrows = E <= LABEL_LIMIT;
  for (let e = 0; e < E; e += 1) {
    if (model.edgeGap?.[e] || (!arrows && model.mode3d && !edgeSeen(model, front, e))) continue;
    const [ax, ay, bx, by] = arrows ? edgeEnds(model, P, e, zoom) : [P[3 * model.weShown.edges[8 * e]], P[3 * model.weShown.edges[8 * e] + 1], P[3 * model.weShown.edges[8 * e + 1]], P[3 * model.weShown.edges[8 * e + 1] + 1]];
    if (arrows) painter.arrow(ax, ay, bx, by, { stroke: colors.ink, width: 1.6 });
    else painter.line(ax, ay, bx, by, { stroke: colors.ink, width: 0.8, alpha: 0.7 });
  }
  if (labels) {
    model.faces.forEach((face, f) => {
      if (!face.length) return;
      const [x, y] = centroid(face, P);
      painter.text(x, y, fLabel(f), { fill: colors.series[2], font: 16, weight: 700, halo: colors.background });
    });
  }
  if (arrows) {
    for (let e = 0; e < E; e += 1) {
      if (model.edgeGap?.[e]) continue;
      const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
      const mx = (P[3 * s] + P[3 * t]) / 2; const my = (P[3 * s + 1] + P[3 * t + 1]) / 2;
      painter.text(mx, my, eLabel(e), { fill: colors.ink, font: 13, weight: 600, halo: colors.background });
    }
  }
  drawVertices(painter, model, colors);
}

// Vertex discs and v labels, up to LABEL_LIMIT vertices.
function drawVertices(painter, model, colors) {
  const P = model.projected;
  const V = P.length / 3;
  if (V > LABEL_LIMIT) return;
  const away = labelDirections(model, P);
  for (let v = 0; v < V; v += 1) {
    if (model.vertexGap?.[v]) continue;
    painter.circle(P[3 * v], P[3 * v + 1], 5, { fill: colors.accent, stroke: colors.background, width: 1.5 });
    painter.text(P[3 * v], P[3 * v + 1], vLabel(v), { fill: colors.accent, font: 15, weight: 700, dx: 18 * away[2 * v], dy: -18 * away[2 * v + 1], halo: colors.background });
  }
}

// One per lesson view (setup): the picture of the last base drawing of a big mesh.
export function createBaseCache() {
  return { key: null, sceneKey: null, view: null, canvas: null, ms: 0, timer: 0 };
}
const SLOW_BASE_MS = 30;     // a base picture slower than this is not redrawn while panning
const SETTLE_MS = 200;       // ... but once the view has been still this long

function drawBaseCached(baseCache, painter, model, state, ctx) {
  const E = model.weShown.edges.length / 8;
  if (!(painter instanceof CanvasPainter) || E < CACHE_EDGES) {
    drawBase(painter, model, state, ctx.colors);
    return;
  }
  const { width, height, dpr } = ctx.stage.size;
  const v = state.view;
  const sceneKey = [model.topology, model.version, model.editStep, state.mode3d, state.rotation.yaw, state.rotation.pitch,
    width, height, dpr, ctx.colors.background, ctx.colors.ink, painter.scale].join('|');
  const key = `${sceneKey}|${v.cx}|${v.cy}|${v.zoom}`;
  if (baseCache.key !== key && baseCache.sceneKey === sceneKey && baseCache.ms > SLOW_BASE_MS) {
    // Pan or zoom of a big mesh: move the last picture with the view now, redraw it sharp
    // when the view has settled (s_new = k s_old + offset, k = zoom / old zoom).
    const old = baseCache.view;
    const k = v.zoom / old.zoom;
    const ox = width / 2 + (old.cx - v.cx) * v.zoom - k * width / 2;
    const oy = height / 2 - (old.cy - v.cy) * v.zoom - k * height / 2;
    painter.g.drawImage(baseCache.canvas, ox, oy, width * k, height * k);
    clearTimeout(baseCache.timer);
    baseCache.timer = setTimeout(() => { baseCache.sceneKey = null; ctx.render(); }, SETTLE_MS);
    return;
  }
  if (baseCache.key !== key) {
    const t0 = performance.now();
    const canvas = baseCache.canvas ?? document.createElement('canvas');
    canvas.width = Math.round(width * dpr);
    canvas.height = Math.round(height * dpr);
    const g = canvas.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, width, height);
    drawBase(new CanvasPainter(g, painter.t, { scale: painter.scale, background: ctx.colors.background }), model, state, ctx.colors);
    Object.assign(baseCache, { key, sceneKey, view: { ...v }, canvas, ms: performance.now() - t0 });
  }
  painter.g.drawImage(baseCache.canvas, 0, 0, width, height);
}

function highlightEdge(painter, model, e, style) {
  const P = model.projected;
  const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
  painter.line(P[3 * s], P[3 * s + 1], P[3 * t], P[3 * t + 1], style);
}

function drawElement(painter, model, element, colors, strong) {
  if (!element || (element.kind === 'edge' && model.edgeGap?.[element.index])) return;
  const P = model.projected;
  const colour = colors.series[2];
  if (element.kind === 'vertex') painter.circle(P[3 * element.index], P[3 * element.index + 1], strong ? 11 : 9, { stroke: colour, width: 3 });
  if (element.kind === 'edge') highlightEdge(painter, model, element.index, { stroke: colour, width: strong ? 7 : 5, alpha: 0.8 });
  if (element.kind === 'face') painter.polygon(faceXY(model.faces[element.index], P), { fill: colour, alpha: strong ? 0.35 : 0.25 });
}

function drawWalk(painter, model, state, colors) {
  const frame = model.frame;
  if (!frame) return;
  const P = model.projected;
  const found = colors.series[1];
  const current = colors.series[4];
  if (model.walkKind === 'vertex') {
    const v = model.walkElement;
    painter.circle(P[3 * v], P[3 * v + 1], 13, { stroke: found, width: 3 });
  } else {
    painter.polygon(faceXY(model.faces[model.walkElement], P), { fill: found, alpha: 0.18 });
  }
  if (frame.current >= 0 && !frame.done) highlightEdge(painter, model, frame.current, { stroke: current, width: 11, alpha: 0.55 });
  const zoom = state.view.zoom;
  const labelled = model.E <= LABEL_LIMIT;
  for (let k = 0; k < frame.foundCount; k += 1) {
    const e = frame.order[k];
    // Found edges keep their S -> E arrow and their label on top of the highlight.
    painter.arrow(...edgeEnds(model, P, e, zoom), { stroke: found, width: 4.5 });
    if (labelled) {
      const s0 = model.weShown.edges[8 * e]; const t0 = model.weShown.edges[8 * e + 1];
      painter.text((P[3 * s0] + P[3 * t0]) / 2, (P[3 * s0 + 1] + P[3 * t0 + 1]) / 2, eLabel(e), { fill: colors.ink, font: 13, weight: 700, halo: colors.background });
    }
    const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
    const x = P[3 * s] + (P[3 * t] - P[3 * s]) * 0.7; const y = P[3 * s + 1] + (P[3 * t + 1] - P[3 * s + 1]) * 0.7;
    painter.circle(x, y, 10, { fill: found, stroke: colors.background, width: 1.5 });
    painter.text(x, y, String(k + 1), { fill: colors.background, font: 12, weight: 700 });
  }
  if (!frame.done && frame.next >= 0 && frame.line >= 2) highlightEdge(painter, model, frame.next, { stroke: found, width: 3, dash: [6, 6] });
}

export function drawMesh(baseCache, selection, painter, model, state, ctx) {
  if (!model) return;
  drawBaseCached(baseCache, painter, model, state, ctx);
  drawWalk(painter, model, state, ctx.colors);
  drawElement(painter, model, selection.hover, ctx.colors, false);
  drawElement(painter, model, selection.pick, ctx.colors, true);
  // The edit player: the row the current assignment writes, on the canvas too.
  if (model.editRow) drawElement(painter, model, model.editRow, ctx.colors, true);
}

// The element under a canvas point (world coordinates of the view plane): an edge within
// a few pixels, else the front-most face containing the point.
export function pickElement(model, x, y, zoom) {
  const P = model.projected;
  const E = model.weShown.edges.length / 8;
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
  model.faces.forEach((f, index) => {
    if (!f.length) return;
    let inside = false;
    for (let i = 0, j = f.length - 1; i < f.length; j = i, i += 1) {
      const xi = P[3 * f[i]]; const yi = P[3 * f[i] + 1]; const xj = P[3 * f[j]]; const yj = P[3 * f[j] + 1];
      if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
    }
    if (!inside) return;
    const depth = f.reduce((s, v) => s + P[3 * v + 2], 0) / f.length;
    if (depth > faceDepth) { faceDepth = depth; face = { kind: 'face', index }; }
  });
  return face;
}
