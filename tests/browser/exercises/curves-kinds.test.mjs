// Exercise kinds 3, 4 and 5 in their lessons, answered right and wrong by pointer
// and keyboard: classify a joint and say why (continuity lab), compute a value by hand
// (curve explorer: B₁,₃(1/2) = 3·(1/2)·(1/2)² = 3/8; P(1/2) of P0..P3 = (0,0), (1,2), (3,2),
// (4,0) is (P0 + 3P1 + 3P2 + P3)/8 = (2, 1.5)), and shape a curve until it passes through a
// point (the inner points raised by 4/3 lift P(1/2) by 3/8·4/3·2 = 1).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { exerciseAt } from '../../helpers/exercise-levels.mjs';
import { drag } from '../../helpers/pointer.mjs';

const env = useSiteAndBrowser();
const feedback = (page) => page.locator('#exercise-feedback').innerText();
const status = (page) => page.locator('#exercise-status').getAttribute('data-status');

test('a joint that is G1 but not C1 (legs 1 : 2): a wrong class is explained, the right one with its reasons is accepted', async () => {
  const page = await env.openLesson(`${env.site.url}${exerciseAt('continuity-classify-g1', { level: 'worked' })}`);
  // The lab does not give the answer away: no verdict on the drawing, the joint panel hidden.
  assert.equal(await page.locator('#joints-panel').isVisible(), false);
  assert.equal(await page.evaluate(() => window.wingspline.labelRects().some((r) => /C\d|G\d/.test(r.text ?? ''))), false);
  // Wrong, by pointer: C1 and G1.
  await page.locator('label[for="exercise-parametric-1"]').click();
  await page.locator('label[for="exercise-geometric-1"]').click();
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /Not yet/);
  assert.equal(await status(page), 'started');
  // Right, by keyboard: C0 (arrow left from C1), G1 kept, the reasons ticked with Space.
  await page.locator('#exercise-parametric-1').focus();
  await page.keyboard.press('ArrowLeft');
  assert.equal(await page.locator('#exercise-parametric-0').isChecked(), true);
  // The statements as the panel offers them (the core's jointReasons, read by the exercises
  // part the session loaded, not the page's curves part).
  const reasons = await page.$$eval('input[id^="exercise-why-"]', (inputs) => inputs.map((i) => i.id.slice('exercise-why-'.length)));
  for (const id of ['meet', 'same-direction']) {
    assert.ok(reasons.includes(id), id);
    await page.locator(`#exercise-why-${id}`).focus();
    await page.keyboard.press('Space');
  }
  await page.locator(`#exercise-why-${reasons[0]}`).focus();
  await page.keyboard.press('Enter');
  assert.match(await feedback(page), /^✓ Right\./);
  assert.equal(await status(page), 'solved');
  await page.locator('#exercise-show-worked').click();
  assert.ok((await page.locator('#exercise-worked li').count()) >= 1);
});

test('B₁,₃(0.5) by hand: 0.4 is refused without the exact value (it is in the worked answer); 3/8 typed as a fraction is right', async () => {
  const page = await env.openLesson(`${env.site.url}${exerciseAt('curves-bernstein-half', { level: 'worked' })}`);
  await page.locator('#exercise-value').click();
  await page.keyboard.type('0.4');
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /not within the tolerance of B₁,₃\(u\) at u = 0\.5\. Re-read: Bᵢ,ₙ\(u\) = C\(n, i\)/);
  assert.doesNotMatch(await feedback(page), /0\.375|3\/8/);
  assert.equal(await status(page), 'started');
  await page.locator('#exercise-value').fill('');
  await page.locator('#exercise-value').focus();
  await page.keyboard.type('3/8');
  await page.keyboard.press('Enter');
  assert.match(await feedback(page), /^✓ Right\./);
  await page.locator('#exercise-show-worked').click();
  assert.ok((await page.locator('#exercise-worked li').allInnerTexts()).some((l) => /0\.375/.test(l)));
  // Not a number: said, not counted as a check.
  await page.locator('#exercise-value').fill('three eighths');
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /"three" is not a number/);
  assert.match(await page.locator('#exercise-status').innerText(), /2 checks/);
});

test('P(0.5) of the lecture\'s Bezier curve: a point typed as x, y', async () => {
  const page = await env.openLesson(`${env.site.url}curves.html#exercise=curves-de-casteljau-point`);
  await page.locator('#exercise-value').fill('(2, 1.4)');
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /Not yet/);
  await page.locator('#exercise-value').fill('2, 1.5');
  await page.locator('#exercise-value').press('Enter');
  assert.match(await feedback(page), /^✓ Right\./);
});

test('through a point: dragging by pointer gets close, the inspector (keyboard) makes it hold; the shaped curve survives a reload', async () => {
  const page = await env.openLesson(`${env.site.url}curves.html#exercise=curves-through-a-point`);
  const live = () => page.locator('.exercise-live').innerText();
  assert.match(await live(), /^Not yet/);
  const zoom = await page.evaluate(() => window.wingspline.state.view.zoom);
  await drag(page, 'p1', 0, -0.5 * zoom);
  assert.match(await live(), /^Not yet/);
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /Not yet/);
  for (const id of ['p1', 'p2']) {
    await page.locator('#stage').focus();
    for (let i = 0; i < 8 && await page.evaluate(() => window.wingspline.selected) !== id; i += 1) await page.keyboard.press(']');
    assert.equal(await page.evaluate(() => window.wingspline.selected), id);
    // The inspector shows the newly selected point on the next frame (late on a busy machine).
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
    await page.locator('#inspect-y').fill(String(2 + 4 / 3));
    await page.locator('#inspect-y').press('Enter');
  }
  // (the inspector keeps 4 decimals: 3.3333, P(1/2) then 2.499975, well within the tolerance)
  await page.waitForFunction(() => /holds/.test(document.querySelector('.exercise-live').textContent), null, { timeout: 3000 }).catch(() => {});
  assert.match(await live(), /holds/, JSON.stringify(await page.evaluate(() => window.wingspline.state.points)));
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /^✓ Right\./);
  const shaped = await page.evaluate(() => window.wingspline.state.points);
  await page.evaluate(() => window.wingspline.flush());
  await page.reload();
  await page.waitForSelector('#exercise-panel');
  assert.deepEqual(await page.evaluate(() => window.wingspline.state.points), shaped);
  assert.equal(await status(page), 'solved');
});

test('C¹ but not C²: dragging under the C1 constraint breaks C2 and the property holds', async () => {
  const page = await env.openLesson(`${env.site.url}continuity.html#exercise=continuity-make-c1-not-c2`);
  const live = () => page.locator('.exercise-live').innerText();
  assert.match(await live(), /^Not yet/);
  const handles = await page.evaluate(() => window.wingspline.handles().map((x) => x.id));
  await drag(page, handles[handles.length - 2], 30, 40);
  assert.match(await live(), /holds/);
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /^✓ Right\./);
});
