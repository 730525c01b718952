// Driving a lesson's drawing as a person does: the page says where a handle is
// (window.wingspline.handles(), CSS pixels), the mouse goes there, presses, moves in five
// steps and lets go.
import assert from 'node:assert/strict';

export async function handle(page, id) {
  const found = (await page.evaluate(() => window.wingspline.handles())).find((x) => x.id === id);
  assert.ok(found, `handle ${id} is on the page`);
  return found;
}

export async function drag(page, id, dx, dy) {
  const hd = await handle(page, id);
  await page.mouse.move(hd.x, hd.y);
  await page.mouse.down();
  await page.mouse.move(hd.x + dx, hd.y + dy, { steps: 5 });
  await page.mouse.up();
}
