// @ts-check
// Continuity lab (lectures 000, 001, 002, 004): a piecewise curve, its joints classified by
// the core as C^k and G^k with the evidence (derivatives from both sides, their ratio, the
// curvatures), constraint modes while dragging, plots of |P'(u)|, P''(u) and the curvature
// along the whole curve, and a point travelling at parametric speed.
import { object, list, number, oneOf, boolean, text, viewSchema } from '../../app/schema.js';
import { createPlayer } from '../../app/player.js';
import { h, panel, table, setChildren } from '../../app/dom.js';
import { formatNumber } from '../../ui/mathml.js';
import { formatVector as fmtVec } from '../../ui/format.js';
import { drawSeriesPlot } from '../../ui/series-plot.js';
import { drawCurve, drawPolygon, drawSamples, drawVector, drawLegend, arrowScale } from '../../ui/curve-overlays.js';
import { PRESETS, DEFAULT_PRESET } from './presets.js';
import { CONSTRAINTS, dragWithConstraint, enforceAll, appendSegment } from './constraints.js';
import { computeModel, segmentCurves, SAMPLES_PER_SEGMENT } from './model.js';
import { continuityExercise } from './exercise.js';

const FAMILIES = ['bezier', 'hermite', 'bspline', 'catmull-rom'];
const FAMILY_NAMES = { bezier: 'Bezier', hermite: 'Hermite', bspline: 'Uniform B-spline', 'catmull-rom': 'Catmull-Rom' };
const PLAY_STEPS_PER_SEGMENT = 40;
// Tangent arrows and Hermite tangent handles are drawn at 1/3 of P'(u): the length of the
// equivalent Bezier leg (lecture 002: p'(0) = 3 (p1 - p0)). Second derivatives at 1/6.
const FIRST_SCALE = 1 / 3;
const SECOND_SCALE = 1 / 6;
const BEAD_EVERY = 4;
const MAX_SEGMENTS = 8; // a bead every 4 samples = every 1/20 of a segment's parameter

const pair = list(number(), { min: 2, max: 2 });
const isPiecewise = (family) => family === 'bezier' || family === 'hermite';
const segmentsOf = (state) => (isPiecewise(state.family) ? state.points.length / 4 : state.points.length - 3);

function presetState(name, view) {
  const p = PRESETS[name];
  return {
    family: p.family, constraint: p.constraint, preset: name,
    points: p.points.map((q) => q.slice()), u: 0,
    show: { first: true, second: true, beads: true },
    view: view ?? { cx: 0, cy: 0, zoom: 90 },
  };
}

export const label = (kind, k) => (k < 0 ? `${kind}-1` : `${kind}${k}`);

function pointName(state, i) {
  if (!isPiecewise(state.family)) return `P${i}`;
  const s = Math.floor(i / 4) + 1;
  const k = i % 4;
  if (state.family === 'bezier') return `Q${s}: P${k}`;
  return `Q${s}: ${['p0', 'p1', 'tangent t0', 'tangent t1'][k]}`;
}

function handlePosition(state, i) {
  const p = state.points[i];
  if (state.family === 'hermite' && i % 4 >= 2) {
    const base = state.points[i - 2];
    return [base[0] + p[0] * FIRST_SCALE, base[1] + p[1] * FIRST_SCALE];
  }
  return p;
}


// Every control entry is a handle (Hermite tangents drawn at P + T/3).
function handlesOf(state) {
  return state.points.map((_, i) => {
    const [x, y] = handlePosition(state, i);
    return { id: `p${i}`, x, y, label: pointName(state, i) };
  });
}

