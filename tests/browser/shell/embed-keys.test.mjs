// An embed in a real reveal.js deck gives the presenter's keys back. The deck (reveal.js
// from the npm registry, a dev dependency) is served from a second origin
// (http://localhost:<port>, the lessons from http://127.0.0.1:<port>), under a strict CSP of
// its own (scripts, styles and frames from named origins only, no inline script); its
// second slide holds the mesh lesson as a lazy `data-src` iframe embed, as docs/embed.md
// writes it. By pointer and keyboard, as a lecturer with a clicker:
// - a click inside the embed's canvas, then ArrowRight (or PageDown) moves the deck to the
//   next slide (Reveal.getIndices() in the deck);
// - Escape in the embed gives the focus back to the deck: the next ArrowRight reaches the
//   deck's own document, and reveal.js moves;
// - a key the embed uses stays in it: ArrowRight on a selected vertex moves the vertex, and
//   PageDown on the canvas steps the walk when the walk panel is shown (panels=walk-panel);
// - a host that is not reveal.js gets the documented messages ({ type: 'wingspline:key' },
//   { type: 'wingspline:focus-host' }) from the lesson's origin.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { useSiteAndBrowser, repoRoot, screenshot } from '../../helpers/browser.mjs';
import { createStaticServer, listen } from '../../../scripts/lib/static-server.mjs';

const env = useSiteAndBrowser();
const REVEAL_DIST = path.join(repoRoot, 'node_modules', 'reveal.js', 'dist');
// A 1280 x 720 deck in a 1280 x 800 window: reveal.js scales the slide (and the frame in it).
const VIEWPORT = { width: 1280, height: 800 };
const SLIDE_FRAME = { width: 900, height: 520 };

let deckDir;
let deck;

// The deck's script (no inline script under its CSP): reveal.js as an ES module; the keys
// that reach the deck's own document and the messages its window receives are recorded for
// the test.
const deckScript = `import Reveal from './reveal.mjs';
window.deckKeys = [];
window.hostMessages = [];
window.cspViolations = [];
document.addEventListener('keydown', (event) => window.deckKeys.push(event.key));
document.addEventListener('securitypolicyviolation', (event) => window.cspViolations.push(event.violatedDirective + ' ' + event.blockedURI));
window.addEventListener('message', (event) => {
  if (event.data && typeof event.data === 'object' && String(event.data.type).startsWith('wingspline:')) {
    window.hostMessages.push({ origin: event.origin, ...event.data });
  }
});
const deck = new Reveal({ hash: false, width: 1280, height: 720, transition: 'none', controls: false, progress: false });
deck.initialize().then(() => { window.deck = deck; document.body.dataset.ready = 'true'; });
`;

function deckPage(appOrigin, embedSrc) {
  const attr = (text) => text.replace(/&/g, '&amp;').replace(/"/g, '&quot;');
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; font-src 'self' data:; frame-src ${appOrigin}">
<title>Lecture 004: the winged edge</title>
<link rel="icon" href="data:,">
<link rel="stylesheet" href="reveal.css">
<link rel="stylesheet" href="theme/white.css">
<script type="module" src="deck.js"></script>
</head>
<body>
<div class="reveal"><div class="slides">
<section><h2>The winged edge</h2><p>Eight pointers per edge.</p></section>
<section><h2>Around a vertex</h2>
<iframe data-src="${attr(embedSrc)}" width="${SLIDE_FRAME.width}" height="${SLIDE_FRAME.height}" title="Mesh representations (Wingspline)" data-preload></iframe>
</section>
<section><h2>What it costs</h2><p>The next slide.</p></section>
</div></div>
</body>
</html>
`;
}

before(async () => {
  assert.ok(fs.existsSync(path.join(REVEAL_DIST, 'reveal.mjs')), 'reveal.js is installed (npm install: it is a dev dependency)');
  deckDir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-deck-'));
  fs.writeFileSync(path.join(deckDir, 'deck.js'), deckScript);
  // The deck's own files first, reveal.js's dist/ under them: one static server, the project's.
  const { server, url } = await listen(createStaticServer(REVEAL_DIST, { overlays: [deckDir] }));
  // Another origin than the lessons' (127.0.0.1): the deck is addressed as localhost.
  deck = { server, origin: url.replace('127.0.0.1', 'localhost').replace(/\/$/, '') };
});

after(async () => {
  deck.server.closeAllConnections?.();
  await new Promise((resolve) => deck.server.close(resolve));
  fs.rmSync(deckDir, { recursive: true, force: true });
});

let deckCount = 0;
// The deck opened on its embed slide (the second, index 1), the lesson ready in the frame.
async function openDeck(hash, viewport = VIEWPORT) {
  const appOrigin = new URL(env.site.url).origin;
  deckCount += 1;
  const file = `deck-${deckCount}.html`;
  fs.writeFileSync(path.join(deckDir, file), deckPage(appOrigin, new URL(`mesh.html#${hash}`, env.site.url).href));
  const context = await env.newContext({ viewport });
  const page = await context.newPage();
  page.problems = [];
  page.on('pageerror', (err) => page.problems.push(`pageerror: ${err.message}`));
  page.on('console', (msg) => { if (msg.type() === 'error') page.problems.push(`console: ${msg.text()}`); });
  await page.goto(`${deck.origin}/${file}`);
  await page.waitForSelector('body[data-ready=true]');
  assert.deepEqual(await indices(page), { h: 0, v: 0 });
  // The lecturer goes to the embed's slide with the deck's own key.
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await indices(page), { h: 1, v: 0 }, 'the deck moves by its own keys');
  const frameElement = await page.waitForSelector('section.present iframe[src]');
  const frame = await frameElement.contentFrame();
  await frame.waitForSelector('body[data-ready=true]', { timeout: 20000 });
  assert.notEqual(new URL(frame.url()).origin, deck.origin, 'the lesson is another origin than the deck');
  const scale = await frameElement.evaluate((el) => el.getBoundingClientRect().width / el.offsetWidth);
  assert.ok(Math.abs(scale - 1) > 0.01, `reveal.js scales the slide and the frame in it (${scale})`);
  return { page, frame };
}

