// Issue 18: the three ways the lectures write a basis matrix, as a choice a lesson offers
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
// Anything but a boolean there is a damaged link: refused (share-link.js says so).
export function migrateTransposed(old) {
  const { transposed, ...rest } = old;
  if (typeof transposed !== 'boolean') throw new TypeError('transposed must be true or false');
  return { ...rest, form: transposed ? 'transposed' : 'descending' };
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
