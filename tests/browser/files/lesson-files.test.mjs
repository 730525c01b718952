// Export and import, for every ready lesson and the fixture lesson: the JSON file
// is the documented envelope (docs/state-format.md) and imports back to the identical state,
// numbers bit for bit; SVG and PNG figures and the lesson's own exports download; JSON is
// imported by the file picker and by drag and drop; a hostile file name and contents are
// shown as text and nothing runs.
import { test, describe } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser, downloadedBytes } from '../../helpers/browser.mjs';
import {
  lessonsUnderTest, startClassroomSite, openLesson, waitReady, nothingExecuted, payloads, stateBits, bitsOf,
  awkwardView, tinyView, setView
} from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser(startClassroomSite);

async function exportFile(page, key) {
  await page.click('details.menu > summary');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(`[data-export="${key}"]`)]);
  return { name: download.suggestedFilename(), bytes: await downloadedBytes(download) };
}

async function importByPicker(page, name, text) {
  await page.setInputFiles('#import-file', { name, mimeType: 'application/json', buffer: Buffer.from(text) });
}

async function importByDrop(page, name, text) {
  await page.evaluate(({ name: n, text: t }) => {
    const data = new DataTransfer();
    data.items.add(new File([t], n, { type: 'application/json' }));
    document.body.dispatchEvent(new DragEvent('dragover', { dataTransfer: data, bubbles: true, cancelable: true }));
    document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
  }, { name, text });
}

