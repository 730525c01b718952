// @ts-check
// Drawing without mathematics: a painter draws what the core computed, in world
// coordinates, through a view transform. Two painters share one interface, so a lesson's
// draw() makes both the canvas picture and the exported SVG figure:
//   clear(), line(ax,ay,bx,by,style), polyline(xy, style, stride=2), polygon(xy, style,
//   stride=2), circle(x,y,radiusPx,style), text(x,y,string,style), arrow(ax,ay,bx,by,style)
// `xy` is a flat array (x0, y0, x1, y1, ...) with the given stride (2 or 3: z ignored).
// style: { stroke, fill, width (px), dash ([px]), font (px size), align, baseline, alpha }
// Texts are labels (app/label-layout.js): text() asks, finish() places them all (no two
// overlap, none leaves the canvas, none under MIN_LABEL_PX) and draws them on top.
// text style extras: priority (higher is placed first: the selected/dragged element),
// fixed (only the asked place). legend(entries) gives the frame's legend, entries
// [color, words, dash?]: the canvas painter shows it as HTML next to the canvas
// (app/canvas-legend.js), the SVG painter as a band under the figure.
import { LabelLayout, MIN_LABEL_PX, recordLabels, cssFont } from './label-layout.js';
import { showLegend } from './canvas-legend.js';

export class Transform {
  // world (x, y) -> screen (cssX, cssY): y up in the world, down on screen.
  constructor({ cx = 0, cy = 0, zoom = 100, width = 800, height = 600 } = {}) {
    this.cx = cx;
    this.cy = cy;
    this.zoom = zoom;
    this.width = width;
    this.height = height;
  }
  toScreen(x, y) { return [this.width / 2 + (x - this.cx) * this.zoom, this.height / 2 - (y - this.cy) * this.zoom]; }
  toWorld(sx, sy) { return [this.cx + (sx - this.width / 2) / this.zoom, this.cy - (sy - this.height / 2) / this.zoom]; }
}

// The arrow head at (bx, by), in screen pixels: tip and two barbs (null for a zero-length arrow).
function arrowHead(t, ax, ay, bx, by, scale) {
  const [x0, y0] = t.toScreen(ax, ay);
  const [x1, y1] = t.toScreen(bx, by);
  const len = Math.hypot(x1 - x0, y1 - y0);
  if (len < 1e-9) return null;
  const head = Math.min(12 * scale, len * 0.4);
  const ux = (x1 - x0) / len;
  const uy = (y1 - y0) / len;
  return [[x1, y1], [x1 - head * ux + head * 0.45 * uy, y1 - head * uy - head * 0.45 * ux],
    [x1 - head * ux - head * 0.45 * uy, y1 - head * uy + head * 0.45 * ux]];
}

// A label asked by either painter: the same sizes and the same layout for both.
const layoutOf = (painter) => {
  if (!painter.layout) painter.layout = new LabelLayout(painter.t.width, painter.t.height);
  return painter.layout;
};

// A circle is a marker labels keep off (app/label-layout.js).
const markerOf = (painter, sx, sy, radiusPx) => layoutOf(painter).obstacle(sx, sy, radiusPx * painter.scale);

function askLabel(painter, x, y, string, style) {
  layoutOf(painter);
  const [sx, sy] = painter.t.toScreen(x, y);
  painter.layout.ask(string, sx, sy, {
    px: Math.max(style.font ?? MIN_LABEL_PX, MIN_LABEL_PX) * painter.scale,
    weight: style.weight ?? 500,
    align: style.align ?? 'center',
    baseline: style.baseline ?? 'middle',
    dx: (style.dx ?? 0) * painter.scale,
    dy: (style.dy ?? 0) * painter.scale,
    priority: style.priority ?? 0,
    fixed: style.fixed ?? false,
    style,
  });
}

const placeLabels = (painter) => (painter.layout ? painter.layout.place() : []);

export class CanvasPainter {
  constructor(ctx2d, transform, { scale = 1, background = '#fff' } = {}) {
    this.g = ctx2d;
    this.t = transform;
    this.scale = scale; // presentation mode draws thicker lines and bigger handles
    this.background = background;
  }

