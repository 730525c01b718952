// Exercise kind subdivide in the subdivision lesson: every gallery subdivide exercise played
// wrong, then right, once by keyboard and once by pointer, at feedback level check. The right
// answers are the masks' formulas worked here (Loop: 3/8, 3/8 of an interior edge's ends and
// 1/8 of each opposite corner; the boundary's 1/8, 6/8, 1/8; Catmull-Clark's corner of a cube,
// n = 3: (1/3) v + (1/9)(three neighbours) + (1/9)(three face points), each face point 1/4 of
// its corners) and the counts' rules (V + E + F, 2E + corners, corners), from the cube's
// faces as the core generates them; nothing is read from the app's answers. While a wrong
// answer is shown, neither the feedback nor any canvas label holds a right value.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import { loadWingspline } from 'wingspline';
import { useSiteAndBrowser, trap } from '../../helpers/browser.mjs';
import { exerciseAt } from '../../helpers/exercise-levels.mjs';

const env = useSiteAndBrowser();
const api = await loadWingspline();

// The cube's corner v1: its neighbours (1/3 v + ...: 1/9 + 2 * 1/36 = 1/6 each) and the
// other corner of each face around it (1/36 each); v1 itself 1/3 + 3/36 = 5/12.
function cubeCorner() {
  const { faces } = api.generateMesh('cube');
  const around = faces.filter((f) => f.includes(0));
  const next = new Set(around.flatMap((f) => { const k = f.indexOf(0); return [f[(k + 1) % 4], f[(k + 3) % 4]]; }));
  const far = new Set(around.map((f) => f[(f.indexOf(0) + 2) % 4]));
  assert.equal(next.size, 3);
  assert.equal(far.size, 3);
  return [['v1', '5/12'], ...[...next].map((v) => [`v${v + 1}`, '1/6']), ...[...far].map((v) => [`v${v + 1}`, '1/36'])];
}

const PLAYS = {
  'subdivision-loop-edge-point-e2': {
    wrong: { mask: 'edge-boundary', rows: [['v2', '1/2'], ['v3', '1/2']] },
    right: { mask: 'edge-interior', rows: [['v2', '3/8'], ['v3', '3/8'], ['v1', '1/8'], ['v4', '1/8']] },
    said: /The mask chosen is not the one that makes the edge point of e2/,
    mark: 'edge point of e2?',
  },
  'subdivision-loop-vertex-point-v2': {
    wrong: { mask: 'vertex-interior', rows: [['v2', '3/4'], ['v3', '1/8'], ['v4', '1/8']] },
    right: { mask: 'vertex-boundary', rows: [['v2', '6/8'], ['v1', '1/8'], ['v5', '1/8']] },
    said: /v3 \(row 2\) is not one of the old points the vertex point of v2 averages/,
    mark: 'vertex point of v2?',
  },
  'subdivision-catmull-clark-cube-corner': {
    wrong: { mask: 'vertex-interior', rows: cubeCorner().map(([v, w]) => [v, v === 'v1' ? '1/3' : w]) },
    right: { mask: 'vertex-interior', rows: cubeCorner() },
    said: /The weight of v1 \(row 1\) in the vertex point of v1 is not right/,
    mark: 'vertex point of v1?',
  },
  'subdivision-catmull-clark-cube-counts': {
    wrong: { counts: ['26', '36', '24'] },
    right: { counts: ['26', '48', '24'] },
    said: /The number of edges after one Catmull-Clark step is not right/,
  },
};
const valuesOf = (play) => (play.right.counts ? play.right.counts.filter((c, i) => c !== play.wrong.counts[i]) : [...new Set(play.right.rows.map(([, w]) => w))]);

const rowCount = (page) => page.locator('#exercise-weights tbody tr').count();

