// @ts-check
// The mesh parts of the API. 'mesh' (wasm/wingspline-mesh): meshes, tables, walks, edits, as
// the mesh lesson uses them. 'subdivision' (wasm/wingspline-subdivision): meshes, tables and
// walks with mesh subdivision and curve sampling, as the subdivision lesson uses them (a
// polygon's limit B-spline beside its meshes), and no edits. Both asked for at once
// (loadWingspline() with every part): wasm/wingspline-meshes, every mesh binding in one
// module, so that one mesh can be both edited and subdivided. wingspline.js imports this
// file only when one of them is asked for.
import { createMeshApi } from './mesh-api.js';
import { createCurveSamplingApi } from './curve-sampling-api.js';

/** @param {any} raw the mesh module's embind functions */
export function createMeshPart(raw) {
  return createMeshApi(raw, { withSubdivision: false });
}

/** @param {any} raw the subdivision module's embind functions */
export function createSubdivisionPart(raw) {
  return { ...createMeshApi(raw, { withEdits: false }), ...createCurveSamplingApi(raw) };
}

/** @param {any} raw the meshes module's embind functions (every mesh binding) */
export function createMeshesPart(raw) {
  return { ...createMeshApi(raw), ...createCurveSamplingApi(raw) };
}
