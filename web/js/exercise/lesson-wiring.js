// @ts-check
// Exercises in a lesson page, as one value the shell is handed (runLesson's
// `options.exercises`, composed by the page entry web/js/pages/lesson-page.js): the skeleton
// (app/) imports nothing of exercises, and a page without this value is a plain lesson.
// The shell calls it at four points (app/contract.js, ExerciseWiring): before the lesson
// starts (session.js openExercise reads the link), once the panels are built (the opening's
// start mounts the player), when the address changes (an exercise link opens the page
// afresh), and behind "Make an exercise from this view" (author.js).
import { openExercise } from './session.js';
import { readExerciseLink } from './link.js';
import { openAuthorDialog } from './author.js';

/** @type {import('../app/contract.js').ExerciseWiring} */
export const exerciseWiring = Object.freeze({
  open: openExercise,
  named: (hash) => readExerciseLink(hash) !== null,
  author: (parts) => { openAuthorDialog(parts); },
});
