// The embed mode, from a SECOND origin: a host page on another port of
// 127.0.0.1 (cross-origin, and the same site, so the frame shares the full app's local
// storage: an embed that wrote its state would write over the person's saved work, which is
// what this file checks it never does) holds the lesson in an 800 x 500 iframe.
// For every ready lesson: a prepared state made in the full app (a handle moved by the
// keyboard), then the person's own work (moved again, saved); the embed of the prepared
// state shows it, fitted to the frame (every handle on the canvas, the canvas the frame
// within EDGE_PX, no scroll bars) with only the embed controls; a drag in the frame changes
// the state and Reset brings back the prepared state bit for bit; the saved work and the
// theme preference are untouched. theme= and present= are applied; tampered embed
// parameters give one clear line and the lesson still opens embedded; "Copy embed code"
// gives a snippet whose src opens the same state (clipboard granted, and the dialog when
// the clipboard is refused).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import http from 'node:http';
import { LESSON_OBJECTS } from '../../../web/js/lessons/all.js';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { readyLessons, editByKeyboard, nothingExecuted, payloads } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();
// The frame in the host page (CSS px): the snippet's size, and a small one for the resize.
const FRAME = { width: 800, height: 500 };
const SMALL = { width: 400, height: 300 };
// How far the canvas's box may be from the frame's edges (CSS px): sub-pixel layout only.
const EDGE_PX = 2;
// A message line is one sentence for a person, not a page of text.
const MESSAGE_MAX_CHARS = 300;

