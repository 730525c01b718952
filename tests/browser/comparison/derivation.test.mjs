// The derivation panel of the comparison lab, driven like a student: open it, read
// the matrices (lecture 000's M_H and C, S and M_B, lecture 003's 1/6 M_BS as the page shows
// them), then drag P1 with the mouse and nudge it with the keyboard and see R1 = 3(P2 - P1)
// follow with the new numbers (the lecture's P1, P2 are the lab's P0, P1).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { drag } from '../../helpers/pointer.mjs';

const env = useSiteAndBrowser();
async function openLab() {
  const page = await env.openPage(`${env.site.url}comparison.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  return page;
}
// The cells of the n-th matrix in a family's section, as the page shows them.
const cells = (page, family, n) => page.$$eval(`#derivation-panel .derivation[data-family="${family}"] mtable`,
  (tables, k) => Array.from(tables[k].querySelectorAll('mtd'), (td) => td.textContent.trim()), n);
const state = (page) => page.evaluate(() => window.wingspline.state);
// the page prints vectors as (x, y) with 3 significant digits
const shown = (v) => `(${v.map((x) => String(Number(x.toPrecision(3)))).join(', ')})`;
async function liveR1(page) {
  const s = await state(page);
  const [P1, P2] = s.points;
  const R1 = [3 * (P2[0] - P1[0]), 3 * (P2[1] - P1[1])];
  // the core's R1 (convertBasis) equals, within 1e-12 relative to |R1| (rounding of doubles), the lecture's 3 (P2 - P1) for the current points ...
  await page.waitForFunction((want) => {
    const got = window.wingspline.model.derivations.live.R1;
    return Math.hypot(got[0] - want[0], got[1] - want[1]) <= 1e-12 * Math.max(1, Math.hypot(want[0], want[1]));
  }, R1);
  // ... and the panel prints it
  await page.waitForFunction((want) => document.getElementById('derivation-live').textContent.includes(`= ${want};`), shown(R1));
  return R1;
}

test('the derivation panel shows C, M_H, S, M_B and M_BS as on the slides', async () => {
  const page = await openLab();
  await page.click('#derivation-panel summary');
  assert.deepEqual(await cells(page, 'hermite', 0), ['0', '0', '0', '1', '1', '1', '1', '1', '0', '0', '1', '0', '3', '2', '1', '0']);
  assert.deepEqual(await cells(page, 'hermite', 1), ['2', '-2', '1', '1', '-3', '3', '-2', '-1', '0', '0', '1', '0', '1', '0', '0', '0']);
  assert.deepEqual(await cells(page, 'bezier', 0), ['1', '0', '0', '0', '0', '0', '0', '1', '-3', '3', '0', '0', '0', '0', '-3', '3']);
  assert.deepEqual(await cells(page, 'bezier', 1), ['-1', '3', '-3', '1', '3', '-6', '3', '0', '-3', '3', '0', '0', '1', '0', '0', '0']);
  const bs = await cells(page, 'bspline', 0);
  const sixths = [-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0];
  // the page prints each fraction in lowest terms: k/6
  assert.deepEqual(bs, sixths.map((k) => { const g = [6, 3, 2, 1].find((d) => k % d === 0 && 6 % d === 0); return k === 0 ? '0' : 6 / g === 1 ? String(k / g) : `${k / g}/${6 / g}`; }));
  assert.equal(await page.$$eval('#derivation-panel .derivation[data-family="bspline"] .conditions li', (l) => l.length), 16);
  await liveR1(page);
  await screenshot(page, 'comparison-derivation');
  assert.deepEqual(page.problems, []);
});

test('R1 = 3(P2 - P1) follows a drag and the arrow keys with live numbers', async () => {
  const page = await openLab();
  await page.click('#derivation-panel summary');
  const before = await liveR1(page);
  await drag(page, 'p1', 30, -20);
  const afterDrag = await liveR1(page);
  assert.ok(Math.hypot(afterDrag[0] - before[0], afterDrag[1] - before[1]) > 0.1, 'R1 changed with P2');
  await page.focus('#stage');
  // the drag selected P1 (the lab's p1); [ steps back to p0
  await page.keyboard.press('[');
  assert.equal(await page.evaluate(() => window.wingspline.selected), 'p0');
  await page.keyboard.press('ArrowLeft');
  const afterKey = await liveR1(page);
  assert.ok(afterKey[0] > afterDrag[0], 'P1 moved left: R1 grows in x');
  assert.deepEqual(page.problems, []);
});
