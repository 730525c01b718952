// Every lesson page weighs 300 KB or less (a lesson with a code editor: its registry entry's
// weightBudget, docs/architecture.md "Module size"), counted as the benchmark's ui_load counts
// (tests/bench/browser/load.bench.mjs): every response the page receives from navigation to
// ready and the network quiet, each body compressed with gzip -9, summed. A lesson page
// fetches only the core modules of its lesson group (docs/architecture.md, "Module size").
import { test } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { lessons } from '../../../web/js/lessons/registry.js';
import { LESSON_OBJECTS } from '../../../web/js/lessons/all.js';

const BUDGET_GZIP_BYTES = 300_000;
const env = useSiteAndBrowser();

// A cold load (a fresh context: empty caches; no service worker, as in ui_load): the
// responses' paths and their gzip -9 sizes.
async function coldLoad(url) {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (err) => problems.push(err.message));
  const bodies = [];
  page.on('response', (response) => bodies.push(response.body().then((b) => ({ path: new URL(response.url()).pathname, b }), () => null)));
  await page.goto(url);
  await page.waitForSelector('body[data-ready=true]', { timeout: 30000 });
  await page.waitForLoadState('networkidle');
  const files = (await Promise.all(bodies)).filter(Boolean).map(({ path, b }) => ({ path, gzip: zlib.gzipSync(b, { level: 9 }).length }));
  return { files, total: files.reduce((a, f) => a + f.gzip, 0), problems };
}

for (const entry of lessons.filter((l) => l.ready)) {
  const budget = entry.weightBudget ?? BUDGET_GZIP_BYTES;
  test(`the ${entry.id} lesson loads in ${budget.toLocaleString('en')} bytes gzip or less, with its own core modules only`, async () => {
    const { files, total, problems } = await coldLoad(new URL(entry.page, env.site.url).href);
    assert.deepEqual(problems, []);
    const largest = [...files].sort((a, b) => b.gzip - a.gzip).slice(0, 5).map((f) => `${f.path} ${f.gzip}`).join(', ');
    assert.ok(total <= budget, `${entry.page}: ${total} bytes gzip in ${files.length} responses (largest: ${largest})`);
    // The wasm modules fetched are exactly those of the lesson's group (lesson.core; 'mesh'
    // and 'subdivision' together are one module, wingspline-meshes: core/wingspline.js).
    const wasm = files.filter((f) => f.path.endsWith('.wasm')).map((f) => f.path.replace(/^.*\/wingspline-(.*)\.wasm$/, '$1')).sort();
    const core = LESSON_OBJECTS[entry.id].core;
    assert.deepEqual(wasm, core.includes('mesh') && core.includes('subdivision') ? ['meshes', ...core.filter((p) => p !== 'mesh' && p !== 'subdivision')].sort() : [...core].sort());
  });
}
