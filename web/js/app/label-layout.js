// @ts-check
// Label layout: screen layout, no mathematics. Every text a painter or a side
// plot draws on a canvas is a label: it asks for an anchor (screen px) and a preferred
// offset; the layout measures its box (the text's measured width, 1.25 x its font size
// high, plus LABEL_MARGIN_PX on every side) and puts it at the first candidate whose box
// lies inside the canvas and overlaps no box already placed in this frame. The candidates,
// in order: the asked position, its mirror images (dx, dy negated), then rings of eight
// positions around the anchor at 1x, 2x and 3x the box size. A label that fits nowhere is
// dropped (counted in `dropped`, so a test can see it); one placed farther from its anchor
// than it asked (and than LEADER_MIN_PX) is joined to it by a thin leader line. Labels also keep off the drawn
// markers (circles: handles, control points) where a candidate allows it. Labels are placed in priority
// order (higher first, then the order they were asked in): the element a person is
// pointing at or dragging asks with a higher priority and so keeps its asked place.
// `fixed: true` labels (a number inside a badge) only take their asked place or are dropped.
// A label asked again with the same text at the same anchor replaces the first one (a
// label drawn again on top of a highlight is one label).
//
// Sizes: no label is smaller than MIN_LABEL_PX CSS px (MIN_LABEL_PX_PRESENT in
// presentation mode, :root[data-present]); see docs/architecture.md, "Labels".
//
// The app keeps the labels of the last frame of every canvas (labelRects() below, used by
// window.wingspline.labelRects) in client pixels with their text and font size.

export const MIN_LABEL_PX = 14;
export const MIN_LABEL_PX_PRESENT = 20;
export const LABEL_MARGIN_PX = 2;
export const LABEL_LINE_HEIGHT = 1.25; // box height / font size
export const OBSTACLE_MIN_RADIUS_PX = 4; // smaller dots (beads, samples) may be under a label
export const LABEL_FONT_FAMILY = 'system-ui, "DejaVu Sans", sans-serif';

export const isPresenting = () => typeof document !== 'undefined' && document.documentElement.hasAttribute('data-present');

// The font size a side plot uses for its axis labels and legends.
export const plotFontPx = () => (isPresenting() ? MIN_LABEL_PX_PRESENT : MIN_LABEL_PX);

export const cssFont = (px, weight = 500) => `${weight} ${px}px ${LABEL_FONT_FAMILY}`;

let measureContext = null;
// Width in CSS px of `text` at `px` (one measuring context for every painter, so the canvas
// and the SVG export place labels alike). Without a canvas (node), 0.6 em per character.
export function measureText(text, px, weight = 500) {
  if (measureContext === null) {
    try {
      measureContext = typeof OffscreenCanvas !== 'undefined' ? new OffscreenCanvas(1, 1).getContext('2d')
        : typeof document !== 'undefined' ? document.createElement('canvas').getContext('2d') : false;
    } catch { measureContext = false; }
  }
  if (!measureContext) return String(text).length * px * 0.6;
  measureContext.font = cssFont(px, weight);
  return measureContext.measureText(String(text)).width;
}

// The box {x, y, w, h} of a text drawn at (x, y) with canvas align/baseline.
function boxAt(x, y, w, h, align, baseline) {
  const left = align === 'left' || align === 'start' ? x : align === 'right' || align === 'end' ? x - w : x - w / 2;
  const top = baseline === 'top' || baseline === 'hanging' ? y : baseline === 'bottom' ? y - h
    : baseline === 'alphabetic' ? y - h * 0.8 : y - h / 2;
  return { x: left, y: top, w, h };
}

const overlaps = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;

export class LabelLayout {
  constructor(width, height) {
    this.width = width;
    this.height = height;
    this.requests = [];
    this.byText = new Map(); // text -> indices into requests (the same-label test is O(1) per ask)
    this.obstacles = [];
    this.dropped = 0;
  }

  // A drawn marker (a handle, a control point: a circle of radius >= OBSTACLE_MIN_RADIUS_PX)
  // that labels keep off when they can: a label never hides the point it names.
  obstacle(cx, cy, r) {
    if (r >= OBSTACLE_MIN_RADIUS_PX) this.obstacles.push({ x: cx - r, y: cy - r, w: 2 * r, h: 2 * r });
  }

