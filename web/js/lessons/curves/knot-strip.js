// @ts-check
// The knot strip of a B-spline (lecture 002: knots, multiplicity, open/clamped vectors):
// every knot t_j as a marker on a line, repeated knots stacked with "×m", the continuity
// C^(p-m) written above each distinct knot, the domain [t_p, t_K] shaded, the u cursor.
// Knots are dragged with the pointer (kept in order: a knot stops at its neighbours), or
// with the keyboard ([ and ] choose a knot, arrows move it). Reusable by other lessons.
//
//   const strip = createKnotStrip(container, { onChange(knots, {final}) });
//   strip.update({ knots, groups, degree, domain, u, editable, colors, present });
// groups: the distinct knots as the core reports them ({ value, multiplicity, firstIndex,
// continuity }, api.knotMultiplicities).
import { createPlotCanvas } from '../../ui/plot-canvas.js';
import { plotLabels, plotFontPx } from '../../app/label-layout.js';
import { formatShort as fmt } from '../../ui/format.js';
import { continuityLabel } from './families.js';

const PAD_X = 28;
// The axis sits a label row above the bottom (the strip is taller in presentation mode,
// curves.css): axisFor(height) px from the top.
const axisFor = (height) => Math.round(height - plotFontPx() * 1.25 - 16);
const STACK_PX = 11;
const HIT_PX = 12;

/**
 * @param {HTMLElement} container
 * @param {{ onChange?: (knots: number[] | null, change: { final: boolean }) => void, label?: string }} [options]
 *   knots: the whole knot vector after a move, null when a drag ends
 */
