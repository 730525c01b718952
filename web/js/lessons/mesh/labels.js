// The slides' labels: 1-based on screen (v1, e1, F1) although the core's indices are
// 0-based; -1 (none: a boundary side) is shown as an empty cell, as on the slide.
export const vLabel = (i) => (i >= 0 ? `v${i + 1}` : '');
export const eLabel = (i) => (i >= 0 ? `e${i + 1}` : '');
export const fLabel = (i) => (i >= 0 ? `F${i + 1}` : '');

// Numbers in tables: short, and -0 as 0.
export function num(x, digits = 4) {
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return '0';
  if (Number.isInteger(x)) return String(x);
  return String(Number(x.toPrecision(digits)));
}
