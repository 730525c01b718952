// The mesh lesson driven as a person would: the lecture's tables on screen, a dragged
// vertex, the CCW walk around v2 by keyboard, a bad OFF file, a reload, the 3D view and a
// large mesh. Expected values are the slide's (lecture 000), never the page's own output.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { drag, handle } from '../../helpers/pointer.mjs';

// Lecture 000, "Winged Edge": the slide's tables, entry for entry ('' = no face: boundary).
const SLIDE_EDGE_TABLE = [
  //  e     S     E     L     R    S:L   S:R   E:L   E:R
  ['e1', 'v1', 'v3', '', 'F1', 'e2', 'e2', 'e4', 'e3'],
  ['e2', 'v1', 'v2', 'F1', '', 'e1', 'e1', 'e3', 'e6'],
  ['e3', 'v2', 'v3', 'F1', 'F2', 'e2', 'e5', 'e1', 'e4'],
  ['e4', 'v3', 'v4', '', 'F2', 'e1', 'e3', 'e7', 'e5'],
  ['e5', 'v2', 'v4', 'F2', 'F3', 'e3', 'e6', 'e4', 'e7'],
  ['e6', 'v2', 'v5', 'F3', '', 'e5', 'e2', 'e7', 'e7'],
  ['e7', 'v4', 'v5', '', 'F3', 'e4', 'e5', 'e6', 'e6'],
];
const SLIDE_VERTEX_EDGES = [['v1', 'e1'], ['v2', 'e6'], ['v3', 'e3'], ['v4', 'e5'], ['v5', 'e6']];
const SLIDE_FACE_EDGES = [['F1', 'e1'], ['F2', 'e3'], ['F3', 'e5']];
// The slide's face table (vertex and face tables): v2 is a corner of all three faces.
const FACES_AT_V2 = 3;
// "Find CCW edges adjacent to v2": e6, e5, e3, e2; v2 is the Start of e6, e5, e3 (read
// S:L) and the End of e2 (read E:R).
const V2_WALK = [['e6', 'S:L'], ['e5', 'S:L'], ['e3', 'S:L'], ['e2', 'E:R']];
const EDGE_COLUMN_NAMES = ['', 'S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R'];
const SLIDE_EDGE_HEADER = ['', 'S', 'E', 'L', 'R', 'L', 'R', 'L', 'R'];
const DRAG_PX = 60; // how far the test drags v2, in CSS pixels

const env = useSiteAndBrowser();

async function openLesson(contextOptions) {
  const page = await env.openPage(`${env.site.url}mesh.html`, contextOptions);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  return page;
}

// The page renders on the next animation frame after a change; wait for it.
const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
const press = async (page, key) => { await page.keyboard.press(key); await settle(page); };
const click = async (page, selector) => { await page.click(selector); await settle(page); };

const tableCells = (page, id) => page.$$eval(`#${id} tbody tr[data-row]`, (rows) => rows.map((r) => [...r.children].map((c) => c.textContent.trim())));
const markedRow = (page, id) => page.$$eval(`#${id} tbody tr.is-highlighted`, (rows) => rows.map((r) => r.children[0].textContent.trim()));
const readColumns = (page, id) => page.$$eval(`#${id} td.is-read`, (cells) => cells.map((c) => [...c.parentElement.children].indexOf(c)));
const currentLine = (page) => page.$eval('#walk-code li.is-current', (li) => Number(li.dataset.line));

test('the lecture example shows the slide\'s winged-edge tables entry for entry', async () => {
  const page = await openLesson();
  assert.deepEqual(await tableCells(page, 'we-edge-table'), SLIDE_EDGE_TABLE);
  const vertexRows = await tableCells(page, 'we-vertex-table');
  assert.deepEqual(vertexRows.map((r) => [r[0], r[4]]), SLIDE_VERTEX_EDGES);
  assert.deepEqual(await tableCells(page, 'we-face-table'), SLIDE_FACE_EDGES);
  // The slide's two-level header: S E L R | S: L R | E: L R.
  const head = await page.$$eval('#we-edge-table thead tr', (rows) => rows.map((r) => [...r.children].map((c) => [c.textContent.trim(), c.colSpan])));
  assert.deepEqual(head[0].slice(1), [['S', 2], ['E', 2]]);
  assert.deepEqual(head[1].map((c) => c[0]), SLIDE_EDGE_HEADER);
  // Canvas labels are 1-based: the handles are v1..v5.
  const labels = await page.evaluate(() => window.wingspline.handles().map((h) => h.label));
  assert.deepEqual(labels, ['v1', 'v2', 'v3', 'v4', 'v5']);
  await screenshot(page, 'mesh-lecture');
  assert.deepEqual(page.problems, []);
});

