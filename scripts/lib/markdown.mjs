// The Markdown of the project's own guides (docs/classroom.md, docs/embed.md,
// docs/exercises.md) as HTML, for the pages the build adds to the site (scripts/lib/guides.mjs).
// The subset those files use, and nothing more: ATX headings (#..####, each with a GitHub-style
// id so the docs' anchors work), paragraphs, flat lists (- or 1.; a line indented under an item
// continues it), fenced code blocks, pipe tables (\| a pipe inside a cell), and inline code,
// **strong**, *emphasis*, [links](target). Every character of the text is escaped: raw HTML in
// a doc shows as text (the docs only write HTML inside code), so the pages keep their strict
// CSP with nothing that could run.
//
// Decision: written here rather than a dependency (markdown-it, marked): the subset is about
// a hundred and fifty lines with its tests (tests/scripts/markdown.test.mjs), it escapes
// everything by construction, where a full converter passes raw HTML through unless configured
// not to, and the build gains no package to keep up to date.

export const escapeHtml = (text) => String(text).replace(/[<>&"']/g, (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&#39;' })[c]);

/**
 * A heading's id as GitHub makes it: lower case, punctuation dropped, spaces to hyphens.
 * @param {string} text the heading's text (inline Markdown removed)
 */
export function slugOf(text) {
  return text.toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, '').trim().replace(/\s/g, '-');
}

// Inline Markdown without its marks (for ids and labels).
const plain = (text) => text.replace(/`([^`]*)`/g, '$1').replace(/\*\*([^*]+)\*\*/g, '$1').replace(/\*([^*]+)\*/g, '$1')
  .replace(/\[([^\]]*)\]\([^)]*\)/g, '$1');

/**
 * Inline Markdown to HTML. `link(target)` says where a link goes (null: the text alone).
 * @param {string} text
 * @param {(target: string) => string | null} link
 */
export function inline(text, link) {
  let out = '';
  let rest = text;
  const patterns = [
    { re: /^`([^`]+)`/, html: (m) => `<code>${escapeHtml(m[1])}</code>` },
    { re: /^\*\*(.+?)\*\*/, html: (m) => `<strong>${inline(m[1], link)}</strong>` },
    { re: /^\*([^*\s][^*]*?)\*/, html: (m) => `<em>${inline(m[1], link)}</em>` },
    { re: /^\[([^\]]+)\]\(([^)\s]+)\)/, html: (m) => {
      const href = link(m[2]);
      return href === null ? inline(m[1], link) : `<a href="${escapeHtml(href)}">${inline(m[1], link)}</a>`;
    } },
  ];
  while (rest.length) {
    const hit = /[`*[]/.exec(rest);
    if (!hit) { out += escapeHtml(rest); break; }
    out += escapeHtml(rest.slice(0, hit.index));
    rest = rest.slice(hit.index);
    const found = patterns.map((p) => ({ p, m: p.re.exec(rest) })).find((x) => x.m);
    if (found) {
      out += found.p.html(found.m);
      rest = rest.slice(found.m[0].length);
    } else {
      out += escapeHtml(rest[0]);
      rest = rest.slice(1);
    }
  }
  return out;
}

// A table row's cells: split on | that is not written \|.
const cellsOf = (line) => line.trim().replace(/^\|/, '').replace(/\|$/, '').split(/(?<!\\)\|/).map((c) => c.trim().replace(/\\\|/g, '|'));
const isTableRule = (line) => /^\s*\|?\s*:?-{3,}:?\s*(\|\s*:?-{3,}:?\s*)*\|?\s*$/.test(line);

/**
 * A Markdown document to HTML, and its headings ({ level, text, id }) and first heading.
 * @param {string} source
 * @param {{ link?: (target: string) => string | null }} [options] where links go (default: as written)
 */
export function markdownToHtml(source, { link = (target) => target } = {}) {
  const lines = source.replace(/\r\n?/g, '\n').split('\n');
  const out = [];
  const headings = [];
  const ids = new Map();
  let tables = 0;
  let i = 0;
  const text = (t) => inline(t, link);
  while (i < lines.length) {
    const line = lines[i];
    if (!line.trim()) { i += 1; continue; }
    const fence = /^(`{3,})\s*([\w-]*)\s*$/.exec(line);
    if (fence) {
      const body = [];
      i += 1;
      while (i < lines.length && !lines[i].startsWith(fence[1])) body.push(lines[i++]);
      i += 1; // the closing fence (or the end of the file)
      const lang = fence[2] ? ` class="language-${escapeHtml(fence[2])}"` : '';
      // A code block may be wider than a phone: it scrolls, so it takes the focus (keyboard users scroll it).
      out.push(`<pre tabindex="0"><code${lang}>${escapeHtml(body.join('\n'))}</code></pre>`);
      continue;
    }
    const heading = /^(#{1,6})\s+(.*?)\s*#*\s*$/.exec(line);
    if (heading) {
      const level = heading[1].length;
      const title = plain(heading[2]);
      let id = slugOf(title);
      const seen = ids.get(id) ?? 0;
      ids.set(id, seen + 1);
      if (seen) id = `${id}-${seen}`;
      headings.push({ level, text: title, id });
      out.push(`<h${level} id="${escapeHtml(id)}">${text(heading[2])}</h${level}>`);
      i += 1;
      continue;
    }
    if (line.trimStart().startsWith('|') && i + 1 < lines.length && isTableRule(lines[i + 1])) {
      const head = cellsOf(line);
      i += 2;
      const rows = [];
      while (i < lines.length && lines[i].trimStart().startsWith('|')) rows.push(cellsOf(lines[i++]));
      tables += 1;
      // Wide tables scroll sideways in their own box: focusable, and named by their columns.
      const label = `Table ${tables}: ${head.map(plain).join(', ')}`;
      out.push(`<div class="doc-table" tabindex="0" role="region" aria-label="${escapeHtml(label)}"><table>`
        + `<thead><tr>${head.map((c) => `<th scope="col">${text(c)}</th>`).join('')}</tr></thead>`
        + `<tbody>${rows.map((r) => `<tr>${head.map((_, k) => `<td>${text(r[k] ?? '')}</td>`).join('')}</tr>`).join('')}</tbody>`
        + '</table></div>');
      continue;
    }
    const item = /^([-*]|\d+\.)\s+(.*)$/.exec(line);
    if (item) {
      const ordered = /\d/.test(item[1]);
      const items = [];
      while (i < lines.length) {
        const m = /^([-*]|\d+\.)\s+(.*)$/.exec(lines[i]);
        if (m && /\d/.test(m[1]) === ordered) {
          items.push(m[2]);
          i += 1;
        } else if (items.length && /^\s+\S/.test(lines[i])) {
          items[items.length - 1] += ` ${lines[i].trim()}`; // a continuation line of the item
          i += 1;
        } else if (!lines[i].trim() && i + 1 < lines.length && /^([-*]|\d+\.)\s+/.test(lines[i + 1])
          && /\d/.test(/^([-*]|\d+\.)/.exec(lines[i + 1])[1]) === ordered) {
          i += 1; // a blank line between items of one list
        } else {
          break;
        }
      }
      const tag = ordered ? 'ol' : 'ul';
      out.push(`<${tag}>${items.map((t) => `<li>${text(t)}</li>`).join('')}</${tag}>`);
      continue;
    }
    // A paragraph: up to a blank line or the start of another block.
    const para = [];
    while (i < lines.length && lines[i].trim() && !/^(#{1,6}\s|`{3,}|([-*]|\d+\.)\s)/.test(lines[i])
      && !(lines[i].trimStart().startsWith('|') && i + 1 < lines.length && isTableRule(lines[i + 1]))) {
      para.push(lines[i].trim());
      i += 1;
    }
    out.push(`<p>${text(para.join(' '))}</p>`);
  }
  return { html: out.join('\n'), headings, title: headings[0]?.text ?? '' };
}
