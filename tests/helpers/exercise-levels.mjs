// A gallery exercise at another feedback level (docs/exercises.md, "Feedback levels"), opened
// by its #x= link as a lecturer's own copy would be: the same question with `feedback` changed.
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot } from './browser.mjs';
import { linkCode } from './classroom.mjs';

/** The gallery exercise's JSON (the file as shipped). */
export function galleryExercise(id) {
  return JSON.parse(fs.readFileSync(path.join(repoRoot, 'web', 'exercises', `${id}.json`), 'utf8'));
}

/** `<lesson>.html#x=…` for the exercise with `feedback` ({level, hintAfter?}; null: the field left out). */
export function exerciseAt(id, feedback) {
  const exercise = galleryExercise(id);
  delete exercise.id;
  if (feedback) exercise.feedback = feedback;
  else delete exercise.feedback;
  return `${exercise.lesson}.html#x=${linkCode(JSON.stringify(exercise))}`;
}
