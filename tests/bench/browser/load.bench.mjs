// ui_load (docs/benchmarks.md): time from navigation to the first lesson drawn and
// interactive (the shell's performance mark 'wingspline-ready'; until a lesson is marked
// ready in the registry, the test-only fixture lesson of tests/fixtures/site, which costs
// the whole skeleton and the core but no lesson code), and the bytes transferred: raw, gzip -9 of each
// response (the 300 KB budget is for gzip), the bodies as the classroom server sent them
// (wire_bytes: compressed by its Accept-Encoding, brotli for Chromium), plus the gzip size of all of dist/.
// Each repetition is a cold load in a fresh browser context (empty caches, no worker).
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { report, wants } from '../wasm/harness.mjs';
import { launchBrowser, startSite, repoRoot } from '../../helpers/browser.mjs';
import { lessons } from '../../../web/js/lessons/registry.js';
import { startClassroomSite } from '../../helpers/classroom.mjs';

const REPETITIONS = 7;
const gzipSize = (bytes) => zlib.gzipSync(bytes, { level: 9 }).length;

function distGzipBytes() {
  let total = 0;
  const walk = (dir) => {
    for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full); else total += gzipSize(fs.readFileSync(full));
    }
  };
  walk(path.join(repoRoot, 'dist'));
  return total;
}

if (wants('ui_load')) {
  const first = lessons.find((l) => l.ready);
  const pageFile = first ? first.page : 'fixture.html';
  const site = first ? await startSite() : await startClassroomSite();
  const browser = await launchBrowser();
  const ms = [];
  let transfer = null;
  try {
    for (let r = 0; r < REPETITIONS; r += 1) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
      const page = await context.newPage();
      const bodies = [];
      page.on('response', (response) => bodies.push(Promise.all([response.body(), response.request().sizes()])
        .then(([b, sizes]) => ({ url: response.url(), b, wire: sizes.responseBodySize })).catch(() => null)));
      await page.goto(new URL(pageFile, site.url).href);
      await page.waitForSelector('body[data-ready=true]', { timeout: 30000 });
      ms.push(await page.evaluate(() => performance.getEntriesByName('wingspline-ready')[0].startTime));
      await page.waitForLoadState('networkidle');
      if (!transfer) {
        const files = (await Promise.all(bodies)).filter(Boolean);
        transfer = {
          bytes: files.reduce((a, f) => a + f.b.length, 0),
          gzip_bytes: files.reduce((a, f) => a + gzipSize(f.b), 0),
          wire_bytes: files.reduce((a, f) => a + f.wire, 0),
          largest: files.map((f) => ({ file: new URL(f.url).pathname, gzip: gzipSize(f.b) })).sort((a, b) => b.gzip - a.gzip).slice(0, 4),
          requests: files.length,
        };
      }
      await context.close();
    }
  } finally {
    await browser.close();
    await site.close();
  }
  report({
    task: 'ui_load', build: 'browser', input: pageFile, n: 1, unit: 'ms', seconds: ms,
    checksum: transfer.gzip_bytes, ms_min: Math.min(...ms), ms_median: [...ms].sort((a, b) => a - b)[Math.floor(ms.length / 2)],
    ...transfer, dist_gzip_bytes: distGzipBytes(), budget_gzip_bytes: 300 * 1024,
  });
}