test('dragging v2 moves it in every table; independent faces rewrite one copy per face', async () => {
  const page = await openLesson();
  const before = (await tableCells(page, 'we-vertex-table'))[1];
  const v2 = (await page.evaluate(() => window.wingspline.handles())).find((h) => h.label === 'v2');
  await page.mouse.move(v2.x, v2.y);
  await page.mouse.down();
  await page.mouse.move(v2.x + DRAG_PX / 2, v2.y - DRAG_PX / 2, { steps: 4 });
  await page.mouse.move(v2.x + DRAG_PX, v2.y - DRAG_PX, { steps: 4 });
  await page.mouse.up();
  await settle(page);
  const state = await page.evaluate(() => window.wingspline.state);
  assert.equal(state.moved.length, 1);
  assert.equal(state.moved[0].v, 1, 'v2 (index 1) was moved');
  const after = (await tableCells(page, 'we-vertex-table'))[1];
  assert.notEqual(after[1], before[1], 'x of v2 changed in the winged-edge vertex table');
  assert.notEqual(after[2], before[2], 'y of v2 changed');
  assert.equal(after[4], 'e6', 'the vertex still stores e6');
  const [x, y] = [after[1], after[2]];
  await click(page, '#tab-faces');
  const faces = await tableCells(page, 'independent-face-table');
  const copies = faces.flat().filter((cell) => cell.startsWith(`(${x}, ${y},`)).length;
  assert.equal(copies, FACES_AT_V2, 'each face at v2 holds its own copy of the new coordinates');
  assert.match(await page.textContent('#change-independent'), new RegExp(`rewrote ${FACES_AT_V2} coordinate triples`));
  await click(page, '#tab-vertex-face');
  assert.match(await page.textContent('#change-vertex-face'), /winged edge rewrote 1\b/);
  const vf = (await tableCells(page, 'vf-vertex-table'))[1];
  assert.deepEqual([vf[1], vf[2]], [x, y]);
  await screenshot(page, 'mesh-dragged');
  // Undo puts v2 back: every table shows the coordinates from before the drag.
  await page.click('#walk-title');
  await press(page, 'Control+z');
  assert.deepEqual(await page.evaluate(() => window.wingspline.state.moved), []);
  // (undo restores the whole state before the drag, including its open tab)
  assert.equal(await page.evaluate(() => window.wingspline.state.tab), 'winged');
  assert.deepEqual((await tableCells(page, 'we-vertex-table'))[1], before);
  assert.deepEqual(page.problems, []);
});

test('the CCW walk around v2 steps e6, e5, e3, e2 from the keyboard, row and column following', async () => {
  const page = await openLesson();
  await page.click('#walk-title'); // focus leaves the canvas: arrows drive the walk
  await press(page, 'Home');
  assert.equal(await currentLine(page), 0, 'Initialize');
  assert.deepEqual(await markedRow(page, 'we-vertex-table'), ['v2']);
  const keys = ['ArrowRight', 'PageDown', 'ArrowRight', 'PageDown'];
  for (let k = 0; k < V2_WALK.length; k += 1) {
    await press(page, keys[k]);
    const [edge, column] = V2_WALK[k];
    assert.deepEqual(await markedRow(page, 'we-edge-table'), [edge], `step ${k + 1} is at ${edge}`);
    assert.deepEqual((await readColumns(page, 'we-edge-table')).map((c) => EDGE_COLUMN_NAMES[c]), [column], `step ${k + 1} reads ${column}`);
    assert.equal(await currentLine(page), column === 'S:L' ? 2 : 3);
    const found = await page.$$eval('#walk-found .found-edge', (s) => s.map((x) => x.textContent.replace(/^\d+\.\s*/, '')));
    assert.deepEqual(found, V2_WALK.slice(0, k + 1).map((w) => w[0]));
  }
  await press(page, 'ArrowRight');
  assert.equal(await currentLine(page), 4, 'While: back at e6, the loop ends');
  await press(page, 'PageUp');
  assert.deepEqual(await markedRow(page, 'we-edge-table'), ['e2']);
  // The found edges are drawn on the canvas: the badge of e2 (70% along S -> E) carries the
  // found colour.
  const colour = await page.evaluate(() => {
    const m = window.wingspline.model;
    const s = m.we.edges[8 * 1]; const e = m.we.edges[8 * 1 + 1];
    const x = m.projected[3 * s] + 0.7 * (m.projected[3 * e] - m.projected[3 * s]);
    const y = m.projected[3 * s + 1] + 0.7 * (m.projected[3 * e + 1] - m.projected[3 * s + 1]);
    const p = window.wingspline.toClient(x, y);
    const canvas = document.getElementById('stage');
    const r = canvas.getBoundingClientRect();
    const dpr = canvas.width / r.width;
    // the badge's ring is the found colour; sample just inside its edge
    const d = canvas.getContext('2d').getImageData(Math.round((p.x - r.left + 7) * dpr), Math.round((p.y - r.top) * dpr), 1, 1).data;
    return [d[0], d[1], d[2]];
  });
  const vermillion = [0xd5, 0x5e, 0x00];
  assert.ok(colour.every((c, i) => Math.abs(c - vermillion[i]) < 40), `found edge drawn in the found colour, got ${colour}`);
  await screenshot(page, 'mesh-walk-v2');
  assert.deepEqual(page.problems, []);
});

