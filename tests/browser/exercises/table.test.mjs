// Exercise kind 1: the slide's winged-edge tables, filled in by a student. A right
// answer in ANOTHER numbering (the slide's edges renumbered backwards, e5 walked the other
// way) typed cell by cell from the keyboard is accepted; one wrong cell is named with its
// row and column and marked; the worked answer is shown on request. The answers are built
// here from the slide's printed tables (tests/helpers/lecture-slide.mjs), not from the app.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { slideRows, SLIDE_VERTEX_EDGES, SLIDE_FACE_EDGES, FOLEY_EDGE_LIST, FOLEY_POLYGONS } from '../../helpers/lecture-slide.mjs';

const env = useSiteAndBrowser();
const FIELDS = ['S', 'E', 'L', 'R', 'SL', 'SR', 'EL', 'ER'];

// The slide's tables with the edges renumbered by `order` (student row r holds the slide's
// edge order[r]) and the edges of `flipped` walked the other way: S<->E, L<->R, S:L<->E:R,
// S:R<->E:L (the checker's definition; lecture 000 names the wings by the edge's ends).
function renumbered(order, flipped = []) {
  const rename = (e) => `e${order.indexOf(e) + 1}`;
  const none = (x) => (x === '-' ? 'none' : x);
  const rows = Object.fromEntries(slideRows().map((r) => [r.e, r]));
  const edges = order.map((e) => {
    let r = rows[e];
    if (flipped.includes(e)) r = { ...r, S: r.E, E: r.S, L: r.R, R: r.L, SL: r.ER, ER: r.SL, SR: r.EL, EL: r.SR };
    return [r.S, r.E, none(r.L), none(r.R), rename(r.SL), rename(r.SR), rename(r.EL), rename(r.ER)];
  });
  return { edges, vertices: SLIDE_VERTEX_EDGES.map(rename), faces: SLIDE_FACE_EDGES.map(rename) };
}

// Types every cell from the keyboard: the first cell focused, then Tab from cell to cell.
async function typeAnswer(page, answer) {
  const cells = [...answer.edges.flat(), ...answer.vertices, ...answer.faces];
  await page.locator('.exercise-grid input.cell').first().focus();
  for (const value of cells) {
    await page.keyboard.press('Control+a');
    await page.keyboard.type(value);
    await page.keyboard.press('Tab');
  }
}

const backwards = ['e7', 'e6', 'e5', 'e4', 'e3', 'e2', 'e1'];

test('the slide\'s tables in another numbering, with e5 walked the other way, typed by keyboard: right', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-winged-edge-slide`);
  assert.equal(await page.locator('#tables-panel').isVisible(), false);
  assert.equal(await page.locator('.exercise-grid input.cell').count(), 7 * 8 + 5 + 3);
  await typeAnswer(page, renumbered(backwards, ['e5']));
  await page.keyboard.press('Shift+Tab');
  await page.keyboard.press('Enter');
  assert.match(await page.locator('#exercise-feedback').innerText(), /^✓ Right\./);
  assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'solved');
  // Reload: the answer as typed comes back.
  await page.reload();
  await page.waitForSelector('#exercise-panel');
  assert.equal(await page.locator('.exercise-grid input[aria-label="e1 S"]').inputValue(), 'v4');
});

test('one wrong wing is named with its row and column and marked; the worked answer keeps the student\'s numbering', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-winged-edge-slide`);
  const answer = renumbered(backwards);
  // Row e3 of this numbering is the slide's e5 (S v2, E v4, S:L e3 -> here e5): write e4 instead.
  assert.equal(answer.edges[2][4], 'e5');
  answer.edges[2][4] = 'e4';
  await typeAnswer(page, answer);
  await page.locator('#exercise-check').click();
  const text = await page.locator('#exercise-feedback').innerText();
  // The self-study exercise (level worked) names where and the rule; the value only in the worked answer.
  assert.match(text, /Row e3, column S:L: this is not that wing\. Re-read: S:L is the other edge at S of the face on the Left/);
  assert.doesNotMatch(text, /\be5\b/);
  assert.equal(await page.locator('.exercise-grid input[aria-label="e3 S:L"]').getAttribute('aria-invalid'), 'true');
  assert.equal(await page.locator('.exercise-grid input[aria-invalid="true"]').count(), 1);
  assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'started');
  // By pointer: the cell clicked and fixed, then Check.
  await page.locator('.exercise-grid input[aria-label="e3 S:L"]').click();
  await page.keyboard.press('Control+a');
  await page.keyboard.type('e5');
  await page.locator('#exercise-check').click();
  assert.match(await page.locator('#exercise-feedback').innerText(), /^✓ Right\./);
  await page.locator('#exercise-show-worked').click();
  const worked = await page.locator('.exercise-worked table').first().locator('tbody tr').first().locator('td').allInnerTexts();
  // The worked row e1 of this numbering is the slide's e7: v4 v5, -, F3, wings renamed.
  assert.deepEqual(worked, ['v4', 'v5', 'none', 'F3', 'e4', 'e3', 'e2', 'e2']);
});

