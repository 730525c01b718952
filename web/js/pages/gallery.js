// @ts-check
// The exercise gallery: the exercises shipped with the site (exercises/index.json,
// made by the build from web/exercises/), by lesson in course order, each with its status in
// this browser; and an exercise file from disk, read and checked here, then opened in its
// lesson by a link that carries it (#x=...). A file that cannot be read is named with its
// field, and nothing is opened. And the hand-in: every exercise answered in this browser, in
// one submission file with the name or ID the student types (exercise/submission.js), for an
// assignment upload; the lecturer grades it with `wingspline grade`.
import { h, setChildren } from '../app/dom.js';
import { lessons } from '../lessons/registry.js';
import { applyStoredTheme } from '../app/theme.js';
import { registerServiceWorker } from '../app/sw-register.js';
import { KINDS, parseExercise, MAX_EXERCISE_CHARS } from '../exercise/format.js';
import { exerciseUrl } from '../exercise/link.js';
import { siteStatuses, listProgress } from '../exercise/progress.js';
import { makeSubmission } from '../exercise/submission.js';
import { download } from '../app/file-io.js';
import { stringifyExact } from '../app/share-link.js';

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

// The hand-in panel: the attempts kept in this browser, each ticked, a name, one file.
function showHandIn() {
  const box = /** @type {HTMLElement} */ (document.getElementById('hand-in'));
  const attempts = listProgress();
  if (!attempts.length) {
    setChildren(box, h('p', { id: 'hand-in-empty' }, 'Nothing to hand in yet: the exercises you answer in this browser are listed here.'));
    return;
  }
  const name = /** @type {HTMLInputElement} */ (h('input', { type: 'text', id: 'hand-in-name', autocomplete: 'name', maxlength: '200', 'aria-describedby': 'hand-in-name-hint' }));
  const boxes = attempts.map(({ key, progress }, i) => {
    const input = /** @type {HTMLInputElement} */ (h('input', { type: 'checkbox', id: `hand-in-${i}`, checked: true, 'data-key': key }));
    const status = progress.status === 'solved' ? (progress.sawWorked ? 'solved after the worked answer' : 'solved') : 'started';
    return { key, progress, input, item: h('li', {}, input, ' ', h('label', { for: `hand-in-${i}` }, progress.title || key, ` (${status}, ${progress.checks} check${progress.checks === 1 ? '' : 's'})`)) };
  });
  const result = h('p', { id: 'hand-in-result', role: 'status', 'aria-live': 'polite' });
  const button = h('button', { type: 'button', class: 'primary', id: 'hand-in-export', onclick: () => exportSubmission() }, 'Export the submission file');
  setChildren(box,
    h('p', {}, h('label', { for: 'hand-in-name' }, 'Your name or student ID'), ' ', name),
    h('p', { class: 'hint', id: 'hand-in-name-hint' }, 'Written into the file as you type it; your lecturer\'s gradebook shows it next to the file\'s name.'),
    h('fieldset', {}, h('legend', {}, 'The exercises to hand in'), h('ul', { class: 'hand-in-list' }, boxes.map((b) => b.item))),
    h('p', {}, button), result);

  async function exportSubmission() {
    const student = name.value.trim();
    const chosen = boxes.filter((b) => b.input.checked);
    if (!student) {
      result.dataset.kind = 'error';
      result.textContent = 'Type your name or student ID first: the file is graded under it.';
      name.focus();
      return;
    }
    if (!chosen.length) {
      result.dataset.kind = 'error';
      result.textContent = 'Tick at least one exercise to hand in.';
      return;
    }
    let app = 'unknown';
    try {
      const { loadWingspline } = await import('../core/wingspline.js');
      // Either module reports the version; the curves one is the smaller download.
      app = (await loadWingspline({ parts: ['curves'] })).version;
    } catch {
      // (the version is a courtesy: the grader checks every answer itself)
    }
    const submission = await makeSubmission({
      student, app,
      entries: chosen.map(({ key, progress }) => ({ id: key.startsWith('site:') ? key.slice(5) : (progress.id ?? null), hash: progress.hash ?? null, progress })),
    });
    const slug = student.toLowerCase().normalize('NFKD').replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '').slice(0, 40) || 'student';
    download(`wingspline-submission-${slug}.json`, stringifyExact(submission, 2) + '\n', 'application/json');
    result.dataset.kind = 'info';
    result.textContent = `The submission file (${chosen.length} exercise${chosen.length === 1 ? '' : 's'}) is downloaded: upload it to your course's assignment.`;
  }
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
showHandIn();