test('walking the edges of F1 reads the face table, then E:L or S:R', async () => {
  const page = await openLesson();
  await page.selectOption('#walk-kind', 'face');
  await page.click('#walk-title');
  await press(page, 'Home');
  assert.deepEqual(await markedRow(page, 'we-face-table'), ['F1']);
  // F1 = (v1 v2 v3) stores e1; e1 has F1 on its Right (read S:R = e2), e2 and e3 have F1
  // on their Left (read E:L).
  const expected = [['e1', 'S:R'], ['e2', 'E:L'], ['e3', 'E:L']];
  for (const [edge, column] of expected) {
    await press(page, 'n');
    assert.deepEqual(await markedRow(page, 'we-edge-table'), [edge]);
    assert.deepEqual((await readColumns(page, 'we-edge-table')).map((c) => EDGE_COLUMN_NAMES[c]), [column]);
  }
  assert.deepEqual(page.problems, []);
});

test('a malformed OFF file names its line, and the page keeps its mesh', async () => {
  const page = await openLesson();
  // A good square first (two triangles), then a broken file: the square must stay.
  const square = 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n';
  await page.setInputFiles('#import-file', { name: 'square.off', mimeType: 'text/plain', buffer: Buffer.from(square) });
  await page.waitForFunction(() => window.wingspline.state.meshKind === 'file');
  // The tables follow the state on the next drawn frame (render on demand): wait for it, so
  // a loaded machine does not read the cube's table of the frame before.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  assert.equal((await tableCells(page, 'we-face-table')).length, 2);
  const broken = 'OFF\n4 2 0\n0 0 0\n1 0 zero\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n';
  await page.setInputFiles('#import-file', { name: 'broken.off', mimeType: 'text/plain', buffer: Buffer.from(broken) });
  await page.waitForSelector('#message[data-kind=error]');
  const text = await page.textContent('#message .message-text');
  assert.match(text, /broken\.off/);
  assert.match(text, /line 4/, 'the message names the line of the bad number');
  const state = await page.evaluate(() => window.wingspline.state);
  assert.equal(state.imported.name, 'square.off', 'the square is still the mesh');
  assert.equal((await tableCells(page, 'we-face-table')).length, 2);
  await screenshot(page, 'mesh-bad-off');
  // The bad file was reported through the message line, not the console.
  assert.deepEqual(page.problems, []);
});

test('a reload keeps the mesh, the moved vertex, the walk step, the tab and the 3D view', async () => {
  const page = await openLesson();
  await click(page, '#tab-storage');
  await page.click('#walk-title');
  await press(page, 'ArrowRight');
  await press(page, 'ArrowRight');
  await click(page, '#toggle-3d');
  await page.evaluate(async () => window.wingspline.flush());
  const before = await page.evaluate(() => window.wingspline.state);
  assert.equal(before.step, 2);
  assert.equal(before.mode3d, true);
  await page.reload();
  await page.waitForSelector('body[data-ready=true]');
  const after = await page.evaluate(() => window.wingspline.state);
  assert.deepEqual(after, before);
  assert.equal(await page.getAttribute('#tab-storage', 'aria-selected'), 'true');
  assert.match(await page.textContent('#storage-body'), /V = 5, E = 7, F = 3/);
  assert.deepEqual(page.problems, []);
});

test('the cube in 3D shows planes by cross product and Newell, and rotates with the mouse', async () => {
  const page = await openLesson();
  await page.selectOption('#mesh-kind', 'cube');
  await page.waitForFunction(() => window.wingspline.state.meshKind === 'cube');
  assert.equal(await page.evaluate(() => window.wingspline.state.mode3d), true);
  await click(page, '#tab-planes');
  const rows = await tableCells(page, 'plane-table');
  assert.equal(rows.length, 6, 'six faces');
  // A unit cube's faces are planar unit squares: residual 0, every unit normal is an axis.
  for (const r of rows) {
    assert.equal(r[10], '0', `${r[0]} is planar`);
    const n = r[9].slice(1, -1).split(',').map(Number);
    assert.equal(n.filter((c) => Math.abs(c) === 1).length, 1, `${r[0]} has an axis normal, got ${r[9]}`);
  }
  const yaw0 = await page.evaluate(() => window.wingspline.state.rotation.yaw);
  const box = await page.$eval('#stage', (c) => { const r = c.getBoundingClientRect(); return { x: r.left + 20, y: r.top + 20 }; });
  await page.mouse.move(box.x, box.y);
  await page.mouse.down();
  await page.mouse.move(box.x + 80, box.y, { steps: 5 });
  await page.mouse.up();
  await settle(page);
  const yaw1 = await page.evaluate(() => window.wingspline.state.rotation.yaw);
  assert.ok(yaw1 > yaw0, 'dragging empty canvas in 3D turns the mesh');
  await screenshot(page, 'mesh-cube-3d');
  assert.deepEqual(page.problems, []);
});

