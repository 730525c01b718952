// Nothing saved is lost (docs/classroom.md, "Your work in this browser"; docs/state-format.md,
// "Saved work and its revision", "The history"): two tabs of one lesson, a tab closed right
// after an edit, a page that frames a lesson, a link then a reload, the history's budget and
// Forget, imported meshes kept while anything refers to them, and a browser without
// IndexedDB. Real tabs (pages of one browser context share local storage and IndexedDB),
// real frames, real reloads, the pointer and the keyboard.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser, trap, waitReady } from '../../helpers/browser.mjs';
import { drag } from '../../helpers/pointer.mjs';

const env = useSiteAndBrowser();
const VIEWPORT = { viewport: { width: 1280, height: 800 } };

async function tab(context, page) {
  const p = trap(await context.newPage());
  await p.goto(`${env.site.url}${page}`);
  await waitReady(p);
  return p;
}
const points = (page) => page.evaluate(() => window.wingspline.state.points);
const record = (page, lesson = 'curves') => page.evaluate((k) => localStorage.getItem(k), `wingspline:${lesson}:state`);
const message = (page) => page.evaluate(() => window.wingspline.message());
const settle = (page) => page.evaluate(() => window.wingspline.flush());
// A tab that misses the other tabs' saves (one the browser froze, events lost): its
// listeners for them are stopped before the page's own, until hear() is called.
const deafen = (page) => page.evaluate(() => {
  window.__deaf = true;
  const stop = (e) => { if (window.__deaf) e.stopImmediatePropagation(); };
  window.addEventListener('storage', stop, true);
  document.addEventListener('visibilitychange', stop, true);
});
const hear = (page) => page.evaluate(() => { window.__deaf = false; });

// The History dialog's entries as the person reads them.
async function historyEntries(page) {
  await page.click('[data-action=history]');
  await page.waitForSelector('.history-dialog .history-list li');
  const items = await page.locator('.history-dialog .history-list li').allInnerTexts();
  return items.filter((t) => !/^Nothing yet/.test(t));
}

test('two tabs: each tab takes the other\'s later save; both edits survive closing one and reopening', async () => {
  const context = await env.newContext(VIEWPORT);
  const b = await tab(context, 'curves.html'); // opened earlier
  const a = await tab(context, 'curves.html');
  const start = await points(a);
  await drag(a, 'p0', 60, 0); // tab A moves P0
  await settle(a);
  const afterA = await points(a);
  assert.notDeepEqual(afterA[0], start[0]);
  await b.bringToFront();
  await b.waitForFunction((x) => window.wingspline.state.points[0][0] === x, afterA[0][0]);
  assert.match(await message(b), /Updated to the work saved in another tab/);
  await drag(b, 'p3', 0, -60); // tab B moves P3, on top of A's move
  await settle(b);
  const afterB = await points(b);
  assert.deepEqual(afterB[0], afterA[0], 'A\'s move is still in B');
  await a.close({ runBeforeUnload: true });
  const again = await tab(context, 'curves.html');
  assert.deepEqual(await points(again), afterB, 'reopened: both moves');
  assert.deepEqual([...a.problems, ...b.problems, ...again.problems], []);
});

test('a stale tab that only zooms with the wheel never writes its old drawing over a later save', async () => {
  const context = await env.newContext(VIEWPORT);
  const b = await tab(context, 'curves.html');
  await settle(b);
  // B misses the other tab's saves.
  await deafen(b);
  const a = await tab(context, 'curves.html');
  await drag(a, 'p0', 60, 0);
  await settle(a);
  const moved = await points(a);
  await b.bringToFront();
  const box = await b.locator('#stage').boundingBox();
  await b.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  for (let i = 0; i < 3; i += 1) await b.mouse.wheel(0, -200);
  await settle(b);
  const rec = JSON.parse(await record(b));
  const fresh = await tab(context, 'curves.html');
  assert.deepEqual(await points(fresh), moved, 'A\'s move is the saved work');
  assert.equal(rec.tab === JSON.parse(await record(a)).tab, true);
  // The stale tab shows the later work once it notices it (here: at its next write).
  await b.waitForFunction((x) => window.wingspline.state.points[0][0] === x, moved[0][0]);
  assert.deepEqual([...a.problems, ...b.problems], []);
});

