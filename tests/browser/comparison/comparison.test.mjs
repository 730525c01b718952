// The comparison lab: the live table against lecture 003's table, a drag that keeps the
// facts, basis conversion against lecture 002's Bezier tangents, and invariance.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';

// Lecture 003's comparison table, typed from the notes (Hermite, Bezier, B-spline, Catmull-Rom).
const LECTURE_003 = {
  convexHull: ['N/A', 'Yes', 'Yes', 'No'],
  interpolatesSome: ['Yes', 'Yes', 'No', 'Yes'],
  interpolatesAll: ['Yes', 'No', 'No', 'Yes'],
  subdivision: ['Good', 'Best', 'Avg', 'Avg'],
  inherent: ['C0 G0', 'C0 G0', 'C2 G2', 'C1 G1'],
  easy: ['C1 G1', 'C1 G1', 'C2 G2', 'C1 G1'],
};
// Lecture 001's non-uniform B-spline column (YES, NO, NO, High, C2 G2, C2 G2).
const LECTURE_001_NUBS = { convexHull: 'Yes', interpolatesSome: 'No', interpolatesAll: 'No', subdivision: 'High', inherent: 'C2 G2', easy: 'C2 G2' };
const FAMILIES = ['hermite', 'bezier', 'bspline', 'catmull-rom'];
const EXACT = 1e-12; // world units: "the same curve"

const env = useSiteAndBrowser();

