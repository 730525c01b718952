// Exercise kind 2: predicting the CCW walk, step after step, in the mesh lesson,
// by keyboard and by pointer. The expected walks are read off lecture 000's printed tables by
// the lecture's own rule (tests/helpers/lecture-slide.mjs), not from the app.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { slideWalk } from '../../helpers/lecture-slide.mjs';
import { exerciseAt } from '../../helpers/exercise-levels.mjs';

const env = useSiteAndBrowser();
const feedback = (page) => page.locator('#exercise-feedback').innerText();
const status = (page) => page.locator('#exercise-status').getAttribute('data-status');

test('the lecture\'s walks, as the slide reads them', () => {
  assert.deepEqual(slideWalk('vertex', 'v2'), ['e6', 'e5', 'e3', 'e2']);
  assert.deepEqual(slideWalk('face', 'F1'), ['e1', 'e2', 'e3']);
});

test('around v2 by keyboard: a wrong edge is explained, the right ones close the walk, and the progress survives a reload', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-walk-around-v2`);
  const walk = slideWalk('vertex', 'v2');
  assert.match(await page.locator('.exercise-walk-path').innerText(), new RegExp(`${walk[0]} → \\?`));
  // The walk's own panel and the tables, which would tell the answer, are hidden.
  assert.equal(await page.locator('#walk-panel').isVisible(), false);
  assert.equal(await page.locator('#tables-panel').isVisible(), false);
  // Wrong first: e7 (the keyboard reaches it: focus the first choice, arrow keys).
  await page.locator('#exercise-edge-1').focus();
  for (let i = 0; i < 6; i += 1) await page.keyboard.press('ArrowRight');
  assert.equal(await page.locator('#exercise-edge-7').isChecked(), true);
  await page.keyboard.press('Enter');
  const wrong = await feedback(page);
  // Level check (the gallery's): the step and the rule, never the next edge.
  assert.match(wrong, /Step 1, from e6: that is not the edge the walk reads next\. Re-read the rule \(lecture 000\): the counter-clockwise walk around v2 reads S:L from an edge whose Start is v2 and E:R/);
  assert.doesNotMatch(wrong, /\be5\b/);
  assert.equal(await status(page), 'started');
  // Then every right edge in turn, typed from the keyboard: Home, arrows to it, Enter.
  for (let k = 1; k < walk.length; k += 1) {
    const n = Number(walk[k].slice(1));
    await page.locator('#exercise-edge-1').focus();
    await page.keyboard.press('ArrowLeft'); // wraps to the last
    await page.keyboard.press('ArrowRight'); // back to e1, checked
    for (let i = 1; i < n; i += 1) await page.keyboard.press('ArrowRight');
    await page.keyboard.press('Enter');
    assert.match(await feedback(page), new RegExp(`Right: .*${walk[k]}`));
  }
  // The walk comes back to its first edge: the last check closes it.
  await page.locator(`#exercise-edge-${walk[0].slice(1)}`).focus();
  await page.keyboard.press('Space');
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), new RegExp(`✓ Right\\. ${walk[0]}: .*the first edge again, so the walk is closed`));
  assert.equal(await status(page), 'solved');
  assert.match(await page.locator('.exercise-walk-path').innerText(), new RegExp(`${walk.join(' → ')} → back to ${walk[0]}`));
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await status(page), 'solved');
  assert.match(await page.locator('#exercise-status').innerText(), /Solved · 5 checks/);
  assert.match(await page.locator('.exercise-walk-path').innerText(), /back to e6/);
});

test('along F1 by pointer (level worked, hints after one wrong check): click the edges, then the worked answer lists the walk with its rule', async () => {
  const page = await env.openLesson(`${env.site.url}${exerciseAt('mesh-walk-along-f1', { level: 'worked', hintAfter: 1 })}`);
  const walk = slideWalk('face', 'F1');
  await page.locator(`label[for="exercise-edge-${walk[2].slice(1)}"]`).click(); // skips a step: wrong
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), new RegExp(`Step 1, from ${walk[0]}: that is not the edge the walk reads next\\. .*the walk along F1 reads E:L from an edge whose Left face is F1 and S:R from one whose Right face is F1`));
  assert.match(await feedback(page), new RegExp(`Hint: F1 is the Right face of ${walk[0]}: find the edge its S:R wing names`));
  assert.doesNotMatch(await feedback(page), new RegExp(`\\b${walk[1]}\\b`));
  for (const e of [...walk.slice(1), walk[0]]) {
    await page.locator(`label[for="exercise-edge-${e.slice(1)}"]`).click();
    await page.locator('#exercise-check').click();
  }
  assert.equal(await status(page), 'solved');
  await page.locator('#exercise-show-worked').click();
  const lines = await page.locator('#exercise-worked li').allInnerTexts();
  assert.deepEqual(lines.map((l) => l.split(':')[0]), walk.map((e, i) => `${e} → ${walk[(i + 1) % walk.length]}`));
  // Start again clears the progress.
  await page.locator('#exercise-start-again').click();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await status(page), 'started');
  assert.match(await page.locator('.exercise-walk-path').innerText(), new RegExp(`${walk[0]} → \\?`));
});

test('progress kept before the walk recorded its picks ({known}, the fixture) opens where it was, and is saved as picks', async () => {
  const fixture = JSON.parse(fs.readFileSync(new URL('../../fixtures/exercise-progress/walk-known-v1.json', import.meta.url), 'utf8'));
  const page = await env.openLesson(`${env.site.url}mesh.html`);
  await page.evaluate(({ key, entry }) => localStorage.setItem(key, JSON.stringify(entry)), fixture);
  await page.goto(`${env.site.url}mesh.html#exercise=mesh-walk-around-v2`);
  await page.waitForSelector('body[data-ready="true"]');
  const walk = slideWalk('vertex', 'v2');
  // known = 3: e6, e5, e3 shown; the next step is the fourth edge.
  assert.match(await page.locator('.exercise-walk-path').innerText(), new RegExp(`${walk.slice(0, 3).join(' → ')} → \\?`));
  assert.match(await page.locator('#exercise-status').innerText(), /4 checks/);
  await page.locator(`label[for="exercise-edge-${walk[3].slice(1)}"]`).click();
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), new RegExp(`Right: .*${walk[3]}`));
  const saved = await page.evaluate((key) => JSON.parse(localStorage.getItem(key)), fixture.key);
  assert.deepEqual(saved.answer, { picks: [...walk.slice(1, 4)].map((e) => Number(e.slice(1))) });
});
