// Tampered share links: each gives one line of message, a working page at the default (or
// the valid part), and nothing executed. The cases the lesson's state reader meets run on
// every ready lesson; those the shell refuses before any lesson reads them, on the fixture
// and mesh lessons (shellLessonIds). Split from shell/state.test.mjs so the two files run side by side.
import { test, describe, before } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import {
  lessonsUnderTest, startClassroomSite, waitReady, nothingExecuted, payloads,
  linkCode, envelopeCode, stateBits, editByKeyboard, shellLessonIds
} from '../../helpers/classroom.mjs';

// A message line is one sentence for a person, not a stack trace or a page of text.
const MESSAGE_MAX_CHARS = 300;

const env = useSiteAndBrowser(startClassroomSite);

for (const lesson of lessonsUnderTest) {
  describe(`${lesson.title}: tampered links`, () => {
    const id = lesson.id;
    const good = (state) => envelopeCode(id, lesson.fixture ? 2 : 1, state);
    // Each case: the #s= code, and whether the valid rest of the state is kept (then the
    // view, a field every lesson has, is checked to be the default).
    // The third field: { shell: true } marks a case the shell refuses before the lesson reads
    // anything (checked on shellLessonIds only, see tests/helpers/classroom.mjs).
    const cases = [
      ['garbage characters', '%3Cscript%3Ewindow.__pwned%3D1%3C%2Fscript%3E!!', { shell: true }],
      ['random base64 that does not decompress', 'QUJDREVGR0hJSktMTU5PUA', { shell: true }],
      ['a truncated link', null, { shell: true }],
      ['text that is not JSON', linkCode('hello, not json'), { shell: true }],
      ['JSON that is not an envelope', linkCode('[1, 2, 3]'), { shell: true }],
      ['wrong types', good({ view: 'wide', points: 'many' })],
      ['huge numbers', linkCode(`{"format":"wingspline","lesson":"${id}","version":${lesson.fixture ? 2 : 1},"state":{"view":{"cx":1e999,"cy":-1e308,"zoom":1e300}}}`)],
      ['NaN and Infinity as strings', good({ view: { cx: 'NaN', cy: 'Infinity', zoom: '-Infinity' } })],
      ['script in strings', linkCode(JSON.stringify({ format: 'wingspline', lesson: payloads.img, version: 1, state: { view: payloads.script } })), { shell: true }],
      ['script in a text field', good({ note: payloads.img, view: { cx: payloads.svg, cy: 0, zoom: 50 } })],
      ['another lesson', envelopeCode(id === 'curves' ? 'mesh' : 'curves', 1, {}), { shell: true }],
      ['a newer version', envelopeCode(id, 99, {}), { shell: true }],
      ['a version that is not a number', envelopeCode(id, '1', {}), { shell: true }],
      ['an oversized link', 'A'.repeat(250000), { shell: true }],
      // Unknown fields are dropped (docs/state-format.md, reading step 4), and a state
      // missing the lesson's fields is reset with a message: this link, a valid envelope
      // of the page's own version, holds nothing but __proto__/constructor keys. What
      // matters most is that nothing is polluted.
      ['a prototype-polluting key', linkCode(`{"format":"wingspline","lesson":"${id}","version":${lesson.fixture ? 2 : 1},"state":{"__proto__":{"polluted":true},"constructor":{"prototype":{"polluted":true}}}}`)],
    ];
    // The lesson's own link, read once for all cases (the truncated case cuts it in half).
    // (It was read again before every case; a page load each, 90 in all.)
    let real;
    const thorough = shellLessonIds.has(id);
    if (thorough) before(async () => {
      const probe = await env.openLesson(new URL(lesson.page, env.site.url).href);
      assert.equal(await probe.evaluate(() => window.wingspline.lesson), id);
      real = (await probe.evaluate(() => window.wingspline.shareUrl())).split('#s=')[1];
    });
    let reloaded = false;
    for (const [name, code, { quiet = false, shell = false } = {}] of cases) {
      if (shell && !thorough) continue;
      // The reload after the repair is the shell's: every case on the shell's lessons, the
      // first case elsewhere.
      const reload = thorough || !reloaded;
      reloaded = true;
      test(name, async () => {
        const hash = code ?? real.slice(0, Math.floor(real.length / 2));
        const page = await env.openLesson(`${new URL(lesson.page, env.site.url).href}#s=${hash}`);
        const message = await page.evaluate(() => window.wingspline.message());
        if (quiet) {
          assert.equal(message, '', 'unknown fields are dropped quietly');
        } else {
          assert.ok(message.length > 0, 'a message says what happened');
          assert.ok(!message.includes('\n') && message.length <= MESSAGE_MAX_CHARS, `one line: ${message}`);
          assert.equal(await page.getAttribute('#message', 'data-kind'), 'warn');
        }
        assert.deepEqual(await nothingExecuted(page), { pwned: null, injectedElements: 0 });
        assert.equal(await page.evaluate(() => ({}).polluted ?? Object.prototype.polluted ?? null), null);
        assert.deepEqual(page.dialogs, []);
        assert.deepEqual(page.problems, []);
        // A working page: the state is valid (the default view), a handle moves by keyboard.
        const state = await page.evaluate(() => window.wingspline.state);
        for (const key of ['cx', 'cy', 'zoom']) assert.ok(Number.isFinite(state.view[key]), `view.${key} is a number`);
        const before1 = await stateBits(page);
        await editByKeyboard(page);
        assert.notDeepEqual(await stateBits(page), before1, 'the page still takes edits');
        // The address bar now holds the usable state, so a reload shows no warning.
        // (Saving is debounced; wait for it, as a person does not reload within 200 ms.)
        if (!reload) return;
        await page.evaluate(() => window.wingspline.flush());
        await page.reload();
        await waitReady(page);
        assert.equal(await page.evaluate(() => window.wingspline.message()), '');
      });
    }
  });
}