test('two tabs editing the same work: the later save is the work, the other is set aside with one click back', async () => {
  const context = await env.newContext(VIEWPORT);
  const a = await tab(context, 'curves.html');
  const b = await tab(context, 'curves.html');
  for (const page of [a, b]) {
    await page.waitForTimeout(500); // the starting view fits the canvas while the page fills in
    await settle(page);
  }
  // Both tabs edit the same saved work before either has saved (within the debounce), as
  // two windows side by side do; whichever saves later is the current work.
  // Each edit returns the tab's points as it left them, in the same task: on a loaded machine
  // a debounced save can land before a later read, and the other tab take its work already.
  const edit = (page, i, dy) => page.evaluate(([i, dy]) => { const w = window.wingspline; const h = w.handles()[i]; w.ctx.commit(w.hooks.moveHandle(w.view, w.state, h.id, h.world.x, h.world.y + dy, w.model)); return w.state.points; }, [i, dy]);
  // (Both also miss each other's saves while they edit, so a slow machine, where one tab's
  // save can land before the other's edit, still meets the clash at the later write.)
  await deafen(a);
  await deafen(b);
  const [editedA, editedB] = await Promise.all([edit(a, 1, 0.5), edit(b, 2, -0.5)]);
  const mine = new Map([[a, editedA], [b, editedB]]);
  assert.notDeepEqual(mine.get(a), mine.get(b));
  await Promise.all([settle(a), settle(b)]);
  // Both are shown again and look at the saved work.
  for (const page of [a, b]) {
    await hear(page);
    await page.evaluate(() => document.dispatchEvent(new Event('visibilitychange')));
  }
  const setAside = (page) => page.evaluate(() => /set aside in the History/.test(window.wingspline.message()));
  let loser = null;
  // Up to 30 s: on a loaded machine (CI at a load of 15) the two debounced saves and the
  // storage events between two processes take seconds.
  for (let i = 0; i < 300 && !loser; i += 1) {
    if (await setAside(a)) loser = a; else if (await setAside(b)) loser = b; else await a.waitForTimeout(100);
  }
  assert.ok(loser, `one tab says its work was set aside: ${await a.evaluate(() => window.wingspline.message())} | ${await b.evaluate(() => window.wingspline.message())}`);
  const winner = loser === a ? b : a;
  assert.equal(await setAside(winner), false);
  assert.deepEqual(await points(loser), mine.get(winner), 'the set-aside tab now shows the current work');
  assert.match((await historyEntries(loser))[0], /set aside by a later save in another tab/);
  await loser.keyboard.press('Escape');
  // One click brings the work back; now the other tab's goes into the history and it says so.
  await loser.click('#message button:has-text("Bring my work back")');
  assert.deepEqual(await points(loser), mine.get(loser));
  await settle(loser);
  await winner.waitForFunction(() => /set aside in the History/.test(window.wingspline.message()));
  assert.deepEqual(await points(winner), mine.get(loser));
  const fresh = await tab(context, 'curves.html');
  assert.deepEqual(await points(fresh), mine.get(loser));
  const list = await historyEntries(fresh);
  assert.ok(list.length >= 2, `both set-aside works are in the history: ${list.join(' | ')}`);
  assert.deepEqual([...a.problems, ...b.problems, ...fresh.problems], []);
});

test('an edit is saved even when the tab is closed at once after it (6 runs)', async () => {
  const context = await env.newContext(VIEWPORT);
  for (let run = 0; run < 6; run += 1) {
    const page = await tab(context, 'curves.html');
    const before = await points(page);
    await page.click('#stage');
    await page.evaluate(() => { const w = window.wingspline; const h = w.handles()[0]; w.ctx.commit(w.hooks.moveHandle(w.view, w.state, h.id, h.world.x + 0.125, h.world.y, w.model)); });
    const edited = await points(page);
    assert.notDeepEqual(edited, before);
    await page.close({ runBeforeUnload: true }); // no time for the 200 ms debounce
    const next = await tab(context, 'curves.html');
    assert.deepEqual(await points(next), edited, `run ${run}: the edit came back`);
    await next.close();
  }
});

