// The lectures' notation in the comparison lab's conversion panels: f and the
// checkbox switch M between decimals and lecture 003's exact form; the switch is state (undo,
// links). Expected integers typed from lecture 003 (003_55ddbc47c7ee2ef3.txt).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { frame } from '../../helpers/curves-page.mjs';
import { envelopeCode } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();
const M_BSPLINE = [[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 0, 3, 0], [1, 4, 1, 0]].map((r) => r.map(String));
const M_CR = [[-1, 3, -3, 1], [2, -5, 4, -1], [-1, 0, 1, 0], [0, 2, 0, 0]].map((r) => r.map(String));

// Each conversion panel's M: the factor in front (or null) and the entries, row-major strings.
const panels = (page) => page.$$eval('#conversion-panel .matrix-panel', (roots) => roots.map((root) => {
  const frac = root.querySelector('[data-matrix=M-fraction]');
  const m = root.querySelector('math [data-matrix=M]');
  return {
    notation: root.dataset.notation,
    fraction: frac ? [...frac.children].map((c) => c.textContent) : null,
    entries: [...m.querySelectorAll('mtr')].map((tr) => [...tr.querySelectorAll('mtd')].map((td) => td.textContent.trim())),
  };
}));

test('conversion panels: f and the checkbox give 1/6 [integers] and 1/2 [integers]; undo and links keep it', async () => {
  const page = await env.openPage(`${env.site.url}comparison.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await page.selectOption('#scene', 'conversion');
  await page.selectOption('#conv-from', 'catmull-rom');
  await page.selectOption('#conv-to', 'bspline');
  await frame(page);
  let [from, to] = await panels(page);
  assert.equal(from.notation, 'decimal');
  assert.equal(to.fraction, null);
  assert.equal(to.entries[0][0], '-0.1667');

  await page.click('#conversion-panel .matrix-heading');
  await page.keyboard.press('f');
  await frame(page);
  assert.equal((await page.evaluate(() => window.wingspline.state)).notation, 'fraction');
  [from, to] = await panels(page);
  assert.deepEqual(from.fraction, ['1', '2']);
  assert.deepEqual(from.entries, M_CR);
  assert.deepEqual(to.fraction, ['1', '6']);
  assert.deepEqual(to.entries, M_BSPLINE);
  assert.equal(await page.isChecked('#conv-fractions'), true);

  await page.click('[data-action=undo]');
  await frame(page);
  [from, to] = await panels(page);
  assert.equal(to.notation, 'decimal');
  assert.equal(to.fraction, null);

  await page.click('#conv-fractions');
  await frame(page);
  [, to] = await panels(page);
  assert.deepEqual(to.fraction, ['1', '6']);
  const url = await page.evaluate(() => window.wingspline.shareUrl());
  const other = await env.openPage(url);
  await other.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await frame(other);
  assert.deepEqual((await panels(other))[1].fraction, ['1', '6']);

  // An old (version 1) link opens in decimals, the rest kept.
  const { notation, ...old } = await page.evaluate(() => window.wingspline.state);
  assert.equal(notation, 'fraction');
  const legacy = await env.openPage(`${env.site.url}comparison.html#s=${envelopeCode('comparison', 1, old)}`);
  await legacy.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  const s = await legacy.evaluate(() => window.wingspline.state);
  assert.equal(s.notation, 'decimal');
  assert.equal(s.conversion.to, 'bspline');
});

test('conversion panels in lecture 002\'s and lecture 001\'s forms (the choice is state; old links open in 000/003\'s)', async () => {
  // Lecture 002 (002_5284cf65dc3cb6f3.txt): M_s = 1/6 (1 4 1 0; -3 0 3 0; 3 -6 3 0; -1 3 -3 1);
  // its Catmull-Rom from its own conditions (not the slip): 1/2 (0 2 0 0; -1 0 1 0; 2 -5 4 -1; -1 3 -3 1).
  const M_S_002 = [[1, 4, 1, 0], [-3, 0, 3, 0], [3, -6, 3, 0], [-1, 3, -3, 1]].map((r) => r.map(String));
  const M_R_002 = [[0, 2, 0, 0], [-1, 0, 1, 0], [2, -5, 4, -1], [-1, 3, -3, 1]].map((r) => r.map(String));
  const transpose = (m) => m[0].map((_, j) => m.map((row) => row[j]));
  const page = await env.openPage(`${env.site.url}comparison.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await page.selectOption('#scene', 'conversion');
  await page.selectOption('#conv-from', 'catmull-rom');
  await page.selectOption('#conv-to', 'bspline');
  await page.click('#conv-fractions');
  await page.selectOption('#conv-form', 'ascending');
  await frame(page);
  let [from, to] = await panels(page);
  assert.deepEqual([from.entries, to.entries], [M_R_002, M_S_002]);
  assert.equal(await page.$eval('#conversion-panel .matrix-panel', (r) => r.dataset.form), 'ascending');
  await page.click('#conversion-panel .matrix-heading');
  await page.keyboard.press('m');
  await frame(page);
  [from, to] = await panels(page);
  assert.deepEqual([from.entries, to.entries], [transpose(M_CR), transpose(M_BSPLINE)]);
  assert.equal((await page.evaluate(() => window.wingspline.state)).form, 'transposed');
  // A version-2 link (before the choice) opens in lectures 000/003's form.
  const { form, ...old } = await page.evaluate(() => window.wingspline.state);
  const other = await env.openPage(`${env.site.url}comparison.html#s=${envelopeCode('comparison', 2, old)}`);
  await other.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await frame(other);
  assert.equal((await other.evaluate(() => window.wingspline.state)).form, 'descending');
  assert.deepEqual((await panels(other))[1].entries, M_BSPLINE);
});