  #apply(style) {
    const g = this.g;
    g.globalAlpha = style.alpha ?? 1;
    g.lineWidth = (style.width ?? 1.5) * this.scale;
    g.setLineDash((style.dash ?? []).map((d) => d * this.scale));
    g.lineJoin = 'round';
    g.lineCap = 'round';
    if (style.stroke) g.strokeStyle = style.stroke;
    if (style.fill) g.fillStyle = style.fill;
  }

  #finish(style) {
    if (style.fill) this.g.fill();
    if (style.stroke) this.g.stroke();
    this.g.globalAlpha = 1;
  }

  // A transparent canvas: the picture under it (the stage's WebGL2 underlay) shows through.
  clearTransparent() {
    const g = this.g;
    g.save();
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.clearRect(0, 0, g.canvas.width, g.canvas.height);
    g.restore();
  }

  clear() {
    const g = this.g;
    g.save();
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.fillStyle = this.background;
    g.fillRect(0, 0, g.canvas.width, g.canvas.height);
    g.restore();
  }

  line(ax, ay, bx, by, style = {}) {
    const [x0, y0] = this.t.toScreen(ax, ay);
    const [x1, y1] = this.t.toScreen(bx, by);
    this.g.beginPath();
    this.g.moveTo(x0, y0);
    this.g.lineTo(x1, y1);
    this.#apply({ stroke: '#000', ...style, fill: undefined });
    this.#finish({ stroke: style.stroke ?? '#000' });
  }

  #path(xy, stride, close) {
    const g = this.g;
    g.beginPath();
    for (let i = 0; i + 1 < xy.length; i += stride) {
      const [sx, sy] = this.t.toScreen(xy[i], xy[i + 1]);
      if (i === 0) g.moveTo(sx, sy); else g.lineTo(sx, sy);
    }
    if (close) g.closePath();
  }

  polyline(xy, style = {}, stride = 2) {
    this.#path(xy, stride, false);
    this.#apply(style);
    this.#finish({ stroke: style.stroke ?? '#000' });
  }

  polygon(xy, style = {}, stride = 2) {
    this.#path(xy, stride, true);
    this.#apply(style);
    this.#finish(style);
  }

  // Many shapes in one path, one fill or stroke (a big mesh: 100k faces are one call, not
  // 100k). xy: flat world coordinates; polygons: offsets[i]..offsets[i+1] are polygon i's
  // points (as indices of points, not of numbers); segments: 4 numbers per segment.
  polygons(xy, offsets, style = {}) {
    const g = this.g;
    const { cx, cy, zoom, width, height } = this.t; // toScreen, inlined: no array per point
    const ox = width / 2 - cx * zoom; const oy = height / 2 + cy * zoom;
    g.beginPath();
    for (let i = 0; i + 1 < offsets.length; i += 1) {
      for (let k = offsets[i]; k < offsets[i + 1]; k += 1) {
        const sx = ox + xy[2 * k] * zoom; const sy = oy - xy[2 * k + 1] * zoom;
        if (k === offsets[i]) g.moveTo(sx, sy); else g.lineTo(sx, sy);
      }
      if (style.stroke) g.closePath(); // a fill closes each subpath by itself (closePath is slow)
    }
    this.#apply(style);
    this.#finish(style);
  }

  segments(xy, style = {}) {
    const g = this.g;
    const { cx, cy, zoom, width, height } = this.t;
    const ox = width / 2 - cx * zoom; const oy = height / 2 + cy * zoom;
    g.beginPath();
    for (let i = 0; i + 3 < xy.length; i += 4) {
      g.moveTo(ox + xy[i] * zoom, oy - xy[i + 1] * zoom);
      g.lineTo(ox + xy[i + 2] * zoom, oy - xy[i + 3] * zoom);
    }
    this.#apply({ stroke: '#000', ...style, fill: undefined });
    this.#finish({ stroke: style.stroke ?? '#000' });
  }

  circle(x, y, radiusPx, style = {}) {
    const [sx, sy] = this.t.toScreen(x, y);
    markerOf(this, sx, sy, radiusPx);
    this.g.beginPath();
    this.g.arc(sx, sy, radiusPx * this.scale, 0, Math.PI * 2);
    this.#apply(style);
    this.#finish(style);
  }

  text(x, y, string, style = {}) {
    askLabel(this, x, y, string, style);
  }

  legend(entries) { this.legendEntries = entries; }

  // Places and draws the frame's labels, records them for labelRects(), shows the legend.
  finish() {
    const g = this.g;
    const placed = placeLabels(this);
    for (const p of placed.filter((q) => q.leader)) { // leaders first: no leader crosses a text
      g.globalAlpha = 0.7;
      g.lineWidth = this.scale;
      g.setLineDash([]);
      g.strokeStyle = p.opts.style.fill ?? '#000';
      g.beginPath(); g.moveTo(p.leader[0], p.leader[1]); g.lineTo(p.leader[2], p.leader[3]); g.stroke();
    }
    for (const p of placed) {
      const style = p.opts.style;
      g.font = cssFont(p.opts.px, p.opts.weight);
      g.textAlign = p.opts.align;
      g.textBaseline = p.opts.baseline;
      g.globalAlpha = style.alpha ?? 1;
      if (style.halo) {
        g.lineWidth = 4 * this.scale;
        g.strokeStyle = style.halo;
        g.lineJoin = 'round';
        g.setLineDash([]);
        g.strokeText(p.text, p.x, p.y);
      }
      g.fillStyle = style.fill ?? '#000';
      g.fillText(p.text, p.x, p.y);
      g.globalAlpha = 1;
    }
    recordLabels(g.canvas, placed, this.layout?.dropped ?? 0);
    if (g.canvas?.isConnected) showLegend(g.canvas, this.legendEntries ?? [], this.scale);
    this.layout = null;
  }

  arrow(ax, ay, bx, by, style = {}) {
    this.line(ax, ay, bx, by, style);
    const pts = arrowHead(this.t, ax, ay, bx, by, this.scale);
    if (!pts) return;
    const g = this.g;
    g.beginPath();
    g.moveTo(...pts[0]);
    g.lineTo(...pts[1]);
    g.lineTo(...pts[2]);
    g.closePath();
    g.globalAlpha = style.alpha ?? 1;
    g.fillStyle = style.stroke ?? '#000';
    g.fill();
    g.globalAlpha = 1;
  }
}

