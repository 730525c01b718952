// @ts-check
// Where an exercise comes from (docs/exercises.md, "Links"):
//   lesson.html#exercise=<id>   one shipped with the site: exercises/<id>.json, same origin
//   lesson.html#x=<code>        any exercise, its JSON packed into the link (share-link.js codec)
// Both are read, validated and refused here with one sentence; nothing else is fetched.
import { packText, unpackText, stringifyExact } from '../app/share-link.js';
import { EXERCISE_ID, MAX_EXERCISE_CHARS, ExerciseError, parseExercise } from './format.js';

/** @returns {{ id: string } | { code: string } | { problem: string } | null} */
export function readExerciseLink(hash) {
  const params = new URLSearchParams(String(hash ?? '').replace(/^#/, ''));
  if (params.has('exercise')) {
    const id = params.get('exercise') ?? '';
    return EXERCISE_ID.test(id) ? { id } : { problem: `the link names the exercise "${id.slice(0, 40)}", which is not an exercise name` };
  }
  if (params.has('x')) return { code: params.get('x') ?? '' };
  return null;
}

/** The path of a shipped exercise, relative to the site's pages. */
export const shippedExercisePath = (id) => `exercises/${id}.json`;

/** The link (absolute URL) of an exercise: its JSON packed into the fragment. */
export async function exerciseUrl(exercise, page, base = window.location.href) {
  const code = await packText(stringifyExact(exercise));
  return new URL(`${page}#x=${code}`, base).href;
}

/**
 * The exercise a link names, read and checked (not yet its lesson state).
 * @param {{ id: string } | { code: string }} link
 * @param {{ lessonIds: string[], fetchText?: (path: string) => Promise<string> }} options
 */
export async function loadLinkedExercise(link, { lessonIds, fetchText = fetchSameOrigin }) {
  let textValue;
  if ('id' in link) {
    try {
      textValue = await fetchText(shippedExercisePath(link.id));
    } catch (err) {
      throw new ExerciseError(`the exercise "${link.id}" is not one of this site's exercises (${err.message})`);
    }
  } else {
    if (link.code.length > 2 * MAX_EXERCISE_CHARS) throw new ExerciseError('the link is far longer than any exercise');
    try {
      textValue = await unpackText(link.code, MAX_EXERCISE_CHARS);
    } catch (err) {
      throw new ExerciseError(err.message.replace(/^it /, 'the link '));
    }
  }
  const exercise = parseExercise(textValue, { lessonIds });
  if ('id' in link && exercise.id !== link.id) throw new ExerciseError(`the file exercises/${link.id}.json holds the exercise "${exercise.id ?? '(no id)'}"`);
  return exercise;
}

async function fetchSameOrigin(path) {
  const response = await fetch(path, { credentials: 'same-origin', cache: 'no-cache' });
  if (!response.ok) throw new Error(`the site answered ${response.status}`);
  const length = Number(response.headers.get('content-length') ?? 0);
  if (length > MAX_EXERCISE_CHARS) throw new Error('the file is far larger than an exercise');
  return response.text();
}
