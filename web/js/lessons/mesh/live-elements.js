// @ts-check
// Which elements of the mesh on screen exist, and what becomes of the lesson's references
// to elements when the mesh changes (another mesh chosen, undo, redo, an import, a link, an
// edit that removes an element). The hovered and picked element live in the lesson view
// (lesson.js setup); the walk's and the query's elements live in the state. After every
// compute a reference to an element that no longer exists is dropped (the pick and the
// hover), or the element is clamped to the mesh or said to be gone (the walk, the query),
// so no panel asks the core about an element it does not have. No DOM here.
import { elementLabel } from '../../ui/element-labels.js';

const KIND_COUNT = { vertex: 'V', edge: 'E', face: 'F' };
const GAP_LIST = { vertex: 'vertices', edge: 'edges', face: 'faces' };
const PLURAL = { vertex: 'vertices', edge: 'edges', face: 'faces' };

// Whether the element ({kind, index}) is one of the model's: a number of its table that is
// not a gap an edit left (a removed element keeps its number until Compact numbering).
export function exists(model, element) {
  if (!model || !element || !Object.prototype.hasOwnProperty.call(KIND_COUNT, element.kind)) return false;
  const { kind, index } = element;
  if (!Number.isInteger(index) || index < 0 || index >= model[KIND_COUNT[kind]]) return false;
  return !isGap(model, kind, index);
}

// Whether the element's number is a gap an edit left in the model's tables.
export function isGap(model, kind, index) {
  return Boolean(model.gapLists?.[GAP_LIST[kind]]?.includes(index));
}

// Why an element is not one of the model's, in a sentence a student reads ("F6 is not in
// this mesh: it has faces F1 to F4"), or null when it is.
export function whyNot(model, element) {
  if (exists(model, element)) return null;
  const label = elementLabel(element.kind, element.index);
  if (isGap(model, element.kind, element.index)) return `${label} was removed by an edit (its number stays a gap until Compact numbering)`;
  const n = model[KIND_COUNT[element.kind]];
  return `${label} is not in this mesh: it has ${PLURAL[element.kind]} ${elementLabel(element.kind, 0)} to ${elementLabel(element.kind, n - 1)}`;
}

// Drops the view's hovered and picked element when the model does not have them. A dropped
// pick is remembered as `gone` with the topology it was dropped at, so the edit panel can
// say what happened to it while that mesh is shown.
export function dropStale(selection, model) {
  if (!selection) return;
  if (selection.hover && !exists(model, selection.hover)) selection.hover = null;
  if (selection.pick && !exists(model, selection.pick)) {
    selection.gone = { ...selection.pick, topology: model.topology, reason: whyNot(model, selection.pick) };
    selection.pick = null;
  }
}

// What the edit panel says about a pick that was dropped, while the mesh it was dropped
// for is shown (null otherwise).
export function goneNote(selection, model) {
  const gone = selection?.gone;
  return gone && !selection.pick && gone.topology === model.topology ? gone.reason : null;
}

// The element a query of the state asks about ({kind: 'vertex'|'face'|'edge', index}),
// clamped into the mesh's numbers, with `removed` set when that number is a gap.
export function queryTarget(model, query, kind) {
  const count = model[KIND_COUNT[kind]];
  const index = Math.max(0, Math.min(query[kind], count - 1));
  return { kind, index, removed: isGap(model, kind, index) };
}

// The corner choice of "split face" kept when the face still has those corners: the value
// given if it is one of `corners`, else the default.
export const keptCorner = (value, corners, fallback) => (corners.includes(value) ? value : fallback);
