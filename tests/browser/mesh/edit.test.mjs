// Editing the winged edge in the mesh lesson, driven as a student would: pick an
// edge on the canvas with the pointer, split it, step through the pointer assignments, undo
// and redo, reload from the share link; flip an edge and flip it back. The expected tables
// are worked out by hand from lecture 000's conventions (tests/native has the same cases for
// every operation); the page is asked where things are, never what the answer is.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { clickToPick, edgeMiddle } from '../../helpers/mesh-page.mjs';

const env = useSiteAndBrowser();

async function openLesson(url = `${env.site.url}mesh.html`) {
  const page = await env.openPage(url);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  return page;
}
const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
const tableCells = (page, id) => page.$$eval(`#${id} tbody tr[data-row]`, (rows) => rows.map((r) => [...r.children].map((c) => c.textContent.trim())));

// The lecture mesh: F1 = (v1 v2 v3), F2 = (v2 v4 v3) side e3 = v2 -> v3 between them.
// Splitting e3 at t = 1/2 (worked by hand, lecture 000's S, E, L, R and wings):
//   new vertex v6 at the midpoint of v2 and v3, new edge e8 = v6 -> v3 with e3's faces,
//   e3 = v2 -> v6 keeps its Start wings; its End wings become e8 on both sides;
//   e8: S:L = S:R = e3, E:L = e1 (e3's old E:L), E:R = e4 (e3's old E:R);
//   e1's E:R and e4's S:R, which named e3 at v3, now name e8; v3 stores e8.
const SPLIT_E3 = {
  e3: ['e3', 'v2', 'v6', 'F1', 'F2', 'e2', 'e5', 'e8', 'e8'],
  e8: ['e8', 'v6', 'v3', 'F1', 'F2', 'e3', 'e3', 'e1', 'e4'],
  e1: ['e1', 'v1', 'v3', '', 'F1', 'e2', 'e2', 'e4', 'e8'],
  e4: ['e4', 'v3', 'v4', '', 'F2', 'e1', 'e8', 'e7', 'e5'],
};

async function pickEdgeWithPointer(page, e) {
  await clickToPick(page, await edgeMiddle(page, e), `e${e + 1}`);
}

const rowOf = (rows, label) => rows.find((r) => r[0] === label);