test('a 15 x 15 grid: every vertex has its disc; labels only where they fit, none overlapping', async () => {
  const page = await openLesson();
  await page.selectOption('#mesh-kind', 'grid');
  await page.fill('#grid-nx', '15');
  await page.press('#grid-nx', 'Enter');
  await page.fill('#grid-ny', '15');
  await page.press('#grid-ny', 'Enter');
  await page.waitForFunction(() => window.wingspline.model.F === 450);
  // The figure as SVG (the same drawing code as the canvas): V = 16 x 16 vertex discs. Over
  // LABEL_LIMIT = 400 faces: labelled by screen density, so some labels of each
  // kind but not all, and no two labels placed by density overlapping (boxes 10 px per
  // character plus 6 px wide, 18 px high, around the label's anchor). The walk's vertex and
  // its current edge are labelled whatever the density.
  const labels = async () => {
    const svg = await page.evaluate(() => window.wingspline.svg());
    const discs = (svg.match(/<circle [^>]* r="5" /g) ?? []).length;
    const placed = [...svg.matchAll(/<text x="([-\d.]+)" y="([-\d.]+)"[^>]*>([Fev]\d+)<\/text>/g)].map((m) => ({ x: Number(m[1]), y: Number(m[2]), label: m[3] }));
    return { discs, placed };
  };
  const { discs, placed } = await labels();
  assert.equal(discs, 256, 'one disc of radius 5 per vertex');
  const count = (k) => new Set(placed.filter((p) => p.label.startsWith(k)).map((p) => p.label)).size;
  assert.ok(count('v') > 0 && count('v') < 256, `${count('v')} of 256 vertices labelled`);
  assert.ok(count('F') > 0 && count('F') < 450, `${count('F')} of 450 faces labelled`);
  const walked = `v${await page.evaluate(() => window.wingspline.state.vertex) + 1}`;
  assert.ok(placed.some((p) => p.label === walked), `the walk's vertex ${walked} is labelled`);
  const current = `e${await page.evaluate(() => window.wingspline.model.frame.current) + 1}`;
  const touched = new Set([walked, current]);
  const free = placed.filter((p) => !touched.has(p.label));
  for (let i = 0; i < free.length; i += 1) {
    for (let j = i + 1; j < free.length; j += 1) {
      const a = free[i]; const b = free[j];
      const halfWidths = (10 * a.label.length + 6) / 2 + (10 * b.label.length + 6) / 2;
      assert.ok(Math.abs(a.x - b.x) >= halfWidths - 1e-6 || Math.abs(a.y - b.y) >= 18 - 1e-6, `${a.label} (${a.x}, ${a.y}) and ${b.label} (${b.x}, ${b.y}) overlap`);
    }
  }
  // Zoomed in 4x about the middle, more of the grid's labels fit where they are on screen.
  await page.evaluate(() => { const v = window.wingspline.state.view; window.wingspline.ctx.setView({ ...v, zoom: v.zoom * 4 }); });
  const zoomed = await labels();
  assert.ok(zoomed.placed.filter((p) => p.label.startsWith('F')).length > 0);
  assert.deepEqual(page.problems, []);
});

test('a 10,000-face sphere keeps its tables virtual and walks around the pole', async () => {
  const page = await openLesson();
  await page.selectOption('#mesh-kind', 'sphere');
  await page.fill('#sphere-slices', '100');
  await page.press('#sphere-slices', 'Enter');
  await page.fill('#sphere-stacks', '51');
  await page.press('#sphere-stacks', 'Enter');
  await page.waitForFunction(() => window.wingspline.model.F === 10000);
  await click(page, '#tab-winged');
  const drawnRows = await page.$$eval('#we-edge-table tbody tr[data-row]', (r) => r.length);
  assert.ok(drawnRows < 200, `only the rows in view are in the DOM (${drawnRows})`);
  const notes = await page.$$eval('.table-note:not([hidden])', (n) => n.map((x) => x.textContent));
  assert.ok(notes.some((t) => /15,000 rows/.test(t)), `the edge table says it is virtual: ${notes}`);
  // docs/benchmarks.md's sphere: vertex 0 is the north pole, of valence `slices`.
  await page.click('#walk-title');
  await press(page, 'End');
  const found = await page.evaluate(() => window.wingspline.model.frame.foundCount);
  assert.equal(found, 100);
  await screenshot(page, 'mesh-sphere-10k');
  // Every row of the other representations is reachable: scroll the face table of the
  // vertex and face tables to its end with the mouse wheel. docs/benchmarks.md's sphere closes with
  // the south cap, so the last face is (ring 50, slice 99), south pole, (ring 50, slice 0):
  // vertices 1 + 49*100 + 99 = 5000, 5001 and 4901, labelled v5001, v5002, v4902.
  await click(page, '#tab-vertex-face');
  await page.hover('#vf-face-table tbody');
  for (let i = 0; i < 4; i += 1) await page.mouse.wheel(0, 100000);
  await settle(page);
  const rows = await tableCells(page, 'vf-face-table');
  assert.deepEqual(rows.at(-1), ['F10000', 'v5001', 'v5002', 'v4902']);
  const faceNote = await page.$eval('#vf-face-table', (t) => t.closest('.table-block').querySelector('.table-note').textContent);
  assert.doesNotMatch(faceNote, /first/, 'no rows are cut off');
  assert.deepEqual(page.problems, []);
});

