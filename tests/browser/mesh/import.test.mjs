// Import: a mesh file is read, parsed and checked off the page (a worker) with a
// progress bar naming the stage and a Cancel button; cancelling (pointer or Escape) leaves
// the previous mesh, its drawing and tables; a file over the limits is refused with the figure
// and the limit, and the saved work is kept; a 200,000-face import survives a reload. The
// files are generated here with the core (UV spheres, docs/benchmarks.md's construction), never
// committed. The page is asked for its state and counts, the maths stays in the core.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();
let api;
// sphere(slices, stacks) has 2 * slices * (stacks - 1) triangles.
const offs = new Map();
function sphereOff(slices, stacks) {
  const key = `${slices}x${stacks}`;
  if (!offs.has(key)) offs.set(key, Buffer.from(api.formatMesh(api.generateMesh('sphere', { slices, stacks, layout: 'csr' }), { format: 'off' })));
  return offs.get(key);
}
before(async () => { api = await loadWingspline(); });

async function openMesh() {
  const page = await env.openLesson(`${env.site.url}mesh.html`);
  await page.selectOption('#mesh-kind', 'tetrahedron'); // some work of the person's own
  await page.waitForFunction(() => window.wingspline.model?.F === 4);
  await page.evaluate(() => window.wingspline.flush());
  return page;
}

// Chosen as a file on disk, as a person picks one: the browser reads the path itself (a
// 15 MB buffer sent through the protocol took over 30 s on a busy machine).
const fileDir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-import-'));
after(() => fs.rmSync(fileDir, { recursive: true, force: true }));
const choose = (page, name, buffer) => {
  const file = path.join(fileDir, name);
  fs.writeFileSync(file, buffer);
  return page.setInputFiles('#import-file', file);
};
const frames = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

// What the person sees and what the page keeps: state, counts, the drawing, the tables,
// the saved state.
async function snapshot(page) {
  await frames(page);
  return page.evaluate(() => ({
    state: JSON.stringify(window.wingspline.state),
    counts: [window.wingspline.model.V, window.wingspline.model.E, window.wingspline.model.F],
    canvas: document.querySelector('#stage').toDataURL(),
    panels: document.querySelector('#panels').textContent,
    saved: localStorage.getItem('wingspline:mesh:state'),
  }));
}

for (const how of ['pointer', 'Escape']) {
  test(`an import shows its progress and stage; Cancel by ${how} leaves the previous mesh, drawing, tables and saved work`, async () => {
    const page = await openMesh();
    const before = await snapshot(page);
    await choose(page, 'sphere-300k.off', sphereOff(500, 301)); // 300,000 faces, about 15 MB
    await page.waitForSelector('#import-progress', { state: 'visible' });
    const label = await page.textContent('#import-stage');
    assert.match(label, /^(Reading|Parsing|Checking) sphere-300k\.off/, 'the label names the stage and the file');
    assert.equal(await page.getAttribute('#import-progress', 'id'), await page.getAttribute('#import-stage', 'for'), 'the bar is labelled');
    if (how === 'pointer') await page.click('#import-cancel');
    else await page.keyboard.press('Escape');
    await page.waitForFunction(() => /cancelled/.test(window.wingspline.message()));
    assert.match(await page.evaluate(() => window.wingspline.message()), /Import of sphere-300k\.off cancelled; your mesh and work are unchanged/);
    assert.equal(await page.isVisible('#import-progress'), false);
    // Long enough for the terminated worker's import to have finished had it gone on.
    await page.waitForTimeout(4000);
    assert.deepEqual(await snapshot(page), before);
    assert.deepEqual(page.problems, []);
  });
}

test('a file whose OFF header is over the limit is refused naming the figure and the limit; the work is kept over a reload', async () => {
  const page = await openMesh();
  const before = await snapshot(page);
  const limit = api.meshLimits.maxFaces;
  const body = '0 0 0\n'.repeat(200000); // never read: the header already refuses the file
  await choose(page, 'huge.off', Buffer.from(`OFF\n3 ${limit + 1} 0\n${body}`));
  await page.waitForFunction(() => /not imported/.test(window.wingspline.message()));
  const text = await page.evaluate(() => window.wingspline.message());
  assert.match(text, /huge\.off was not imported/);
  assert.match(text, new RegExp(String(limit + 1)), 'names the figure');
  assert.match(text, new RegExp(String(limit)), 'names the limit');
  assert.equal(await page.getAttribute('#message', 'data-code'), 'too-large');
  assert.deepEqual(await snapshot(page), before);
  await page.reload();
  await page.waitForSelector('body[data-ready=true]');
  await page.waitForFunction(() => window.wingspline.model?.F === 4);
  assert.equal(await page.evaluate(() => window.wingspline.state.meshKind), 'tetrahedron');
  assert.deepEqual(page.problems, []);
});

test('a 200,000-face import is drawn and survives a reload (kept in IndexedDB by its hash)', async () => {
  const page = await openMesh();
  await choose(page, 'sphere-200k.off', sphereOff(400, 251));
  await page.waitForFunction(() => window.wingspline.model?.F === 200000, null, { timeout: 90000 });
  assert.equal(await page.evaluate(() => window.wingspline.state.meshKind), 'file');
  assert.match(await page.evaluate(() => window.wingspline.message()), /Imported sphere-200k\.off/);
  await page.evaluate(() => window.wingspline.flush());
  const link = await page.evaluate(() => window.location.hash);
  assert.ok(link.length < 2000, `the link refers to the mesh instead of holding it (${link.length} characters)`);
  await page.reload();
  await page.waitForSelector('body[data-ready=true]');
  await page.waitForFunction(() => window.wingspline.model?.F === 200000, null, { timeout: 90000 });
  const kept = await page.evaluate(() => ({ kind: window.wingspline.state.meshKind, name: window.wingspline.state.imported.name, V: window.wingspline.model.V }));
  // A UV sphere of 400 slices and 251 stacks: 400 * 250 + 2 vertices.
  assert.deepEqual(kept, { kind: 'file', name: 'sphere-200k.off', V: 400 * 250 + 2 });
  assert.deepEqual(page.problems, []);
});
