// The guide pages of the site: dist/guide/<name>.html from docs/<name>.md for the docs a
// newcomer needs (how to use it in class, how to embed it, how to set homework), in the frame
// web/templates/guide.html. The landing page points to them. A link to another built guide
// goes to its page; a link to any other file of the repository goes to that file in the
// repository (package.json "repository"), so the pages have no broken links; other links stay
// as written when they are http(s) or in-page anchors, and become plain text otherwise.
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot } from './run.mjs';
import { markdownToHtml, escapeHtml } from './markdown.mjs';

// name (docs/<name>.md, dist/guide/<name>.html) and the short title of the guides' menu.
export const guides = [
  { name: 'classroom', label: 'In the classroom' },
  { name: 'embed', label: 'Embedding in slides and course pages' },
  { name: 'exercises', label: 'Exercises and homework' },
];

// The repository's web address (https://host/owner/name) from package.json, or null.
function repositoryUrl() {
  const pkg = JSON.parse(fs.readFileSync(path.join(repoRoot, 'package.json'), 'utf8'));
  const url = typeof pkg.repository === 'string' ? pkg.repository : pkg.repository?.url;
  return url ? url.replace(/^git\+/, '').replace(/\.git$/, '') : null;
}

/**
 * Where a doc's link goes on its guide page.
 * @param {string} target the link as written in docs/<name>.md
 * @param {string | null} repo the repository's web address
 */
export function guideLink(target, repo) {
  if (/^https?:\/\//i.test(target) || target.startsWith('#')) return target;
  if (/^[a-z][a-z0-9+.-]*:/i.test(target)) return null; // mailto:, javascript: and the like: text only
  const [file, anchor] = target.split('#');
  const built = guides.find((g) => file === `${g.name}.md`);
  if (built) return `${built.name}.html${anchor ? `#${anchor}` : ''}`;
  if (!repo) return null;
  // A file beside the docs (docs/x.md) or above them (../README.md), in the repository.
  const inRepo = path.posix.normalize(path.posix.join('docs', file));
  if (inRepo.startsWith('..')) return null;
  return `${repo}/blob/main/${inRepo}${anchor ? `#${anchor}` : ''}`;
}

/** The guide pages: [{ file: 'guide/<name>.html', html, title }]. */
export function guidePages() {
  const frame = fs.readFileSync(path.join(repoRoot, 'web', 'templates', 'guide.html'), 'utf8')
    .replace(/<!-- The frame of every guide page\.[\s\S]*?-->\n/, '');
  const repo = repositoryUrl();
  return guides.map(({ name }) => {
    const source = fs.readFileSync(path.join(repoRoot, 'docs', `${name}.md`), 'utf8');
    const { html, title } = markdownToHtml(source, { link: (target) => guideLink(target, repo) });
    const nav = guides.map((g) => (g.name === name
      ? `<a href="${g.name}.html" aria-current="page">${escapeHtml(g.label)}</a>`
      : `<a href="${g.name}.html">${escapeHtml(g.label)}</a>`)).join(' ');
    // Filled in one pass, so nothing in a doc's text can be read as another placeholder.
    const values = { title: escapeHtml(title), name: escapeHtml(name), nav, body: html };
    return { file: `guide/${name}.html`, title, html: frame.replace(/\{\{(title|name|nav|body)\}\}/g, (_, key) => values[key]) };
  });
}
