// Labels on every canvas of every lesson (readable on a projector), at 1920x1080 and
// 1280x720 in presentation mode and on a 390x844 touch phone, in the default state and in
// crowded ones: the app reports every label it drew in the last frame (client px boxes with
// their text and font size, window.wingspline.labelRects) and its legends
// (window.wingspline.legendRects). No two labels overlap, every label lies inside its
// canvas, none is smaller than the stated minimum (docs/architecture.md, "Labels"); the
// legend is outside every canvas (never over the drawing) and says the scale of every arrow
// drawn; the continuity lab's plots of |P'| and kappa start at 0.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { decodePng } from '../../helpers/png.mjs';
import { screenshot, useSiteAndBrowser, downloadedBytes } from '../../helpers/browser.mjs';
import { random as seededRandom } from '../../helpers/seeded-random.mjs';
import { lessons } from '../../../web/js/lessons/registry.js';

// The stated minimum label sizes, CSS px (docs/architecture.md, "Labels").
const MIN_LABEL_PX = 14;
const MIN_LABEL_PX_PRESENT = 20;
// A label farther than this from the point it names (CSS px, box to anchor), and farther than
// the place it asked for, has a leader line to it (docs/architecture.md, "Labels"; the
// layout's LEADER_MIN_PX, 18 px).
const LEADER_MIN_PX = 18;
// Two boxes "overlap" when they share more than this, in CSS px, both ways (rounding of
// client rectangles).
const OVERLAP_TOL_PX = 1;

const VIEWPORTS = [
  { name: '1920p', options: { viewport: { width: 1920, height: 1080 } }, present: true, min: MIN_LABEL_PX_PRESENT },
  { name: '1280p', options: { viewport: { width: 1280, height: 720 } }, present: true, min: MIN_LABEL_PX_PRESENT },
  { name: 'phone', options: { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true }, present: false, min: MIN_LABEL_PX },
];

const env = useSiteAndBrowser();

const frames = (page, n = 3) => page.evaluate((k) => new Promise((resolve) => {
  const step = (i) => (i === 0 ? resolve() : requestAnimationFrame(() => step(i - 1)));
  step(k);
}), n);

async function commit(page, patch) {
  const ok = await page.evaluate((p) => {
    const { ctx } = window.wingspline;
    const merged = { ...ctx.state };
    for (const [key, value] of Object.entries(p)) {
      merged[key] = value && typeof value === 'object' && !Array.isArray(value) && typeof ctx.state[key] === 'object' ? { ...ctx.state[key], ...value } : value;
    }
    return ctx.commit(merged);
  }, patch);
  assert.ok(ok, `the state ${JSON.stringify(patch)} is accepted`);
}

async function choose(page, selector, value) {
  await page.selectOption(selector, value);
}

// Crowded states per lesson, reached as a person would where a control exists (a preset
// or scene select) and otherwise through the page's state (as a shared link would).
const CROWDED = {
  mesh: [
    ['walk under way', (page) => commit(page, { step: 9 })],
    ['3D', (page) => commit(page, { mode3d: true, step: 6 })],
  ],
  curves: [
    ['de Casteljau at u = 0.5 with P\' and P\'\'', (page) => commit(page, { family: 'bezier', u: 0.5, construction: { kind: 'de-casteljau', step: 40 }, overlays: { tangent: true, second: true, hull: true } })],
    ['Hermite with tangents', (page) => commit(page, { family: 'hermite', overlays: { tangent: true, second: true } })],
  ],
  continuity: [
    ['gap preset', (page) => choose(page, '#preset', 'gap')],
    ['C2 preset', (page) => choose(page, '#preset', 'c2-bezier')],
  ],
  comparison: [
    ['all families', (page) => commit(page, { scene: 'families', show: { hermite: true, bezier: true, bspline: true, 'catmull-rom': true, nubs: true } })],
    ['conversion', (page) => choose(page, '#scene', 'conversion')],
  ],
  surfaces: [
    ['twists and a second patch', (page) => commit(page, { joined: true, show: { net: true, iso: true, shaded: true, twists: true } })],
  ],
  subdivision: [
    ['level 2', (page) => commit(page, { level: 2 })],
  ],
};

const overlap = (a, b) => Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x) > OVERLAP_TOL_PX
  && Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y) > OVERLAP_TOL_PX;

