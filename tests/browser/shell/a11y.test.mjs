// Accessible and secure: axe-core finds no serious or critical violation on any
// page (landing, every ready lesson, the fixture; light, dark and presentation mode); the
// keyboard alone reaches a control point, moves it, and types exact coordinates (a lesson with nothing to drag: its controls), and a
// screen reader hears where it is; the key map opens with ? at its top; presentation mode hides
// the advanced controls; reduced motion slows the player; print shows no control at all.
// axe runs through tests/helpers/axe.mjs (which says why it is evaluated, not added as a script tag).
import { test, describe, after } from 'node:test';
import assert from 'node:assert/strict';
import { screenshot, useSiteAndBrowser } from '../../helpers/browser.mjs';
import { lessonsUnderTest, startClassroomSite, openLesson, trap } from '../../helpers/classroom.mjs';
import { seriousViolations as audit } from '../../helpers/axe.mjs';
import { LESSON_OBJECTS } from '../../../web/js/lessons/all.js';

const env = useSiteAndBrowser(startClassroomSite);

const pages = [{ title: 'Landing page', page: 'index.html', landing: true }, ...lessonsUnderTest];
for (const scheme of ['light', 'dark']) {
  for (const entry of pages) {
    test(`axe: ${entry.title} (${scheme}) has no serious or critical violations`, async () => {
      const context = await env.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: scheme });
      const page = trap(await context.newPage());
      await page.goto(new URL(entry.page, env.site.url).href);
      if (entry.landing) await page.waitForSelector('[data-core-status][data-state=ready]');
      else await page.waitForSelector('body[data-ready=true]');
      assert.deepEqual(await audit(page), []);
      if (!entry.landing) {
        // With a handle selected (the inspector live) and in presentation mode too.
        await page.focus('#stage');
        await page.keyboard.press(']');
        await page.keyboard.press('p');
        await page.waitForFunction(() => document.documentElement.hasAttribute('data-present'));
        assert.deepEqual(await audit(page), [], 'presentation mode');
        await screenshot(page, `${entry.page.replace('.html', '')}-present-${scheme}`);
      }
      assert.deepEqual(page.problems, []);
    });
  }
}

