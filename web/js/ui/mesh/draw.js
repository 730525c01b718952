// @ts-check
// Drawing the mesh: faces, directed edges S -> E, vertices, each labelled as on the slides,
// and the overlays of the walk (found edges in order, the current edge, the next one) and
// of the element under the mouse. Nothing here computes geometry of the mesh; the only
// arithmetic is the view: the 2D view shows (x, y), the 3D view an orthographic picture
// rotated by the state's yaw and pitch (rotate by dragging empty canvas in 3D).
// Offers: drawMesh(baseCache, selection, painter, model, state, ctx), createBaseCache() (one
//   per lesson view: the picture of a big mesh, kept between frames).
// Needs: the model a mesh lesson computes (its fields below: mesh, source, topology, version,
//   positions, projected, rotation, centre, faceOffsets, faceVertices, we, weShown, V, F,
//   mode3d, vertexGap, edgeGap, editStep, editRow, lastEdit, lastOperation, and the walk's
//   walkKind, walkElement, frame: ui/mesh/walk.js), selection {hover, pick} ({kind, index} or
//   null), state.view and state.rotation, and the shell's ctx (stage.size, stage.gl(),
//   colors, render()).
import { CanvasPainter } from '../../app/painter.js';
import { eLabel } from '../element-labels.js';
import { parseColour } from '../gl-mesh.js';
import { faceCount, cornersOf, hasCorners, faceXY, frontFacing, edgeSeen } from './faces.js';
import { LABEL_LIMIT, labelPlan, drawLabels, createLabelCache } from './label-plan.js';
import { recordEdges } from './winged-arrays.js';

const CACHE_EDGES = 2000;        // from this size the still mesh is drawn once into a bitmap

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

