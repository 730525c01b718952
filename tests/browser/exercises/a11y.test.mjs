// The exercise pages for everyone: axe finds no serious or critical violation on the
// gallery, on a lesson page playing an exercise of each kind (after a wrong check, with its
// feedback and marked cells, and with the worked answer shown), and in the authoring dialog,
// in the light and dark themes; every answer control has a name.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import { useSiteAndBrowser, trap } from '../../helpers/browser.mjs';
import { exerciseAt } from '../../helpers/exercise-levels.mjs';

const axeSource = fs.readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const env = useSiteAndBrowser();

async function audit(page) {
  await page.evaluate(axeSource);
  const result = await page.evaluate(() => window.axe.run(document, { resultTypes: ['violations'] }));
  return result.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.id} (${v.impact}): ${v.help} at ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`);
}

const ONE_PER_KIND = ['mesh-winged-edge-slide', 'mesh-walk-around-v2', 'continuity-classify-g1', 'curves-bernstein-half', 'curves-through-a-point',
  'mesh-edit-flip-e3', 'mesh-half-edge-table-lecture', 'mesh-half-edge-walk-around-v2'];

for (const scheme of ['light', 'dark']) {
  test(`axe (${scheme}): the gallery`, async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: scheme });
    const page = trap(await context.newPage());
    await page.goto(`${env.site.url}exercises.html`);
    await page.waitForSelector('body[data-ready="true"]');
    assert.deepEqual(await audit(page), []);
    assert.deepEqual(page.problems, []);
  });

  for (const id of ONE_PER_KIND) {
    test(`axe (${scheme}): ${id}, answered wrong, then with the worked answer`, async () => {
      const context = await env.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: scheme });
      const page = trap(await context.newPage());
      // At level worked (a copy of the gallery's exercise), so the worked answer is there to audit.
      await page.goto(`${env.site.url}${exerciseAt(id, { level: 'worked', hintAfter: 1 })}`);
      await page.waitForSelector('#exercise-panel');
      assert.deepEqual(await audit(page), [], 'as opened');
      // Every answer control has an accessible name.
      const unnamed = await page.evaluate(() => [...document.querySelectorAll('#exercise-panel input, #exercise-panel button, #exercise-panel select')]
        .filter((el) => !(el.labels?.length || el.getAttribute('aria-label') || el.textContent.trim())).map((el) => el.outerHTML.slice(0, 80)));
      assert.deepEqual(unnamed, []);
      const first = page.locator('#exercise-panel .exercise-grid input.cell:not([readonly])').first();
      if (await first.count()) await first.fill('q');
      if (await page.locator('#exercise-value').count()) await page.locator('#exercise-value').fill('0.2');
      if (await page.locator('#exercise-edge-1').count()) await page.locator('label[for="exercise-edge-1"]').click();
      if (await page.locator('#exercise-halfedge-1').count()) await page.locator('label[for="exercise-halfedge-1"]').click();
      await page.locator('#exercise-check').click();
      await page.locator('#exercise-show-worked').click();
      assert.deepEqual(await audit(page), [], 'after a check and the worked answer');
      assert.deepEqual(page.problems, []);
    });
  }

  test(`axe (${scheme}): the authoring dialog`, async () => {
    const context = await env.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: scheme });
    const page = trap(await context.newPage());
    await page.goto(`${env.site.url}continuity.html`);
    await page.waitForSelector('body[data-ready="true"]');
    await page.locator('[data-action="make-exercise"]').click();
    await page.waitForSelector('dialog.exercise-author[open]');
    assert.deepEqual(await audit(page), []);
    await page.locator('#author-kind').selectOption('property');
    assert.deepEqual(await audit(page), [], 'property fields');
    assert.deepEqual(page.problems, []);
  });
}
