// The HTML of a lesson page: the one frame web/templates/lesson.html with the lesson's id and
// title filled in. The build writes dist/<id>.html with it for every lesson of the registry;
// the browser tests write the test-only fixture lesson's page with it, so the fixture runs
// in exactly the frame the real lessons run in.
import fs from 'node:fs';
import path from 'node:path';
import { repoRoot } from './run.mjs';

const escapeHtml = (text) => String(text).replace(/[<>&"']/g, (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&#39;' })[c]);

// script: the page's entry script; the site's pages run their bundle (scripts/build.mjs), the
// test-only fixture its unbundled page.js.
export function lessonPage({ id, title, script = `js/lessons/${id}/page.js` }) {
  const frame = fs.readFileSync(path.join(repoRoot, 'web', 'templates', 'lesson.html'), 'utf8')
    .replace(/<!-- The frame of every lesson page\.[\s\S]*?-->\n/, '');
  return frame.replaceAll('{{id}}', escapeHtml(id)).replaceAll('{{title}}', escapeHtml(title)).replaceAll('{{script}}', escapeHtml(script));
}
