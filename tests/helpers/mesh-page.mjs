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

// The client point a third of the way along edge e (0-based) of the mesh lesson's drawing,
// asked of the page (clear of the edge's label in the middle).
export async function edgeMiddle(page, e) {
  return page.evaluate((edge) => {
    const m = window.wingspline.model;
    const s = m.we.edges[8 * edge]; const t = m.we.edges[8 * edge + 1];
    const x = m.projected[3 * s] + (m.projected[3 * t] - m.projected[3 * s]) / 3;
    const y = m.projected[3 * s + 1] + (m.projected[3 * t + 1] - m.projected[3 * s + 1]) / 3;
    return window.wingspline.toClient(x, y);
  }, e);
}
