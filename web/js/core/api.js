// @ts-check
// The API object over a started core module: the one place the parts of the API are put
// together. wingspline.js starts the shipped module and calls this; the benchmark starts
// the bench module (the same bindings plus its timing entry points) and calls it too, so its
// meshes are the product's. Not part of the package's exports.
import { unwrap } from './errors.js';
import { createMeshApi } from './mesh-api.js';
import { createCurvesApi } from './curves-api.js';
import { createExerciseApi } from './exercise-api.js';
import { createExerciseCurvesApi } from './exercise-curves-api.js';
import { createExerciseSubdivideApi } from './exercise-subdivide-api.js';
import { createExerciseEditApi } from './exercise-edit-api.js';

/** @param {any} raw the module's embind functions */
export function createApi(raw) {
  const version = raw.version();
  return Object.freeze({
    version,
    // {linearBytes: size of the wasm memory, heapInUse: bytes malloc has handed out}; the
    // leak tests of both cores watch heapInUse across thousands of calls.
    memoryUsage() {
      const { linearBytes, heapInUse } = unwrap(raw.memoryUsage());
      return { linearBytes, heapInUse };
    },
    // Every error code the API can give, with what it means (the core's one list, error_codes.h):
    // [{code, group, meaning}], frozen.
    errorCodes: Object.freeze(unwrap(raw.errorCodes()).codes.map((/** @type {any} */ c) => Object.freeze({ code: c.code, group: c.group, meaning: c.meaning }))),
    ...createMeshApi(raw),
    ...createCurvesApi(raw),
    ...createExerciseApi(raw),
    ...createExerciseCurvesApi(raw),
    ...createExerciseSubdivideApi(raw),
    ...createExerciseEditApi(raw),
  });
}
