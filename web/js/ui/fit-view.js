// The view {cx, cy, zoom} that shows the box [minX, maxX] x [minY, maxY] on `canvas` with a
// margin, measured from the canvas's current layout. (stage.fit uses the size of the last
// ResizeObserver report, which on a page's first frame can still be the default 300 x 150.)
export function fitView(canvas, minX, minY, maxX, maxY, margin = 0.12) {
  const rect = canvas.getBoundingClientRect();
  const w = Math.max(maxX - minX, 1e-9);
  const h = Math.max(maxY - minY, 1e-9);
  const zoom = Math.min(rect.width / (w * (1 + 2 * margin)), rect.height / (h * (1 + 2 * margin)));
  return { cx: (minX + maxX) / 2, cy: (minY + maxY) / 2, zoom: Math.min(1e5, Math.max(1, zoom)) };
}
