// @ts-check
// The mesh part of the API (wasm/wingspline-mesh): meshes, tables, walks, edits, mesh and
// polygon subdivision. wingspline.js imports it only when the 'mesh' part is asked for, so
// a curve lesson loads none of it.
import { createMeshApi } from './mesh-api.js';

/** @param {any} raw the mesh module's embind functions */
export function createMeshPart(raw) {
  return createMeshApi(raw);
}
