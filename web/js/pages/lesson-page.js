// @ts-check
// The entry of every lesson page (each web/js/lessons/<id>/page.js calls it): the skeleton
// (app/shell.js) composed with what sits above it, which the skeleton must not import: the
// exercise wiring (exercise/lesson-wiring.js) and the WebGL2 mesh renderer the stage keeps
// under the canvas (ui/gl-mesh.js). docs/architecture.md, "Layers", says why.
import { runLesson } from '../app/shell.js';
import { exerciseWiring } from '../exercise/lesson-wiring.js';
import { createGlMesh } from '../ui/gl-mesh.js';

/** @param {import('../app/contract.js').Lesson} lesson */
export function runLessonPage(lesson) {
  return runLesson(lesson, { exercises: exerciseWiring, gpuRenderer: createGlMesh });
}
