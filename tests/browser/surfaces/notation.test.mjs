// The surfaces lesson names the matrix it shows correctly. The formula writes
// u^T = [u^3 u^2 u 1] (descending powers, lectures 000 and 003), so the M it shows must be
// that convention's matrix; lecture 002 derives M_B and M_H for u = (1, u, u^2, u^3), i.e.
// the same matrices with the rows in the opposite order. The expected matrices are computed
// here from lecture 002's own derivation in integers (M = A^-1 B), not read from the app.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();

const mul = (a, b) => a.map((row) => b[0].map((_, j) => row.reduce((s, x, k) => s + x * b[k][j], 0)));
const I4 = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
// Lecture 002: (p(0), p(1), p'(0), p'(1)) = A (c0, c1, c2, c3).
const A = [[1, 0, 0, 0], [1, 1, 1, 1], [0, 1, 0, 0], [0, 1, 2, 3]];
// Its inverse in integers, checked below (A Ainv = I), so M_H = Ainv (lecture 002: M_H = A_H^-1).
const Ainv = [[1, 0, 0, 0], [0, 0, 1, 0], [-3, 3, -2, -1], [2, -2, 1, 1]];
// Lecture 002: (p0, p3, 3p1 - 3p0, 3p3 - 3p2) = B (p0, p1, p2, p3), M_B = A^-1 B.
const B = [[1, 0, 0, 0], [0, 0, 0, 1], [-3, 3, 0, 0], [0, 0, -3, 3]];

const shownM = (page) => page.$eval('#formula-panel [data-matrix=M]', (m) =>
  [...m.querySelectorAll('mtr')].map((tr) => [...tr.querySelectorAll('mtd')].map((td) => Number(td.textContent))));

test('the surfaces lesson shows lecture 003\'s descending M and says lecture 002\'s M_B, M_H are its rows reversed', async () => {
  assert.deepEqual(mul(A, Ainv), I4, 'A_H^-1 typed right');
  const M_B_002 = mul(Ainv, B);
  const M_H_002 = Ainv;
  const page = await env.openPage(`${env.site.url}surfaces.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });

  assert.deepEqual(await shownM(page), M_B_002.slice().reverse(), 'Bezier: shown M = lecture 002 M_B, rows reversed');
  const bezierNote = await page.textContent('#surface-matrix-name');
  assert.match(bezierNote, /M is M_Bezier of lecture 003, for uᵀ = \[u³ u² u 1\]/);
  assert.match(bezierNote, /its M_B is this M with the rows in the opposite order/);
  assert.doesNotMatch(bezierNote, /M is M_B of lecture 002/);

  await page.selectOption('#kind', 'hermite');
  await page.waitForFunction(() => window.wingspline.state.kind === 'hermite');
  assert.deepEqual(await shownM(page), M_H_002.slice().reverse(), 'Hermite: shown M = lecture 002 M_H, rows reversed');
  assert.match(await page.textContent('#surface-matrix-name'), /M is M_Hermite of lectures 000 and 003.*M_H = A_H⁻¹ is this M with the rows in the opposite order/);
});
