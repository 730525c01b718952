// @ts-check
// The landing page: the lesson list (from the registry) and a live check of the core.
import { lessons } from '../lessons/registry.js';
import { loadWingspline } from '../core/wingspline.js';
import { math, matrix, mi, mo, el, rows4 } from '../ui/mathml.js';
import { registerServiceWorker } from '../app/sw-register.js';
import { applyStoredTheme } from '../app/theme.js';

function lessonCard(lesson) {
  const item = document.createElement('li');
  item.className = 'lesson-card' + (lesson.ready ? '' : ' is-coming');
  const title = document.createElement('h3');
  if (lesson.ready) {
    const link = document.createElement('a');
    link.href = lesson.page;
    link.textContent = lesson.title;
    title.append(link);
  } else {
    title.textContent = lesson.title;
    const badge = document.createElement('span');
    badge.className = 'badge';
    badge.textContent = 'coming';
    title.append(' ', badge);
  }
  const lectures = document.createElement('p');
  lectures.className = 'lectures';
  lectures.textContent = `Lectures ${lesson.lectures}`;
  const summary = document.createElement('p');
  summary.textContent = lesson.summary;
  item.append(title, lectures, summary);
  return item;
}

function showLessons() {
  const list = document.getElementById('lesson-list');
  list.replaceChildren(...lessons.map(lessonCard));
}

async function showCore() {
  const status = /** @type {HTMLElement} */ (document.querySelector('[data-core-status]'));
  const proof = document.getElementById('core-proof');
  try {
    // The Hermite proof is curve maths: only the curves module is fetched.
    const api = await loadWingspline({ parts: ['curves'] });
    const { constraints, matrix: mh } = api.hermiteFromConstraints();
    status.textContent = `Wingspline core ${api.version} is running (WebAssembly).`;
    status.dataset.state = 'ready';
    proof.replaceChildren(
      math(el('msub', mi('M'), mi('Hermite')), mo('='), el('msup', matrix(rows4(constraints)), el('mn', '-1')),
        mo('='), matrix(rows4(mh))));
    proof.hidden = false;
    document.body.dataset.coreVersion = api.version;
  } catch (err) {
    status.textContent = err?.code ? err.message : `The WebAssembly core could not be loaded: ${err?.message ?? err}`;
    status.dataset.state = 'error';
  }
}

applyStoredTheme();
// The first visit may be the landing page: it installs the offline copy of the whole site.
registerServiceWorker();
showLessons();
showCore();
