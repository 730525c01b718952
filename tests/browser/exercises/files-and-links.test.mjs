// Exercises in and out: the gallery lists the site's exercises by lesson with the
// progress of this browser; an exercise made in a lesson ("Make an exercise") round-trips
// through its JSON file (opened from the gallery) and through its link; a damaged file or
// link is refused in one sentence naming the field, and the person's saved work is kept.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { useSiteAndBrowser, downloadedBytes } from '../../helpers/browser.mjs';
import { readyLessons, payloads, nothingExecuted, linkCode } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();

test('the gallery lists at least two exercises per lesson, in course order, each opening its lesson; a solved one says so', async () => {
  const page = await env.openPage(`${env.site.url}exercises.html`);
  await page.waitForSelector('body[data-ready="true"]');
  const sections = await page.locator('.gallery-lesson h2').allInnerTexts();
  assert.deepEqual(sections, readyLessons.map((l) => l.title));
  for (const lesson of readyLessons) {
    const links = await page.locator(`a[href^="${lesson.page}#exercise="]`).count();
    assert.ok(links >= 2, `${lesson.id}: ${links}`);
  }
  assert.equal(await page.locator('[data-exercise="mesh-walk-around-v2"] .gallery-status').getAttribute('data-status'), 'new');
  // Solve one (by pointer), then come back.
  await page.locator('[data-exercise="mesh-walk-along-f1"] a').click();
  await page.waitForSelector('#exercise-panel');
  for (const e of [2, 3, 1]) {
    await page.locator(`label[for="exercise-edge-${e}"]`).click();
    await page.locator('#exercise-check').click();
  }
  assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'solved');
  await page.locator('#exercise-panel a[href="./exercises.html"]').click();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.locator('[data-exercise="mesh-walk-along-f1"] .gallery-status').innerText(), '✓ Solved');
});