async function answerByKeyboard(page, answer) {
  if (answer.counts) {
    await page.locator('#exercise-count-vertices').focus();
    for (const [i, c] of answer.counts.entries()) {
      await page.keyboard.press('ControlOrMeta+a');
      await page.keyboard.type(c);
      if (i < 2) await page.keyboard.press('Tab');
    }
    await page.keyboard.press('Enter');
    return;
  }
  // The mask: arrow keys through the radio group until the one wanted is checked.
  await page.locator('input[name="exercise-mask"]').first().focus();
  await page.keyboard.press('Space');
  for (let i = 0; i < 5 && !(await page.locator(`#exercise-mask-${answer.mask}`).isChecked()); i += 1) await page.keyboard.press('ArrowDown');
  assert.equal(await page.locator(`#exercise-mask-${answer.mask}`).isChecked(), true);
  // The rows: Alt+Delete empties the grid, Alt+N adds a row after the one the focus is in.
  await page.locator('#exercise-weights tbody input').first().focus();
  for (let n = await rowCount(page); n > 1; n -= 1) await page.keyboard.press('Alt+Delete');
  await page.keyboard.press('Alt+Delete');
  for (const [i, [point, weight]] of answer.rows.entries()) {
    if (i > 0) await page.keyboard.press('Alt+n');
    await page.keyboard.press('ControlOrMeta+a');
    await page.keyboard.type(point);
    await page.keyboard.press('Tab');
    await page.keyboard.press('ControlOrMeta+a');
    await page.keyboard.type(weight);
  }
  assert.equal(await rowCount(page), answer.rows.length);
  await page.keyboard.press('Enter');
}

async function answerByPointer(page, answer) {
  if (answer.counts) {
    for (const [i, key] of ['vertices', 'edges', 'faces'].entries()) {
      await page.locator(`#exercise-count-${key}`).click();
      await page.locator(`#exercise-count-${key}`).fill(answer.counts[i]);
    }
    await page.locator('#exercise-check').click();
    return;
  }
  await page.locator(`label[for="exercise-mask-${answer.mask}"]`).click();
  // Remove every row with its ✕, then add the rows needed with "Add an old point".
  for (let n = await rowCount(page); n > 0; n -= 1) await page.locator('.exercise-remove-row').first().click();
  assert.equal(await rowCount(page), 1); // the grid keeps one empty row
  for (let i = 1; i < answer.rows.length; i += 1) await page.locator('#exercise-add-row').click();
  const inputs = page.locator('#exercise-weights tbody input');
  for (const [i, [point, weight]] of answer.rows.entries()) {
    await inputs.nth(2 * i).click();
    await inputs.nth(2 * i).fill(point);
    await inputs.nth(2 * i + 1).click();
    await inputs.nth(2 * i + 1).fill(weight);
  }
  await page.locator('#exercise-check').click();
}

for (const [id, play] of Object.entries(PLAYS)) {
  for (const [how, answer] of [['keyboard', answerByKeyboard], ['pointer', answerByPointer]]) {
    test(`${id}, by ${how}: wrong (named, no right value shown), then right`, async () => {
      const page = await env.openLesson(`${env.site.url}subdivision.html#exercise=${id}`);
      // The step panel (masks, weights, counts) and the tables are hidden; the drawing names
      // the old vertices and marks the asked point, and draws no weight.
      assert.equal(await page.locator('#step-panel').isVisible(), false);
      assert.equal(await page.locator('#tables-panel').isVisible(), false);
      const labels = await page.evaluate(() => window.wingspline.labelRects().map((r) => r.text));
      assert.ok(labels.includes('v1') && labels.includes('v2'), labels.join(' '));
      if (play.mark) assert.ok(labels.includes(play.mark), `the drawing marks "${play.mark}": ${labels.join(' ')}`);
      assert.equal(labels.some((t) => /\d\/\d|0\.\d/.test(t)), false, labels.join(' '));
      await answer(page, play.wrong);
      const wrong = await page.locator('#exercise-feedback').innerText();
      assert.match(wrong, /Not yet/);
      assert.match(wrong, play.said);
      for (const value of valuesOf(play)) assert.ok(!wrong.includes(value), `the feedback shows ${value}: ${wrong}`);
      // Nor does the page anywhere else (the typed answers are in inputs, not in its text).
      if (!play.right.counts) {
        const text = await page.locator('body').innerText();
        for (const value of valuesOf(play)) assert.ok(!text.includes(value), `the page shows ${value}`);
      }
      assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'started');
      await answer(page, play.right);
      assert.match(await page.locator('#exercise-feedback').innerText(), /✓ Right\./);
      assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'solved');
      assert.match(await page.locator('#exercise-status').innerText(), /2 checks/);
      assert.deepEqual(page.problems, []);
    });
  }
}

