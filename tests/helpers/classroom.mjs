// Shared pieces of the classroom tests: which lesson pages to test (every lesson
// marked ready in the registry, plus the test-only fixture lesson under tests/fixtures/site),
// share links built the way the page builds them, bit patterns of numbers, and a trap that
// records any script a tampered link or file might manage to run.
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { repoRoot, startSite } from './browser.mjs';

export { waitReady, openLesson, trap } from './browser.mjs';
import { lessons } from '../../web/js/lessons/registry.js';
import { lessonPage } from '../../scripts/lib/lesson-page.mjs';

export const fixturesSite = path.join(repoRoot, 'tests', 'fixtures', 'site');

// The fixture has stateVersion 2 and a migration from 1; real lessons are tested the same way.
export const fixture = { id: 'fixture', title: 'Classroom fixture', page: 'fixture.html', fixture: true };
export const readyLessons = lessons.filter((l) => l.ready).map((l) => ({ id: l.id, title: l.title, page: l.page }));
export const lessonsUnderTest = [...readyLessons, fixture];
// What the shell does without reading a lesson's state (envelopes, the history, links pasted
// into a tab, the back button) is the same code for every lesson: it is checked on the
// fixture lesson and on the mesh lesson (the largest state: imports, edits). What reads or
// writes a lesson's own state (its reader, its link, a reload) is checked on every lesson.
// (Every case on every lesson took about 40 of the browser layer's 85 minutes.)
export const shellLessonIds = new Set(['fixture', 'mesh']);


// The fixture's page is written from the real lesson frame (web/templates/lesson.html), as
// the build writes every lesson's page, into a folder served before tests/fixtures/site.
export const fixturePages = path.join(repoRoot, 'build', 'test-pages');
export function writeFixturePage() {
  fs.mkdirSync(fixturePages, { recursive: true });
  fs.writeFileSync(path.join(fixturePages, fixture.page), lessonPage(fixture));
}

export function startClassroomSite(options = {}) {
  writeFixturePage();
  return startSite({ overlays: [fixturePages, fixturesSite], ...options });
}

// dist/ pages: the landing page and every ready lesson (the fixture is not part of dist/).
export const distPages = ['index.html', ...readyLessons.map((l) => l.page)];

// The payloads used in tampered links set window.__pwned when they run.
export const payloads = {
  img: '<img src=x onerror="window.__pwned=\'img\'">',
  script: '<script>window.__pwned="script"</script>',
  svg: '<svg onload="window.__pwned=\'svg\'"></svg>',
};
export async function nothingExecuted(page) {
  return page.evaluate(() => ({
    pwned: window.__pwned ?? null,
    injectedElements: document.querySelectorAll('img[src=x], script:not([src]), svg[onload]').length,
  }));
}

// What the page writes after #s=: deflate-raw of the JSON text, base64url without padding.
export function linkCode(jsonText) {
  return zlib.deflateRawSync(Buffer.from(jsonText, 'utf8')).toString('base64url');
}
export function envelopeCode(lessonId, version, state) {
  return linkCode(JSON.stringify({ format: 'wingspline', lesson: lessonId, version, state }));
}

// Every number of a value replaced by the hex of its IEEE-754 bits (in the page), so two
// states compare bit for bit (-0 differs from 0).
export async function stateBits(page) {
  return page.evaluate(() => {
    const hex = (x) => {
      const view = new DataView(new ArrayBuffer(8));
      view.setFloat64(0, x);
      return `f64:${view.getBigUint64(0).toString(16).padStart(16, '0')}`;
    };
    const walk = (v) => (typeof v === 'number' ? hex(v)
      : Array.isArray(v) ? v.map(walk)
        : v && typeof v === 'object' ? Object.fromEntries(Object.entries(v).map(([k, x]) => [k, walk(x)])) : v);
    return walk(window.wingspline.state);
  });
}
export function bitsOf(value) {
  const buffer = Buffer.alloc(8);
  const walk = (v) => {
    if (typeof v === 'number') {
      buffer.writeDoubleBE(v);
      return `f64:${buffer.toString('hex')}`;
    }
    if (Array.isArray(v)) return v.map(walk);
    if (v && typeof v === 'object') return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, walk(x)]));
    return v;
  };
  return walk(value);
}

// A change every lesson accepts: the view (part of every lesson's state) moved to numbers
// whose text is awkward: 0.1 + 0.2 (0.30000000000000004), -0 and 1e-300.
export const awkwardView = { cx: 0.1 + 0.2, cy: -0, zoom: 64.1 };
export const tinyView = { cx: 1e-300, cy: -1e-300, zoom: 33.3 };
export async function setView(page, view) {
  await page.evaluate((v) => window.wingspline.ctx.setView(v), view);
  await page.evaluate(() => window.wingspline.flush());
}

// Moves the first draggable handle by keyboard, so the edit goes the way a person's does.
export async function editByKeyboard(page) {
  // A lesson whose drawing has nothing to drag (the code lesson's mesh is a view of its
  // tables) is edited by keyboard in its first choice of the panels instead.
  if (!await page.evaluate(() => window.wingspline.handles().some((hd) => hd.draggable))) {
    await page.focus('.panels select');
    await page.keyboard.press('ArrowDown');
    await page.evaluate(() => window.wingspline.flush());
    return;
  }
  await page.focus('#stage');
  await page.keyboard.press(']');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowUp');
  await page.evaluate(() => window.wingspline.flush());
}

/**
 * Make an exercise (the dialog already open on `page`): choose `kind`, take its link, open it
 * in a page of `context` and wait for the exercise; the dialog must say no problem, the played
 * page must play that kind with an empty message line. Returns the played page.
 */
export async function playMadeExercise(page, context, kind) {
  await page.locator('#author-kind').selectOption(kind);
  await page.locator('#author-copy-link').click();
  await page.waitForSelector('#author-link:not([hidden])');
  if (await page.locator('.author-problem').innerText()) throw new Error(`the dialog refused ${kind}: ${await page.locator('.author-problem').innerText()}`);
  const played = await context.newPage();
  await played.goto(await page.locator('#author-link').inputValue());
  await played.waitForSelector('#exercise-panel');
  const shown = await played.evaluate(() => [document.documentElement.dataset.exercise, document.querySelector('#message')?.textContent ?? '']);
  if (shown[0] !== kind || shown[1].trim()) throw new Error(`the made ${kind} exercise plays as ${shown[0]}, message "${shown[1]}"`);
  return played;
}