test('on a phone held sideways the page does not scroll sideways', async () => {
  const page = await openLesson({ viewport: { width: 844, height: 390 }, isMobile: true });
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflow <= 0, `no horizontal scrolling (overflow ${overflow}px)`);
  await screenshot(page, 'mesh-phone-landscape');
  assert.deepEqual(page.problems, []);
});

test('queries compared: every representation answers alike and says how many entries it read', async () => {
  const page = await openLesson();
  await click(page, '#tab-queries');
  // Slide: v2 is a corner of F1, F2 and F3; e3 has L = F1 and R = F2.
  const answers = async () => page.$$eval('#query-table tbody tr', (rows) => rows.map((r) => ({
    name: r.dataset.representation, answer: r.children[1].textContent.split(', ').sort().join(' '), read: Number(r.children[2].textContent.replace(/,/g, '')),
  })));
  const aroundV2 = await answers();
  assert.deepEqual(aroundV2.map((r) => r.name), ['independent-faces', 'vertex-face-tables', 'adjacency-lists', 'partial-adjacency-lists', 'edge-list', 'winged-edge', 'half-edge'],
    'the lecture\'s six representations answer, and the half-edge');
  for (const r of aroundV2) {
    assert.equal(r.answer, 'F1 F2 F3', `${r.name} finds the faces around v2`);
    assert.ok(r.read > 0, `${r.name} read some entries`);
  }
  await page.selectOption('#query-kind', 'faces-of-edge');
  await page.fill('#query-element', '3');
  await page.press('#query-element', 'Enter');
  await settle(page);
  for (const r of await answers()) assert.equal(r.answer, 'F1 F2', `${r.name}: e3 separates F1 and F2`);
  assert.deepEqual(page.problems, []);
});

test('storage per representation counts the slide\'s entries, with the lectures\' pros and cons', async () => {
  const page = await openLesson();
  await click(page, '#tab-storage');
  const arrays = await page.$$eval('#storage-table tbody tr', (rows) => Object.fromEntries(rows.map((r) => [r.dataset.representation, r.querySelector('.arrays').textContent])));
  // Independent faces: 3 faces x 3 corners x (x, y, z) = 27 coordinates (the slide's face
  // table); vertex and face tables: 5 x 3 coordinates and 9 vertex references; the winged
  // edge's edge table: 7 edges x 8 fields.
  assert.match(arrays['independent-faces'], /coordinates: 27 ×/);
  assert.match(arrays['vertex-face-tables'], /coordinates: 15 ×/);
  assert.match(arrays['vertex-face-tables'], /vertices: 9 ×/);
  assert.match(arrays['winged-edge'], /: 56 ×/);
  const cons = await page.$eval('.pros-cons[data-representation=independent-faces]', (d) => d.textContent);
  assert.match(cons, /Redundant vertices/i);
  assert.match(await page.$eval('.pros-cons[data-representation=winged-edge]', (d) => d.textContent), /Mesh needs to be oriented/i);
  await screenshot(page, 'mesh-storage');
  assert.deepEqual(page.problems, []);
});

test('a file the winged edge cannot hold shows the whole validation report and keeps the mesh', async () => {
  const page = await openLesson();
  // Three triangles on the edge v1-v2 (0-1): "shared by 3 faces".
  const fin = 'OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0.5 0.5 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n';
  await page.setInputFiles('#import-file', { name: 'fin.off', mimeType: 'text/plain', buffer: Buffer.from(fin) });
  await page.waitForSelector('#mesh-report:not([hidden])');
  const codes = await page.$$eval('#mesh-report li', (li) => li.map((x) => x.dataset.code));
  assert.ok(codes.includes('non-manifold-edge'), `the report names the shared edge: ${codes}`);
  assert.match(await page.textContent('#mesh-report'), /v1 v2|v2 v1/, 'the offending vertices are named with slide labels');
  assert.match(await page.textContent('#message .message-text'), /fin\.off was not imported/);
  assert.equal(await page.evaluate(() => window.wingspline.state.meshKind), 'lecture');
  assert.equal((await tableCells(page, 'we-edge-table')).length, 7, 'the lecture example is still shown');
  await screenshot(page, 'mesh-report');
  assert.deepEqual(page.problems, []);
});

