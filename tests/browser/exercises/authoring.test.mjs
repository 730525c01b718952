// "Make an exercise from this view" in every lesson: for each kind a lesson offers,
// the dialog's suggestion, exported as a link, opens as a playable exercise of that kind with
// no warning; a check that cannot be asked of the drawing is said in the dialog and nothing
// is exported.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { readyLessons } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();

for (const lesson of readyLessons) {
  test(`${lesson.id}: every kind it offers, made from the starting view, plays`, async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
    const page = await context.newPage();
    await page.goto(`${env.site.url}${lesson.page}`);
    await page.waitForSelector('body[data-ready="true"]');
    const kinds = await page.evaluate(() => window.wingspline.hooks.exercise.kinds);
    assert.ok(kinds.length >= 1);
    await page.locator('[data-action="make-exercise"]').click();
    for (const kind of kinds) {
      await page.locator('#author-kind').selectOption(kind);
      await page.locator('#author-copy-link').click();
      await page.waitForSelector('#author-link:not([hidden])');
      assert.equal(await page.locator('.author-problem').innerText(), '');
      const url = await page.locator('#author-link').inputValue();
      const played = await context.newPage();
      await played.goto(url);
      await played.waitForSelector('#exercise-panel');
      assert.equal(await played.evaluate(() => document.documentElement.dataset.exercise), kind);
      assert.equal(await played.locator('#message').innerText(), '', `${lesson.id} ${kind}`);
      // The suggestion is a real question: not already answered by the drawing as it is.
      await played.locator('#exercise-check').click();
      assert.notEqual(await played.locator('#exercise-feedback').getAttribute('data-result'), 'right', `${lesson.id} ${kind}`);
      await played.close();
    }
  });
}

test('a check the drawing cannot answer is said in the dialog, and nothing is exported', async () => {
  const page = await env.openLesson(`${env.site.url}continuity.html`);
  await page.locator('[data-action="make-exercise"]').click();
  await page.locator('#author-kind').selectOption('joint');
  await page.locator('#author-field-joint').fill('9');
  await page.locator('#author-copy-link').click();
  assert.match(await page.locator('.author-problem').innerText(), /Not yet an exercise: its field exercise\.check\.joint is 9, but the curve has 1 joint/);
  assert.equal(await page.locator('#author-link').isVisible(), false);
  await page.locator('#author-field-joint').fill('1');
  await page.locator('#author-question').fill('');
  await page.locator('#author-copy-link').click();
  assert.match(await page.locator('.author-problem').innerText(), /exercise\.question must not be empty/);
});
