// @ts-check
// The matrix form of one curve segment as MathML, with the numbers the core multiplies
// with (STYLE.md 12: the matrix shown is the matrix used), in the form a lecture writes it
// (the core gives M, G, C in that form, segmentMatrices(..., { form }).shown):
//   'descending' (lectures 000, 003, 004): P(u) = [u^3 u^2 u 1] . M . G, C = M . G
//   'ascending'  (lecture 002):            p(u) = u^T M g, u = (1, u, u^2, u^3), C = M g
//   'transposed' (lecture 001):            Q(t) = G . M . T, G a row of points, T a column
// Reusable: give it what api.segmentMatrices returns ({M, G, C, shown, labels, degree,
// columns, homogeneous, start, end, localParameter}) and the parameter.
//
//   const panel = createMatrixPanel(container);
//   panel.update({ segment, u, point, form, title, notation });
// notation 'fraction' writes M as the slides do, (1/d) . [integers], with the
// fraction and the integers the core gives (shown.rational); 'decimal' (the default) writes
// the entries as decimals. A matrix without a small common denominator stays in decimals
// and the note says so.
import { math, mi, mo, mn, el, fixedMo, bracketed, formatNumber } from './mathml.js';

export const MATRIX_DIGITS = 4;

export function createMatrixPanel(container) {
  const root = document.createElement('div');
  root.className = 'matrix-panel';
  root.setAttribute('aria-live', 'off');
  // Wide matrices (degree 7, the projector's large type) scroll sideways: the panel is the
  // one scroll container, focusable so the keyboard can scroll it too.
  root.tabIndex = 0;
  root.setAttribute('role', 'region');
  root.setAttribute('aria-label', 'Matrix form of the current segment (scrolls sideways when wide)');
  container.append(root);
  // The MathML is built once per shape (degree, columns, row names, form) and then only its
  // number text nodes change, and only when the shown text changes: dragging a point
  // rewrites a few dozen strings instead of rebuilding some hundred elements per move.
  let shape = null;
  let cells = null;

  function build({ segment, form, title, fraction, names }) {
    const p = segment.degree;
    const n = p + 1;
    const transposed = form === 'transposed';
    const ascending = form === 'ascending';
    const name = transposed ? 't' : 'u';
    // Lecture 002 writes p and g in lower case; 000/001/003 write P (Q for 001) and G.
    const curve = transposed ? 'Q' : ascending ? 'p' : 'P';
    const geo = ascending ? 'g' : 'G';
    const call = (arg) => [mi(curve), fixedMo('('), arg, fixedMo(')')];
    const heading = document.createElement('p');
    heading.className = 'matrix-heading';
    heading.textContent = title;
    const slots = { M: [], G: [], C: [], t: null, x: null, y: null, denominators: [] };
    // A matrix of numbers whose text nodes land in slots[key] (row-major of the shown form).
    const numbers = (key, r, c, role) => {
      const out = [];
      const table = el('mtable');
      for (let i = 0; i < r; i += 1) {
        const tr = el('mtr');
        for (let j = 0; j < c; j += 1) {
          const text = document.createTextNode('');
          out.push(text);
          tr.append(el('mtd', el('mn', text)));
        }
        table.append(tr);
      }
      slots[key].push(out);
      const inBrackets = tag(ascending ? bracketed(table, r, '(', ')') : bracketed(table, r), role);
      if (key !== 'M' || !fraction) return inBrackets;
      // The slide's common factor in front: 1/d typeset as a fraction (d filled by update).
      const d = document.createTextNode('');
      slots.denominators.push(d);
      return el('mrow', tag(el('mfrac', mn('1'), el('mn', d)), 'M-fraction'), inBrackets);
    };
    // The powers of the parameter: descending u^p .. u 1 (000, 001, 003), ascending
    // 1 u .. u^p (002).
    const powers = () => {
      const out = [];
      for (let k = 0; k <= p; k += 1) {
        const r = ascending ? k : p - k;
        out.push(r === 0 ? mn('1') : r === 1 ? mi(name) : el('msup', mi(name), mn(String(r))));
      }
      return out;
    };
    // A row vector keeps the height of a row; a column vector's brackets stretch.
    const powerRow = () => bracketed(el('mtable', el('mtr', ...powers().map((x) => el('mtd', x)))), 1);
    const powerColumn = () => bracketed(el('mtable', ...powers().map((x) => el('mtr', el('mtd', x)))), n);
    const shown = segment.shown;
    const [gr, gc] = [shown.geometryRows, shown.geometryColumns];
    const labelColumn = segment.labels.map((l) => [l]);
    const uT = () => el('msup', mi(name), mi('T'));
    const dot = () => mo('·');

    const symbolic = math(transposed
      ? el('mrow', ...call(mi('t')), mo('='), mi('G'), dot(), mi('M'), dot(), mi('T'))
      : ascending
        ? el('mrow', ...call(mi('u')), mo('='), uT(), mi('C'), mo('='), uT(), mi('M'), mi('g'), mo(','), mspace(),
          uT(), mo('='), powerRow())
        : el('mrow', ...call(mi('u')), mo('='), powerRow(), dot(), mi('M'), dot(), mi('G')));
    const named = names ? lectureLine(names, form, name, powerRow) : null;
    const geometry = math(el('mrow', mi(geo), mo('='), tag(labelMatrix(transposed ? transpose(labelColumn) : labelColumn, ascending), 'G-labels'), mo('='), numbers('G', gr, gc, 'G')));
    // The product in three pieces that wrap (site.css .formula-pieces): a degree-3 product in
    // decimals is 650 px wide, more than a projector's side column.
    const product = document.createElement('div');
    product.className = 'formula-pieces matrix-product';
    product.append(...(transposed
      ? [math(el('mrow', ...call(mi('t')), mo('='), numbers('G', gr, gc, 'G'), dot())), math(el('mrow', numbers('M', n, n, 'M'), dot())), math(powerColumn())]
      : [math(el('mrow', ...call(mi('u')), mo('='), powerRow(), dot())), math(el('mrow', numbers('M', n, n, 'M'), dot())), math(numbers('G', gr, gc, 'G'))]));
    const coefficients = math(transposed
      ? el('mrow', mi('G'), dot(), mi('M'), mo('='), numbers('C', gr, gc, 'C'))
      : el('mrow', mi('C'), mo('='), mi('M'), dot(), mi(geo), mo('='), numbers('C', gr, gc, 'C')));
    slots.t = document.createTextNode('');
    slots.x = document.createTextNode('');
    slots.y = document.createTextNode('');
    const value = math(el('mrow', ...call(el('mn', slots.t)), mo('='),
      fixedMo('('), el('mn', slots.x), mo(','), el('mn', slots.y), fixedMo(')')));
    const note = document.createElement('p');
    note.className = 'hint';
    slots.note = document.createTextNode('');
    note.append(slots.note);
    root.replaceChildren(...[heading, symbolic, named, geometry, product, coefficients, value, note].filter(Boolean));
    root.dataset.form = form;
    root.dataset.notation = fraction ? 'fraction' : 'decimal';
    return slots;
  }

  // Writes a row-major matrix, already in the shown form (the core's), into every copy of
  // its slots.
  function fill(list, flat, digits = MATRIX_DIGITS) {
    for (const texts of list) texts.forEach((text, k) => setText(text, formatNumber(flat[k], digits)));
  }

  // names: the lecture's own names for this segment (matrix-forms.js lectureNames), or null.
  function update({ segment, u, point, form = 'descending', title = '', notation = 'decimal', names = null }) {
    const p = segment.degree;
    const shown = segment.shown;
    if (!shown || shown.form !== form) throw new Error(`matrix panel: the segment was asked for in the ${shown?.form} form, not ${form}`);
    const transposed = form === 'transposed';
    // Fractions when asked for and the core found the slide's form; a denominator of 1 is
    // a matrix of integers, written without a factor as the slides do (Bezier, Hermite).
    const rational = notation === 'fraction' ? shown.rational ?? null : null;
    const fraction = rational !== null && rational.denominator !== 1;
    const key = JSON.stringify([p, shown.geometryRows, shown.geometryColumns, form, title, Array.from(segment.labels), fraction, names]);
    if (key !== shape) {
      shape = key;
      cells = build({ segment, form, title, fraction, names });
    }
    if (rational) {
      // Integers: every digit is shown, never rounded to MATRIX_DIGITS significant ones.
      fill(cells.M, rational.numerators, 17);
      for (const d of cells.denominators) setText(d, String(rational.denominator));
    } else fill(cells.M, shown.M);
    fill(cells.G, shown.G);
    fill(cells.C, shown.C);
    const local = segment.localParameter === false ? u : (u - segment.start) / ((segment.end - segment.start) || 1);
    const t = Math.min(1, Math.max(0, local));
    const name = transposed ? 't' : 'u';
    setText(cells.t, formatNumber(t, MATRIX_DIGITS));
    setText(cells.x, formatNumber(point[0], MATRIX_DIGITS));
    setText(cells.y, formatNumber(point[1], MATRIX_DIGITS));
    const range = `segment ${segment.segment + 1} of ${segment.segmentCount}, curve parameter ${formatNumber(segment.start)} to ${formatNumber(segment.end)}`;
    const decimals = notation === 'fraction' && !rational ? ' The entries of M are not fractions with a small common denominator here (uneven knots or tension), so M is shown in decimals.' : '';
    setText(cells.note, (segment.homogeneous
      ? `${range}; G holds the homogeneous points (w x, w y, w): divide by the last column to get the point.`
      : segment.localParameter === false ? `${range}; ${name} is the curve parameter itself.` : `${range}; local ${name} = ${formatNumber(t, MATRIX_DIGITS)}.`) + decimals);
  }

  return { element: root, update };
}