// The second origin: a tiny server whose pages the tests set (path -> HTML).
const hostPages = new Map();
let host = null;
before(async () => {
  const server = http.createServer((req, res) => {
    const body = hostPages.get(new URL(req.url, 'http://x').pathname);
    res.writeHead(body ? 200 : 404, { 'content-type': 'text/html; charset=utf-8' }).end(body ?? 'not found');
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  host = { server, origin: `http://127.0.0.1:${server.address().port}` };
});
after(() => new Promise((resolve) => { host.server.closeAllConnections?.(); host.server.close(resolve); }));

const attr = (text) => text.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
let pageCount = 0;
// A host page holding `body` (HTML, as an author would write it); returns its URL.
function hostPage(body) {
  pageCount += 1;
  const path = `/host-${pageCount}.html`;
  hostPages.set(path, `<!doctype html><html><head><meta charset="utf-8"><title>Host</title></head><body style="margin:0">${body}</body></html>`);
  return `${host.origin}${path}`;
}
const iframeHtml = (src, size = FRAME) => `<iframe src="${attr(src)}" width="${size.width}" height="${size.height}" title="embed" style="border:0;display:block"></iframe>`;

const settle = (target) => target.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

// The host page at the second origin, its frame's lesson ready.
async function openHost(context, body) {
  const page = await context.newPage();
  page.problems = [];
  page.on('pageerror', (err) => page.problems.push(`pageerror: ${err.message}`));
  await page.goto(hostPage(body));
  const handle = await page.waitForSelector('iframe');
  const frame = await handle.contentFrame();
  frame.problems = page.problems;
  await frame.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  assert.notEqual(new URL(frame.url()).origin, host.origin, 'the frame is another origin than its host');
  await settle(frame);
  return { page, frame };
}

// The state without its view (the view is fitted to the frame).
const withoutView = (state) => { const { view, ...rest } = state; return rest; };

// Where the frame's canvas is, against the frame, the handles and the page's scroll size.
async function layout(frame) {
  return frame.evaluate(() => {
    const r = document.getElementById('stage').getBoundingClientRect();
    // The canvas legend (colours, arrow scales) stays under the canvas in an embed: the
    // figure is the canvas and its legend.
    const legend = document.querySelector('.canvas-legend');
    const l = legend && legend.getClientRects().length ? legend.getBoundingClientRect() : null;
    const handles = window.wingspline.handles();
    const s = document.scrollingElement;
    return {
      canvas: { left: r.left, top: r.top, right: r.right, bottom: r.bottom },
      figureBottom: l ? l.bottom : r.bottom,
      legendGap: l ? l.top - r.bottom : 0,
      frame: { width: innerWidth, height: innerHeight },
      handles: handles.length,
      outside: handles.filter((hd) => !(hd.x >= r.left && hd.x <= r.right && hd.y >= r.top && hd.y <= r.bottom)).map((hd) => hd.label),
      scroll: { width: s.scrollWidth, height: s.scrollHeight, clientWidth: s.clientWidth, clientHeight: s.clientHeight },
    };
  });
}

function assertFitted(fit, size, what) {
  assert.equal(fit.frame.width, size.width, `${what}: the frame is ${size.width} px wide`);
  assert.ok(fit.handles > 0, `${what}: the lesson has handles`);
  assert.deepEqual(fit.outside, [], `${what}: every handle is on the canvas`);
  assert.ok(Math.abs(fit.canvas.left) <= EDGE_PX && Math.abs(fit.canvas.top) <= EDGE_PX
    && Math.abs(fit.canvas.right - size.width) <= EDGE_PX && Math.abs(fit.figureBottom - size.height) <= EDGE_PX,
  `${what}: the canvas (and its legend under it) fills the frame (${JSON.stringify(fit)} in ${size.width}x${size.height})`);
  assert.ok(Math.abs(fit.legendGap) <= EDGE_PX, `${what}: the legend sits right under the canvas`);
  assert.ok(fit.canvas.bottom - fit.canvas.top >= 0.5 * size.height, `${what}: the canvas is at least half the frame`);
  assert.ok(fit.scroll.width <= fit.scroll.clientWidth && fit.scroll.height <= fit.scroll.clientHeight,
    `${what}: no scroll bars (${JSON.stringify(fit.scroll)})`);
}

// The controls the embed shows: the toolbar's buttons and links by their action.
const toolbarActions = (frame) => frame.evaluate(() => [...document.querySelectorAll('#lesson-toolbar button, #lesson-toolbar a, #lesson-toolbar details')]
  .filter((el) => el.getClientRects().length > 0).map((el) => el.dataset.action ?? el.tagName.toLowerCase()));

// In the full app (top level, site origin): the prepared state (one keyboard move) and its
// link, then the person's own work (another move), saved. Resolves to what the embed must
// show and what must stay.
async function prepare(context, lesson) {
  const app = await context.newPage();
  await app.goto(new URL(lesson.page, env.site.url).href);
  await app.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await editByKeyboard(app);
  const prepared = await app.evaluate(() => window.wingspline.state);
  const link = await app.evaluate(() => window.wingspline.shareUrl());
  const isDefault = await app.evaluate((s) => JSON.stringify(s) === JSON.stringify(window.wingspline.hooks.defaultState()),
    withoutView(prepared));
  await app.keyboard.press('ArrowRight');
  await app.keyboard.press('ArrowRight');
  await app.evaluate(() => window.wingspline.flush());
  const key = `wingspline:${lesson.id}:state`;
  const saved = await app.evaluate((k) => ({ code: localStorage.getItem(k), theme: localStorage.getItem('wingspline:theme'), state: window.wingspline.state }), key);
  assert.ok(saved.code, 'the full app saved the work');
  assert.notDeepEqual(withoutView(saved.state), withoutView(prepared), 'the saved work differs from the prepared state');
  return { app, prepared, link, code: link.split('#s=')[1], key, saved, isDefault };
}
const embedSrc = (link, extra = '') => link.replace('#s=', `#embed=1${extra}&s=`);

async function dragFirstHandle(page, frame) {
  const box = await page.locator('iframe').boundingBox();
  const handles = await frame.evaluate(() => {
    const r = document.getElementById('stage').getBoundingClientRect();
    return window.wingspline.handles().filter((hd) => hd.draggable && hd.x > r.left + 40 && hd.x < r.right - 40 && hd.y > r.top + 40 && hd.y < r.bottom - 40);
  });
  assert.ok(handles.length > 0, 'a draggable handle well inside the canvas');
  const { x, y } = handles[0];
  await page.mouse.move(box.x + x, box.y + y);
  await page.mouse.down();
  await page.mouse.move(box.x + x + 12, box.y + y + 8, { steps: 4 });
  await page.mouse.move(box.x + x + 25, box.y + y + 15, { steps: 4 });
  await page.mouse.up();
  await settle(frame);
}

// The shell's own parts of the embed (its parameters, the snippet it copies) run the same
// code for every lesson: they are checked on these two (a mesh and a curve lesson); what
// shows the lesson's state runs on every lesson.
const EMBED_SHELL_LESSONS = new Set(['mesh', 'curves']);

for (const lesson of readyLessons) {
  test(`${lesson.id}: the embed at 800x500 from another origin shows the prepared state fitted; drag, Reset; the saved work untouched`, async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
    const { prepared, link, key, saved, isDefault } = await prepare(context, lesson);
    assert.equal(isDefault, false, 'the prepared state is not the lesson\'s default');

    const { page, frame } = await openHost(context, iframeHtml(embedSrc(link)));
    // The frame shares the full app's storage (same site): the test can see a write.
    assert.equal(await frame.evaluate((k) => localStorage.getItem(k), key), saved.code, 'the frame reads the same storage as the full app');
    const shown = await frame.evaluate(() => window.wingspline.state);
    assert.deepEqual(withoutView(shown), withoutView(prepared), 'the frame shows the prepared state');
    assertFitted(await layout(frame), FRAME, 'on load');
    assert.deepEqual(await toolbarActions(frame), ['reset', 'open'], 'only Reset and Open in Wingspline');
    const chrome = await frame.evaluate(() => ({
      brand: document.querySelector('.brand')?.getClientRects().length ?? 0,
      panels: document.getElementById('panels').getClientRects().length,
      open: (() => { const a = document.querySelector('#lesson-toolbar a[data-action=open]'); return { href: a.href, target: a.target, rel: a.rel, text: a.textContent }; })(),
    }));
    assert.equal(chrome.brand, 0, 'no site brand');
    assert.equal(chrome.panels, 0, 'no side panels unless asked for');
    assert.equal(chrome.open.target, '_blank');
    assert.match(chrome.open.rel, /\bnoopener\b/);
    assert.match(chrome.open.text, /Open in Wingspline/);
    const openUrl = new URL(chrome.open.href);
    assert.equal(openUrl.pathname, new URL(link).pathname, 'Open in Wingspline goes to the full lesson');
    assert.ok(!/embed=/.test(openUrl.hash) && /(^#|&)s=/.test(openUrl.hash), 'with the state and without the embed flag');
    const loaded = await frame.evaluate(() => window.wingspline.state);

    // A drag changes the state where the drawing has something to drag (the code lesson's
    // drawing is a view of its tables: nothing there to drag or reset).
    if (await frame.evaluate(() => window.wingspline.handles().some((hd) => hd.draggable))) {
      await dragFirstHandle(page, frame);
      const dragged = await frame.evaluate(() => window.wingspline.state);
      assert.notDeepEqual(withoutView(dragged), withoutView(prepared), 'a drag in the frame changes the state');
      await frame.evaluate(() => window.wingspline.flush());
      await frame.click('#lesson-toolbar [data-action=reset]');
      await settle(frame);
      assert.deepEqual(await frame.evaluate(() => window.wingspline.state), loaded, 'Reset brings back the prepared state exactly');
    } else {
      assert.ok(!LESSON_OBJECTS[lesson.id].moveHandle, `${lesson.id}: no handle to drag, and no hook to move one`);
    }

    // Resized to 400 x 300 by the host: fitted again.
    await page.evaluate(({ width, height }) => { const f = document.querySelector('iframe'); f.width = String(width); f.height = String(height); }, SMALL);
    await frame.waitForFunction((w) => innerWidth === w, SMALL.width);
    await settle(frame);
    await settle(frame);
    assertFitted(await layout(frame), SMALL, 'after a resize to 400x300');

    // Nothing of the embed reached the person's storage (read in the frame, which shares it,
    // before any full app opens again: a full app may write the same state back with its
    // fields in another order); the full app shows the saved work.
    await frame.evaluate(() => window.wingspline.flush());
    await settle(frame);
    assert.equal(await frame.evaluate((k) => localStorage.getItem(k), key), saved.code, 'the saved work of the lesson is unchanged');
    assert.equal(await frame.evaluate(() => localStorage.getItem('wingspline:theme')), saved.theme, 'the theme preference is unchanged');
    const app = await context.newPage();
    await app.goto(new URL(lesson.page, env.site.url).href);
    await app.waitForSelector('body[data-ready=true]', { timeout: 15000 });
    const after = await app.evaluate(() => ({ state: window.wingspline.state }));
    assert.deepEqual(withoutView(after.state), withoutView(saved.state), 'the full app opens at the saved work');
    // Open in Wingspline (after Reset: the prepared state) opens the full lesson there.
    const openHref = await frame.evaluate(() => document.querySelector('#lesson-toolbar a[data-action=open]').href);
    const full = await context.newPage();
    await full.goto(openHref);
    await full.waitForSelector('body[data-ready=true]', { timeout: 15000 });
    assert.deepEqual(withoutView(await full.evaluate(() => window.wingspline.state)), withoutView(prepared), 'Open in Wingspline shows the state of the frame');
    assert.equal(await full.locator('[data-action=share]').count(), 1, 'in the full app');
    assert.deepEqual(page.problems, []);
  });

  test(`${lesson.id}: theme=dark and present=1 travel in the link and leave the saved preference alone`, async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
    const { app, link, prepared } = await prepare(context, lesson);
    // The person's own preference: light, chosen with the Theme button.
    for (let i = 0; i < 3 && (await app.evaluate(() => document.documentElement.dataset.theme)) !== 'light'; i += 1) await app.click('[data-action=theme]');
    assert.equal(await app.evaluate(() => localStorage.getItem('wingspline:theme')), 'light');
    const { frame } = await openHost(context, iframeHtml(embedSrc(link, '&theme=dark&present=1')));
    const seen = await frame.evaluate(() => ({
      theme: document.documentElement.dataset.theme,
      present: document.documentElement.hasAttribute('data-present'),
      background: window.wingspline.ctx.colors.background,
      stored: localStorage.getItem('wingspline:theme'),
      state: window.wingspline.state,
    }));
    assert.equal(seen.theme, 'dark');
    assert.equal(seen.present, true);
    // The canvas is drawn dark: relative luminance of its background under 0.2.
    const [r, g, b] = seen.background.match(/^#([0-9a-f]{2})([0-9a-f]{2})([0-9a-f]{2})$/i).slice(1).map((x) => parseInt(x, 16) / 255);
    assert.ok(0.2126 * r + 0.7152 * g + 0.0722 * b < 0.2, `a dark canvas (${seen.background})`);
    assert.equal(seen.stored, 'light', 'the saved theme preference is unchanged');
    assert.deepEqual(withoutView(seen.state), withoutView(prepared));
    assertFitted(await layout(frame), FRAME, 'in presentation mode');
    assert.equal(await app.evaluate(() => localStorage.getItem('wingspline:theme')), 'light');
  });

  // The embed's parameters are read by the shell before the lesson sees them: two lessons.
  if (EMBED_SHELL_LESSONS.has(lesson.id)) test(`${lesson.id}: tampered embed parameters give one clear line, and the lesson still opens embedded`, async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
    const { link, prepared } = await prepare(context, lesson);
    const tampered = `&theme=${encodeURIComponent(payloads.img)}&present=yes&panels=${encodeURIComponent(`no-such-panel,${payloads.script}`)}`;
    const { frame } = await openHost(context, iframeHtml(embedSrc(link, tampered)));
    const message = await frame.evaluate(() => window.wingspline.message());
    assert.ok(message.length > 0 && message.length <= MESSAGE_MAX_CHARS, `one line says what was wrong (${message.length} chars)`);
    assert.match(message, /theme/, 'the message names the parameter');
    assert.deepEqual(await nothingExecuted(frame), { pwned: null, injectedElements: 0 });
    assert.deepEqual(withoutView(await frame.evaluate(() => window.wingspline.state)), withoutView(prepared), 'the prepared state is shown');
    assert.deepEqual(await toolbarActions(frame), ['reset', 'open'], 'still embedded');
    const look = await frame.evaluate(() => ({ theme: document.documentElement.dataset.theme ?? 'system', present: document.documentElement.hasAttribute('data-present') }));
    assert.notEqual(look.theme, payloads.img);
    assert.equal(look.present, false, 'a present value other than 1 is not presentation mode');
    assertFitted(await layout(frame), FRAME, 'with tampered parameters');
  });
}

// "Copy embed code" in the full app, for one lesson per run of the two clipboard cases.
const snippetPattern = /^<iframe src="([^"<>]+)" width="800" height="500" title="([^"<>]+)" loading="lazy" style="border:0"><\/iframe>$/;
const unescapeAttr = (text) => text.replace(/&quot;/g, '"').replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&amp;/g, '&');

for (const lesson of readyLessons.filter((l) => EMBED_SHELL_LESSONS.has(l.id))) {
  test(`${lesson.id}: Copy embed code copies an iframe snippet whose src opens the same state (clipboard granted)`, async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
    await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(env.site.url).origin });
    const { app } = await prepare(context, lesson);
    const state = await app.evaluate(() => window.wingspline.state);
    await app.click('details.menu > summary');
    await app.getByRole('button', { name: 'Copy embed code' }).click();
    await app.waitForFunction(() => /embed code/i.test(window.wingspline.message()));
    assert.match(await app.evaluate(() => window.wingspline.message()), /copied/i);
    const snippet = await app.evaluate(() => navigator.clipboard.readText());
    const m = snippet.match(snippetPattern);
    assert.ok(m, `the snippet is one iframe element (${snippet.slice(0, 200)})`);
    assert.equal(unescapeAttr(m[2]), `${lesson.title} (Wingspline)`);
    const src = unescapeAttr(m[1]);
    assert.match(new URL(src).hash, /(^#|&)embed=1(&|$)/);
    const { frame } = await openHost(context, snippet);
    assert.equal(await frame.evaluate(() => window.wingspline.lesson), lesson.id);
    assert.deepEqual(withoutView(await frame.evaluate(() => window.wingspline.state)), withoutView(state), 'the snippet opens the same state');
    assertFitted(await layout(frame), FRAME, 'the snippet\'s frame');
  });
}

