// Edit playback read from the back row, and an edit's cost that teaches. Driven as a
// lecturer does: pick an element by its number, press the operation, then step through its
// assignments with the player's buttons, by pointer one way and by keyboard the other, at
// 1920 x 1080 presenting and at 1280 x 720 (normal and presenting). At every step the
// drawing, the current assignment line and the table cell it rewrote are inside the window
// and not covered (elementFromPoint at their centres). The costs are checked against the
// slide's tables counted by hand (tests/wasm/mesh/edit.test.mjs gives the reasoning).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();

const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

async function openLesson(viewport, present) {
  const page = await env.openPage(`${env.site.url}mesh.html`, { viewport });
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  if (present) {
    await page.click('[data-action=present]');
    await page.waitForFunction(() => document.documentElement.hasAttribute('data-present'));
  }
  await settle(page);
  return page;
}

// Picks an element by typing its number (1-based, as the tables write it) and runs `op`.
// corners: the two choices (vertex numbers) an operation needs besides the element.
async function edit(page, kind, number, op, corners = null) {
  await page.selectOption('#edit-kind', kind);
  await page.fill('#edit-element', String(number));
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(([k, n]) => document.querySelector('#edit-picked')?.textContent.includes(`${k === 'face' ? 'F' : k[0]}${n}`), [kind, number]);
  if (corners) {
    await page.selectOption('#edit-corner-a', String(corners[0] - 1));
    await page.selectOption('#edit-corner-b', String(corners[1] - 1));
  }
  await settle(page);
  assert.equal(await page.isEnabled(`button[data-op="${op}"]`), true, `${op} on ${kind} ${number}: ${await page.textContent('#edit-reasons')}`);
  // The operation's own key (its button's title names it), as a lecturer at the keyboard.
  const key = await page.$eval(`button[data-op="${op}"]`, (b) => /\((\w)\)/.exec(b.title)[1]);
  await page.evaluate(() => /** @type {HTMLElement} */ (document.activeElement)?.blur());
  await page.keyboard.press(key);
  await page.waitForFunction(() => window.wingspline.message().startsWith('Done:'));
  await settle(page);
}

const stepOf = (page) => page.$eval('#edit-step', (el) => el.textContent.split(' of ').map(Number));

// Where the three things a student must see are, and whether each is the topmost element at
// its centre; the cell is the one the assignment line names, at every step up to the last.
function boxes(page) {
  return page.evaluate(() => {
    const seen = (el) => {
      if (!el) return null;
      const r = el.getBoundingClientRect();
      const x = r.left + r.width / 2; const y = r.top + r.height / 2;
      const top = document.elementFromPoint(x, y);
      return {
        inside: r.width > 0 && r.height > 0 && r.left >= 0 && r.top >= 0 && r.right <= window.innerWidth && r.bottom <= window.innerHeight,
        uncovered: Boolean(top && (top === el || el.contains(top))),
        box: [Math.round(r.left), Math.round(r.top), Math.round(r.right), Math.round(r.bottom)],
      };
    };
    // The cell the line names ("Assignment 3: edge table, e9 · E:L: e3 → e10"): its table,
    // the row whose header reads e9, the column whose header reads E:L. It must be the cell
    // marked as read.
    const line = document.getElementById('edit-current')?.textContent ?? '';
    const named = /(vertex|edge|face) table, (\S+) · (\S+?): /.exec(line);
    let cell = null;
    let marked = false;
    if (named) {
      const table = document.getElementById(`we-${named[1]}-table`);
      // A column's name as the line writes it: the edge table's two head rows give "S:L"
      // (group S over its column L), "S" (a column under no group); a one-row head its text.
      const headRows = [...(table?.tHead?.rows ?? [])];
      const groups = [];
      if (headRows.length > 1) for (const th of headRows[0].cells) for (let k = 0; k < th.colSpan; k += 1) groups.push(th.textContent.trim());
      const names = [...(headRows.at(-1)?.cells ?? [])].map((th, k) => (groups[k] ? `${groups[k]}:` : '') + th.textContent.trim());
      const row = [...(table?.tBodies[0]?.rows ?? [])].find((tr) => tr.cells[0]?.textContent.trim().split(' ')[0] === named[2]);
      const column = names.indexOf(named[3].trim());
      cell = row && column >= 0 ? row.cells[column] ?? null : null;
      marked = Boolean(cell?.classList.contains('is-read'));
    }
    return {
      drawing: seen(document.getElementById('stage')),
      line: seen(document.getElementById('edit-current')),
      cell: seen(cell),
      named: named ? named.slice(1) : null,
      marked,
      lineText: line,
      scrolled: window.scrollY,
    };
  });
}

