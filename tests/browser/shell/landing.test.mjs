// The served site loads, the wasm core answers in Chromium, and nothing logs an error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';

const pkg = JSON.parse(fs.readFileSync(new URL('../../../package.json', import.meta.url), 'utf8'));
const env = useSiteAndBrowser();

test('the landing page shows the lessons and a live core', async () => {
  const page = await env.openPage(env.site.url);
  await page.waitForSelector('[data-core-status][data-state=ready]', { timeout: 10000 });
  assert.match(await page.textContent('[data-core-status]'), new RegExp(pkg.version.replace(/\./g, '\\.')));
  assert.equal(await page.getAttribute('body', 'data-core-version'), pkg.version);
  // The computed inverse is on screen as MathML, with the slide's entries.
  const cells = await page.$$eval('#core-proof mtable', (tables) => tables[1].textContent);
  assert.equal(cells.replace(/\s+/g, ''), '2-211-33-2-100101000');
  const titles = await page.$$eval('.lesson-card h3', (hs) => hs.map((h) => h.textContent));
  for (const name of ['Mesh representations', 'Curve explorer', 'Continuity lab', 'Surface patches']) {
    assert.ok(titles.some((t) => t.includes(name)), `lesson ${name} is listed`);
  }
  const file = await screenshot(page, 'landing');
  assert.ok(fs.statSync(file).size > 10000, 'a real screenshot was written');
  assert.deepEqual(page.problems, []);
});

test('the landing page is readable on a phone', async () => {
  const page = await env.openPage(env.site.url, { viewport: { width: 390, height: 844 }, isMobile: true });
  await page.waitForSelector('[data-core-status][data-state=ready]');
  const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  assert.ok(overflow <= 0, `no horizontal scrolling on a phone (overflow ${overflow}px)`);
  await screenshot(page, 'landing-phone');
  assert.deepEqual(page.problems, []);
});

test('opened from file:// the page says how to serve it', async () => {
  const { pathToFileURL } = await import('node:url');
  const page = await env.openPage(pathToFileURL(new URL('../../../dist/index.html', import.meta.url).pathname).href);
  await page.waitForSelector('#file-warning:not([hidden])', { timeout: 5000 });
  assert.match(await page.textContent('#file-warning'), /python3 -m http.server/);
  assert.match(await page.textContent('[data-core-status]'), /opened from a file/);
});
