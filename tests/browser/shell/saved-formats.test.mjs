// What people saved keeps opening: for every build whose formats are kept in
// tests/fixtures/saved/ (written by that build, never regenerated: make-fixtures.mjs), its
// saved work in local storage, its share links, its exported files, its imported meshes in
// IndexedDB (database version 1), its exercise links and its progress open in this build, as
// the state that build held (with the fields later migrations add, at the values they give).
import { test, describe } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { useSiteAndBrowser, trap, waitReady, repoRoot } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();
const dir = path.join(repoRoot, 'tests', 'fixtures', 'saved');
const builds = fs.readdirSync(dir).filter((f) => f.endsWith('.json')).sort()
  .map((f) => JSON.parse(fs.readFileSync(path.join(dir, f), 'utf8')));

// The same values, whatever the order of the keys (JSON.stringify writes -0 as 0 on both sides).
const plain = (x) => (x === undefined ? undefined : JSON.parse(JSON.stringify(x)));
const same = (a, b) => { try { assert.deepStrictEqual(plain(a), plain(b)); return true; } catch { return false; } };
// The fields that differ, for the failure message.
const differ = (a, b) => Object.keys({ ...a, ...b }).filter((k) => !same(a?.[k], b?.[k])).map((k) => `${k}: ${JSON.stringify(a?.[k])?.slice(0, 120)} vs ${JSON.stringify(b?.[k])?.slice(0, 120)}`).join('; ');
// Fields a lesson's migrations added after a build was kept, with the value each migration
// gives an older state (the lesson's migrations in web/js/lessons/<id>/lesson.js): a saved
// state opens as it was, plus these. Any other difference fails.
const ADDED_SINCE = {
  subdivision: { reconnect: -1 }, // state version 3: the reconnection's playback, shown whole
};
async function sameState(page, saved, what) {
  const state = await page.evaluate(() => window.wingspline.state);
  const added = Object.fromEntries(Object.entries(ADDED_SINCE[await page.evaluate(() => window.wingspline.lesson)] ?? {})
    .filter(([key]) => !Object.hasOwn(saved, key)));
  const expected = { ...saved, ...added };
  assert.ok(same(state, expected), `${what}: ${differ(state, expected)}`);
}

async function open(context, url) {
  const page = trap(await context.newPage());
  await page.goto(url);
  await waitReady(page);
  return page;
}

for (const build of builds) {
  describe(`saved by ${build.build}`, () => {
    for (const [id, saved] of Object.entries(build.lessons)) {
      test(`${id}: the saved work in local storage, the share link and the exported file open as that build held them`, async () => {
        const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
        await context.addInitScript(([key, value]) => {
          if (!sessionStorage.getItem('seeded')) { localStorage.setItem(key, value); sessionStorage.setItem('seeded', '1'); }
        }, [saved.storageKey, saved.stored]);
        const page = await open(context, `${env.site.url}${saved.page}`);
        await sameState(page, saved.state, 'local storage');
        assert.equal(await page.evaluate(() => window.wingspline.message()), '', 'nothing to say');
        // Saved again in today's format, it still holds the same state.
        await page.evaluate(() => window.wingspline.flush());
        await page.reload();
        await waitReady(page);
        await sameState(page, saved.state, 'after a reload');

        const linked = await open(await env.newContext({ viewport: { width: 1280, height: 800 } }), `${env.site.url}${saved.page}${saved.hash}`);
        await sameState(linked, saved.state, 'share link');

        const fresh = await open(await env.newContext({ viewport: { width: 1280, height: 800 } }), `${env.site.url}${saved.page}`);
        await fresh.setInputFiles('#import-file', { name: `${id}-state.json`, mimeType: 'application/json', buffer: Buffer.from(saved.exported) });
        await fresh.waitForFunction((name) => window.wingspline.message().includes(name), `${id}-state.json`);
        await sameState(fresh, saved.state, 'exported file');
        assert.deepEqual([...page.problems, ...linked.problems, ...fresh.problems], []);
      });
    }

    if (build.imported) {
      test('an imported mesh kept in IndexedDB (database version 1) opens, and the database is upgraded keeping it', async () => {
        const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
        const seed = trap(await context.newPage());
        await seed.goto(`${env.site.url}index.html`);
        // The database as that build wrote it: version 1, one store `content` with index `used`.
        await seed.evaluate(async ({ entries, stored }) => {
          const db = await new Promise((resolve, reject) => {
            const req = indexedDB.open('wingspline-content', 1);
            req.onupgradeneeded = () => req.result.createObjectStore('content', { keyPath: 'hash' }).createIndex('used', 'used');
            req.onsuccess = () => resolve(req.result);
            req.onerror = () => reject(req.error);
          });
          const tx = db.transaction('content', 'readwrite');
          for (const { hash, text } of entries) tx.objectStore('content').put({ hash, text, used: Date.now() });
          await new Promise((resolve) => { tx.oncomplete = resolve; });
          db.close();
          localStorage.setItem('wingspline:mesh:state', stored);
        }, build.imported);
        const page = await open(context, `${env.site.url}mesh.html`);
        await sameState(page, build.imported.state, 'imported mesh');
        assert.equal(await page.evaluate(() => window.wingspline.model.F), 900);
        const db = await page.evaluate(() => new Promise((resolve) => {
          const req = indexedDB.open('wingspline-content');
          req.onsuccess = () => {
            const stores = [...req.result.objectStoreNames].sort();
            const get = req.result.transaction('meta').objectStore('meta').getAll();
            get.onsuccess = () => { resolve({ version: req.result.version, stores, meta: get.result.map((m) => [m.hash, m.chars]) }); req.result.close(); };
          };
        }));
        assert.equal(db.version, 2);
        assert.deepEqual(db.stores, ['content', 'history', 'meta']);
        assert.deepEqual(db.meta, build.imported.entries.map((e) => [e.hash, e.text.length]));
        assert.deepEqual(page.problems, []);
      });
    }

    test('its exercise link opens the exercise, and its progress shows as solved', async () => {
      const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
      const linked = await open(context, `${env.site.url}curves.html${build.exercise.hash}`);
      await linked.waitForSelector('#exercise-panel');
      assert.match(await linked.locator('#exercise-panel').innerText(), new RegExp(JSON.parse(build.exercise.text).title.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')));
      const withProgress = await env.newContext({ viewport: { width: 1280, height: 800 } });
      await withProgress.addInitScript((entries) => {
        if (!sessionStorage.getItem('seeded')) { for (const [k, v] of Object.entries(entries)) localStorage.setItem(k, v); sessionStorage.setItem('seeded', '1'); }
      }, build.progress);
      const page = await open(withProgress, `${env.site.url}curves.html#exercise=${JSON.parse(build.exercise.text).id}`);
      await page.waitForSelector('#exercise-status');
      assert.match(await page.locator('#exercise-status').innerText(), /Solved · 2 checks/);
      assert.deepEqual([...linked.problems, ...page.problems], []);
    });
  });
}