// Every visible canvas that draws text in a frame (the 2D context's fillText, watched here)
// reports labels: no canvas draws text around the layout.
async function watchText(page) {
  await page.evaluate(() => {
    const proto = CanvasRenderingContext2D.prototype;
    if (!proto.fillText.watched) {
      const original = proto.fillText;
      proto.fillText = function fillText(...args) {
        if (this.canvas?.dataset) this.canvas.dataset.drewText = '1';
        return original.apply(this, args);
      };
      proto.fillText.watched = true;
    }
    for (const c of document.querySelectorAll('canvas')) delete c.dataset.drewText;
    window.wingspline.ctx.render();
  });
}

async function checkLabels(page, where, min) {
  await watchText(page);
  await frames(page);
  const labels = await page.evaluate(() => window.wingspline.labelRects());
  assert.ok(labels.length > 0, `${where}: the page reports its labels`);
  const texting = await page.$$eval('canvas[data-drew-text]', (list) => list.filter((c) => c.getClientRects().length && c.getBoundingClientRect().width > 0).map((c) => c.id || c.className));
  assert.ok(texting.includes('stage'), `${where}: the text watch sees the lesson canvas draw its labels`);
  for (const name of texting) assert.ok(labels.some((l) => l.canvas === name), `${where}: canvas ${name} draws text but reports no label`);
  for (const l of labels) {
    assert.ok(l.fontPx >= min, `${where}: label "${l.text}" on ${l.canvas} is ${l.fontPx}px, under the ${min}px minimum`);
    const c = l.canvasRect;
    assert.ok(l.x >= c.x - OVERLAP_TOL_PX && l.y >= c.y - OVERLAP_TOL_PX && l.x + l.width <= c.x + c.width + OVERLAP_TOL_PX
      && l.y + l.height <= c.y + c.height + OVERLAP_TOL_PX, `${where}: label "${l.text}" lies inside its canvas ${l.canvas}`);
    const nx = Math.min(Math.max(l.anchor.x, l.x), l.x + l.width); const ny = Math.min(Math.max(l.anchor.y, l.y), l.y + l.height);
    const far = Math.hypot(nx - l.anchor.x, ny - l.anchor.y);
    if (far > Math.max(LEADER_MIN_PX, l.askedDistance + 1) + OVERLAP_TOL_PX) assert.ok(l.leader, `${where}: label "${l.text}" is ${far.toFixed(0)}px from its point and has no leader line`);
  }
  for (let i = 0; i < labels.length; i += 1) {
    for (let j = i + 1; j < labels.length; j += 1) {
      assert.ok(!overlap(labels[i], labels[j]), `${where}: labels "${labels[i].text}" (${labels[i].canvas}) and "${labels[j].text}" (${labels[j].canvas}) overlap`);
    }
  }
  // The legend is never over a drawing: outside every canvas that has labels.
  const legends = await page.evaluate(() => window.wingspline.legendRects());
  const canvases = [...new Map(labels.map((l) => [l.canvas, l.canvasRect])).values()];
  for (const legend of legends) {
    for (const c of canvases) assert.ok(!overlap(legend, c), `${where}: the legend "${legend.text.slice(0, 40)}..." is over a canvas`);
  }
  return { labels, legends };
}

async function open(id, file, vp) {
  const page = await env.openPage(`${env.site.url}${file ?? `${id}.html`}`, vp.options);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  if (vp.present) {
    await page.locator('#stage').focus();
    await page.keyboard.press('p');
    await page.waitForFunction(() => document.documentElement.hasAttribute('data-present'));
  }
  return page;
}

for (const { id, page: file, ready } of lessons) {
  if (!ready) continue;
  for (const vp of VIEWPORTS) {
    test(`${id} at ${vp.name}: no label overlaps another, leaves its canvas or is under ${vp.min}px; the legend is off the drawing`, async () => {
      const page = await open(id, file, vp);
      await checkLabels(page, `${id} ${vp.name} default`, vp.min);
      await screenshot(page, `labels-${id}-${vp.name}`);
      for (const [name, reach] of CROWDED[id] ?? []) {
        await reach(page);
        await checkLabels(page, `${id} ${vp.name} ${name}`, vp.min);
        await screenshot(page, `labels-${id}-${vp.name}-${name.replace(/[^a-z0-9]+/gi, '-')}`);
      }
      assert.deepEqual(page.problems, []);
    });
  }
}

