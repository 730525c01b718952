// The mesh file import path against script-bearing input ("no HTML is ever built
// from URL, file or user text"). The classroom tests cover hostile names of JSON state
// files and tampered share links on every lesson; this file covers what only the mesh
// lesson has: OFF/OBJ files whose name, tokens and validation report carry markup, shown
// in the message line, the validation report and the source label. Each must appear as
// literal text, and nothing may run or be injected.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { startClassroomSite, nothingExecuted, payloads } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser(startClassroomSite);

const tetrahedronOff = 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n';
// Three triangles on edge v1-v2: refused with a validation report.
const nonManifoldOff = 'OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 1 0 4\n';

async function importMesh(page, name, text) {
  await page.setInputFiles('#import-file', { name, mimeType: 'text/plain', buffer: Buffer.from(text) });
}

// Every place the page could have turned text into markup: no element the payloads would
// create, no handler attribute anywhere.
async function injected(page) {
  return page.evaluate(() => ({
    handlers: [...document.querySelectorAll('*')].filter((el) => [...el.attributes].some((a) => /^on/i.test(a.name))).length,
    images: document.querySelectorAll('img[src=x]').length,
    inlineScripts: document.querySelectorAll('script:not([src])').length,
  }));
}

function openMesh() {
  return env.openLesson(new URL('mesh.html', env.site.url).href);
}

// Nothing ran, nothing was injected, no dialog opened, no error on the page.
async function assertNothingRan(page) {
  assert.deepEqual(await nothingExecuted(page), { pwned: null, injectedElements: 0 });
  assert.deepEqual(await injected(page), { handlers: 0, images: 0, inlineScripts: 0 });
  assert.deepEqual(page.dialogs, []);
  assert.deepEqual(page.problems, []);
}

test('an OFF file with a script-bearing name imports, and the name is shown as text', async () => {
  const page = await openMesh();
  const name = `${payloads.img}.off`;
  await importMesh(page, name, tetrahedronOff);
  await page.waitForFunction(() => /Imported/.test(window.wingspline.message()));
  assert.ok((await page.evaluate(() => window.wingspline.message())).includes(name), 'the message shows the name literally');
  assert.equal(await page.evaluate(() => window.wingspline.state.imported?.name), name);
  const shown = await page.evaluate((n) => document.body.textContent.includes(n.replace(/\.off$/, '')), name);
  assert.ok(shown, 'the name appears in the page as text');
  await assertNothingRan(page);
});

test('a refused mesh with a script-bearing name: the validation report and message are text', async () => {
  const page = await openMesh();
  const before0 = await page.evaluate(() => JSON.stringify(window.wingspline.state));
  const name = `${payloads.svg}.off`;
  await importMesh(page, name, nonManifoldOff);
  await page.waitForFunction(() => window.wingspline.message().includes('was not imported'));
  const message = await page.evaluate(() => window.wingspline.message());
  assert.ok(message.startsWith(`${name} was not imported`), message);
  // The core's report names the edge (1-based labels, docs/api-mesh.md).
  assert.match(await page.evaluate(() => document.body.textContent), /v1-v2 is shared by 3 faces/);
  assert.equal(await page.evaluate(() => JSON.stringify(window.wingspline.state)), before0, 'a refused file changes nothing');
  await assertNothingRan(page);
});

test('markup inside an OFF or OBJ file reaches the message only as quoted text', async () => {
  const page = await openMesh();
  // The reader quotes the offending token (the first 30 characters of it) in its message.
  await importMesh(page, 'coordinates.off', `OFF\n3 1 0\n0 0 0\n${payloads.script} 0 0\n0 1 0\n3 0 1 2\n`);
  await page.waitForFunction(() => /line 4/.test(window.wingspline.message()));
  assert.ok((await page.evaluate(() => window.wingspline.message())).includes('<script>'), 'the token is shown, not parsed');
  // OBJ object and group names are read past; a statement the reader does not know is quoted.
  await importMesh(page, 'names.obj', `o ${payloads.img}\ng ${payloads.svg}\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n`);
  await page.waitForFunction(() => /Imported names\.obj/.test(window.wingspline.message()));
  await importMesh(page, 'statement.obj', `v 0 0 0\n${payloads.img} 1 2\n`);
  await page.waitForFunction(() => /line 2/.test(window.wingspline.message()));
  await assertNothingRan(page);
});

// A valid 40,000-triangle fan (1.7 MB OFF) whose hub is vertex 1 (the
// walk's vertex after an import): its walk has 40,003 frames. Each frame used to copy the
// "found so far" list (memory quadratic in the steps), which crashed the tab. Imported
// through the file input and stepped with the keyboard as a person would.
test('a 40,000-triangle fan imports and its walk steps to the end without crashing', async () => {
  const n = 40000;
  const lines = ['OFF', `${n + 2} ${n} 0`, '0 0 0'];
  for (let i = 0; i <= n; i += 1) {
    const t = (1.5 * Math.PI * i) / n;
    lines.push(`${Math.cos(t).toFixed(6)} ${Math.sin(t).toFixed(6)} 0`);
  }
  for (let i = 1; i <= n; i += 1) lines.push(`3 0 ${i} ${i + 1}`);
  const text = lines.join('\n') + '\n';
  assert.ok(text.length > 1.2e6);
  const page = await openMesh();
  await importMesh(page, 'fan-40000.off', text);
  await page.waitForFunction(() => /Imported/.test(window.wingspline.message()), null, { timeout: 60000 });
  assert.equal(await page.evaluate(() => window.wingspline.model.V), n + 2);
  await page.click('#walk-title');
  await page.keyboard.press('End');
  await page.waitForFunction((count) => window.wingspline.model.frame?.foundCount === count, n + 1, { timeout: 60000 });
  await page.keyboard.press('ArrowLeft');
  await page.waitForFunction((count) => window.wingspline.model.frame?.foundCount === count, n + 1, { timeout: 60000 });
  await page.keyboard.press('Home');
  await page.waitForFunction(() => window.wingspline.model.stepIndex === 0, null, { timeout: 60000 });
  for (let k = 0; k < 3; k += 1) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.wingspline.model.frame?.foundCount === 3, null, { timeout: 60000 });
  // The panel follows the model on the next frame.
  await page.waitForFunction(() => /1\. e\s*\d+.*2\. e\s*\d+.*3\. e\s*\d+/s.test(document.querySelector('#walk-found').textContent), null, { timeout: 10000 })
    .catch(async () => assert.fail(`the found list shows three edges: ${await page.textContent('#walk-found')}`));
  assert.deepEqual(page.problems, []);
});
