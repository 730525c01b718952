// A newcomer's way in: the landing page says where a student and a teacher start, and its
// links open the guide pages the build makes from docs/classroom.md, docs/embed.md and
// docs/exercises.md (scripts/lib/guides.mjs). Followed by clicks as a visitor does; each guide
// shows its doc: the same headings and tables as the Markdown file (counted here from the file
// itself), code shown as text (the embed snippet's <iframe> is text, not a frame), every link
// within the site reaching a page and every #anchor an element; axe finds no serious or
// critical violation (light and dark); no page wider than a phone; offline once the site has
// been visited.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot, screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { seriousViolations } from '../../helpers/axe.mjs';
import { cspProblems } from '../../helpers/csp.mjs';

const env = useSiteAndBrowser();

// What the Markdown file holds, read here without the build's converter: the headings (lines
// starting with #, outside ``` fences) and the number of tables (their |---| rule lines).
function docOutline(name) {
  const lines = fs.readFileSync(path.join(repoRoot, 'docs', `${name}.md`), 'utf8').split('\n');
  const headings = [];
  let tables = 0;
  let inFence = false;
  for (const line of lines) {
    if (line.startsWith('```')) { inFence = !inFence; continue; }
    if (inFence) continue;
    const h = /^(#+)\s+(.*)$/.exec(line);
    if (h) headings.push({ level: h[1].length, text: h[2].replace(/`/g, '').replace(/\*\*/g, '') });
    if (/^\|\s*-{3,}/.test(line)) tables += 1;
  }
  return { headings, tables };
}

// The guide page as shown: its headings, its tables (header cells and row counts), frames.
const shownOutline = (page) => page.evaluate(() => ({
  headings: [...document.querySelectorAll('main h1, main h2, main h3, main h4')].map((h) => ({ level: Number(h.tagName[1]), text: h.textContent })),
  tables: [...document.querySelectorAll('main table')].map((t) => ({ head: [...t.querySelectorAll('th')].map((th) => th.textContent), rows: t.querySelectorAll('tbody tr').length })),
  iframes: document.querySelectorAll('iframe').length,
  code: [...document.querySelectorAll('pre code')].map((c) => c.textContent),
}));

const guides = [
  { name: 'classroom', link: 'In the classroom', who: 'teacher' },
  { name: 'embed', link: 'Embedding a lesson', who: 'teacher' },
  { name: 'exercises', link: 'Exercises that check themselves', who: 'teacher' },
];

test('the landing page says where a student and a teacher start; each teacher link opens its guide, which shows the doc\'s headings and tables', async () => {
  const page = await env.openPage(env.site.url, { viewport: { width: 1280, height: 720 } });
  const start = page.getByRole('region', { name: 'Where to start' });
  await start.getByRole('heading', { name: 'For a student' }).waitFor();
  await start.getByRole('heading', { name: 'For a teacher' }).waitFor();
  await screenshot(page, 'landing-where-to-start');
  for (const guide of guides) {
    await page.goto(env.site.url);
    const teacher = page.getByRole('region', { name: 'For a teacher' });
    await teacher.getByRole('link', { name: guide.link }).click();
    await page.waitForURL(`**/guide/${guide.name}.html`);
    const shown = await shownOutline(page);
    const doc = docOutline(guide.name);
    assert.deepEqual(shown.headings, doc.headings, `${guide.name}: the doc's headings, in order, at their levels`);
    assert.equal(shown.tables.length, doc.tables, `${guide.name}: every table of the doc`);
    assert.ok(shown.tables.every((t) => t.head.length >= 2 && t.rows >= 1), `${guide.name}: each table has its header and rows`);
    assert.equal(await page.title(), `${doc.headings[0].text} · Wingspline`);
    assert.equal(shown.iframes, 0, 'HTML in the doc is shown as text, never made into elements');
    const csp = await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content');
    assert.deepEqual(cspProblems(csp), [], `${guide.name}: the site's strict policy`);
    assert.ok(!/wasm-unsafe-eval/.test(csp), 'a guide compiles no WebAssembly, so it may not');
    assert.deepEqual(page.problems, []);
    await screenshot(page, `guide-${guide.name}`);
  }
});

test('the embed guide reads as the doc: the options table row by row, the snippet as text, the reveal.js section', async () => {
  const page = await env.openPage(new URL('guide/embed.html', env.site.url).href);
  const options = await page.evaluate(() => {
    const table = [...document.querySelectorAll('main table')].find((t) => t.querySelector('th')?.textContent === 'parameter');
    return [...table.querySelectorAll('tbody tr')].map((tr) => [...tr.cells].map((td) => td.textContent));
  });
  // docs/embed.md's options table: its first column, parameter by parameter.
  assert.deepEqual(options.map((r) => r[0]), ['embed', 's', 'panels', 'controls', 'theme', 'present']);
  assert.equal(options.find((r) => r[0] === 'theme')[1], 'light, dark');
  const { code } = await shownOutline(page);
  assert.ok(code.some((c) => c.includes('<iframe src="https://example.org/wingspline/curves.html#embed=1&amp;s=...')), 'the snippet as written, as text');
  const reveal = page.getByRole('heading', { name: 'In a reveal.js slide' });
  assert.equal(await reveal.getAttribute('id'), 'in-a-revealjs-slide', 'the GitHub-style anchor');
});

test('student and teacher links reach pages, and every link of the guides within the site reaches a page and its #anchor', async () => {
  const page = await env.openPage(env.site.url);
  await page.getByRole('region', { name: 'For a student' }).getByRole('link', { name: 'Mesh representations' }).click();
  await page.waitForSelector('body[data-ready=true]', { timeout: 20000 });
  assert.equal(new URL(page.url()).pathname, '/mesh.html', 'the first lesson opened');
  const pages = ['index.html', ...guides.map((g) => `guide/${g.name}.html`)];
  const checked = [];
  for (const from of pages) {
    await page.goto(new URL(from, env.site.url).href);
    const hrefs = await page.evaluate(() => [...document.querySelectorAll('a[href]')].map((a) => a.href));
    for (const href of hrefs) {
      const url = new URL(href);
      if (url.origin !== new URL(env.site.url).origin) {
        assert.match(href, /^https:\/\//, `${from}: a link out of the site is https (${href})`);
        continue;
      }
      const res = await fetch(url.href.split('#')[0]);
      assert.equal(res.status, 200, `${from}: ${href} answers`);
      if (url.hash && url.pathname.endsWith('.html')) {
        const target = await env.browser.newPage();
        await target.goto(url.href);
        assert.equal(await target.locator(`[id="${decodeURIComponent(url.hash.slice(1))}"]`).count(), 1, `${from}: ${href} has its anchor`);
        await target.close();
      }
      checked.push(href);
    }
  }
  assert.ok(checked.some((h) => h.endsWith('guide/classroom.html#your-work-in-this-browser')), 'the student is pointed to where their work is kept');
});

for (const scheme of ['light', 'dark']) {
  test(`axe: the guide pages (${scheme}) have no serious or critical violations`, async () => {
    for (const guide of guides) {
      const page = await env.openPage(new URL(`guide/${guide.name}.html`, env.site.url).href, { colorScheme: scheme });
      assert.deepEqual(await seriousViolations(page), [], guide.name);
    }
  });
}

test('on a phone (390 x 844) no guide and not the landing page is wider than the screen: wide tables and code scroll in their boxes', async () => {
  for (const file of ['index.html', ...guides.map((g) => `guide/${g.name}.html`)]) {
    const page = await env.openPage(new URL(file, env.site.url).href, { viewport: { width: 390, height: 844 }, isMobile: true });
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 0, `${file}: no sideways scrolling (${overflow}px)`);
    await screenshot(page, `phone-${file.replace(/\W+/g, '-')}`);
  }
});

test('the guides are in the offline copy: listed in the service worker\'s manifest, and open offline after a visit', async () => {
  const manifest = fs.readFileSync(path.join(repoRoot, 'dist', 'sw-manifest.js'), 'utf8');
  for (const guide of guides) assert.ok(manifest.includes(`"guide/${guide.name}.html"`), `guide/${guide.name}.html is precached`);
  const context = await env.newContext({ serviceWorkers: 'allow' });
  const page = await context.newPage();
  await page.goto(env.site.url);
  await page.evaluate(async () => {
    await navigator.serviceWorker.ready;
    if (!navigator.serviceWorker.controller) {
      await new Promise((resolve) => navigator.serviceWorker.addEventListener('controllerchange', resolve, { once: true }));
    }
  });
  await context.setOffline(true);
  for (const guide of guides) {
    await page.goto(new URL(`guide/${guide.name}.html`, env.site.url).href);
    assert.equal(await page.locator('main h1').textContent(), docOutline(guide.name).headings[0].text, `${guide.name} offline`);
    assert.ok(await page.evaluate(() => getComputedStyle(document.body).fontFamily !== ''), 'with its style sheet');
  }
});