/** @type {import('../../app/contract.js').Lesson} */
export const lesson = {
  id: 'continuity',
  title: 'Continuity lab',
  // The core modules the page loads (docs/architecture.md, "Module size").
  core: ['curves'],
  stateVersion: 1,
  exercise: continuityExercise,
  schema: {
    family: oneOf(...FAMILIES),
    constraint: oneOf(...CONSTRAINTS),
    preset: text({ maxLength: 40 }),
    points: list(pair, { min: 5, max: 64 }),
    u: number({ min: 0, max: 64 }),
    show: object({ first: boolean(), second: boolean(), beads: boolean() }),
    view: viewSchema(),
  },
  checkState(state) {
    if (isPiecewise(state.family) && (state.points.length % 4 !== 0 || state.points.length < 8)) {
      return `a ${FAMILY_NAMES[state.family]} curve here has 4 entries per segment and at least 2 segments, not ${state.points.length} entries`;
    }
    if (state.u > segmentsOf(state)) return `u = ${state.u} lies beyond the last segment (u runs from 0 to ${segmentsOf(state)})`;
    return null;
  },
  defaultState: () => presetState(DEFAULT_PRESET),

  compute(view, state, ctx) {
    return { ...computeModel(ctx.api, state), state };
  },

  fitView(view, model, stage) {
    const xs = [];
    const ys = [];
    for (const s of model.segments) for (let j = 0; j < s.points.length; j += 2) { xs.push(s.points[j]); ys.push(s.points[j + 1]); }
    for (const hd of handlesOf(model.state)) { xs.push(hd.x); ys.push(hd.y); }
    const [minY, maxY] = [Math.min(...ys), Math.max(...ys)];
    // The legend is under the canvas (app/canvas-legend.js): no room to keep for it here.
    return stage.fit(Math.min(...xs), minY, Math.max(...xs), maxY);
  },

  setup(ctx) {
    const player = createPlayer({
      count: () => segmentsOf(ctx.state) * PLAY_STEPS_PER_SEGMENT + 1,
      getStep: () => Math.round(ctx.state.u * PLAY_STEPS_PER_SEGMENT),
      onStep: (k) => ctx.commit({ ...ctx.state, u: k / PLAY_STEPS_PER_SEGMENT }, { history: false }),
      stepsPerSecond: 20,
    });

    const familySelect = h('select', { id: 'family', onchange: () => switchFamily(familySelect.value) },
      FAMILIES.map((f) => h('option', { value: f }, FAMILY_NAMES[f])));
    const constraintSelect = h('select', { id: 'constraint', onchange: () => switchConstraint(constraintSelect.value) },
      CONSTRAINTS.map((c) => h('option', { value: c }, c === 'free' ? 'free (ends may part: C-1)' : `keep ${c}`)));
    // "your own points": what the menu shows while the points are no preset (an exercise's,
    // a file's, a link's); never a choice (disabled), and not listed while a preset is shown.
    const ownPoints = h('option', { value: '', disabled: true, hidden: true }, 'your own points');
    const presetSelect = h('select', { id: 'preset', onchange: () => loadPreset(presetSelect.value) },
      ownPoints, Object.entries(PRESETS).map(([key, p]) => h('option', { value: key }, p.label)));
    const uSlider = h('input', { type: 'range', id: 'u', min: 0, max: 2, step: 1 / PLAY_STEPS_PER_SEGMENT,
      oninput: () => ctx.commit({ ...ctx.state, u: Number(uSlider.value) }, { history: false }) });
    const uOut = h('output', { for: 'u', id: 'u-value' });
    const playButton = h('button', { type: 'button', class: 'tool', id: 'play', onclick: () => player.toggle() }, 'Play');
    player.onChange(() => { playButton.textContent = player.playing ? 'Pause' : 'Play'; playButton.setAttribute('aria-pressed', String(player.playing)); });
    const toggles = [['first', 'P\' arrows'], ['second', 'P\'\' arrows'], ['beads', 'equal-u beads']].map(([key, text]) => {
      const box = h('input', { type: 'checkbox', id: `show-${key}`, onchange: () => ctx.commit({ ...ctx.state, show: { ...ctx.state.show, [key]: box.checked } }, { recompute: false }) });
      return { key, box, label: h('label', { for: `show-${key}` }, box, text) };
    });

    const addButton = h('button', { type: 'button', class: 'tool', id: 'add-segment', onclick: () => addSegment() }, 'Add segment');
    const removeButton = h('button', { type: 'button', class: 'tool', id: 'remove-segment', onclick: () => removeSegment() }, 'Remove last segment');
    ctx.controls.replaceChildren(
      h('label', { for: 'preset' }, 'Preset ', presetSelect),
      h('label', { for: 'family' }, 'Family ', familySelect),
      h('label', { for: 'constraint' }, 'While dragging ', constraintSelect),
      h('label', { for: 'u' }, 'u ', uSlider, uOut), playButton,
      ...toggles.map((t) => t.label), addButton, removeButton,
    );

    const jointsBody = panel(ctx.panels, { id: 'joints-panel', title: 'Joints: the core\'s verdict and its evidence' });
    const plotsBody = panel(ctx.panels, { id: 'plots-panel', title: 'Along the whole curve' });
    const ruleBody = panel(ctx.panels, { id: 'rule-panel', title: 'C1 implies G1, but not conversely' });
    const plotCanvas = (id, name) => h('canvas', { class: 'continuity-plot', id, role: 'img', 'aria-label': name });
    const curvatureUndefined = h('p', { class: 'hint', id: 'curvature-undefined', 'aria-live': 'polite' });
    const plots = {
      speed: plotCanvas('plot-speed', 'Speed |P\'(u)| along the curve, joints marked'),
      second: plotCanvas('plot-second', 'Components of P\'\'(u) along the curve, joints marked'),
      curvature: plotCanvas('plot-curvature', 'Curvature along the curve, joints marked'),
    };
    plotsBody.append(
      h('h3', {}, 'Speed |P\'(u)|'), plots.speed,
      h('h3', {}, 'Second derivative P\'\'(u): x and y'), plots.second,
      h('h3', {}, 'Curvature κ(u)'), plots.curvature, curvatureUndefined,
      h('p', { class: 'hint' }, 'u runs over segment i on [i, i+1]; dashed lines mark the joints. A jump in |P\'| is a G1-but-not-C1 joint; a jump in κ is a joint that is not G2.'),
    );
    const ui = { curvatureUndefined, familySelect, constraintSelect, presetSelect, ownPoints, uSlider, uOut, toggles, jointsBody, ruleBody, plots, addButton, removeButton };

    function loadPreset(name) {
      if (!Object.prototype.hasOwnProperty.call(PRESETS, name)) { ctx.refresh(); return; } // not a preset: the menu shows the state again
      player.pause();
      const next = presetState(name, ctx.state.view);
      if (ctx.commit(next)) ctx.fitView();
    }
    function switchFamily(family) {
      player.pause();
      const state = ctx.state;
      let points;
      if (family === state.family) return;
      if (isPiecewise(family)) {
        // The same curve in the new basis, segment by segment: q = M^-1 M_B P (lecture 002).
        points = [];
        for (const c of segmentCurves(state.family, state.points)) {
          const g = state.family === 'hermite' ? [...c.points, ...c.tangents] : c.points;
          const q = ctx.api.convertBasis(g, 2, state.family, family);
          for (let i = 0; i < 4; i += 1) points.push([q[2 * i], q[2 * i + 1]]);
        }
        ctx.message.info(`The same curve written as ${FAMILY_NAMES[family]} segments (q = M⁻¹ M P, lecture 002).`);
      } else {
        // Shared control points cannot hold separate segments: start from that family's preset.
        const name = family === 'bspline' ? 'bspline' : 'catmull-rom';
        points = PRESETS[name].points.map((p) => p.slice());
      }
      ctx.commit({ ...state, family, points, constraint: isPiecewise(family) ? state.constraint : 'free', u: Math.min(state.u, 1) });
    }
    function addSegment() {
      const state = ctx.state;
      if (segmentsOf(state) >= MAX_SEGMENTS) return;
      if (ctx.commit({ ...state, points: appendSegment(ctx.api, state.points, state.family, state.constraint) })) ctx.fitView();
    }
    function removeSegment() {
      const state = ctx.state;
      if (segmentsOf(state) <= 2) return;
      const points = state.points.slice(0, isPiecewise(state.family) ? -4 : -1);
      const segments = isPiecewise(state.family) ? points.length / 4 : points.length - 3;
      ctx.commit({ ...state, points, u: Math.min(state.u, segments) });
    }
    function switchConstraint(mode) {
      const state = ctx.state;
      const points = isPiecewise(state.family) ? enforceAll(ctx.api, state.points, state.family, mode) : state.points;
      ctx.commit({ ...state, constraint: mode, points });
    }

    const notCanvas = (e) => e.target !== ctx.stage.canvas;
    ctx.keymap.add({ keys: [' '], label: 'play / pause the travelling point (not on the focused canvas)', group: 'Lesson', action: () => player.toggle(), when: notCanvas });
    ctx.keymap.add({ keys: ['n', 'PageDown'], label: 'travelling point one step forward', group: 'Lesson', action: () => player.next() });
    ctx.keymap.add({ keys: ['b', 'PageUp'], label: 'travelling point one step back', group: 'Lesson', action: () => player.prev() });
    ctx.keymap.add({ keys: ['Home'], label: 'travelling point to u = 0', group: 'Lesson', action: () => player.restart(), when: notCanvas });
    ctx.keymap.add({ keys: ['m'], label: 'next constraint mode', group: 'Lesson', action: () => {
      if (!isPiecewise(ctx.state.family)) return;
      switchConstraint(CONSTRAINTS[(CONSTRAINTS.indexOf(ctx.state.constraint) + 1) % CONSTRAINTS.length]);
    } });
    // The view: the panels' elements, the travelling point's player, and the core (the
    // constraint modes move points through it while a handle is dragged).
    // While a "classify this joint" exercise is answered, the verdicts are not shown.
    return { ui, player, api: ctx.api, verdictsHidden: () => ctx.ui.exercise === 'joint' };
  },

  update(view, model, state, ctx) {
    const ui = view.ui;
    ui.familySelect.value = state.family;
    ui.constraintSelect.value = state.constraint;
    ui.constraintSelect.disabled = !isPiecewise(state.family);
    ui.constraintSelect.title = isPiecewise(state.family) ? '' : `${FAMILY_NAMES[state.family]} joints are continuous by construction`;
    const isPreset = Object.prototype.hasOwnProperty.call(PRESETS, state.preset);
    ui.ownPoints.hidden = isPreset;
    ui.presetSelect.value = isPreset ? state.preset : '';
    ui.uSlider.max = String(model.segmentCount);
    ui.uSlider.value = String(state.u);
    ui.uOut.textContent = formatNumber(state.u, 3);
    for (const t of ui.toggles) t.box.checked = state.show[t.key];
    ui.addButton.disabled = model.segmentCount >= MAX_SEGMENTS;
    ui.removeButton.disabled = model.segmentCount <= 2;

    ui.jointsBody.replaceChildren(...model.joints.map((joint) => {
      const verdict = `${label('C', joint.parametric)} · ${label('G', joint.geometric)}`;
      const l = joint.left;
      const r = joint.right;
      const speedL = l.speed;
      const speedR = r.speed;
      return h('section', { class: 'joint-card', 'data-joint': joint.index, 'data-parametric': joint.parametric, 'data-geometric': joint.geometric },
        h('h3', {}, `Joint J${joint.index} (u = ${joint.u}): `, h('span', { class: 'verdict', 'data-verdict': verdict }, verdict)),
        table({
          head: [['', `left, u → ${joint.u}⁻`, `right, u → ${joint.u}⁺`]],
          rows: [
            ['P(u)', fmtVec(l.point), fmtVec(r.point)],
            ['P\'(u)', fmtVec(l.d1), fmtVec(r.d1)],
            ['|P\'(u)|', formatNumber(speedL, 4), formatNumber(speedR, 4)],
            ['P\'\'(u)', fmtVec(l.d2), fmtVec(r.d2)],
            ['curvature κ', curvatureCell(l, joint.u, '⁻'), curvatureCell(r, joint.u, '⁺')],
          ],
        }),
        h('p', { class: 'ratio' }, joint.parametric < 0
          ? explainJoint(joint)
          : joint.zeroTangent
          ? `A first derivative is the zero vector: ${explainJoint(joint)}`
          : `|P'⁺| / |P'⁻| = ${formatNumber(joint.ratio, 4)}, angle ${formatNumber((joint.tangentAngle * 180) / Math.PI, 3)}°: ${explainJoint(joint)}`),
        // At a gap the core's note says what the line above says.
        joint.notes.length && joint.parametric >= 0 ? h('ul', { class: 'notes' }, joint.notes.map((n) => h('li', {}, n))) : null,
        wordingsTable(joint),
      );
    }));

    const note = PRESETS[state.preset]?.note ?? '';
    setChildren(ui.ruleBody,
      h('p', {}, 'C1 (equal first derivatives) implies G1 (same tangent direction): equal non-zero vectors point the same way. The converse fails: G1 only needs P\'⁺ = α P\'⁻ with α > 0, and α ≠ 1 is G1 without C1. The exception (lecture 004): when both tangents are zero, C1 holds and G1 can fail.'),
      h('p', {}, 'Now: ', model.joints.map((j) => `J${j.index} ${label('C', j.parametric)}, ${label('G', j.geometric)}`).join('; '), '.'),
      note ? h('p', { class: 'hint' }, note) : null,
    );
  },

  draw(view, painter, model, state, ctx) {
    if (!model) return;
    const c = ctx.colors;
    const segColors = [c.series[0], c.series[2]];
    // control polygons / tangent arrows (the curve explorer's overlay pieces)
    const polygonStyle = { stroke: c.muted, width: 1, dash: [5, 4] };
    if (state.family === 'bezier') {
      for (let i = 0; i + 3 < state.points.length; i += 4) drawPolygon(painter, state.points.slice(i, i + 4), polygonStyle);
    } else if (state.family === 'hermite') {
      for (let i = 0; i < state.points.length; i += 1) {
        if (i % 4 >= 2) drawVector(painter, state.points[i - 2], state.points[i], FIRST_SCALE, { stroke: c.muted, width: 1.2 });
      }
    } else {
      drawPolygon(painter, state.points, polygonStyle);
    }
    // the segments, alternating colours, each labelled
    model.segments.forEach((s, i) => {
      drawCurve(painter, s.points, { stroke: segColors[i % 2] });
      const mid = Math.floor(SAMPLES_PER_SEGMENT / 2);
      painter.text(s.points[2 * mid], s.points[2 * mid + 1], `Q${i + 1}`, { fill: segColors[i % 2], font: 13, dy: -14, halo: c.background });
      if (state.show.beads) drawSamples(painter, s.points, BEAD_EVERY, { fill: c.ink });
    });
    // joints and their evidence; the right-hand label only where it does not sit on the left one
    const apart = (a, b, scale) => Math.hypot(a[0] - b[0], a[1] - b[1]) * scale * painter.t.zoom > 40;
    for (const joint of model.joints) {
      const at = joint.right.point;
      // Each side's arrows start at its own end (they differ at a C-1 gap, drawn dashed).
      const atL = joint.left.point;
      const halo = c.background;
      if (joint.parametric < 0) {
        painter.line(atL[0], atL[1], at[0], at[1], { stroke: c.ink, width: 2, dash: [4, 4] });
        painter.circle(atL[0], atL[1], 5, { fill: c.background, stroke: c.ink, width: 2 });
      }
      if (state.show.second) {
        drawVector(painter, atL, joint.left.d2, SECOND_SCALE, { stroke: c.series[3], width: 3, alpha: 0.8, halo }, 'P\'\'⁻/6');
        drawVector(painter, at, joint.right.d2, SECOND_SCALE, { stroke: c.series[6], width: 1.5, dash: [5, 3], halo },
          apart(joint.left.d2, joint.right.d2, SECOND_SCALE) ? 'P\'\'⁺/6' : null);
      }
      if (state.show.first) {
        drawVector(painter, atL, joint.left.d1, FIRST_SCALE, { stroke: c.series[1], width: 4, alpha: 0.85, halo }, 'P\'⁻/3');
        drawVector(painter, at, joint.right.d1, FIRST_SCALE, { stroke: c.series[5], width: 1.8, dash: [6, 3], halo },
          apart(joint.left.d1, joint.right.d1, FIRST_SCALE) ? 'P\'⁺/3' : null);
      }
      painter.circle(at[0], at[1], 5, { fill: c.background, stroke: c.ink, width: 2 });
      painter.text(at[0], at[1], view.verdictsHidden() ? `J${joint.index}` : `J${joint.index}: ${label('C', joint.parametric)} ${label('G', joint.geometric)}`, { fill: c.ink, font: 15, weight: 700, dy: 24, halo });
    }
    // handles
    const selected = ctx.ui.selected;
    for (const hd of handlesOf(state)) {
      const on = hd.id === selected;
      painter.circle(hd.x, hd.y, on ? 8 : 6, { fill: on ? c.highlight : c.background, stroke: c.ink, width: 1.5 });
    }
    // the travelling point and its velocity
    const t = model.traveller;
    drawVector(painter, t.point, t.velocity, FIRST_SCALE, { stroke: c.series[4], width: 3, halo: c.background }, 'velocity P\'/3');
    painter.circle(t.point[0], t.point[1], 7, { fill: c.series[4], stroke: c.ink, width: 1.5 });
    // The legend (HTML under the canvas): what each arrow is and the scale it is drawn at.
    const legend = [];
    const third = arrowScale(FIRST_SCALE); const sixth = arrowScale(SECOND_SCALE);
    if (state.family === 'hermite') legend.push([c.muted, `Hermite tangents R, drawn at ${third} of R`, []]);
    if (state.show.first) legend.push([c.series[1], 'P\'⁻/3 left', []], [c.series[5], 'P\'⁺/3 right', [6, 3]]);
    if (state.show.second) legend.push([c.series[3], 'P\'\'⁻/6 left', []], [c.series[6], 'P\'\'⁺/6 right', [5, 3]]);
    legend.push([c.series[4], 'velocity P\'/3 at the travelling point', []]);
    legend.push([null, `arrows drawn at ${third} of P'(u)${state.show.second ? ` and ${sixth} of P''(u)` : ''}`]);
    drawLegend(painter, legend);
  },

  // The plots of |P'|, P'' and the curvature follow every frame (the cursor at u).
  afterFrame(view, model, state, ctx) { drawPlots(view.ui, model, state, ctx); },

  handles(view, model, state) { return handlesOf(state); },

  moveHandle(view, state, id, x, y) {
    const i = Number(id.slice(1));
    if (!Number.isInteger(i) || i < 0 || i >= state.points.length) return null;
    let to = [x, y];
    if (state.family === 'hermite' && i % 4 >= 2) {
      const base = state.points[i - 2];
      to = [(x - base[0]) / FIRST_SCALE, (y - base[1]) / FIRST_SCALE];
    }
    if (!isPiecewise(state.family)) {
      const points = state.points.map((p) => p.slice());
      points[i] = to;
      return { ...state, points };
    }
    return { ...state, points: dragWithConstraint(view.api, state.points, state.family, state.constraint, i, to) };
  },

  // One line for the History.
  summarize: (state) => `${state.family}, ${state.points.length} points, ${state.constraint} dragging`,
  describe(view, model, state) {
    if (!model) return '';
    const joints = model.joints.map((j) => `joint ${j.index}: ${view.verdictsHidden() ? '' : `${label('C', j.parametric)} and ${label('G', j.geometric)}, `}speed ${formatNumber(j.left.speed, 3)} before and ${formatNumber(j.right.speed, 3)} after`).join('; ');
    return `${FAMILY_NAMES[state.family]} curve of ${model.segmentCount} segments, dragging keeps ${state.constraint}. ${joints}. Travelling point at u = ${formatNumber(state.u, 3)}, (${formatNumber(model.traveller.point[0], 3)}, ${formatNumber(model.traveller.point[1], 3)}).`;
  },

  exports: [{
    label: 'Samples along the curve (CSV)', filename: 'continuity-samples.csv', type: 'text/csv',
    make(view, model) {
      const lines = ['u,x,y,dx,dy,ddx,ddy,speed,curvature'];
      for (const s of model.segments) {
        for (let j = 0; j < s.u.length; j += 1) {
          lines.push([s.u[j], s.points[2 * j], s.points[2 * j + 1], s.d1[2 * j], s.d1[2 * j + 1], s.d2[2 * j], s.d2[2 * j + 1], s.speed[j], s.curvature[j]].join(','));
        }
      }
      return lines.join('\n') + '\n';
    },
  }],
};

