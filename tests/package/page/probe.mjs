// What the package test asks the installed core, the same in Node and in a page without a
// bundler: a point of a cubic Bezier, the CCW walk around v2 of lecture 000's mesh built from
// the slide's own tables, and dispose. Plain values out; the test compares them with the
// lecture's values (tests/package/package.test.mjs).

// Lecture 000's mesh, the slide's numbering (0-based here: v1 = 0, e1 = 0, F1 = 0).
// The slide's edge table: e1 v1-v3, e2 v1-v2, e3 v2-v3, e4 v3-v4, e5 v2-v4, e6 v2-v5, e7 v4-v5;
// vertex table v1 e1, v2 e6, v3 e3, v4 e5, v5 e6; face table F1 e1, F2 e3, F3 e5.
export const slideMesh = {
  positions: [0, 1, 0, 1, 0, 0, 1, 2, 0, 2, 1, 0, 2, -1, 0],
  faces: [[0, 1, 2], [1, 3, 2], [1, 4, 3]],
  edges: [[0, 2], [0, 1], [1, 2], [2, 3], [1, 3], [1, 4], [3, 4]],
  vertexEdges: [0, 5, 2, 4, 5],
  faceEdges: [0, 2, 4],
};

export async function probe(loadWingspline) {
  const api = await loadWingspline();
  const bezier = { kind: 'bezier', dim: 2, points: [0, 0, 1, 2, 3, 2, 4, 0] };
  const params = [0, 0.25, 0.5, 1];
  const points = Array.from(api.evaluateCurve(bezier, params));
  const liveBefore = api.liveMeshCount();
  const mesh = api.buildMesh(slideMesh);
  const walk = mesh.traversalSteps(1).map((s) => s.edge);
  const liveDuring = api.liveMeshCount();
  mesh.dispose();
  let afterDispose = null;
  try {
    mesh.traversalSteps(1);
  } catch (err) {
    afterDispose = err.code;
  }
  return { version: api.version, params, points, walk, liveBefore, liveDuring, liveAfter: api.liveMeshCount(), disposed: mesh.disposed, afterDispose };
}
