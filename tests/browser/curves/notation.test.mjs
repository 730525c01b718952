// The lectures' notation in the curve explorer: the matrix panel switches between
// decimals and the slides' exact form (1/6 [integers] for the uniform B-spline, 1/2 [...] for
// Catmull-Rom) by keyboard and by pointer; the switch is state (undo, share links). The
// expected integers are typed from lecture 003, never read from the page's own code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { openCurves, frame, chooseFamily } from '../../helpers/curves-page.mjs';
import { envelopeCode } from '../../helpers/classroom.mjs';

const env = useSiteAndBrowser();

// Lecture 003 (003_55ddbc47c7ee2ef3.txt), row by row.
const M_BSPLINE = [[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 0, 3, 0], [1, 4, 1, 0]];
const M_CR = [[-1, 3, -3, 1], [2, -5, 4, -1], [-1, 0, 1, 0], [0, 2, 0, 0]];
// Lecture 002 (002_5284cf65dc3cb6f3.txt): M_s = B^-1 A = 1/6 (1 4 1 0; -3 0 3 0; 3 -6 3 0; -1 3 -3 1).
const M_S_002 = [[1, 4, 1, 0], [-3, 0, 3, 0], [3, -6, 3, 0], [-1, 3, -3, 1]];
const transpose = (m) => m[0].map((_, j) => m.map((row) => row[j]));

// What the panel typesets for M: the factor in front (numerator, denominator) or null, and the
// entries of the first copy of M (the product line P(u) = [..] . M . G), row-major strings.
const shownM = (page) => page.evaluate(() => {
  const root = document.querySelector('.matrix-panel');
  const frac = root.querySelector('[data-matrix=M-fraction]');
  const m = root.querySelector('math [data-matrix=M]');
  return {
    notation: root.dataset.notation,
    fraction: frac && frac.localName === 'mfrac' ? [...frac.children].map((c) => c.textContent) : null,
    entries: [...m.querySelectorAll('mtr')].map((tr) => [...tr.querySelectorAll('mtd')].map((td) => td.textContent.trim())),
  };
});
const strings = (m) => m.map((row) => row.map(String));
// A neutral place to click so the keyboard goes to the page, as a person clicks the heading.
const focusPage = (page) => page.click('.matrix-heading');

test('uniform B-spline: f and the checkbox switch M between decimals and lecture 003\'s 1/6 [integers]', async () => {
  const page = await openCurves(env);
  await chooseFamily(page, 'bspline-uniform');
  let shown = await shownM(page);
  assert.equal(shown.notation, 'decimal');
  assert.equal(shown.fraction, null);
  assert.equal(shown.entries[0][0], '-0.1667', 'decimals by default (-1/6 to 4 digits)');

  await focusPage(page);
  await page.keyboard.press('f');
  await frame(page);
  assert.equal((await page.evaluate(() => window.wingspline.state)).notation, 'fraction');
  shown = await shownM(page);
  assert.equal(shown.notation, 'fraction');
  assert.deepEqual(shown.fraction, ['1', '6']);
  assert.deepEqual(shown.entries, strings(M_BSPLINE));
  assert.equal(await page.isChecked('#matrix-fractions'), true);

  // m steps through the forms: lecture 002's ascending form (M_s as 002 prints it), then
  // lecture 001's transposed form.
  await page.keyboard.press('m');
  await frame(page);
  assert.equal((await page.evaluate(() => window.wingspline.state)).form, 'ascending');
  shown = await shownM(page);
  assert.deepEqual(shown.fraction, ['1', '6']);
  assert.deepEqual(shown.entries, strings(M_S_002));
  await page.keyboard.press('m');
  await frame(page);
  shown = await shownM(page);
  assert.deepEqual(shown.fraction, ['1', '6']);
  assert.deepEqual(shown.entries, strings(transpose(M_BSPLINE)));
  assert.equal(await page.inputValue('#matrix-form'), 'transposed');

  // Undo takes back each form step, then the notation (each was one step).
  await page.click('[data-action=undo]');
  await frame(page);
  assert.deepEqual((await shownM(page)).entries, strings(M_S_002));
  await page.click('[data-action=undo]');
  await frame(page);
  assert.deepEqual((await shownM(page)).entries, strings(M_BSPLINE));
  // The form choice by pointer.
  await page.selectOption('#matrix-form', 'ascending');
  await frame(page);
  assert.deepEqual((await shownM(page)).entries, strings(M_S_002));
  await page.selectOption('#matrix-form', 'descending');
  await frame(page);

  // A non-uniform B-spline with an irrational interior knot: no small common denominator.
  await chooseFamily(page, 'bspline');
  const state = await page.evaluate(() => window.wingspline.state);
  assert.equal(state.points.length, 4, 'the four Bezier points are kept');
  // Degree 2 on 4 points: 7 knots, one interior knot at 0.3/sqrt 2, an irrational ratio of
  // the two spans, so M on the first span has no small common denominator.
  const knots = [0, 0, 0, 0.3 * Math.SQRT1_2, 1, 1, 1];
  const link = envelopeCode('curves', 3, { ...state, degree: 2, knots, u: 0.1 });
  const other = await env.openPage(`${env.site.url}curves.html#s=${link}`, { colorScheme: 'light' });
  await other.waitForSelector('body[data-ready=true]');
  await frame(other);
  shown = await shownM(other);
  assert.equal(shown.notation, 'decimal');
  assert.match(await other.textContent('.matrix-panel .hint'), /not fractions with a small common denominator/);
});

