// The subdivision lesson on the lecture's mesh and the tetrahedron as a class sees them, the
// labels of Catmull-Clark's face points, and the reconnection played pointer by pointer.
// Expected values come from lecture 000's slide (v1..v5 at (0,1) (1,0) (1,2) (2,1) (2,-1)),
// from the numbering of one step (docs/api-mesh.md, "Subdivision": the halves of old edge e
// are 2e from S to the edge point V + e and 2e + 1 from it to E) and from the counts of one
// Loop step of the tetrahedron (218 entries: 10 vertex, 16 face, 24 x 8 edge), never from
// the page's own output.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser, screenshot } from '../../helpers/browser.mjs';
import { decodePng } from '../../helpers/png.mjs';

const env = useSiteAndBrowser();
const url = () => `${env.site.url}subdivision.html`;
const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
const labels = (page) => page.evaluate(() => window.wingspline.labelRects().map((r) => r.text));
const cellsOf = (page, id, label) => page.$$eval(`#${id} tbody tr[data-row]`, (rows, l) => rows.map((r) => [...r.children].map((c) => c.textContent.trim())).find((r) => r[0] === l), label);

for (const colorScheme of ['light', 'dark']) {
  test(`the lecture's mesh opens from the top as the slide draws it, every vertex labelled (${colorScheme})`, async () => {
    const page = await env.openLesson(url(), { viewport: { width: 1280, height: 720 }, colorScheme });
    await page.selectOption('#mesh-kind', 'lecture');
    await page.waitForFunction(() => window.wingspline.model?.counts.faces === 3);
    assert.deepEqual(await page.evaluate(() => window.wingspline.state.rotation), { yaw: 0, pitch: 0 });
    // Seen from the top, the drawing's x, y differ from vertex v1's as the slide's do.
    const slide = [[0, 1], [1, 0], [1, 2], [2, 1], [2, -1]];
    const drawn = await page.evaluate(() => Array.from(window.wingspline.model.projected));
    for (let v = 0; v < 5; v += 1) {
      assert.ok(Math.abs((drawn[3 * v] - drawn[0]) - (slide[v][0] - slide[0][0])) < 1e-12, `v${v + 1} x`);
      assert.ok(Math.abs((drawn[3 * v + 1] - drawn[1]) - (slide[v][1] - slide[0][1])) < 1e-12, `v${v + 1} y`);
    }
    await settle(page);
    const shown = await labels(page);
    for (const v of ['v1', 'v2', 'v3', 'v4', 'v5']) assert.ok(shown.includes(v), `${v} is labelled: ${shown.join(' ')}`);
    // The mesh has no interior vertex: the note says so, not "every interior vertex has valence 6".
    assert.match(await page.textContent('#extraordinary'), /No interior vertex: every vertex is on the boundary/);
    await screenshot(page, `subdivision-lecture-${colorScheme}`);
    assert.deepEqual(page.problems, []);
  });
}

test('the tetrahedron at level 0 in flat shading shows three faces in three shades', async () => {
  const page = await env.openLesson(url());
  await page.waitForFunction(() => window.wingspline.model?.counts.faces === 4);
  await settle(page);
  // The faces that face the viewer (their projected corners counter-clockwise on screen,
  // y up), and the middle of each on the screen.
  const faces = await page.evaluate(() => {
    const m = window.wingspline.model;
    const out = [];
    for (let f = 0; f < 4; f += 1) {
      const c = Array.from(m.faceVertices.subarray(m.faceOffsets[f], m.faceOffsets[f + 1])).map((v) => [m.projected[3 * v], m.projected[3 * v + 1]]);
      const area = (c[1][0] - c[0][0]) * (c[2][1] - c[0][1]) - (c[2][0] - c[0][0]) * (c[1][1] - c[0][1]);
      if (area > 0) out.push(window.wingspline.toClient((c[0][0] + c[1][0] + c[2][0]) / 3, (c[0][1] + c[1][1] + c[2][1]) / 3));
    }
    return out;
  });
  assert.equal(faces.length, 3, 'three faces face the viewer');
  const box = await page.locator('#stage').boundingBox();
  const png = decodePng(await page.screenshot({ clip: box }));
  const colour = (p) => { const x = Math.round(p.x - box.x); const y = Math.round(p.y - box.y); const i = 4 * (y * png.width + x); return [png.rgba[i], png.rgba[i + 1], png.rgba[i + 2]]; };
  const shades = faces.map(colour);
  for (let a = 0; a < 3; a += 1) {
    for (let b = a + 1; b < 3; b += 1) {
      const d = Math.max(...shades[a].map((x, k) => Math.abs(x - shades[b][k])));
      assert.ok(d >= 20, `faces ${a} and ${b} differ by ${d} levels: ${JSON.stringify(shades)}`);
    }
  }
  assert.deepEqual(page.problems, []);
});

