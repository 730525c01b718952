// Handing in: a student answers gallery exercises, then the gallery's "Hand in your answers"
// exports one submission file with what this browser recorded, under the name they type. The
// file is then graded in this test's Node process by the same grader `wingspline grade` runs
// (web/js/exercise/grade.js), with the gallery's exercise files as the lecturer's copies: the
// solved walk is right, the wrong M G entry is wrong with a reason that does not give the value.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from 'wingspline';
import { useSiteAndBrowser, downloadedBytes } from '../../helpers/browser.mjs';
import { readSubmission, exerciseHash } from '../../../web/js/exercise/submission.js';
import { parseExercise } from '../../../web/js/exercise/format.js';
import { gradeFiles, RESULTS } from '../../../web/js/exercise/grade.js';
import { GRADERS } from '../../../web/js/exercise/graders.js';
import { LESSON_OBJECTS } from '../../../web/js/lessons/all.js';
import { slideWalk } from '../../helpers/lecture-slide.mjs';

const env = useSiteAndBrowser();
const galleryText = (id) => fs.readFileSync(new URL(`../../../web/exercises/${id}.json`, import.meta.url), 'utf8');
const lessonIds = Object.keys(LESSON_OBJECTS);

test('with nothing answered, the hand-in says so and offers no file', async () => {
  const page = await env.openPage(`${env.site.url}exercises.html`);
  await page.waitForSelector('body[data-ready="true"]');
  assert.match(await page.locator('#hand-in-empty').innerText(), /Nothing to hand in yet/);
  assert.equal(await page.locator('#hand-in-export').count(), 0);
});

test('answered exercises are exported in one submission file under the typed name, and graded by the core', async () => {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  const page = await context.newPage();
  // The walk along F1, solved by pointer: the edges the slide's own rule gives, after the first.
  await page.goto(`${env.site.url}mesh.html#exercise=mesh-walk-along-f1`);
  await page.waitForSelector('#exercise-panel');
  const walk = slideWalk('face', 'F1').map((e) => Number(e.slice(1)));
  for (const e of [...walk.slice(1), walk[0]]) {
    await page.locator(`label[for="exercise-edge-${e}"]`).click();
    await page.locator('#exercise-check').click();
  }
  assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'solved');
  // The Hermite M G entry, answered wrong by keyboard.
  await page.goto(`${env.site.url}comparison.html#exercise=comparison-hermite-mg`);
  await page.waitForSelector('#exercise-panel');
  await page.locator('#exercise-value').fill('3');
  await page.locator('#exercise-value').press('Enter');
  assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'started');

  await page.goto(`${env.site.url}exercises.html`);
  await page.waitForSelector('body[data-ready="true"]');
  const listed = await page.locator('.hand-in-list li').allInnerTexts();
  assert.equal(listed.length, 2, listed.join(' / '));
  assert.ok(listed.some((t) => t.includes(`(solved, ${walk.length} checks)`)), listed.join(' / '));
  // No name: refused, the name field focused.
  await page.locator('#hand-in-export').click();
  assert.match(await page.locator('#hand-in-result').innerText(), /Type your name or student ID first/);
  assert.equal(await page.evaluate(() => document.activeElement?.id), 'hand-in-name');
  await page.keyboard.type('=Ada Lovelace');
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#hand-in-export').click()]);
  assert.equal(download.suggestedFilename(), 'wingspline-submission-ada-lovelace.json');
  const text = (await downloadedBytes(download)).toString('utf8');
  assert.match(await page.locator('#hand-in-result').innerText(), /2 exercises\) is downloaded/);
  await context.close();

  const { submission, intact } = await readSubmission(text);
  assert.equal(intact, true);
  assert.equal(submission.student, '=Ada Lovelace');
  const byId = Object.fromEntries(submission.exercises.map((e) => [e.id, e]));
  for (const id of ['mesh-walk-along-f1', 'comparison-hermite-mg']) {
    assert.equal(byId[id].hash, await exerciseHash(parseExercise(galleryText(id), { lessonIds })), `${id}: the hash of the version answered`);
  }
  assert.equal(byId['mesh-walk-along-f1'].status, 'solved');
  assert.equal(byId['comparison-hermite-mg'].answer, '3');

  const files = [['walk.json', galleryText('mesh-walk-along-f1')], ['mg.json', galleryText('comparison-hermite-mg')], ['ada.json', text]]
    .map(([name, t]) => ({ name, size: t.length, read: () => t }));
  const api = await loadWingspline();
  const { rows } = await gradeFiles({ api, files, lessons: LESSON_OBJECTS, graders: GRADERS });
  const row = Object.fromEntries(rows.map((r) => [r.exercise, r]));
  assert.equal(row['mesh-walk-along-f1'].result, RESULTS.right);
  assert.equal(row['mesh-walk-along-f1'].score, 1);
  assert.equal(row['comparison-hermite-mg'].result, RESULTS.wrong);
  assert.equal(row['comparison-hermite-mg'].student, '=Ada Lovelace');
  assert.ok(row['comparison-hermite-mg'].reason.length > 0);
});
