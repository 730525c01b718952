// @ts-check
// The exercise gallery: the exercises shipped with the site (exercises/index.json,
// made by the build from web/exercises/), by lesson in course order, each with its status in
// this browser; and an exercise file from disk, read and checked here, then opened in its
// lesson by a link that carries it (#x=...). A file that cannot be read is named with its
// field, and nothing is opened.
import { h, setChildren } from '../app/dom.js';
import { lessons } from '../lessons/registry.js';
import { applyStoredTheme } from '../app/theme.js';
import { registerServiceWorker } from '../app/sw-register.js';
import { KINDS, parseExercise, MAX_EXERCISE_CHARS } from '../exercise/format.js';
import { exerciseUrl } from '../exercise/link.js';
import { siteStatuses } from '../exercise/progress.js';

const lessonIds = lessons.map((l) => l.id);
const message = /** @type {HTMLElement} */ (document.getElementById('message'));
function say(text, kind = 'error') {
  message.textContent = text;
  message.dataset.kind = kind;
  message.hidden = false;
}

async function showGallery() {
  const box = /** @type {HTMLElement} */ (document.getElementById('gallery'));
  let index;
  try {
    const response = await fetch('exercises/index.json', { cache: 'no-cache' });
    if (!response.ok) throw new Error(`the site answered ${response.status}`);
    index = await response.json();
    if (index?.format !== 'wingspline-exercise-index' || !Array.isArray(index.exercises)) throw new Error('it is not the exercise index');
  } catch (err) {
    setChildren(box, h('p', { class: 'callout error' }, `The list of exercises could not be loaded (${err.message}).`));
    return;
  }
  const statuses = siteStatuses(index.exercises.map((x) => x.id));
  setChildren(box, lessons.map((lesson) => {
    const mine = index.exercises.filter((x) => x.lesson === lesson.id);
    if (!mine.length) return null;
    return h('section', { class: 'gallery-lesson', 'aria-labelledby': `gallery-${lesson.id}` },
      h('h2', { id: `gallery-${lesson.id}` }, lesson.title),
      h('ul', { class: 'gallery-list' }, mine.map((x) => h('li', { 'data-exercise': x.id },
        h('h3', {}, h('a', { href: `${lesson.page}#exercise=${x.id}` }, x.title)),
        h('p', { class: 'kind' }, KINDS[x.kind]?.label ?? x.kind),
        x.source ? h('p', { class: 'source' }, x.source) : null,
        h('p', { class: 'gallery-status', 'data-status': statuses[x.id] ?? 'new' }, statuses[x.id] === 'solved' ? '✓ Solved' : statuses[x.id] === 'started' ? 'Started' : 'Not started')))));
  }));
  document.body.dataset.ready = 'true';
}

// An exercise file from disk: read, checked, then opened in its lesson.
async function openFile(file) {
  if (file.size > MAX_EXERCISE_CHARS) {
    say(`"${file.name}" is ${Math.round(file.size / 1024)} KB, more than an exercise can be (${MAX_EXERCISE_CHARS / 1024} KB). Nothing was opened.`);
    return;
  }
  let exercise;
  try {
    exercise = parseExercise(await file.text(), { lessonIds });
  } catch (err) {
    say(`"${file.name}" cannot be used: ${err.message}. Nothing was opened.`);
    return;
  }
  const lesson = lessons.find((l) => l.id === exercise.lesson);
  window.location.assign(await exerciseUrl(exercise, lesson?.page ?? `${exercise.lesson}.html`));
}

applyStoredTheme();
registerServiceWorker();
if (window.location.protocol === 'file:') /** @type {HTMLElement} */ (document.getElementById('file-warning')).hidden = false;
const input = /** @type {HTMLInputElement} */ (document.getElementById('exercise-file'));
input.addEventListener('change', () => {
  const file = input.files?.[0];
  input.value = '';
  if (file) openFile(file);
});
showGallery();
