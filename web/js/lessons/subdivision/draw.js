// @ts-check
// Drawing the subdivision lesson: the mesh shown (shaded by the core's normals, far faces
// first), the new points of the phases shown, the chosen point's mask as lines to the old
// vertices it averages with their weights, the extraordinary vertices ringed (the side plot
// of the curve is curve-plot.js). Only the view's arithmetic happens here (projection was done in
// compute; the shade of a face is a dot product of the core's normal with the light).
import { CanvasPainter } from '../../app/painter.js';
import { parseColour } from '../../ui/gl-mesh.js';
import { faceXY, facesViewer } from '../../ui/mesh/faces.js';
import { formatWeight } from './format-weight.js';
import { PHASES, label } from './source.js';

const SMALL_FACES = 4000;   // up to this many faces: one polygon each, far to near, with edges
const SHADES = 24;          // a bigger mesh: faces turned away skipped, the rest batched by shade
const BATCH = 256;          // ... at most this many faces per path
const POINT_LIMIT = 20000;  // more new points than this are not drawn one by one
export const NEW_POINT_LABELS = 30; // the newest phase's points named (face or edge) up to this many
const LABEL_VERTICES = 12;  // vertex labels up to this many vertices (the mask's own are always named)
const EXERCISE_LABEL_VERTICES = 60; // ... and in a subdivide exercise, whose answer names old vertices by their labels
const CONTROL_LIMIT = 400; // control vertices drawn (and dragged) up to this many
const PICK_PX = 12;         // a click this close to a new point picks it
// The light, in view coordinates (x right, y up, z towards the viewer), unit length.
const LIGHT = (() => { const l = [-0.35, 0.45, 0.82]; const n = Math.hypot(...l); return l.map((x) => x / n); })();

// Brightness 0..1 of a normal n (world) under the view's rotation R; two-sided, so the
// inside of an open mesh is lit too.
function brightness(R, n, k) {
  const x = R[0] * n[k] + R[1] * n[k + 1] + R[2] * n[k + 2];
  const y = R[3] * n[k] + R[4] * n[k + 1] + R[5] * n[k + 2];
  const z = R[6] * n[k] + R[7] * n[k + 1] + R[8] * n[k + 2];
  return Math.abs(x * LIGHT[0] + y * LIGHT[1] + z * LIGHT[2]);
}

function faceShade(model, f) {
  const { kind, normals } = model.shading;
  if (kind === 'flat') return brightness(model.rotation, normals, 3 * f);
  let sum = 0;
  const a = model.faceOffsets[f]; const b = model.faceOffsets[f + 1];
  for (let k = a; k < b; k += 1) sum += brightness(model.rotation, normals, 3 * model.faceVertices[k]);
  return sum / (b - a);
}

const shadeColour = (s) => `hsl(205 50% ${Math.round(16 + 62 * s)}%)`;

// The same ramp for the GPU: hsl(205, 50%, L) as rgb 0..1 (hue 205 lies in the 180..240
// sector: r = m, g = m + X, b = m + C, with C = (1 - |2L - 1|) S, X = C (1 - |205/60 mod 2 - 1|),
// m = L - C / 2), at L = 16%, 50% and 78%, between which rgb is linear in L.
function rampColour(L) {
  const C = (1 - Math.abs(2 * L - 1)) * 0.5;
  const X = C * (1 - Math.abs(((205 / 60) % 2) - 1));
  const m = L - C / 2;
  return [m, m + X, m + C];
}
const RAMP = [rampColour(0.16), rampColour(0.5), rampColour(0.78)];