test('Catmull-Clark\'s face points are labelled with their faces, its edge points with their edges', async () => {
  const page = await env.openLesson(url());
  await page.selectOption('#scheme', 'catmull-clark');
  await page.selectOption('#mesh-kind', 'cube');
  await page.waitForFunction(() => window.wingspline.state.meshKind === 'cube' && window.wingspline.model?.counts.faces === 6);
  await page.click('#phase-next');
  await page.waitForFunction(() => window.wingspline.state.phase === 1);
  await settle(page);
  let shown = await labels(page);
  for (const f of ['F1', 'F2', 'F3', 'F4', 'F5', 'F6']) assert.ok(shown.includes(f), `${f} names its face point: ${shown.join(' ')}`);
  assert.match(await page.textContent('#phase-list'), /face points \(6, each labelled with its face\)/);
  await page.click('#phase-next');
  await page.waitForFunction(() => window.wingspline.state.phase === 2);
  await settle(page);
  shown = await labels(page);
  // The cube's 12 edges; the face points keep their dots and give the names to the newest phase.
  for (let e = 1; e <= 12; e += 1) assert.ok(shown.includes(`e${e}`), `e${e} names its edge point: ${shown.join(' ')}`);
  assert.deepEqual(page.problems, []);
});

test('the reconnection plays pointer by pointer: empty tables filled entry by entry, by pointer and keyboard', async () => {
  const page = await env.openLesson(url());
  await page.waitForFunction(() => window.wingspline.model?.counts.faces === 4);
  // The old edge table (level 0): the halves of old e1 run from its S to the edge point v5
  // (V + e with V = 4, e = 0: index 4, v5 on screen) and from v5 to its E.
  const old = await page.evaluate(() => Array.from(window.wingspline.model.we.edges.subarray(0, 2)));
  const v = (i) => `v${i + 1}`;
  for (let k = 0; k < 3; k += 1) await page.click('#phase-next');
  await page.waitForFunction(() => window.wingspline.state.phase === 4);
  assert.match(await page.textContent('#reconnect-step'), /^218 of 218$/);
  await page.click('#reconnect-restart');
  await page.waitForFunction(() => window.wingspline.state.reconnect === 0);
  assert.match(await page.textContent('#reconnect-current'), /Nothing written yet/);
  // Before: the next level's tables are empty (the positions, computed in the phases before, stay).
  let e1 = await cellsOf(page, 'sub-edge-table', 'e1');
  assert.deepEqual(e1.slice(1), ['', '', '', '', '', '', '', '']);
  const vertexRow = await cellsOf(page, 'sub-vertex-table', 'v1');
  assert.equal(vertexRow[vertexRow.length - 1], '', 'v1 has no edge yet');
  // Step by pointer: the first half of old e1 gets S = old S.
  await page.click('#reconnect-next');
  await page.waitForFunction(() => window.wingspline.state.reconnect === 1);
  assert.equal(await page.textContent('#reconnect-current'), `old e1: edge table, e1 · S: — → ${v(old[0])}`);
  e1 = await cellsOf(page, 'sub-edge-table', 'e1');
  assert.deepEqual(e1.slice(1, 3), [v(old[0]), ''], 'S is written, E not yet');
  // The cell written last is marked.
  assert.equal(await page.$eval('#sub-edge-table tr[data-row="0"]', (r) => r.children[1].classList.contains('is-read')), true);
  // Step by keyboard (Enter on the focused Step button): E = the edge point v5.
  await page.focus('#reconnect-next');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.wingspline.state.reconnect === 2);
  assert.equal(await page.textContent('#reconnect-current'), 'old e1: edge table, e1 · E: — → v5');
  await page.keyboard.press('Enter');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.wingspline.state.reconnect === 4);
  assert.equal(await page.textContent('#reconnect-current'), `old e1: edge table, e2 · E: — → ${v(old[1])}`);
  // The lines count what is made: 4 of the 24 halves' ends (6 edges x 2 halves x 2).
  assert.match(await page.textContent('#reconnect-lines li[data-line="0"]'), /\(4 of 24\)/);
  assert.match(await page.textContent('#reconnect-lines'), /\(0 of 16\).*\(0 of 96\).*\(0 of 72\).*\(0 of 0\).*\(0 of 10\)/s);
  // The drawing marks the row written (e2) on the next level's mesh.
  await settle(page);
  assert.ok((await labels(page)).includes('e2'));
  // After: every entry written; the tables are the next level's (the same as before the playback).
  await page.click('#reconnect-end');
  await page.waitForFunction(() => window.wingspline.state.reconnect === 218);
  const finished = await page.evaluate(() => Array.from(window.wingspline.model.we.edges.subarray(0, 8)));
  e1 = await cellsOf(page, 'sub-edge-table', 'e1');
  const name = (k, x) => (x < 0 ? '—' : `${k < 2 ? 'v' : k < 4 ? 'F' : 'e'}${x + 1}`);
  assert.deepEqual(e1.slice(1), finished.map((x, k) => name(k, x)));
  assert.match(await page.textContent('#reconnect-lines'), /\(24 of 24\).*\(16 of 16\).*\(96 of 96\).*\(72 of 72\).*\(10 of 10\)/s);
  // Back one step: the vertex table's last entry (v10's edge) is empty again.
  await page.click('#reconnect-back');
  await page.waitForFunction(() => window.wingspline.state.reconnect === 217);
  const v10 = await cellsOf(page, 'sub-vertex-table', 'v10');
  assert.equal(v10[v10.length - 1], '');
  // Leaving the phase forgets the playback: back at the reconnection, the tables are whole.
  await page.click('#phase-prev');
  await page.waitForFunction(() => window.wingspline.state.phase === 3);
  assert.equal(await page.evaluate(() => window.wingspline.state.reconnect), -1);
  await screenshot(page, 'subdivision-reconnection');
  assert.deepEqual(page.problems, []);
});

