// The curve explorer driven as a person does, shared by tests/browser/curves/*.test.mjs.
import assert from 'node:assert/strict';

// Two animation frames: whatever the last input changed has been drawn.
export const frame = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

// The curve explorer in a light-theme page with nothing saved: ready and drawn. `env` is
// useSiteAndBrowser's (its page closes after the test).
export async function openCurves(env) {
  const page = await env.openPage(`${env.site.url}curves.html`, { colorScheme: 'light' });
  await page.evaluate(() => localStorage.clear());
  await page.goto(`${env.site.url}curves.html`);
  await page.waitForSelector('body[data-ready=true]');
  await frame(page);
  return page;
}

export async function chooseFamily(page, family) {
  await page.selectOption('#curve-family', family);
  await frame(page);
  assert.equal((await page.evaluate(() => window.wingspline.state)).family, family);
}

// The NURBS family with its exact-circle preset, drawn.
export async function circlePreset(page) {
  await chooseFamily(page, 'nurbs');
  await page.click('[data-action=circle-preset]');
  await frame(page);
}