test('hovering a table row marks the element on the canvas, and the canvas marks the rows', async () => {
  const page = await openLesson();
  await page.hover('#we-edge-table tr[data-row="2"]');
  await settle(page);
  assert.deepEqual(await page.evaluate(() => window.wingspline.view.selection.hover), { kind: 'edge', index: 2 }, 'e3 is marked for the canvas');
  // The centroid of F3 = (v2 v5 v4) on the canvas: the F3 row of the face table lights up.
  const point = await page.evaluate(() => {
    const m = window.wingspline.model;
    const [x, y] = Array.from(m.faceVertices.subarray(m.faceOffsets[2], m.faceOffsets[3])).reduce((acc, v) => [acc[0] + m.projected[3 * v] / 3, acc[1] + m.projected[3 * v + 1] / 3], [0, 0]);
    return window.wingspline.toClient(x, y);
  });
  await page.mouse.move(point.x, point.y);
  await settle(page);
  const hovered = await page.$$eval('#we-face-table tr.is-hovered', (rows) => rows.map((r) => r.children[0].textContent));
  assert.deepEqual(hovered, ['F3']);
  assert.deepEqual(page.problems, []);
});

test('exports: the edge table as CSV with the slide\'s rows, LaTeX with the two-level header, the mesh as OFF', async () => {
  const page = await openLesson();
  async function exported(filename) {
    await page.click('.menu > summary');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click(`[data-export="${filename}"]`)]);
    const stream = await download.createReadStream();
    const chunks = [];
    for await (const chunk of stream) chunks.push(chunk);
    return Buffer.concat(chunks).toString('utf8');
  }
  const csv = await exported('mesh-winged-edge.csv');
  for (const row of SLIDE_EDGE_TABLE) assert.ok(csv.includes(`\n${row.join(',')}\n`), `CSV has the slide's row ${row.join(',')}`);
  const latex = await exported('mesh-winged-edge.tex');
  assert.match(latex, /\\multicolumn\{2\}\{c\|\}\{S\} & \\multicolumn\{2\}\{c\}\{E\}/);
  assert.match(latex, /\$e_\{6\}\$ & \$v_\{2\}\$ & \$v_\{5\}\$ & \$F_\{3\}\$ &  & \$e_\{5\}\$ & \$e_\{2\}\$ & \$e_\{7\}\$ & \$e_\{7\}\$/);
  const off = await exported('mesh.off');
  const parsed = await page.evaluate((text) => { const m = window.wingspline.api.parseMesh(text, { format: 'off' }); return { v: m.positions.length / 3, faces: m.faces }; }, off);
  assert.deepEqual(parsed, { v: 5, faces: [[0, 1, 2], [1, 3, 2], [1, 4, 3]] }, 'the slide\'s faces F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4)');
  assert.deepEqual(page.problems, []);
});

test('Play runs the walk to its end by itself and stops there', async () => {
  const page = await openLesson();
  await page.fill('#walk-speed', '6');
  await page.click('#walk-play');
  await page.waitForFunction(() => window.wingspline.state.step === window.wingspline.model.frames.length - 1, null, { timeout: 10000 });
  await settle(page);
  assert.equal(await page.getAttribute('#walk-play', 'aria-pressed'), 'false', 'the player paused at the last step');
  assert.equal(await currentLine(page), 4);
  assert.deepEqual(page.problems, []);
});

test('presentation mode, dark theme and a 1280 x 720 projector keep the page whole', async () => {
  const page = await openLesson({ viewport: { width: 1280, height: 720 }, colorScheme: 'dark' });
  await page.click('[data-action=present]');
  await settle(page);
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflow <= 0, `no horizontal scrolling (overflow ${overflow}px)`);
  const canvas = await page.$eval('#stage', (c) => c.getBoundingClientRect().height);
  assert.ok(canvas >= 300, `the drawing keeps its room (${canvas}px)`);
  await screenshot(page, 'mesh-present-dark-720p');
  assert.deepEqual(page.problems, []);
});

