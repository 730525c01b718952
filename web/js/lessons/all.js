// @ts-check
// Every lesson object by its id, for what works with any lesson outside a page: the
// exercise grader (exercise/grade.js, run by `wingspline grade` in Node) reads an exercise's
// lesson state and asks its subject here. A page imports only its own lesson.
import { meshLesson } from './mesh/lesson.js';
import { lesson as curvesLesson } from './curves/lesson.js';
import { lesson as continuityLesson } from './continuity/lesson.js';
import { lesson as comparisonLesson } from './comparison/lesson.js';
import { lesson as surfacesLesson } from './surfaces/lesson.js';
import { subdivisionLesson } from './subdivision/lesson.js';
import { codeLesson } from './code/lesson.js';

/** @type {Readonly<Record<string, import('../app/contract.js').Lesson>>} */
export const LESSON_OBJECTS = Object.freeze(Object.fromEntries(
  [meshLesson, curvesLesson, continuityLesson, comparisonLesson, surfacesLesson, subdivisionLesson, codeLesson].map((l) => [l.id, l])));
