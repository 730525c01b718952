// @ts-check
// Lecture 002's Bezier subdivision matrices G_B^L and G_B^R, shown beside the matrix form of a
// cubic Bezier curve. The fraction and the integers come from the core
// (bezierSubdivisionMatrices(3, 1/2): the de Casteljau split at u = 1/2 written as matrices);
// this module only typesets them.
import { h } from '../../app/dom.js';
import { math, el, mi, mo, mn } from '../../ui/mathml.js';

export function createSubdivisionMatrices(container, api) {
  const split = api.bezierSubdivisionMatrices(3, 0.5);
  const root = h('div', { class: 'subdivision-matrices', id: 'subdivision-matrices' },
    h('p', { class: 'matrix-heading' }, 'Lecture 002: subdividing the cubic Bezier at u = 1/2'),
    h('p', { class: 'hint' }, 'The de Casteljau construction at u = 1/2: the left half\'s control points are the first point of every level '
      + '(P0, the midpoint of P0 P1, ...), the right half\'s the last point of every level. Written as matrices acting on P0..P3:'),
    formula('L', split.leftRational), formula('R', split.rightRational));
  container.append(root);
  return {
    element: root,
    update(state) {
      root.hidden = !(state.family === 'bezier' && state.points.length === 4);
    },
  };
}

function formula(side, rational) {
  const n = Math.round(Math.sqrt(rational.numerators.length));
  const table = el('mtable');
  for (let i = 0; i < n; i += 1) {
    table.append(el('mtr', ...Array.from({ length: n }, (_, j) => el('mtd', mn(String(rational.numerators[n * i + j]))))));
  }
  const points = el('mtable', ...Array.from({ length: n }, (_, i) => el('mtr', el('mtd', el('msub', mi('P'), mn(String(i)))))));
  const node = math(el('msubsup', mi('G'), mi('B'), mi(side)), mo('='),
    el('mfrac', mn('1'), mn(String(rational.denominator))),
    el('mrow', mo('('), table, mo(')')), el('mrow', mo('('), points, mo(')')));
  node.setAttribute('data-split', side);
  return node;
}
