// @ts-check
// The slides' names of mesh elements: 1-based on screen (v1, e1, F1) although the core's
// indices are 0-based; -1 (none) has no name. One place for every page (the mesh and
// subdivision lessons and the exercises' tables) and for the API's own messages: defined
// in core/element-labels.js, which the JS API uses too.
import { elementLabel } from '../core/element-labels.js';

export { elementLabel };
export const vLabel = (i) => elementLabel('vertex', i);
export const eLabel = (i) => elementLabel('edge', i);
export const fLabel = (i) => elementLabel('face', i);
