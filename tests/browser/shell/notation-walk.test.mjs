// Parentheses in P(u) no taller than a row, and no internal ids in
// headings: every lesson is walked as a person would (each family chosen in turn, each
// matrix form, each scene), and at every stop
//  - the brackets of a function application, P(u), Q(t), p(u, v), and of a row vector are
//    at most 1.5 x the line height of their formula (a non-stretchy bracket is about one
//    line high; a stretched one beside a 4-row matrix is well over 3), while the brackets of
//    the matrices themselves still stretch (more than 2.5 line heights for 4 rows);
//  - no visible heading, caption, summary, label, option or table header shows a family or
//    basis id of the lessons' schemas (bezier, bspline-uniform, catmull-rom, nubs, ...);
//  - no visible text outside the formulas has a raw "^" (C^(p-m) is typeset), and no
//    heading, caption or label a raw subscript "_" (the blending plot's N_i,3(u)).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { frame } from '../../helpers/curves-page.mjs';
import { FAMILY_IDS as CURVE_FAMILIES } from '../../../web/js/lessons/curves/families.js';
import { FAMILY_IDS as COMPARISON_FAMILIES } from '../../../web/js/lessons/comparison/families.js';
import { MATRIX_FORMS } from '../../../web/js/ui/matrix-forms.js';

const env = useSiteAndBrowser();

// Ids that are not English words (interpolation, cardinal are both an id and a word; the
// lectures' names are capitalised: Hermite, Bezier, B-spline, Catmull-Rom, NURBS).
const ENGLISH = new Set(['interpolation', 'cardinal']);
const IDS = [...new Set([...CURVE_FAMILIES, ...COMPARISON_FAMILIES, 'hermite', 'bezier', 'bspline', 'catmull-rom', 'nurbs'])]
  .filter((id) => !ENGLISH.has(id));
const LINE_FACTOR = 1.5;     // application / row-vector bracket height, in line heights
const STRETCHED_FACTOR = 2.5; // a 4-row matrix's bracket, at least, in line heights

// Measures every visible formula of the page. Line height: the computed one, or 1.2 em
// when it is 'normal' (CSS's usual value for 'normal').
function measure() {
  const lineOf = (node) => {
    const cs = getComputedStyle(node.closest('math'));
    const lh = parseFloat(cs.lineHeight);
    return Number.isFinite(lh) ? lh : 1.2 * parseFloat(cs.fontSize);
  };
  const visible = (node) => node.getClientRects().length > 0 && node.checkVisibility({ visibilityProperty: true });
  const isName = (node) => node && ['mi', 'msub', 'msup', 'msubsup'].includes(node.localName);
  const rowTable = (node) => node && node.localName === 'mtable' && node.querySelectorAll(':scope > mtr').length === 1;
  const tallTable = (node) => node && node.localName === 'mtable' && node.querySelectorAll(':scope > mtr').length >= 4;
  const text = (node) => node.textContent.trim();
  const out = { fixed: [], stretched: [] };
  for (const math of document.querySelectorAll('math')) {
    if (!visible(math)) continue;
    for (const mo of math.querySelectorAll('mo')) {
      const t = text(mo);
      const line = lineOf(mo);
      const height = mo.getBoundingClientRect().height / line;
      const where = `${text(math).slice(0, 40)} | ${t}`;
      const prev = mo.previousElementSibling;
      const next = mo.nextElementSibling;
      // "(" after a name, and the ")" that closes it: function application.
      let application = t === '(' && isName(prev);
      if (t === ')') {
        let open = prev;
        for (let depth = 0; open; open = open.previousElementSibling) {
          if (open.localName === 'mo' && text(open) === ')') depth += 1;
          if (open.localName === 'mo' && text(open) === '(') { if (depth === 0) break; depth -= 1; }
        }
        application = Boolean(open && isName(open.previousElementSibling));
      }
      const rowVector = ('([').includes(t) && rowTable(next) || (')]').includes(t) && rowTable(prev);
      if (application || rowVector) out.fixed.push({ where, height });
      else if (('([').includes(t) && tallTable(next)) out.stretched.push({ where, height });
    }
  }
  return out;
}

function ids() {
  const found = [];
  const selector = 'h1, h2, h3, h4, h5, h6, summary, caption, figcaption, legend, label, th, option, .matrix-heading, [role=heading]';
  for (const node of document.querySelectorAll(selector)) {
    const select = node.closest('select');
    const shown = node.localName === 'option' ? select && select.getClientRects().length > 0 && select.checkVisibility() : node.getClientRects().length > 0 && node.checkVisibility();
    if (shown) found.push(node.localName === 'option' ? node.textContent : node.innerText);
  }
  return found;
}