// What the GPU draws of the mesh shown. Smooth: the core's vertex normals, interpolated per
// pixel. Flat: each face its own corners carrying the core's normal of the face (as the 2D
// painter shades it: a non-planar quad is one shade, not two), the edges drawn between the
// first copies of their ends.
function gpuMesh(model) {
  const base = { edges: model.we.edges, edgeStride: 8, edgeGap: null, centre: model.centre };
  if (model.shading.kind === 'smooth') {
    return { ...base, positions: model.positions, faceOffsets: model.faceOffsets, faceVertices: model.faceVertices, normals: model.shading.normals };
  }
  const { faceOffsets: o, faceVertices: c, positions: p } = model;
  const n = model.shading.normals;
  const corners = o[o.length - 1];
  const positions = new Float64Array(3 * corners);
  const normals = new Float64Array(3 * corners);
  const first = new Int32Array(p.length / 3).fill(-1); // a vertex's first corner
  for (let f = 0; f + 1 < o.length; f += 1) {
    for (let i = o[f]; i < o[f + 1]; i += 1) {
      const v = c[i];
      if (first[v] < 0) first[v] = i;
      for (let k = 0; k < 3; k += 1) { positions[3 * i + k] = p[3 * v + k]; normals[3 * i + k] = n[3 * f + k]; }
    }
  }
  const edges = Int32Array.from(model.we.edges);
  for (let e = 0; 8 * e < edges.length; e += 1) {
    if (edges[8 * e] >= 0) edges[8 * e] = first[edges[8 * e]];
    if (edges[8 * e + 1] >= 0) edges[8 * e + 1] = first[edges[8 * e + 1]];
  }
  const faceVertices = new Int32Array(corners);
  for (let i = 0; i < corners; i += 1) faceVertices[i] = i;
  return { ...base, edges, positions, faceOffsets: o, faceVertices, normals };
}

// The faces by WebGL2 (ui/gl-mesh.js): the same shading, opaque, nearest surface; the edges
// of the mesh drawn over it as the painter does (fainter on a big mesh).
function drawFacesGpu(gl, model, ctx) {
  const { width, height, dpr } = ctx.stage.size;
  const v = ctx.state.view;
  const F = model.faceOffsets.length - 1;
  if (gl.meshKey !== model.glKey) gl.setMesh(model.glKey, gpuMesh(model));
  const drawn = gl.draw(
    { R: model.rotation, offset: [model.centre[0] - v.cx, model.centre[1] - v.cy], zoom: v.zoom, width, height, dpr },
    {
      background: parseColour(ctx.colors.background), fill: [0, 0, 0], ink: parseColour(ctx.colors.ink), faceAlpha: 1, backAlpha: 1, lit: false,
      shade: { smooth: model.shading.kind === 'smooth', ramp: RAMP },
      edges: true, edgeAlpha: F <= 600 ? 1 : F <= SMALL_FACES ? 0.6 : 0.25, useProxy: false,
    },
  );
  if (drawn === 'more') ctx.render(); // a big level drawn over frames (gl-mesh.js)
}

function drawFaces(painter, model, colors) {
  const P = model.projected;
  const F = model.faceOffsets.length - 1;
  if (F <= SMALL_FACES) {
    const depth = new Float64Array(F);
    for (let f = 0; f < F; f += 1) {
      let z = 0;
      for (let k = model.faceOffsets[f]; k < model.faceOffsets[f + 1]; k += 1) z += P[3 * model.faceVertices[k] + 2];
      depth[f] = z / (model.faceOffsets[f + 1] - model.faceOffsets[f]);
    }
    const order = Array.from({ length: F }, (_, f) => f).sort((a, b) => depth[a] - depth[b]);
    const width = F > 600 ? 0.5 : 1.2;
    for (const f of order) painter.polygon(faceXY(model, P, f), { fill: shadeColour(faceShade(model, f)), stroke: colors.ink, width, alpha: 1 });
    return;
  }
  // One path per BATCH faces of a shade: the rasteriser's cost grows faster than linearly
  // with the subpaths of one path (the mesh lesson measured it), so long paths are cut.
  const buckets = Array.from({ length: SHADES }, () => ({ xy: [], offsets: [0] }));
  const flush = (i) => {
    const b = buckets[i];
    if (b.offsets.length > 1) painter.polygons(b.xy, b.offsets, { fill: shadeColour((i + 0.5) / SHADES), stroke: colors.ink, width: 0.3, alpha: 1 });
    buckets[i] = { xy: [], offsets: [0] };
  };
  for (let f = 0; f < F; f += 1) {
    if (!facesViewer(model, P, f)) continue;
    const i = Math.min(SHADES - 1, Math.floor(faceShade(model, f) * SHADES));
    const bucket = buckets[i];
    for (let k = model.faceOffsets[f]; k < model.faceOffsets[f + 1]; k += 1) bucket.xy.push(P[3 * model.faceVertices[k]], P[3 * model.faceVertices[k] + 1]);
    bucket.offsets.push(bucket.xy.length / 2);
    if (bucket.offsets.length > BATCH) flush(i);
  }
  for (let i = 0; i < SHADES; i += 1) flush(i);
}

