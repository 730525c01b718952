import { chromium } from 'playwright-core';
import { createStaticServer, listen } from './lib/static-server.mjs';
const { url } = await listen(createStaticServer(new URL('../dist', import.meta.url).pathname, {}));
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox'] });
for (const [name, vw, vh, present] of [['1920p', 1920, 1080, true], ['1280', 1280, 720, false], ['phone', 390, 844, false]]) {
  const ctx = await browser.newContext({ viewport: { width: vw, height: vh }, hasTouch: name === 'phone', isMobile: name === 'phone' });
  const page = await ctx.newPage();
  await page.goto(`${url}mesh.html`);
  await page.waitForSelector('body[data-ready=true]');
  const p = await page.evaluate(() => { const m = window.wingspline.model; const s = m.we.edges[16], t = m.we.edges[17]; return window.wingspline.toClient(m.projected[3*s] + (m.projected[3*t]-m.projected[3*s])/3, m.projected[3*s+1] + (m.projected[3*t+1]-m.projected[3*s+1])/3); });
  await page.mouse.click(p.x, p.y);
  await page.click('button[data-op="split-edge"]');
  await page.waitForTimeout(300);
  await page.click('#edit-restart'); await page.click('#edit-next'); await page.click('#edit-next'); await page.click('#edit-next');
  if (present) await page.keyboard.press('p').catch(() => {});
  await page.waitForTimeout(400);
  await page.screenshot({ path: `/tmp/shots/mesh-${name}.png` });
  await page.evaluate(() => document.querySelector('#edit-panel').scrollIntoView());
  await page.waitForTimeout(200);
  await page.screenshot({ path: `/tmp/shots/mesh-${name}-panel.png` });
  await ctx.close();
}
await browser.close();
process.exit(0);