test('Copy embed code where the clipboard is refused: the snippet in a dialog to copy by hand', async () => {
  const lesson = readyLessons[0];
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  // The browser refuses the clipboard (a policy, a denied permission).
  await context.addInitScript(() => {
    Object.defineProperty(Navigator.prototype, 'clipboard', { get: () => ({ writeText: () => Promise.reject(new DOMException('Write permission denied.', 'NotAllowedError')) }) });
  });
  const { app } = await prepare(context, lesson);
  const state = await app.evaluate(() => window.wingspline.state);
  await app.click('details.menu > summary');
  await app.getByRole('button', { name: 'Copy embed code' }).click();
  const dialog = app.locator('dialog[open]');
  await dialog.waitFor();
  const snippet = await dialog.locator('textarea').inputValue();
  const m = snippet.match(snippetPattern);
  assert.ok(m, `the dialog holds the snippet (${snippet.slice(0, 200)})`);
  assert.equal(await dialog.locator('iframe').count(), 0, 'the snippet is text, not markup');
  assert.match(await app.evaluate(() => window.wingspline.message()), /copy/i);
  const { frame } = await openHost(context, snippet);
  assert.deepEqual(withoutView(await frame.evaluate(() => window.wingspline.state)), withoutView(state));
  await dialog.getByRole('button', { name: /close/i }).click();
  assert.equal(await app.locator('dialog[open]').count(), 0, 'the dialog closes');
});

