// The winged-edge walk on a 390x844 phone, stepped with a finger. The tables are
// far below the walk's buttons there, so the row the walk reads is shown under the
// narration: at every step of both walks it is on screen, it is the same row as the edge,
// vertex or face table's highlighted one (same cells, same cell read), and stepping moves
// neither the page nor the Step button under the finger. Failed before: no such row; the
// highlighted row was 1,500 px below the Step button.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();
const PHONE = { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true };

test('phone: the row the walk reads is on screen under the narration at every step', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html`, PHONE);
  const stepButton = page.getByRole('button', { name: 'Step forward (→ or PageDown)' });
  for (const [kind, element] of [['vertex', '2'], ['face', '3']]) {
    await page.selectOption('#walk-kind', kind);
    await page.fill('#walk-element', element);
    await page.press('#walk-element', 'Enter');
    await page.waitForFunction((k) => window.wingspline.state.walk === k && window.wingspline.state.step === 0, kind);
    await page.getByRole('group', { name: 'Walk player' }).evaluate((el) => el.scrollIntoView({ block: 'start' }));
    const steps = await page.evaluate(() => window.wingspline.model.frames.length);
    let before = null;
    for (let step = 0; step < steps; step += 1) {
      if (step > 0) await stepButton.tap();
      await page.waitForFunction((s) => window.wingspline.state.step === s, step);
      await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
      const seen = await page.evaluate(() => {
        const mini = document.querySelector('#walk-row tr.is-highlighted');
        const big = document.querySelector('#tabpanel-winged tr.is-highlighted');
        const r = mini?.getBoundingClientRect();
        const cells = (row) => [...row.children].map((c) => c.textContent.trim());
        const readAt = (row) => [...row.children].findIndex((c) => c.classList.contains('is-read'));
        const button = document.querySelector('.walk-controls [title^="Step forward"]').getBoundingClientRect();
        return { inside: Boolean(r) && r.top >= 0 && r.bottom <= innerHeight && r.height > 0, mini: mini && cells(mini), big: big && cells(big),
          miniRead: mini && readAt(mini), bigRead: big && readAt(big), scrollY, buttonTop: button.top };
      });
      assert.ok(seen.inside, `${kind} walk, step ${step}: the row the walk reads is on screen`);
      assert.deepEqual(seen.mini, seen.big, `${kind} walk, step ${step}: the same row as the table's`);
      assert.equal(seen.miniRead, seen.bigRead, `${kind} walk, step ${step}: the same cell read`);
      if (before) {
        assert.equal(seen.scrollY, before.scrollY, 'stepping does not scroll the page');
        assert.ok(Math.abs(seen.buttonTop - before.buttonTop) < 1, 'the Step button stays under the finger');
      }
      before = seen;
    }
  }
  await screenshot(page, 'mesh-walk-phone'); // a full-page shot resizes the page: last
  assert.deepEqual(page.problems, []);
});

test('wide screens show the tables beside the walk, not the extra row', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html`, { viewport: { width: 1280, height: 800 } });
  assert.equal(await page.locator('#walk-row').isVisible(), false);
  assert.ok(await page.locator('#tabpanel-winged tr.is-highlighted').isVisible());
});

// A finger on the canvas scrolls the page (shell/touch.test.mjs), so on a phone the 3D view
// turns with its turn and tilt sliders (by finger or keys). Failed before: nothing on a
// phone turned the mesh lesson's 3D view once one finger scrolled the page.
test('phone: the 3D view turns and tilts with its sliders', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html`, PHONE);
  assert.equal(await page.locator('#view-turn').isDisabled(), true, 'the turn slider is off in 2D');
  await page.locator('#toggle-3d').tap();
  await page.waitForFunction(() => window.wingspline.state.mode3d);
  // The sliders are enabled when the panels show the 3D state (the next frame).
  await page.waitForFunction(() => !document.getElementById('view-turn').disabled && !document.getElementById('view-tilt').disabled);
  const before = await page.evaluate(() => ({ rotation: window.wingspline.state.rotation, p: Array.from(window.wingspline.model.projected.slice(0, 6)) }));
  await page.locator('#view-turn').focus();
  for (let i = 0; i < 20; i += 1) await page.keyboard.press('ArrowRight');
  await page.locator('#view-tilt').focus();
  for (let i = 0; i < 10; i += 1) await page.keyboard.press('ArrowLeft');
  const after = await page.evaluate(() => ({ rotation: window.wingspline.state.rotation, p: Array.from(window.wingspline.model.projected.slice(0, 6)) }));
  assert.ok(Math.abs(after.rotation.yaw - before.rotation.yaw - 0.2) < 1e-9, `turned by 20 steps of 0.01 rad (${after.rotation.yaw - before.rotation.yaw})`);
  assert.ok(Math.abs(after.rotation.pitch - before.rotation.pitch + 0.1) < 1e-9, `tilted by -0.1 rad (${after.rotation.pitch - before.rotation.pitch})`);
  assert.ok(after.p.some((x, i) => Math.abs(x - before.p[i]) > 1e-3), 'the projected mesh moved');
  assert.deepEqual(page.problems, []);
});
