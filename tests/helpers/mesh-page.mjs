// The mesh lesson's UV sphere chosen as a person does (the mesh menu, then slices and stacks
// typed and confirmed), waiting until the page holds its 2 * slices * (stacks - 1) faces.
export async function chooseSphere(page, slices, stacks, { timeout = 60000 } = {}) {
  await page.selectOption('#mesh-kind', 'sphere');
  await page.fill('#sphere-slices', String(slices));
  await page.press('#sphere-slices', 'Enter');
  await page.fill('#sphere-stacks', String(stacks));
  await page.press('#sphere-stacks', 'Enter');
  await page.waitForFunction((f) => window.wingspline.model?.F === f, 2 * slices * (stacks - 1), { timeout });
}

// A click at a client point of the mesh lesson's canvas that picks the element `label`
// (v1, e3, F6): waits until the edit panel says it is the picked one.
export async function clickToPick(page, point, label) {
  await page.mouse.click(point.x, point.y);
  await page.waitForFunction((l) => document.querySelector('#edit-picked')?.textContent === `Picked: ${l}`, label);
}