test('lesson pages may be framed by another origin: no X-Frame-Options, no frame-ancestors', async () => {
  for (const lesson of readyLessons) {
    const res = await fetch(new URL(lesson.page, env.site.url));
    assert.equal(res.status, 200);
    assert.equal(res.headers.get('x-frame-options'), null, `${lesson.page}: no X-Frame-Options`);
    assert.doesNotMatch(res.headers.get('content-security-policy') ?? '', /frame-ancestors/);
    assert.doesNotMatch(await res.text(), /frame-ancestors/);
  }
});

test('panels= shows the listed side panels beside the canvas, and no other', async () => {
  const lesson = readyLessons.find((l) => l.id === 'curves');
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  const { link } = await prepare(context, lesson);
  const { frame } = await openHost(context, iframeHtml(embedSrc(link, '&panels=panel-matrix,panel-overlays')));
  const seen = await frame.evaluate(() => ({
    shown: [...document.querySelectorAll('#panels > *')].filter((el) => el.getClientRects().length > 0).map((el) => el.id),
    all: document.querySelectorAll('#panels > *').length,
    canvas: document.getElementById('stage').getBoundingClientRect().toJSON(),
    panels: document.getElementById('panels').getBoundingClientRect().toJSON(),
    message: window.wingspline.message(),
    scroll: { w: document.scrollingElement.scrollWidth, h: document.scrollingElement.scrollHeight },
  }));
  assert.deepEqual(seen.shown.sort(), ['panel-matrix', 'panel-overlays']);
  assert.ok(seen.all > 2, 'the lesson has other panels, hidden');
  assert.equal(seen.message, '', 'nothing to say');
  assert.ok(seen.panels.left >= seen.canvas.right - EDGE_PX, 'the panels beside the canvas');
  assert.ok(seen.scroll.w <= FRAME.width && seen.scroll.h <= FRAME.height, `no scroll bars (${JSON.stringify(seen.scroll)})`);
  assert.deepEqual((await layout(frame)).outside, [], 'every handle on the canvas');
});