test('a version-2 state (before the reconnection\'s playback) opens with the finished tables', async () => {
  const page = await env.openLesson(url());
  const state = await page.evaluate(() => window.wingspline.state);
  delete state.reconnect;
  const file = JSON.stringify({ format: 'wingspline', lesson: 'subdivision', version: 2, state: { ...state, phase: 4 } });
  await page.setInputFiles('#import-file', { name: 'old.json', mimeType: 'application/json', buffer: Buffer.from(file) });
  await page.waitForFunction(() => window.wingspline.state.phase === 4);
  assert.equal(await page.evaluate(() => window.wingspline.state.reconnect), -1);
  // The player says so once the panels follow the state (a frame later, at load 13 in CI).
  await page.waitForFunction(() => document.querySelector('#reconnect-step')?.textContent !== '', null, { timeout: 15000 });
  assert.match(await page.textContent('#reconnect-step'), /^218 of 218$/);
  assert.deepEqual(page.problems, []);
});

// On a projector and a laptop the player, the assignment it names and the cell it wrote are
// on screen and uncovered at every step (the side column scrolls to the cell below the
// player, which stays at its top). Steps 1-40 (the halves, the first faces' new faces and
// inner edges) and the last 12 (sides, vertex table) of the tetrahedron's 218.
for (const [width, height, present] of [[1920, 1080, true], [1280, 720, false], [1280, 720, true]]) {
  test(`the reconnection's cell, line and player stay in view at ${width} x ${height}${present ? ' presenting' : ''}`, async () => {
    const page = await env.openLesson(url(), { viewport: { width, height } });
    if (present) {
      await page.click('[data-action=present]');
      await page.waitForFunction(() => document.documentElement.hasAttribute('data-present'));
    }
    await page.waitForFunction(() => window.wingspline.model?.counts.faces === 4);
    for (let k = 0; k < 3; k += 1) await page.click('#phase-next');
    await page.waitForFunction(() => window.wingspline.state.phase === 4);
    await page.click('#reconnect-restart');
    const seen = () => page.evaluate(() => {
      const look = (el) => {
        if (!el) return null;
        const r = el.getBoundingClientRect();
        const top = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
        return { inside: r.width > 0 && r.left >= 0 && r.top >= 0 && r.right <= innerWidth && r.bottom <= innerHeight, uncovered: Boolean(top && (top === el || el.contains(top))) };
      };
      return { cell: look(document.querySelector('#tables-panel td.is-read')), line: look(document.getElementById('reconnect-current')), next: look(document.getElementById('reconnect-next')) };
    });
    const check = async (k) => {
      await page.waitForFunction((n) => window.wingspline.state.reconnect === n, k);
      await settle(page);
      const s = await seen();
      for (const what of ['cell', 'line', 'next']) assert.deepEqual(s[what], { inside: true, uncovered: true }, `step ${k}: the ${what} ${JSON.stringify(s)}`);
    };
    for (let k = 1; k <= 40; k += 1) { await page.click('#reconnect-next'); await check(k); }
    await page.click('#reconnect-end');
    await page.waitForFunction(() => window.wingspline.state.reconnect === 218);
    await page.focus('#reconnect-back');
    for (let k = 217; k >= 206; k -= 1) { await page.keyboard.press('Enter'); await check(k); }
    await screenshot(page, `subdivision-reconnection-${width}${present ? '-present' : ''}`);
    assert.deepEqual(page.problems, []);
  });
}