for (const lesson of lessonsUnderTest) {
  describe(`${lesson.title}: keyboard and presentation`, () => {
    test('the keyboard alone reaches a control point, moves it and types its coordinates', async () => {
      const page = await env.openLesson(new URL(lesson.page, env.site.url).href);
      // Tab from the top of the page until the drawing has the focus, with a visible ring.
      let reached = false;
      for (let i = 0; i < 60 && !reached; i += 1) {
        await page.keyboard.press('Tab');
        reached = await page.evaluate(() => document.activeElement?.id === 'stage');
      }
      assert.ok(reached, 'Tab reaches the drawing');
      const ring = await page.evaluate(() => getComputedStyle(document.activeElement).outlineStyle);
      assert.notEqual(ring, 'none', 'the focused drawing shows a focus ring');
      const handles = await page.evaluate(() => window.wingspline.handles());
      if (!handles.some((x) => x.draggable)) {
        // A lesson that draws nothing to drag (the code lesson's mesh is a view of its tables):
        // ] still selects a vertex and says where it is; Tab goes on to the lesson's controls.
        assert.ok(LESSON_OBJECTS[lesson.id] && !LESSON_OBJECTS[lesson.id].moveHandle, 'only a lesson that moves no handle has none to drag');
        await page.keyboard.press(']');
        assert.equal(await page.evaluate(() => window.wingspline.selected), handles[0].id);
        assert.match(await page.textContent('#stage-announce'), new RegExp(`^${handles[0].label}`));
        let control = false;
        for (let i = 0; i < 60 && !control; i += 1) {
          await page.keyboard.press('Tab');
          control = await page.evaluate(() => document.activeElement?.closest('.panels') !== null && ['BUTTON', 'SELECT'].includes(document.activeElement.tagName));
        }
        assert.ok(control, 'Tab reaches a control of the panels');
        assert.notEqual(await page.evaluate(() => getComputedStyle(document.activeElement).outlineStyle), 'none', 'with a focus ring');
        return;
      }
      const target = handles.findIndex((x) => x.draggable);
      assert.ok(target >= 0, 'the lesson has a draggable handle');
      for (let i = 0; i <= target; i += 1) await page.keyboard.press(']');
      assert.equal(await page.evaluate(() => window.wingspline.selected), handles[target].id);
      const before0 = handles[target].world;
      const zoom = (await page.evaluate(() => window.wingspline.state)).view.zoom;
      await page.keyboard.press('ArrowRight');
      await page.keyboard.press('Shift+ArrowUp');
      const after = (await page.evaluate(() => window.wingspline.handles()))[target];
      const after0 = after.world;
      // The stage nudges 10 px per arrow (Shift: 1 px), in world units 10/zoom; a lesson may
      // constrain the move, so the direction is what every lesson must honour.
      assert.ok(after0.x > before0.x, `moved right: ${before0.x} -> ${after0.x} (zoom ${zoom})`);
      assert.ok(after0.y >= before0.y, 'Shift+Up does not move it down');
      const spoken = await page.textContent('#stage-announce');
      assert.match(spoken, new RegExp(`^${after.label} at \\(-?[0-9.e-]+, -?[0-9.e-]+\\)$`));
      // Exact values through the inspector, reached by Tab.
      let inInspector = false;
      for (let i = 0; i < 80 && !inInspector; i += 1) { // scroll regions are tab stops too (dom.js)
        await page.keyboard.press('Tab');
        inInspector = await page.evaluate(() => document.activeElement?.id === 'inspect-x');
      }
      if (await page.$('#inspect-x')) {
        assert.ok(inInspector, 'Tab reaches the inspector');
        await page.keyboard.press('Control+a');
        await page.keyboard.type('1.5');
        await page.keyboard.press('Tab');
        await page.keyboard.press('Control+a');
        await page.keyboard.type('2');
        await page.keyboard.press('Enter');
        const moved = (await page.evaluate(() => window.wingspline.handles()))[target];
        assert.deepEqual([moved.world.x, moved.world.y], [1.5, 2], 'typed coordinates are taken exactly');
        assert.equal(await page.textContent('#stage-announce'), `${moved.label} at (1.5, 2)`);
      }
    });

    test('? shows the key map; presentation mode keeps the essentials', async () => {
      const page = await env.openLesson(new URL(lesson.page, env.site.url).href);
      await page.focus('#stage');
      await page.keyboard.press('?');
      await page.waitForSelector('dialog.keymap-dialog[open]');
      const keys = await page.textContent('dialog.keymap-dialog');
      for (const word of ['undo', 'presentation mode', 'move the selected handle', 'show this key map']) assert.ok(keys.includes(word), word);
      // It opens at its top: the title in view and the focus on Close, on a 1366 x 768 laptop too.
      await page.keyboard.press('Escape');
      await page.setViewportSize({ width: 1366, height: 768 });
      await page.focus('#stage');
      await page.keyboard.press('?');
      await page.waitForSelector('dialog.keymap-dialog[open]');
      const opened = await page.evaluate(() => {
        const title = document.getElementById('keymap-title').getBoundingClientRect();
        const dialog = document.querySelector('dialog.keymap-dialog');
        const box = dialog.getBoundingClientRect();
        return { top: title.top, boxTop: box.top, scrollTop: dialog.scrollTop, focus: document.activeElement?.textContent };
      });
      assert.ok(opened.top >= opened.boxTop && opened.top >= 0, `the title is in view: ${JSON.stringify(opened)}`);
      assert.equal(opened.scrollTop, 0);
      assert.equal(opened.focus, 'Close');
      await page.keyboard.press('Escape');
      await page.setViewportSize({ width: 1280, height: 800 });
      await page.waitForSelector('dialog.keymap-dialog:not([open])', { state: 'attached' });
      assert.equal(await page.evaluate(() => document.activeElement?.id), 'stage', 'focus returns to the drawing');
      await page.click('[data-action=present]');
      await page.waitForFunction(() => document.documentElement.hasAttribute('data-present'));
      const visible = await page.$$eval('.advanced', (els) => els.filter((e) => e.getClientRects().length > 0).length);
      assert.equal(visible, 0, 'advanced controls are hidden');
      for (const action of ['undo', 'present', 'keys']) assert.ok(await page.isVisible(`[data-action=${action}]`), `${action} stays`);
      // The type follows the screen's height (site.css): 8 px + 1.3% of the rows,
      // at least 18 and at most 24 px; 18.4 px on this 800-row window (17 px when not presenting).
      const size = await page.evaluate(() => parseFloat(getComputedStyle(document.documentElement).fontSize));
      assert.ok(Math.abs(size - Math.min(24, Math.max(18, 8 + 0.013 * 800))) < 0.1, `large type (${size}px)`);
      await page.keyboard.press('Escape');
      await page.waitForFunction(() => !document.documentElement.hasAttribute('data-present'));
    });

    test('print shows the figure and tables without the controls', async () => {
      const page = await env.openLesson(new URL(lesson.page, env.site.url).href, { colorScheme: 'dark' });
      await page.emulateMedia({ media: 'print' });
      for (const selector of ['#lesson-toolbar', '#stage-controls']) assert.equal(await page.isVisible(selector), false, `${selector} hidden`);
      assert.ok(await page.isVisible('#stage'));
      assert.ok(await page.isVisible('h1'));
      // No control of any kind is printed: buttons, menus, sliders, checkboxes, selects.
      const printed = await page.evaluate(() => [...document.querySelectorAll('button, select, input, textarea, details.menu')]
        .filter((el) => el.getClientRects().length > 0).map((el) => el.id || el.outerHTML.slice(0, 60)));
      assert.deepEqual(printed, []);
    });
  });
}