test('controls=1 shows the lesson\'s controls under the canvas, inside the frame', async () => {
  const lesson = readyLessons.find((l) => l.id === 'curves');
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  const { link } = await prepare(context, lesson);
  const { frame } = await openHost(context, iframeHtml(embedSrc(link, '&controls=1')));
  const seen = await frame.evaluate(() => {
    const c = document.getElementById('stage-controls').getBoundingClientRect();
    const s = document.getElementById('stage').getBoundingClientRect();
    const legend = document.querySelector('.canvas-legend');
    const figureBottom = legend && legend.getClientRects().length ? legend.getBoundingClientRect().bottom : s.bottom;
    return { controls: { top: c.top, bottom: c.bottom, height: c.height }, canvasBottom: figureBottom,
      scroll: { w: document.scrollingElement.scrollWidth, h: document.scrollingElement.scrollHeight } };
  });
  assert.ok(seen.controls.height > 0, 'the controls are shown');
  assert.ok(seen.controls.top >= seen.canvasBottom - EDGE_PX && seen.controls.bottom <= FRAME.height + EDGE_PX, `under the canvas, inside the frame (${JSON.stringify(seen)})`);
  assert.ok(seen.scroll.w <= FRAME.width && seen.scroll.h <= FRAME.height, `no scroll bars (${JSON.stringify(seen.scroll)})`);
  assert.deepEqual((await layout(frame)).outside, [], 'every handle on the canvas');
});

