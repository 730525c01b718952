// A picked element that the next mesh does not have (another mesh chosen, or undo back to a
// smaller one) is dropped, never asked of the core: a student picks F6 of the grid with the
// pointer, then chooses the tetrahedron from the Mesh menu; later picks F6 again and presses
// Ctrl+Z back to the tetrahedron. Each time the page raises no error, every table shows the
// tetrahedron's rows and the Euler line its counts. The tetrahedron's numbers are counted by
// hand: 4 vertices, 6 edges, 4 triangles, closed (V - E + F = 4 - 6 + 4 = 2).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { clickToPick } from '../../helpers/mesh-page.mjs';

const env = useSiteAndBrowser();
const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
const rowLabels = (page, id) => page.$$eval(`#${id} tbody tr[data-row]`, (rows) => rows.map((r) => r.children[0].textContent.trim()));

// The client point of face f's centroid (asked of the page: where the face is drawn, not
// what it holds).
async function faceInside(page, f) {
  return page.evaluate((face) => {
    const m = window.wingspline.model;
    const corners = Array.from(m.faceVertices.slice(m.faceOffsets[face], m.faceOffsets[face + 1]));
    const P = m.projected;
    const cx = corners.reduce((s, v) => s + P[3 * v], 0) / corners.length;
    const cy = corners.reduce((s, v) => s + P[3 * v + 1], 0) / corners.length;
    return window.wingspline.toClient(cx, cy);
  }, f);
}

async function pickFaceWithPointer(page, f) {
  await clickToPick(page, await faceInside(page, f), `F${f + 1}`);
}

async function chooseGrid(page) {
  await page.selectOption('#mesh-kind', 'grid');
  // The default grid: 4 x 3 squares, each split into two triangles.
  await page.waitForFunction(() => document.querySelectorAll('#we-face-table tbody tr[data-row]').length === 24);
  await settle(page);
}

async function expectTetrahedron(page, what) {
  // (not there in time: the assertions below say what the page shows instead)
  await page.waitForFunction(() => /4 − 6 \+ 4 = 2/.test(document.querySelector('#edit-euler')?.textContent ?? ''), null, { timeout: 5000 })
    .catch(() => {});
  await settle(page);
  assert.deepEqual(page.problems, [], `${what}: no page error`);
  assert.match(await page.textContent('#edit-euler'), /^V − E \+ F: 4 − 6 \+ 4 = 2 /, `${what}: the Euler line`);
  assert.deepEqual(await rowLabels(page, 'we-vertex-table'), ['v1', 'v2', 'v3', 'v4'], `${what}: vertex table`);
  assert.deepEqual(await rowLabels(page, 'we-edge-table'), ['e1', 'e2', 'e3', 'e4', 'e5', 'e6'], `${what}: edge table`);
  assert.deepEqual(await rowLabels(page, 'we-face-table'), ['F1', 'F2', 'F3', 'F4'], `${what}: face table`);
  // The independent faces tab too: one row per triangle.
  await page.click('#tab-faces');
  await settle(page);
  assert.deepEqual(await rowLabels(page, 'independent-face-table'), ['F1', 'F2', 'F3', 'F4'], `${what}: independent faces`);
  await page.click('#tab-winged');
  await settle(page);
  // The pick is gone, and the panel says why; no operation is offered for a face it has not.
  const picked = await page.textContent('#edit-picked');
  assert.match(picked, /^Nothing picked \(F6 is not in this mesh: it has faces F1 to F4\)$/, `${what}: the edit panel`);
  assert.deepEqual(await page.$$eval('#edit-panel button[data-op]:not([hidden])', (b) => b.filter((x) => !x.disabled).map((x) => x.dataset.op)), [], `${what}: no operation enabled`);
  assert.deepEqual(page.problems, [], `${what}: no page error after the tabs`);
}

test('F6 picked on the grid, then the tetrahedron chosen or undone to: no error, the tetrahedron\'s tables', async () => {
  const page = await env.openPage(`${env.site.url}mesh.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await chooseGrid(page);
  await pickFaceWithPointer(page, 5);

  await page.selectOption('#mesh-kind', 'tetrahedron');
  await expectTetrahedron(page, 'tetrahedron chosen from the menu');

  // Back to the grid (one undoable step), pick F6 again, then undo with the keyboard.
  await chooseGrid(page);
  await pickFaceWithPointer(page, 5);
  await page.focus('body');
  await page.keyboard.press('Control+z');
  await expectTetrahedron(page, 'undo back to the tetrahedron');

  // Redo brings the grid back: F6 exists again but was dropped, so nothing is picked and the
  // grid's own counts show (20 vertices, 43 edges, 24 triangles: 4 x 3 squares, one diagonal each).
  await page.keyboard.press('Control+y');
  await page.waitForFunction(() => document.querySelectorAll('#we-face-table tbody tr[data-row]').length === 24);
  await settle(page);
  assert.match(await page.textContent('#edit-euler'), /^V − E \+ F: 20 − 43 \+ 24 = 1 /);
  assert.equal(await page.textContent('#edit-picked'), 'Nothing picked');
  assert.deepEqual(page.problems, []);
});

test('a face removed by an edit cannot be picked from its struck-through row, and a query of it is said', async () => {
  const page = await env.openPage(`${env.site.url}mesh.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  // The lecture mesh: F1 and F2 share e3; joining them across e3 removes F2 (a gap).
  await page.selectOption('#edit-kind', 'edge');
  await page.fill('#edit-element', '3');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: e3');
  await page.click('button[data-op="join-faces"]');
  await page.waitForFunction(() => window.wingspline.message().startsWith('Done: '));
  await settle(page);
  // The struck-through row of the removed face, clicked: nothing picked, and said.
  const gapRow = await page.$$eval('#we-face-table tbody tr[data-row].is-gap', (rows) => rows.map((r) => r.children[0].textContent.trim()));
  assert.equal(gapRow.length, 1, 'one face row is a gap');
  await page.click(`#we-face-table tbody tr[data-row].is-gap`);
  await settle(page);
  assert.match(await page.evaluate(() => window.wingspline.message()), new RegExp(`^${gapRow[0]} was removed by an edit`));
  assert.notEqual(await page.textContent('#edit-picked'), `Picked: ${gapRow[0]}`);
  // The query tab asked about the removed face: said, not thrown.
  await page.click('#tab-queries');
  await page.selectOption('#query-kind', 'edges-of-face');
  await page.fill('#query-element', gapRow[0].slice(1));
  await page.press('#query-element', 'Enter');
  await page.waitForFunction(() => !document.querySelector('#query-removed')?.hidden);
  assert.match(await page.textContent('#query-removed'), new RegExp(`^${gapRow[0]} was removed by an edit`));
  // The walk along it too.
  await page.selectOption('#walk-kind', 'face');
  await page.fill('#walk-element', gapRow[0].slice(1));
  await page.press('#walk-element', 'Enter');
  await page.waitForFunction((label) => document.querySelector('#walk-text')?.textContent.startsWith(`${label} was removed by an edit`), gapRow[0]);
  assert.deepEqual(page.problems, []);
});