test('an exercise made from the view round-trips through its JSON file and through its link', async () => {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(env.site.url).origin });
  const page = await context.newPage();
  await page.goto(`${env.site.url}mesh.html`);
  await page.waitForSelector('body[data-ready="true"]');
  // The walk around v4 (the walk's vertex field), by keyboard in the lesson.
  await page.locator('#walk-element').fill('4');
  await page.locator('#walk-element').press('Enter');
  await page.locator('[data-action="make-exercise"]').click();
  await page.locator('#author-kind').selectOption('walk');
  assert.equal(await page.locator('#author-field-element').inputValue(), '4');
  await page.locator('#author-title').fill('Around v4 <b>by hand</b>');
  await page.locator('#author-question').fill(`Which edges, in turn? ${payloads.img}`);
  assert.equal(await page.locator('#author-hide-walk-panel').isChecked(), true);
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#author-export-json').click()]);
  const bytes = await downloadedBytes(download);
  const exercise = JSON.parse(bytes.toString('utf8'));
  assert.equal(exercise.format, 'wingspline-exercise');
  assert.deepEqual(exercise.check, { kind: 'walk', around: 'vertex', element: 4 });
  assert.ok(exercise.hide.includes('walk-panel'));
  assert.equal(exercise.title, 'Around v4 <b>by hand</b>');
  await page.locator('#author-copy-link').click();
  await page.waitForSelector('#author-link:not([hidden])');
  const url = await page.locator('#author-link').inputValue();
  assert.match(url, /mesh\.html#x=[A-Za-z0-9_-]+$/);
  await page.locator('#author-close').click();

  // The link, in a new tab: the same exercise; markup in it is text.
  const other = await context.newPage();
  await other.goto(url);
  await other.waitForSelector('#exercise-panel');
  assert.equal(await other.locator('#exercise-title').innerText(), 'Around v4 <b>by hand</b>');
  assert.match(await other.locator('#exercise-question').innerText(), /Which edges, in turn\? <img src=x/);
  assert.deepEqual(await nothingExecuted(other), { pwned: null, injectedElements: 0 });
  assert.match(await other.locator('.exercise-walk-path').innerText(), /^The walk around v4: e\d → \?$/);
  assert.equal(await other.locator('#walk-panel').isVisible(), false);

  // The file, opened from the gallery: the same exercise again.
  const gallery = await context.newPage();
  await gallery.goto(`${env.site.url}exercises.html`);
  await gallery.waitForSelector('body[data-ready="true"]');
  await Promise.all([gallery.waitForURL(/mesh\.html#x=/), gallery.locator('#exercise-file').setInputFiles({ name: download.suggestedFilename(), mimeType: 'application/json', buffer: bytes })]);
  await gallery.waitForSelector('#exercise-panel');
  assert.equal(await gallery.locator('#exercise-title').innerText(), 'Around v4 <b>by hand</b>');
  assert.equal(await gallery.evaluate(() => window.wingspline.state.vertex), 3);
});

test('a damaged exercise file is refused in the gallery, naming the field; nothing is opened', async () => {
  const page = await env.openPage(`${env.site.url}exercises.html`);
  await page.waitForSelector('body[data-ready="true"]');
  const good = JSON.parse(fs.readFileSync(new URL('../../../web/exercises/curves-bernstein-half.json', import.meta.url), 'utf8'));
  const cases = [
    [{ ...good, check: { ...good.check, tolerance: 'tiny' } }, /"bad\.json" cannot be used: its field exercise\.check\.tolerance must be a finite number/],
    [{ ...good, lesson: 'knitting' }, /exercise\.lesson names "knitting"/],
    ['{"format": "wingspline-exercise",', /is not valid JSON/],
  ];
  for (const [content, expected] of cases) {
    await page.locator('#exercise-file').setInputFiles({ name: 'bad.json', mimeType: 'application/json', buffer: Buffer.from(typeof content === 'string' ? content : JSON.stringify(content)) });
    await page.waitForFunction(() => !document.getElementById('message').hidden);
    assert.match(await page.locator('#message').innerText(), expected);
    assert.match(page.url(), /exercises\.html$/);
  }
});

test('a damaged or unknown exercise link is said in one sentence and the saved work is shown, untouched', async () => {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  await page.goto(`${env.site.url}curves.html`);
  await page.waitForSelector('body[data-ready="true"]');
  await page.locator('#stage').focus();
  await page.keyboard.press(']');
  await page.keyboard.press('ArrowUp');
  await page.evaluate(() => window.wingspline.flush());
  const saved = await page.evaluate(() => JSON.stringify(window.wingspline.state.points));
  const stored = await page.evaluate(() => ({ ...localStorage }));
  const tampered = JSON.parse(fs.readFileSync(new URL('../../../web/exercises/curves-bernstein-half.json', import.meta.url), 'utf8'));
  tampered.state.points[2] = [3, 'two'];
  for (const [hash, expected] of [
    ['#exercise=no-such-exercise', /This exercise could not be opened: the exercise "no-such-exercise" is not one of this site's exercises \(the site answered 404\)\. Showing your own work instead\./],
    ['#x=%%%', /This exercise could not be opened: the link contains characters a share link never has/],
    [`#x=${linkCode(JSON.stringify(tampered))}`, /This exercise could not be opened: its field exercise\.state\.points\[2\]\[1\] must be a finite number/],
  ]) {
    const tab = await context.newPage();
    await tab.goto(`${env.site.url}curves.html${hash}`);
    await tab.waitForSelector('body[data-ready="true"]');
    assert.match(await tab.locator('#message').innerText(), expected);
    assert.equal(await tab.locator('#exercise-panel').count(), 0);
    assert.equal(await tab.evaluate(() => JSON.stringify(window.wingspline.state.points)), saved);
    await tab.close();
  }
  // An exercise shown and answered leaves the saved lesson work as it was.
  const ex = await context.newPage();
  await ex.goto(`${env.site.url}curves.html#exercise=curves-bernstein-half`);
  await ex.waitForSelector('#exercise-panel');
  await ex.locator('#stage').focus();
  await ex.keyboard.press(']');
  await ex.keyboard.press('ArrowDown');
  await ex.waitForTimeout(400);
  const after = await ex.evaluate(() => ({ ...localStorage }));
  for (const [key, value] of Object.entries(stored)) if (!key.startsWith('wingspline:exercise:')) assert.equal(after[key], value, key);
});
