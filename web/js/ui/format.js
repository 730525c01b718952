// @ts-check
// Number formats shared by the lesson panels and plots (on top of mathml.js formatNumber).
import { formatNumber } from './mathml.js';

// Three significant digits, for axis labels and knot values on small plots.
export const formatShort = (x) => String(Number(x.toPrecision(3)));

// A size (distance, error, weight) that keeps tiny values visible: 1.1e-16, never 0 unless
// it is exactly 0.
export const formatSize = (x) => (x === 0 ? '0' : Math.abs(x) < 1e-3 ? x.toExponential(1) : formatNumber(x, 3));

// (x, y) with `digits` significant digits.
export const formatVector = (v, digits = 3) => `(${v.map((c) => formatNumber(c, digits)).join(', ')})`;
