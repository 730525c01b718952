// The matrix form of one curve segment as MathML, with the numbers the core multiplies
// with (STYLE.md 12: the matrix shown is the matrix used):
//   lectures 000, 003, 004:  P(u) = [u^3 u^2 u 1] . M . G = [u^3 u^2 u 1] . C
//   lecture 001:             Q(t) = G . M . T, G a row of points, M transposed, T a column
// Reusable: give it what api.segmentMatrices returns ({M, G, C, labels, degree, columns,
// homogeneous, start, end, localParameter}) and the parameter.
//
//   const panel = createMatrixPanel(container);
//   panel.update({ segment, u, point, transposed, title });
import { math, matrix, mi, mo, mn, el, formatNumber } from '../../ui/mathml.js';

export const MATRIX_DIGITS = 4;

export function createMatrixPanel(container) {
  const root = document.createElement('div');
  root.className = 'matrix-panel';
  root.setAttribute('aria-live', 'off');
  container.append(root);

  function update({ segment, u, point, transposed = false, title = '' }) {
    const p = segment.degree;
    const n = p + 1;
    const cols = segment.columns;
    const M = rows(segment.M, n, n);
    const G = rows(segment.G, n, cols);
    const C = rows(segment.C, n, cols);
    const local = segment.localParameter === false ? u : (u - segment.start) / ((segment.end - segment.start) || 1);
    const t = Math.min(1, Math.max(0, local));
    const name = transposed ? 't' : 'u';
    const labelColumn = segment.labels.map((l) => [l]);
    const heading = document.createElement('p');
    heading.className = 'matrix-heading';
    heading.textContent = title;

    // Fresh nodes for every use: a DOM node lives in one place only.
    const powers = () => {
      const out = [];
      for (let r = p; r >= 0; r -= 1) out.push(r === 0 ? mn('1') : r === 1 ? mi(name) : el('msup', mi(name), mn(String(r))));
      return out;
    };
    const powerRow = el('mrow', mo('['), el('mtable', el('mtr', ...powers().map((x) => el('mtd', x)))), mo(']'));
    const powerColumn = el('mrow', mo('['), el('mtable', ...powers().map((x) => el('mtr', el('mtd', x)))), mo(']'));

    const symbolic = math(transposed
      ? el('mrow', mi('Q'), mo('('), mi('t'), mo(')'), mo('='), mi('G'), mo('·'), mi('M'), mo('·'), mi('T'))
      : el('mrow', mi('P'), mo('('), mi('u'), mo(')'), mo('='), powerRow, mo('·'), mi('M'), mo('·'), mi('G')));

    const gNamed = tag(labelMatrix(transposed ? transpose(labelColumn) : labelColumn), 'G-labels');
    const gNumbers = tag(matrix(transposed ? transpose(G) : G, { digits: MATRIX_DIGITS }), 'G');
    const mNumbers = tag(matrix(transposed ? transpose(M) : M, { digits: MATRIX_DIGITS }), 'M');
    const cNumbers = tag(matrix(transposed ? transpose(C) : C, { digits: MATRIX_DIGITS }), 'C');
    const geometry = math(el('mrow', mi('G'), mo('='), gNamed, mo('='), gNumbers));
    const product = math(transposed
      ? el('mrow', mi('Q'), mo('('), mi('t'), mo(')'), mo('='), gNumbers.cloneNode(true), mo('·'), mNumbers, mo('·'), powerColumn)
      : el('mrow', mi('P'), mo('('), mi('u'), mo(')'), mo('='), powerRow.cloneNode(true), mo('·'), mNumbers, mo('·'), gNumbers.cloneNode(true)));
    const coefficients = math(transposed
      ? el('mrow', mi('G'), mo('·'), mi('M'), mo('='), cNumbers)
      : el('mrow', mi('C'), mo('='), mi('M'), mo('·'), mi('G'), mo('='), cNumbers));
    const value = math(el('mrow', mi(transposed ? 'Q' : 'P'), mo('('), mn(formatNumber(t, MATRIX_DIGITS)), mo(')'), mo('='),
      mo('('), mn(formatNumber(point[0], MATRIX_DIGITS)), mo(','), mn(formatNumber(point[1], MATRIX_DIGITS)), mo(')')));

    const note = document.createElement('p');
    note.className = 'hint';
    const range = `segment ${segment.segment + 1} of ${segment.segmentCount}, curve parameter ${formatNumber(segment.start)} to ${formatNumber(segment.end)}`;
    note.textContent = segment.homogeneous
      ? `${range}; G holds the homogeneous points (w x, w y, w): divide by the last column to get the point.`
      : segment.localParameter === false ? `${range}; ${name} is the curve parameter itself.` : `${range}; local ${name} = ${formatNumber(t, MATRIX_DIGITS)}.`;
    root.replaceChildren(heading, symbolic, geometry, product, coefficients, value, note);
    root.dataset.form = transposed ? 'GMT' : 'TMG';
  }

  return { element: root, update };
}

// The slide's row names ("P_0", "t_k+1") with their subscripts typeset.
function labelMatrix(cells) {
  const table = el('mtable');
  for (const row of cells) table.append(el('mtr', ...row.map((text) => el('mtd', labelNode(String(text))))));
  return el('mrow', mo('['), table, mo(']'));
}

function labelNode(text) {
  const cut = text.indexOf('_');
  if (cut <= 0) return mi(text);
  return el('msub', mi(text.slice(0, cut)), el('mrow', mi(text.slice(cut + 1).replace(/[{}]/g, ''))));
}

function tag(node, role) {
  node.setAttribute('data-matrix', role);
  return node;
}

function rows(flat, r, c) {
  const out = [];
  for (let i = 0; i < r; i += 1) out.push(Array.from(flat.slice(c * i, c * i + c)));
  return out;
}

function transpose(m) {
  return m[0].map((_, j) => m.map((row) => row[j]));
}
