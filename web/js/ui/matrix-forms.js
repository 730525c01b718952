// @ts-check
// The three ways the lectures write a basis matrix, as a choice a lesson offers
// (state field `form`) and the words for it. The matrices themselves come from the core
// (api.segmentMatrices(curve, i, { form }).shown, api.basisMatrixRational(kind, form)).
import { h } from '../app/dom.js';

export const MATRIX_FORMS = ['descending', 'ascending', 'transposed'];

export const FORM_LABELS = {
  descending: 'Lectures 000, 003: P(u) = [u³ u² u 1] · M · G',
  ascending: 'Lecture 002: p(u) = uᵀ M g, u = (1, u, u², u³)',
  transposed: 'Lecture 001: Q(t) = G · M · T (M transposed)',
};

// Version 2 -> 3 of a lesson state: the checkbox `transposed` becomes the form it showed.
// A damaged value is passed on as the form, so the schema refuses that one field with its
// message and keeps the rest (a missing one is reset and said, like any missing field).
export function migrateTransposed(old) {
  const { transposed, ...rest } = old;
  if (transposed === undefined) return rest;
  return { ...rest, form: transposed === true ? 'transposed' : transposed === false ? 'descending' : transposed };
}

// A labelled <select> of the forms; onPick(form) when the person picks one.
export function createFormSelect(id, onPick) {
  const select = h('select', { id, onchange: (e) => onPick(e.target.value) },
    MATRIX_FORMS.map((f) => h('option', { value: f }, FORM_LABELS[f])));
  const label = h('label', { for: id, class: 'matrix-form-label' }, 'Matrix form ');
  return { select, row: h('div', { class: 'matrix-form-row' }, label, select) };
}

// The key that steps through the forms.
export const nextForm = (form) => MATRIX_FORMS[(MATRIX_FORMS.indexOf(form) + 1) % MATRIX_FORMS.length];

// Each form's own names for the cubic families, typed from the lectures:
//   003: C = M_h G_h, G_h = [P1 P4 R1 R4]; C = M_b G_b; C_i = 1/6 [...] [P_i-1 .. P_i+2];
//        000: P_k(u) = H0(u) p_k + H1(u) p_k+1 + H2(u) t_k + H3(u) t_k+1
//   002: C = M_H g, g = (p_0, p_3, p'_0, p'_3), b(u) = M_H^T u; C = M_B P; M_s with
//        (p_i-2, p_i-1, p_i, p_i+1); M_R
//   001: Q(t) = G_H M_H T, G_H = [P1 P4 R1 R4]; G_B = [P1 P2 P3 P4], B_B = M_B T;
//        G_Bs_i = [P_i-3 P_i-2 P_i-1 P_i] (001 prints no Catmull-Rom)
// Keys are the core's segment bases; a label "X_{sub}" is typeset with its subscript.
const P1234 = ['P_1', 'P_2', 'P_3', 'P_4'];
const HERMITE_ROWS = ['P_1', 'P_4', 'R_1', 'R_4'];
const P_AROUND = ['P_{i−1}', 'P_i', 'P_{i+1}', 'P_{i+2}'];
const p0123 = ['p_0', 'p_1', 'p_2', 'p_3'];
export const LECTURE_NAMES = {
  descending: {
    lecture: '003',
    hermite: { M: 'M_h', G: 'G_h', rows: HERMITE_ROWS, blending: ['H_0', 'H_1', 'H_2', 'H_3'], blendingLecture: '000' },
    bezier: { M: 'M_b', G: 'G_b', rows: P1234 },
    bspline: { M: 'M', G: 'G', rows: P_AROUND },
    'catmull-rom': { M: 'M', G: 'G', rows: P_AROUND },
  },
  ascending: {
    lecture: '002',
    hermite: { M: 'M_H', G: 'g', rows: ['p_0', 'p_3', 'p′_0', 'p′_3'], blending: 'b' },
    bezier: { M: 'M_B', G: 'P', rows: p0123, blending: 'b' },
    bspline: { M: 'M_s', G: 'p', rows: ['p_{i−2}', 'p_{i−1}', 'p_i', 'p_{i+1}'], blending: 'b' },
    'catmull-rom': { M: 'M_R', G: 'P', rows: p0123 },
  },
  transposed: {
    lecture: '001',
    hermite: { M: 'M_H', G: 'G_H', rows: HERMITE_ROWS },
    bezier: { M: 'M_B', G: 'G_B', rows: P1234, blending: 'B_B' },
    bspline: { M: 'M_{Bs}', G: 'G_{Bs}', rows: ['P_{i−3}', 'P_{i−2}', 'P_{i−1}', 'P_i'] },
  },
};

// The names of `form` for a basis, or null when the lecture of that form has none (a
// Bezier curve of another degree, a non-uniform B-spline, a cardinal spline, ...).
export function lectureNames(form, basis) {
  const table = LECTURE_NAMES[form];
  const names = table?.[basis];
  return names ? { lecture: table.lecture, ...names } : null;
}
