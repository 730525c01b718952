// The half-edge tab of the mesh lesson, driven as a person would (the tab by keyboard, a
// half-edge row by pointer, an edge by its number), on the lecture's mesh. Every expected
// value is worked by hand below from the slide's winged-edge tables (lecture 000) and the
// numbering the page states (eₖ gives h₂ₖ₋₁ = S → E on its left face and h₂ₖ = E → S on its
// right), never read from the page or the core.
//
// The slide: e1 v1→v3 (L none, R F1; wings e2 e2 e4 e3), e2 v1→v2 (F1, none; e1 e1 e3 e6),
// e3 v2→v3 (F1, F2; e2 e5 e1 e4), e4 v3→v4 (none, F2; e1 e3 e7 e5), e5 v2→v4 (F2, F3; e3 e6
// e4 e7), e6 v2→v5 (F3, none; e5 e2 e7 e7), e7 v4→v5 (none, F3; e4 e5 e6 e6).
// By hand: next(h₂ₖ₋₁) is the half-edge of E:L that starts at E; prev(h₂ₖ₋₁) the half-edge of
// S:L that ends at S; next(h₂ₖ) the half-edge of S:R that starts at S; prev(h₂ₖ) the half-edge
// of E:R that ends at E. So:
//   h5 (e3, v2→v3, F1): next = e1 from v3 = h2, prev = e2 into v2 = h3, twin h6;
//   h6 (e3, v3→v2, F2): next = e5 from v2 = h9, prev = e4 into v3 = h8, twin h5;
//   h1 (e1, v1→v3, boundary): next = e4 from v3 = h7; the boundary loop h1 h7 h13 h12 h4
//   (v1 v3 v4 v5 v2), so prev(h1) = h4.
// A boundary vertex stores its boundary half-edge: v1 h1, v2 h4, v3 h7, v4 h13, v5 h12.
// Around v2 from e6 (the slide's walk e6, e5, e3, e2): h11 (e6 from v2), prev = h10, twin h9
// (e5), prev(h9) = h6, twin h5 (e3), prev(h5) = h3, twin h4 (e2).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();
const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

async function openHalfEdgeTab(viewport = { width: 1280, height: 800 }) {
  const page = await env.openPage(`${env.site.url}mesh.html`, { viewport });
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  // By keyboard: the tab list's arrows from the winged edge to the half-edge tab.
  await page.focus('#tab-winged');
  await page.click('#tab-winged');
  const order = await page.$$eval('[role=tab]', (tabs) => tabs.map((t) => t.id));
  for (let k = order.indexOf('tab-winged'); k < order.indexOf('tab-half-edge'); k += 1) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.querySelector('#tab-half-edge')?.getAttribute('aria-selected') === 'true');
  await settle(page);
  return page;
}

// The half-edge tab open, e3 picked by its number and flipped with the edit panel's button.
async function flipE3OnHalfEdgeTab() {
  const page = await openHalfEdgeTab();
  await page.selectOption('#edit-kind', 'edge');
  await page.fill('#edit-element', '3');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: e3');
  await page.click('button[data-op="flip-edge"]');
  await page.waitForFunction(() => window.wingspline.state.ops.length === 1);
  return page;
}

const rowOf = (page, table, label) => page.$eval(`#${table}`, (t, want) => {
  const tr = [...t.tBodies[0].rows].find((r) => r.cells[0].textContent.trim() === want);
  return tr ? [...tr.cells].slice(1).map((c) => c.textContent.trim()) : null;
}, label);