function setText(node, text) {
  if (node.data !== text) node.data = text;
}

// The slide's row names ("P_0", "t_k+1") with their subscripts typeset; lecture 002 writes
// its vectors in round brackets.
function labelMatrix(cells, round = false) {
  const table = el('mtable');
  for (const row of cells) table.append(el('mtr', ...row.map((text) => el('mtd', labelNode(String(text))))));
  return round ? bracketed(table, cells.length, '(', ')') : bracketed(table, cells.length);
}

// The form's formula in its lecture's names: 003 C = M_h G_h, G_h = [P_1 ..]
// and 000's H_0..H_3; 002 C = M_H g, g = (p_0, ..), b(u) = M_H^T u; 001 Q(t) = G_H M_H T.
function lectureLine(names, form, name, powerRow) {
  const sub = (text) => labelNode(text);
  const rows = names.rows.map((r) => [r]);
  const lines = [];
  if (form === 'transposed') {
    lines.push([mi('Q'), fixedMo('('), mi('t'), fixedMo(')'), mo('='), sub(names.G), mo('·'), sub(names.M), mo('·'), mi('T'), mo(','), mspace(),
      sub(names.G), mo('='), labelMatrix(transpose(rows))]);
    if (names.blending) lines.push([sub(names.blending), mo('='), sub(names.M), mo('·'), mi('T')]);
  } else {
    const ascending = form === 'ascending';
    lines.push([mi('C'), mo('='), sub(names.M), sub(names.G), mo(','), mspace(), sub(names.G), mo('='), labelMatrix(rows, ascending)]);
    if (ascending && names.blending) {
      lines.push([mi(names.blending), fixedMo('('), mi(name), fixedMo(')'), mo('='), el('msup', sub(names.M), mi('T')), mi(name)]);
    } else if (Array.isArray(names.blending)) {
      const row = el('mtable', el('mtr', ...names.blending.map((b) => el('mtd', el('mrow', sub(b), fixedMo('('), mi(name), fixedMo(')'))))));
      lines.push([bracketed(row, 1), mo('='), powerRow(), mo('·'), sub(names.M)]);
    }
  }
  // Each line its own block formula, so a narrow panel wraps between them.
  const box = document.createElement('div');
  box.className = 'lecture-names';
  box.dataset.role = 'lecture-names';
  box.dataset.lecture = names.lecture;
  const where = document.createElement('p');
  where.className = 'hint lecture-note';
  where.textContent = `In lecture ${names.lecture}'s names${names.blendingLecture ? ` (the blending functions as lecture ${names.blendingLecture} names them)` : ''}:`;
  box.append(where, ...lines.map((parts) => math(el('mrow', ...parts))));
  return box;
}

function mspace() {
  const node = el('mspace');
  node.setAttribute('width', '1em');
  return node;
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

function transpose(m) {
  return m[0].map((_, j) => m.map((row) => row[j]));
}
