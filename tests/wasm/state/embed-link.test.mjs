// The embed parameters of a link (docs/embed.md) and the iframe snippet, in Node
// over the real module (web/js/app/share-link.js). Property: for thousands of seeded
// fragments of random parameters and values (hostile text included), readEmbedOptions
// either says "not an embed" (no embed key) or returns only known values (theme light,
// dark or null; panels valid ids, at most EMBED_MAX_PANELS, no repeats) and one sentence per
// value it could not use; the snippet's src and title read back (by an independent HTML
// attribute reader) exactly as given, whatever characters they hold.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readEmbedOptions, embedProblemsText, embedUrl, embedSnippet, EMBED_MAX_PANELS } from '../../../web/js/app/share-link.js';
import { random as seededRandom } from '../../helpers/seeded-random.mjs';

const CASES = 5000;

test('the embed flag: absent is the full app; every parameter is read or named', () => {
  assert.equal(readEmbedOptions('#s=abc'), null);
  assert.equal(readEmbedOptions(''), null);
  assert.deepEqual(readEmbedOptions('#embed=1&s=abc&theme=dark&present=1&panels=panel-matrix,panel-knots'),
    { panels: ['panel-matrix', 'panel-knots'], theme: 'dark', present: true, controls: false, problems: [] });
  const bad = readEmbedOptions('embed=yes&theme=purple&present=2&controls=0&panels=Bad!');
  assert.deepEqual([bad.theme, bad.present, bad.controls, bad.panels], [null, false, false, []]);
  assert.equal(bad.problems.length, 5);
  for (const [p, name] of bad.problems.map((p, i) => [p, ['embed', 'present', 'controls', 'theme', 'panels'][i]])) assert.match(p, new RegExp(`^${name}`));
  const text = embedProblemsText(bad.problems);
  assert.match(text, /^This embed link's embed, present, controls, theme, panels settings were not understood \(embed="yes" is not understood/);
  assert.equal(embedProblemsText(['theme="x" is not light or dark']), 'This embed link\'s theme="x" is not light or dark; the lesson opens without it.');
  assert.equal(embedProblemsText([]), null);
});

test(`${CASES} seeded random fragments: only known values come out, every other value is named`, () => {
  const random = seededRandom(19);
  const pick = (list) => list[Math.floor(random() * list.length)];
  const words = ['1', '0', 'yes', 'light', 'dark', 'system', '', 'panel-matrix', 'a,b,c', '<img src=x onerror=1>', '__proto__', 'x'.repeat(300), 'é"\'&', 'A-b', 'a'.repeat(41)];
  for (let i = 0; i < CASES; i += 1) {
    const params = new URLSearchParams();
    const n = Math.floor(random() * 6);
    for (let k = 0; k < n; k += 1) params.append(pick(['embed', 'theme', 'present', 'controls', 'panels', 's', 'other']), Array.from({ length: 1 + Math.floor(random() * 3) }, () => pick(words)).join(pick([',', '', ' '])));
    const out = readEmbedOptions(`#${params}`);
    if (!params.has('embed')) { assert.equal(out, null); continue; }
    assert.ok(out.theme === null || out.theme === 'light' || out.theme === 'dark');
    assert.equal(typeof out.present, 'boolean');
    assert.ok(out.panels.length <= EMBED_MAX_PANELS && new Set(out.panels).size === out.panels.length);
    for (const id of out.panels) assert.match(id, /^[a-z][a-z0-9-]{0,39}$/);
    assert.equal(out.present, params.get('present') === '1');
    if (params.has('theme') && out.theme === null) assert.ok(out.problems.some((p) => p.startsWith('theme=')), 'a refused theme is named');
    for (const p of out.problems) assert.ok(p.length < 120 && !p.includes('\n'), `one short sentence: ${p}`);
    const text = embedProblemsText(out.problems);
    if (text) assert.ok(text.length <= 300);
  }
});

// An HTML attribute reader written apart from the page's escaper: the value between the
// quotes, character references &amp; &quot; &lt; &gt; &#39; decoded.
function attribute(html, name) {
  const m = html.match(new RegExp(`\\s${name}="([^"]*)"`));
  assert.ok(m, `${name} is a double-quoted attribute`);
  return m[1].replace(/&(amp|quot|lt|gt|#39);/g, (_, e) => ({ amp: '&', quot: '"', lt: '<', gt: '>', '#39': "'" })[e]);
}

test('the snippet: src and title read back exactly, whatever they hold', () => {
  const src = embedUrl('https://example.org/site/curves.html?x="1"&y=<2>#s=abc_-9');
  assert.equal(src, 'https://example.org/site/curves.html?x=%221%22&y=%3C2%3E#embed=1&s=abc_-9');
  const titles = ['Curve explorer', 'Tom & "Jerry" <b>', "it's"];
  for (const title of titles) {
    const snippet = embedSnippet(src, title);
    assert.match(snippet, /^<iframe src="[^"]*" width="800" height="500" title="[^"]*" loading="lazy" style="border:0"><\/iframe>$/);
    assert.equal(attribute(snippet, 'src'), src);
    assert.equal(attribute(snippet, 'title'), `${title} (Wingspline)`);
  }
  assert.equal(embedUrl('https://example.org/mesh.html'), 'https://example.org/mesh.html#embed=1');
});