for (const lesson of lessonsUnderTest) {
  describe(`${lesson.title}: export and import`, () => {
    test('the JSON export is the versioned envelope and imports back bit for bit', async () => {
      const page = await env.openLesson(new URL(lesson.page, env.site.url).href);
      await setView(page, awkwardView);
      const exported = await stateBits(page);
      const file = await exportFile(page, `${lesson.id}-state.json`);
      assert.equal(file.name, `${lesson.id}-state.json`);
      const text = file.bytes.toString('utf8');
      const data = JSON.parse(text);
      assert.deepEqual(Object.keys(data), ['format', 'lesson', 'version', 'state']);
      assert.equal(data.format, 'wingspline');
      assert.equal(data.lesson, lesson.id);
      assert.ok(Number.isInteger(data.version) && data.version >= 1);
      assert.deepEqual(bitsOf(data.state), exported, 'the file holds the state, -0 and 0.1+0.2 exactly');
      assert.match(text, /"cy": -0[,\n]/, '-0 is written with its sign');
      // Change the state, then import the file by the picker: back to the exported state.
      await setView(page, tinyView);
      assert.notDeepEqual(await stateBits(page), exported);
      await importByPicker(page, file.name, text);
      await page.waitForFunction(() => /Imported/.test(window.wingspline.message()));
      assert.deepEqual(await stateBits(page), exported, 'file picker');
      // And by drag and drop.
      await setView(page, tinyView);
      await importByDrop(page, file.name, text);
      await page.waitForFunction((v) => window.wingspline.state.view.zoom !== v, tinyView.zoom);
      assert.deepEqual(await stateBits(page), exported, 'drag and drop');
      // The import is one undoable step.
      await page.click('[data-action=undo]');
      assert.deepEqual((await stateBits(page)).view, bitsOf(tinyView));
      assert.deepEqual(page.problems, []);
    });

    test('SVG and PNG figures and the lesson exports download', async () => {
      const page = await env.openLesson(new URL(lesson.page, env.site.url).href);
      const svg = await exportFile(page, `${lesson.id}.svg`);
      assert.match(svg.bytes.toString('utf8'), /^(<\?xml[^>]*\?>\s*)?<svg[^>]*xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
      const png = await exportFile(page, `${lesson.id}.png`);
      assert.deepEqual([...png.bytes.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a], 'PNG signature');
      const extra = await page.$$eval('[data-export]', (buttons) => buttons.map((b) => b.dataset.export));
      for (const key of extra.slice(3)) {
        const file = await exportFile(page, key);
        assert.ok(file.bytes.length > 0, `${key} is not empty`);
      }
      assert.deepEqual(page.problems, []);
    });

    test('a hostile file name and contents are shown as text and nothing runs', async () => {
      const page = await env.openLesson(new URL(lesson.page, env.site.url).href);
      const before0 = await stateBits(page);
      const name = '<img src=x onerror=alert(1)>.json';
      await importByPicker(page, name, '{"format":"wingspline"');
      await page.waitForSelector('#message[data-kind=error]');
      const message = await page.evaluate(() => window.wingspline.message());
      assert.ok(message.startsWith(`${name} was not imported`), message);
      await importByDrop(page, name, JSON.stringify({ format: 'wingspline', lesson: payloads.img, version: 1, state: {} }));
      await page.waitForFunction(() => /does not name a lesson/.test(window.wingspline.message()));
      const version = lesson.fixture ? 2 : 1;
      await importByPicker(page, `${payloads.script}.json`, JSON.stringify({ format: 'wingspline', lesson: lesson.id, version, state: { view: payloads.svg } }));
      await page.waitForFunction((n) => window.wingspline.message().startsWith(`${n}.json was not imported`), payloads.script);
      assert.match(await page.evaluate(() => window.wingspline.message()), /view must be an object/);
      assert.deepEqual(await stateBits(page), before0, 'a refused file changes nothing');
      assert.deepEqual(await nothingExecuted(page), { pwned: null, injectedElements: 0 });
      assert.deepEqual(page.dialogs, [], 'no alert ran');
      assert.deepEqual(page.problems, []);
    });
  });
}

describe('Classroom fixture: lesson exports', () => {
  test('the CSV export holds the points in full precision and its importer reads it back', async () => {
    const page = await env.openLesson(new URL('fixture.html', env.site.url).href);
    const points = [{ x: 0.1 + 0.2, y: 1e-300 }, { x: -1.5, y: 2 }, { x: 3, y: 1 / 3 }];
    await page.evaluate((p) => window.wingspline.ctx.commit({ ...window.wingspline.ctx.state, points: p }), points);
    const csv = await exportFile(page, 'fixture-points.csv');
    assert.equal(csv.bytes.toString('utf8'), 'i,x,y\n0,0.30000000000000004,1e-300\n1,-1.5,2\n2,3,0.3333333333333333\n');
    await page.evaluate(() => window.wingspline.ctx.commit({ ...window.wingspline.ctx.state, points: [{ x: 0, y: 0 }, { x: 1, y: 1 }] }));
    await page.setInputFiles('#import-file', { name: 'points.csv', mimeType: 'text/csv', buffer: csv.bytes });
    await page.waitForFunction(() => window.wingspline.state.points.length === 3);
    assert.deepEqual((await stateBits(page)).points, bitsOf(points));
  });
});

// An imported mesh of 20,000 vertices or more used to make the link and
// the saved state too long to read back, and the lecture mesh was saved over it. Imported
// meshes are now kept in IndexedDB by content hash and the state refers to them.
// A grid of nx x ny vertices as OFF text, coordinates with many digits (so the file does
// not compress to nothing), triangles of two per cell.
function gridOff(nx, ny) {
  const lines = ['OFF', `${nx * ny} ${2 * (nx - 1) * (ny - 1)} 0`];
  for (let j = 0; j < ny; j += 1) {
    for (let i = 0; i < nx; i += 1) lines.push(`${(i / 7).toFixed(9)} ${(j / 3).toFixed(9)} ${Math.sin(i * 0.37 + j * 0.11).toFixed(9)}`);
  }
  for (let j = 0; j + 1 < ny; j += 1) {
    for (let i = 0; i + 1 < nx; i += 1) {
      const a = j * nx + i;
      lines.push(`3 ${a} ${a + 1} ${a + nx + 1}`, `3 ${a} ${a + nx + 1} ${a + nx}`);
    }
  }
  return `${lines.join('\n')}\n`;
}
const BIG = { nx: 160, ny: 160, name: 'big-grid.off' }; // 25,600 vertices, 50,562 faces
const LINK_MAX_CHARS = 2000; // a link to a big mesh names it, it does not carry it

async function importOff(page, name, text) {
  await page.setInputFiles('#import-file', { name, mimeType: 'text/plain', buffer: Buffer.from(text) });
  await page.waitForFunction((n) => window.wingspline.message().startsWith(`Imported ${n}`), name, { timeout: 60000 });
  await page.evaluate(() => window.wingspline.flush());
}
const meshSummary = (page) => page.evaluate(() => ({
  kind: window.wingspline.state.meshKind, name: window.wingspline.state.imported?.name ?? null,
  V: window.wingspline.model.V, F: window.wingspline.model.F,
}));

describe('Mesh: imported meshes are kept', () => {
  const meshUrl = () => new URL('mesh.html', env.site.url).href;

  test('a 25,600-vertex OFF imported with the file chooser is still there after a reload', async () => {
    const page = await env.openLesson(meshUrl());
    await importOff(page, BIG.name, gridOff(BIG.nx, BIG.ny));
    const expected = { kind: 'file', name: BIG.name, V: BIG.nx * BIG.ny, F: 2 * (BIG.nx - 1) * (BIG.ny - 1) };
    assert.deepEqual(await meshSummary(page), expected);
    assert.ok(page.url().length < LINK_MAX_CHARS, `the link stays small (${page.url().length} characters)`);
    await page.reload();
    await waitReady(page);
    assert.equal(await page.evaluate(() => window.wingspline.message()), '', 'no warning after the reload');
    assert.deepEqual(await meshSummary(page), expected, 'reload from the link');
    await page.goto(meshUrl());
    await waitReady(page);
    assert.deepEqual(await meshSummary(page), expected, 'reopened without a link (saved work)');
    assert.deepEqual(page.problems, []);
  });

  test('a link to a big imported mesh: the share button offers the file, another browser is told and keeps its work', async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
    const page = await openLesson(context, meshUrl());
    await importOff(page, BIG.name, gridOff(BIG.nx, BIG.ny));
    await page.click('[data-action=share]');
    await page.waitForFunction(() => /only stored in this browser/.test(window.wingspline.message()));
    assert.match(await page.evaluate(() => window.wingspline.message()), /share the OFF file/i);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#message [data-message-action]')]);
    assert.equal(download.suggestedFilename(), 'mesh.off');
    const off = (await downloadedBytes(download)).toString('utf8');
    assert.match(off, new RegExp(`^OFF\\s+${BIG.nx * BIG.ny}\\s+${2 * (BIG.nx - 1) * (BIG.ny - 1)}\\s`));
    const link = page.url();
    await context.close();

    // Another browser, with work of its own.
    const other = await env.newContext({ viewport: { width: 1280, height: 800 } });
    let mine = await openLesson(other, meshUrl());
    await mine.selectOption('#mesh-kind', 'cube');
    await mine.waitForFunction(() => window.wingspline.state.meshKind === 'cube');
    await mine.evaluate(() => window.wingspline.flush());
    const saved = await stateBits(mine);
    await mine.close();
    mine = await openLesson(other, link);
    const text = await mine.evaluate(() => window.wingspline.message());
    assert.match(text, /imported mesh/, text);
    assert.match(text, /big-grid\.off/, 'the message names the file to ask for');
    assert.deepEqual(await stateBits(mine), saved, 'the saved work is shown, not the default');
    await mine.evaluate(() => window.wingspline.flush());
    await mine.goto(meshUrl());
    await waitReady(mine);
    assert.deepEqual(await stateBits(mine), saved, 'and the saved work was not overwritten');
  });

  test('a small imported mesh still travels inside the link to another browser', async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
    const page = await openLesson(context, meshUrl());
    await importOff(page, 'small-grid.off', gridOff(6, 5));
    const link = page.url();
    const expected = await meshSummary(page);
    await page.click('[data-action=share]');
    await page.waitForFunction(() => /Link copied|address bar/.test(window.wingspline.message()));
    await context.close();
    const fresh = await env.openLesson(link);
    assert.deepEqual(await meshSummary(fresh), expected);
    assert.equal(await fresh.evaluate(() => window.wingspline.message()), '');
  });
});