// The curvature of one side at a joint; where P' = 0 it is undefined, and the evidence says why.
function curvatureCell(side, u, sign) {
  if (side.curvature === null) return `undefined (|P'${sign}| = ${formatNumber(side.speed, 3)} at u = ${u}: P' = 0)`;
  return formatNumber(side.curvature, 4);
}

// What each lecture's wording of G^n says for this joint, as the core computed it.
function wordingsTable(joint) {
  if (!joint.wordings?.length) return null;
  return h('details', { class: 'wordings', 'data-joint': joint.index },
    h('summary', {}, 'G2 in the lectures\' words: what each reading says here'),
    table({
      head: [['reading', 'source', 'says', 'why']],
      rows: joint.wordings.map((w) => [`“${w.wording}”`, w.source, label('G', w.geometric), w.reason]),
    }));
}

function explainJoint(joint) {
  // Lecture 004, "Parametric Continuity": C^-1, the joint is discontinuous. The gap is the
  // core's, relative to the size of the two segments (docs/api-curves.md).
  if (joint.parametric < 0) {
    return `C-1: the joint is discontinuous, V1(1) ≠ V2(0) (lecture 004). The gap |V2(0) − V1(1)| = ${formatNumber(joint.positionGap, 4)}: the gap is ${formatNumber(100 * joint.relativeGap, 3)}% of the size of the two segments.`;
  }
  if (joint.parametric >= 1 && joint.geometric < 1) return 'equal (zero) derivatives but no common direction: C1 without G1.';
  if (joint.parametric >= 1) return 'equal first derivatives (C1).';
  if (joint.geometric >= 1) return 'same direction, different length: G1 but not C1; the speed jumps.';
  return 'the directions differ: a corner (C0 only).';
}

