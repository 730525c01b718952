// Drawing the mesh: faces, directed edges S -> E, vertices, each labelled as on the slides,
// and the overlays of the walk (found edges in order, the current edge, the next one) and
// of the element under the mouse. Nothing here computes geometry of the mesh; the only
// arithmetic is the view: the 2D view shows (x, y), the 3D view an orthographic picture
// rotated by the state's yaw and pitch (rotate by dragging empty canvas in 3D).
import { CanvasPainter } from '../../app/painter.js';
import { vLabel, eLabel, fLabel } from './labels.js';
import { parseColour } from '../../ui/gl-mesh.js';

export const LABEL_LIMIT = 400; // more elements than this: labels culled by screen density
const CACHE_EDGES = 2000;        // from this size the still mesh is drawn once into a bitmap

// The view's rotation and projection (shared with the subdivision lesson): ui/mesh-view.js.

// The faces are CSR (model.faceOffsets, model.faceVertices): face f's corners are
// cornersOf(model, f); a removed face has none.
const faceCount = (model) => model.faceOffsets.length - 1;
const cornersOf = (model, f) => model.faceVertices.subarray(model.faceOffsets[f], model.faceOffsets[f + 1]);
const hasCorners = (model, f) => model.faceOffsets[f + 1] > model.faceOffsets[f];

function faceOrder(model, P) {
  const F = faceCount(model);
  const order = [];
  for (let f = 0; f < F; f += 1) if (hasCorners(model, f)) order.push(f);
  if (!model.mode3d) return order;
  const depth = new Float64Array(F);
  for (const f of order) {
    let z = 0;
    for (const v of cornersOf(model, f)) z += P[3 * v + 2];
    depth[f] = z / (model.faceOffsets[f + 1] - model.faceOffsets[f]);
  }
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
  const F = faceCount(model);
  const front = new Uint8Array(F).fill(1);
  if (!model.mode3d) return front;
  const { faceOffsets: o, faceVertices: c } = model;
  for (let f = 0; f < F; f += 1) {
    let area = 0;
    for (let i = o[f], j = o[f + 1] - 1; i < o[f + 1]; j = i, i += 1) area += P[3 * c[j]] * P[3 * c[i] + 1] - P[3 * c[i]] * P[3 * c[j] + 1];
    front[f] = area >= 0 ? 1 : 0;
  }
  return front;
}

function edgeSeen(model, front, e) {
  const left = model.weShown.edges[8 * e + 2]; const right = model.weShown.edges[8 * e + 3];
  return left < 0 || right < 0 || front[left] || front[right];
}

