// The answer grids fit (docs/exercises.md, "On a phone" and "The grids"): the winged-edge
// exercise's tables at 1366x768 and 1440x900 show every column's input inside the panel's
// visible box (no column behind a horizontal scroll); on a 390x844 phone a grid wider than the
// screen scrolls in its own box and a cue above it says so, every input reachable by scrolling
// that box. And the drawing gives no answer away as it opens: a table exercise draws no walk
// (its first edge is the vertex table's entry), a walk exercise only its start.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { galleryExercise } from '../../helpers/exercise-levels.mjs';
import { linkCode } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();

// Per grid: its inputs outside the box that shows them (the grid's scroll box, clipped by the
// exercise panel), and whether that box scrolls and its cue shows.
function measure(page) {
  return page.evaluate(() => [...document.querySelectorAll('#exercise-panel .exercise-grid:not(.worked)')].map((table) => {
    const box = table.closest('.exercise-grid-box');
    const b = box.getBoundingClientRect();
    const p = document.querySelector('#exercise-panel').getBoundingClientRect();
    const left = Math.max(b.left, p.left); const right = Math.min(b.right, p.right);
    const outside = [...table.querySelectorAll('input')].filter((i) => { const r = i.getBoundingClientRect(); return r.left < left - 0.5 || r.right > right + 0.5; }).map((i) => i.getAttribute('aria-label'));
    const cue = box.previousElementSibling;
    return { caption: table.querySelector('caption').textContent, outside, scrolls: box.scrollWidth > box.clientWidth + 1, cue: Boolean(cue?.classList.contains('exercise-scroll-cue') && !cue.hidden && cue.getBoundingClientRect().height > 0) };
  }));
}

for (const [width, height] of [[1366, 768], [1440, 900]]) {
  test(`${width}x${height}: every column of the winged-edge tables is inside the panel, no grid scrolls, no cue`, async () => {
    const context = await env.newContext({ viewport: { width, height } });
    const page = await context.newPage();
    await page.goto(`${env.site.url}mesh.html#exercise=mesh-winged-edge-slide`);
    await page.waitForSelector('body[data-ready="true"]');
    const grids = await measure(page);
    assert.equal(grids.length, 3);
    for (const g of grids) assert.deepEqual({ caption: g.caption, outside: g.outside, scrolls: g.scrolls, cue: g.cue }, { caption: g.caption, outside: [], scrolls: false, cue: false });
    // "none" typed in a cell is shown whole (the narrow cells hold four characters).
    const cell = page.locator('.exercise-grid input[aria-label="e1 E:R"]');
    await cell.fill('none');
    assert.ok(await cell.evaluate((el) => el.scrollWidth <= el.clientWidth + 1), 'none fits its cell');
  });
}

test('390x844 phone: the edge table scrolls in its own box with a visible cue; every input can be scrolled into the box', async () => {
  const context = await env.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  const page = await context.newPage();
  await page.goto(`${env.site.url}mesh.html#exercise=mesh-winged-edge-slide`);
  await page.waitForSelector('body[data-ready="true"]');
  const grids = await measure(page);
  for (const g of grids) {
    if (g.outside.length) assert.deepEqual([g.caption, g.scrolls, g.cue], [g.caption, true, true], `${g.caption}: hidden columns must come with a cue`);
    else assert.equal(g.cue, false, `${g.caption}: no cue when it fits`);
  }
  assert.ok(grids.some((g) => g.cue), 'the edge table is wider than a phone');
  // Every input of the edge table, focused (as Tab does), is scrolled inside the box.
  const labels = await page.locator('.exercise-grid input.cell').evaluateAll((els) => els.map((e) => e.getAttribute('aria-label')));
  for (const label of labels.filter((l) => /^e\d/.test(l))) {
    await page.locator(`.exercise-grid input[aria-label="${label}"]`).focus();
    const inside = await page.locator(`.exercise-grid input[aria-label="${label}"]`).evaluate((el) => {
      const b = el.closest('.exercise-grid-box').getBoundingClientRect(); const r = el.getBoundingClientRect();
      return r.left >= b.left - 0.5 && r.right <= b.right + 0.5;
    });
    assert.ok(inside, `${label} comes into view`);
  }
});

test('the drawing gives nothing away as an exercise opens: a table exercise draws no walk; a walk exercise starts at step 0 whatever its state said', async () => {
  // The gallery's walk exercise with its state at step 3 (its author had stepped the walk).
  const walkExercise = { ...galleryExercise('mesh-walk-around-v2'), state: { ...galleryExercise('mesh-walk-around-v2').state, step: 3 } };
  delete walkExercise.id;
  const page = await env.openLesson(`${env.site.url}mesh.html#x=${linkCode(JSON.stringify(walkExercise))}`);
  assert.equal(await page.evaluate(() => window.wingspline.state.step), 0);
  // Step 0 of the walk numbers no found edge: no badge 1, 2, … on the canvas.
  const badges = await page.evaluate(() => window.wingspline.labelRects().filter((r) => /^\d+$/.test(r.text ?? '')).length);
  assert.equal(badges, 0);
  // The table exercise over a state stepped to 3: nothing of the walk is drawn (no badges).
  const tableExercise = { ...galleryExercise('mesh-winged-edge-slide'), state: { ...galleryExercise('mesh-winged-edge-slide').state, step: 3 } };
  delete tableExercise.id;
  const table = await env.openLesson(`${env.site.url}mesh.html#x=${linkCode(JSON.stringify(tableExercise))}`);
  assert.equal(await table.evaluate(() => window.wingspline.labelRects().filter((r) => /^\d+$/.test(r.text ?? '')).length), 0);
});
