// @ts-check
// The blending functions (lectures 000, 001: B = M T; lecture 002: Cox-de Boor N_i,p) of
// a curve, plotted over its parameter domain, each in the colour of its control point and
// labelled, with the same u cursor as the curve. Reusable: the continuity, comparison and
// surface lessons give it other curves.
//
//   const plot = createBlendingPlot(container, { onSeek(u, {final}) });
//   plot.update({ params, count, values, u, domain: {start, end}, colors, labels,
//                 colorIndex?, dashed?, knots?, highlight?, present? });
// values[count*j + i] is function i at params[j] (the core's layout).
import { createPlotCanvas, dashFor } from './plot-canvas.js';
import { formatShort as fmt } from './format.js';
import { plotLabels, plotFontPx } from '../app/label-layout.js';

// Padding around the plot, in CSS px, from the label size (app/label-layout.js): room for the
// 0/1 ticks at the left, the domain ends under it, the u label above it.
const padFor = (px) => ({ left: Math.round(px * 1.6 + 10), right: 12, top: Math.round(px * 1.25 + 6), bottom: Math.round(px * 1.25 + 8) });

export function createBlendingPlot(container, { label = 'Blending functions', height = 190, onSeek = null } = {}) {
  const figure = document.createElement('figure');
  figure.className = 'blending-plot';
  const caption = document.createElement('figcaption');
  caption.textContent = label;
  container.append(figure);
  const surface = createPlotCanvas(figure, { className: 'blending-canvas', label, height });
  let PAD = padFor(plotFontPx()); // set again at every draw (presentation mode changes it)
  figure.append(caption);
  let data = null;

  const xOf = (u) => {
    const { width } = surface.size;
    const { start, end } = data.domain;
    return PAD.left + ((u - start) / (end - start || 1)) * (width - PAD.left - PAD.right);
  };
  const uOf = (x) => {
    const { width } = surface.size;
    const { start, end } = data.domain;
    const t = (x - PAD.left) / (width - PAD.left - PAD.right);
    return Math.min(end, Math.max(start, start + t * (end - start)));
  };

  function range() {
    let lo = 0;
    let hi = 1;
    for (const v of data.values) { if (v < lo) lo = v; if (v > hi) hi = v; }
    return [lo, hi];
  }

  function draw() {
    if (!data) return;
    const { colors } = data;
    const g = surface.begin(colors.background);
    const { height: hgt } = surface.size;
    const scale = data.present ? 1.5 : 1;
    /** @type {import('./plot-canvas.js').PlotLabels} */
    const labels = plotLabels(g, surface.canvas, surface.size.width, hgt);
    PAD = padFor(plotFontPx());
    const [lo, hi] = range();
    const yOf = (v) => PAD.top + (1 - (v - lo) / (hi - lo || 1)) * (hgt - PAD.top - PAD.bottom);
    // axes: 0 and 1
    g.strokeStyle = colors.grid;
    g.lineWidth = 1;
    g.setLineDash([]);
    for (const v of [0, 1]) {
      g.beginPath(); g.moveTo(PAD.left, yOf(v)); g.lineTo(surface.size.width - PAD.right, yOf(v)); g.stroke();
    }
    labels.text('1', PAD.left - 6, yOf(1), { fill: colors.muted, align: 'right', fixed: true, priority: 3 });
    labels.text('0', PAD.left - 6, yOf(0), { fill: colors.muted, align: 'right', fixed: true, priority: 3 });
    // knots (B-splines) or segment joints, and the domain ends
    for (const k of data.knots ?? []) {
      if (k < data.domain.start - 1e-12 || k > data.domain.end + 1e-12) continue;
      g.strokeStyle = colors.grid;
      g.beginPath(); g.moveTo(xOf(k), PAD.top); g.lineTo(xOf(k), hgt - PAD.bottom); g.stroke();
    }
    labels.text(fmt(data.domain.start), xOf(data.domain.start), hgt - PAD.bottom + 4, { fill: colors.muted, align: 'left', baseline: 'top', priority: 3, fixed: true });
    labels.text(fmt(data.domain.end), xOf(data.domain.end), hgt - PAD.bottom + 4, { fill: colors.muted, align: 'right', baseline: 'top', priority: 3, fixed: true });
    // the functions
    const { params, count, values } = data;
    for (let i = 0; i < count; i += 1) {
      const c = data.colorIndex ? data.colorIndex(i) : i;
      const emphasised = data.highlight === null || data.highlight === undefined || data.highlight === c;
      g.strokeStyle = colors.series[c % colors.series.length];
      g.globalAlpha = emphasised ? 1 : 0.3;
      g.lineWidth = (data.highlight === c ? 3.5 : 2) * scale;
      g.setLineDash(data.dashed?.(i) ? [6, 4] : dashFor(c));
      g.beginPath();
      let peak = 0;
      for (let j = 0; j < params.length; j += 1) {
        const v = values[count * j + i];
        if (Math.abs(v) > Math.abs(values[count * peak + i])) peak = j;
        if (j === 0) g.moveTo(xOf(params[j]), yOf(v)); else g.lineTo(xOf(params[j]), yOf(v));
      }
      g.stroke();
      g.globalAlpha = 1;
      // label at the function's peak, so the colour is never the only key (the layout moves
      // it off its neighbours' labels; the highlighted function's label is placed first)
      const pv = values[count * peak + i];
      labels.text(data.labels[i], xOf(params[peak]), yOf(pv), { fill: colors.series[c % colors.series.length], baseline: 'bottom', dy: pv >= 0 ? -2 : 2 + plotFontPx(),
        priority: data.highlight === c ? 2 : 0 });
    }
    // the u cursor, shared with the curve, over the labels (drawn first)
    const xu = xOf(data.u);
    labels.text(`u = ${fmt(data.u)}`, xu, PAD.top - 4, { fill: colors.highlight, baseline: 'bottom', priority: 4 });
    labels.draw();
    g.setLineDash([]);
    g.strokeStyle = colors.highlight;
    g.lineWidth = 2 * scale;
    g.beginPath(); g.moveTo(xu, PAD.top - 6); g.lineTo(xu, hgt - PAD.bottom); g.stroke();
  }
  surface.onRedraw(draw);

  // Click or drag on the plot moves u (a pointer gesture, coalesced into one undo step).
  let dragging = false;
  surface.canvas.addEventListener('pointerdown', (e) => {
    if (!onSeek || !data) return;
    dragging = true;
    surface.canvas.setPointerCapture(e.pointerId);
    onSeek(uOf(surface.local(e)[0]), { final: false });
  });
  surface.canvas.addEventListener('pointermove', (e) => {
    if (dragging) onSeek(uOf(surface.local(e)[0]), { final: false });
  });
  const end = () => { if (dragging) { dragging = false; onSeek?.(null, { final: true }); } };
  surface.canvas.addEventListener('pointerup', end);
  surface.canvas.addEventListener('pointercancel', end);

  return {
    element: figure,
    canvas: surface.canvas,
    update(next) {
      data = next;
      // A caption is text, or a node (typeset names) put in once while it stays.
      const c = next.caption ?? label;
      if (typeof c === 'string') { if (caption.textContent !== c || caption.firstElementChild) caption.textContent = c; } else if (caption.firstChild !== c) caption.replaceChildren(c);
      draw();
    },
    // Screen position of the cursor (tests and the bench ask where u is drawn).
    cursorClientX() {
      if (!data) return null;
      return surface.canvas.getBoundingClientRect().left + xOf(data.u);
    },
  };
}