async function checkStep(page, where) {
  const [k, n] = await stepOf(page);
  const b = await boxes(page);
  assert.equal(b.scrolled, 0, `${where} step ${k}: the page itself does not scroll`);
  assert.ok(b.drawing.inside && b.drawing.uncovered, `${where} step ${k}: the drawing in view ${JSON.stringify(b.drawing)}`);
  assert.ok(b.line.inside && b.line.uncovered, `${where} step ${k}: the assignment line in view ${JSON.stringify(b.line)}`);
  if (k >= 1) assert.match(b.lineText, /table, /, `${where} step ${k}: the line names the table written`);
  if (k >= 1) {
    assert.ok(b.cell, `${where} step ${k} of ${n}: the cell the line names (${JSON.stringify(b.named)}) is drawn`);
    assert.ok(b.marked, `${where} step ${k} of ${n}: the cell the line names (${JSON.stringify(b.named)}) is the one marked`);
    assert.ok(b.cell.inside && b.cell.uncovered, `${where} step ${k} of ${n}: the rewritten cell in view ${JSON.stringify(b.cell)}`);
  }
}

// Every step forward by pointer (Step ▶), then every step back by keyboard (◀ Back, Enter).
// The way back is checked in full when `checkBack` (the first edit of each size): it is the
// same layout again, reached by another key.
async function playEveryStep(page, where, checkBack) {
  await page.click('#edit-restart');
  await page.waitForFunction(() => document.querySelector('#edit-step')?.textContent.startsWith('0 of'));
  const [, n] = await stepOf(page);
  assert.ok(n > 0, `${where}: the edit has assignments`);
  for (let k = 1; k <= n; k += 1) {
    await page.click('#edit-next');
    await page.waitForFunction((want) => document.querySelector('#edit-step')?.textContent.startsWith(`${want} of`), k);
    await settle(page);
    await checkStep(page, `${where} (pointer)`);
  }
  await page.focus('#edit-back');
  for (let k = n - 1; k >= 1; k -= 1) {
    await page.keyboard.press('Enter');
    await page.waitForFunction((want) => document.querySelector('#edit-step')?.textContent.startsWith(`${want} of`), k);
    if (!checkBack && k > 1) continue;
    await settle(page);
    await checkStep(page, `${where} (keyboard)`);
  }
  return n;
}

// The lecture's mesh, one edit of each operation (split face on the quad that joining the
// faces of e3 leaves: every face of the slide is a triangle).
const EDITS = [
  { name: 'flip e3', steps: [['edge', 3, 'flip-edge']] },
  { name: 'split e3', steps: [['edge', 3, 'split-edge']] },
  // F1 is then the quad v1 v2 v4 v3: split it by its diagonal v1-v4.
  { name: 'join e3 then split F1', steps: [['edge', 3, 'join-faces'], ['face', 1, 'split-face', [1, 4]]] },
  { name: 'join e5', steps: [['edge', 5, 'join-faces']] },
  { name: 'collapse e6', steps: [['edge', 6, 'collapse-edge']] },
  { name: 'poke F2', steps: [['face', 2, 'poke-face']] },
  { name: 'split v2', steps: [['vertex', 2, 'split-vertex', [1, 4]]] },
];

const SIZES = [
  { name: '1920x1080 presenting', viewport: { width: 1920, height: 1080 }, present: true },
  { name: '1280x720', viewport: { width: 1280, height: 720 }, present: false },
  { name: '1280x720 presenting', viewport: { width: 1280, height: 720 }, present: true },
];

for (const size of SIZES) {

  test(`${size.name}: every step of every edit shows the drawing, the assignment and the rewritten cell; the walk folds while it plays`, async () => {
    const page = await openLesson(size.viewport, size.present);
    for (const e of EDITS) {
      // Each edit on the slide's mesh: undo back to it first (Ctrl+Z, as a lecturer would).
      while (await page.evaluate(() => window.wingspline.state.ops.length)) {
        await page.keyboard.press('Control+z');
        await settle(page);
      }
      for (const [kind, number, op, corners] of e.steps) await edit(page, kind, number, op, corners);
      const n = await playEveryStep(page, `${size.name}, ${e.name}`, e === EDITS[0]);
      // The number of lines played equals the winged edge's writes in the cost table.
      const writes = await page.$eval('#edit-costs tr[data-representation="winged-edge"] td[data-cost=writes]', (td) => Number(td.textContent.replace(/,/g, '')));
      assert.equal(n, writes, `${e.name}: ${n} lines played, the winged edge wrote ${writes}`);
      assert.equal(await page.$$eval('#edit-steps li', (li) => li.length), n);
      // While it plays the walk is folded to its title; after the last assignment it is back.
      assert.equal(await page.isVisible('#walk-panel .walk-controls'), false, `${e.name}: the walk folds while the edit plays`);
      if (e.name === 'split e3') await screenshot(page, `edit-playback-${size.name.replace(/ /g, '-')}`);
      await page.click('#edit-end');
      await settle(page);
      assert.equal(await page.isVisible('#walk-panel .walk-controls'), true, `${e.name}: the walk is back after the edit`);
    }
    assert.deepEqual(page.problems, []);
  });
}