test('a page that frames a lesson (same site, no embed=1, hidden) reads and writes nothing of the saved work', async () => {
  const context = await env.newContext(VIEWPORT);
  const own = await tab(context, 'curves.html');
  await drag(own, 'p1', 40, 40);
  await settle(own);
  const saved = await record(own);
  const ownPoints = await points(own);
  await own.close();
  // A link made elsewhere: the starting point moved.
  const maker = await env.openLesson(`${env.site.url}curves.html`);
  await drag(maker, 'p2', -50, 30);
  const link = await maker.evaluate(() => window.wingspline.shareUrl());
  const host = trap(await context.newPage());
  await host.goto(`${env.site.url}index.html`);
  await host.evaluate((src) => {
    const frame = document.createElement('iframe');
    frame.src = src;
    frame.width = '1';
    frame.height = '1';
    frame.style.opacity = '0';
    document.body.append(frame);
  }, link);
  const frame = await (await host.waitForSelector('iframe')).contentFrame();
  await frame.waitForSelector('body[data-ready=true]', { state: 'attached' });
  // The frame's own edits are not saved either.
  await frame.evaluate(() => { const w = window.wingspline; const h = w.handles()[0]; w.ctx.commit(w.hooks.moveHandle(w.view, w.state, h.id, 9, 9, w.model)); });
  await frame.evaluate(() => window.wingspline.flush());
  assert.equal(await frame.evaluate(() => window.wingspline.message()).then((m) => /previous work/i.test(m)), false, 'no restore offer in the frame');
  assert.equal(await frame.locator('[data-action=history]').count(), 0, 'no History in a frame');
  await host.evaluate(() => document.querySelector('iframe').remove());
  assert.equal(await record(host), saved, 'the saved work is unchanged');
  const back = await tab(context, 'curves.html');
  assert.deepEqual(await points(back), ownPoints);
  assert.equal(await back.evaluate(() => Object.keys(localStorage).filter((k) => k.startsWith('wingspline:aside:')).length), 0);
  assert.deepEqual((await historyEntries(back)).length, 0, 'nothing went into the history either');
  assert.deepEqual([...host.problems, ...back.problems], []);
});

test('a link replaced my work, then I reloaded: the work is in the History and one click brings it back', async () => {
  const context = await env.newContext(VIEWPORT);
  const page = await tab(context, 'curves.html');
  await drag(page, 'p1', 40, 40);
  await settle(page);
  const mine = await points(page);
  const maker = await env.openLesson(`${env.site.url}curves.html`);
  const link = await maker.evaluate(() => window.wingspline.shareUrl());
  const linked = await points(maker);
  await page.goto(link);
  await waitReady(page);
  assert.deepEqual(await points(page), linked);
  await settle(page);
  await page.reload();
  await waitReady(page);
  assert.deepEqual(await points(page), linked, 'after the reload: the link\'s state');
  const entries = await historyEntries(page);
  assert.equal(entries.length, 1);
  assert.match(entries[0], /bezier curve, 4 control points: .* \(replaced by a link\)/);
  await page.click('.history-dialog [data-history-restore]');
  assert.deepEqual(await points(page), mine, 'restored');
  assert.match(await message(page), /Restored your work of/);
  await settle(page);
  await page.reload();
  await waitReady(page);
  assert.deepEqual(await points(page), mine, 'and kept over a reload');
  // The link's state went into the history by the restore.
  assert.match((await historyEntries(page))[0], /replaced by a restore/);
  assert.deepEqual(page.problems, []);
});

test('Reset and an import put the work they replace into the History; the same work is kept once', async () => {
  const context = await env.newContext(VIEWPORT);
  const page = await tab(context, 'curves.html');
  await drag(page, 'p1', 40, 40);
  await settle(page);
  await page.click('[data-action=reset]');
  await settle(page);
  await drag(page, 'p1', 40, 40); // the same edit again: the same work
  await settle(page);
  await page.click('[data-action=reset]');
  await settle(page);
  const entries = await historyEntries(page);
  assert.equal(entries.length, 1, entries.join(' | '));
  assert.match(entries[0], /before Reset/);
  await page.keyboard.press('Escape');
  await drag(page, 'p2', -30, 0);
  await settle(page);
  const file = await page.evaluate(() => window.wingspline.hooks.defaultState());
  await page.setInputFiles('#import-file', { name: 'start.json', mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify({ format: 'wingspline', lesson: 'curves', version: 3, state: file })) });
  await page.waitForFunction(() => /Imported|imported/.test(window.wingspline.message()));
  await settle(page);
  assert.match((await historyEntries(page))[0], /replaced by an import/);
  assert.deepEqual(page.problems, []);
});

