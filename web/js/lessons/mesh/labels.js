// The slides' labels (v1, e1, F1): ui/element-labels.js, shared with the other pages.
export { vLabel, eLabel, fLabel } from '../../ui/element-labels.js';

// Numbers in tables: short, and -0 as 0.
export function num(x, digits = 4) {
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return '0';
  if (Number.isInteger(x)) return String(x);
  return String(Number(x.toPrecision(digits)));
}