function drawOldEdges(painter, model, colors) {
  if (!model.newProjected) return;
  const P = model.oldProjected ?? model.projected;
  const edges = model.we.edges;
  const xy = [];
  for (let e = 0; 8 * e < edges.length; e += 1) xy.push(P[3 * edges[8 * e]], P[3 * edges[8 * e] + 1], P[3 * edges[8 * e + 1]], P[3 * edges[8 * e + 1] + 1]);
  painter.segments(xy, { stroke: colors.ink, width: 1, alpha: 0.45, dash: [3, 3] });
}

function drawVertexLabels(painter, P, colors, most) {
  const V = P.length / 3;
  if (V > most) return;
  for (let v = 0; v < V; v += 1) {
    painter.circle(P[3 * v], P[3 * v + 1], 3.5, { fill: colors.ink });
    painter.text(P[3 * v], P[3 * v + 1], label('vertex', v), { fill: colors.ink, font: 13, weight: 700, dx: 12, dy: -12, halo: colors.background });
  }
}

// The new points of the phases shown. Those of the newest phase carry the name of what they
// are the point of (a face point "F2", an edge point "e5"; vertex points sit by their old
// vertex's label), up to NEW_POINT_LABELS of them, so a student can tell which face or edge
// each one averages.
function drawNewPoints(painter, model, colors, naming) {
  const N = model.newProjected;
  if (!N) return;
  const newest = model.pointPhases[model.pointPhases.length - 1];
  const { vertices: V, edges: E } = model.levelCounts;
  for (const phase of model.pointPhases) {
    if (phase.count > POINT_LIMIT) continue;
    const colour = colors.series[PHASES.indexOf(phase.name) % colors.series.length];
    const named = naming && phase === newest && phase.count <= NEW_POINT_LABELS && phase.name !== 'vertex-points';
    for (let i = phase.first; i < phase.first + phase.count; i += 1) {
      painter.circle(N[3 * i], N[3 * i + 1], 4, { fill: colour, stroke: colors.background, width: 1 });
      if (named) {
        const name = phase.name === 'face-points' ? label('face', i - V - E) : label('edge', i - V);
        painter.text(N[3 * i], N[3 * i + 1], name, { fill: colour, font: 13, weight: 700, dx: 0, dy: -14, halo: colors.background });
      }
    }
  }
}

// The chosen point's mask: a line to each old vertex it averages, the weight beside it.
function drawMask(painter, model, colors) {
  const i = model.focus;
  if (i < 0 || !model.newProjected) return;
  const s = model.steps;
  const N = model.newProjected;
  const old = model.oldProjected ?? model.projected;
  const x = N[3 * i]; const y = N[3 * i + 1];
  const colour = colors.series[2];
  for (let k = s.masks.offsets[i]; k < s.masks.offsets[i + 1]; k += 1) {
    const v = s.masks.vertices[k];
    const vx = old[3 * v]; const vy = old[3 * v + 1];
    painter.line(x, y, vx, vy, { stroke: colour, width: 2, dash: [5, 4] });
    painter.circle(vx, vy, 6, { stroke: colour, width: 2.5 });
    painter.text(vx, vy, label('vertex', v), { fill: colors.ink, font: 13, weight: 700, dx: 12, dy: -12, halo: colors.background });
    painter.text(vx + (x - vx) * 0.3, vy + (y - vy) * 0.3, formatWeight(s.masks.weights[k]), { fill: colour, font: 14, weight: 700, halo: colors.background });
  }
  painter.circle(x, y, 8, { stroke: colour, width: 3 });
  painter.text(x, y, `new ${label('vertex', i)}`, { fill: colour, font: 13, weight: 700, dx: 0, dy: 20, halo: colors.background });
}