test('the worked answer gives the mask and every weight; the answer typed is kept over a reload', async () => {
  // (the gallery's copy is level check, with no worked answer: a lecturer's copy at level worked)
  const page = await env.openLesson(`${env.site.url}${exerciseAt('subdivision-loop-edge-point-e2', { level: 'worked' })}`);
  await answerByPointer(page, { mask: 'edge-interior', rows: [['v2', '3/8'], ['v3', '']] });
  assert.match(await page.locator('#exercise-feedback').innerText(), /Row 2: type the weight of v3/);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.locator('#exercise-mask-edge-interior').isChecked(), true);
  assert.equal(await page.locator('#exercise-weights tbody input').nth(1).inputValue(), '3/8');
  await page.locator('#exercise-show-worked').click();
  const lines = await page.locator('#exercise-worked li').allInnerTexts();
  assert.match(lines[0], /The edge point of e2 is made by the interior edge mask \(Loop\)/);
  for (const [v, w] of PLAYS['subdivision-loop-edge-point-e2'].right.rows) assert.ok(lines.some((l) => l.startsWith(`${v}: ${w}`)), `${v}: ${w} in ${lines.join(' | ')}`);
});

test('Make an exercise from the view: the edge point the drawing shows becomes a mask question that plays', async () => {
  const page = await env.openLesson(`${env.site.url}subdivision.html`);
  // The tetrahedron under Loop: Next phase skips the (empty) face points and shows the edge
  // points, the first one's mask drawn.
  await page.getByRole('button', { name: /Next phase/ }).click();
  await page.locator('[data-action="make-exercise"]').click();
  await page.locator('#author-kind').selectOption('subdivide');
  assert.equal(await page.locator('#author-field-ask').inputValue(), 'mask');
  assert.equal(await page.locator('#author-field-point-type').inputValue(), 'edge');
  assert.equal(await page.locator('#author-field-point-element').inputValue(), '1');
  await page.locator('#author-copy-link').click();
  await page.waitForSelector('#author-link:not([hidden])');
  assert.equal(await page.locator('.author-problem').innerText(), '');
  const played = await env.openLesson(await page.locator('#author-link').inputValue());
  assert.match(await played.locator('#exercise-question').innerText(), /new edge point from e1/);
  // The drawing shows the step's new points but no weight of the mask.
  const labels = await played.evaluate(() => window.wingspline.labelRects().map((r) => r.text));
  assert.ok(labels.includes('edge point of e1?'), labels.join(' '));
  assert.equal(labels.some((t) => /\d\/\d|0\.\d/.test(t)), false, labels.join(' '));
  // The tetrahedron's edges are interior: 3/8 of each end, 1/8 of each other corner. Which
  // corners are e1's ends is the question's data: the first row of the edge table of the
  // tetrahedron as the core builds it from its faces (the drawing's numbering).
  const built = api.buildMesh(api.generateMesh('tetrahedron'));
  const { edges } = built.wingedEdgeArrays();
  built.dispose();
  const ends = [edges[0], edges[1]];
  const rows = [0, 1, 2, 3].map((v) => [`v${v + 1}`, ends.includes(v) ? '3/8' : '1/8']);
  await answerByPointer(played, { mask: 'edge-boundary', rows });
  assert.match(await played.locator('#exercise-feedback').innerText(), /The mask chosen is not the one that makes the edge point of e1/);
  await answerByPointer(played, { mask: 'edge-interior', rows });
  assert.match(await played.locator('#exercise-feedback').innerText(), /✓ Right\./);
  assert.deepEqual(played.problems, []);
});

const axeSource = fs.readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
async function audit(page) {
  await page.evaluate(axeSource);
  const result = await page.evaluate(() => window.axe.run(document, { resultTypes: ['violations'] }));
  return result.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.id} (${v.impact}): ${v.help} at ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`);
}

for (const scheme of ['light', 'dark']) {
  for (const id of ['subdivision-loop-edge-point-e2', 'subdivision-catmull-clark-cube-counts']) {
    test(`axe (${scheme}): ${id} as opened, after a wrong check and with the worked answer; every control named`, async () => {
      const context = await env.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: scheme });
      const page = trap(await context.newPage());
      await page.goto(`${env.site.url}${exerciseAt(id, { level: 'worked' })}`);
      await page.waitForSelector('#exercise-panel');
      assert.deepEqual(await audit(page), [], 'as opened');
      const unnamed = await page.evaluate(() => [...document.querySelectorAll('#exercise-panel input, #exercise-panel button, #exercise-panel select')]
        .filter((el) => !(el.labels?.length || el.getAttribute('aria-label') || el.textContent.trim())).map((el) => el.outerHTML.slice(0, 80)));
      assert.deepEqual(unnamed, []);
      await (id.endsWith('counts') ? answerByPointer(page, { counts: ['1', '2', '3'] }) : answerByPointer(page, PLAYS[id].wrong));
      await page.locator('#exercise-show-worked').click();
      assert.deepEqual(await audit(page), [], 'after a check and the worked answer');
      assert.deepEqual(page.problems, []);
    });
  }
}