const svgNumber = (x) => (Math.round(x * 100) / 100).toString();
const escapeXml = (s) => String(s).replace(/[<>&"']/g, (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&apos;' })[c]);

// Builds an SVG document as text. Every user-visible string goes through escapeXml, so a
// label from a file cannot become markup.
export class SvgPainter {
  constructor(transform, { scale = 1, background = '#fff' } = {}) {
    this.t = transform;
    this.scale = scale;
    this.background = background;
    this.parts = [];
  }

  #style(style, { fill = 'none' } = {}) {
    const attrs = [];
    attrs.push(`fill="${escapeXml(style.fill ?? fill)}"`);
    if (style.stroke) attrs.push(`stroke="${escapeXml(style.stroke)}"`, `stroke-width="${svgNumber((style.width ?? 1.5) * this.scale)}"`,
      'stroke-linecap="round"', 'stroke-linejoin="round"');
    if (style.dash?.length) attrs.push(`stroke-dasharray="${style.dash.map((d) => svgNumber(d * this.scale)).join(' ')}"`);
    if (style.alpha !== undefined) attrs.push(`opacity="${svgNumber(style.alpha)}"`);
    return attrs.join(' ');
  }

  #points(xy, stride) {
    const out = [];
    for (let i = 0; i + 1 < xy.length; i += stride) out.push(this.t.toScreen(xy[i], xy[i + 1]).map(svgNumber).join(','));
    return out.join(' ');
  }

  clear() {
    this.parts = [`<rect width="100%" height="100%" fill="${escapeXml(this.background)}"/>`];
  }

  line(ax, ay, bx, by, style = {}) {
    const [x0, y0] = this.t.toScreen(ax, ay);
    const [x1, y1] = this.t.toScreen(bx, by);
    this.parts.push(`<line x1="${svgNumber(x0)}" y1="${svgNumber(y0)}" x2="${svgNumber(x1)}" y2="${svgNumber(y1)}" ${this.#style({ stroke: '#000', ...style, fill: undefined })}/>`);
  }

  polyline(xy, style = {}, stride = 2) {
    this.parts.push(`<polyline points="${this.#points(xy, stride)}" ${this.#style({ stroke: '#000', ...style })}/>`);
  }

  polygon(xy, style = {}, stride = 2) {
    this.parts.push(`<polygon points="${this.#points(xy, stride)}" ${this.#style(style)}/>`);
  }

  polygons(xy, offsets, style = {}) {
    const d = [];
    for (let i = 0; i + 1 < offsets.length; i += 1) {
      for (let k = offsets[i]; k < offsets[i + 1]; k += 1) {
        d.push((k === offsets[i] ? 'M' : 'L') + this.t.toScreen(xy[2 * k], xy[2 * k + 1]).map(svgNumber).join(','));
      }
      d.push('Z');
    }
    this.parts.push(`<path d="${d.join('')}" ${this.#style(style)}/>`);
  }

  segments(xy, style = {}) {
    const d = [];
    for (let i = 0; i + 3 < xy.length; i += 4) {
      d.push(`M${this.t.toScreen(xy[i], xy[i + 1]).map(svgNumber).join(',')}L${this.t.toScreen(xy[i + 2], xy[i + 3]).map(svgNumber).join(',')}`);
    }
    this.parts.push(`<path d="${d.join('')}" ${this.#style({ stroke: '#000', ...style, fill: 'none' })}/>`);
  }

  circle(x, y, radiusPx, style = {}) {
    const [sx, sy] = this.t.toScreen(x, y);
    markerOf(this, sx, sy, radiusPx);
    this.parts.push(`<circle cx="${svgNumber(sx)}" cy="${svgNumber(sy)}" r="${svgNumber(radiusPx * this.scale)}" ${this.#style(style)}/>`);
  }

  text(x, y, string, style = {}) {
    askLabel(this, x, y, string, style);
  }

  legend(entries) { this.legendEntries = entries; }

  #emitLeader(p) {
    const style = p.opts.style;
    if (p.leader) this.parts.push(`<line x1="${svgNumber(p.leader[0])}" y1="${svgNumber(p.leader[1])}" x2="${svgNumber(p.leader[2])}" y2="${svgNumber(p.leader[3])}" stroke="${escapeXml(style.fill ?? '#000')}" stroke-width="${svgNumber(this.scale)}" opacity="0.7"/>`);
  }

  #emitText(p) {
    const style = p.opts.style;
    const anchor = { left: 'start', right: 'end', center: 'middle', start: 'start', end: 'end' }[p.opts.align];
    const baseline = { top: 'hanging', middle: 'central', bottom: 'text-after-edge', alphabetic: 'alphabetic' }[p.opts.baseline];
    const halo = style.halo ? ` stroke="${escapeXml(style.halo)}" stroke-width="${svgNumber(4 * this.scale)}" paint-order="stroke"` : '';
    const alpha = style.alpha !== undefined ? ` opacity="${svgNumber(style.alpha)}"` : '';
    this.parts.push(`<text x="${svgNumber(p.x)}" y="${svgNumber(p.y)}" font-family="system-ui, sans-serif" font-size="${svgNumber(p.opts.px)}" font-weight="${p.opts.weight}" text-anchor="${anchor}" dominant-baseline="${baseline}" fill="${escapeXml(style.fill ?? '#000')}"${halo}${alpha}>${escapeXml(p.text)}</text>`);
  }

  // The legend as a band under the figure: one row per entry, a line sample in the
  // entry's colour and dash, then its words (the canvas shows the same legend as HTML).
  #legendBand() {
    const entries = this.legendEntries ?? [];
    if (!entries.length) return 0;
    const px = MIN_LABEL_PX * this.scale;
    const rowH = px * 1.6;
    const top = this.t.height;
    this.parts.push(`<rect x="0" y="${svgNumber(top)}" width="${svgNumber(this.t.width)}" height="${svgNumber(rowH * entries.length + px)}" fill="${escapeXml(this.background)}"/>`);
    entries.forEach(([color, words, dash = []], i) => {
      const y = top + px / 2 + rowH * (i + 0.5);
      if (color) this.parts.push(`<line x1="${svgNumber(px)}" y1="${svgNumber(y)}" x2="${svgNumber(3 * px)}" y2="${svgNumber(y)}" ${this.#style({ stroke: color, width: 3, dash })}/>`);
      this.parts.push(`<text x="${svgNumber(3.6 * px)}" y="${svgNumber(y)}" font-family="system-ui, sans-serif" font-size="${svgNumber(px)}" dominant-baseline="central" fill="${escapeXml(color ?? '#000')}">${escapeXml(words)}</text>`);
    });
    return rowH * entries.length + px;
  }

  arrow(ax, ay, bx, by, style = {}) {
    this.line(ax, ay, bx, by, style);
    const pts = arrowHead(this.t, ax, ay, bx, by, this.scale);
    if (!pts) return;
    this.parts.push(`<polygon points="${pts.map((p) => p.map(svgNumber).join(',')).join(' ')}" fill="${escapeXml(style.stroke ?? '#000')}"/>`);
  }

  toString() {
    const placed = placeLabels(this);
    for (const p of placed) this.#emitLeader(p); // leaders first: no leader crosses a text
    for (const p of placed) this.#emitText(p);
    this.layout = null;
    const band = this.#legendBand();
    const w = svgNumber(this.t.width);
    const h = svgNumber(this.t.height + band);
    return `<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}">\n${this.parts.join('\n')}\n</svg>\n`;
  }
}