test('flip e3: reads and writes per representation as counted by hand on the slide, and the cost against mesh size drawn', async () => {
  const page = await openLesson({ width: 1280, height: 720 }, false);
  await edit(page, 'edge', 3, 'flip-edge');
  const costs = await page.$$eval('#edit-costs tbody tr', (rows) => Object.fromEntries(rows.map((r) => [r.dataset.representation,
    [Number(r.querySelector('[data-cost=reads]').textContent), Number(r.querySelector('[data-cost=writes]').textContent)]])));
  // Reads (the reasoning is in tests/wasm/mesh/edit.test.mjs): the winged edge 2 + 7 + 7;
  // the face table scans all 3 faces (13) and reads F1's and F2's sides (10); independent
  // faces compare coordinates (31 + 22); the three with faces stored per edge 2 + 10.
  // Writes: the winged edge's 18 (slide's tables against FLIP_E3: v3, F1 and 16 fields of
  // e1..e5); the face table's 4 (F1's v3 -> v4 and F2 listed anew).
  assert.deepEqual(costs['winged-edge'], [16, 18]);
  assert.deepEqual(costs['vertex-face-tables'], [23, 4]);
  assert.equal(costs['independent-faces'][0], 53);
  for (const rep of ['adjacency-lists', 'partial-adjacency-lists', 'edge-list']) assert.equal(costs[rep][0], 12, rep);
  // The words say the lesson: what the winged edge wrote and read, who had to search.
  const note = await page.textContent('#edit-cost-note');
  assert.match(note, /The winged edge wrote 18 entries .* and read 16 to find the faces on both sides of e3/);
  assert.match(note, /vertex and face tables \(23 read, 4 written\) had to search the whole mesh, all 3 faces/);
  // The chart: 4 sizes, the winged edge's series flat, the face table's growing.
  await screenshot(page, 'edit-costs-flip-e3');
  await page.focus('#edit-growth summary');
  await page.keyboard.press('Enter');
  const series = await page.$$eval('#edit-growth-table tbody tr', (rows) => Object.fromEntries(rows.map((tr) =>
    [tr.dataset.representation, [...tr.querySelectorAll('td')].map((td) => Number(td.textContent.replace(/,/g, '')))])));
  const heads = await page.$$eval('#edit-growth-table thead th', (th) => th.map((x) => x.textContent));
  assert.deepEqual(heads.slice(1), ['F = 968', 'F = 9,800', 'F = 100,352', 'F = 1,002,528']);
  assert.equal(series['winged-edge'].length, 4);
  assert.equal(new Set(series['winged-edge']).size, 1, `flat: ${series['winged-edge']}`);
  const vf = series['vertex-face-tables'];
  for (let k = 1; k < 4; k += 1) assert.ok(vf[k] > 9 * vf[k - 1], `the face table's search grows with F: ${vf}`);
  // The plot has pixels of its own (not a blank canvas).
  const inked = await page.$eval('#edit-growth-plot', (c) => {
    const g = c.getContext('2d'); const d = g.getImageData(0, 0, c.width, c.height).data;
    const colours = new Set(); for (let i = 0; i < d.length; i += 4 * 37) colours.add(`${d[i]},${d[i + 1]},${d[i + 2]}`);
    return colours.size;
  });
  assert.ok(inked > 3, `the chart is drawn (${inked} colours)`);
  // After the edit the column still gives the tables and the costs room (the walk shrinks).
  const room = await page.$eval('.panels-rest', (el) => el.getBoundingClientRect().height);
  assert.ok(room >= 150, `the column below the walk keeps room at 1280 x 720: ${room}px`);
  await screenshot(page, 'edit-costs-flip-e3-after');
  assert.deepEqual(page.problems, []);
});