function drawExtraordinary(painter, model, colors) {
  const P = model.projected; // where the mesh is drawn (its limit positions when asked)
  const colour = colors.series[3];
  const labelled = model.extraordinary.length <= LABEL_VERTICES;
  for (const { v, n } of model.extraordinary) {
    painter.circle(P[3 * v], P[3 * v + 1], 10, { stroke: colour, width: 2.5 });
    if (labelled) painter.text(P[3 * v], P[3 * v + 1], `n=${n}`, { fill: colour, font: 12, weight: 700, dx: -16, dy: 16, halo: colors.background });
  }
}

// The control mesh (level 0) over finer levels, and its vertices, the handles.
function drawControl(painter, model, ctx) {
  const colors = ctx.colors;
  const { edges } = model.control;
  const P = model.control.projected ?? model.projected;
  const V = P.length / 3;
  if (model.control.projected && edges.length / 8 <= 4 * SMALL_FACES) {
    const xy = [];
    for (let e = 0; 8 * e < edges.length; e += 1) xy.push(P[3 * edges[8 * e]], P[3 * edges[8 * e] + 1], P[3 * edges[8 * e + 1]], P[3 * edges[8 * e + 1] + 1]);
    painter.segments(xy, { stroke: colors.accent, width: 1.2, alpha: 0.8 });
  }
  if (V > CONTROL_LIMIT) return;
  for (let v = 0; v < V; v += 1) {
    const id = `v${v}`;
    const r = ctx.ui.selected === id ? 7 : ctx.ui.hover === id ? 6 : 4;
    painter.circle(P[3 * v], P[3 * v + 1], r, { fill: colors.accent, stroke: colors.background, width: 1.5 });
  }
  const selected = ctx.ui.selected?.startsWith('v') ? Number(ctx.ui.selected.slice(1)) : -1;
  if (selected >= 0 && selected < V) painter.circle(P[3 * selected], P[3 * selected + 1], 11, { stroke: colors.accent, width: 2.5 });
}

export function drawScene(painter, model, state, ctx) {
  if (!model) return;
  const colors = ctx.colors;
  const gl = painter instanceof CanvasPainter ? ctx.stage.gl() : null;
  if (gl) {
    painter.clearTransparent();
    drawFacesGpu(gl, model, ctx);
  } else {
    drawFaces(painter, model, colors);
  }
  // A subdivide exercise asks for the masks: the drawing names the old vertices and draws
  // neither a mask's weights nor the rings of extraordinary vertices (they are interior
  // ones: the ring would tell an interior mask from a boundary one).
  const asking = ctx.ui.exercise === 'subdivide';
  drawOldEdges(painter, model, colors);
  if (!asking) drawExtraordinary(painter, model, colors);
  drawVertexLabels(painter, model.oldProjected ?? model.projected, colors, asking ? EXERCISE_LABEL_VERTICES : LABEL_VERTICES);
  drawControl(painter, model, ctx);
  drawNewPoints(painter, model, colors, !asking);
  if (!asking) drawMask(painter, model, colors);
  drawReconnectionStep(painter, model, colors);
}

