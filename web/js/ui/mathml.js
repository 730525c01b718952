// @ts-check
// MathML built with DOM calls (never from strings), so numbers and names are always text.
const NS = 'http://www.w3.org/1998/Math/MathML';

export function el(tag, ...children) {
  const node = document.createElementNS(NS, tag);
  for (const child of children) {
    node.append(typeof child === 'string' ? document.createTextNode(child) : child);
  }
  return node;
}

export const mi = (text) => el('mi', text);
export const mo = (text) => el('mo', text);
export const mn = (text) => el('mn', text);
// A bracket that keeps the height of a row (the parentheses of P(u) and of a row
// vector must not stretch to the height of a matrix beside them; matrix brackets still do).
export const fixedMo = (text) => {
  const node = mo(text);
  node.setAttribute('stretchy', 'false');
  return node;
};

// Formats a number for display: integers plainly, others with up to `digits` significant
// digits, and -0 as 0.
export function formatNumber(x, digits = 4) {
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return '0';
  if (Number.isInteger(x)) return String(x);
  return String(Number(x.toPrecision(digits)));
}

// A bracketed matrix; `rows` is an array of arrays of numbers or strings.
export function matrix(rows, { digits = 4 } = {}) {
  const table = el('mtable');
  for (const row of rows) {
    const tr = el('mtr');
    for (const cell of row) {
      tr.append(el('mtd', typeof cell === 'number' ? mn(formatNumber(cell, digits)) : mi(String(cell))));
    }
    table.append(tr);
  }
  return bracketed(table, rows.length);
}

// [table] with brackets that stretch for a column or a matrix and keep the height of a row
// for a row vector (a one-row matrix's brackets no taller than a row).
export function bracketed(table, rowCount, open = '[', close = ']') {
  const b = rowCount === 1 ? fixedMo : mo;
  return el('mrow', b(open), table, b(close));
}

export function math(...children) {
  const node = el('math', ...children);
  node.setAttribute('display', 'block');
  return node;
}

// A formula inside a sentence (no display=block): C^(p-m) in a caption is a superscript.
export function inlineMath(...children) {
  return el('math', ...children);
}
// C^(sup) with the superscript written as a row of names and signs, e.g. 'p−m', 'k'.
export function continuityClass(letter, sup) {
  const parts = sup.split(/([−+-])/).filter(Boolean).map((t) => (/^[−+-]$/.test(t) ? mo(t === '-' ? '−' : t) : /^\d+$/.test(t) ? mn(t) : mi(t)));
  return inlineMath(el('msup', mi(letter), parts.length === 1 ? parts[0] : el('mrow', ...parts)));
}

// Splits a row-major 4x4 Float64Array into rows.
export function rows4(m) {
  return [0, 1, 2, 3].map((r) => Array.from(m.slice(4 * r, 4 * r + 4)));
}