test('the history keeps its budget: the newest 40 of a lesson; unreadable entries set aside are never written over', async () => {
  const context = await env.newContext(VIEWPORT);
  const page = await tab(context, 'curves.html');
  const counts = await page.evaluate(async () => {
    const { createWorkHistory, MAX_PER_LESSON } = await import('./js/app/work-history.js');
    const { createContentStore } = await import('./js/app/content-store.js');
    const { createDatabase } = await import('./js/app/idb.js');
    const db = createDatabase();
    let history = null;
    const contents = createContentStore({ db, referenced: () => history.referenced() });
    history = createWorkHistory({ db, contents });
    for (let i = 0; i < 50; i += 1) await history.add({ lesson: 'surfaces', reason: 'reset', summary: `entry ${i}`, code: `code-${i}`, time: 1000 + i });
    // 1,001 unreadable entries set aside: each under a key of its own, all moved into the history.
    for (let i = 0; i < 1001; i += 1) localStorage.setItem(`wingspline:aside:${i}`, JSON.stringify({ lesson: 'comparison', reason: 'unreadable', raw: `old ${i}` }));
    const moved = await history.sweep();
    const list = await history.list('surfaces');
    const unreadable = await history.list('comparison');
    return { max: MAX_PER_LESSON, kept: list.length, newest: list[0].summary, oldest: list.at(-1).summary, moved, unreadable: unreadable.length,
      left: Object.keys(localStorage).filter((k) => k.startsWith('wingspline:aside:')).length, distinct: new Set(unreadable.map((e) => e.raw)).size };
  });
  assert.equal(counts.kept, counts.max);
  assert.equal(counts.newest, 'entry 49');
  assert.equal(counts.oldest, `entry ${50 - counts.max}`);
  assert.equal(counts.moved, 1001);
  assert.equal(counts.left, 0);
  // The per-lesson cap applies to unreadable entries too: the newest 40 of 1,001, none overwritten by another.
  assert.equal(counts.unreadable, counts.max);
  assert.equal(counts.distinct, counts.max);
});

test('the history\'s byte budget drops the oldest entries and the meshes only they refer to, never the saved work\'s', async () => {
  const context = await env.newContext(VIEWPORT);
  const page = await tab(context, 'mesh.html');
  const r = await page.evaluate(async () => {
    const { createWorkHistory } = await import('./js/app/work-history.js');
    const { createContentStore } = await import('./js/app/content-store.js');
    const { createDatabase } = await import('./js/app/idb.js');
    const { packText, sha256 } = await import('./js/app/share-link.js');
    const db = createDatabase();
    let history = null;
    const budget = 100000;
    const contents = createContentStore({ db, referenced: () => history.referenced(), budgetChars: budget });
    history = createWorkHistory({ db, contents, budgetChars: budget });
    const text = (i) => JSON.stringify({ name: `m${i}`, pad: 'x'.repeat(30000) });
    const code = async (hash) => packText(JSON.stringify({ format: 'wingspline', lesson: 'mesh', version: 3, state: { imported: { $content: hash, label: 'm' } } }));
    // Five imports one after the other: each is the saved work, and the one before goes into
    // the history (as the page does: the saved record, then the history entry).
    const hashes = [];
    let saved = null;
    for (let i = 0; i < 5; i += 1) {
      hashes.push(await sha256(text(i)));
      await contents.put(hashes[i], text(i));
      if (saved) await history.add({ lesson: 'mesh', reason: 'import', summary: `mesh ${i - 1}`, code: saved, time: 1000 + i });
      saved = await code(hashes[i]);
      localStorage.setItem('wingspline:mesh:state', JSON.stringify({ v: 2, rev: i + 1, tab: 't', at: 1, drawing: 'd', summary: '', code: saved }));
      contents.pin([hashes[i]]);
    }
    await history.prune(); // (the page prunes once the saved work is written)
    const list = await history.list('mesh');
    const sizes = await contents.sizes();
    return { kept: list.map((e) => e.summary), stored: hashes.map((h) => sizes.has(h)) };
  });
  // 100,000 characters: the saved work's mesh (30,022) and two entries with theirs fit, not three.
  assert.deepEqual(r.kept, ['mesh 3', 'mesh 2']);
  assert.deepEqual(r.stored, [false, false, true, true, true]);
});

