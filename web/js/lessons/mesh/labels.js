// @ts-check
// The slides' labels (v1, e1, F1): ui/element-labels.js, shared with the other pages.
export { vLabel, eLabel, fLabel } from '../../ui/element-labels.js';