  // text at anchor (ax, ay) in screen px, drawn at (ax + dx, ay + dy) if that is free.
  // opts: { px, weight, align, baseline, dx, dy, priority, fixed, ...anything the drawer needs }
  ask(text, ax, ay, opts) {
    const key = String(text);
    const indices = this.byText.get(key) ?? [];
    const same = indices.find((i) => Math.abs(this.requests[i].ax - ax) < 0.5 && Math.abs(this.requests[i].ay - ay) < 0.5) ?? -1;
    const request = { text: key, ax, ay, opts, order: same >= 0 ? this.requests[same].order : this.requests.length };
    if (same >= 0) { this.requests[same] = request; return; }
    indices.push(this.requests.length);
    this.byText.set(key, indices);
    this.requests.push(request);
  }

  // Places every asked label: [{ text, x, y, box, opts }] with x, y where to draw it
  // (align/baseline as asked) and box the margin-free text box.
  place() {
    const m = LABEL_MARGIN_PX;
    const placed = [];
    const taken = [];
    this.dropped = 0;
    const order = [...this.requests].sort((a, b) => (b.opts.priority ?? 0) - (a.opts.priority ?? 0) || a.order - b.order);
    for (const r of order) {
      const { px, weight = 500, align = 'center', baseline = 'middle', dx = 0, dy = 0 } = r.opts;
      const w = measureText(r.text, px, weight);
      const h = px * LABEL_LINE_HEIGHT;
      const asked = boxAt(r.ax + dx, r.ay + dy, w, h, align, baseline);
      const candidates = [asked];
      if (!r.opts.fixed) {
        for (const [sx, sy] of [[-1, 1], [1, -1], [-1, -1]]) {
          if ((sx < 0 && dx === 0) || (sy < 0 && dy === 0)) continue;
          candidates.push(boxAt(r.ax + sx * dx, r.ay + sy * dy, w, h, align, baseline));
        }
        const gap = 6;
        for (const k of [1, 2, 3]) {
          const ox = k * (w / 2 + gap); const oy = k * (h / 2 + gap);
          for (const [cx, cy] of [[0, -oy], [ox, 0], [0, oy], [-ox, 0], [ox, -oy], [-ox, -oy], [ox, oy], [-ox, oy]]) {
            candidates.push({ x: r.ax + cx - w / 2, y: r.ay + cy - h / 2, w, h });
          }
        }
      }
      let chosen = null;
      // First a place off the markers too (not for a fixed label: its marker is its badge),
      // then any place off the other labels.
      for (const avoid of r.opts.fixed ? [false] : [true, false]) {
        for (const c of candidates) {
          const b = { x: c.x - m, y: c.y - m, w: c.w + 2 * m, h: c.h + 2 * m };
          if (b.x < 0 || b.y < 0 || b.x + b.w > this.width || b.y + b.h > this.height) continue;
          if (taken.some((t) => overlaps(t, b))) continue;
          if (avoid && this.obstacles.some((t) => overlaps(t, b))) continue;
          chosen = c; taken.push(b);
          break;
        }
        if (chosen) break;
      }
      if (!chosen) { this.dropped += 1; continue; }
      // Where to draw so that the text fills the chosen box, with the asked align/baseline.
      const x = align === 'left' || align === 'start' ? chosen.x : align === 'right' || align === 'end' ? chosen.x + w : chosen.x + w / 2;
      const y = baseline === 'top' || baseline === 'hanging' ? chosen.y : baseline === 'bottom' ? chosen.y + h
        : baseline === 'alphabetic' ? chosen.y + h * 0.8 : chosen.y + h / 2;
      placed.push({ text: r.text, x, y, box: chosen, opts: r.opts, anchor: [r.ax, r.ay], asked: askedDistance(r, asked), leader: leaderOf(r, chosen, asked) });
    }
    return placed;
  }
}