export function createKnotStrip(container, { onChange, label = 'Knot strip' } = {}) {
  const surface = createPlotCanvas(container, { className: 'knot-strip', label, height: 96, tabIndex: 0, role: 'application' });
  let AXIS_Y = axisFor(96); // set from the strip's height at every draw
  surface.canvas.setAttribute('aria-roledescription', 'knot strip');
  let data = null;
  let selected = null;
  let drag = null;

  const bounds = () => {
    const k = data.knots;
    const lo = k[0];
    const hi = k[k.length - 1];
    const pad = (hi - lo || 1) * 0.04;
    return [lo - pad, hi + pad];
  };
  const xOf = (t) => {
    const [lo, hi] = bounds();
    return PAD_X + ((t - lo) / (hi - lo)) * (surface.size.width - 2 * PAD_X);
  };
  const tOf = (x) => {
    const [lo, hi] = bounds();
    return lo + ((x - PAD_X) / (surface.size.width - 2 * PAD_X)) * (hi - lo);
  };

  // Marker j sits in its stack at height = its rank among equal knots.
  function markerPosition(j) {
    const k = data.knots;
    let rank = 0;
    for (let i = j - 1; i >= 0 && k[i] === k[j]; i -= 1) rank += 1;
    return [xOf(k[j]), AXIS_Y - rank * STACK_PX];
  }

  function draw() {
    if (!data) return;
    const { colors } = data;
    const g = surface.begin(colors.background);
    const w = surface.size.width;
    AXIS_Y = axisFor(surface.size.height);
    /** @type {import('../../ui/plot-canvas.js').PlotLabels} */
    const labels = plotLabels(g, surface.canvas, w, surface.size.height);
    // domain
    g.fillStyle = colors.grid;
    g.fillRect(xOf(data.domain.start), AXIS_Y - 4, xOf(data.domain.end) - xOf(data.domain.start), 8);
    g.strokeStyle = colors.muted;
    g.lineWidth = 1;
    g.beginPath(); g.moveTo(PAD_X / 2, AXIS_Y); g.lineTo(w - PAD_X / 2, AXIS_Y); g.stroke();
    // u cursor
    g.strokeStyle = colors.highlight;
    g.lineWidth = 2;
    g.beginPath(); g.moveTo(xOf(data.u), AXIS_Y - 10); g.lineTo(xOf(data.u), AXIS_Y + 10); g.stroke();
    // knots
    for (const group of data.groups) {
      const x = xOf(group.value);
      for (let j = group.firstIndex; j < group.firstIndex + group.multiplicity; j += 1) {
        const [mx, my] = markerPosition(j);
        g.beginPath();
        g.moveTo(mx, my - 5); g.lineTo(mx + 5, my + 4); g.lineTo(mx - 5, my + 4); g.closePath();
        g.fillStyle = j === selected ? colors.highlight : (data.editable ? colors.accent : colors.muted);
        g.fill();
      }
      const top = AXIS_Y - (group.multiplicity - 1) * STACK_PX - 8;
      const inside = group.value > data.domain.start && group.value < data.domain.end;
      const text = inside ? continuityLabel(group.continuity) : '';
      const label = group.multiplicity > 1 ? `${text} ×${group.multiplicity}`.trim() : text;
      if (label) labels.text(label, x, top, { fill: colors.ink, baseline: 'bottom', priority: 1, fixed: true });
      labels.text(fmt(group.value), x, AXIS_Y + 10, { fill: colors.muted, baseline: 'top', priority: 2, fixed: true });
    }
    if (selected !== null) labels.text(`t${sub(selected)} = ${fmt(data.knots[selected])}`, 4, 2, { fill: colors.highlight, align: 'left', baseline: 'top', priority: 3 });
    labels.draw();
  }
  surface.onRedraw(draw);

  function hitKnot(sx, sy) {
    let best = null;
    let bestD = HIT_PX;
    data.knots.forEach((_, j) => {
      const [mx, my] = markerPosition(j);
      const d = Math.hypot(mx - sx, my - sy);
      // on ties the top of a stack wins: the last equal knot can move right, the first left
      if (d <= bestD) { best = j; bestD = d; }
    });
    return best;
  }

  // Keeps the order: t_{j-1} <= t_j <= t_{j+1}.
  function moved(j, t) {
    const k = data.knots.slice();
    const lo = j > 0 ? k[j - 1] : -Infinity;
    const hi = j < k.length - 1 ? k[j + 1] : Infinity;
    k[j] = Math.round(Math.min(hi, Math.max(lo, t)) * 1e6) / 1e6;
    return k;
  }

  surface.canvas.addEventListener('pointerdown', (e) => {
    if (!data?.editable) return;
    const [sx, sy] = surface.local(e);
    const j = hitKnot(sx, sy);
    if (j === null) return;
    selected = j;
    drag = { j, pointerId: e.pointerId };
    surface.canvas.setPointerCapture(e.pointerId);
    surface.canvas.focus({ preventScroll: true });
    draw();
    e.preventDefault();
  });
  surface.canvas.addEventListener('pointermove', (e) => {
    if (!drag || e.pointerId !== drag.pointerId) return;
    onChange(moved(drag.j, tOf(surface.local(e)[0])), { final: false });
  });
  const end = (e) => {
    if (!drag || e.pointerId !== drag.pointerId) return;
    drag = null;
    onChange(null, { final: true });
  };
  surface.canvas.addEventListener('pointerup', end);
  surface.canvas.addEventListener('pointercancel', end);
  surface.canvas.addEventListener('keydown', (e) => {
    if (!data?.editable) return;
    const n = data.knots.length;
    if (e.key === ']' || e.key === '[') {
      selected = selected === null ? 0 : (selected + (e.key === ']' ? 1 : -1) + n) % n;
      draw();
    } else if ((e.key === 'ArrowLeft' || e.key === 'ArrowRight') && selected !== null) {
      const [lo, hi] = bounds();
      const step = (hi - lo) * (e.shiftKey ? 0.002 : 0.02) * (e.key === 'ArrowLeft' ? -1 : 1);
      onChange(moved(selected, data.knots[selected] + step), { final: true });
    } else {
      return;
    }
    e.preventDefault();
    e.stopPropagation();
  });

  return {
    canvas: surface.canvas,
    update(next) {
      data = next;
      if (selected !== null && selected >= next.knots.length) selected = null;
      surface.canvas.setAttribute('aria-label', `${label}: knots ${next.knots.map(fmt).join(', ')}; degree ${next.degree}`);
      draw();
    },
    // Client position of knot j's marker (for tests).
    knotClient(j) {
      const [x, y] = markerPosition(j);
      const rect = surface.canvas.getBoundingClientRect();
      return { x: rect.left + x, y: rect.top + y };
    },
    get selected() { return selected; },
  };
}

const sub = (j) => String(j).split('').map((d) => '₀₁₂₃₄₅₆₇₈₉'[Number(d)]).join('');