test('an embed whose state is damaged shows the starting point with one line, and leaves the saved work alone', async () => {
  const lesson = readyLessons.find((l) => l.id === 'curves');
  const context = await env.newContext({ viewport: { width: 1280, height: 800 } });
  const { link, key, saved } = await prepare(context, lesson);
  const damaged = embedSrc(link).replace(/&s=.*/, '&s=QUJDREVGR0hJSktMTU5PUA');
  const { frame } = await openHost(context, iframeHtml(damaged));
  const seen = await frame.evaluate((k) => ({ message: window.wingspline.message(), stored: localStorage.getItem(k),
    isDefault: (() => { const { view, ...rest } = window.wingspline.state; const { view: v, ...d } = window.wingspline.hooks.defaultState(); return JSON.stringify(rest) === JSON.stringify(d); })() }), key);
  assert.match(seen.message, /could not be used/);
  assert.ok(seen.message.length <= MESSAGE_MAX_CHARS);
  assert.equal(seen.isDefault, true, 'the lesson\'s starting point, not the saved work');
  assert.equal(seen.stored, saved.code, 'the saved work is neither shown nor moved');
  assert.deepEqual(await toolbarActions(frame), ['reset', 'open']);
  assertFitted(await layout(frame), FRAME, 'at the starting point');
});