// Every arrow drawn at a scale has that scale spelled out in the legend.
const ARROW_LEGENDS = [
  ['continuity', null, [/velocity P'\/3/, /P'⁻\/3 left/, /P''⁺\/6 right/, /arrows drawn at 1\/3 of P'\(u\) and 1\/6 of P''\(u\)/]],
  ['comparison', null, [/Hermite tangents t_i: arrows drawn at 1\/3 of t_i/]],
  ['surfaces', { show: { twists: true } }, [/twist vectors p_uv: arrows drawn at 1\/9 of p_uv/]],
  ['curves', { family: 'hermite', overlays: { tangent: true, second: true } }, [/1\/3 of T_i/, /arrow drawn at 1\/3 of P'\(u\)/, /arrow drawn at 1\/6 of P''\(u\)/]],
];
for (const [id, patch, expected] of ARROW_LEGENDS) {
  test(`${id}: the legend says the scale of every arrow drawn`, async () => {
    const page = await open(id, null, VIEWPORTS[1]);
    if (patch) await commit(page, patch);
    await frames(page);
    const legends = await page.evaluate(() => window.wingspline.legendRects());
    const text = legends.map((l) => l.text).join('\n');
    for (const re of expected) assert.match(text, re);
    assert.deepEqual(page.problems, []);
  });
}

// |P'| and kappa are never negative: their axes start at 0 and no plotted sample is below it,
// in the default state and in 40 random (seeded) polygons.
test('continuity: the |P\'| and kappa plots start at 0, for the default and random curves', async () => {
  const page = await open('continuity', null, VIEWPORTS[1]);
  const rand = seededRandom(18);
  const check = async (where) => {
    await frames(page, 2);
    const plots = await page.$$eval('#plot-speed, #plot-curvature', (list) => list.map((c) => ({ id: c.id, axisMin: c.dataset.axisMin, sampleMin: c.dataset.sampleMin })));
    assert.equal(plots.length, 2);
    for (const p of plots) {
      assert.equal(Number(p.axisMin), 0, `${where}: ${p.id}'s axis starts at 0 (not ${p.axisMin})`);
      assert.ok(Number(p.sampleMin) >= 0, `${where}: ${p.id} plots no sample below 0`);
    }
    const ticks = (await page.evaluate(() => window.wingspline.labelRects())).filter((l) => /plot-(speed|curvature)/.test(l.canvas) && /^-?[\d.e+-]+$/.test(l.text));
    assert.ok(ticks.length >= 2, `${where}: the plots show their axis numbers`);
    for (const t of ticks) assert.ok(Number(t.text) >= 0, `${where}: axis number ${t.text} on ${t.canvas} is not negative`);
  };
  // the plots sit in a panel: open it as a person would
  await page.evaluate(() => { for (const d of document.querySelectorAll('details')) if (d.querySelector('#plot-speed')) d.open = true; });
  await check('default');
  for (let k = 0; k < 40; k += 1) {
    const points = Array.from({ length: 8 }, () => [rand() * 8 - 4, rand() * 6 - 3]);
    await commit(page, { constraint: 'free', family: 'bezier', points });
    await check(`random polygon ${k}`);
  }
  assert.deepEqual(page.problems, []);
});

// The exported figures carry the legend: the SVG as a band of text under the drawing, the
// PNG as a band of rows under the canvas picture (taller than the canvas).
test('continuity: the exported SVG and PNG figures carry the legend under the drawing', async () => {
  const page = await env.openLesson(`${env.site.url}continuity.html`);
  const exportFile = async (key) => {
    await page.click('details.menu > summary');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click(`[data-export="${key}"]`)]);
    return downloadedBytes(download);
  };
  const canvas = await page.$eval('#stage', (c) => ({ cssHeight: c.getBoundingClientRect().height, height: c.height }));
  const svg = (await exportFile('continuity.svg')).toString('utf8');
  assert.match(svg, /arrows drawn at 1\/3 of P&apos;\(u\)/);
  const svgHeight = Number(/<svg[^>]* height="([\d.]+)"/.exec(svg)[1]);
  assert.ok(svgHeight > canvas.cssHeight + 20, `the SVG (${svgHeight}) is taller than the drawing (${canvas.cssHeight})`);
  const png = decodePng(await exportFile('continuity.png'));
  assert.ok(png.height > canvas.height + 20, `the PNG (${png.height} px) is taller than the canvas (${canvas.height} px)`);
  assert.deepEqual(page.problems, []);
});
