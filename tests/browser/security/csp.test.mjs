// Every page, live in Chromium: the CSP meta is present and strict, the page
// runs under it without a single violation (so the wasm core needs no 'unsafe-eval'), no
// inline script exists in the live DOM, and the policy is really enforced: an inline
// script, an inline handler and eval injected into the page do not run.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { launchBrowser, repoRoot, closingContexts } from '../../helpers/browser.mjs';
import { createStaticServer, listen } from '../../../scripts/lib/static-server.mjs';
import { cspProblems } from '../../helpers/csp.mjs';

const pages = fs.readdirSync(path.join(repoRoot, 'dist')).filter((f) => f.endsWith('.html')).sort();

let site;
let browser;
const contexts = closingContexts(() => browser);
// A same-origin script (allowed by script-src 'self') that tries to build code from text.
// It has to come from the page's origin: code evaluated through the DevTools protocol is
// exempt from the page's CSP, so eval tried from page.evaluate would prove nothing.
const PROBE_PATH = '/__csp-probe.js';
const probeScript = `
  const outcome = (build) => { try { build(); return 'ran'; } catch (err) { return err.name; } };
  window.__probe = { eval: outcome(() => (0, eval)('1 + 1')), newFunction: outcome(() => new Function('return 1')()) };
`;

function startProbedSite() {
  const dist = createStaticServer(path.join(repoRoot, 'dist'));
  const handler = dist.listeners('request')[0];
  dist.removeAllListeners('request');
  dist.on('request', (req, res) => {
    if (req.url === PROBE_PATH) res.writeHead(200, { 'content-type': 'text/javascript' }).end(probeScript);
    else handler(req, res);
  });
  return listen(dist).then(({ server, url }) => ({ url, close: () => new Promise((r) => server.close(r)) }));
}

before(async () => {
  site = await startProbedSite();
  browser = await launchBrowser();
});
after(async () => {
  await browser?.close();
  await site?.close();
});

async function openWatched(pageName) {
  const context = await contexts.newContext();
  const page = await context.newPage();
  const problems = [];
  page.on('console', (msg) => { if (msg.type() === 'error') problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (err) => problems.push(`pageerror: ${err.message}`));
  // Installed before any page script: records every CSP violation the page causes.
  await page.addInitScript(() => {
    window.__cspViolations = [];
    document.addEventListener('securitypolicyviolation', (e) => {
      window.__cspViolations.push(`${e.violatedDirective} blocked ${e.blockedURI || 'inline'} (${e.sourceFile}:${e.lineNumber})`);
    });
  });
  await page.goto(`${site.url}${pageName}`, { waitUntil: 'load' });
  // Settled: the core answered (the landing page's status, a lesson's data-ready) and two
  // frames were drawn after that; the page must be quiet by then.
  await page.waitForSelector(pageName === 'index.html' ? '[data-core-status][data-state=ready]' : 'body[data-ready=true]', { timeout: 15000 });
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  return { page, context, problems };
}

test('the site has pages to check', () => {
  assert.ok(pages.includes('index.html'), pages.join(', '));
});

for (const pageName of pages) {
  test(`${pageName} runs under a strict CSP with no violation and no inline script`, async () => {
    const { page, problems } = await openWatched(pageName);
    const metas = await page.$$eval('meta[http-equiv="Content-Security-Policy" i]', (ms) => ms.map((m) => m.content));
    assert.equal(metas.length, 1, 'exactly one CSP meta');
    assert.deepEqual(cspProblems(metas[0]), []);
    const inline = await page.$$eval('script:not([src])', (ss) => ss.map((s) => s.outerHTML.slice(0, 120)));
    assert.deepEqual(inline, [], 'no inline scripts in the live DOM');
    const handlers = await page.evaluate(() => [...document.querySelectorAll('*')]
      .flatMap((el) => [...el.attributes].filter((a) => /^on/i.test(a.name)).map((a) => `${el.tagName}[${a.name}]`)));
    assert.deepEqual(handlers, [], 'no inline event handlers in the live DOM');
    const remote = await page.evaluate(() => performance.getEntriesByType('resource')
      .map((r) => r.name).filter((u) => new URL(u).origin !== location.origin && !u.startsWith('data:')));
    assert.deepEqual(remote, [], 'nothing loaded from another origin');
    assert.deepEqual(await page.evaluate(() => window.__cspViolations), [], 'the page itself causes no CSP violation');
    assert.deepEqual(problems, []);
  });
}

test('the policy is enforced: injected inline script, handler and eval do not run', async () => {
  const { page } = await openWatched('index.html');
  const outcome = await page.evaluate(async () => {
    const s = document.createElement('script');
    s.textContent = 'window.__inlineRan = true;';
    document.body.append(s);
    const img = document.createElement('img');
    img.setAttribute('onerror', 'window.__handlerRan = true');
    img.src = 'data:image/png;base64,broken';
    document.body.append(img);
    const probe = document.createElement('script');
    probe.src = '/__csp-probe.js';
    const loaded = new Promise((resolve) => { probe.onload = resolve; probe.onerror = resolve; });
    document.body.append(probe);
    await loaded;
    await new Promise((r) => setTimeout(r, 300));
    return { inline: window.__inlineRan ?? false, handler: window.__handlerRan ?? false, probe: window.__probe ?? null };
  });
  // The same-origin script ran ('self' works), and its eval and new Function were refused.
  assert.deepEqual(outcome, { inline: false, handler: false, probe: { eval: 'EvalError', newFunction: 'EvalError' } });
  const violations = await page.evaluate(() => window.__cspViolations);
  assert.ok(violations.some((v) => v.startsWith('script-src')), violations.join('; '));
});