test('the half-edge tables of the lecture mesh, worked by hand from the slide', async () => {
  const page = await openHalfEdgeTab();
  //                                    origin target face  next  prev  twin
  assert.deepEqual(await rowOf(page, 'he-halfedge-table', 'h5'), ['v2', 'v3', 'F1', 'h2', 'h3', 'h6']);
  assert.deepEqual(await rowOf(page, 'he-halfedge-table', 'h6'), ['v3', 'v2', 'F2', 'h9', 'h8', 'h5']);
  assert.deepEqual(await rowOf(page, 'he-halfedge-table', 'h1'), ['v1', 'v3', '—', 'h7', 'h4', 'h2']);
  assert.equal(await page.$$eval('#he-halfedge-table tbody tr[data-row]', (r) => r.length), 14, '2E = 14 half-edges');
  for (const [v, he] of [['v1', 'h1'], ['v2', 'h4'], ['v3', 'h7'], ['v4', 'h13'], ['v5', 'h12']]) {
    assert.deepEqual(await rowOf(page, 'he-vertex-table', v), [he], `${v}'s half-edge is its boundary one`);
  }
  // A face's half-edge lies on the face.
  for (const f of ['F1', 'F2', 'F3']) {
    const [he] = await rowOf(page, 'he-face-table', f);
    assert.equal((await rowOf(page, 'he-halfedge-table', he))[2], f, `${f}'s half-edge ${he} is on ${f}`);
  }
  // The walk around v2 (the lesson's walk) in half-edge terms meets the slide's ring.
  const walk = await page.$$eval('#he-walk tbody tr', (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent.trim())));
  assert.deepEqual(walk.map((r) => r[1]), ['h11', 'h9', 'h5', 'h4']);
  assert.deepEqual(walk.map((r) => r[4]), ['e6', 'e5', 'e3', 'e2']);
  assert.deepEqual(walk.map((r) => r[5]), ['e6', 'e5', 'e3', 'e2'], 'the winged-edge walk, step for step');
  assert.match(walk[0][2], /^prev\(h11\) = h10$/);
  assert.match(await page.textContent('#he-walk-note'), /the same edges in the same order/);
  assert.deepEqual(page.problems, []);
});

test('the correspondence: a half-edge row picked by pointer shows its edge\'s winged-edge row as half-edge expressions', async () => {
  const page = await openHalfEdgeTab();
  // h6 is e3's E → S half: a click picks e3.
  await page.click('#he-halfedge-table tr[data-row="5"] th');
  await page.waitForFunction(() => /Edge e3 in both structures/.test(document.querySelector('#he-correspondence-title')?.textContent ?? ''));
  const rows = await page.$$eval('#he-correspondence tbody tr', (trs) => trs.map((r) => [...r.cells].map((c) => c.textContent.trim())));
  assert.deepEqual(rows.map((r) => r[0]), ['S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R']);
  // Stored (the slide's e3 row) and the value of each expression, by hand above.
  assert.deepEqual(rows.map((r) => r[1]), ['v2', 'v3', 'F1', 'F2', 'e2', 'e5', 'e1', 'e4']);
  assert.deepEqual(rows.map((r) => r[3]), ['v2', 'v3', 'F1', 'F2', 'e2 (h3)', 'e5 (h9)', 'e1 (h2)', 'e4 (h8)']);
  assert.equal(rows[4][2], 'edge of prev(h)');
  // Both halves of the picked edge are marked in the half-edge table.
  assert.deepEqual(await page.$$eval('#he-halfedge-table tr.is-picked', (trs) => trs.map((r) => r.cells[0].textContent.trim())), ['h5', 'h6']);
  await screenshot(page, 'half-edge-tab-1280');
  assert.deepEqual(page.problems, []);
});

test('after a flip of e3 (and its undo) the half-edge rows and the correspondence follow the winged edge', async () => {
  const page = await flipE3OnHalfEdgeTab();
  await page.click('#tab-half-edge');
  await settle(page);
  // The flip turns e3 into the other diagonal of the quad v1 v2 v4 v3: the slide's tables
  // after it (lecture 000's flip, tests/helpers/lecture-slide.mjs FLIP_E3) have e3 = v4 → v1.
  const h5 = await rowOf(page, 'he-halfedge-table', 'h5');
  assert.deepEqual(h5.slice(0, 2), ['v4', 'v1']);
  assert.equal(h5[5], 'h6');
  // The correspondence of e3, picked by its S → E row.
  await page.click('#he-halfedge-table tr[data-row="4"] th');
  await page.waitForFunction(() => /Edge e3 in both/.test(document.querySelector('#he-correspondence-title')?.textContent ?? ''));
  const rows = await page.$$eval('#he-correspondence tbody tr', (trs) => trs.map((r) => [...r.cells].map((c) => c.textContent.trim())));
  for (const r of rows) assert.equal(r[3].split(' ')[0], r[1], `${r[0]}: the expression's value is what the winged edge stores`);
  assert.deepEqual(rows.slice(0, 2).map((r) => r[1]), ['v4', 'v1']);
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => window.wingspline.state.ops.length === 0);
  await settle(page);
  assert.deepEqual(await rowOf(page, 'he-halfedge-table', 'h5'), ['v2', 'v3', 'F1', 'h2', 'h3', 'h6']);
  assert.deepEqual(page.problems, []);
});