test('old links open as they did: version 1 without the notation, version 2 with the lecture-001 checkbox', async () => {
  const page = await openCurves(env);
  const { notation, form, ...rest } = await page.evaluate(() => window.wingspline.state);
  assert.equal(notation, 'decimal');
  assert.equal(form, 'descending');
  const open = async (version, state) => {
    const other = await env.openPage(`${env.site.url}curves.html#s=${envelopeCode('curves', version, state)}`, { colorScheme: 'light' });
    await other.waitForSelector('body[data-ready=true]');
    await frame(other);
    return other;
  };
  let other = await open(1, { ...rest, transposed: true });
  let state = await other.evaluate(() => window.wingspline.state);
  assert.equal(state.notation, 'decimal');
  assert.equal(state.form, 'transposed', 'the old checkbox becomes lecture 001\'s form');
  assert.equal('transposed' in state, false);
  assert.equal(await other.$eval('.matrix-panel', (m) => m.dataset.form), 'transposed');
  other = await open(2, { ...rest, notation: 'fraction', transposed: false });
  state = await other.evaluate(() => window.wingspline.state);
  assert.deepEqual([state.form, state.notation], ['descending', 'fraction']);
  // A tampered link: the checkbox is not true or false. That field is refused with a
  // message naming it, the default form shown, the rest of the link kept.
  other = await open(2, { ...rest, notation: 'fraction', transposed: 'yes' });
  state = await other.evaluate(() => window.wingspline.state);
  assert.equal(state.form, 'descending');
  assert.equal(state.notation, 'fraction', 'the rest is kept');
  assert.match(await other.evaluate(() => window.wingspline.message()), /form/);
  // ... and a version-3 link with a form the page does not know.
  other = await open(3, { ...rest, notation: 'decimal', form: 'upside-down' });
  assert.equal((await other.evaluate(() => window.wingspline.state)).form, 'descending');
  assert.match(await other.evaluate(() => window.wingspline.message()), /form/);
});

