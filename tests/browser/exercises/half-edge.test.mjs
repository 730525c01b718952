// The half-edge exercises in the mesh lesson (the table kind's half-edge tables, the walk kind
// on the half-edges), each gallery exercise answered right and wrong by keyboard and by
// pointer. Lecture 000's half-edge table is worked out by hand (tests/helpers/lecture-slide.mjs,
// SLIDE_HALF_EDGES), and so are the walks: around v2 from its boundary half-edge
// h4, twin(prev(h)) gives h11 (prev(h4) = h12, v5 -> v2), h9, h5, back to h4; along F2 from h6
// (e3's E -> S side), next(h) gives h9, h8, back to h6.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { exerciseAt } from '../../helpers/exercise-levels.mjs';
import { SLIDE_HALF_EDGES, SLIDE_HALF_EDGE_VERTICES as SLIDE_VERTICES, SLIDE_HALF_EDGE_FACES as SLIDE_FACES } from '../../helpers/lecture-slide.mjs';

const env = useSiteAndBrowser();
const feedback = (page) => page.locator('#exercise-feedback').innerText();
const status = (page) => page.locator('#exercise-status').getAttribute('data-status');

const SLIDE = SLIDE_HALF_EDGES;

// The slide's table renumbered: student row r is the slide's half-edge order[r] (1-based), so
// twin pairs need not sit together.
function renumbered(order) {
  const rename = (x) => (/^h\d+$/.test(x) ? `h${order.indexOf(Number(x.slice(1))) + 1}` : x);
  return {
    rows: order.map((k) => SLIDE[k - 1].map(rename)),
    vertices: SLIDE_VERTICES.map(rename),
    faces: SLIDE_FACES.map(rename),
  };
}
// The odd half-edges first, then the even ones: h1 h3 … h13 h2 h4 … h14.
const ODD_FIRST = [1, 3, 5, 7, 9, 11, 13, 2, 4, 6, 8, 10, 12, 14];

async function typeAnswer(page, answer) {
  const cells = [...answer.rows.flat(), ...answer.vertices, ...answer.faces];
  await page.locator('.exercise-grid input.cell').first().focus();
  for (const value of cells) {
    await page.keyboard.press('Control+a');
    await page.keyboard.type(value);
    await page.keyboard.press('Tab');
  }
}

test('the half-edge tables of the slide\'s mesh in another numbering, typed by keyboard: right', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-half-edge-table-lecture`);
  assert.equal(await page.locator('#tables-panel').isVisible(), false);
  assert.equal(await page.locator('.exercise-grid input.cell').count(), 14 * 5 + 5 + 3);
  await typeAnswer(page, renumbered(ODD_FIRST));
  await page.keyboard.press('Shift+Tab');
  await page.keyboard.press('Enter');
  assert.match(await feedback(page), /^✓ Right\./);
  assert.equal(await status(page), 'solved');
  await page.reload();
  await page.waitForSelector('#exercise-panel');
  // Row h8 of this numbering is the slide's h2 (v3 -> v1 on F1).
  assert.equal(await page.locator('.exercise-grid input[aria-label="h8 origin"]').inputValue(), 'v3');
});

test('one wrong cell, typed by pointer: named with its row, column and rule, marked, never its value', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-half-edge-table-lecture`);
  const answer = renumbered(ODD_FIRST);
  // Row h3 here is the slide's h5 (v2 -> v3 on F1); its next is the slide's h2, here h8. Write h9
  // (the slide's h4) instead.
  assert.equal(answer.rows[2][2], 'h8');
  answer.rows[2][2] = 'h9';
  const inputs = page.locator('.exercise-grid input.cell');
  const cells = [...answer.rows.flat(), ...answer.vertices, ...answer.faces];
  for (let i = 0; i < cells.length; i += 1) {
    await inputs.nth(i).click();
    await inputs.nth(i).fill(cells[i]);
  }
  await page.locator('#exercise-check').click();
  const text = await feedback(page);
  assert.match(text, /Row h3, column next: this is not next\(h3\)\. Re-read: next\(h\) must start where h ends \(v3\), and lie on the same face \(F1\)/);
  assert.doesNotMatch(text, /\bh8\b/);
  assert.equal(await page.locator('.exercise-grid input[aria-label="h3 next"]').getAttribute('aria-invalid'), 'true');
  assert.equal(await status(page), 'started');
  // Put right by pointer: solved.
  await page.locator('.exercise-grid input[aria-label="h3 next"]').fill('h8');
  await page.locator('#exercise-check').click();
  assert.match(await feedback(page), /^✓ Right\./);
});

