// @ts-check
// The derivation of each cubic family's matrix, computed by the core in exact
// fractions (api.cubicDerivation), with live numbers from the first segment P0..P3 of the
// lab's polygon (the lecture's P1..P4): Hermite's constraints and M_H = C^-1; Bezier from
// Hermite with R1 = 3(P2 - P1), R4 = 3(P4 - P3); the uniform B-spline from its C2 conditions.
import { h, panel, setChildren } from '../../app/dom.js';
import { math, matrix } from '../../ui/mathml.js';
import { formatVector } from '../../ui/format.js';

const fraction = (m, i) => (m.den[i] === 1 ? String(m.num[i]) : `${m.num[i]}/${m.den[i]}`);
const fractionRows = (m) => Array.from({ length: m.rows }, (_, r) => Array.from({ length: m.cols }, (_, c) => fraction(m, m.cols * r + c)));

// The core's part: the three derivations (fixed) and, for the live numbers, the Hermite
// geometry of the first Bezier segment (convertBasis: G_H = M_H^-1 M_B G_B).
export function computeDerivations(api, points) {
  const g = points.slice(0, 4).flat();
  const hermite = api.convertBasis(g, 2, 'bezier', 'hermite');
  return {
    hermite: api.cubicDerivation('hermite'),
    bezier: api.cubicDerivation('bezier'),
    bspline: api.cubicDerivation('bspline'),
    live: { P: points.slice(0, 4), R1: [hermite[4], hermite[5]], R4: [hermite[6], hermite[7]] },
  };
}

export function createDerivationPanel(panels) {
  const body = panel(panels, { id: 'derivation-panel', title: 'Deriving the matrices (lectures 000, 002, 003)', open: false });
  function update(d) {
    const { P, R1, R4 } = d.live;
    setChildren(body,
      h('section', { class: 'derivation', 'data-family': 'hermite' },
        h('h3', {}, 'Hermite: four constraints'),
        h('p', {}, 'P(u) = [u³ u² u 1] [a b c d]ᵀ must satisfy ', d.hermite.conditions.join(', '), ': C [a b c d]ᵀ = [P1 P4 R1 R4]ᵀ with'),
        math(matrix(fractionRows(d.hermite.constraint))),
        h('p', {}, 'so M_H = C⁻¹ (C M_H = I, exact):'),
        math(matrix(fractionRows(d.hermite.basis)))),
      h('section', { class: 'derivation', 'data-family': 'bezier' },
        h('h3', {}, 'Bezier from Hermite'),
        h('p', { class: 'live', id: 'derivation-live' },
          `R1 = 3(P2 − P1) = 3(${formatVector(P[1])} − ${formatVector(P[0])}) = ${formatVector(R1)}; `,
          `R4 = 3(P4 − P3) = 3(${formatVector(P[3])} − ${formatVector(P[2])}) = ${formatVector(R4)} (this lab's P0..P3 are the lecture's P1..P4).`),
        h('p', {}, '[P1 P4 R1 R4]ᵀ = S [P1 P2 P3 P4]ᵀ with S ='),
        math(matrix(fractionRows(d.bezier.substitution))),
        h('p', {}, 'and M_B = M_H S ='),
        math(matrix(fractionRows(d.bezier.basis)))),
      h('section', { class: 'derivation', 'data-family': 'bspline' },
        h('h3', {}, 'Uniform B-spline from C2'),
        h('p', {}, 'The blending functions b0..b3 of a segment are unknown cubics (16 coefficients). Each point\'s blending function is C2 where it enters and leaves its four segments, and they sum to 1:'),
        h('ul', { class: 'conditions' }, d.bspline.conditions.map((c) => h('li', {}, c))),
        h('p', {}, 'Solved exactly, M_BS ='),
        math(matrix(fractionRows(d.bspline.basis)))),
    );
  }
  return { update };
}