test('the notes say where the lectures disagree: 002\'s Catmull-Rom first row, 001\'s row and column T', async () => {
  const page = await openCurves(env);
  assert.equal(await page.isHidden('#notation-note'), true, 'Bezier in the default form: nothing to say');
  await chooseFamily(page, 'catmull-rom');
  const note = await page.textContent('#notation-note');
  assert.match(note, /Lecture 002 prints the first row of M_R as \(−1 3 −3 0\); lecture 003 has \(−1 3 −3 1\)/);
  assert.match(note, /computes lecture 003's matrix/);
  // ... and the first row shown is lecture 003's.
  await page.click('#matrix-fractions');
  await frame(page);
  assert.deepEqual((await shownM(page)).entries[0], ['-1', '3', '-3', '1']);
  await page.selectOption('#matrix-form', 'transposed');
  await frame(page);
  assert.match(await page.textContent('#notation-note'), /Lecture 001 writes T = \[t³ t² t 1\] as a row in Q\(t\) = T · C and as a column in G · M · T/);
  await chooseFamily(page, 'bezier');
  assert.doesNotMatch(await page.textContent('#notation-note'), /M_R/);
});

test('a cubic Bezier shows lecture 002\'s G_B^L and G_B^R = 1/8 [integers] with the construction', async () => {
  // Lecture 002 (002_5284cf65dc3cb6f3.txt), typed from the slide.
  const GL = [[8, 0, 0, 0], [4, 4, 0, 0], [2, 4, 2, 0], [1, 3, 3, 1]].map((r) => r.map(String));
  const GR = [[1, 3, 3, 1], [0, 2, 4, 2], [0, 0, 4, 4], [0, 0, 0, 8]].map((r) => r.map(String));
  const page = await openCurves(env);
  const read = (side) => page.$eval(`#subdivision-matrices [data-split=${side}]`, (m) => ({
    sub: m.querySelector('msubsup').textContent,
    fraction: [...m.querySelector('mfrac').children].map((c) => c.textContent),
    entries: [...m.querySelector('mfrac').nextElementSibling.querySelectorAll('mtr')].map((tr) => [...tr.querySelectorAll('mtd')].map((td) => td.textContent)),
  }));
  assert.equal(await page.isVisible('#subdivision-matrices'), true);
  assert.deepEqual(await read('L'), { sub: 'GBL', fraction: ['1', '8'], entries: GL });
  assert.deepEqual(await read('R'), { sub: 'GBR', fraction: ['1', '8'], entries: GR });
  assert.match(await page.textContent('#subdivision-matrices'), /de Casteljau construction at u = 1\/2/);
  await chooseFamily(page, 'catmull-rom');
  assert.equal(await page.isHidden('#subdivision-matrices'), true, 'only for the cubic Bezier');
});

test('each form names the geometry and the blending functions as its lecture does (typeset, not raw text)', async () => {
  // Typed from the lectures: 003 C = M_h G_h, G_h = [P1 P4 R1 R4], 000 H0..H3; 002
  // g = (p_0, p_3, p'_0, p'_3), b(u) = M_H^T u; 001 G_H = [P1 P4 R1 R4], Q(t) = G_H M_H T.
  const page = await openCurves(env);
  await chooseFamily(page, 'hermite');
  const names = () => page.$eval('.matrix-panel [data-role=lecture-names]', (root) => ({
    lecture: root.dataset.lecture,
    // every subscripted name as base + subscript, in order
    subs: [...root.querySelectorAll('msub')].map((s) => [...s.children].map((c) => c.textContent).join('_')),
    sups: [...root.querySelectorAll('msup')].map((s) => [...s.children]
      .map((c) => (c.localName === 'msub' ? [...c.children].map((x) => x.textContent).join('_') : c.textContent)).join('^')),
    raw: [...root.querySelectorAll('math')].map((m) => m.textContent).join(' '),
  }));
  let n = await names();
  assert.equal(n.lecture, '003');
  for (const name of ['M_h', 'G_h', 'P_1', 'P_4', 'R_1', 'R_4', 'H_0', 'H_1', 'H_2', 'H_3']) assert.ok(n.subs.includes(name), `${name} in ${n.subs}`);
  assert.doesNotMatch(n.raw, /[_^]/, 'no raw _ or ^');
  await page.selectOption('#matrix-form', 'ascending');
  await frame(page);
  n = await names();
  assert.equal(n.lecture, '002');
  for (const name of ['M_H', 'p_0', 'p_3', 'p′_0', 'p′_3']) assert.ok(n.subs.includes(name), `${name} in ${n.subs}`);
  assert.ok(n.sups.includes('M_H^T'), `b(u) = M_H^T u: ${n.sups}`);
  await page.selectOption('#matrix-form', 'transposed');
  await frame(page);
  n = await names();
  assert.equal(n.lecture, '001');
  for (const name of ['G_H', 'M_H', 'P_1', 'P_4', 'R_1', 'R_4']) assert.ok(n.subs.includes(name), `${name} in ${n.subs}`);
  // The uniform B-spline in 002's form: M_s and p_{i-2} .. p_{i+1}.
  await chooseFamily(page, 'bspline-uniform');
  await page.selectOption('#matrix-form', 'ascending');
  await frame(page);
  n = await names();
  for (const name of ['M_s', 'p_i−2', 'p_i−1', 'p_i', 'p_i+1']) assert.ok(n.subs.includes(name), `${name} in ${n.subs}`);
  // A Bezier curve of degree 5 is not a lecture's cubic: no names line.
  await chooseFamily(page, 'interpolation');
  assert.equal(await page.$('.matrix-panel [data-role=lecture-names]'), null);
});

test('a non-uniform B-spline that is its points\' Bezier curve says so (lecture 002), and only then', async () => {
  const page = await openCurves(env);
  assert.equal(await page.isHidden('#bezier-disguise-note'), true, 'Bezier itself: no note');
  await chooseFamily(page, 'bspline');
  const state = await page.evaluate(() => window.wingspline.state);
  assert.deepEqual(state.knots, [0, 0, 0, 0, 1, 1, 1, 1], 'four points of degree 3, clamped');
  assert.equal(await page.isVisible('#bezier-disguise-note'), true);
  assert.match(await page.textContent('#bezier-disguise-note'), /Bezier curve of its 4 points.*lecture 002/);
  // Five points, an interior knot: a B-spline of two segments, no note.
  const five = { ...state, points: [...state.points, [5, 1]], weights: [1, 1, 1, 1, 1], tangents: [...state.tangents, [1, 0]], knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1] };
  const other = await env.openPage(`${env.site.url}curves.html#s=${envelopeCode('curves', 3, five)}`, { colorScheme: 'light' });
  await other.waitForSelector('body[data-ready=true]');
  await frame(other);
  assert.equal((await other.evaluate(() => window.wingspline.state)).points.length, 5);
  assert.equal(await other.isHidden('#bezier-disguise-note'), true);
});
