// @ts-check
// A small helper canvas for the curve lessons' secondary plots (blending functions, knot
// strip, homogeneous inset): device-pixel sizing, a redraw on resize, and the pointer
// position in CSS pixels. Drawing stays with the owner; this only manages the surface.
export function createPlotCanvas(container, { className, label, height, tabIndex = null, role = 'img' }) {
  const canvas = document.createElement('canvas');
  canvas.className = className;
  canvas.setAttribute('role', role);
  canvas.setAttribute('aria-label', label);
  if (tabIndex !== null) canvas.tabIndex = tabIndex;
  if (height) canvas.dataset.height = String(height);
  container.append(canvas);
  const g = canvas.getContext('2d');
  let size = { width: 300, height: height ?? 150, dpr: 1 };
  let redraw = () => {};

  function resize() {
    const rect = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    size = { width: Math.max(1, rect.width), height: Math.max(1, rect.height), dpr };
    canvas.width = Math.round(size.width * dpr);
    canvas.height = Math.round(size.height * dpr);
    redraw();
  }
  new ResizeObserver(resize).observe(canvas);

  return {
    canvas,
    get size() { return size; },
    onRedraw(fn) { redraw = fn; },
    begin(background) {
      g.setTransform(size.dpr, 0, 0, size.dpr, 0, 0);
      g.fillStyle = background;
      g.fillRect(0, 0, size.width, size.height);
      return g;
    },
    local(event) {
      const rect = canvas.getBoundingClientRect();
      return [event.clientX - rect.left, event.clientY - rect.top];
    },
  };
}

/**
 * A side plot's labels (app/label-layout.js `plotLabels`): text() asks for a label at (x, y)
 * in CSS pixels, draw() places and paints them all after the plot's lines. A plot declares
 * its labels with this type: the style's `fill` (the text colour) is read by plotLabels but
 * not visible in the type inferred from its destructured options.
 * @typedef {{ px: number,
 *   text(string: string, x: number, y: number, style?: { fill?: string, align?: string, baseline?: string,
 *     dx?: number, dy?: number, weight?: number, priority?: number, fixed?: boolean, halo?: string, px?: number }): void,
 *   draw(): unknown[] }} PlotLabels
 */

// Dash patterns so that curves differ by more than colour (index i -> a pattern).
export const DASHES = [[], [8, 4], [2, 3], [10, 3, 2, 3], [5, 5], [1, 4], [12, 2], [6, 2, 1, 2]];
export const dashFor = (i) => DASHES[Math.floor(i / 8) % DASHES.length];