test('Forget my work on this computer clears the saved work, the history and the progress, after a confirmation', async () => {
  const context = await env.newContext(VIEWPORT);
  const page = await tab(context, 'curves.html');
  await drag(page, 'p1', 40, 40);
  await settle(page);
  await page.click('[data-action=reset]');
  await settle(page);
  await drag(page, 'p2', 40, 40);
  await settle(page);
  await page.evaluate(() => { localStorage.setItem('wingspline:exercise:site:curves-bernstein-half', '{"version":1,"status":"solved","checks":1}'); localStorage.setItem('wingspline:theme', 'dark'); });
  await page.click('[data-action=history]');
  await page.click('[data-action=forget]');
  await page.click('[data-action=forget-cancel]'); // changed my mind
  assert.equal((await page.locator('.history-dialog .history-list li').count()), 1);
  await page.click('[data-action=forget]');
  await Promise.all([page.waitForNavigation(), page.click('[data-action=forget-confirm]')]);
  await waitReady(page);
  await settle(page);
  const left = await page.evaluate(() => Object.keys(localStorage).filter((k) => k.startsWith('wingspline:')).sort());
  // The theme is a setting, not work; the fresh page keeps what it shows (the starting point).
  assert.deepEqual(left, ['wingspline:curves:state', 'wingspline:theme']);
  assert.deepEqual(await points(page), await page.evaluate(() => window.wingspline.hooks.defaultState().points));
  assert.equal(JSON.parse(await record(page)).rev, 1, 'a first save: nothing of the earlier revisions is left');
  assert.deepEqual(await historyEntries(page), []);
  assert.deepEqual(page.problems, []);
});

// A grid of (n+1)^2 vertices and 2 n^2 triangles as OFF text, heights with many digits (so
// it does not compress to nothing); `salt` makes each file different.
function gridOff(n, salt = 0) {
  const lines = ['OFF', `${(n + 1) ** 2} ${2 * n * n} 0`];
  for (let j = 0; j <= n; j += 1) for (let i = 0; i <= n; i += 1) lines.push(`${(i / n).toFixed(9)} ${(j / n).toFixed(9)} ${Math.sin(i * 0.37 + j * 0.11 + salt).toFixed(9)}`);
  for (let j = 0; j < n; j += 1) {
    for (let i = 0; i < n; i += 1) {
      const a = j * (n + 1) + i;
      lines.push(`3 ${a} ${a + 1} ${a + n + 2}`, `3 ${a} ${a + n + 2} ${a + n + 1}`);
    }
  }
  return Buffer.from(`${lines.join('\n')}\n`);
}

test('sixteen imports in another lesson never evict the mesh the saved work refers to', async () => {
  const context = await env.newContext(VIEWPORT);
  const mesh = await tab(context, 'mesh.html');
  await mesh.setInputFiles('#import-file', { name: 'mine.off', mimeType: 'text/plain', buffer: gridOff(30) });
  await mesh.waitForFunction(() => window.wingspline.model?.F === 1800, null, { timeout: 60000 });
  await settle(mesh);
  await mesh.close();
  const sub = await tab(context, 'subdivision.html');
  for (let i = 1; i <= 17; i += 1) {
    await sub.setInputFiles('#import-file', { name: `other-${i}.off`, mimeType: 'text/plain', buffer: gridOff(30, i) });
    await sub.waitForFunction((name) => window.wingspline.state.imported?.name === name, `other-${i}.off`, { timeout: 60000 });
    await settle(sub);
  }
  const again = await tab(context, 'mesh.html');
  assert.equal(await again.evaluate(() => window.wingspline.model.F), 1800);
  assert.equal(await again.evaluate(() => window.wingspline.state.imported.name), 'mine.off');
  assert.doesNotMatch(await message(again), /could not|another browser/);
  // The subdivision lesson's saved work still opens too, and its history holds its earlier imports.
  const sub2 = await tab(context, 'subdivision.html');
  assert.equal(await sub2.evaluate(() => window.wingspline.state.imported.name), 'other-17.off');
  assert.deepEqual([...sub.problems, ...again.problems, ...sub2.problems], []);
});

// A browser without IndexedDB (as some private modes): neither the pages nor the import
// worker (whose script gets the same first line) find it.
async function withoutIndexedDb(context) {
  const hide = 'Object.defineProperty(globalThis, \'indexedDB\', { get() { return undefined; } });';
  await context.addInitScript(hide);
  await context.route('**/mesh-import-worker.js', async (route) => {
    const response = await route.fetch();
    await route.fulfill({ response, body: `${hide}\n${await response.text()}` });
  });
}

