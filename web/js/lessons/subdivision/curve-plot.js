// @ts-check
// The curve beside the mesh: its control polygon, the polygon after as many
// subdivision steps as the mesh's level and the B-spline they approach, on a plot canvas of
// its own. The control points are dragged with the pointer (mouse, pen, touch); the plot's
// frame fits the polygon and stays still while a point is dragged, so the point stays under
// the pointer. Every position drawn is the core's (the lesson's compute asked for it).
import { createPlotCanvas } from '../../ui/plot-canvas.js';
import { showLegend } from '../../app/canvas-legend.js';

const PAD = 14;        // px around the polygon
const LABELS = 0;      // px above it for a legend (the legend is HTML under the plot: app/canvas-legend.js)
const HIT_PX = 12;     // a press this close to a control point (CSS px) picks it
const ROUND = 1e4;     // dragged coordinates are kept to 1e-4 (short links)

// The frame that shows the control polygon whole: world (x, y) <-> plot pixels.
function frameOf(control, width, height) {
  let minX = Infinity; let maxX = -Infinity; let minY = Infinity; let maxY = -Infinity;
  for (let i = 0; i < control.length; i += 2) {
    minX = Math.min(minX, control[i]); maxX = Math.max(maxX, control[i]);
    minY = Math.min(minY, control[i + 1]); maxY = Math.max(maxY, control[i + 1]);
  }
  const k = Math.min((width - 2 * PAD) / (maxX - minX || 1), (height - 2 * PAD - LABELS) / (maxY - minY || 1));
  return {
    toPlot: (x, y) => [PAD + (x - minX) * k, height - PAD - (y - minY) * k],
    toWorld: (px, py) => [minX + (px - PAD) / k, minY + (height - PAD - py) / k],
  };
}

/**
 * @param {HTMLElement} container
 * @param {any} ctx the lesson's ctx (state, commit, endGesture, render)
 */
export function createCurvePlot(container, ctx) {
  const plot = createPlotCanvas(container, { className: 'curve-plot', label: 'Control polygon, its subdivided polygon and the B-spline it converges to; drag a control point to reshape', height: 190 });
  plot.onRedraw(() => ctx.render());
  /** @type {{ frame: any, control: Float64Array | null, drag: any, drags: number }} */
  const self = { frame: null, control: null, drag: null, drags: 0 };

  const pointAt = (px, py) => {
    let best = -1; let bestD = HIT_PX;
    for (let i = 0; self.control && 2 * i < self.control.length; i += 1) {
      const [x, y] = self.frame.toPlot(self.control[2 * i], self.control[2 * i + 1]);
      const d = Math.hypot(x - px, y - py);
      if (d <= bestD) { best = i; bestD = d; }
    }
    return best;
  };
  plot.canvas.addEventListener('pointerdown', (e) => {
    if (!self.frame) return;
    const [px, py] = plot.local(e);
    const i = pointAt(px, py);
    if (i < 0) return;
    self.drags += 1;
    self.drag = { i, pointerId: e.pointerId, frame: self.frame, key: `curve-point:${self.drags}` };
    plot.canvas.setPointerCapture(e.pointerId);
    e.preventDefault();
  });
  plot.canvas.addEventListener('pointermove', (e) => {
    const drag = self.drag;
    if (!drag || e.pointerId !== drag.pointerId) return;
    const [px, py] = plot.local(e);
    const [x, y] = drag.frame.toWorld(px, py).map((v) => Math.round(v * ROUND) / ROUND);
    const state = ctx.state;
    // The polygon changed under the pointer (undo, a link) and has no such point: the drag ends.
    if (2 * drag.i + 1 >= state.curve.points.length) { self.drag = null; ctx.endGesture(); return; }
    const points = state.curve.points.slice();
    points[2 * drag.i] = x; points[2 * drag.i + 1] = y;
    ctx.commit({ ...state, curve: { ...state.curve, points } }, { coalesce: drag.key });
  });
  const end = (e) => {
    if (!self.drag || e.pointerId !== self.drag.pointerId) return;
    self.drag = null;
    ctx.endGesture();
    ctx.render();
  };
  plot.canvas.addEventListener('pointerup', end);
  plot.canvas.addEventListener('pointercancel', end);

  return {
    plot,
    // Client position of control point i (for tests: where to press).
    pointClient(i) {
      const [x, y] = self.frame.toPlot(self.control[2 * i], self.control[2 * i + 1]);
      const rect = plot.canvas.getBoundingClientRect();
      return { x: rect.left + x, y: rect.top + y };
    },
    draw(model, colors) {
      if (!model) return;
      const g = plot.begin(colors.background);
      const { width, height } = plot.size;
      const { control, refined, limit, closed, steps } = model.curve;
      self.control = control;
      self.frame = self.drag ? self.drag.frame : frameOf(control, width, height);
      const path = (xy, style, close) => {
        g.beginPath();
        for (let i = 0; i < xy.length; i += 2) {
          const [x, y] = self.frame.toPlot(xy[i], xy[i + 1]);
          if (i) g.lineTo(x, y); else g.moveTo(x, y);
        }
        if (close) g.closePath();
        g.strokeStyle = style.stroke; g.lineWidth = style.width; g.setLineDash(style.dash ?? []);
        g.stroke();
      };
      const dots = (xy, r, fill) => {
        g.fillStyle = fill;
        for (let i = 0; i < xy.length; i += 2) {
          const [x, y] = self.frame.toPlot(xy[i], xy[i + 1]);
          g.beginPath(); g.arc(x, y, r, 0, 2 * Math.PI); g.fill();
        }
      };
      path(control, { stroke: colors.muted, width: 1.2, dash: [5, 4] }, closed);
      dots(control, 4, colors.muted);
      path(limit, { stroke: colors.series[1], width: 3 }, closed);
      path(refined, { stroke: colors.series[0], width: 1.5 }, closed);
      if (refined.length <= 400) dots(refined, 2.5, colors.series[0]);
      g.setLineDash([]);
      // The legend under the plot, never over the curves.
      showLegend(plot.canvas, [[colors.muted, 'control polygon', [5, 4]], [colors.series[0], `after ${steps} step${steps === 1 ? '' : 's'}`, []],
        [colors.series[1], 'B-spline (limit)', []]]);
    },
  };
}