// The part of an edge that is drawn: shortened at both ends so the arrow head stays
// visible next to the vertex disc.
function edgeEnds(model, P, e, zoom, insetPx = 11) {
  const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
  const ax = P[3 * s]; const ay = P[3 * s + 1]; const bx = P[3 * t]; const by = P[3 * t + 1];
  const len = Math.hypot(bx - ax, by - ay);
  const k = len > 0 ? Math.min(0.3, insetPx / zoom / len) : 0;
  return [ax + (bx - ax) * k, ay + (by - ay) * k, bx - (bx - ax) * k, by - (by - ay) * k];
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
      painter.polygon(faceXY(model, P, f), { fill: faceFill, alpha: front[f] ? 0.16 : 0.06, stroke: undefined });
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

// One per lesson view (setup): the picture of the last base drawing of a big mesh, and the
// label candidates of the last scene and view (label-plan.js).
export function createBaseCache() {
  return { key: null, sceneKey: null, view: null, canvas: null, ms: 0, timer: 0, gpu: { viewKey: null, meshKey: null, timer: 0, proxyPending: false, uploading: null }, labels: createLabelCache() };
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
  const P = model.points;
  const s = model.weShown.edges[8 * e]; const t = model.weShown.edges[8 * e + 1];
  painter.line(P[3 * s], P[3 * s + 1], P[3 * t], P[3 * t + 1], style);
}

function drawElement(painter, model, element, colors, strong) {
  if (!element || (element.kind === 'edge' && model.edgeGap?.[element.index])) return;
  const P = model.points;
  const colour = colors.series[2];
  if (element.kind === 'vertex') painter.circle(P[3 * element.index], P[3 * element.index + 1], strong ? 11 : 9, { stroke: colour, width: 3 });
  if (element.kind === 'edge') highlightEdge(painter, model, element.index, { stroke: colour, width: strong ? 7 : 5, alpha: 0.8 });
  if (element.kind === 'face' && element.index < faceCount(model)) painter.polygon(faceXY(model, P, element.index), { fill: colour, alpha: strong ? 0.35 : 0.25 });
}

// How many of the found edges (the last ones) carry their name and step number: a pole of
// valence 40,000 would ask 80,000 labels per frame, and no screen shows more than a few dozen.
const FOUND_LABELLED = 48;

// elementOnly: the walk's vertex (face) alone, without its edges (a half-edge walk being
// predicted starts on a half-edge of another edge than the winged walk's first).
function drawWalk(painter, model, state, colors, elementOnly = false) {
  const frame = model.frame;
  if (!frame) return;
  const P = model.points;
  const found = colors.series[1];
  const current = colors.series[4];
  if (model.walkKind === 'vertex') {
    const v = model.walkElement;
    painter.circle(P[3 * v], P[3 * v + 1], 13, { stroke: found, width: 3 });
  } else {
    painter.polygon(faceXY(model, P, model.walkElement), { fill: found, alpha: 0.18 });
  }
  if (elementOnly) return;
  if (frame.current >= 0 && !frame.done) highlightEdge(painter, model, frame.current, { stroke: current, width: 11, alpha: 0.55 });
  const zoom = state.view.zoom;
  const labelledFrom = Math.max(0, frame.foundCount - FOUND_LABELLED);
  for (let k = 0; k < frame.foundCount; k += 1) {
    const e = frame.order[k];
    // Found edges keep their S -> E arrow; the last FOUND_LABELLED keep their label and
    // step number on top of the highlight (on a mesh of any size: the walk's elements are
    // always labelled).
    painter.arrow(...edgeEnds(model, P, e, zoom), { stroke: found, width: 4.5 });
    if (k < labelledFrom) continue;
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

// What changed from a picture the GPU may show to this model's (gl.followMesh): the last
// edit's faces (those the lesson read again), the vertices it moved, added or removed and
// the edges it rewrote, added or removed, from the mesh as it was before the edit (any step
// of its player: the key's last field) or from another step of this edit's player (its edges
// alone changed what is drawn). The key's fields: source|topology|version|step.
function followOf(model) {
  const record = model.lastOperation;
  const follow = model.derived?.follow;
  const none = { from: () => false, faces: [], vertices: [], edges: [] };
  if (!record?.rows && !follow) return none;
  const versionOf = (key) => key.split('|').at(-2);
  const sameSource = (key) => key.startsWith(`${model.source}|`);
  // From the mesh before the edits and undos: only when the lesson followed them (their
  // faces read again).
  const fromBefore = follow && follow.from !== model.version ? follow.from : null;
  // (From another step of the edit player at the same version only the edit's edges differ.)
  const edges = record?.rows ? recordEdges(record) : new Set();
  if (fromBefore) for (const e of follow.edges) edges.add(e);
  return {
    from: (key) => sameSource(key) && (versionOf(key) === model.version || versionOf(key) === fromBefore),
    faces: fromBefore ? follow.faces : [],
    vertices: fromBefore ? follow.vertices : [],
    edges,
  };
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
  // A local change (an edit, a step of its player) rewrites what it touched in the GPU's buffers.
  if (gl.meshKey !== key && gl.followMesh(key, data, followOf(model))) gpu.uploading = null;
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
  const plan = labelPlan(painter, model, state, touched(model, selection), baseCache.labels);
  const gl = painter instanceof CanvasPainter ? ctx.stage.gl() : null;
  if (gl) {
    painter.clearTransparent();
    drawGpu(gl, baseCache.gpu, model, state, ctx);
    drawArrows(painter, model, state, ctx.colors);
    drawLabels(painter, model, state, ctx.colors, plan);
  } else {
    drawBaseCached(baseCache, painter, model, state, ctx, plan);
  }
  // While a table is filled in, the walk is not drawn: its first edge is the vertex (face)
  // table's entry, an answer. A walk being predicted shows its start only (mesh/exercise.js);
  // a half-edge walk its vertex or face only (the winged walk's first edge is not its start).
  if (!ctx.ui?.exercise || ctx.ui.exercise === 'walk') drawWalk(painter, model, state, ctx.colors, ctx.ui?.exerciseStructure === 'half-edge');
  drawElement(painter, model, selection.hover, ctx.colors, false);
  drawElement(painter, model, selection.pick, ctx.colors, true);
  // The edit player: the row the current assignment writes, on the canvas too.
  if (model.editRow) drawElement(painter, model, model.editRow, ctx.colors, true);
}
