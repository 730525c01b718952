// @ts-check
// The exercises part of the API (wasm/wingspline-exercises): the checkers and worked answers
// of every exercise kind, mesh and curve. wingspline.js imports it only when the 'exercises'
// part is asked for: a lesson page asks when an exercise opens or one is being made, so a
// plain lesson loads none of it. The checkers take plain values (the exercise's faces, the
// curve's points), never a mesh of the mesh module.
import { createExerciseApi } from './exercise-api.js';
import { createExerciseSubdivideApi } from './exercise-subdivide-api.js';
import { createExerciseEditApi } from './exercise-edit-api.js';
import { createExerciseCurvesApi } from './exercise-curves-api.js';

/** @param {any} raw the exercises module's embind functions */
export function createExercisesPart(raw) {
  return {
    ...createExerciseApi(raw),
    ...createExerciseSubdivideApi(raw),
    ...createExerciseEditApi(raw),
    ...createExerciseCurvesApi(raw),
  };
}
