// @ts-check
// Surface patches (lecture 002): bicubic Hermite and Bezier patches p(u,v) = u^T M P M^T v
// sampled by the core, shown in a small 3D view (turntable camera, painter's algorithm over
// shaded quads, iso-curves in u and v), the 4x4 net draggable in the view plane, the
// interpolated corners, the twist vectors, the formula with live numbers, and two patches
// joined with C0 or C1 across their shared boundary. setup returns the view (the controls
// and panel bodies update fills in); the lesson keeps nothing at module level.
import { object, list, number, oneOf, boolean, integer, viewSchema } from '../../app/schema.js';
import { h, panel, table } from '../../app/dom.js';
import { math, matrix, mi, mo, el, rows4, formatNumber, inlineMath } from '../../ui/mathml.js';
import { createCamera, projectAll } from './view3d.js';
import { drawLegend, arrowScale } from '../../ui/curve-overlays.js';
import { defaultBezierNet, handleOf, hermiteEntryFromHandle, entryName, joinPatches, sharedEntriesOfB } from './nets.js';
import { surfacesExercise } from './exercise.js';

const GRID = 17; // samples per direction: u = i / 16
const ISO_EVERY = 2; // an iso-curve every 2 grid steps: u, v = 0, 1/8, ..., 1
const TWIST_SCALE = 1 / 9; // p_uv drawn at 1/9: the Bezier relation p_uv(0,0) = 9 (p00 - p01 - p10 + p11)
const triple = list(number({ min: -100, max: 100 }), { min: 3, max: 3 });
const net16 = list(triple, { min: 16, max: 16 });
const PATCHES = ['a', 'b'];
const PATCH_NAMES = { a: 'A', b: 'B' };

const fmt = (x) => formatNumber(x, 3);
// A bracket that keeps its text size next to tall matrices.
const fixed = (text) => { const o = mo(text); o.setAttribute('stretchy', 'false'); return o; };
const fmt3 = (p) => `(${fmt(p[0])}, ${fmt(p[1])}, ${fmt(p[2])})`;
const flat = (net) => net.flatMap((p) => p);
const at3 = (values, idx) => [values[3 * idx], values[3 * idx + 1], values[3 * idx + 2]];
const gridIndex = (i, j) => GRID * i + j;

function defaultState() {
  const a = defaultBezierNet();
  const b0 = a.map(([x, y, z]) => [x + 3, y, z * 0.6]);
  const { b } = joinPatches('bezier', a, b0, 'C1', 'a');
  return {
    kind: 'bezier', a, b, joined: false, join: 'C1',
    camera: { yaw: -35, pitch: 35, perspective: false },
    show: { net: true, iso: true, shaded: true, twists: true },
    marker: { i: 8, j: 8 },
    view: { cx: 0, cy: 0, zoom: 90 },
  };
}

// Converts a whole net between the Hermite and Bezier bases in the core
// (Q = C P C^T, C = M_to^-1 M_from: lecture 002's q = M^-1 M_B P down the columns, then
// along the rows), back to the state's 16 [x, y, z] entries.
function convertNet(api, net, from, to) {
  const q = api.convertPatchBasis(flat(net), from, to);
  return Array.from({ length: 16 }, (_, e) => at3(q, e));
}

function netHandles(state) {
  const out = [];
  const camera = createCamera(state.camera);
  for (const patch of PATCHES) {
    if (patch === 'b' && !state.joined) continue;
    const hidden = patch === 'b' ? sharedEntriesOfB(state.kind) : [];
    for (let i = 0; i < 4; i += 1) {
      for (let j = 0; j < 4; j += 1) {
        if (hidden.includes(4 * i + j)) continue;
        const p = handleOf(state.kind, state[patch], i, j);
        const [x, y, depth] = camera.project(...p);
        out.push({ id: `${patch}${i}${j}`, patch, i, j, x, y, depth, p, label: `patch ${PATCH_NAMES[patch]} ${entryName(state.kind, i, j)}` });
      }
    }
  }
  return out;
}

