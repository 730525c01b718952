// In the page: Hermite has its own tangents by default (the arrow tips
// drag them, one undo step per drag), Catmull-Rom's tangents are an explicit choice with
// its note, and the choice is state (links). The distances themselves are tested in the
// lessons layer (tests/lessons/comparison-checks.test.mjs), not here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { frame } from '../../helpers/curves-page.mjs';
import { envelopeCode } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();

async function openLab(hash = '') {
  const page = await env.openPage(`${env.site.url}comparison.html${hash}`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await frame(page);
  return page;
}

test('Hermite\'s own tangents: the arrow tip drags T_i; Catmull-Rom\'s tangents are a choice with its note', async () => {
  const page = await openLab();
  let state = await page.evaluate(() => window.wingspline.state);
  assert.equal(state.hermite.tangents, 'own');
  assert.equal(await page.isHidden('#hermite-note'), true);
  const before = state.hermite.own[2].slice();
  const tip = (await page.evaluate(() => window.wingspline.handles())).find((x) => x.id === 't2');
  assert.ok(tip, 'the tip of T2 is a handle');
  await page.mouse.move(tip.x, tip.y);
  await page.mouse.down();
  await page.mouse.move(tip.x + 40, tip.y + 30, { steps: 5 });
  await page.mouse.up();
  await frame(page);
  state = await page.evaluate(() => window.wingspline.state);
  assert.notDeepEqual(state.hermite.own[2], before, 'T2 moved');
  assert.deepEqual(state.points[2], [-0.9, 1.6], 'P2 stayed');
  await page.click('[data-action=undo]');
  await frame(page);
  assert.deepEqual((await page.evaluate(() => window.wingspline.state)).hermite.own[2], before, 'one undo step');

  await page.selectOption('#hermite-tangents', 'catmull-rom');
  await frame(page);
  assert.match(await page.textContent('#hermite-note'), /Catmull-Rom inside Hermite/);
  assert.equal((await page.evaluate(() => window.wingspline.handles())).some((x) => x.id[0] === 't'), false, 'no tips to drag then');
  assert.deepEqual(page.problems, []);
});

test('a version-3 link (before the choice) opens with Catmull-Rom\'s tangents, as it was drawn', async () => {
  const page = await openLab();
  const { hermite, ...old } = await page.evaluate(() => window.wingspline.state);
  assert.equal(hermite.tangents, 'own');
  const other = await openLab(`#s=${envelopeCode('comparison', 3, old)}`);
  const state = await other.evaluate(() => window.wingspline.state);
  assert.equal(state.hermite.tangents, 'catmull-rom');
  assert.equal(state.hermite.own.length, state.points.length);
  assert.match(await other.textContent('#hermite-note'), /Catmull-Rom inside Hermite/);
});
