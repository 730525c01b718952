// @ts-check
// A small function plot for the side panels: one or more series over a shared parameter
// axis, drawn piece by piece so a jump at a joint stays a visible gap (a smooth-looking
// polyline across the joint would hide exactly what the continuity lesson teaches).
// It draws numbers the core returned; it computes nothing but the axis range.
//
//   drawSeriesPlot(canvas, {
//     series: [{ label, color, dash?, pieces: [{ u: Float64Array, v: Float64Array }] }],
//     marks: [u...]        vertical lines (joints), labelled marks[i].label if objects
//     cursor: u | null     the parameter of the travelling point
//     yLabel, colors: { ink, muted, grid, background },
//     nonNegative: true     a quantity that is never negative (a speed |P'|, the lecture's
//                           curvature kappa = |P' x P''| / |P'|^3): the axis starts at 0
//   })
// Returns the axis range and the plotted samples' minimum; the labels (ticks, marks, yLabel)
// go through the label layout (app/label-layout.js): no overlap, at least the minimum size.
import { plotLabels, plotFontPx, measureText } from '../app/label-layout.js';

// top: the y label's row, then half a tick label above the top grid line.
const padFor = (px) => ({ left: Math.round(measureText('-0.000', px) + 10), right: 10, top: Math.round(px * 1.9 + 7), bottom: Math.round(px * 1.25 + 6) });

function niceRange(lo, hi) {
  if (!Number.isFinite(lo) || !Number.isFinite(hi)) return [0, 1];
  if (hi - lo < 1e-9) { const c = (hi + lo) / 2; const s = Math.max(Math.abs(c) * 0.1, 0.5); return [c - s, c + s]; }
  const span = hi - lo;
  return [lo - span * 0.08, hi + span * 0.08];
}

function tickLabel(x) {
  const a = Math.abs(x);
  if (a !== 0 && (a < 0.01 || a >= 1e4)) return x.toExponential(1);
  return String(Number(x.toPrecision(3)));
}

export function drawSeriesPlot(canvas, { series, marks = [], cursor = null, yLabel = '', colors, nonNegative = false }) {
  const rect = canvas.getBoundingClientRect();
  const dpr = window.devicePixelRatio || 1;
  const width = Math.max(1, rect.width);
  const height = Math.max(1, rect.height);
  if (canvas.width !== Math.round(width * dpr) || canvas.height !== Math.round(height * dpr)) {
    canvas.width = Math.round(width * dpr);
    canvas.height = Math.round(height * dpr);
  }
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.fillStyle = colors.background;
  g.fillRect(0, 0, width, height);

  let uMin = Infinity; let uMax = -Infinity; let vMin = Infinity; let vMax = -Infinity;
  for (const s of series) {
    for (const p of s.pieces) {
      for (let i = 0; i < p.u.length; i += 1) {
        if (!Number.isFinite(p.v[i])) continue;
        uMin = Math.min(uMin, p.u[i]); uMax = Math.max(uMax, p.u[i]);
        vMin = Math.min(vMin, p.v[i]); vMax = Math.max(vMax, p.v[i]);
      }
    }
  }
  if (!Number.isFinite(uMin)) { uMin = 0; uMax = 1; }
  const sampleMin = vMin;
  [vMin, vMax] = niceRange(Math.min(vMin, 0), vMax);
  if (nonNegative) { vMin = 0; vMax = Math.max(vMax, 1e-12); }
  const PAD = padFor(plotFontPx());
  /** @type {import('./plot-canvas.js').PlotLabels} */
  const labels = plotLabels(g, canvas, width, height);
  const plotW = width - PAD.left - PAD.right;
  const plotH = height - PAD.top - PAD.bottom;
  const X = (u) => PAD.left + ((u - uMin) / Math.max(uMax - uMin, 1e-12)) * plotW;
  const Y = (v) => PAD.top + (1 - (v - vMin) / (vMax - vMin)) * plotH;

  g.lineWidth = 1;
  g.strokeStyle = colors.grid;
  for (const v of [vMin, 0, vMax]) {
    if (v < vMin || v > vMax) continue;
    g.beginPath(); g.moveTo(PAD.left, Y(v)); g.lineTo(width - PAD.right, Y(v)); g.stroke();
    labels.text(tickLabel(v), PAD.left - 4, Y(v), { fill: colors.muted, align: 'right', priority: 2, fixed: true });
  }
  g.setLineDash([4, 3]);
  g.strokeStyle = colors.muted;
  for (const m of marks) {
    const u = typeof m === 'number' ? m : m.u;
    g.beginPath(); g.moveTo(X(u), PAD.top); g.lineTo(X(u), PAD.top + plotH); g.stroke();
    labels.text(typeof m === 'number' ? `u=${tickLabel(u)}` : m.label, X(u), PAD.top + plotH + 3, { fill: colors.muted, baseline: 'top', priority: 1, fixed: true });
  }
  g.setLineDash([]);
  if (yLabel) labels.text(yLabel, PAD.left + 4, 2, { fill: colors.ink, align: 'left', baseline: 'top', priority: 3 });

  for (const s of series) {
    g.strokeStyle = s.color;
    g.lineWidth = 2;
    g.setLineDash(s.dash ?? []);
    for (const p of s.pieces) {
      g.beginPath();
      let started = false;
      for (let i = 0; i < p.u.length; i += 1) {
        if (!Number.isFinite(p.v[i])) { started = false; continue; }
        const x = X(p.u[i]);
        const y = Math.min(height, Math.max(0, Y(p.v[i])));
        if (started) g.lineTo(x, y); else { g.moveTo(x, y); started = true; }
      }
      g.stroke();
    }
  }
  g.setLineDash([]);
  if (cursor !== null && cursor !== undefined) {
    g.strokeStyle = colors.ink;
    g.lineWidth = 1.5;
    g.beginPath(); g.moveTo(X(cursor), PAD.top); g.lineTo(X(cursor), PAD.top + plotH); g.stroke();
  }
  labels.draw();
  canvas.dataset.axisMin = String(vMin);
  canvas.dataset.sampleMin = String(sampleMin);
  return { X, Y, uMin, uMax, vMin, vMax, sampleMin };
}
