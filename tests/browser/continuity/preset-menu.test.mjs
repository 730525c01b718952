// The continuity lab's Preset menu, every entry chosen with the keyboard and the pointer.
// Its first entry, "your own points", names no preset: it is shown (disabled) while the
// points are a person's own (an exercise's, a file's, a link's), and can never be chosen,
// so choosing it once threw on the missing preset. Every preset entry loads that preset.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';

const env = useSiteAndBrowser();
const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

async function openLab(hash = '') {
  const page = await env.openPage(`${env.site.url}continuity.html${hash}`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  return page;
}
const menu = (page) => page.$$eval('#preset option', (options) => options.map((o) => ({ value: o.value, text: o.textContent, disabled: o.disabled, hidden: o.hidden })));
const shown = (page) => page.evaluate(() => {
  const select = document.querySelector('#preset');
  return { value: select.value, text: select.selectedOptions[0]?.textContent ?? null, preset: window.wingspline.state.preset };
});

test('every Preset entry chosen with the keyboard: each loads its preset, none throws', async () => {
  const page = await openLab();
  const entries = await menu(page);
  const presets = entries.filter((o) => o.value !== '');
  assert.ok(presets.length >= 5, 'the lab has its presets');
  assert.deepEqual(entries.filter((o) => o.value === '').map((o) => o.text), ['your own points']);
  await page.focus('#preset');
  // Home, then down through every entry and past the end; End, then up past the top.
  const seen = new Set();
  for (const key of ['Home', ...entries.map(() => 'ArrowDown'), 'ArrowDown', 'End', ...entries.map(() => 'ArrowUp'), 'ArrowUp']) {
    await page.keyboard.press(key);
    await settle(page);
    const now = await shown(page);
    assert.notEqual(now.value, '', `${key}: "your own points" is not chosen`);
    assert.equal(now.preset, now.value, `${key}: the state holds the preset shown`);
    seen.add(now.value);
  }
  assert.deepEqual([...seen].sort(), presets.map((o) => o.value).sort(), 'every preset was reached');
  assert.deepEqual(page.problems, []);
});

test('every Preset entry chosen with the pointer; "your own points" shows for a state of no preset and cannot be chosen', async () => {
  const page = await openLab();
  const entries = await menu(page);
  for (const entry of entries.filter((o) => o.value !== '')) {
    await page.click('#preset');
    await page.selectOption('#preset', entry.value);
    await page.waitForFunction((v) => window.wingspline.state.preset === v, entry.value);
    await settle(page);
    assert.deepEqual(await shown(page), { value: entry.value, text: entry.text, preset: entry.value });
  }
  // "your own points" chosen with the pointer: nothing happens (it once threw).
  const before = await page.evaluate(() => window.wingspline.state);
  await page.click('#preset');
  await page.selectOption('#preset', '', { timeout: 2000 }).catch(() => {});
  await settle(page);
  assert.deepEqual(page.problems, [], 'choosing "your own points" raises no error');
  assert.deepEqual(await page.evaluate(() => window.wingspline.state), before);
  assert.notEqual((await shown(page)).value, '');
  // While the points are a preset, it is not offered at all.
  const placeholder = async () => (await menu(page)).find((o) => o.value === '');
  assert.deepEqual(await placeholder(), { value: '', text: 'your own points', disabled: true, hidden: true });

  // Points that are no preset (as an exercise or a file gives them): the menu says so.
  await page.evaluate(() => { const c = window.wingspline.ctx; c.commit({ ...c.state, preset: '' }); });
  await settle(page);
  assert.deepEqual(await placeholder(), { value: '', text: 'your own points', disabled: true, hidden: false });
  assert.deepEqual(await shown(page), { value: '', text: 'your own points', preset: '' });
  // From there a preset entry loads, and the keyboard never lands on "your own points".
  await page.focus('#preset');
  await page.keyboard.press('ArrowDown');
  await settle(page);
  assert.equal((await shown(page)).preset, entries.find((o) => o.value !== '').value);
  await page.keyboard.press('ArrowUp');
  await settle(page);
  assert.notEqual((await shown(page)).value, '');
  assert.deepEqual(page.problems, []);
});
