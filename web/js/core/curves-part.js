// @ts-check
// The curves part of the API (wasm/wingspline-curves): curves, continuity, comparison,
// surfaces. wingspline.js imports it only when the 'curves' part is asked for, so the mesh
// lesson loads none of it.
import { createCurvesApi } from './curves-api.js';

/** @param {any} raw the curves module's embind functions */
export function createCurvesPart(raw) {
  return createCurvesApi(raw);
}