const indices = (page) => page.evaluate(() => { const { h, v } = window.deck.getIndices(); return { h, v }; });
const deckKeys = (page) => page.evaluate(() => [...window.deckKeys]);
const hostMessages = (page) => page.evaluate(() => [...window.hostMessages]);
const frameFocus = (frame) => frame.evaluate(() => ({ focused: document.hasFocus(), active: document.activeElement?.id || document.activeElement?.tagName }));

// A point of the canvas with nothing under it (no vertex, edge or face of the mesh): the
// canvas's left edge at mid-height, where the fitted drawing leaves a margin. Canvas CSS px.
async function emptyCanvasPoint(frame) {
  return frame.evaluate(() => {
    const r = document.getElementById('stage').getBoundingClientRect();
    const handles = window.wingspline.handles();
    const x = 6;
    const y = r.height / 2;
    const near = handles.filter((hd) => Math.hypot(hd.x - r.left - x, hd.y - r.top - y) < 30);
    return { x, y, near: near.length };
  });
}

// Clicks inside the embed's canvas as a person does (the mouse, through reveal.js's scaling).
async function clickCanvas(frame, position) {
  await frame.locator('#stage').click({ position: { x: position.x, y: position.y } });
}

const settle = (target) => target.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

// The deck takes the key: its slide index, within a few frames (the message is async).
async function waitForSlide(page, h) {
  await page.waitForFunction((want) => window.deck.getIndices().h === want, h, { timeout: 3000 }).catch(() => {});
  return indices(page);
}

test('after a click in the embed\'s canvas, ArrowRight and PageDown move the reveal.js deck; the deck hears the documented messages', async () => {
  for (const key of ['ArrowRight', 'PageDown']) {
    const { page, frame } = await openDeck('embed=1&present=1');
    const point = await emptyCanvasPoint(frame);
    assert.equal(point.near, 0, 'nothing of the mesh under the click');
    await clickCanvas(frame, point);
    assert.deepEqual(await frameFocus(frame), { focused: true, active: 'stage' }, 'the click gave the embed the focus');
    const before = await deckKeys(page);
    await page.keyboard.press(key);
    assert.deepEqual(await waitForSlide(page, 2), { h: 2, v: 0 }, `${key} in the embed moved the deck to the next slide`);
    assert.deepEqual((await deckKeys(page)).slice(before.length), [], `${key} was pressed in the frame, not in the deck`);
    const messages = await hostMessages(page);
    const appOrigin = new URL(env.site.url).origin;
    assert.deepEqual(messages.filter((m) => m.type === 'wingspline:key').map(({ origin, key: k, command }) => ({ origin, key: k, command })),
      [{ origin: appOrigin, key, command: key === 'ArrowRight' ? 'right' : 'next' }], 'one generic message, from the lesson\'s origin');
    assert.deepEqual(page.problems, []);
    assert.deepEqual(await page.evaluate(() => window.cspViolations), [], 'the deck\'s strict CSP holds');
  }
});

