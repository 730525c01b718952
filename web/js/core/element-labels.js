// @ts-check
// The slides' names of mesh elements: 1-based (v1, e1, F1) although the API's indices are
// 0-based; -1 (none) has no name. Every message names elements this way, as the core's do
// (vertex_label, edge_label, face_label) and as the lesson tables show them; the pages take
// these from ui/element-labels.js, which re-exports them.
// A half-edge (the half-edge view, beyond the lectures) is h1, h2, ... the same way.
const PREFIX = { vertex: 'v', edge: 'e', face: 'F', halfedge: 'h' };

/** @param {'vertex'|'edge'|'face'|'halfedge'} kind @param {number} i */
export const elementLabel = (kind, i) => (i >= 0 ? `${PREFIX[kind]}${i + 1}` : '');
