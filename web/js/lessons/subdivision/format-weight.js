// @ts-check
// How a mask's weight is written on screen.
import { formatNumber } from '../../ui/mathml.js';

// A weight as a fraction p/q when it is one (q <= 1024, within FRACTION_TOLERANCE * q: the
// core computes in doubles, so 3/8 arrives exactly and 1/9 within an ulp), else a decimal
// (Loop's beta of valence 5 involves cos(2 pi / 5)). Presentation only.
const FRACTION_TOLERANCE = 1e-12;
export function formatWeight(w) {
  for (let q = 1; q <= 1024; q += 1) {
    const p = Math.round(w * q);
    if (Math.abs(w * q - p) <= FRACTION_TOLERANCE * q) return q === 1 ? String(p) : `${p}/${q}`;
  }
  return formatNumber(w, 5);
}
