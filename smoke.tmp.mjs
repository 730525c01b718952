import { startSite, launchBrowser, openPage, screenshot } from './tests/helpers/browser.mjs';
const site = await startSite(); const browser = await launchBrowser();
for (const id of process.argv.slice(2)) {
  const page = await openPage(browser, `${site.url}${id}.html`);
  await page.waitForSelector('body[data-ready]', { timeout: 10000 }).catch(() => {});
  await page.waitForTimeout(500);
  console.log(id, await page.getAttribute('body', 'data-ready'), page.problems, await page.evaluate(() => window.wingspline?.message()));
  await screenshot(page, `smoke-${id}`);
  await page.context().close();
}
await browser.close(); await site.close();