function parseId(id) {
  const m = /^([ab])([0-3])([0-3])$/.exec(id ?? '');
  return m ? { patch: m[1], i: Number(m[2]), j: Number(m[3]) } : null;
}

// Replaces entry (i, j) of `patch` and re-joins the patches with that patch as master.
function withEntry(state, patch, i, j, value) {
  const next = { ...state, [patch]: state[patch].map((p) => p.slice()) };
  next[patch][4 * i + j] = value;
  if (next.joined) Object.assign(next, joinPatches(next.kind, next.a, next.b, next.join, patch));
  return next;
}

const DEGREES_PER_PX = 0.5;
// An angle in degrees as -180 <= a < 180.
const wrapDegrees = (a) => ((((a + 180) % 360) + 360) % 360) - 180;

/** @type {import('../../app/contract.js').Lesson} */
/** @type {import('../../app/contract.js').Lesson} */
export const lesson = {
  id: 'surfaces',
  title: 'Surface patches',
  // The core modules the page loads (docs/architecture.md, "Module size").
  core: ['curves'],
  stateVersion: 1,
  exercise: surfacesExercise,
  // The net's entries are 3D: its own inspector takes x, y and z; the shell's 2D
  // inspector would type view-plane coordinates, which are not the entry's.
  inspector: false,
  schema: {
    kind: oneOf('bezier', 'hermite'),
    a: net16,
    b: net16,
    joined: boolean(),
    join: oneOf('C0', 'C1'),
    camera: object({ yaw: number({ min: -360, max: 360 }), pitch: number({ min: -90, max: 90 }), perspective: boolean() }),
    show: object({ net: boolean(), iso: boolean(), shaded: boolean(), twists: boolean() }),
    marker: object({ i: integer({ min: 0, max: GRID - 1 }), j: integer({ min: 0, max: GRID - 1 }) }),
    view: viewSchema(),
  },
  defaultState,

  compute(view, state, ctx) {
    const api = ctx.api;
    const patches = {};
    for (const patch of PATCHES) {
      if (patch === 'b' && !state.joined) continue;
      const s = api.samplePatch({ kind: state.kind, points: flat(state[patch]), nu: GRID, nv: GRID });
      // The core compares each corner with the net entry holding it (tolerance relative to the patch's size).
      const check = api.patchCornerCheck({ kind: state.kind, points: flat(state[patch]) });
      const corners = check.corners.map(({ entry, distance, interpolated }, c) => {
        const [u, v] = [c >> 1, c & 1];
        return { u, v, entry, value: at3(s.positions, gridIndex(u * (GRID - 1), v * (GRID - 1))), control: state[patch][entry], distance, interpolated };
      });
      patches[patch] = { samples: s, corners };
    }
    let boundary = null;
    if (state.joined) {
      // A's u = 1 edge against B's u = 0 edge, C0 / C1 within the core's tolerance.
      boundary = api.patchJoinCheck({ kind: state.kind, a: flat(state.a), b: flat(state.b), samples: GRID });
    }
    return { state, patches, boundary, M: api.basisMatrix(state.kind) };
  },

  fitView(view, model, stage) {
    const camera = createCamera(model.state.camera);
    const xs = [];
    const ys = [];
    for (const p of Object.values(model.patches)) {
      const { xy } = projectAll(camera, p.samples.positions);
      for (let k = 0; k < xy.length; k += 2) { xs.push(xy[k]); ys.push(xy[k + 1]); }
    }
    for (const hd of netHandles(model.state)) { xs.push(hd.x); ys.push(hd.y); }
    return stage.fit(Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys), 0.14);
  },

  setup(ctx) {
    const commitView = (patch) => ctx.commit({ ...ctx.state, ...patch }, { history: false });
    const kindSelect = h('select', { id: 'kind', onchange: () => switchKind(kindSelect.value) },
      h('option', { value: 'bezier' }, 'Bezier patch'), h('option', { value: 'hermite' }, 'Hermite patch'));
    const yaw = h('input', { type: 'range', id: 'yaw', min: -180, max: 180, step: 1, oninput: () => commitView({ camera: { ...ctx.state.camera, yaw: Number(yaw.value) } }) });
    const pitch = h('input', { type: 'range', id: 'pitch', min: -90, max: 90, step: 1, oninput: () => commitView({ camera: { ...ctx.state.camera, pitch: Number(pitch.value) } }) });
    const box = (id, text, get, set) => {
      const input = h('input', { type: 'checkbox', id, onchange: () => set(input.checked) });
      return { input, get, label: h('label', { for: id }, input, text) };
    };
    const boxes = [
      box('perspective', 'perspective', (s) => s.camera.perspective, (on) => commitView({ camera: { ...ctx.state.camera, perspective: on } })),
      box('show-shaded', 'shaded', (s) => s.show.shaded, (on) => commitView({ show: { ...ctx.state.show, shaded: on } })),
      box('show-iso', 'iso-curves', (s) => s.show.iso, (on) => commitView({ show: { ...ctx.state.show, iso: on } })),
      box('show-net', 'control net', (s) => s.show.net, (on) => commitView({ show: { ...ctx.state.show, net: on } })),
      box('show-twists', 'twist vectors', (s) => s.show.twists, (on) => commitView({ show: { ...ctx.state.show, twists: on } })),
      box('joined', 'second patch', (s) => s.joined, (on) => setJoined(on)),
    ];
    const joinSelect = h('select', { id: 'join', onchange: () => setJoin(joinSelect.value) },
      h('option', { value: 'C0' }, 'C0 across the boundary'), h('option', { value: 'C1' }, 'C1 across the boundary'));
    ctx.controls.replaceChildren(
      h('label', { for: 'kind' }, 'Patch ', kindSelect),
      h('label', { for: 'yaw' }, 'turn ', yaw), h('label', { for: 'pitch' }, 'tilt ', pitch),
      ...boxes.map((b) => b.label), h('label', { for: 'join' }, 'join ', joinSelect),
    );

    const inspectorBody = panel(ctx.panels, { id: 'inspector-panel', title: 'Selected entry of the net' });
    const inputs = ['x', 'y', 'z'].map((axis, k) => {
      const input = h('input', { type: 'number', id: `entry-${axis}`, step: 0.1, onchange: () => setEntryComponent(k, Number(input.value)) });
      return { input, label: h('label', { for: `entry-${axis}` }, `${axis} `, input) };
    });
    const inspectorTitle = h('p', { id: 'entry-name' });
    inspectorBody.append(inspectorTitle, h('div', { class: 'xyz-row' }, inputs.map((x) => x.label)),
      h('p', { class: 'hint' }, 'Select with [ and ] on the focused drawing (or click a handle); arrows move it in the view plane; type exact values here, z included. Drag empty space to turn the view (Shift-drag pans).'));
    const formulaBody = panel(ctx.panels, { id: 'formula-panel', title: 'p(u, v) = uᵀ M P Mᵀ v' });
    const markerU = h('input', { type: 'range', id: 'marker-u', min: 0, max: GRID - 1, step: 1, oninput: () => commitView({ marker: { ...ctx.state.marker, i: Number(markerU.value) } }) });
    const markerV = h('input', { type: 'range', id: 'marker-v', min: 0, max: GRID - 1, step: 1, oninput: () => commitView({ marker: { ...ctx.state.marker, j: Number(markerV.value) } }) });
    const formulaOut = h('div', { class: 'formula-out' });
    formulaBody.append(h('div', { class: 'xyz-row' }, h('label', { for: 'marker-u' }, 'u ', markerU), h('label', { for: 'marker-v' }, 'v ', markerV)), formulaOut);
    const cornersBody = panel(ctx.panels, { id: 'corners-panel', title: 'Corners and twist vectors' });
    const boundaryBody = panel(ctx.panels, { id: 'boundary-panel', title: 'Two patches: across the shared boundary' });
    const view = { kindSelect, yaw, pitch, boxes, joinSelect, inputs, inspectorTitle, markerU, markerV, formulaOut, cornersBody, boundaryBody };

    function switchKind(kind) {
      const state = ctx.state;
      if (kind === state.kind) return;
      const next = { ...state, kind, a: convertNet(ctx.api, state.a, state.kind, kind), b: convertNet(ctx.api, state.b, state.kind, kind) };
      if (ctx.commit(next)) ctx.message.info(`The same surface written in the ${kind === 'bezier' ? 'Bezier' : 'Hermite'} basis: Q = (M⁻¹ M') P (M⁻¹ M')ᵀ, computed by the core.`);
    }
    function setJoined(on) {
      const state = ctx.state;
      const next = { ...state, joined: on, ...(on ? joinPatches(state.kind, state.a, state.b, state.join, 'a') : {}) };
      if (ctx.commit(next)) ctx.fitView();
    }
    function setJoin(mode) {
      const state = ctx.state;
      ctx.commit({ ...state, join: mode, ...(state.joined ? joinPatches(state.kind, state.a, state.b, mode, 'a') : {}) });
    }
    function setEntryComponent(k, value) {
      const sel = parseId(ctx.ui.selected);
      if (!sel || !Number.isFinite(value)) return;
      const entry = ctx.state[sel.patch][4 * sel.i + sel.j].slice();
      entry[k] = value;
      ctx.commit(withEntry(ctx.state, sel.patch, sel.i, sel.j, entry));
    }
    const turn = (dyaw, dpitch) => {
      const c = ctx.state.camera;
      commitView({ camera: { ...c, yaw: wrapDegrees(c.yaw + dyaw), pitch: Math.max(-90, Math.min(90, c.pitch + dpitch)) } });
    };
    ctx.keymap.add({ keys: ['a'], label: 'turn the view left', group: 'View', action: () => turn(-10, 0) });
    ctx.keymap.add({ keys: ['d'], label: 'turn the view right', group: 'View', action: () => turn(10, 0) });
    ctx.keymap.add({ keys: ['w'], label: 'tilt: look more from above', group: 'View', action: () => turn(0, 10) });
    ctx.keymap.add({ keys: ['s'], label: 'tilt: look more from the side', group: 'View', action: () => turn(0, -10) });
    ctx.keymap.add({ keys: ['o'], label: 'orthographic / perspective', group: 'View', action: () => commitView({ camera: { ...ctx.state.camera, perspective: !ctx.state.camera.perspective } }) });
    ctx.keymap.add({ keys: ['h'], label: 'Bezier / Hermite basis (same surface)', group: 'Lesson', action: () => switchKind(ctx.state.kind === 'bezier' ? 'hermite' : 'bezier') });
    ctx.keymap.add({ keys: ['j'], label: 'second patch on / off', group: 'Lesson', action: () => setJoined(!ctx.state.joined) });
    return view;
  },

  update(view, model, state, ctx) {
    view.kindSelect.value = state.kind;
    view.yaw.value = String(state.camera.yaw);
    view.pitch.value = String(state.camera.pitch);
    for (const b of view.boxes) b.input.checked = b.get(state);
    view.joinSelect.value = state.join;
    view.joinSelect.disabled = !state.joined;
    view.markerU.value = String(state.marker.i);
    view.markerV.value = String(state.marker.j);

    const sel = parseId(ctx.ui.selected);
    const entry = sel && (sel.patch === 'a' || state.joined) ? state[sel.patch][4 * sel.i + sel.j] : null;
    view.inspectorTitle.textContent = entry
      ? `Patch ${PATCH_NAMES[sel.patch]}, row ${sel.i}, column ${sel.j}: ${entryName(state.kind, sel.i, sel.j)}${state.kind === 'hermite' && (sel.i >= 2 || sel.j >= 2) ? ' (a vector)' : ''}`
      : 'No entry selected.';
    view.inputs.forEach((x, k) => { x.input.disabled = !entry; x.input.value = entry ? String(Number(entry[k].toPrecision(6))) : ''; });

    // The formula with the matrices the core used, and the value at the marker.
    const A = model.patches.a;
    const u = state.marker.i / (GRID - 1);
    const v = state.marker.j / (GRID - 1);
    const value = at3(A.samples.positions, gridIndex(state.marker.i, state.marker.j));
    const Pcells = [0, 1, 2, 3].map((i) => [0, 1, 2, 3].map((j) => state.a[4 * i + j]));
    const Mrows = rows4(model.M);
    const MT = Mrows[0].map((_, c) => Mrows.map((r) => r[c]));
    const powers = (t) => [[t ** 3, t ** 2, t, 1]];
    view.formulaOut.replaceChildren(
      h('div', { class: 'formula' }, math(mi('p'), fixed('('), mi('u'), mo(','), mi('v'), fixed(')'), mo('='),
        el('msup', mi('u'), mi('T')), named(matrix(Mrows), 'M'), mi('P'), matrix(MT), mi('v'))),
      h('div', { class: 'formula-row' }, ['x', 'y', 'z'].map((axis, k) => h('div', { class: 'formula' },
        math(el('msub', mi('P'), mi(axis)), mo('='), matrix(Pcells.map((row) => row.map((p) => p[k]))))))),
      h('div', { class: 'formula' }, math(el('msup', mi('u'), mi('T')), mo('='), matrix(powers(u)), mo(','), el('msup', mi('v'), mi('T')), mo('='), matrix(powers(v)))),
      h('p', { id: 'marker-value', 'data-u': u, 'data-v': v }, `p(${fmt(u)}, ${fmt(v)}) = ${fmt3(value)} (patch A, sampled by the core).`),
      // u^T here is [u^3 u^2 u 1] (descending, lectures 000 and 003), so M is the
      // matrix of those lectures; lecture 002 writes u = (1, u, u^2, u^3) and its M_B, M_H are
      // this M with the rows in the opposite order.
      h('p', { class: 'hint lecture-note', id: 'surface-matrix-name' }, state.kind === 'bezier'
        ? 'Bezier: P holds the 16 control points p_ij (lecture 002). M is M_Bezier of lecture 003, for uᵀ = [u³ u² u 1]; lecture 002 writes u = (1, u, u², u³), and its M_B is this M with the rows in the opposite order.'
        : 'Hermite: P holds corner points, v-tangents, u-tangents and twists (lecture 002\'s Q = [q_ij]). M is M_Hermite of lectures 000 and 003, for uᵀ = [u³ u² u 1]; lecture 002 writes u = (1, u, u², u³), and its M_H = A_H⁻¹ is this M with the rows in the opposite order.'),
    );

    const cornerRows = [];
    for (const [patch, p] of Object.entries(model.patches)) {
      p.corners.forEach((c, idx) => {
        const tw = at3(p.samples.twists, idx);
        cornerRows.push([`${PATCH_NAMES[patch]}: p(${c.u},${c.v})`, fmt3(c.value), `${entryName(state.kind, Math.floor(c.entry / 4), c.entry % 4)} ${fmt3(c.control)}`,
          c.interpolated ? `0 ✓ (${c.distance.toExponential(0)})` : fmt(c.distance), fmt3(tw)]);
      });
    }
    view.cornersBody.replaceChildren(table({
      caption: h('span', {}, 'The patch interpolates its corner points; ', inlineMath(el('msub', mi('p'), mi('uv'))), ' is the twist (flat there when 0)'),
      head: [['corner', 'p(u,v) from the core', 'control entry', 'distance', h('span', {}, 'twist ', inlineMath(el('msub', mi('p'), mi('uv'))))]], rows: cornerRows, className: 'data-table corners-table',
    }));

    if (model.boundary) {
      const b = model.boundary;
      const { c0, c1 } = b;
      view.boundaryBody.replaceChildren(
        h('p', { id: 'boundary-verdict', 'data-c0': String(c0), 'data-c1': String(c1) },
          `Across A's u = 1 edge and B's u = 0 edge: position gap ${b.positionGap.toExponential(1)} (${c0 ? 'C0 ✓' : 'not C0'}), p_u gap ${b.duGap.toExponential(1)} (${c1 ? 'C1 ✓' : 'not C1'}).`),
        h('p', { class: 'hint' }, state.kind === 'bezier'
          ? 'Bezier: C0 shares the boundary row of control points; C1 also makes every column p2j, p3j = q0j, q1j collinear with equal legs (lecture 001, column by column).'
          : 'Hermite: C0 shares the boundary points and v-tangents; C1 also shares the u-tangents and twists.'),
      );
    } else {
      view.boundaryBody.replaceChildren(h('p', { class: 'hint' }, 'Tick "second patch" to join a second patch along the u = 1 edge.'));
    }
  },

  draw(view, painter, model, state, ctx) {
    if (!model) return;
    const c = ctx.colors;
    const camera = createCamera(state.camera);
    const eye = camera.towardsEye;
    const quads = [];
    const fills = { a: c.series[5], b: c.series[4] };
    const projected = {};
    for (const [patch, p] of Object.entries(model.patches)) {
      const s = p.samples;
      const { xy, depth } = projectAll(camera, s.positions);
      projected[patch] = xy;
      for (let i = 0; i + 1 < GRID; i += 1) {
        for (let j = 0; j + 1 < GRID; j += 1) {
          const ids = [gridIndex(i, j), gridIndex(i + 1, j), gridIndex(i + 1, j + 1), gridIndex(i, j + 1)];
          let d = 0;
          const n = [0, 0, 0];
          for (const id of ids) { d += depth[id]; for (let k = 0; k < 3; k += 1) n[k] += s.normals[3 * id + k]; }
          const len = Math.hypot(...n) || 1;
          const light = Math.abs((n[0] * eye[0] + n[1] * eye[1] + n[2] * eye[2]) / len);
          quads.push({ patch, i, j, ids, depth: d / 4, light });
        }
      }
    }
    // Painter's algorithm: far quads first; each quad brings its own iso-curve edges so
    // nearer quads hide them too.
    quads.sort((q1, q2) => q2.depth - q1.depth);
    for (const q of quads) {
      const xy = projected[q.patch];
      const poly = q.ids.flatMap((id) => [xy[2 * id], xy[2 * id + 1]]);
      if (state.show.shaded) {
        painter.polygon(poly, { fill: fills[q.patch] });
        painter.polygon(poly, { fill: '#000', alpha: 0.6 * (1 - q.light) });
      }
      if (state.show.iso) {
        const edge = (id1, id2, color) => painter.line(xy[2 * id1], xy[2 * id1 + 1], xy[2 * id2], xy[2 * id2 + 1], { stroke: color, width: 1.4 });
        const uColor = c.series[0];
        const vColor = c.series[1];
        if (q.i % ISO_EVERY === 0) edge(q.ids[0], q.ids[3], uColor);
        if (q.i + 1 === GRID - 1) edge(q.ids[1], q.ids[2], uColor);
        if (q.j % ISO_EVERY === 0) edge(q.ids[0], q.ids[1], vColor);
        if (q.j + 1 === GRID - 1) edge(q.ids[3], q.ids[2], vColor);
      }
    }
    // Corners, twists, the marker.
    for (const [patch, p] of Object.entries(model.patches)) {
      const xy = projected[patch];
      p.corners.forEach((corner, idx) => {
        const id = gridIndex(corner.u * (GRID - 1), corner.v * (GRID - 1));
        painter.circle(xy[2 * id], xy[2 * id + 1], 9, { stroke: c.series[2], width: 2.5 });
        if (state.show.twists) {
          const tw = at3(p.samples.twists, idx);
          const base = corner.value;
          const [tx, ty] = camera.project(base[0] + tw[0] * TWIST_SCALE, base[1] + tw[1] * TWIST_SCALE, base[2] + tw[2] * TWIST_SCALE);
          painter.arrow(xy[2 * id], xy[2 * id + 1], tx, ty, { stroke: c.series[3], width: 2.5 });
          painter.text(tx, ty, `p_uv/9`, { fill: c.series[3], font: 11, dy: -10, halo: c.background });
        }
        // B's u = 0 corners are A's u = 1 corners: label them once.
        if (patch === 'b' && corner.u === 0) return;
        painter.text(xy[2 * id], xy[2 * id + 1], `${PATCH_NAMES[patch]} p(${corner.u},${corner.v})`, { fill: c.ink, font: 12, dx: 12, dy: 14, align: 'left', halo: c.background });
      });
    }
    const m = gridIndex(state.marker.i, state.marker.j);
    painter.circle(projected.a[2 * m], projected.a[2 * m + 1], 6, { fill: c.series[4], stroke: c.ink, width: 1.5 });
    // The control net on top, with its handles.
    if (state.show.net) {
      const handles = netHandles(state);
      const byId = new Map(handles.map((hd) => [hd.id, hd]));
      for (const patch of Object.keys(model.patches)) {
        const pos = (i, j) => {
          const hd = byId.get(`${patch}${i}${j}`) ?? (patch === 'b' ? byId.get(`a${3}${j}`) : null);
          return hd ? [hd.x, hd.y] : null;
        };
        for (let i = 0; i < 4; i += 1) {
          const row = []; const col = [];
          for (let j = 0; j < 4; j += 1) { row.push(...(pos(i, j) ?? [])); col.push(...(pos(j, i) ?? [])); }
          if (state.kind === 'bezier') {
            painter.polyline(row, { stroke: c.ink, width: 1, dash: [4, 3], alpha: 0.7 });
            painter.polyline(col, { stroke: c.ink, width: 1, dash: [4, 3], alpha: 0.7 });
          }
        }
        if (state.kind === 'hermite') {
          // Each vector handle hangs from its corner.
          for (const hd of handles.filter((x) => x.patch === patch && (x.i >= 2 || x.j >= 2))) {
            const corner = byId.get(`${patch}${hd.i % 2}${hd.j % 2}`) ?? byId.get(`a1${hd.j % 2}`);
            if (corner) painter.line(corner.x, corner.y, hd.x, hd.y, { stroke: c.ink, width: 1, dash: [4, 3], alpha: 0.7 });
          }
        }
      }
      for (const hd of handles) {
        const on = hd.id === ctx.ui.selected;
        painter.circle(hd.x, hd.y, on ? 8 : 5.5, { fill: on ? c.highlight : c.background, stroke: hd.patch === 'a' ? c.ink : c.series[4], width: 1.5 });
      }
    }
    // Axes and legend in the corner of the view.
    const tr = painter.t;
    const [ox, oy] = tr.toWorld(60, tr.height - 60);
    const axisLen = 40 / tr.zoom;
    /** @type {[string, number[]][]} */ ([['x', [1, 0, 0]], ['y', [0, 1, 0]], ['z', [0, 0, 1]]]).forEach(([name, dir], k) => {
      const [ax, ay] = createCamera({ ...state.camera, perspective: false }).project(...dir);
      painter.arrow(ox, oy, ox + ax * axisLen, oy + ay * axisLen, { stroke: c.series[[0, 1, 2][k]], width: 2 });
      painter.text(ox + ax * axisLen * 1.3, oy + ay * axisLen * 1.3, name, { fill: c.ink, font: 12, priority: 1 });
    });
    // The legend, under the canvas (app/canvas-legend.js), with the twist arrows' scale.
    drawLegend(painter, [[c.series[0], 'iso-curves u = const', []], [c.series[1], 'iso-curves v = const', []], [c.series[2], 'corners (interpolated), circled', []],
      ...(state.show.twists ? [[c.series[3], `twist vectors p_uv: arrows drawn at ${arrowScale(TWIST_SCALE)} of p_uv (label p_uv/9)`, []]] : []),
      [c.series[4], 'p(u, v) at the marker, a dot', []]]);
  },

  handles(view, model, state) {
    return netHandles(state).map(({ id, x, y, label }) => ({ id, x, y, label }));
  },

  // A drag on empty canvas turns the view (half a degree per pixel: across, turn; down,
  // look more from above); Shift-drag pans, as the stage does by default. The pointer
  // that started the drag steers; a second finger pinches to zoom as usual.
  click(view, x, y, ctx, event) {
    if (!event || event.shiftKey || (event.button ?? 0) !== 0) return false;
    const start = { id: event.pointerId, x: event.clientX, y: event.clientY, ...ctx.state.camera };
    const move = (e) => {
      if (e.pointerId !== start.id) return;
      const yaw = wrapDegrees(Math.round(start.yaw + (e.clientX - start.x) * DEGREES_PER_PX));
      const pitch = Math.max(-90, Math.min(90, Math.round(start.pitch + (e.clientY - start.y) * DEGREES_PER_PX)));
      const c = ctx.state.camera;
      if (yaw !== c.yaw || pitch !== c.pitch) ctx.commit({ ...ctx.state, camera: { ...c, yaw, pitch } }, { history: false });
    };
    const end = (e) => {
      if (e.pointerId !== start.id) return;
      window.removeEventListener('pointermove', move);
      window.removeEventListener('pointerup', end);
      window.removeEventListener('pointercancel', end);
    };
    window.addEventListener('pointermove', move);
    window.addEventListener('pointerup', end);
    window.addEventListener('pointercancel', end);
    return true;
  },

  moveHandle(view, state, id, x, y) {
    const sel = parseId(id);
    if (!sel) return null;
    const camera = createCamera(state.camera);
    const current = handleOf(state.kind, state[sel.patch], sel.i, sel.j);
    const [sx, sy, depth] = camera.project(...current);
    const delta = camera.screenDelta(x - sx, y - sy, depth);
    const target = current.map((v, k) => v + delta[k]);
    const value = state.kind === 'bezier' ? target : hermiteEntryFromHandle(state[sel.patch], sel.i, sel.j, target);
    return withEntry(state, sel.patch, sel.i, sel.j, value);
  },

  // One line for the History.
  summarize: (state) => `${state.kind} patch${state.joined ? `es joined ${state.join}` : ''}`,
  describe(view, model, state) {
    if (!model) return '';
    const a = model.patches.a;
    const corners = a.corners.map((c) => `p(${c.u},${c.v}) = ${fmt3(c.value)}`).join(', ');
    const joined = model.boundary ? ` A second patch is joined along u = 1; position gap ${model.boundary.positionGap.toExponential(1)}, p_u gap ${model.boundary.duGap.toExponential(1)}.` : '';
    return `Bicubic ${state.kind === 'bezier' ? 'Bezier' : 'Hermite'} patch seen from turn ${state.camera.yaw}°, tilt ${state.camera.pitch}°. Corners: ${corners}.${joined}`;
  },

  exports: [{
    label: 'Patch A samples (CSV)', filename: 'patch-samples.csv', type: 'text/csv',
    make(view, model) {
      const s = model.patches.a.samples;
      const lines = ['u,v,x,y,z,nx,ny,nz'];
      for (let i = 0; i < GRID; i += 1) {
        for (let j = 0; j < GRID; j += 1) {
          const id = gridIndex(i, j);
          lines.push([i / (GRID - 1), j / (GRID - 1), ...at3(s.positions, id), ...at3(s.normals, id)].join(','));
        }
      }
      return lines.join('\n') + '\n';
    },
  }],
};

// A typeset matrix marked for the tests and the reader (data-matrix).
function named(node, name) {
  node.setAttribute('data-matrix', name);
  return node;
}
