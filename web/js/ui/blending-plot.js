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

const PAD = { left: 40, right: 12, top: 14, bottom: 24 };

export function createBlendingPlot(container, { label = 'Blending functions', height = 190, onSeek = null } = {}) {
  const figure = document.createElement('figure');
  figure.className = 'blending-plot';
  const caption = document.createElement('figcaption');
  caption.textContent = label;
  container.append(figure);
  const surface = createPlotCanvas(figure, { className: 'blending-canvas', label, height });
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
    const [lo, hi] = range();
    const yOf = (v) => PAD.top + (1 - (v - lo) / (hi - lo || 1)) * (hgt - PAD.top - PAD.bottom);
    g.font = `${12 * scale}px system-ui, "DejaVu Sans", sans-serif`;
    // axes: 0 and 1
    g.strokeStyle = colors.grid;
    g.lineWidth = 1;
    g.setLineDash([]);
    for (const v of [0, 1]) {
      g.beginPath(); g.moveTo(PAD.left, yOf(v)); g.lineTo(surface.size.width - PAD.right, yOf(v)); g.stroke();
    }
    g.fillStyle = colors.muted;
    g.textAlign = 'right';
    g.textBaseline = 'middle';
    g.fillText('1', PAD.left - 6, yOf(1));
    g.fillText('0', PAD.left - 6, yOf(0));
    // knots (B-splines) or segment joints, and the domain ends
    g.textAlign = 'center';
    g.textBaseline = 'top';
    for (const k of data.knots ?? []) {
      if (k < data.domain.start - 1e-12 || k > data.domain.end + 1e-12) continue;
      g.strokeStyle = colors.grid;
      g.beginPath(); g.moveTo(xOf(k), PAD.top); g.lineTo(xOf(k), hgt - PAD.bottom); g.stroke();
    }
    g.fillStyle = colors.muted;
    g.fillText(fmt(data.domain.start), xOf(data.domain.start), hgt - PAD.bottom + 4);
    g.fillText(fmt(data.domain.end), xOf(data.domain.end), hgt - PAD.bottom + 4);
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
      // label at the function's peak, so the colour is never the only key
      g.setLineDash([]);
      g.fillStyle = colors.series[c % colors.series.length];
      g.textBaseline = 'bottom';
      const pv = values[count * peak + i];
      // kept inside the plot: a peak at either end would cut the label in half
      const half = g.measureText(data.labels[i]).width / 2;
      const lx = Math.min(Math.max(xOf(params[peak]), PAD.left + half), surface.size.width - PAD.right - half);
      const ly = Math.min(Math.max(yOf(pv) - (pv >= 0 ? 2 : -14 * scale), 12 * scale + 2), hgt - 2);
      g.fillText(data.labels[i], lx, ly);
      g.globalAlpha = 1;
    }
    // the u cursor, shared with the curve
    g.setLineDash([]);
    g.strokeStyle = colors.highlight;
    g.lineWidth = 2 * scale;
    const xu = xOf(data.u);
    g.beginPath(); g.moveTo(xu, PAD.top - 6); g.lineTo(xu, hgt - PAD.bottom); g.stroke();
    g.fillStyle = colors.highlight;
    g.textBaseline = 'bottom';
    g.fillText(`u = ${fmt(data.u)}`, Math.min(Math.max(xu, PAD.left + 30), surface.size.width - 40), PAD.top + 2);
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
      // A caption is text, or a node (typeset names, issue 18) put in once while it stays.
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

