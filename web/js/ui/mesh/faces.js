// @ts-check
// The faces of a mesh model as the drawing, the label plan and picking read them: CSR
// (model.faceOffsets, model.faceVertices; face f's corners are cornersOf(model, f), a removed
// face has none) over the projected positions P (P[3*v + k]: view-plane x, y and depth).
// Offers: faceCount, cornersOf, hasCorners, faceXY, facesViewer, frontFacing, edgeSeen.
// Needs: a model with faceOffsets, faceVertices, mode3d and (edgeSeen) weShown.edges
//   (the winged-edge records, edges[8*e + k]: S, E, L, R, ...).

export const faceCount = (model) => model.faceOffsets.length - 1;
export const cornersOf = (model, f) => model.faceVertices.subarray(model.faceOffsets[f], model.faceOffsets[f + 1]);
export const hasCorners = (model, f) => model.faceOffsets[f + 1] > model.faceOffsets[f];

// Face f's corners in the view plane, as a polygon for the painter (x0, y0, x1, y1, ...).
export function faceXY(model, P, f) {
  const a = model.faceOffsets[f]; const b = model.faceOffsets[f + 1];
  const xy = new Float64Array(2 * (b - a));
  for (let k = a; k < b; k += 1) { const v = model.faceVertices[k]; xy[2 * (k - a)] = P[3 * v]; xy[2 * (k - a) + 1] = P[3 * v + 1]; }
  return xy;
}

// Whether face f's projected corners run counter-clockwise, that is whether it faces the
// viewer (faces are CCW seen from outside).
export function facesViewer(model, P, f) {
  const a = model.faceOffsets[f]; const b = model.faceOffsets[f + 1];
  let area = 0;
  for (let k = a, j = b - 1; k < b; j = k, k += 1) {
    const p = model.faceVertices[j]; const q = model.faceVertices[k];
    area += P[3 * p] * P[3 * q + 1] - P[3 * q] * P[3 * p + 1];
  }
  return area >= 0;
}

// In 3D a face whose projected corners run clockwise faces away (faces are CCW seen from
// outside); large meshes then skip the edges of the far side, so the picture stays legible.
export function frontFacing(model, P) {
  const F = faceCount(model);
  const front = new Uint8Array(F).fill(1);
  if (!model.mode3d) return front;
  for (let f = 0; f < F; f += 1) front[f] = facesViewer(model, P, f) ? 1 : 0;
  return front;
}

// Whether edge e borders a face turned towards the viewer (or the boundary).
export function edgeSeen(model, front, e) {
  const left = model.weShown.edges[8 * e + 2]; const right = model.weShown.edges[8 * e + 3];
  return left < 0 || right < 0 || front[left] || front[right];
}