test('without IndexedDB: a mesh too big to keep is not saved over the earlier work, said with its file; the history says where it lives', async () => {
  const context = await env.newContext(VIEWPORT);
  await withoutIndexedDb(context);
  const page = await tab(context, 'mesh.html');
  await page.selectOption('#mesh-kind', 'tetrahedron');
  await page.waitForFunction(() => window.wingspline.model?.F === 4);
  await settle(page);
  const saved = await record(page, 'mesh');
  await page.setInputFiles('#import-file', { name: 'big.off', mimeType: 'text/plain', buffer: gridOff(160) }); // 51,200 faces
  await page.waitForFunction(() => window.wingspline.model?.F === 51200, null, { timeout: 120000 });
  await settle(page);
  await page.waitForFunction(() => document.querySelector('#message')?.dataset.code === 'too-long-to-keep');
  assert.match(await message(page), /too large to keep in this browser here .* gone after a reload; your earlier saved work is kept/);
  assert.equal(await page.locator('#message button:has-text("Export the OFF file")').count(), 1, 'the file is offered');
  assert.equal(await record(page, 'mesh'), saved, 'the earlier work is still the saved work');
  const link = await page.evaluate(() => new URLSearchParams(location.hash.slice(1)).get('s') ?? '');
  assert.ok(link.length < 200000, 'the address bar holds no link the reader would refuse');
  await page.reload();
  await waitReady(page);
  assert.equal(await page.evaluate(() => window.wingspline.model.F), 4, 'the earlier work opens after a reload');
  assert.deepEqual(page.problems, []);
  await page.click('[data-action=history]');
  await page.waitForSelector('.history-dialog .history-note');
  assert.match(await page.locator('.history-dialog .history-note').innerText(), /no IndexedDB here .* large imported meshes are not kept/);
});

test('an exercise\'s drawing goes into the History before its Reset and before Start again, and comes back from it', async () => {
  const context = await env.newContext(VIEWPORT);
  const page = await tab(context, 'curves.html#exercise=curves-through-a-point');
  await page.waitForSelector('#exercise-panel');
  const first = await page.evaluate(() => window.wingspline.handles().find((x) => x.draggable).id);
  await drag(page, first, 30, -30);
  const dragged = await points(page);
  await page.click('[data-action=reset]');
  await page.waitForFunction(() => window.wingspline.historyEntries().then((list) => list.length === 1));
  const [entry] = await page.evaluate(() => window.wingspline.historyEntries());
  assert.equal(entry.reason, 'exercise');
  assert.match(entry.summary, /your drawing in the exercise/);
  // Restore from the History brings the drawing back into the exercise.
  await page.click('[data-action=history]');
  await page.click('.history-dialog [data-history-restore]');
  assert.deepEqual(await points(page), dragged);
  // Start again: the attempt (its drawing) is kept too, and listed after the reload.
  await drag(page, first, -30, 30);
  await page.waitForTimeout(400); // the exercise's progress is written once the drawing rests
  await Promise.all([page.waitForNavigation(), page.click('#exercise-start-again')]);
  await waitReady(page);
  await page.waitForFunction(() => window.wingspline.historyEntries().then((list) => list.some((e) => /your attempt at/.test(e.summary))));
  assert.deepEqual(page.problems, []);
});

test('the History by keyboard alone, and axe finds no serious violation in it (light and dark)', async () => {
  const { createRequire } = await import('node:module');
  const fs = await import('node:fs');
  const axeSource = fs.readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
  for (const scheme of ['light', 'dark']) {
    const context = await env.newContext({ ...VIEWPORT, colorScheme: scheme });
    const page = await tab(context, 'curves.html');
    await drag(page, 'p1', 40, 40);
    await settle(page);
    const mine = await points(page);
    await page.click('[data-action=reset]');
    await settle(page);
    await page.focus('[data-action=history]');
    await page.keyboard.press('Enter');
    await page.waitForSelector('.history-dialog [data-history-restore]');
    await page.evaluate(axeSource);
    const violations = await page.evaluate(() => window.axe.run(document.querySelector('.history-dialog'), { resultTypes: ['violations'] }));
    assert.deepEqual(violations.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.help}`), [], scheme);
    // Tab reaches Restore (its name says which work); Enter restores and closes the dialog.
    let name = '';
    for (let i = 0; i < 10 && !/^Restore the work of/.test(name); i += 1) {
      await page.keyboard.press('Tab');
      name = await page.evaluate(() => document.activeElement?.getAttribute('aria-label') ?? '');
    }
    assert.match(name, /^Restore the work of .*: bezier curve/);
    await page.keyboard.press('Enter');
    await page.waitForSelector('.history-dialog', { state: 'detached' });
    assert.deepEqual(await points(page), mine);
    assert.deepEqual(page.problems, []);
  }
});