// The 3D view turns about the mesh's centre, and says when the walk is seen
// from behind (its CCW order then looks clockwise on screen).
const YAW_PER_PX = 0.01; // radians per CSS pixel of a rotating drag (panels.js)
async function dragEmptyCanvas(page, dx) {
  const start = await page.$eval('#stage', (c) => { const r = c.getBoundingClientRect(); return { x: r.left + 20, y: r.top + 20 }; });
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  await page.mouse.move(start.x + dx, start.y, { steps: 10 });
  await page.mouse.up();
  await settle(page);
}
// The centre of the vertices' box on the page, from the positions the app reports.
async function projectedCentre(page) {
  const hs = (await page.evaluate(() => window.wingspline.handles())).filter((x) => /^v\d+$/.test(x.id));
  const xs = hs.map((x) => x.x); const ys = hs.map((x) => x.y);
  return { x: (Math.min(...xs) + Math.max(...xs)) / 2, y: (Math.min(...ys) + Math.max(...ys)) / 2 };
}
const sideNote = (page) => page.evaluate(() => { const e = document.getElementById('walk-side'); return !e || e.hidden ? '' : e.textContent; });

test('3D view: a half turn by dragging keeps the mesh in the canvas and says it is seen from behind', async () => {
  const page = await openLesson();
  // A mesh in its own frame, far from the origin as imported files often are: two CCW
  // triangles (seen from +z) of a unit square at x, y in [20, 21], z = 0.
  const square = 'OFF\n4 2 0\n20 20 0\n21 20 0\n21 21 0\n20 21 0\n3 0 1 2\n3 0 2 3\n';
  await page.setInputFiles('#import-file', { name: 'far-square.off', mimeType: 'text/plain', buffer: Buffer.from(square) });
  await page.waitForFunction(() => window.wingspline.state.meshKind === 'file');
  await click(page, '#toggle-3d');
  assert.equal(await page.evaluate(() => window.wingspline.state.mode3d), true);
  const canvas = await page.$eval('#stage', (c) => { const r = c.getBoundingClientRect(); return { left: r.left, top: r.top, right: r.right, bottom: r.bottom }; });
  const inside = (p) => p.x >= canvas.left && p.x <= canvas.right && p.y >= canvas.top && p.y <= canvas.bottom;
  for (const walk of ['vertex', 'face']) {
    await page.selectOption('#walk-kind', walk);
    await settle(page);
    assert.equal(await sideNote(page), '', `${walk} walk seen from the front: no note`);
  }
  const yaw0 = await page.evaluate(() => window.wingspline.state.rotation.yaw);
  await dragEmptyCanvas(page, Math.round(Math.PI / YAW_PER_PX));
  const yaw1 = await page.evaluate(() => window.wingspline.state.rotation.yaw);
  assert.ok(Math.abs(yaw1 - yaw0 - Math.PI) < 0.02, `a half turn (yaw ${yaw0} -> ${yaw1})`);
  const centre = await projectedCentre(page);
  assert.ok(inside(centre), `the mesh's centre at (${centre.x.toFixed(0)}, ${centre.y.toFixed(0)}) stays in the canvas ${JSON.stringify(canvas)}`);
  // The square lies in z = 0 with CCW faces seen from +z: after a half turn about the
  // vertical axis the walk is seen from behind.
  for (const walk of ['face', 'vertex']) {
    await page.selectOption('#walk-kind', walk);
    await settle(page);
    assert.match(await sideNote(page), /behind.*clockwise/i, `${walk} walk seen from behind says so`);
  }
  await screenshot(page, 'mesh-3d-behind');
  await dragEmptyCanvas(page, -Math.round(Math.PI / YAW_PER_PX));
  assert.equal(await sideNote(page), '', 'turned back to the front: no note');
  assert.ok(inside(await projectedCentre(page)));
  assert.deepEqual(page.problems, []);
});

// The vertex table stores one of v2's edges (the slide: e6); a person chooses e3
// in the winged-edge tab. The row changes, the walk starts there (CCW from e3: e3, e2, e6,
// e5), undo restores e6, and a reload and a share link keep the choice.
test('choosing another stored edge for v2 changes its table row and the walk; undo, reload and a link keep it', async () => {
  const page = await openLesson();
  const v2Edge = async () => (await tableCells(page, 'we-vertex-table'))[1][4];
  assert.equal(await v2Edge(), 'e6');
  assert.equal(await page.textContent('label[for=stored-edge]'), 'Edge stored for v2:');
  // Only v2's own edges are offered, in edge order.
  assert.deepEqual(await page.$$eval('#stored-edge option', (os) => os.map((o) => o.textContent)), ['e2', 'e3', 'e5', 'e6']);
  await page.focus('#stored-edge');
  await page.selectOption('#stored-edge', { label: 'e3' });
  await settle(page);
  assert.equal(await v2Edge(), 'e3');
  assert.match(await page.textContent('#stored-edge-note'), /vertex table, row v2: edge e6 → e3/);
  // The walk starts at the stored edge and meets v2's edges in the same CCW order.
  await page.click('#walk-title');
  await press(page, 'Home');
  assert.match(await page.textContent('#walk-text'), /stores e3 for v2/);
  await press(page, 'End');
  assert.match(await page.textContent('#walk-text'), /e3, e2, e6, e5/);
  // The other rows are the slide's.
  assert.deepEqual(await tableCells(page, 'we-edge-table'), SLIDE_EDGE_TABLE);
  // Undo restores the slide's row; redo is a new choice.
  await press(page, 'Control+z');
  assert.equal(await v2Edge(), 'e6');
  assert.equal(await page.$eval('#stored-edge', (s) => s.selectedOptions[0].textContent), 'e6');
  await page.selectOption('#stored-edge', { label: 'e5' });
  await settle(page);
  assert.equal(await v2Edge(), 'e5');
  await page.evaluate(async () => window.wingspline.flush());
  await page.reload();
  await page.waitForSelector('body[data-ready=true]');
  assert.equal(await v2Edge(), 'e5', 'a reload keeps the choice');
  const link = await page.evaluate(() => window.wingspline.shareUrl());
  await page.context().close();
  const other = await env.openPage(link);
  await other.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  assert.equal((await tableCells(other, 'we-vertex-table'))[1][4], 'e5', 'a share link carries it');
  assert.deepEqual(other.problems, []);
});

