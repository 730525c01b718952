// A selected control point that the state no longer has (the point was added, selected,
// then undone) is no selection: "Add point" appends at the end and "Remove point" asks for
// a selection, as with nothing selected; neither throws nor names the point that is gone.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { openCurves, frame } from '../../helpers/curves-page.mjs';

const env = useSiteAndBrowser();
const pointCount = (page) => page.evaluate(() => window.wingspline.state.points.length);

test('a point selected and then undone away is not the selection for Add point and Remove point', async () => {
  const page = await openCurves(env);
  const before = await pointCount(page);
  await page.click('[data-action=add-point]');
  await frame(page);
  assert.equal(await pointCount(page), before + 1);
  // Select the new last point with the pointer, then take its addition back.
  const last = `p${before}`;
  const handle = (await page.evaluate(() => window.wingspline.handles())).find((x) => x.id === last);
  await page.mouse.click(handle.x, handle.y);
  await frame(page);
  assert.equal(await page.evaluate(() => window.wingspline.selected), last);
  await page.focus('body');
  await page.keyboard.press('Control+z');
  await frame(page);
  assert.equal(await pointCount(page), before);

  // Add point with nothing that exists selected: a new last point, P<before>.
  await page.click('[data-action=add-point]');
  await frame(page);
  assert.equal(await pointCount(page), before + 1);
  assert.equal(await page.evaluate(() => window.wingspline.message()), `Added P${before}.`);
  assert.deepEqual(page.problems, []);

  // Undo again: Remove point asks for a selection and removes nothing.
  await page.keyboard.press('Control+z');
  await frame(page);
  const points = await page.evaluate(() => window.wingspline.state.points);
  await page.click('[data-action=remove-point]');
  await frame(page);
  assert.deepEqual(await page.evaluate(() => window.wingspline.state.points), points);
  assert.match(await page.evaluate(() => window.wingspline.message()), /^Select a control point first/);
  assert.deepEqual(page.problems, []);
});
