// The slides' names of mesh elements: 1-based on screen (v1, e1, F1) although the core's
// indices are 0-based; -1 (none: a boundary side) has no name. One place for every page:
// the mesh and subdivision lessons and the exercises' tables.
const PREFIX = { vertex: 'v', edge: 'e', face: 'F' };

/** @param {'vertex'|'edge'|'face'} kind @param {number} i */
export const elementLabel = (kind, i) => (i >= 0 ? `${PREFIX[kind]}${i + 1}` : '');
export const vLabel = (i) => elementLabel('vertex', i);
export const eLabel = (i) => elementLabel('edge', i);
export const fLabel = (i) => elementLabel('face', i);