test('choosing the stored edge of a face: F2 stores e5, its walk starts there', async () => {
  const page = await openLesson();
  await page.selectOption('#walk-kind', 'face');
  await page.fill('#walk-element', '2');
  await page.press('#walk-element', 'Enter');
  await settle(page);
  assert.equal(await page.textContent('label[for=stored-edge]'), 'Edge stored for F2:');
  // F2 = (v2 v4 v3): its sides are e3, e4, e5.
  assert.deepEqual(await page.$$eval('#stored-edge option', (os) => os.map((o) => o.textContent)), ['e3', 'e4', 'e5']);
  await page.selectOption('#stored-edge', { label: 'e5' });
  await settle(page);
  assert.deepEqual((await tableCells(page, 'we-face-table'))[1], ['F2', 'e5']);
  await page.click('#walk-title');
  await press(page, 'End');
  assert.match(await page.textContent('#walk-text'), /e5, e4, e3/);
  // The face set did not change: F2 is still listed (v2 v4 v3).
  await click(page, '#tab-vertex-face');
  assert.deepEqual((await tableCells(page, 'vf-face-table'))[1], ['F2', 'v2', 'v4', 'v3']);
  assert.deepEqual(page.problems, []);
});

// Dragging a vertex moves it and leaves the walk where it was; a click (press and
// release without moving) makes the vertex the walk's.
test('dragging v3 moves it without changing the walk\'s vertex; clicking v3 makes it the walk\'s vertex', async () => {
  const page = await openLesson();
  const before = await page.evaluate(() => ({ vertex: window.wingspline.state.vertex, p: Array.from(window.wingspline.model.positions.slice(6, 9)) }));
  assert.equal(before.vertex, 1, 'the walk starts at v2');
  await drag(page, 'v2', 40, -30); // handle ids count from 0: v2 is the slide's v3
  const after = await page.evaluate(() => ({ vertex: window.wingspline.state.vertex, p: Array.from(window.wingspline.model.positions.slice(6, 9)) }));
  assert.notDeepEqual(after.p, before.p, 'v3 moved');
  assert.equal(after.vertex, 1, 'the walk still goes around v2');
  const h3 = await handle(page, 'v2');
  await page.mouse.click(h3.x, h3.y);
  await page.waitForFunction(() => window.wingspline.state.vertex === 2);
  // Chosen with ] on the canvas, a vertex is only selected: a later click elsewhere (on a
  // button) does not make it the walk's vertex.
  await page.locator('#stage').focus();
  await page.keyboard.press(']');
  await page.click('#walk-title');
  assert.equal(await page.evaluate(() => window.wingspline.state.vertex), 2, 'the walk stays at v3');
  assert.deepEqual(page.problems, []);
});

// A message goes when it goes stale. A refusal stays while nothing else changed
// and is cleared by the next accepted change; a message shown for that change stays.
test('a refusal goes once a later change is accepted, not before', async () => {
  const page = await openLesson();
  await page.selectOption('#mesh-kind', 'sphere');
  await page.waitForFunction(() => window.wingspline.state.meshKind === 'sphere');
  await page.fill('#sphere-slices', '5000');
  await page.press('#sphere-slices', 'Enter');
  await page.waitForFunction(() => /must be a whole number from 3 to 1000/.test(window.wingspline.message()));
  assert.equal(await page.evaluate(() => window.wingspline.state.sphere.slices), 12, 'the refused value did not enter');
  // A view change (zoom) is not an edit: the refusal stays.
  await page.locator('#stage').focus();
  await page.keyboard.press('+');
  assert.match(await page.evaluate(() => window.wingspline.message()), /must be a whole number from 3 to 1000/);
  // An accepted edit (a walk step) makes it stale: it goes.
  await page.locator('#walk-title').click();
  await page.keyboard.press('PageDown');
  await page.waitForFunction(() => window.wingspline.message() === '');
  assert.deepEqual(page.problems, []);
});