// A label placed farther from its anchor than it asked to be, and farther than LEADER_MIN_PX,
// gets a thin leader line from the anchor to the nearest point of its box ([x0, y0, x1, y1]).
export const LEADER_MIN_PX = 18;
const distanceToBox = (x, y, box) => {
  const nx = Math.min(Math.max(x, box.x), box.x + box.w);
  const ny = Math.min(Math.max(y, box.y), box.y + box.h);
  return [Math.hypot(nx - x, ny - y), nx, ny];
};
function leaderOf(r, box, asked) {
  const [d, nx, ny] = distanceToBox(r.ax, r.ay, box);
  return d > Math.max(LEADER_MIN_PX, distanceToBox(r.ax, r.ay, asked)[0] + 1) ? [r.ax, r.ay, nx, ny] : null;
}
const askedDistance = (r, asked) => distanceToBox(r.ax, r.ay, asked)[0];

// ---- the labels of the last frame, per canvas --------------------------------------
const frames = new Map(); // canvas element -> { labels: [{ text, box, px }], dropped }

export function recordLabels(canvas, placed, dropped = 0) {
  if (!canvas) return;
  frames.set(canvas, { labels: placed.map((p) => ({ text: p.text, box: p.box, px: p.opts.px, anchor: p.anchor, asked: p.asked, leader: !!p.leader })), dropped });
}

// Every label drawn in the last frame of every canvas on the page, in client px:
// [{ canvas (id or class), text, x, y, width, height, fontPx, anchor {x, y}, askedDistance
// (px from the anchor to the box it asked for), leader (bool), canvasRect }].
export function labelRects() {
  const out = [];
  for (const [canvas, frame] of frames) {
    if (!canvas.isConnected) { frames.delete(canvas); continue; }
    const r = canvas.getBoundingClientRect();
    if (r.width === 0 && r.height === 0) continue; // a hidden plot shows no labels
    const name = canvas.id || canvas.className;
    for (const l of frame.labels) {
      out.push({ canvas: name, text: l.text, x: r.left + l.box.x, y: r.top + l.box.y, width: l.box.w, height: l.box.h, fontPx: l.px,
        anchor: { x: r.left + l.anchor[0], y: r.top + l.anchor[1] }, askedDistance: l.asked, leader: l.leader,
        canvasRect: { x: r.left, y: r.top, width: r.width, height: r.height } });
    }
  }
  return out;
}

// A side plot's labels: ask with text(), then draw() places and paints them all with the
// 2D context g (after the plot's lines, so labels sit on top) and records them.
export function plotLabels(g, canvas, width, height) {
  const layout = new LabelLayout(width, height);
  return {
    px: plotFontPx(),
    /**
     * @param {string} string
     * @param {number} x
     * @param {number} y
     * @param {{fill?: string, align?: string, baseline?: string, dx?: number, dy?: number, weight?: number, priority?: number, fixed?: boolean, halo?: any, px?: number|null}} [style]
     */
    text(string, x, y, { fill, align = 'center', baseline = 'middle', dx = 0, dy = 0, weight = 500, priority = 0, fixed = false, halo = null, px = null } = {}) {
      layout.ask(string, x, y, { px: Math.max(px ?? plotFontPx(), plotFontPx()), weight, align, baseline, dx, dy, priority, fixed, fill, halo });
    },
    draw() {
      const placed = layout.place();
      for (const p of placed.filter((q) => q.leader)) { // leaders first: no leader crosses a text
        g.strokeStyle = p.opts.fill ?? '#000'; g.lineWidth = 1; g.setLineDash([]); g.globalAlpha = 0.7;
        g.beginPath(); g.moveTo(p.leader[0], p.leader[1]); g.lineTo(p.leader[2], p.leader[3]); g.stroke();
        g.globalAlpha = 1;
      }
      for (const p of placed) {
        g.font = cssFont(p.opts.px, p.opts.weight);
        g.textAlign = p.opts.align;
        g.textBaseline = p.opts.baseline;
        if (p.opts.halo) {
          g.lineWidth = 4; g.strokeStyle = p.opts.halo; g.lineJoin = 'round'; g.setLineDash([]);
          g.strokeText(p.text, p.x, p.y);
        }
        g.fillStyle = p.opts.fill ?? '#000';
        g.fillText(p.text, p.x, p.y);
      }
      recordLabels(canvas, placed, layout.dropped);
      return placed;
    },
  };
}