async function openLab() {
  const page = await env.openPage(`${env.site.url}comparison.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  return page;
}
const liveTable = (page) => page.$$eval('.live-cell', (cells) => cells.map((c) => ({ row: c.dataset.row, family: c.dataset.family, answer: c.dataset.answer })));

function assertMatchesLecture(cells) {
  for (const [row, answers] of Object.entries(LECTURE_003)) {
    FAMILIES.forEach((family, k) => {
      const cell = cells.find((c) => c.row === row && c.family === family);
      assert.ok(cell, `cell ${row} / ${family} is on the page`);
      assert.equal(cell.answer, answers[k], `${row} for ${family}`);
    });
    const nubs = cells.find((c) => c.row === row && c.family === 'nubs');
    assert.equal(nubs?.answer, LECTURE_001_NUBS[row], `${row} for the non-uniform B-spline (lecture 001)`);
  }
}

test('the live table matches lecture 003 for the default polygon', async () => {
  const page = await openLab();
  assertMatchesLecture(await liveTable(page));
  const interp = await page.evaluate(() => Object.fromEntries(Object.entries(window.wingspline.model.table.columns)
    .map(([f, c]) => [f, c.interpolatesSome.interpolated])));
  // A cubic Bezier segment interpolates its end points only: P0, P3, P6 of the 7-point polygon.
  assert.deepEqual(interp.bezier, [0, 3, 6]);
  assert.deepEqual(interp.bspline, [], 'the uniform B-spline passes through none');
  assert.deepEqual(interp.hermite, [0, 1, 2, 3, 4, 5, 6]);
  assert.equal(await page.$$eval('.live-cell [class="lecture differs"]', (x) => x.length), 0);
  await screenshot(page, 'comparison-families');
  assert.deepEqual(page.problems, []);
});

test('adding and removing segments keeps the lecture\'s table true at every joint', async () => {
  const page = await openLab();
  const points = () => page.evaluate(() => window.wingspline.state.points.length);
  const bezierJoints = () => page.$eval('.live-cell[data-row="inherent"][data-family="bezier"] .evidence', (e) => e.textContent);
  assert.match(await bezierJoints(), /of 1 joint$/);
  await page.click('#add-segment');
  await page.waitForFunction(() => window.wingspline.state.points.length === 10);
  assertMatchesLecture(await liveTable(page));
  assert.match(await bezierJoints(), /of 2 joints/);
  const interp = await page.evaluate(() => window.wingspline.model.table.columns.bezier.interpolatesSome.interpolated);
  assert.deepEqual(interp, [0, 3, 6, 9], 'a cubic Bezier passes through every third point');
  // By key: n adds, x removes; never below one segment, never above ten.
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('x');
  assert.equal(await points(), 7);
  assert.equal(await page.$eval('#remove-segment', (b) => b.disabled), true);
  assertMatchesLecture(await liveTable(page));
  await page.keyboard.press('x');
  assert.equal(await points(), 7, 'two segments are the least by button: the continuity rows need a joint');
  for (let i = 0; i < 10; i += 1) await page.keyboard.press('n');
  assert.equal(await points(), 31);
  assert.equal(await page.$eval('#add-segment', (b) => b.disabled), true);
  assertMatchesLecture(await liveTable(page));
  // Undo takes the last addition back.
  await page.click('[data-action="undo"]');
  assert.equal(await points(), 28);
  assert.deepEqual(page.problems, []);
});

test('dragging a control point keeps the lecture\'s facts true', async () => {
  const page = await openLab();
  const hd = (await page.evaluate(() => window.wingspline.handles())).find((x) => x.id === 'p1');
  await page.mouse.move(hd.x, hd.y);
  await page.mouse.down();
  await page.mouse.move(hd.x + 30, hd.y - 40, { steps: 5 });
  await page.mouse.up();
  const s = await page.evaluate(() => window.wingspline.state);
  assert.notDeepEqual(s.points[1], [-2.4, 1.3]);
  assertMatchesLecture(await liveTable(page));
  assert.deepEqual(page.problems, []);
});

test('basis conversion: the Hermite geometry of a Bezier segment is P0, P3, 3(P1 - P0), 3(P3 - P2)', async () => {
  const page = await openLab();
  await page.selectOption('#scene', 'conversion');
  await page.selectOption('#conv-to', 'hermite');
  const r = await page.evaluate(() => {
    const m = window.wingspline.model.conversion;
    return { q: Array.from(m.q), distance: m.distance, points: window.wingspline.state.points };
  });
  const [P0, P1, P2, P3] = r.points;
  // Lecture 002: p'(0) = 3 (p1 - p0), p'(1) = 3 (p3 - p2).
  const expected = [...P0, ...P3, 3 * (P1[0] - P0[0]), 3 * (P1[1] - P0[1]), 3 * (P3[0] - P2[0]), 3 * (P3[1] - P2[1])];
  expected.forEach((v, k) => assert.ok(Math.abs(r.q[k] - v) < EXACT, `q[${k}]`));
  assert.ok(r.distance < EXACT, 'the converted geometry draws the same curve');
  assert.match(await page.textContent('#conversion-panel'), /max distance/);
  await screenshot(page, 'comparison-conversion');
  // Keep G and swap M: the same four points read as B-spline geometry give another curve.
  await page.selectOption('#conv-mode', 'keep-geometry');
  await page.selectOption('#conv-to', 'bspline');
  const swapped = await page.evaluate(() => window.wingspline.model.conversion.distance);
  assert.ok(swapped > 0.05, 'a different curve');
  assert.deepEqual(page.problems, []);
});

test('invariance: affine maps commute with every family; perspective only with the rational form', async () => {
  const page = await openLab();
  await page.selectOption('#scene', 'invariance');
  let inv = await page.evaluate(() => window.wingspline.model.invariance);
  for (const f of [...FAMILIES, 'nubs']) assert.ok(inv.rows[f].distance < 1e-12, `${f} is affine invariant`);
  await page.selectOption('#tf-kind', 'perspective');
  await page.waitForFunction(() => window.wingspline.state.transform.kind === 'perspective');
  inv = await page.evaluate(() => window.wingspline.model.invariance);
  assert.ok(inv.rows.bezier.distance > 1e-3, 'a polynomial Bezier curve is not perspective invariant');
  assert.ok(inv.rational.distance < 1e-12, 'the rational Bezier with weights w(P_i) is');
  await screenshot(page, 'comparison-perspective');
  assert.deepEqual(page.problems, []);
});

// Every choice of the conversion panel reads as words and numbers.
test('basis conversion: the panel never prints null, undefined or NaN', async () => {
  const page = await openLab();
  await page.selectOption('#scene', 'conversion');
  for (const mode of ['keep-curve', 'keep-geometry']) {
    await page.selectOption('#conv-mode', mode);
    for (const from of ['bezier', 'bspline', 'catmull-rom']) {
      await page.selectOption('#conv-from', from);
      for (const to of ['hermite', 'bezier', 'bspline', 'catmull-rom']) {
        await page.selectOption('#conv-to', to);
        await page.waitForFunction(([m, f, t]) => { const c = window.wingspline.state.conversion; return c.mode === m && c.from === f && c.to === t; }, [mode, from, to]);
        await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
        const text = await page.textContent('#conversion-panel');
        assert.doesNotMatch(text, /null|undefined|NaN/, `${mode}, ${from} -> ${to}: ${text.slice(0, 200)}`);
      }
    }
  }
  assert.deepEqual(page.problems, []);
});

// A cell of the lecture's table is a guarantee for every polygon; what this
// polygon happens to do is shown beside it and never turns the lecture red.
async function typePoint(page, id, [x, y]) {
  const hd = (await page.evaluate(() => window.wingspline.handles())).find((k) => k.id === id);
  await page.mouse.click(hd.x, hd.y);
  await page.waitForFunction((want) => window.wingspline.selected === want, id);
  await page.fill('#inspect-x', String(x));
  await page.fill('#inspect-y', String(y));
  await page.press('#inspect-y', 'Enter');
  await page.waitForFunction(([i, px, py]) => { const p = window.wingspline.state.points[i]; return p[0] === px && p[1] === py; }, [Number(id.slice(1)), x, y]);
}
const polygonCell = (page, row, family) => page.$eval(`.polygon-cell[data-row="${row}"][data-family="${family}"]`, (c) => ({ answer: c.dataset.answer, text: c.textContent }));

test('a polygon that happens to be smoother, or to touch its curve, keeps the lecture\'s guarantees', async () => {
  const page = await openLab();
  const [, P1, , P3] = await page.evaluate(() => window.wingspline.state.points);
  // P2 midway between P1 and P3: the uniform B-spline passes through P2 ((P1 + 4 P2 + P3) / 6 = P2).
  const P2 = [(P1[0] + P3[0]) / 2, (P1[1] + P3[1]) / 2];
  await typePoint(page, 'p2', P2);
  // P2, P3, P4 collinear with equal legs (P4 = 2 P3 - P2): this Bezier joint is C1.
  await typePoint(page, 'p4', [2 * P3[0] - P2[0], 2 * P3[1] - P2[1]]);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  assertMatchesLecture(await liveTable(page));
  assert.equal(await page.$$eval('.live-cell [class="lecture differs"]', (x) => x.length), 0, 'no cell marks the lecture wrong');
  // What this polygon does, in its own column.
  assert.match((await polygonCell(page, 'inherent', 'bezier')).answer, /^C1 G1$/, 'this Bezier polygon happens to be C1 at its joint');
  const touch = await polygonCell(page, 'interpolatesSome', 'bspline');
  assert.equal(touch.answer, 'Yes');
  assert.match(touch.text, /P2\b/, 'the B-spline happens to pass through P2');
  // Ease of subdivision is the lecture's judgement: quoted, never checked.
  const quoted = await page.$$eval('.live-cell[data-row="subdivision"]', (cells) => cells.map((c) => ({ quoted: c.dataset.quoted, text: c.textContent })));
  assert.equal(quoted.length, 5);
  for (const q of quoted) {
    assert.equal(q.quoted, 'true');
    assert.match(q.text, /quoted/i);
    assert.doesNotMatch(q.text, /✓/);
  }
  assert.deepEqual(page.problems, []);
});
