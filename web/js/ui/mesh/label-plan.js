// @ts-check
// Which labels of a mesh are drawn, and drawing them: the label plan. A small mesh is
// labelled whole, as the slides are; a bigger one labels the elements the walk, an edit or
// the pointer touches, and then as many others as fit on screen without overlapping.
// Offers: LABEL_LIMIT, labelPlan(painter, model, state, forced, cache) -> {vertices, faces,
//   edges, forced, away}, createLabelCache(), drawLabels(painter, model, state, colors, plan).
// Needs: a painter (app/painter.js: t, scale, circle, text), a model with projected, V, F,
//   faceOffsets, faceVertices, weShown.edges, mode3d, vertexGap/edgeGap (1 where an edit
//   left a gap, or null), and the theme's colours (accent, ink, background, series).
import { vLabel, eLabel, fLabel } from '../element-labels.js';
import { faceCount, cornersOf, hasCorners, frontFacing, edgeSeen } from './faces.js';

export const LABEL_LIMIT = 400; // more elements than this: labels culled by screen density

function centroid(face, P) {
  let x = 0; let y = 0;
  for (const v of face) { x += P[3 * v]; y += P[3 * v + 1]; }
  return [x / face.length, y / face.length];
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

// What a big mesh offers for labels in one view: whether it is too crowded to label, and
// otherwise every element whose label would sit on screen and on a face turned towards the
// viewer, with that screen point, in the order they are tried (vertices, faces, edges, each
// by number). One pass over the mesh, kept while the scene and the view stay (`cache`): a
// walk step, a hover or a pick changes only the forced labels, so the frame places labels
// among these (about as many as fit on the screen, whatever the mesh's size) and reads no
// other element. `sceneKey` names the mesh state, the projection and the view.
function labelCandidates(model, t, scale) {
  const w = t.width; const h = t.height;
  const boxW = LABEL_BOX.w * scale; const boxH = LABEL_BOX.h * scale;
  const E = model.weShown.edges.length / 8;
  // Screen x = w/2 + (x - cx) zoom, y = h/2 - (y - cy) zoom (painter.js Transform), inline:
  // a call per vertex that returns an array cost 30 ms a frame on a million faces. The
  // crowding is first estimated from every k-th vertex (20,000 of them), so a zoomed-out
  // big mesh costs no per-vertex work at all.
  const ax = w / 2 - t.cx * t.zoom; const ay = h / 2 + t.cy * t.zoom; const z = t.zoom;
  // The sample is turned here from the positions (R (p - c) + c, view.js projectAll), so a
  // turn of a crowded big mesh projects 20,000 vertices, not all of them.
  const stride = Math.max(1, Math.ceil(model.V / 20000));
  const R = model.rotation; const X = model.positions;
  const [cx, cy, cz] = model.mode3d ? model.centre : [0, 0, 0];
  let sampled = 0;
  for (let v = 0; v < model.V; v += stride) {
    const x = X[3 * v] - cx; const y = X[3 * v + 1] - cy; const zz = X[3 * v + 2] - cz;
    const sx = ax + (R[0] * x + R[1] * y + R[2] * zz + cx) * z; const sy = ay - (R[3] * x + R[4] * y + R[5] * zz + cy) * z;
    if (sx >= 0 && sx <= w && sy >= 0 && sy <= h) sampled += 1;
  }
  if (sampled * stride * boxW * boxH > 0.5 * w * h) return { crowded: true };
  const P = model.projected;
  const screen = new Float32Array(2 * model.V);
  for (let v = 0; v < model.V; v += 1) { screen[2 * v] = ax + P[3 * v] * z; screen[2 * v + 1] = ay - P[3 * v + 1] * z; }
  const front = frontMarks(model, P);
  const away = vertexLabelDirections(model, P);
  const onScreen = (x, y) => x >= 0 && x <= w && y >= 0 && y <= h;
  const vertices = []; const faces = []; const edges = [];
  for (let v = 0; v < model.V; v += 1) {
    // A vertex label sits VERTEX_LABEL_PX beside its disc (drawLabels): its box is there.
    const x = screen[2 * v] + VERTEX_LABEL_PX * scale * awayX(away, v); const y = screen[2 * v + 1] - VERTEX_LABEL_PX * scale * awayY(away, v);
    if (onScreen(x, y) && !model.vertexGap?.[v] && (!front || front.vertex[v])) vertices.push(v, x, y);
  }
  const { faceOffsets: o, faceVertices: c } = model;
  for (let f = 0; f < faceCount(model); f += 1) {
    const n = o[f + 1] - o[f];
    if (!n) continue;
    let x = 0; let y = 0;
    for (let i = o[f]; i < o[f + 1]; i += 1) { x += screen[2 * c[i]]; y += screen[2 * c[i] + 1]; }
    x /= n; y /= n;
    if (onScreen(x, y) && (!front || front.face[f])) faces.push(f, x, y);
  }
  const ends = model.weShown.edges;
  for (let e = 0; e < E; e += 1) {
    const a = ends[8 * e]; const b = ends[8 * e + 1];
    if (a < 0 || b < 0) continue;
    const x = (screen[2 * a] + screen[2 * b]) / 2; const y = (screen[2 * a + 1] + screen[2 * b + 1]) / 2;
    if (onScreen(x, y) && !model.edgeGap?.[e] && (!front || edgeSeen(model, front.face, e))) edges.push(e, x, y);
  }
  return { crowded: false, away, vertices, faces, edges };
}

// The key of what labelCandidates read: the mesh as shown, its projection and the view.
function sceneKeyOf(model, t, scale) {
  return [model.source, model.topology, model.version, model.weShown === model.we ? 'all' : model.editStep, model.mode3d,
    model.rotation?.join(','), t.cx, t.cy, t.zoom, t.width, t.height, scale].join('|');
}

/**
 * Which labels a frame draws. `cache` (one per lesson view; createLabelCache) keeps a big
 * mesh's candidates between frames of the same scene and view (labelCandidates).
 * @param {any} painter @param {any} model @param {any} state
 * @param {{ kind: string, index: number }[]} [forced] @param {{ key: string | null, candidates: any }} [cache]
 */
export function labelPlan(painter, model, state, forced = [], cache = createLabelCache()) {
  // A few vertices read (model.points); labelCandidates reads every vertex when the mesh is
  // not crowded on screen.
  const P = model.points;
  const t = painter.t;
  const scale = painter.scale ?? 1;
  const plan = { vertices: [], faces: [], edges: [], forced: new Set(), away: null };
  const E = model.weShown.edges.length / 8;
  // A mesh with at most LABEL_LIMIT elements of every kind (the slides' meshes) is labelled
  // whole; a bigger one by screen density.
  const small = model.V <= LABEL_LIMIT && model.F <= LABEL_LIMIT && E <= LABEL_LIMIT;
  const key = (kind, i) => `${kind}${i}`;
  for (const element of forced) {
    if (!element || element.index < 0) continue;
    const list = element.kind === 'vertex' ? plan.vertices : element.kind === 'face' ? plan.faces : plan.edges;
    if (plan.forced.has(key(element.kind, element.index))) continue;
    plan.forced.add(key(element.kind, element.index));
    list.push(element.index);
  }
  if (small) {
    const front = frontMarks(model, P);
    for (let v = 0; v < model.V; v += 1) if (!model.vertexGap?.[v] && (!front || front.vertex[v]) && !plan.forced.has(key('vertex', v))) plan.vertices.push(v);
    for (let f = 0; f < faceCount(model); f += 1) if (hasCorners(model, f) && (!front || front.face[f]) && !plan.forced.has(key('face', f))) plan.faces.push(f);
    for (let e = 0; e < E; e += 1) if (!model.edgeGap?.[e] && (!front || edgeSeen(model, front.face, e)) && !plan.forced.has(key('edge', e))) plan.edges.push(e);
    return plan;
  }
  const sceneKey = sceneKeyOf(model, t, scale);
  if (cache.key !== sceneKey) {
    cache.key = sceneKey;
    cache.candidates = labelCandidates(model, t, scale);
  }
  const candidates = cache.candidates;
  if (candidates.crowded) return plan;
  plan.away = candidates.away;
  const w = t.width; const h = t.height;
  const boxH = LABEL_BOX.h * scale;
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
  // The touched elements' boxes first (they are drawn whatever the overlap).
  const offset = VERTEX_LABEL_PX * scale;
  for (const v of plan.vertices) {
    const [x, y] = at(P[3 * v], P[3 * v + 1]);
    fits(x + offset * awayX(plan.away, v), y - offset * awayY(plan.away, v), vLabel(v).length, true);
  }
  for (const f of plan.faces) if (hasCorners(model, f)) fits(...at(...centroid(cornersOf(model, f), P)), fLabel(f).length, true);
  for (const e of plan.edges) {
    const a = model.weShown.edges[8 * e]; const b = model.weShown.edges[8 * e + 1];
    if (a >= 0 && b >= 0) fits(...at((P[3 * a] + P[3 * b]) / 2, (P[3 * a + 1] + P[3 * b + 1]) / 2), eLabel(e).length, true);
  }
  // Then the candidates on screen, in order: a pass over them only, never over the mesh.
  const place = (list, kind, out) => {
    for (let k = 0; k < list.length; k += 3) {
      const i = list[k];
      if (!plan.forced.has(key(kind, i)) && fits(list[k + 1], list[k + 2], labelChars(i))) out.push(i);
    }
  };
  place(candidates.vertices, 'vertex', plan.vertices);
  place(candidates.faces, 'face', plan.faces);
  place(candidates.edges, 'edge', plan.edges);
  return plan;
}

// One per lesson view: the label candidates of the last scene and view (labelPlan).
export function createLabelCache() {
  return { key: null, candidates: null };
}

export function drawLabels(painter, model, state, colors, plan) {
  const P = model.points;
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
