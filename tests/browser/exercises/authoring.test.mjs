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

test('the author chooses the feedback: a new exercise is level check; level hint after 3 wrong checks is what the student is told', async () => {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  await page.goto(`${env.site.url}curves.html`);
  await page.waitForSelector('body[data-ready="true"]');
  await page.locator('[data-action="make-exercise"]').click();
  await page.locator('#author-kind').selectOption('value');
  assert.equal(await page.locator('#author-feedback').inputValue(), 'check');
  assert.equal(await page.locator('#author-hint-after').isVisible(), false);
  await page.locator('#author-copy-link').click();
  await page.waitForSelector('#author-link:not([hidden])');
  const asCheck = await context.newPage();
  await asCheck.goto(await page.locator('#author-link').inputValue());
  await asCheck.waitForSelector('#exercise-panel');
  assert.match(await asCheck.locator('#exercise-level').innerText(), /never shows the right value; no hints, no worked answer/);
  assert.equal(await asCheck.locator('#exercise-show-worked').count(), 0);
  await asCheck.close();
  // By keyboard: the level chosen from its list, then the number of tries typed.
  await page.locator('#author-feedback').focus();
  await page.locator('#author-feedback').selectOption('hint');
  await page.locator('#author-hint-after').fill('3');
  await page.locator('#author-copy-link').click();
  const asHint = await context.newPage();
  await asHint.goto(await page.locator('#author-link').inputValue());
  await asHint.waitForSelector('#exercise-panel');
  assert.match(await asHint.locator('#exercise-level').innerText(), /after 3 wrong checks it adds a hint/);
  // A number of tries out of 1..20 is said in the dialog, and nothing is exported.
  await page.locator('#author-hint-after').fill('25');
  await page.locator('#author-copy-link').click();
  assert.match(await page.locator('.author-problem').innerText(), /exercise\.feedback\.hintAfter/);
});