test('a student splits e3 with the pointer, steps through the assignments, undoes, redoes and reloads the link', async () => {
  const page = await openLesson();
  await pickEdgeWithPointer(page, 2);
  // Split applies to an edge; Poke (a face operation) is not offered for it.
  assert.equal(await page.isEnabled('button[data-op="split-edge"]'), true);
  assert.equal(await page.isVisible('button[data-op="poke-face"]'), false);
  await page.click('button[data-op="split-edge"]');
  // The message line says what was done, and nothing else (it once printed "null" after it).
  await page.waitForFunction(() => window.wingspline.message().startsWith('Done: split e3'));
  const line = await page.$eval('#message', (el) => [...el.childNodes].filter((n) => !(n instanceof HTMLButtonElement)).map((n) => n.textContent).join(''));
  assert.equal(line, await page.evaluate(() => window.wingspline.message()));
  await page.waitForFunction(() => document.querySelectorAll('#we-edge-table tbody tr[data-row]').length === 8);
  const rows = await tableCells(page, 'we-edge-table');
  for (const [label, expected] of Object.entries(SPLIT_E3)) assert.deepEqual(rowOf(rows, label), expected, `row ${label}`);
  const vertices = await tableCells(page, 'we-vertex-table');
  assert.deepEqual(vertices.map((r) => r[0]), ['v1', 'v2', 'v3', 'v4', 'v5', 'v6']);
  assert.equal(rowOf(vertices, 'v3')[4], 'e8');
  assert.equal(rowOf(vertices, 'v6')[4], 'e8');
  // The new vertex is the midpoint of v2 = (1, 1, 0)... read from the page's own v2 and v3.
  const [v2, v3, v6] = await page.evaluate(() => [1, 2, 5].map((v) => Array.from(window.wingspline.model.positions.slice(3 * v, 3 * v + 3))));
  for (let k = 0; k < 3; k += 1) assert.ok(Math.abs(v6[k] - (v2[k] + v3[k]) / 2) <= 1e-12 * (1 + Math.abs(v2[k]) + Math.abs(v3[k])));
  // The cost argument of lecture 000 as numbers: what each representation wrote (counted
  // by hand in tests/wasm/mesh/edit.test.mjs: the winged edge 18, independent faces 9, vertex and face tables 6).
  const costs = await page.$$eval('#edit-costs tbody tr', (rows) => Object.fromEntries(rows.map((r) => [r.dataset.representation, Number(r.querySelector('[data-cost=writes]').textContent)])));
  assert.deepEqual([costs['winged-edge'], costs['independent-faces'], costs['vertex-face-tables']], [18, 9, 6]);
  // Euler's formula after the edit: 6 - 8 + 3 = 1.
  assert.match(await page.textContent('#edit-euler'), /before the last edit 5 − 7 \+ 3 = 1; after it 6 − 8 \+ 3 = 1/);

  // Step back to the start of the edit with the player: before any assignment the edge
  // table shows e3 as it was, and each step forward writes one cell.
  await page.click('#edit-restart');
  await page.waitForFunction(() => document.querySelector('#edit-step')?.textContent.startsWith('0 of'));
  const before = rowOf(await tableCells(page, 'we-edge-table'), 'e3');
  // The canvas too: before the first assignment the new edge e8 is not drawn yet.
  assert.equal(await page.evaluate(() => window.wingspline.model.edgeGap?.[7]), 1);
  assert.deepEqual(before, ['e3', 'v2', 'v3', 'F1', 'F2', 'e2', 'e5', 'e1', 'e4']);
  const total = Number((await page.textContent('#edit-step')).split(' of ')[1]);
  assert.ok(total >= 10, `a split writes at least the new edge's 8 fields and e3's end: ${total}`);
  await page.click('#edit-next');
  await page.waitForFunction(() => document.querySelector('#edit-step')?.textContent.startsWith('1 of'));
  assert.equal(await page.$$eval('#edit-steps li.is-current', (li) => li.length), 1);
  // The first entries the split writes: the new vertex v6's x, y, z (the midpoint of v2 =
  // (1, 0) and v3 = (1, 2): x = 1), then v6 stores its edge e8 (the edge column of the vertex
  // table, row v6): one cell is marked at a time, and the step list says which.
  const marked = () => page.$$eval('#we-vertex-table td.is-read, #we-edge-table td.is-read, #we-face-table td.is-read',
    (cells) => cells.map((c) => [c.closest('table').id, c.parentElement.children[0].textContent.trim(), [...c.parentElement.children].indexOf(c)]));
  assert.deepEqual(await marked(), [['we-vertex-table', 'v6', 1]], 'one cell is being written');
  assert.match(await page.textContent('#edit-steps li.is-current'), /vertex table, v6 · x: — → 1$/);
  for (let k = 2; k <= 4; k += 1) {
    await page.click('#edit-next');
    await page.waitForFunction((want) => document.querySelector('#edit-step')?.textContent.startsWith(`${want} of`), k);
  }
  assert.deepEqual(await marked(), [['we-vertex-table', 'v6', 4]], 'one cell is being written');
  assert.match(await page.textContent('#edit-steps li.is-current'), /vertex table, v6 · edge: — → e8/);
  // ... and the algorithm's first line is the one marked (the core sends its lines).
  assert.equal(await page.$eval('#edit-phases li.is-current', (li) => Number(li.dataset.line)), 0);
  await page.click('#edit-end');
  await page.waitForFunction((n) => document.querySelector('#edit-step')?.textContent === `${n} of ${n}`, total);
  assert.deepEqual(rowOf(await tableCells(page, 'we-edge-table'), 'e3'), SPLIT_E3.e3);
  assert.equal(await page.evaluate(() => window.wingspline.model.edgeGap?.[7] ?? 0), 0, 'e8 drawn once the edit is done');

  // Undo (Ctrl+Z) takes the edit back; redo brings it again.
  await page.focus('body');
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => document.querySelectorAll('#we-edge-table tbody tr[data-row]').length === 7);
  await page.keyboard.press('Control+y');
  await page.waitForFunction(() => document.querySelectorAll('#we-edge-table tbody tr[data-row]').length === 8);

  // The share link holds the edit: opened fresh, it shows the split mesh.
  const link = await page.evaluate(() => window.wingspline.shareUrl());
  const again = await openLesson(link);
  const againRows = await tableCells(again, 'we-edge-table');
  for (const [label, expected] of Object.entries(SPLIT_E3)) assert.deepEqual(rowOf(againRows, label), expected, `row ${label} after the link`);
  assert.deepEqual(page.problems, []);
  assert.deepEqual(again.problems, []);
  await screenshot(page, 'mesh-edit-split');
  await again.context().close();
  await page.context().close();
});