describe('Classroom fixture: presenter remote and reduced motion', () => {
  test('PageDown, PageUp, Home, o and Space drive the steps and overlays', async () => {
    const page = await env.openLesson(new URL('fixture.html', env.site.url).href);
    const state = () => page.evaluate(() => window.wingspline.state);
    await page.keyboard.press('PageDown');
    await page.keyboard.press('PageDown');
    assert.equal((await state()).step, 2);
    await page.keyboard.press('PageUp');
    assert.equal((await state()).step, 1);
    await page.keyboard.press('Home');
    assert.equal((await state()).step, 0);
    await page.keyboard.press('o');
    assert.equal((await state()).showPolygon, false);
    await page.keyboard.press('b');
    assert.equal((await state()).showPolygon, true);
    const keys = await page.evaluate(() => window.wingspline.ctx.keymap.list().filter((b) => b.group === 'Presenter').map((b) => b.label));
    assert.deepEqual(keys, ['next step', 'previous step', 'play / pause', 'back to the first step', 'overlays on / off']);
  });

  test('reduced motion caps the player rate', async () => {
    const context = await env.newContext({ reducedMotion: 'reduce' });
    const page = await openLesson(context, new URL('fixture.html', env.site.url).href);
    const rates = await page.evaluate(async () => {
      const { createPlayer, REDUCED_MOTION_STEPS_PER_SECOND } = await import('./js/app/player.js');
      const player = createPlayer({ count: () => 5, getStep: () => 0, onStep: () => {}, stepsPerSecond: 4 });
      return { speed: player.speed, effective: player.effectiveSpeed, cap: REDUCED_MOTION_STEPS_PER_SECOND };
    });
    assert.deepEqual(rates, { speed: 4, effective: rates.cap, cap: 0.5 });
  });
});
