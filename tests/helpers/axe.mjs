// axe-core on a page as it is served: the serious and critical violations, one line each,
// and two that read wrongly to a screen reader although axe calls them minor or moderate: a
// role that overrides an element's own (a <math> made a region) and two regions with one name.
// axe is injected with page.evaluate(source), not page.addScriptTag: addScriptTag inserts an
// inline <script>, which the pages' CSP (script-src 'self') rightly refuses, and bypassCSP
// would audit a page with its policy switched off. Evaluation through the DevTools protocol is
// not subject to the page's CSP, so the audited page is the real one.
import fs from 'node:fs';
import { createRequire } from 'node:module';

const axeSource = fs.readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

export async function seriousViolations(page) {
  await page.evaluate(axeSource);
  const result = await page.evaluate(() => window.axe.run(document, { resultTypes: ['violations'] }));
  return result.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical' || ['aria-allowed-role', 'landmark-unique'].includes(v.id))
    .map((v) => `${v.id} (${v.impact}): ${v.help} at ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`);
}