test('flipping e3 and flipping it back gives the lecture mesh\'s faces again; a refused flip says why and changes nothing', async () => {
  const page = await openLesson();
  const facesBefore = await page.evaluate(() => ((m) => Array.from({ length: m.faceOffsets.length - 1 }, (_, f) => [...m.faceVertices.subarray(m.faceOffsets[f], m.faceOffsets[f + 1])]))(window.wingspline.model));
  await pickEdgeWithPointer(page, 2);
  await page.keyboard.press('f');
  // e3 = v2 v3 between F1 (v1 v2 v3) and F2 (v2 v4 v3) becomes the diagonal v1 - v4.
  await page.waitForFunction(() => {
    const row = document.querySelector('#we-edge-table tbody tr[data-row="2"]');
    const ends = row ? [row.children[1].textContent.trim(), row.children[2].textContent.trim()].sort() : [];
    return ends.join() === 'v1,v4';
  });
  await pickEdgeWithPointer(page, 2);
  await page.keyboard.press('f');
  await page.waitForFunction(() => {
    const row = document.querySelector('#we-edge-table tbody tr[data-row="2"]');
    const ends = row ? [row.children[1].textContent.trim(), row.children[2].textContent.trim()].sort() : [];
    return ends.join() === 'v2,v3';
  });
  // The same faces as corner cycles (each may start at another corner).
  const canonical = (faces) => faces.map((f) => { const k = f.indexOf(Math.min(...f)); return [...f.slice(k), ...f.slice(0, k)].join(' '); }).sort();
  const facesAfter = await page.evaluate(() => ((m) => Array.from({ length: m.faceOffsets.length - 1 }, (_, f) => [...m.faceVertices.subarray(m.faceOffsets[f], m.faceOffsets[f + 1])]))(window.wingspline.model));
  assert.deepEqual(canonical(facesAfter), canonical(facesBefore));
  // e1 is a boundary edge: flipping it is refused with the core's reason, the mesh unchanged.
  const tablesBefore = await tableCells(page, 'we-edge-table');
  await pickEdgeWithPointer(page, 0);
  assert.equal(await page.isDisabled('button[data-op="flip-edge"]'), true);
  assert.match(await page.textContent('#edit-reasons'), /e1/);
  await page.keyboard.press('f');
  await settle(page);
  assert.deepEqual(await tableCells(page, 'we-edge-table'), tablesBefore);
  assert.match(await page.evaluate(() => window.wingspline.message()), /Flip edge: .*e1/);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('on a touch screen: tap F2 and poke it, collapse e7 (its rows stay as struck-through gaps), compact, export the edited mesh', async () => {
  const page = await env.openPage(`${env.site.url}mesh.html`, { hasTouch: true, isMobile: false });
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  // The centroid of F2 = (v2 v4 v3), asked of the page, tapped with a finger.
  const point = await page.evaluate(() => {
    const m = window.wingspline.model;
    const [x, y] = Array.from(m.faceVertices.subarray(m.faceOffsets[1], m.faceOffsets[2])).reduce((acc, v) => [acc[0] + m.projected[3 * v] / 3, acc[1] + m.projected[3 * v + 1] / 3], [0, 0]);
    return window.wingspline.toClient(x, y);
  });
  await page.touchscreen.tap(point.x, point.y);
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: F2');
  await page.tap('button[data-op="poke-face"]');
  // Poking a triangle: V + 1, E + 3, F + 2: 6 - 10 + 5 = 1.
  await page.waitForFunction(() => /after it 6 − 10 \+ 5 = 1/.test(document.querySelector('#edit-euler')?.textContent ?? ''));

  // e7 = v4 -> v5 on the boundary, F3 = (v2 v5 v4) on its right: collapsing it merges v5
  // into v4, and the triangle F3 goes with its edge v5 - v2 (e6). Picked by number.
  await page.selectOption('#edit-kind', 'edge');
  await page.fill('#edit-element', '7');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: e7');
  await page.tap('button[data-op="collapse-edge"]');
  await page.waitForFunction(() => /after it 5 − 8 \+ 4 = 1/.test(document.querySelector('#edit-euler')?.textContent ?? ''));
  const gapRows = (id) => page.$$eval(`#${id} tbody tr.is-gap`, (rows) => rows.map((r) => r.children[0].textContent.replace(' (removed)', '').trim()));
  assert.deepEqual(await gapRows('we-vertex-table'), ['v5']);
  assert.deepEqual(await gapRows('we-edge-table'), ['e6', 'e7']);
  assert.deepEqual(await gapRows('we-face-table'), ['F3']);

  // Compact: the gaps go, the numbers after them move up.
  await page.tap('#edit-compact');
  await page.waitForFunction(() => document.querySelectorAll('#we-edge-table tbody tr[data-row]').length === 8);
  assert.equal(await page.$$eval('#we-vertex-table tbody tr[data-row]', (r) => r.length), 5);
  assert.equal(await page.$$eval('#we-face-table tbody tr[data-row]', (r) => r.length), 4);
  assert.deepEqual(await gapRows('we-edge-table'), []);

  // The OFF export is the edited mesh: 5 vertices, 4 faces.
  await page.click('.menu > summary');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-export="mesh.off"]')]);
  const chunks = [];
  for await (const chunk of await download.createReadStream()) chunks.push(chunk);
  const lines = Buffer.concat(chunks).toString('utf8').split('\n').filter((l) => l.trim() && !l.startsWith('#'));
  assert.equal(lines[0].trim(), 'OFF');
  assert.deepEqual(lines[1].trim().split(/\s+/).slice(0, 2).map(Number), [5, 4]);
  assert.deepEqual(page.problems, []);
  await screenshot(page, 'mesh-edit-touch');
  await page.context().close();
});

test('a link whose edit the core refuses says so, naming the operation, and the saved work stays', async () => {
  const page = await openLesson();
  // Saved work: e3 split.
  await pickEdgeWithPointer(page, 2);
  await page.click('button[data-op="split-edge"]');
  await page.waitForFunction(() => document.querySelectorAll('#we-edge-table tbody tr[data-row]').length === 8);
  await page.evaluate(() => window.wingspline.flush());
  // A link that flips e1, a boundary edge (written the way the page writes links).
  const link = await page.evaluate(async () => {
    const { encodeState } = await import('./js/app/share-link.js');
    const { meshLesson } = await import('./js/lessons/mesh/lesson.js');
    const state = { ...window.wingspline.state, ops: [{ op: 'flip-edge', e: 0 }] };
    return `${location.origin}${location.pathname}#s=${await encodeState(meshLesson, state)}`;
  });
  const other = await page.context().newPage();
  other.problems = [];
  await other.goto(link);
  await other.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await other.waitForFunction(() => /flip-edge/.test(window.wingspline.message()));
  assert.match(await other.evaluate(() => window.wingspline.message()), /e1 is on the boundary/);
  // The page shows the saved work (the split mesh), not a half-applied link.
  assert.equal(await other.$$eval('#we-edge-table tbody tr[data-row]', (r) => r.length), 8);
});

test('every edit has a key of its own: with F1 picked, k pokes it (p stays the presentation key)', async () => {
  const page = await openLesson();
  await page.selectOption('#edit-kind', 'face');
  await page.fill('#edit-element', '1');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: F1');
  await page.evaluate(() => document.activeElement?.blur()); // keys typed into a field are the field's
  await page.keyboard.press('k');
  // Poking the triangle F1: V + 1, E + 3, F + 2.
  await page.waitForFunction(() => /after it 6 − 10 \+ 5 = 1/.test(document.querySelector('#edit-euler')?.textContent ?? ''));
  assert.equal(await page.evaluate(() => document.documentElement.hasAttribute('data-present')), false);
  // Every edit's key is listed in the keyboard dialog under "Edit" and claimed by nothing before it.
  const keys = await page.evaluate(() => window.wingspline.ctx.keymap.list());
  for (const k of keys.filter((b) => b.group === 'Edit').flatMap((b) => b.keys)) {
    assert.equal(keys.findIndex((b) => b.keys.includes(k)), keys.findIndex((b) => b.group === 'Edit' && b.keys.includes(k)), `key ${k} is the edit's`);
  }
});

test('split vertex, from the registry: pick v3, choose two neighbours, split it with its key, step it, undo it', async () => {
  const page = await openLesson();
  await page.selectOption('#edit-kind', 'vertex');
  await page.fill('#edit-element', '3');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: v3');
  // The two choices are v3's neighbours (the registry's query), each named by what it is.
  const options = await page.$$eval('#edit-corner-a option', (o) => o.map((x) => x.textContent));
  const neighbours = await page.evaluate(() => Array.from(window.wingspline.model.mesh.verticesAroundVertex(2), (v) => `v${v + 1}`));
  assert.deepEqual(options, neighbours);
  assert.match(await page.getAttribute('#edit-corner-a', 'aria-label'), /^Split vertex: neighbour/);
  await page.selectOption('#edit-corner-a', { label: 'v1' });
  await page.selectOption('#edit-corner-b', { label: 'v4' });
  assert.equal(await page.isEnabled('button[data-op="split-vertex"]'), true);
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('v');
  // V + 1, E + 3, F + 2: 6 − 10 + 5 = 1, as before the edit.
  await page.waitForFunction(() => /before the last edit 5 − 7 \+ 3 = 1; after it 6 − 10 \+ 5 = 1/.test(document.querySelector('#edit-euler')?.textContent ?? ''));
  await page.waitForFunction(() => window.wingspline.message().startsWith('Done: split v3 between v1 and v4'));
  // The new vertex v6 is joined to v3, v1 and v4 (the new triangles (v3, v1, v6) and (v3, v6, v4)).
  const aroundNew = await page.evaluate(() => Array.from(window.wingspline.model.mesh.verticesAroundVertex(5)).sort());
  for (const v of [0, 2, 3]) assert.ok(aroundNew.includes(v), `v6 is joined to v${v + 1}: ${aroundNew}`);
  await page.waitForFunction(() => document.querySelectorAll('#we-edge-table tbody tr[data-row]').length === 10);
  // The player steps the assignments from the first.
  const total = Number((await page.textContent('#edit-step')).split(' of ')[1]);
  assert.ok(total >= 24, `three new edge rows alone are 24 assignments: ${total}`);
  await page.click('#edit-restart');
  await page.waitForFunction(() => document.querySelector('#edit-step')?.textContent.startsWith('0 of'));
  // v6's three coordinates first, then its edge.
  for (let k = 1; k <= 4; k += 1) {
    await page.click('#edit-next');
    await page.waitForFunction((want) => document.querySelector('#edit-step')?.textContent.startsWith(`${want} of`), k);
  }
  assert.match(await page.textContent('#edit-steps li:nth-child(1)'), /vertex table, v6 · x: — → /);
  assert.match(await page.textContent('#edit-steps li.is-current'), /vertex table, v6 · edge: — → e8/);
  // Undo takes it back.
  await page.focus('body');
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => document.querySelectorAll('#we-edge-table tbody tr[data-row]').length === 7);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('the panel\'s words: a kind changed before a number says nothing; a triangle cannot be split between corners, and says why; a picked vertex lists its operations', async () => {
  const page = await openLesson();
  // Choosing "edge" with no number typed is not a mistake: no error line.
  await page.selectOption('#edit-kind', 'edge');
  await settle(page);
  assert.equal(await page.evaluate(() => window.wingspline.message()), '', 'no message before a number is typed');
  // A number out of range: the sentence says "an edge" and the range (the lecture mesh has e1..e7).
  await page.fill('#edit-element', '9');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => window.wingspline.message().startsWith('Choose an edge number from 1 to 7'));
  // F1 is a triangle (v1 v2 v3): split face between any two corners is refused with the reason
  // that a triangle's corners are all neighbours, not "choose two that are not".
  await page.selectOption('#edit-kind', 'face');
  await page.fill('#edit-element', '1');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: F1');
  const reason = await page.textContent('#edit-reasons li[data-op="split-face"]');
  assert.match(reason, /F1 is a triangle: every two of its corners are joined by a side/);
  assert.doesNotMatch(reason, /choose two corners/);
  // A picked vertex shows the operations on a vertex (split vertex), enabled or with its reason.
  await page.selectOption('#edit-kind', 'vertex');
  await page.fill('#edit-element', '2');
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction(() => document.querySelector('#edit-picked')?.textContent === 'Picked: v2');
  const shown = await page.$$eval('.edit-buttons button[data-op]', (bs) => bs.filter((b) => !b.hidden).map((b) => b.dataset.op));
  assert.deepEqual(shown, ['split-vertex']);
  const enabled = await page.isEnabled('button[data-op="split-vertex"]');
  const why = await page.$$eval('#edit-reasons li[data-op="split-vertex"]', (l) => l.map((x) => x.textContent));
  assert.ok(enabled || why.length === 1, 'either it applies, or the panel says why not');
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