test('a cell that is not a label is said before anything is checked', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-winged-edge-slide`);
  await page.locator('.exercise-grid input[aria-label="e1 L"]').fill('F9');
  await page.locator('.exercise-grid input[aria-label="e1 S"]').fill('q');
  await page.locator('#exercise-check').click();
  const text = await page.locator('#exercise-feedback').innerText();
  assert.match(text, /e1 S: "q" is not a vertex \(write v1 to v5\)/);
  assert.match(text, /e1 L: "F9" is not a face of this mesh \(F1 to F3\)/);
  assert.match(await page.locator('#exercise-status').innerText(), /0 checks/);
});

test('the edge list of two polygons as lecture 001 prints it, renumbered E5..E1: right; a wrong polygon and a wrong side are marked', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-edge-list-foley`);
  // The student numbers the edges backwards: their E1 is the lecture's E5, and so on.
  const order = [4, 3, 2, 1, 0];
  const rename = (e) => `E${order.indexOf(Number(e.slice(1)) - 1) + 1}`;
  const rows = order.map((i) => FOLEY_EDGE_LIST[i]);
  const polygons = FOLEY_POLYGONS.map((p) => p.map(rename).join(' '));
  const type = async (cells) => {
    await page.locator('.exercise-grid input.cell').first().focus();
    for (const value of cells) {
      await page.keyboard.press('Control+a');
      await page.keyboard.type(value);
      await page.keyboard.press('Tab');
    }
  };
  await type([...rows.flat(), ...polygons]);
  await page.locator('#exercise-check').click();
  assert.match(await page.locator('#exercise-feedback').innerText(), /^✓ Right\./);
  // P2 lists the lecture's E1 (here E5) instead of E4 (here E2); E1's polygon is P2, not P1.
  await page.locator('.exercise-grid input[aria-label="P2 edges"]').fill(FOLEY_POLYGONS[1].map((e) => (e === 'E4' ? 'E1' : e)).map(rename).join(' '));
  await page.locator('.exercise-grid input[aria-label="E1 P₁"]').fill('P2');
  await page.locator('#exercise-check').click();
  assert.match(await page.locator('#exercise-feedback').innerText(), /Not yet/);
  assert.equal(await page.locator('.exercise-grid input[aria-label="P2 edges"]').getAttribute('aria-invalid'), 'true');
  assert.equal(await page.locator('.exercise-grid input[aria-label="E1 P₁"]').getAttribute('aria-invalid'), 'true');
});

test('an all-blank table is not counted as a check', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html#exercise=mesh-edge-list-foley`);
  await page.locator('#exercise-check').click();
  assert.match(await page.locator('#exercise-feedback').innerText(), /every cell is blank/);
  assert.match(await page.locator('#exercise-status').innerText(), /0 checks/);
});

test('adjacency lists after one Catmull-Clark step (subdivision lesson): a neighbour missing is named, then right', async () => {
  const page = await env.openLesson(`${env.site.url}subdivision.html#exercise=subdivision-catmull-clark-triangles`);
  assert.equal(await page.locator('.exercise-grid input.cell').count(), 11);
  // The neighbours a student reads off the drawing: the sides of the quads (the drawing's
  // labels are the core's numbering; the test reads the quads through the exercise's subject).
  const next = await page.evaluate(() => {
    const { faceOffsets, faceVertices } = window.wingspline.hooks.exercise.subject(window.wingspline.view, window.wingspline.model, window.wingspline.state, window.wingspline.ctx).mesh;
    const out = Array.from({ length: 11 }, () => new Set());
    for (let f = 0; f + 1 < faceOffsets.length; f += 1) {
      const q = Array.from(faceVertices.slice(faceOffsets[f], faceOffsets[f + 1]));
      q.forEach((v, i) => { const w = q[(i + 1) % q.length]; out[v].add(w); out[w].add(v); });
    }
    return out.map((s) => [...s].map((v) => `v${v + 1}`));
  });
  const cells = next.map((list) => list.join(', '));
  cells[0] = next[0].slice(1).join(', ');
  await page.locator('.exercise-grid input.cell').first().focus();
  for (const value of cells) {
    await page.keyboard.type(value);
    await page.keyboard.press('Tab');
  }
  await page.locator('#exercise-check').click();
  // Level check (the gallery's): the row and what is wrong, never the missing neighbour.
  const said = await page.locator('#exercise-feedback').innerText();
  assert.match(said, /Row v1: an entry is missing\. Re-read: the adjacency list of v1 holds every vertex joined to v1/);
  if (next[0][0] !== 'v1') assert.doesNotMatch(said, new RegExp(`\\b${next[0][0]}\\b`));
  assert.equal(await page.locator('.exercise-grid input[aria-label="v1 vertices"]').getAttribute('aria-invalid'), 'true');
  await page.locator('.exercise-grid input[aria-label="v1 vertices"]').fill(next[0].join(' '));
  await page.locator('.exercise-grid input[aria-label="v1 vertices"]').press('Enter');
  assert.match(await page.locator('#exercise-feedback').innerText(), /^✓ Right\./);
});
