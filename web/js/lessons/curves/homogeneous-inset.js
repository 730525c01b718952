// @ts-check
// The homogeneous view of a NURBS (lectures 001, 002): the control points lifted to
// (w x, w y, w), the polynomial B-spline through them in 3D, and its central projection
// to the plane w = 1, which is the rational curve. A small oblique view: x to the right,
// w up, y into the depth. Reusable for conics and rational Bezier curves.
//
//   const inset = createHomogeneousInset(container);
//   inset.update({ lifted: [[wx, wy, w]...], curve3: Float64Array (stride 3),
//                  projected: [[x, y]...], curve2: Float64Array (stride 2), at: [X, Y, W], colors });
import { createPlotCanvas } from '../../ui/plot-canvas.js';
import { plotLabels } from '../../app/label-layout.js';
import { showLegend } from '../../app/canvas-legend.js';

const DEPTH = [0.45, -0.3]; // screen direction of the y axis (oblique projection)

export function createHomogeneousInset(container) {
  const surface = createPlotCanvas(container, {
    className: 'homogeneous-inset', height: 230,
    label: 'Homogeneous view: the NURBS is the projection of a polynomial curve in (wx, wy, w) space onto the plane w = 1',
  });
  let data = null;

  function draw() {
    if (!data) return;
    const { colors } = data;
    const g = surface.begin(colors.background);
    const { width, height } = surface.size;
    // Fit: all lifted points, projected points and the origin.
    const all = [[0, 0, 0], ...data.lifted, ...data.projected.map(([x, y]) => [x, y, 1])];
    /** @type {(p: number[]) => number[]} the oblique drawing of (x, y, w) before the fit */
    const raw = ([x, y, w]) => [x + DEPTH[0] * y, -(w * wScale) + DEPTH[1] * y];
    let span = 0;
    for (const [x, y] of data.projected) span = Math.max(span, Math.abs(x), Math.abs(y));
    const wScale = Math.max(span, 1) * 0.8;
    let minX = Infinity; let maxX = -Infinity; let minY = Infinity; let maxY = -Infinity;
    for (const p of all) {
      const [sx, sy] = raw(p);
      minX = Math.min(minX, sx); maxX = Math.max(maxX, sx); minY = Math.min(minY, sy); maxY = Math.max(maxY, sy);
    }
    const zoom = Math.min((width - 30) / (maxX - minX || 1), (height - 30) / (maxY - minY || 1));
    /** @type {(p: number[]) => [number, number]} the screen point of a lifted (x, y, w) */
    const S = (p) => { const [sx, sy] = raw(p); return [15 + (sx - minX) * zoom, 15 + (sy - minY) * zoom]; };
    const line = (a, b, style) => {
      const [x0, y0] = S(a); const [x1, y1] = S(b);
      g.strokeStyle = style.stroke; g.lineWidth = style.width ?? 1; g.setLineDash(style.dash ?? []); g.globalAlpha = style.alpha ?? 1;
      g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1, y1); g.stroke(); g.globalAlpha = 1;
    };
    const poly = (xy, stride, style, lift = null) => {
      g.strokeStyle = style.stroke; g.lineWidth = style.width ?? 2; g.setLineDash(style.dash ?? []);
      g.beginPath();
      for (let j = 0; j < xy.length / stride; j += 1) {
        const p = stride === 3 ? [xy[3 * j], xy[3 * j + 1], xy[3 * j + 2]] : [xy[2 * j], xy[2 * j + 1], lift];
        const [sx, sy] = S(p);
        if (j === 0) g.moveTo(sx, sy); else g.lineTo(sx, sy);
      }
      g.stroke();
    };
    // axes from the origin
    const ext = wScale / 0.8;
    line([0, 0, 0], [ext, 0, 0], { stroke: colors.muted });
    line([0, 0, 0], [0, ext, 0], { stroke: colors.muted });
    line([0, 0, 0], [0, 0, 1.6], { stroke: colors.muted });
    /** @type {import('../../ui/plot-canvas.js').PlotLabels} */
    const labels = plotLabels(g, surface.canvas, width, height);
    labels.text('w', ...S([0, 0, 1.65]), { fill: colors.muted, priority: 1, halo: colors.background });
    labels.text('w = 1', ...S([-0.1 * ext, 0, 1]), { fill: colors.muted, halo: colors.background });
    // rays from the origin through each lifted point to its projection
    data.lifted.forEach((p, i) => {
      const far = p[2] >= 1 ? p : [p[0] / p[2], p[1] / p[2], 1];
      line([0, 0, 0], far, { stroke: colors.series[i % colors.series.length], dash: [3, 3], alpha: 0.7 });
    });
    poly(data.curve3, 3, { stroke: colors.ink, width: 2 });
    poly(data.curve2, 2, { stroke: colors.accent, width: 2.5 }, 1);
    data.lifted.forEach((p, i) => {
      const [sx, sy] = S(p);
      g.fillStyle = colors.series[i % colors.series.length];
      g.beginPath(); g.arc(sx, sy, 4, 0, Math.PI * 2); g.fill();
    });
    // the point at u: lifted, and its ray to the curve on w = 1
    line([0, 0, 0], data.at, { stroke: colors.highlight, width: 1.5 });
    const [ax, ay] = S(data.at);
    g.fillStyle = colors.highlight; g.beginPath(); g.arc(ax, ay, 5, 0, Math.PI * 2); g.fill();
    labels.draw();
    // The legend under the inset, never over its drawing.
    showLegend(surface.canvas, [[colors.ink, '3D polynomial curve', []], [colors.accent, 'its projection on w = 1 (the NURBS)', []]]);
  }
  surface.onRedraw(draw);
  return {
    canvas: surface.canvas,
    update(next) { data = next; draw(); },
  };
}