test('Escape in the embed gives the focus back to the deck: the next ArrowRight is the deck\'s own', async () => {
  const { page, frame } = await openDeck('embed=1');
  await clickCanvas(frame, await emptyCanvasPoint(frame));
  assert.equal((await frameFocus(frame)).focused, true);
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => document.hasFocus() && document.activeElement?.tagName !== 'IFRAME', null, { timeout: 3000 }).catch(() => {});
  const deckFocus = await page.evaluate(() => ({ focused: document.hasFocus(), active: document.activeElement?.tagName }));
  assert.deepEqual(deckFocus, { focused: true, active: 'BODY' }, 'the deck\'s document has the focus, not the frame');
  assert.equal((await frameFocus(frame)).focused, false, 'the frame no longer has it');
  assert.deepEqual((await hostMessages(page)).filter((m) => m.type === 'wingspline:focus-host').length, 1, 'and the host was told');
  assert.deepEqual(await indices(page), { h: 1, v: 0 }, 'Escape itself moves nothing');
  const before = await deckKeys(page);
  await page.keyboard.press('ArrowRight');
  assert.deepEqual((await deckKeys(page)).slice(before.length), ['ArrowRight'], 'the key reached the deck\'s own document');
  assert.deepEqual(await waitForSlide(page, 2), { h: 2, v: 0 }, 'and reveal.js moved');
  assert.equal((await hostMessages(page)).filter((m) => m.type === 'wingspline:key').length, 0, 'nothing came through the frame');
  assert.deepEqual(page.problems, []);
});

test('keys the embed uses stay in it: ArrowRight moves a selected vertex, PageDown steps the shown walk', async () => {
  // A vertex picked by a click: the arrows move it (the lesson's), the deck stays.
  {
    const { page, frame } = await openDeck('embed=1');
    const target = await frame.evaluate(() => {
      const r = document.getElementById('stage').getBoundingClientRect();
      const hd = window.wingspline.handles().find((x) => x.draggable && x.x > r.left + 40 && x.x < r.right - 40 && x.y > r.top + 40 && x.y < r.bottom - 40);
      return hd && { id: hd.id, x: hd.x - r.left, y: hd.y - r.top };
    });
    assert.ok(target, 'a vertex well inside the canvas');
    await clickCanvas(frame, target);
    const moved = () => frame.evaluate((id) => window.wingspline.handles().find((x) => x.id === id), target.id);
    const start = await moved();
    await page.keyboard.press('ArrowRight');
    await settle(frame);
    const after = await moved();
    assert.ok(after.x > start.x, `the vertex moved right (${start.x} -> ${after.x})`);
    await settle(page);
    assert.deepEqual(await indices(page), { h: 1, v: 0 }, 'the deck did not move');
    assert.equal((await hostMessages(page)).length, 0, 'nothing was passed on');
  }
  // The walk panel shown beside the canvas: PageDown on the focused canvas steps the walk.
  {
    const { page, frame } = await openDeck('embed=1&panels=walk-panel');
    assert.ok(await frame.locator('#walk-panel').isVisible(), 'the walk panel is shown');
    await clickCanvas(frame, await emptyCanvasPoint(frame));
    const step = () => frame.evaluate(() => window.wingspline.state.step);
    const first = await step();
    await page.keyboard.press('PageDown');
    await settle(frame);
    assert.equal(await step(), first + 1, 'the walk took one step');
    await settle(page);
    assert.deepEqual(await indices(page), { h: 1, v: 0 }, 'the deck did not move');
    // Escape, then the deck's keys again.
    await page.keyboard.press('Escape');
    await page.keyboard.press('ArrowRight');
    assert.deepEqual(await waitForSlide(page, 2), { h: 2, v: 0 });
    assert.deepEqual(page.problems, []);
  }
});

test('the deck with its embed at 1920 x 1080 (present=1), 1280 x 720 and 390 x 844: the keys still reach the deck, screenshots for the eye', async () => {
  for (const [width, height, hash] of [[1920, 1080, 'embed=1&present=1'], [1280, 720, 'embed=1'], [390, 844, 'embed=1']]) {
    const { page, frame } = await openDeck(hash, { width, height });
    await clickCanvas(frame, await emptyCanvasPoint(frame));
    await screenshot(page, `deck-embed-${width}x${height}`);
    await page.keyboard.press('PageDown');
    assert.deepEqual(await waitForSlide(page, 2), { h: 2, v: 0 }, `${width}x${height}`);
    assert.deepEqual(page.problems, []);
  }
});