test('storage and queries list the half-edge beside the lecture\'s representations', async () => {
  const page = await env.openPage(`${env.site.url}mesh.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await page.click('#tab-storage');
  await settle(page);
  // V = 5, E = 7, F = 3: 3V coordinates (8 bytes) and, as int32, origin, face, next and prev
  // per half-edge (4 x 2E) and one half-edge per vertex and per face: 15 + 56 + 5 + 3 = 79
  // entries, 15 x 8 + 64 x 4 = 376 bytes.
  const cells = await page.$eval('#storage-table tr[data-representation="half-edge"]', (tr) => [...tr.cells].map((c) => c.textContent.trim()));
  assert.equal(cells[1], '79');
  assert.equal(cells[2], '376');
  await page.click('#tab-queries');
  await settle(page);
  // Faces around v2 (the lesson's first query): the slide's three faces, whichever the first.
  const answer = await page.$eval('#query-table tr[data-representation="half-edge"]', (tr) => tr.cells[1].textContent.trim());
  assert.deepEqual(answer.split(', ').sort(), ['F1', 'F2', 'F3']);
  assert.deepEqual(page.problems, []);
});

// The walk around v2 from e6, by hand (header): h11, then prev(h11) = h10 and twin h9; prev(h9)
// = h6, twin h5; prev(h5) = h3, twin h4; prev(h4) = h12 (the boundary loop h1 h7 h13 h12 h4),
// twin h11 = h0. One read per step here; the winged-edge walk reads two (the S test, the wing).
test('the walk in half-edge terms plays with the walk player, by keyboard and pointer: row, pseudocode line, cell read, reads counted', async () => {
  const page = await openHalfEdgeTab();
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('Home');
  await settle(page);
  const now = () => page.textContent('#he-walk-now');
  const lines = () => page.$$eval('#he-walk-code li.is-current', (lis) => lis.map((li) => li.dataset.line));
  const marked = () => page.$$eval('#he-halfedge-table tr.is-highlighted', (trs) => trs.map((r) => [r.cells[0].textContent.trim(), [...r.cells].findIndex((c) => c.classList.contains('is-read')), r.querySelector('.is-read')?.textContent.trim() ?? null]));
  const walkRow = () => page.$$eval('#he-walk tbody tr.is-highlighted', (trs) => trs.map((r) => r.cells[1].textContent.trim()));
  assert.deepEqual(await lines(), ['0']);
  assert.match(await now(), /^Start at h11\. Reads so far: 1 here, 1 in the winged-edge walk\.$/);
  assert.deepEqual(await marked(), []);
  const expected = [['h11', 'h10', 'h9', 'e6'], ['h9', 'h6', 'h5', 'e5'], ['h5', 'h3', 'h4', 'e3'], ['h4', 'h12', 'h11', 'e2']];
  for (const [k, [he, prev, twin, edge]] of expected.entries()) {
    // Steps 1 and 3 by the keyboard (n, PageDown), 2 and 4 by the player's button.
    if (k % 2 === 0) await page.keyboard.press(k === 0 ? 'n' : 'PageDown');
    else await page.getByRole('button', { name: 'Step forward (→ or PageDown)' }).click();
    await settle(page);
    assert.deepEqual(await lines(), ['1', '2'], `step ${k + 1}: the Repeat body is the current line`);
    assert.deepEqual(await walkRow(), [he]);
    // Column 5 of the half-edge table is prev: the cell read, holding prev(h).
    assert.deepEqual(await marked(), [[he, 5, prev]], `step ${k + 1}`);
    assert.equal(await now(), `Step ${k + 1}: report ${edge}; read prev(${he}) = ${prev}; its twin is ${twin}. Reads so far: ${k + 2} here, ${2 * k + 3} in the winged-edge walk.`);
  }
  await page.keyboard.press('n');
  await settle(page);
  assert.deepEqual(await lines(), ['4']);
  assert.match(await now(), /^Back at h11 = h₀: 4 edges met\. Reads so far: 5 here, 9 in the winged-edge walk\.$/);
  assert.deepEqual(await marked(), []);
  // Back one step (b): the fourth step again.
  await page.keyboard.press('b');
  await settle(page);
  assert.deepEqual(await marked(), [['h4', 5, 'h12']]);
  assert.deepEqual(page.problems, []);
});

test('a half-edge row picked by pointer names the four winged-edge fields it replaces; an edge picked by keyboard names none', async () => {
  const page = await openHalfEdgeTab();
  const replaced = () => page.$$eval('#he-correspondence tbody tr.is-highlighted', (trs) => trs.map((r) => r.dataset.field));
  // h6 = e3's E → S half (on F2): E (its origin), R (its face), S:R (next), E:R (prev).
  await page.click('#he-halfedge-table tr[data-row="5"] th');
  await page.waitForFunction(() => /^h6 /.test(document.querySelector('#he-correspondence-note')?.textContent ?? ''));
  assert.equal(await page.textContent('#he-correspondence-note'), 'h6 (E → S, on the right face) replaces the winged-edge fields E, R, S:R, E:R: its origin, its face, and the edges of prev and next; the other four are its twin\'s.');
  assert.deepEqual(await replaced(), ['end', 'right', 'startRight', 'endRight']);
  // h5 = e3's S → E half (on F1): S, L, S:L (prev), E:L (next).
  await page.click('#he-halfedge-table tr[data-row="4"] th');
  await page.waitForFunction(() => /^h5 /.test(document.querySelector('#he-correspondence-note')?.textContent ?? ''));
  assert.deepEqual(await replaced(), ['start', 'left', 'startLeft', 'endLeft']);
  // e5 picked by its number (keyboard): the edge, not a half: both halves' fields, none marked.
  await page.focus('#edit-element');
  await page.keyboard.press('Control+a');
  await page.keyboard.type('5');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => /Edge e5 in both/.test(document.querySelector('#he-correspondence-title')?.textContent ?? ''));
  assert.deepEqual(await replaced(), []);
  assert.match(await page.textContent('#he-correspondence-note'), /^Pick an edge/);
  assert.deepEqual(page.problems, []);
});

// Flip e3 in half-edge terms, by hand from the rows above and the flipped slide (e3 = v4 → v1,
// F1 = v1 v2 v4 on its left, F2 = v4 v3 v1 on its right; lecture-slide.mjs FLIP_E3):
//   h5 (e3, now v4 → v1 on F1): origin v2 → v4, next h2 → h3, prev h3 → h9;
//   h6 (now v1 → v4 on F2): origin v3 → v1, next h9 → h8, prev h8 → h2;
//   h2 (e1, v3 → v1, now on F2): face F1 → F2, next h3 → h6, prev h5 → h8;
//   h3 (e2, v1 → v2 on F1): next h5 → h9, prev h2 → h5;   h8 (e4, v4 → v3 on F2): next h6 → h2, prev h9 → h6;
//   h9 (e5, v2 → v4, now on F1): face F2 → F1, next h8 → h5, prev h6 → h3;
//   F1 stores e3, whose S → E lies on it: h2 → h5. Every vertex keeps its boundary half-edge.
// 17 entries; the winged edge writes 18 (tests/wasm/mesh/edit.test.mjs counts them by hand).
// Cells as [table, row, column (1 origin, 3 face, 4 next, 5 prev; 1 a vertex's or face's
// half-edge)] -> [before, after].
const FLIP_E3_CELLS = {
  'he-halfedge-table h5 1': ['v2', 'v4'], 'he-halfedge-table h5 4': ['h2', 'h3'], 'he-halfedge-table h5 5': ['h3', 'h9'],
  'he-halfedge-table h6 1': ['v3', 'v1'], 'he-halfedge-table h6 4': ['h9', 'h8'], 'he-halfedge-table h6 5': ['h8', 'h2'],
  'he-halfedge-table h2 3': ['F1', 'F2'], 'he-halfedge-table h2 4': ['h3', 'h6'], 'he-halfedge-table h2 5': ['h5', 'h8'],
  'he-halfedge-table h3 4': ['h5', 'h9'], 'he-halfedge-table h3 5': ['h2', 'h5'],
  'he-halfedge-table h8 4': ['h6', 'h2'], 'he-halfedge-table h8 5': ['h9', 'h6'],
  'he-halfedge-table h9 3': ['F2', 'F1'], 'he-halfedge-table h9 4': ['h8', 'h5'], 'he-halfedge-table h9 5': ['h6', 'h3'],
  'he-face-table F1 1': ['h2', 'h5'],
};

test('flip e3 played back in half-edge terms, by keyboard and pointer: each hand-worked cell marked once, as it is assigned; the counts of both structures', async () => {
  const page = await flipE3OnHalfEdgeTab();
  await settle(page);
  assert.match(await page.textContent('#edit-written'), /winged edge 18, half-edge 17\b/);
  // Before the edit: the half-edge tables of the slide (worked at the top of this file).
  await page.click('#edit-restart');
  await page.waitForFunction(() => document.querySelector('#edit-step')?.textContent === '0 of 17');
  assert.deepEqual(await rowOf(page, 'he-halfedge-table', 'h5'), ['v2', 'v3', 'F1', 'h2', 'h3', 'h6']);
  assert.deepEqual(await rowOf(page, 'he-face-table', 'F1'), ['h2']);
  const cellText = (key) => page.evaluate((k) => {
    const [id, label, column] = k.split(' ');
    const tr = [...document.getElementById(id).tBodies[0].rows].find((r) => r.cells[0].textContent.trim() === label);
    return tr.cells[Number(column)].textContent.trim();
  }, key);
  for (const [key, [before]] of Object.entries(FLIP_E3_CELLS)) assert.equal(await cellText(key), before, `${key} before the flip`);
  const marked = () => page.$$eval('#he-halfedge-table td.is-read, #he-vertex-table td.is-read, #he-face-table td.is-read',
    (cells) => cells.map((c) => `${c.closest('table').id} ${c.parentElement.children[0].textContent.trim()} ${[...c.parentElement.children].indexOf(c)}`));
  const seen = [];
  for (let k = 1; k <= 17; k += 1) {
    // Odd steps by keyboard (Enter on the focused Step button), even ones by pointer.
    if (k % 2) {
      await page.focus('#edit-next');
      await page.keyboard.press('Enter');
    } else {
      await page.click('#edit-next');
    }
    await page.waitForFunction((want) => document.querySelector('#edit-step')?.textContent === `${want} of 17`, k);
    await settle(page);
    // One cell marked while the edit plays; at its last step the walk's cell (around v2) is
    // marked again beside it, as on the winged-edge tab.
    const cells = await marked();
    if (k < 17) assert.equal(cells.length, 1, `step ${k}: one cell is being assigned`);
    const fresh = cells.filter((c) => c in FLIP_E3_CELLS && !seen.includes(c));
    assert.equal(fresh.length, 1, `step ${k}: one cell the flip changes, not assigned before: ${cells}`);
    const [key] = fresh;
    seen.push(key);
    // The cell shows its new value, and the step's line says the same.
    const [before, after] = FLIP_E3_CELLS[key];
    assert.equal(await cellText(key), after, `step ${k}: ${key}`);
    const field = { 1: key.startsWith('he-halfedge') ? 'origin' : 'half-edge', 3: 'face', 4: 'next', 5: 'prev' }[key.split(' ')[2]];
    const [, row] = key.split(' ');
    // (followed by the winged-edge line it follows, in brackets, when there is one)
    assert.match(await page.textContent('#edit-current'), new RegExp(`: [a-z-]+ table, ${row} · ${field}: ${before} → ${after}( \\(|$)`));
    // The cell is scrolled into the side column's view.
    const inView = await page.evaluate((k) => {
      const [id, label, column] = k.split(' ');
      const tr = [...document.getElementById(id).tBodies[0].rows].find((r) => r.cells[0].textContent.trim() === label);
      const r = tr.cells[Number(column)].getBoundingClientRect();
      return r.top >= 0 && r.bottom <= window.innerHeight;
    }, key);
    assert.ok(inView, `step ${k}: ${key} is in view`);
    if (k === 6) await screenshot(page, 'half-edge-edit-playback-1280');
  }
  assert.equal(seen.length, Object.keys(FLIP_E3_CELLS).length, 'every hand-worked cell was assigned');
  // The rows after the flip, by hand above.
  assert.deepEqual(await rowOf(page, 'he-halfedge-table', 'h5'), ['v4', 'v1', 'F1', 'h3', 'h9', 'h6']);
  // The winged-edge tab plays the same edit's 18 assignments.
  await page.click('#tab-winged');
  await page.waitForFunction(() => / of 18$/.test(document.querySelector('#edit-step')?.textContent ?? ''));
  assert.deepEqual(page.problems, []);
});
