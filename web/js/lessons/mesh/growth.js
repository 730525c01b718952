// @ts-check
// Query and edit cost, and storage, against mesh size: lecture 000's point that the winged
// edge answers "faces around a vertex" in time proportional to the answer while a table
// without adjacency scans the mesh, as a picture. The core answers every number: a query's
// and an edit's reads at the middle element of grids of n x n quads (F = 2 n² triangles),
// about a thousand to a million faces (COST_GRIDS; api.queryCostGrowth, api.editCostGrowth:
// counted on small grids and exact at every size), and the storage of real grids of
// GROWTH_SIZES (mesh.storage and mesh.halfEdgeStorage: bytes per representation). The page only plots them, on
// log-log axes, and lists them in a table for the keyboard and screen readers.
import { h } from '../../app/dom.js';
import { plotLabels, plotFontPx } from '../../app/label-layout.js';
import { createVirtualTable } from '../../ui/virtual-table.js';

// n x n quads: about a thousand, ten thousand, a hundred thousand and a million faces (n even:
// the core measures the same neighbourhood at every size).
export const COST_GRIDS = [22, 70, 224, 708];
export const COST_FACES = COST_GRIDS.map((n) => 2 * n * n);
export const GROWTH_SIZES = [4, 8, 16, 32, 64, 128];

// {sizes: [{n, faces}], series: {[representation]: number[]}}: what a query kind reads on the
// COST_GRIDS, from the core.
export function querySeries(api, kind) {
  const { sizes, reads } = api.queryCostGrowth(kind, COST_GRIDS);
  const series = {};
  for (const one of reads) for (const [rep, n] of Object.entries(one)) (series[rep] ??= []).push(n);
  return { sizes, series };
}

// The same for storage in bytes, on real grids of GROWTH_SIZES, built once per page (the
// meshes are freed at once).
export function storageSeries(api) {
  const sizes = [];
  const series = {};
  for (const n of GROWTH_SIZES) {
    const mesh = api.buildMesh(api.generateMesh('grid', { nx: n, ny: n, layout: 'csr' }));
    try {
      sizes.push({ n, faces: mesh.counts().faces });
      for (const [rep, a] of Object.entries({ ...mesh.storage(), 'half-edge': mesh.halfEdgeStorage() })) (series[rep] ??= []).push(a.bytes);
    } finally {
      mesh.dispose();
    }
  }
  return { sizes, series };
}

// Room for the axis numbers at the label size (app/label-layout.js).
const padFor = (px) => ({ left: Math.round(px * 2.6 + 12), right: 24, top: Math.round(px * 1.25 + 8), bottom: Math.round(px * 1.25 + 10) });
const SUPERSCRIPT = '⁰¹²³⁴⁵⁶⁷⁸⁹';
const power = (k) => `10${String(k).split('').map((d) => (d === '-' ? '⁻' : SUPERSCRIPT[Number(d)])).join('')}`;