// The reconnection's current assignment (reconnection.js) on the next level's mesh: the row
// it wrote (a new face filled, a new edge drawn thick from S to E, a vertex ringed) and the
// element it wrote there (an edge, a face) dashed, each labelled as the tables name it.
function drawReconnectionStep(painter, model, colors) {
  const r = model.reconnection;
  if (!r || r.tooBig !== undefined || r.shown === 0 || r.shown >= r.steps.length) return;
  const s = r.steps[r.shown - 1];
  const P = model.projected;
  const E = model.we.edges;
  const row = colors.series[2];
  const value = colors.series[4];
  const edge = (e, style) => {
    const a = E[8 * e]; const b = E[8 * e + 1];
    if (a < 0 || b < 0) return;
    painter.line(P[3 * a], P[3 * a + 1], P[3 * b], P[3 * b + 1], style);
    painter.text((P[3 * a] + P[3 * b]) / 2, (P[3 * a + 1] + P[3 * b + 1]) / 2, label('edge', e), { fill: style.stroke, font: 13, weight: 700, halo: colors.background, priority: 2 });
  };
  const face = (f, style) => {
    const xy = faceXY(model, P, f);
    painter.polygon(xy, style);
    let x = 0; let y = 0;
    for (let i = 0; i < xy.length; i += 2) { x += xy[i]; y += xy[i + 1]; }
    painter.text(2 * x / xy.length, 2 * y / xy.length, label('face', f), { fill: colors.ink, font: 13, weight: 700, halo: colors.background, priority: 2 });
  };
  if (s.table === 'face') face(s.row, { fill: row, alpha: 0.4 });
  else if (s.table === 'vertex') {
    painter.circle(P[3 * s.row], P[3 * s.row + 1], 9, { stroke: row, width: 3 });
    painter.text(P[3 * s.row], P[3 * s.row + 1], label('vertex', s.row), { fill: colors.ink, font: 13, weight: 700, dx: 12, dy: -12, halo: colors.background, priority: 2 });
  } else edge(s.row, { stroke: row, width: 6, alpha: 0.85 });
  // The value written: a vertex (S, E), a face (L, R) or an edge (a wing, a vertex's or a face's edge).
  if (s.after < 0) return;
  if (['start', 'end'].includes(s.field)) painter.circle(P[3 * s.after], P[3 * s.after + 1], 7, { fill: value, stroke: colors.background, width: 1.5 });
  else if (['left', 'right'].includes(s.field)) face(s.after, { fill: value, alpha: 0.3 });
  else if (!['start', 'end'].includes(s.field)) edge(s.after, { stroke: value, width: 4, alpha: 0.9, dash: [6, 4] });
}

// The new point (of a phase shown) under the canvas point x, y (world), or -1.
export function pointAt(model, x, y, zoom) {
  const N = model.newProjected;
  if (!N) return -1;
  let best = -1;
  let bestD = PICK_PX / zoom;
  for (const phase of model.pointPhases) {
    for (let i = phase.first; i < phase.first + phase.count; i += 1) {
      const d = Math.hypot(N[3 * i] - x, N[3 * i + 1] - y);
      if (d < bestD) { bestD = d; best = i; }
    }
  }
  return best;
}

// An exercise's new point, marked on the old mesh without giving it away: a ring at the
// asked vertex, or at the middle of the asked edge or face as drawn (screen arithmetic:
// the mean of the projected corners), the edge or the face's sides traced, and its label.
// The old mesh is where the level is drawn: nothing is marked once the step is reconnected
// or the limit positions are shown.
export function drawAskedPoint(painter, model, colors, asked) {
  if (model.phase >= PHASES.length || model.limit) return;
  const P = model.oldProjected ?? model.projected;
  const { corners } = asked;
  if (!corners.length || corners.some((v) => 3 * v + 1 >= P.length)) return;
  const colour = colors.series[2];
  let x = 0;
  let y = 0;
  for (const v of corners) { x += P[3 * v]; y += P[3 * v + 1]; }
  x /= corners.length;
  y /= corners.length;
  if (corners.length > 1) {
    const xy = [];
    for (let k = 0; k < corners.length; k += 1) {
      const a = corners[k]; const b = corners[(k + 1) % corners.length];
      if (corners.length === 2 && k === 1) break;
      xy.push(P[3 * a], P[3 * a + 1], P[3 * b], P[3 * b + 1]);
    }
    painter.segments(xy, { stroke: colour, width: 4, alpha: 0.85 });
  }
  painter.circle(x, y, 9, { stroke: colour, width: 3 });
  painter.text(x, y, `${asked.type} point of ${asked.label}?`, { fill: colour, font: 14, weight: 700, dx: 0, dy: 22, halo: colors.background, priority: 2 });
}
