// @ts-check
// An exercise in a lesson page, from the link to the player (through lesson-wiring.js, the
// shell's `options.exercises`): openExercise reads the link, the exercise and its lesson
// state before the lesson starts; the opening's start (startExercise) hides the panels the
// exercise hides and mounts the player once the lesson's panels are built. Whatever cannot
// be used is said in one sentence naming the field, and the page carries on as a plain
// lesson with the person's own work (nothing is lost).
import { lessons } from '../lessons/registry.js';
import { readExerciseLink, loadLinkedExercise } from './link.js';
import { progressKey, readProgress } from './progress.js';
import { readExerciseState, mountExercise } from './player.js';
import { readEnvelope } from '../app/share-link.js';
import { exerciseHash } from './submission.js';
import { loadWingspline } from '../core/wingspline.js';

const lessonIds = lessons.map((l) => l.id);

/**
 * @typedef {import('../app/contract.js').ExerciseOpening & { problem: string | null, api?: any, exercise?: any, key?: string, hash?: string, loaded?: any, initialState?: any }} Session
 * @param {import('../app/contract.js').Lesson} lesson
 * @returns {Promise<Session | null>}
 */
export async function openExercise(lesson) {
  const link = readExerciseLink(window.location.hash);
  if (!link) return null;
  /** @type {Session} */
  const session = {
    ready: false,
    problem: null,
    refuse(text) { session.ready = false; session.problem = `This exercise could not be opened: ${text}. Showing your own work instead.`; },
    start: (parts) => startExercise(session, parts),
  };
  if ('problem' in link) {
    session.refuse(link.problem);
    return session;
  }
  try {
    const exercise = await loadLinkedExercise(link, { lessonIds });
    // The lesson's core with the exercise checkers (the exercises module, fetched now).
    const api = await loadWingspline({ parts: [...lesson.core, 'exercises'] });
    const initialState = readExerciseState(lesson, exercise);
    const key = await progressKey(exercise, { shipped: 'id' in link });
    const hash = await exerciseHash(exercise);
    // The drawing as the student left it, for the kinds where the drawing is the answer.
    let state = initialState;
    // Read once: an unreadable entry is moved aside here, and the player says so.
    const loaded = readProgress(key, { lesson: lesson.id });
    const kept = loaded.progress?.state;
    if (kept && lesson.exercise?.keepsState?.includes(exercise.check.kind)) {
      try {
        const read = readEnvelope(lesson, { format: 'wingspline', lesson: lesson.id, version: lesson.stateVersion, state: kept });
        if (!read.problems.length) state = read.state;
      } catch {
        // the kept drawing is not usable: the exercise's own is shown
      }
    }
    Object.assign(session, { ready: true, shownOnStart: true, api, exercise, key, hash, loaded, initialState, restored: { state, source: 'exercise', problem: null, previous: null } });
  } catch (err) {
    session.refuse(err.message);
  }
  return session;
}

/**
 * @param {Session} session what openExercise returned
 * @param {import('../app/contract.js').ExerciseParts} parts
 * @returns {import('../app/contract.js').ExercisePlayer | null}
 */
export function startExercise(session, { ctx, lesson, view, panels, message, accept, keepInHistory }) {
  if (!session.ready) {
    if (session.problem) message.warn(session.problem, { code: 'exercise-refused' });
    return null;
  }
  const { api, exercise, key, hash, initialState, loaded } = session;
  // The page's Reset, and the panel's "Back to the exercise's drawing": the exercise's
  // starting drawing as one undoable step; the drawing it replaces goes into the history.
  const reset = () => {
    const drawing = ctx.state;
    if (!accept(initialState, 'exercise')) return;
    keepInHistory(drawing, `your drawing in the exercise "${exercise.title}"`);
    ctx.fitView();
    message.info('Back to the exercise\'s starting drawing (Undo brings your changes back).');
  };
  const missing = [];
  for (const id of exercise.hide ?? []) {
    const el = document.getElementById(id);
    // (a panel inside the side column; never the column itself, which holds the exercise)
    if (el && el !== panels && panels.contains(el)) el.dataset.exerciseHidden = '';
    else missing.push(id);
  }
  document.documentElement.dataset.exercise = exercise.check.kind;
  ctx.ui.exercise = exercise.check.kind;
  ctx.ui.exerciseStructure = exercise.check.structure ?? null;
  let player;
  try {
    player = mountExercise({ api, ctx, lesson, view, exercise, key, hash, loaded, panels, reset, initialState });
  } catch (err) {
    delete document.documentElement.dataset.exercise;
    ctx.ui.exercise = null;
    ctx.ui.exerciseStructure = null;
    for (const el of panels.querySelectorAll('[data-exercise-hidden]')) delete /** @type {HTMLElement} */ (el).dataset.exerciseHidden;
    message.warn(`This exercise could not be opened: ${err.message}. Showing your own work instead.`, { code: 'exercise-refused' });
    return null;
  }
  const notes = [player.problem, missing.length ? `The exercise hides ${missing.map((m) => `"${m}"`).join(', ')}, which ${missing.length === 1 ? 'is' : 'are'} not a panel of this lesson.` : null].filter(Boolean);
  if (notes.length) message.warn(notes.join(' '), { code: 'exercise-note' });
  // On a phone the exercise is under the drawing: the message line says where.
  if (window.matchMedia?.('(max-width: 800px)').matches && !notes.length) {
    message.info(`Exercise: ${exercise.title}. The question is under the drawing.`, {
      code: 'exercise-below',
      action: { id: 'go-to-exercise', label: 'Go to the question', run: () => player.root.scrollIntoView({ block: 'start' }) },
    });
  }
  return player;
}