// Visible text nodes outside MathML that hold a raw '^'.
function carets() {
  const found = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const parent = node.parentElement;
    if (!node.data.includes('^') || !parent || parent.closest('math, script, style, textarea, [hidden]')) continue;
    if (parent.getClientRects().length > 0 && parent.checkVisibility({ visibilityProperty: true })) found.push(node.data.trim().slice(0, 80));
  }
  return found;
}

async function check(page, stop, tally) {
  const raw = await page.evaluate(carets);
  assert.deepEqual(raw, [], `${stop}: raw "^" in visible text`);
  const m = await page.evaluate(measure);
  for (const f of m.fixed) assert.ok(f.height <= LINE_FACTOR, `${stop}: "${f.where}" is ${f.height.toFixed(2)} line heights (at most ${LINE_FACTOR})`);
  for (const s of m.stretched) assert.ok(s.height >= STRETCHED_FACTOR, `${stop}: the matrix bracket "${s.where}" should stretch (${s.height.toFixed(2)} line heights)`);
  tally.fixed += m.fixed.length;
  tally.stretched += m.stretched.length;
  for (const text of await page.evaluate(ids)) {
    // A subscript written as raw text ("N_i,3(u)") in a heading, caption or label.
    assert.doesNotMatch(text, /[A-Za-z]_[A-Za-z0-9{]/, `${stop}: raw "_" in the heading/label "${text}"`);
    for (const id of IDS) {
      const re = new RegExp(`(?<![\\w-])${id.replace('-', '\\-')}(?![\\w-])`);
      assert.doesNotMatch(text, re, `${stop}: the heading/label "${text}" shows the internal id "${id}"`);
    }
  }
}

async function open(name) {
  const page = await env.openPage(`${env.site.url}${name}.html`, { colorScheme: 'light', viewport: { width: 1280, height: 720 } });
  await page.evaluate(() => localStorage.clear());
  await page.goto(`${env.site.url}${name}.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await frame(page);
  return page;
}

test('curve explorer: every family in every matrix form', async () => {
  const page = await open('curves');
  const tally = { fixed: 0, stretched: 0 };
  for (const family of CURVE_FAMILIES) {
    await page.selectOption('#curve-family', family);
    for (const form of MATRIX_FORMS) {
      await page.selectOption('#matrix-form', form);
      await frame(page);
      await check(page, `curves ${family} ${form}`, tally);
    }
  }
  // P(u), the row vector and the value line in every stop; the 4-row matrices stretch.
  assert.ok(tally.fixed >= CURVE_FAMILIES.length * MATRIX_FORMS.length * 6, `application brackets measured: ${tally.fixed}`);
  assert.ok(tally.stretched >= CURVE_FAMILIES.length * MATRIX_FORMS.length, `matrix brackets measured: ${tally.stretched}`);
});

test('comparison lab: each scene, the conversion panels in every form', async () => {
  const page = await open('comparison');
  const tally = { fixed: 0, stretched: 0 };
  for (const scene of await page.$$eval('#scene option', (o) => o.map((x) => x.value))) {
    await page.selectOption('#scene', scene);
    await frame(page);
    await check(page, `comparison ${scene}`, tally);
  }
  await page.selectOption('#scene', 'conversion');
  for (const mode of ['keep-curve', 'keep-geometry']) {
    await page.selectOption('#conv-mode', mode);
    for (const form of MATRIX_FORMS) {
      await page.selectOption('#conv-form', form);
      await frame(page);
      await check(page, `comparison conversion ${mode} ${form}`, tally);
    }
  }
  assert.ok(tally.fixed > 0 && tally.stretched > 0, JSON.stringify(tally));
});

test('surfaces, continuity, subdivision and mesh: their formulas and headings', async () => {
  for (const name of ['surfaces', 'continuity', 'subdivision', 'mesh']) {
    const page = await open(name);
    const tally = { fixed: 0, stretched: 0 };
    await check(page, name, tally);
    for (const select of await page.$$eval('select', (all) => all.filter((s) => s.getClientRects().length > 0 && s.id).map((s) => s.id))) {
      // (a disabled placeholder such as the continuity lab's "your own points" is no choice)
      for (const value of await page.$$eval(`#${select} option`, (o) => o.filter((x) => !x.disabled).map((x) => x.value))) {
        if (!(await page.isVisible(`#${select}`)) || !(await page.isEnabled(`#${select}`))) break;
        await page.selectOption(`#${select}`, value);
        await frame(page);
        await check(page, `${name} #${select}=${value}`, tally);
      }
    }
  }
});