function drawPlots(ui, model, state, ctx) {
  const c = ctx.colors;
  const plotColors = { ink: c.ink, muted: c.muted, grid: c.grid, background: c.background };
  const marks = model.joints.map((j) => ({ u: j.u, label: `J${j.index}` }));
  const speedPieces = model.segments.map((s) => ({ u: s.u, v: s.speed }));
  drawSeriesPlot(ui.plots.speed, { series: [{ label: '|P\'|', color: c.series[4], pieces: speedPieces }], marks, cursor: state.u, yLabel: '|P\'(u)|', colors: plotColors, nonNegative: true });
  const comp = (k) => model.segments.map((s) => ({ u: s.u, v: s.u.map((_, j) => s.d2[2 * j + k]) }));
  drawSeriesPlot(ui.plots.second, {
    series: [{ label: 'x\'\'', color: c.series[0], pieces: comp(0) }, { label: 'y\'\'', color: c.series[1], dash: [6, 3], pieces: comp(1) }],
    marks, cursor: state.u, yLabel: 'x\'\' (solid), y\'\' (dashed)', colors: plotColors,
  });
  // A joint is the end of one segment and the start of the next: where both sides have
  // P' = 0 it is one place, named once.
  const undefinedAt = [];
  for (const x of model.segments.flatMap((s) => s.undefinedAt)) {
    const place = `u = ${formatNumber(x.u, 4)} (|P'| = ${formatNumber(x.speed, 3)})`;
    if (!undefinedAt.includes(place)) undefinedAt.push(place);
  }
  ui.curvatureUndefined.textContent = undefinedAt.length
    ? `κ undefined (P' = 0, the plot leaves a gap) at ${undefinedAt.join(', ')}.`
    : '';
  drawSeriesPlot(ui.plots.curvature, {
    series: [{ label: 'κ', color: c.series[2], pieces: model.segments.map((s) => ({ u: s.u, v: s.curvature })) }],
    // the core's kappa = |P' x P''| / |P'|^3 (lecture 004), never negative: the axis starts at 0
    marks, cursor: state.u, yLabel: 'κ(u)', colors: plotColors, nonNegative: true,
  });
}