// Screen direction (x right, y up) for each vertex label: away from the faces around it, so
// the label sits outside the mesh and off its edges.
function labelDirections(model, P) {
  const dir = new Float64Array(2 * (P.length / 3));
  for (let f = 0; f < faceCount(model); f += 1) {
    if (!hasCorners(model, f)) continue;
    const face = cornersOf(model, f);
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
    for (let f = 0; f < faceCount(model); f += 1) {
      if (Boolean(front[f]) !== facing || !hasCorners(model, f)) continue;
      for (const v of cornersOf(model, f)) xy.push(P[3 * v], P[3 * v + 1]);
      offsets.push(xy.length / 2);
      if (offsets.length > BATCH) {
        painter.polygons(xy, offsets, style);
        xy = [];
        offsets = [0];
      }
    }
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

function drawBase(painter, model, state, colors, plan) {
  const P = model.projected;
  const zoom = state.view.zoom;
  const small = faceCount(model) <= LABEL_LIMIT;
  if (!small && model.weShown.edges.length / 8 > LABEL_LIMIT) {
    drawBaseBatched(painter, model, colors);
  } else {
    const faceFill = colors.series[5];
    const front = frontFacing(model, P);
    for (const f of faceOrder(model, P)) {
      painter.polygon(faceXY(cornersOf(model, f), P), { fill: faceFill, alpha: front[f] ? 0.16 : 0.06, stroke: undefined });
    }
    const E = model.weShown.edges.length / 8;
    const arrows = E <= LABEL_LIMIT;
    for (let e = 0; e < E; e += 1) {
      if (model.edgeGap?.[e] || (!arrows && model.mode3d && !edgeSeen(model, front, e))) continue;
      const [ax, ay, bx, by] = arrows ? edgeEnds(model, P, e, zoom) : [P[3 * model.weShown.edges[8 * e]], P[3 * model.weShown.edges[8 * e] + 1], P[3 * model.weShown.edges[8 * e + 1]], P[3 * model.weShown.edges[8 * e + 1] + 1]];
      if (arrows) painter.arrow(ax, ay, bx, by, { stroke: colors.ink, width: 1.6 });
      else painter.line(ax, ay, bx, by, { stroke: colors.ink, width: 0.8, alpha: 0.7 });
    }
  }
  drawLabels(painter, model, state, colors, plan);
}

// The arrows of a small mesh drawn over the GPU picture (the GPU draws the faces only).
function drawArrows(painter, model, state, colors) {
  const E = model.weShown.edges.length / 8;
  if (E > LABEL_LIMIT) return;
  for (let e = 0; e < E; e += 1) {
    if (model.edgeGap?.[e]) continue;
    painter.arrow(...edgeEnds(model, model.projected, e, state.view.zoom), { stroke: colors.ink, width: 1.6 });
  }
}

// ---------------------------------------------------------------- which labels (issue 17)
// Labels only where they can be read. A small mesh (up to LABEL_LIMIT elements of a kind)
// labels every element of that kind, as the slides do. A bigger one labels the elements the
// walk, an edit or the pointer touches, and then as many others as fit on screen without
// overlapping (a grid of placed label boxes, vertices first, then faces, then edges).
// In 3D, an element only on faces turned away from the viewer gets no label, unless no face
// at all is turned towards the viewer (an open sheet seen from behind shows its labels).
const LABEL_BOX = { w: 34, h: 18 }; // CSS px of a typical label, for the density estimate
// Characters of the label of element i (v12, e3, F7: a letter and the number i + 1).
const labelChars = (i) => String(i + 1).length + 1;
const LABEL_CHAR_PX = 10;            // CSS px per character of a label (15 px bold, rounded up)
const LABEL_MARGIN_PX = 6;           // and a margin, so neighbouring labels do not touch
const VERTEX_LABEL_PX = 18;          // a vertex label's distance from its disc

// Screen directions of the vertex labels: away from the faces around each vertex on a small
// mesh (labelDirections), up and to the right on a big one (null: the unit diagonal).
function vertexLabelDirections(model, P) {
  return model.V <= LABEL_LIMIT ? labelDirections(model, P) : null;
}
const awayX = (away, v) => (away ? away[2 * v] : Math.SQRT1_2);
const awayY = (away, v) => (away ? away[2 * v + 1] : Math.SQRT1_2);

function frontMarks(model, P) {
  if (!model.mode3d) return null;
  const front = frontFacing(model, P);
  let any = false;
  for (let f = 0; f < front.length && !any; f += 1) any = front[f] === 1 && hasCorners(model, f);
  if (!any) return null;
  const vertex = new Uint8Array(P.length / 3);
  for (let f = 0; f < front.length; f += 1) if (front[f]) for (const v of cornersOf(model, f)) vertex[v] = 1;
  return { face: front, vertex };
}

export function labelPlan(painter, model, state, forced = []) {
  const P = model.projected;
  const t = painter.t;
  const scale = painter.scale ?? 1;
  const plan = { vertices: [], faces: [], edges: [], forced: new Set(), away: null };
  const E = model.weShown.edges.length / 8;
  // A mesh with at most LABEL_LIMIT elements of every kind (the slides' meshes) is labelled
  // whole; a bigger one by screen density.
  const small = model.V <= LABEL_LIMIT && model.F <= LABEL_LIMIT && E <= LABEL_LIMIT;
  // Density first (no per-face work on a zoomed-out big mesh): how many vertices are on
  // screen; if their labels would cover more than half of it, only the touched elements
  // are labelled.
  const w = t.width; const h = t.height;
  const boxW = LABEL_BOX.w * scale; const boxH = LABEL_BOX.h * scale;
  let screen = null;
  let crowded = false;
  if (!small) {
    // Screen x = w/2 + (x - cx) zoom, y = h/2 - (y - cy) zoom (painter.js Transform), inline:
    // a call per vertex that returns an array cost 30 ms a frame on a million faces. The
    // crowding is first estimated from every k-th vertex (20,000 of them), so a zoomed-out
    // big mesh costs no per-vertex work at all.
    const ax = w / 2 - t.cx * t.zoom; const ay = h / 2 + t.cy * t.zoom; const z = t.zoom;
    const stride = Math.max(1, Math.ceil(model.V / 20000));
    let sampled = 0;
    for (let v = 0; v < model.V; v += stride) {
      const sx = ax + P[3 * v] * z; const sy = ay - P[3 * v + 1] * z;
      if (sx >= 0 && sx <= w && sy >= 0 && sy <= h) sampled += 1;
    }
    crowded = sampled * stride * boxW * boxH > 0.5 * w * h;
    if (!crowded) {
      screen = new Float32Array(2 * model.V);
      for (let v = 0; v < model.V; v += 1) { screen[2 * v] = ax + P[3 * v] * z; screen[2 * v + 1] = ay - P[3 * v + 1] * z; }
    }
  }
  const front = crowded ? null : frontMarks(model, P);
  const faceSeen = (f) => hasCorners(model, f) && (!front || front.face[f]);
  const vertexSeen = (v) => !model.vertexGap?.[v] && (!front || front.vertex[v]);
  const edgeOk = (e) => !model.edgeGap?.[e] && (!front || edgeSeen(model, front.face, e));
  const key = (kind, i) => `${kind}${i}`;
  for (const element of forced) {
    if (!element || element.index < 0) continue;
    const list = element.kind === 'vertex' ? plan.vertices : element.kind === 'face' ? plan.faces : plan.edges;
    if (plan.forced.has(key(element.kind, element.index))) continue;
    plan.forced.add(key(element.kind, element.index));
    list.push(element.index);
  }
  if (small) {
    for (let v = 0; v < model.V; v += 1) if (vertexSeen(v) && !plan.forced.has(key('vertex', v))) plan.vertices.push(v);
    for (let f = 0; f < faceCount(model); f += 1) if (faceSeen(f) && !plan.forced.has(key('face', f))) plan.faces.push(f);
    for (let e = 0; e < E; e += 1) if (edgeOk(e) && !plan.forced.has(key('edge', e))) plan.edges.push(e);
    return plan;
  }
  if (crowded) return plan;
  plan.away = vertexLabelDirections(model, P);
  const placed = new Map();
  // Claims the box of a label of `chars` characters centred at (sx, sy) if it is on screen
  // and overlaps no box placed (`force`: claims it anyway, for the touched elements, which
  // are drawn whatever). Widths: LABEL_CHAR_PX per character plus a margin.
  const halfWidth = (chars) => ((LABEL_CHAR_PX * chars + LABEL_MARGIN_PX) * scale) / 2;
  // Cells at least as wide as two of the widest boxes: overlaps are found in the 3 x 3 cells around.
  const cell = Math.max(2 * halfWidth(9), 2 * boxH);
  const fits = (sx, sy, chars, force = false) => {
    const cx = Math.floor(sx / cell); const cy = Math.floor(sy / cell);
    const half = halfWidth(chars);
    if (!force) {
      if (sx < 0 || sx > w || sy < 0 || sy > h) return false;
      for (let i = cx - 1; i <= cx + 1; i += 1) {
        for (let j = cy - 1; j <= cy + 1; j += 1) {
          for (const [x, y, hw] of placed.get(i * 65536 + j) ?? []) if (Math.abs(x - sx) < hw + half && Math.abs(y - sy) < boxH) return false;
        }
      }
    }
    const k = cx * 65536 + cy;
    if (!placed.has(k)) placed.set(k, []);
    placed.get(k).push([sx, sy, half]);
    return true;
  };
  const at = (x, y) => t.toScreen(x, y);
  // A vertex label sits VERTEX_LABEL_PX beside its disc (drawLabels): its box is there.
  const vx = (v) => screen[2 * v] + VERTEX_LABEL_PX * scale * awayX(plan.away, v);
  const vy = (v) => screen[2 * v + 1] - VERTEX_LABEL_PX * scale * awayY(plan.away, v);
  const edgeMid = (e) => {
    const a = model.weShown.edges[8 * e]; const b = model.weShown.edges[8 * e + 1];
    return [(screen[2 * a] + screen[2 * b]) / 2, (screen[2 * a + 1] + screen[2 * b + 1]) / 2];
  };
  // The touched elements' boxes first (they are drawn whatever the overlap).
  for (const v of plan.vertices) fits(vx(v), vy(v), vLabel(v).length, true);
  for (const f of plan.faces) if (hasCorners(model, f)) fits(...at(...centroid(cornersOf(model, f), P)), fLabel(f).length, true);
  for (const e of plan.edges) if (model.weShown.edges[8 * e] >= 0 && model.weShown.edges[8 * e + 1] >= 0) fits(...edgeMid(e), eLabel(e).length, true);
  // Only what is on screen is considered further (no work, no string, per element off it):
  // a zoomed-in view of a million faces costs a pass over numbers only.
  const onScreen = (x, y) => x >= 0 && x <= w && y >= 0 && y <= h;
  for (let v = 0; v < model.V; v += 1) {
    const x = vx(v); const y = vy(v);
    if (onScreen(x, y) && vertexSeen(v) && !plan.forced.has(key('vertex', v)) && fits(x, y, labelChars(v))) plan.vertices.push(v);
  }
  const { faceOffsets: o, faceVertices: c } = model;
  for (let f = 0; f < faceCount(model); f += 1) {
    const n = o[f + 1] - o[f];
    if (!n) continue;
    let x = 0; let y = 0;
    for (let i = o[f]; i < o[f + 1]; i += 1) { x += screen[2 * c[i]]; y += screen[2 * c[i] + 1]; }
    x /= n; y /= n;
    if (onScreen(x, y) && faceSeen(f) && !plan.forced.has(key('face', f)) && fits(x, y, labelChars(f))) plan.faces.push(f);
  }
  const ends = model.weShown.edges;
  for (let e = 0; e < E; e += 1) {
    const a = ends[8 * e]; const b = ends[8 * e + 1];
    if (a < 0 || b < 0) continue;
    const x = (screen[2 * a] + screen[2 * b]) / 2; const y = (screen[2 * a + 1] + screen[2 * b + 1]) / 2;
    if (onScreen(x, y) && edgeOk(e) && !plan.forced.has(key('edge', e)) && fits(x, y, labelChars(e))) plan.edges.push(e);
  }
  return plan;
}

function drawLabels(painter, model, state, colors, plan) {
  const P = model.projected;
  // Every vertex of a mesh of up to LABEL_LIMIT vertices has its disc (a handle to drag);
  // the labelled ones get theirs below.
  if (model.V <= LABEL_LIMIT) {
    const labelled = new Set(plan.vertices);
    for (let v = 0; v < model.V; v += 1) {
      if (!labelled.has(v) && !model.vertexGap?.[v]) painter.circle(P[3 * v], P[3 * v + 1], 5, { fill: colors.accent, stroke: colors.background, width: 1.5 });
    }
  }
  for (const f of plan.faces) {
    if (!hasCorners(model, f)) continue;
    const [x, y] = centroid(cornersOf(model, f), P);
    painter.text(x, y, fLabel(f), { fill: colors.series[2], font: 16, weight: 700, halo: colors.background });
  }
  for (const e of plan.edges) {
    const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
    if (s < 0 || t < 0) continue;
    painter.text((P[3 * s] + P[3 * t]) / 2, (P[3 * s + 1] + P[3 * t + 1]) / 2, eLabel(e), { fill: colors.ink, font: 13, weight: 600, halo: colors.background });
  }
  const away = plan.vertices.length ? (plan.away ?? vertexLabelDirections(model, P)) : null;
  for (const v of plan.vertices) {
    const dx = awayX(away, v); const dy = awayY(away, v);
    painter.circle(P[3 * v], P[3 * v + 1], 5, { fill: colors.accent, stroke: colors.background, width: 1.5 });
    painter.text(P[3 * v], P[3 * v + 1], vLabel(v), { fill: colors.accent, font: 15, weight: 700, dx: VERTEX_LABEL_PX * dx, dy: -VERTEX_LABEL_PX * dy, halo: colors.background });
  }
}

// One per lesson view (setup): the picture of the last base drawing of a big mesh.
export function createBaseCache() {
  return { key: null, sceneKey: null, view: null, canvas: null, ms: 0, timer: 0, gpu: { viewKey: null, meshKey: null, timer: 0, proxyPending: false, uploading: null } };
}
const SLOW_BASE_MS = 30;     // a base picture slower than this is not redrawn while panning
const SETTLE_MS = 200;       // ... but once the view has been still this long

function drawBaseCached(baseCache, painter, model, state, ctx, plan) {
  const E = model.weShown.edges.length / 8;
  if (!(painter instanceof CanvasPainter) || E < CACHE_EDGES) {
    drawBase(painter, model, state, ctx.colors, plan);
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
    drawLabels(painter, model, state, ctx.colors, plan);
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
    const basePainter = new CanvasPainter(g, painter.t, { scale: painter.scale, background: ctx.colors.background });
    drawBase(basePainter, model, state, ctx.colors, { vertices: [], faces: [], edges: [] });
    basePainter.finish();
    Object.assign(baseCache, { key, sceneKey, view: { ...v }, canvas, ms: performance.now() - t0 });
  }
  painter.g.drawImage(baseCache.canvas, 0, 0, width, height);
  drawLabels(painter, model, state, ctx.colors, plan); // labels follow the walk: not in the bitmap
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
  if (element.kind === 'face' && element.index < faceCount(model)) painter.polygon(faceXY(cornersOf(model, element.index), P), { fill: colour, alpha: strong ? 0.35 : 0.25 });
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
    painter.polygon(faceXY(cornersOf(model, model.walkElement), P), { fill: found, alpha: 0.18 });
  }
  if (frame.current >= 0 && !frame.done) highlightEdge(painter, model, frame.current, { stroke: current, width: 11, alpha: 0.55 });
  const zoom = state.view.zoom;
  for (let k = 0; k < frame.foundCount; k += 1) {
    const e = frame.order[k];
    // Found edges keep their S -> E arrow and their label on top of the highlight (on a
    // mesh of any size: the walk's elements are always labelled).
    painter.arrow(...edgeEnds(model, P, e, zoom), { stroke: found, width: 4.5 });
    {
      const s0 = model.weShown.edges[8 * e]; const t0 = model.weShown.edges[8 * e + 1];
      painter.text((P[3 * s0] + P[3 * t0]) / 2, (P[3 * s0 + 1] + P[3 * t0 + 1]) / 2, eLabel(e), { fill: colors.ink, font: 13, weight: 700, halo: colors.background });
    }
    const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
    const x = P[3 * s] + (P[3 * t] - P[3 * s]) * 0.7; const y = P[3 * s + 1] + (P[3 * t + 1] - P[3 * s + 1]) * 0.7;
    painter.circle(x, y, 10, { fill: found, stroke: colors.background, width: 1.5 });
    painter.text(x, y, String(k + 1), { fill: colors.background, font: 12, weight: 700, fixed: true, priority: 1 });
  }
  if (!frame.done && frame.next >= 0 && frame.line >= 2) highlightEdge(painter, model, frame.next, { stroke: found, width: 3, dash: [6, 6] });
}

// The elements the walk, an edit or the pointer touches: always labelled.
function touched(model, selection) {
  const out = [];
  if (model.frame) {
    out.push({ kind: model.walkKind, index: model.walkElement });
    if (model.frame.current >= 0) out.push({ kind: 'edge', index: model.frame.current });
    if (model.frame.next >= 0 && !model.frame.done) out.push({ kind: 'edge', index: model.frame.next });
  }
  if (model.editRow) out.push(model.editRow);
  if (model.lastEdit && model.lastOperation?.rows) {
    for (const row of model.lastOperation.rows.slice(0, 24)) out.push({ kind: row.table, index: row.row });
  }
  out.push(selection.pick, selection.hover);
  return out.filter((x) => x && ['vertex', 'edge', 'face'].includes(x.kind) && Number.isInteger(x.index));
}

// The style of the GPU picture: what drawBase draws as paths, as one draw call each.
// A big mesh in 3D is a lit nearest surface; its edges (2D or 3D) are drawn while they are at
// least EDGE_SPACING_PX apart on screen on average (closer, they would be a grey blur). While the
// view moves, a mesh of more than PROXY_FROM triangles is drawn as its display proxy (the
// core's vertex clustering, PROXY_TRIANGLES), and whole again SETTLE_MS after the last move.
const EDGE_SPACING_PX = 4;
const PROXY_FROM = 60000;
const PROXY_TRIANGLES = 24000;
function drawGpu(gl, gpu, model, state, ctx) {
  const { width, height, dpr } = ctx.stage.size;
  const v = state.view;
  const centre = model.centre;
  const key = `${model.source}|${model.topology}|${model.version}|${model.weShown === model.we ? 'all' : model.editStep}`;
  const data = {
    positions: model.positions, faceOffsets: model.faceOffsets, faceVertices: model.faceVertices,
    edges: model.weShown.edges, edgeStride: 8, edgeGap: model.edgeGap, centre,
  };
  if (gl.meshKey !== key && model.faceVertices.length > 3 * PROXY_FROM) {
    // A new big mesh is prepared and uploaded in tasks of their own (about 25 and 20 ms for a
    // million faces here), not in the frame that updates the panels; meanwhile the
    // background is shown.
    if (gpu.uploading !== key) {
      gpu.uploading = key;
      setTimeout(() => {
        if (gpu.uploading !== key) return;
        const prepared = gl.prepareMesh(key, data);
        setTimeout(() => {
          if (gpu.uploading !== key) return;
          gpu.uploading = null;
          gl.uploadMesh(prepared);
          ctx.render();
        }, 0);
      }, 0);
    }
    gl.clearPicture(parseColour(ctx.colors.background));
    return;
  }
  gl.setMesh(key, data);
  const viewKey = `${key}|${model.rotation.join(',')}|${v.cx}|${v.cy}|${v.zoom}|${width}|${height}`;
  const moving = gpu.viewKey !== null && gpu.viewKey !== viewKey && gpu.meshKey === key && gl.triangleCount > PROXY_FROM;
  gpu.viewKey = viewKey;
  gpu.meshKey = key;
  if (moving) {
    if (!gl.hasProxy) gl.setProxy(key, model.mesh.displayProxy(PROXY_TRIANGLES));
    clearTimeout(gpu.timer);
    gpu.timer = setTimeout(() => { gpu.viewKey = null; ctx.render(); }, SETTLE_MS);
  }
  const E = model.weShown.edges.length / 8;
  const big = E > LABEL_LIMIT;
  const spacing = Math.sqrt((Math.PI * (gl.radius * v.zoom) ** 2) / Math.max(1, model.F / 2));
  const colors = ctx.colors;
  const drawn = gl.draw(
    { R: model.rotation, offset: [centre[0] - v.cx, centre[1] - v.cy], zoom: v.zoom, width, height, dpr },
    {
      background: parseColour(colors.background), fill: parseColour(colors.series[5]), ink: parseColour(colors.ink),
      faceAlpha: 0.16, backAlpha: model.mode3d ? 0.06 : 0.16, lit: big && model.mode3d,
      edges: big && !moving && spacing >= EDGE_SPACING_PX, edgeAlpha: 0.7, useProxy: moving,
    },
  );
  if (drawn !== 'more') return;
  // A big picture drawn over frames (gl-mesh.js): go on next frame. Its proxy stands in
  // meanwhile; made in a task of its own (25 ms for a million faces here), not this frame's.
  if (!gl.hasProxy && gl.triangleCount > PROXY_FROM && !gpu.proxyPending) {
    gpu.proxyPending = true;
    setTimeout(() => {
      gpu.proxyPending = false;
      if (gl.meshKey === key && !model.mesh.disposed) gl.setProxy(key, model.mesh.displayProxy(PROXY_TRIANGLES));
      ctx.render();
    }, 0);
  } else {
    ctx.render();
  }
}

export function drawMesh(baseCache, selection, painter, model, state, ctx) {
  if (!model) return;
  const plan = labelPlan(painter, model, state, touched(model, selection));
  const gl = painter instanceof CanvasPainter ? ctx.stage.gl() : null;
  if (gl) {
    painter.clearTransparent();
    drawGpu(gl, baseCache.gpu, model, state, ctx);
    drawArrows(painter, model, state, ctx.colors);
    drawLabels(painter, model, state, ctx.colors, plan);
  } else {
    drawBaseCached(baseCache, painter, model, state, ctx, plan);
  }
  drawWalk(painter, model, state, ctx.colors);
  drawElement(painter, model, selection.hover, ctx.colors, false);
  drawElement(painter, model, selection.pick, ctx.colors, true);
  // The edit player: the row the current assignment writes, on the canvas too.
  if (model.editRow) drawElement(painter, model, model.editRow, ctx.colors, true);
}

// The element under a canvas point (world coordinates of the view plane): an edge within
// a few pixels, else the front-most face containing the point.
// On a big mesh the core answers which faces are near the point (mesh.pick: the face the
// line of sight passes through, nearest the viewer, and the faces within VERTEX_PICK_PX of it),
// and only their corners and sides are measured: a vertex within VERTEX_PICK_PX, else an
// edge within 6 px, else the face under the point. A small mesh is searched whole, below.
const VERTEX_PICK_PX = 8;
const CORE_PICK_EDGES = 2000; // from this size the core finds the candidates
export function pickElement(model, x, y, zoom) {
  const P = model.projected;
  const E = model.weShown.edges.length / 8;
  if (E > CORE_PICK_EDGES) return pickInCore(model, x, y, zoom);
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
  const P = model.projected;
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
