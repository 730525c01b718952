// @ts-check
// Exercises in a lesson page, as one value the shell is handed (runLesson's
// `options.exercises`, composed by the page entry web/js/pages/lesson-page.js): the skeleton
// (app/) imports nothing of exercises, and a page without this value is a plain lesson.
// The shell calls it at four points (app/contract.js, ExerciseWiring): before the lesson
// starts (session.js openExercise reads the link), once the panels are built (the opening's
// start mounts the player), when the address changes (an exercise link opens the page
// afresh), and behind "Make an exercise from this view" (author.js).
// The player, the kinds and the author dialog are imported only when an exercise link is
// opened or an exercise is being made, with the core's exercise checkers: a plain lesson
// page loads none of them (docs/architecture.md, "Module size").
import { readExerciseLink } from './link.js';

/** @type {import('../app/contract.js').ExerciseWiring} */
export const exerciseWiring = Object.freeze({
  open: async (lesson) => (readExerciseLink(window.location.hash) ? (await import('./session.js')).openExercise(lesson) : null),
  named: (hash) => readExerciseLink(hash) !== null,
  author: (parts) => {
    import('./author.js').then((m) => m.openAuthorDialog(parts), (err) => {
      parts.message.warn(`The exercise maker could not be loaded: ${err.message}. Reload the page and try again.`, { code: 'exercise-author-refused' });
    });
  },
});