test('the half-edge walk around v2 by keyboard: a typed wrong half-edge is explained, the arrow keys and typing close the walk', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-half-edge-walk-around-v2`);
  assert.equal(await page.locator('#walk-panel').isVisible(), false);
  assert.match(await page.locator('.exercise-walk-path').innerText(), /h4 → \?/);
  assert.equal(await page.locator('.exercise-choices input[type=radio]').count(), 14);
  // Wrong: h12 (prev(h4) itself, not its twin), typed, Enter.
  await page.locator('#exercise-walk-typed').fill('h12');
  assert.equal(await page.locator('#exercise-halfedge-12').isChecked(), true);
  await page.locator('#exercise-walk-typed').press('Enter');
  const wrong = await feedback(page);
  assert.match(wrong, /Step 1, from h4: that is not the half-edge the walk reaches next\. Re-read the rule: around a vertex counter-clockwise, h -> twin\(prev\(h\)\)/);
  assert.doesNotMatch(wrong, /\bh11\b/);
  assert.equal(await status(page), 'started');
  // h11 by the arrow keys: the first choice focused, ten steps right, Enter.
  await page.locator('#exercise-halfedge-1').focus();
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowRight');
  for (let i = 1; i < 11; i += 1) await page.keyboard.press('ArrowRight');
  assert.equal(await page.locator('#exercise-halfedge-11').isChecked(), true);
  await page.keyboard.press('Enter');
  assert.match(await feedback(page), /Right: h11: the CCW walk around v2 goes from h4 to twin\(prev\(h4\)\): prev\(h4\) is h12, and its twin is h11/);
  // Then typed: h9, h5, and h4 closes the walk.
  for (const next of ['h9', 'h5', 'h4']) {
    await page.locator('#exercise-walk-typed').fill(next);
    await page.locator('#exercise-walk-typed').press('Enter');
  }
  assert.match(await feedback(page), /✓ Right\. h4: .*the first half-edge again, so the walk is closed/);
  assert.equal(await status(page), 'solved');
  assert.match(await page.locator('.exercise-walk-path').innerText(), /h4 → h11 → h9 → h5 → back to h4/);
});

test('the half-edge walk along F2 by pointer (made at level hint, after two wrong checks): the hint, then the walk closes', async () => {
  const page = await env.openLesson(`${env.site.url}${exerciseAt('mesh-half-edge-walk-along-f2', { level: 'hint', hintAfter: 2 })}`);
  assert.match(await page.locator('.exercise-walk-path').innerText(), /h6 → \?/);
  // Each choice shows its two ends: h9 runs v2 -> v4.
  assert.match(await page.locator('label[for="exercise-halfedge-9"]').innerText(), /h9\s*\(v2 → v4\)/);
  for (const wrong of [5, 10]) { // twin(h6), and the twin of the right one
    await page.locator(`label[for="exercise-halfedge-${wrong}"]`).click();
    await page.locator('#exercise-check').click();
  }
  const text = await feedback(page);
  assert.match(text, /Step 1, from h6: that is not the half-edge the walk reaches next\. Re-read the rule: along a face, h -> next\(h\)/);
  assert.match(text, /Hint: Stand where h6 ends, inside F2: the side of F2 that leaves there is next\(h6\)\./);
  assert.doesNotMatch(text, /\bh9\b/);
  for (const right of [9, 8, 6]) {
    await page.locator(`label[for="exercise-halfedge-${right}"]`).click();
    await page.locator('#exercise-check').click();
  }
  assert.equal(await status(page), 'solved');
});

test('made at level worked, the half-edge walk\'s worked answer lists each step with its rule', async () => {
  const page = await env.openLesson(`${env.site.url}${exerciseAt('mesh-half-edge-walk-around-v2', { level: 'worked', hintAfter: 1 })}`);
  await page.locator('label[for="exercise-halfedge-3"]').click();
  await page.locator('#exercise-check').click();
  await page.locator('#exercise-show-worked').click();
  const lines = await page.locator('#exercise-worked li').allInnerTexts();
  assert.deepEqual(lines.map((l) => l.split(':')[0]), ['h4 → h11', 'h11 → h9', 'h9 → h5', 'h5 → h4']);
});

test('made from the Half-edge tab: the dialog suggests the half-edge table and the half-edge walk, and both play', async () => {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  await page.goto(`${env.site.url}mesh.html`);
  await page.waitForSelector('body[data-ready="true"]');
  await page.locator('#tab-half-edge').click();
  await page.locator('[data-action="make-exercise"]').click();
  const played = async (kind) => {
    await page.locator('#author-kind').selectOption(kind);
    await page.locator('#author-copy-link').click();
    await page.waitForSelector('#author-link:not([hidden])');
    assert.equal(await page.locator('.author-problem').innerText(), '');
    const p = await context.newPage();
    await p.goto(await page.locator('#author-link').inputValue());
    await p.waitForSelector('#exercise-panel');
    return p;
  };
  const table = await played('table');
  assert.equal(await page.locator('#author-field-table').inputValue(), 'half-edge');
  assert.equal(await table.locator('.exercise-grid input[aria-label="h1 origin"]').count(), 1);
  await table.close();
  const walk = await played('walk');
  assert.equal(await page.locator('#author-field-structure').inputValue(), 'half-edge');
  assert.match(await walk.locator('.exercise-walk-path').innerText(), /h\d+ → \?/);
  assert.ok(await walk.locator('#exercise-walk-typed').isVisible());
});