// A log-log plot of the series against faces, decade grid lines, a marker per size.
// rect: the canvas's size in CSS pixels.
function drawGrowth(canvas, rect, { sizes, series }, { colors, names, yLabel }) {
  const dpr = window.devicePixelRatio || 1;
  const width = Math.max(1, rect.width); const height = Math.max(1, rect.height);
  canvas.width = Math.round(width * dpr); canvas.height = Math.round(height * dpr);
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.fillStyle = colors.background;
  g.fillRect(0, 0, width, height);
  const PAD = padFor(plotFontPx());
  const xs = sizes.map((s) => Math.log10(s.faces));
  const values = Object.values(series).flat().filter((v) => v > 0);
  const x0 = Math.floor(Math.min(...xs)); const x1 = Math.ceil(Math.max(...xs));
  const y0 = Math.floor(Math.log10(Math.min(...values))); const y1 = Math.ceil(Math.log10(Math.max(...values)));
  const X = (x) => PAD.left + ((x - x0) / Math.max(1, x1 - x0)) * (width - PAD.left - PAD.right);
  const Y = (y) => PAD.top + (1 - (y - y0) / Math.max(1, y1 - y0)) * (height - PAD.top - PAD.bottom);
  /** @type {import('../../ui/plot-canvas.js').PlotLabels} */
  const labels = plotLabels(g, canvas, width, height);
  g.strokeStyle = colors.grid; g.lineWidth = 1;
  for (let k = y0; k <= y1; k += 1) {
    g.beginPath(); g.moveTo(PAD.left, Y(k)); g.lineTo(width - PAD.right, Y(k)); g.stroke();
    labels.text(power(k), PAD.left - 4, Y(k), { fill: colors.muted, align: 'right', priority: 1, fixed: true });
  }
  for (let k = x0; k <= x1; k += 1) {
    g.beginPath(); g.moveTo(X(k), PAD.top); g.lineTo(X(k), height - PAD.bottom); g.stroke();
    labels.text(power(k), X(k), height - PAD.bottom + 4, { fill: colors.muted, baseline: 'top', priority: 1, fixed: true });
  }
  labels.text('faces F', width - PAD.right, height - PAD.bottom - 4, { fill: colors.ink, align: 'right', baseline: 'bottom', halo: colors.background });
  labels.text(yLabel, PAD.left + 4, PAD.top, { fill: colors.ink, align: 'left', baseline: 'top', halo: colors.background, priority: 2 });
  Object.keys(series).forEach((rep, i) => {
    const colour = colors.series[i % colors.series.length];
    g.strokeStyle = colour; g.fillStyle = colour; g.lineWidth = 2;
    g.setLineDash(i % 2 ? [6, 4] : []);
    g.beginPath();
    series[rep].forEach((v, k) => { const x = X(xs[k]); const y = Y(Math.log10(Math.max(v, 1))); if (k) g.lineTo(x, y); else g.moveTo(x, y); });
    g.stroke();
    g.setLineDash([]);
    series[rep].forEach((v, k) => { g.beginPath(); g.arc(X(xs[k]), Y(Math.log10(Math.max(v, 1))), 3, 0, 2 * Math.PI); g.fill(); });
  });
  labels.draw(); // the labels last, on top of the lines, none over another (app/label-layout.js)
  return Object.keys(series).map((rep, i) => ({ rep, name: names(rep), colour: colors.series[i % colors.series.length], dashed: i % 2 === 1 }));
}

// The plot, its legend and its numbers as a table (the one windowed table every tab uses).
// update(data) draws new series; `faces`: the mesh sizes the series are given at (the
// query and storage grids by default).
export function createGrowthPlot(ctx, { id, caption, yLabel, names, faces = GROWTH_SIZES.map((n) => 2 * n * n) }) {
  const canvas = h('canvas', { id: `${id}-plot`, class: 'growth-canvas', role: 'img', 'aria-label': caption });
  const legend = h('ul', { class: 'growth-legend', id: `${id}-legend` });
  let data = null;
  let rows = [];
  const table = createVirtualTable({ id: `${id}-table`, className: 'data-table growth-table', caption: `${yLabel} against the number of faces F`,
    head: [['representation', ...faces.map((f) => `F = ${f.toLocaleString('en')}`)]],
    rowLabel: (i) => names(rows[i][0]), rowAttributes: (i) => ({ 'data-representation': rows[i][0] }),
    row: (i) => rows[i][1].map((x) => x.toLocaleString('en')) });
  const details = h('details', { class: 'growth-numbers' }, h('summary', {}, 'The numbers'), table.root);
  const root = h('figure', { class: 'growth', id }, h('figcaption', {}, caption), canvas, legend, details);
  // The canvas's size as its ResizeObserver last saw it (none while hidden): asked of the
  // canvas on every update, it laid out the whole page in the middle of an edit's frame.
  let size = null;
  function draw() {
    if (!data || !root.isConnected || !size?.width) return;
    const keys = drawGrowth(canvas, size, data, { colors: ctx.colors, names, yLabel });
    legend.replaceChildren(...keys.map((k) => {
      const swatch = h('span', { class: `swatch${k.dashed ? ' dashed' : ''}` });
      swatch.style.borderColor = k.colour;
      return h('li', {}, swatch, k.name);
    }));
  }
  new ResizeObserver(([entry]) => { size = { width: entry.contentRect.width, height: entry.contentRect.height }; draw(); }).observe(canvas);
  return {
    root,
    get data() { return data; },
    update(next) {
      if (next === data) { draw(); return; }
      data = next;
      rows = Object.entries(data.series);
      table.refresh(rows.length);
      draw();
    },
  };
}
