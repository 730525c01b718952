// The guides' Markdown converter (scripts/lib/markdown.mjs) on the constructs the docs use,
// each checked against the HTML it must give, written here by hand; everything that is text
// comes out escaped (raw HTML in a doc, a quote in a link); and the guide link rules
// (scripts/lib/guides.mjs): another guide's page, the repository for other files, nothing
// for a scheme that is not http(s).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { markdownToHtml, inline, slugOf } from '../../scripts/lib/markdown.mjs';
import { guideLink, guides, guidePages } from '../../scripts/lib/guides.mjs';
import { repoRoot } from '../helpers/browser.mjs';

const html = (md, options) => markdownToHtml(md, options).html;
const asIs = (t) => t;

test('headings carry GitHub\'s ids (punctuation dropped, spaces to hyphens, repeats numbered)', () => {
  assert.equal(slugOf('In a reveal.js slide'), 'in-a-revealjs-slide');
  assert.equal(slugOf('Options (in the fragment, `&`-separated, any order)'), 'options-in-the-fragment--separated-any-order');
  assert.equal(slugOf('A projector: presentation mode'), 'a-projector-presentation-mode');
  const out = markdownToHtml('# Title\n\n## Tests\n\n### `subdivide` kind\n\n## Tests\n');
  assert.equal(out.html, '<h1 id="title">Title</h1>\n<h2 id="tests">Tests</h2>\n<h3 id="subdivide-kind"><code>subdivide</code> kind</h3>\n<h2 id="tests-1">Tests</h2>');
  assert.equal(out.title, 'Title');
  assert.deepEqual(out.headings.map((h) => h.level), [1, 2, 3, 2]);
});

test('paragraphs join their lines; inline code, strong, emphasis and links', () => {
  assert.equal(html('One line\nand the next.\n\nAnother.'), '<p>One line and the next.</p>\n<p>Another.</p>');
  assert.equal(inline('**Export > Copy** then `a & b` and *before*', asIs),
    '<strong>Export &gt; Copy</strong> then <code>a &amp; b</code> and <em>before</em>');
  assert.equal(inline('see [embed.md](embed.md#tests), 2 * 3 = 6', asIs), 'see <a href="embed.md#tests">embed.md</a>, 2 * 3 = 6');
  assert.equal(inline('**bold with `code` inside**', asIs), '<strong>bold with <code>code</code> inside</strong>');
});

test('lists: items, continuation lines indented under an item, numbered lists', () => {
  assert.equal(html('- first\n  goes on\n- second\n\nAfter.'), '<ul><li>first goes on</li><li>second</li></ul>\n<p>After.</p>');
  assert.equal(html('1. Open it.\n2. Copy\n   the code.'), '<ol><li>Open it.</li><li>Copy the code.</li></ol>');
  assert.equal(html('- a\n\n- b'), '<ul><li>a</li><li>b</li></ul>', 'a blank line between items keeps one list');
});

test('fenced code: the text as it is, escaped, with its language; nothing inside is Markdown', () => {
  assert.equal(html('```html\n<iframe src="x.html#a=1&amp;b=2"></iframe>\n**not bold**\n```'),
    '<pre tabindex="0"><code class="language-html">&lt;iframe src=&quot;x.html#a=1&amp;amp;b=2&quot;&gt;&lt;/iframe&gt;\n**not bold**</code></pre>');
});

test('tables: header cells, rows, \\| inside a cell, inline Markdown in cells; a named, focusable scrolling box', () => {
  const out = html('| parameter | values |\n| --- | --- |\n| `theme` | `light` \\| `dark` |\n| `s` | the code |');
  assert.equal(out, '<div class="doc-table" tabindex="0" role="region" aria-label="Table 1: parameter, values"><table>'
    + '<thead><tr><th scope="col">parameter</th><th scope="col">values</th></tr></thead>'
    + '<tbody><tr><td><code>theme</code></td><td><code>light</code> | <code>dark</code></td></tr>'
    + '<tr><td><code>s</code></td><td>the code</td></tr></tbody></table></div>');
});

test('raw HTML and quotes in the text are text: no element, no attribute can come out of a doc', () => {
  const out = html('A <script>alert(1)</script> and <img src=x onerror=alert(1)>.\n\n[x](https://e.org/"onmouseover="alert(1))');
  assert.doesNotMatch(out, /<script|<img/);
  assert.match(out, /&lt;script&gt;alert\(1\)&lt;\/script&gt;/);
  // The link ends at its first ')' (as Markdown reads it); its quotes stay inside the href.
  assert.match(out, /<a href="https:\/\/e\.org\/&quot;onmouseover=&quot;alert\(1">x<\/a>\)/);
  assert.doesNotMatch(out, /<a [^>]*\sonmouseover=/);
});

test('guide links: another guide\'s page, the repository for other files, text only for other schemes', () => {
  const repo = 'https://example.org/owner/wingspline';
  assert.equal(guideLink('embed.md', repo), 'embed.html');
  assert.equal(guideLink('exercises.md#feedback-levels', repo), 'exercises.html#feedback-levels');
  assert.equal(guideLink('state-format.md', repo), `${repo}/blob/main/docs/state-format.md`);
  assert.equal(guideLink('../README.md#install', repo), `${repo}/blob/main/README.md#install`);
  assert.equal(guideLink('#tests', repo), '#tests');
  assert.equal(guideLink('https://docs.moodle.org/', repo), 'https://docs.moodle.org/');
  assert.equal(guideLink('javascript:alert(1)', repo), null);
  assert.equal(guideLink('state-format.md', null), null, 'without a repository: the text alone');
  assert.equal(guideLink('../../etc/passwd', repo), null, 'nothing outside the repository');
});

test('the built guides: one page per guide, titled by its doc\'s first heading, with every heading of the doc', () => {
  const pages = guidePages();
  assert.deepEqual(pages.map((p) => p.file), guides.map((g) => `guide/${g.name}.html`));
  for (const { file, html: page, title } of pages) {
    const name = path.basename(file, '.html');
    const source = fs.readFileSync(path.join(repoRoot, 'docs', `${name}.md`), 'utf8');
    assert.equal(title, source.split('\n')[0].replace(/^# /, ''));
    assert.match(page, new RegExp(`<title>${title.replace(/[()]/g, '\\$&')} · Wingspline</title>`));
    assert.doesNotMatch(page, /\{\{\w+\}\}/, 'every placeholder filled');
    assert.doesNotMatch(page, /<script(?![^>]*\bsrc="\.\.\/js\/pages\/guide\.js")/, 'no script but the page module');
    const headingLines = source.split('```').filter((_, k) => k % 2 === 0).join('').split('\n').filter((l) => /^#{1,6}\s/.test(l)).length;
    assert.equal((page.match(/<h[1-6] id=/g) ?? []).length, headingLines, `${file}: every heading of the doc`);
  }
});
