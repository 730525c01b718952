// The edit kind in half-edge terms (check.structure "half-edge"), played as a student would:
// the gallery's flip of e3, the rows typed by keyboard (one next wrong first), then a wrong face
// row picked by pointer and put right. The expected rows are worked out by hand (the native test
// tests/native/mesh/test_exercise_half_edge_edit.cpp has the same working): after flip e3,
// F1 = h3 (v1 -> v2), h9 (v2 -> v4), h5 (v4 -> v1); F2 = h2 (v3 -> v1), h6 (v1 -> v4), h8 (v4 ->
// v3); rows h2 h3 h5 h6 h8 h9 change, and F1's half-edge (h2 before, now on F2).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser, screenshot } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();
const feedback = (page) => page.locator('#exercise-feedback').innerText();
const status = (page) => page.locator('#exercise-status').getAttribute('data-status');
const cell = (page, table, row, col) => page.locator(`.exercise-edit input[data-table="${table}"][data-row="${row}"][data-col="${col}"]`);

//            origin face  next  prev
const AFTER = [['v3', 'F2', 'h6', 'h8'], // h2
  ['v1', 'F1', 'h9', 'h5'], // h3
  ['v4', 'F1', 'h3', 'h9'], // h5
  ['v1', 'F2', 'h8', 'h2'], // h6
  ['v4', 'F2', 'h2', 'h6'], // h8
  ['v2', 'F1', 'h5', 'h3']]; // h9

test('flip e3 in half-edge terms by keyboard: a wrong next is named by row and column without its value, then the right rows solve it', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-half-edge-flip-e3`);
  assert.equal(await page.locator('#edit-panel').isVisible(), false);
  assert.match(await page.locator('.exercise-edit-op').innerText(), /flip e3/);
  assert.match(await page.locator('.exercise-edit-half-edge .hint').innerText(), /adds no element/);
  // The rows asked, in order: six half-edges and one face.
  const names = await page.$$eval('.exercise-edit-row .exercise-edit-name', (els) => els.map((e) => e.textContent.trim()));
  assert.deepEqual(names, ['h2', 'h3', 'h5', 'h6', 'h8', 'h9', 'F1']);
  // The rows before, for reading: h5 as the slide's tables give it (e3 = v2 -> v3 on F1).
  assert.match(await page.locator('.exercise-edit-row[data-table="halfedges"][data-row="2"] .exercise-edit-before').innerText(), /origin v2 · face F1 · next h2 · prev h3/);
  for (const [row, cells] of AFTER.entries()) {
    for (const [col, value] of cells.entries()) {
      await cell(page, 'halfedges', row, col).focus();
      // h8's next typed as h6 (its next before the flip): wrong
      await page.keyboard.type(row === 4 && col === 2 ? 'h6' : value);
    }
  }
  await cell(page, 'faces', 0, 0).focus();
  await page.keyboard.type('h5');
  // Up and down move along a column: from h6's next to h8's.
  await cell(page, 'halfedges', 3, 2).focus();
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.evaluate(() => document.activeElement?.getAttribute('data-row')), '4');
  await page.keyboard.press('Enter');
  const wrong = await feedback(page);
  assert.match(wrong, /Row h8, column next: after flip e3 next\(h8\) starts where h8 ends/);
  assert.doesNotMatch(wrong, /\bh2\b/); // the right value is not told
  assert.equal(await cell(page, 'halfedges', 4, 2).getAttribute('aria-invalid'), 'true');
  await cell(page, 'halfedges', 4, 2).fill('');
  await cell(page, 'halfedges', 4, 2).focus();
  await page.keyboard.type('h2');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.querySelector('#exercise-status')?.getAttribute('data-status') === 'solved');
  assert.match(await feedback(page), /Every half-edge row after flip e3 is right/);
  await screenshot(page, 'exercise-half-edge-edit-1280');
  assert.deepEqual(page.problems, []);
});

test('flip e3 in half-edge terms by pointer: F1 given a half-edge of F2 is named, any half-edge of F1 is right', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-half-edge-flip-e3`);
  for (const [row, cells] of AFTER.entries()) for (const [col, value] of cells.entries()) await cell(page, 'halfedges', row, col).fill(value);
  await cell(page, 'faces', 0, 0).click();
  await cell(page, 'faces', 0, 0).fill('h2'); // F1's half-edge before: now on F2
  await page.getByRole('button', { name: /^Check/ }).click();
  await page.waitForFunction(() => /Row F1/.test(document.querySelector('#exercise-feedback')?.textContent ?? ''));
  assert.match(await feedback(page), /Row F1, column half-edge: after flip e3 a face stores one of its own half-edges/);
  assert.equal(await status(page), 'started');
  assert.equal(await cell(page, 'faces', 0, 0).getAttribute('aria-invalid'), 'true');
  // h9 is F1's too (any half-edge of the face is right).
  await cell(page, 'faces', 0, 0).fill('h9');
  await page.getByRole('button', { name: /^Check/ }).click();
  await page.waitForFunction(() => document.querySelector('#exercise-status')?.getAttribute('data-status') === 'solved');
  assert.deepEqual(page.problems, []);
});
