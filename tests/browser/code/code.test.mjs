// "Program the structure" (code.html) driven as a student would: the code typed by keyboard
// into the editor, Run and Step by button and key, the results, the trace in the tables and
// the failing case read off the page. Expected answers come from the lecture (the slide's
// winged-edge table, lecture 000) and the statements, not from the page.
import { test } from 'node:test';
import fs from 'node:fs';
import assert from 'node:assert/strict';
import { useSiteAndBrowser, screenshot, downloadedBytes } from '../../helpers/browser.mjs';
import { CORRECT, typed } from '../../helpers/code-solutions.mjs';
import { TASK_IDS } from '../../../web/js/lessons/code/tasks.js';

const env = useSiteAndBrowser();

// The lecture's rules (tests/helpers/code-solutions.mjs) and a typical mistake for each task,
// written without indentation: the editor indents as it is typed.
const SOLUTIONS = {
  'edges-around-vertex': {
    right: typed(CORRECT['edges-around-vertex']),
    wrong: 'function edgesAroundVertex(mesh, v) {\nconst edges = [];\nconst first = mesh.vertex(v).edge;\nlet e = first;\ndo {\nedges.push(e);\nconst r = mesh.edge(e);\ne = r.start === v ? r.startRight : r.endLeft;\n} while (e !== first);\nreturn edges;\n}',
  },
  'edges-of-face': {
    right: typed(CORRECT['edges-of-face']),
    wrong: 'function edgesOfFace(mesh, f) {\nreturn [mesh.face(f).edge];\n}',
  },
  'faces-around-vertex': {
    right: typed(CORRECT['faces-around-vertex']),
    wrong: 'function facesAroundVertex(mesh, v) {\nconst out = [];\nconst first = mesh.vertex(v).edge;\nlet e = first;\ndo {\nconst r = mesh.edge(e);\nconst s = r.start === v;\nout.push(s ? r.left : r.right);\ne = s ? r.startLeft : r.endRight;\n} while (e !== first);\nreturn out;\n}',
  },
  'euler-characteristic': {
    right: typed(CORRECT['euler-characteristic']),
    wrong: 'function eulerCharacteristic(mesh) {\nlet n = 0;\nfor (let v = 0; v < mesh.vertexCount; v++) if (mesh.vertex(v).edge) n++;\nfor (let e = 0; e < mesh.edgeCount; e++) if (mesh.edge(e).start !== -1) n--;\nfor (let f = 0; f < mesh.faceCount; f++) if (mesh.face(f).edge !== -1) n++;\nreturn n;\n}',
  },
  'half-edges-around-vertex': {
    right: typed(CORRECT['half-edges-around-vertex']),
    wrong: 'function halfEdgesAroundVertex(mesh, v) {\nconst out = [];\nconst first = mesh.vertex(v).halfEdge;\nlet h = first;\ndo {\nout.push(h);\nh = mesh.halfEdge(mesh.halfEdge(h).twin).next;\n} while (h !== first);\nreturn out;\n}',
  },
  'half-edges-of-face': {
    right: typed(CORRECT['half-edges-of-face']),
    wrong: 'function halfEdgesOfFace(mesh, f) {\nconst out = [];\nconst first = mesh.face(f).halfEdge;\nlet h = first;\ndo {\nout.push(h);\nh = mesh.halfEdge(h).prev;\n} while (h !== first);\nreturn out;\n}',
  },
  'split-edge': {
    right: typed(CORRECT['split-edge']),
    // The edges at E keep pointing at e.
    wrong: typed(CORRECT['split-edge'].replace('setWing(a, E, L, n);', '').replace('setWing(b, E, R, n);', '')),
  },
  'loop-edge-point': {
    right: typed(CORRECT['loop-edge-point']),
    // The midpoint everywhere (right on the slide's parallelograms and on the boundary only).
    wrong: 'function loopEdgePoint(mesh, e) {\nconst r = mesh.edge(e);\nconst S = mesh.vertex(r.start).position, E = mesh.vertex(r.end).position;\nreturn [0, 1, 2].map((k) => (S[k] + E[k]) / 2);\n}',
  },
  'loop-vertex-point': {
    right: typed(CORRECT['loop-vertex-point']),
    wrong: 'function loopVertexPoint(mesh, v) {\nreturn mesh.vertex(v).position;\n}',
  },
  'catmull-clark-face-point': {
    right: typed(CORRECT['catmull-clark-face-point']),
    wrong: 'function faceCentroid(mesh, f) {\nconst r = mesh.edge(mesh.face(f).edge);\nreturn mesh.vertex(r.start).position;\n}',
  },
  'flip-edge': {
    right: typed(CORRECT['flip-edge']),
    // Only e's own row: the sides around it still point at the old e.
    wrong: 'function flipEdge(mesh, e) {\nconst r = mesh.edge(e);\nconst a = r.startLeft, b = r.startRight;\nconst other = (x, v) => { const y = mesh.edge(x); return y.start === v ? y.end : y.start; };\nconst S = r.start;\nconst cv = other(a, S), dv = other(b, S);\nr.start = dv;\nr.end = cv;\n}',
  },
};

async function openCode(url = `${env.site.url}code.html`) {
  const page = await env.openPage(url);
  await page.waitForSelector('body[data-ready=true]', { timeout: 20000 });
  await page.waitForSelector('#code-editor[data-ready=true]', { timeout: 20000 });
  return page;
}

// Replaces the editor's text by typing: focus, select all, type.
async function typeCode(page, source) {
  await page.click('#code-editor .cm-content');
  await page.keyboard.press('Control+a');
  await page.keyboard.press('Delete');
  await page.keyboard.type(source, { delay: 0 });
}

async function run(page) {
  const before = await page.evaluate(() => window.wingspline.state.code);
  await page.click('#code-run');
  await page.waitForFunction(() => !document.querySelector('#code-run').disabled && !/Running/.test(document.querySelector('#code-status').textContent), null, { timeout: 15000 });
  return before;
}

const text = (page, sel) => page.textContent(sel);
// The page updates its panels at the next frame: wait for the text, then check it.
async function expectText(page, sel, expected) {
  await page.waitForFunction(([s, e]) => document.querySelector(s)?.textContent === e, [sel, expected], { timeout: 5000 }).catch(() => {});
  assert.equal(await text(page, sel), expected);
}

test('every task: the lecture\'s rule typed by keyboard passes every mesh; a mistake fails on a named mesh with both answers', async () => {
  const page = await openCode();
  assert.deepEqual(Object.keys(SOLUTIONS).sort(), [...TASK_IDS].sort(), 'a right and a wrong solution for every task');
  for (const [task, { right, wrong }] of Object.entries(SOLUTIONS)) {
    await page.selectOption('#code-task', task);
    await page.waitForFunction((t) => window.wingspline.state.task === t, task);
    await typeCode(page, right);
    await run(page);
    const verdict = await text(page, '#code-verdict');
    const [, passed, asked] = verdict.match(/✓ Every mesh passed \((\d) of (\d)\)/) ?? [];
    // (Loop's points are not asked on meshes with polygons: the cube, the joined grid.)
    assert.ok(passed && passed === asked && Number(asked) >= (task.startsWith('loop') ? 5 : 7), `${task}: ${verdict}`);
    assert.equal(await page.$$eval('#case-list li.is-passed', (l) => l.length), Number(asked), task);
    // The code is the state, for this task.
    assert.match(await page.evaluate((t) => window.wingspline.state.code[t], task), /function/);

    await typeCode(page, wrong);
    await run(page);
    assert.match(await text(page, '#code-verdict'), /✗ \d of \d meshes passed/, task);
    const failure = await text(page, '#code-failure');
    assert.match(failure, /^On (the slide's mesh|an open fan|a tetrahedron|a cube|a sphere|a grid|the slide's mesh with)/, `${task}: ${failure}`);
    const edit = { 'flip-edge': 'flip', 'split-edge': 'split' }[task];
    assert.match(failure, edit ? new RegExp(`not the winged edge of the mesh after the ${edit}, so nothing was applied`) : /expected .*your function returned/, `${task}: ${failure}`);
    // The drawing shows the failing case: its label is the first failed item of the list.
    const current = await page.$eval('#case-list li[aria-current=true]', (li) => li.className);
    assert.equal(current, 'is-failed');
  }
  assert.deepEqual(page.problems, []);
});

test('Step plays back what the walk read: v2\'s stored edge, then e6\'s S and S:L, in the tables and the count against the rule', async () => {
  const page = await openCode();
  await typeCode(page, SOLUTIONS['edges-around-vertex'].right);
  await run(page);
  // The slide's case is the first; select it.
  await page.click('#case-list li:first-child button');
  await page.click('#code-step');
  // Lecture 000's vertex table: v2 stores e6.
  await expectText(page, '#trace-line', 'Read 1 of 9: v2.edge = e6');
  assert.equal(await page.$eval('#code-vertex-table tr.is-highlighted th', (th) => th.textContent), 'v2');
  assert.equal(await page.$eval('#code-vertex-table td.is-read', (td) => td.textContent), 'e6');
  await page.click('#code-step');
  await expectText(page, '#trace-line', 'Read 2 of 9: e6.start = v2');
  await page.click('#code-step');
  // e6's wing at S, on the left: e5 (the slide's edge table).
  await expectText(page, '#trace-line', 'Read 3 of 9: e6.startLeft = e5');
  assert.equal(await page.$eval('#code-edge-table tr.is-highlighted th', (th) => th.textContent), 'e6');
  assert.equal(await page.$eval('#code-edge-table td.is-read', (td) => td.textContent), 'e5');
  // n and b on the page step too; back to read 2.
  await page.click('#trace-line');
  await page.keyboard.press('b');
  await expectText(page, '#trace-line', 'Read 2 of 9: e6.start = v2');
  // 1 + 2 per edge of the ring (4 edges): 9, as the core counts the lecture's rule.
  assert.match(await text(page, '#reads-line'), /Your function read 9 entries.*the lecture's rule reads 9/);
  await screenshot(page, 'code-step-1280x800');
  assert.deepEqual(page.problems, []);
});

test('a flip is checked whole and applied: Step shows each entry written, and at the end the slide\'s e3 runs v4 -> v1', async () => {
  const page = await openCode();
  await page.selectOption('#code-task', 'flip-edge');
  await typeCode(page, SOLUTIONS['flip-edge'].right);
  await run(page);
  await page.click('#case-list li:first-child button');
  await page.waitForFunction(() => /applied/.test(document.querySelector('#reads-line').textContent));
  // Before any step e3 is the slide's row: v2 -> v3, L = F1, R = F2.
  const row = () => page.$$eval('#code-edge-table tr[data-row="2"] td', (tds) => tds.slice(0, 4).map((td) => td.textContent));
  assert.deepEqual(await row(), ['v2', 'v3', 'F1', 'F2']);
  await page.click('#trace-line');
  await page.keyboard.press('End');
  await page.waitForFunction(() => /^Read (\d+) of \1: /.test(document.querySelector('#trace-line').textContent));
  // After the flip (worked from the slide): e3 joins v4 to v1, F1 still on its left.
  assert.deepEqual(await row(), ['v4', 'v1', 'F1', 'F2']);
  assert.match(await text(page, '#reads-line'), /wrote \d+; the core's flip-edge writes \d+\. The tables it left are the edited mesh's winged edge: applied\./);
  assert.deepEqual(page.problems, []);
});

test('an endless loop in a nested call stops within two seconds with its line; the page stays responsive; the next run works', async () => {
  const page = await openCode();
  await typeCode(page, 'function spin() {\nwhile (true) {}\n}\nfunction edgesAroundVertex(mesh, v) {\nspin();\nreturn [];\n}');
  const started = Date.now();
  await page.evaluate(() => {
    window.frames_ = 0;
    const tick = () => { window.frames_ += 1; requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  await page.click('#code-run');
  // While it runs, the page answers and draws.
  await page.waitForTimeout(700);
  const during = await page.evaluate(() => window.frames_);
  assert.ok(during > 10, `the page drew ${during} frames while the code ran`);
  await page.waitForFunction(() => /did not|stopped|ran for|timeout|endless/i.test(document.querySelector('#code-failure').textContent + document.querySelector('#code-status').textContent) && !document.querySelector('#code-run').disabled, null, { timeout: 20000 });
  const failure = await text(page, '#code-failure');
  assert.match(failure, /^On the slide's mesh \(lecture 000\), v2: Line 2, column \d+: your code ran longer than 1\.5 s/, failure);
  // The run stops at the first mesh's endless loop (the others are not tried).
  assert.ok(Date.now() - started < 5000, `${Date.now() - started} ms`);
  assert.match(await text(page, '#case-list'), /not run/);
  await typeCode(page, SOLUTIONS['edges-around-vertex'].right);
  await run(page);
  assert.match(await text(page, '#code-verdict'), /✓ Every mesh passed/);
  assert.deepEqual(page.problems, []);
});

test('code that reaches for the page, storage, the network or the prototypes gets a clear error and changes nothing', async () => {
  const page = await openCode();
  await page.evaluate(() => localStorage.setItem('probe', 'kept'));
  const attempts = [
    ['fetch', 'fetch("/")'],
    ['document', 'document.title = "x"'],
    ['localStorage', 'localStorage.setItem("probe", "gone")'],
    ['importScripts', 'importScripts("x.js")'],
    ['postMessage', 'postMessage("x")'],
  ];
  for (const [name, call] of attempts) {
    await typeCode(page, `function edgesAroundVertex(mesh, v) {\n${call};\nreturn [];\n}`);
    await run(page);
    const failure = await text(page, '#code-failure');
    assert.match(failure, new RegExp(`Line 2, column \\d+: ${name} is not available`), failure);
  }
  // A prototype changed inside the sandbox stays there.
  await typeCode(page, 'Object.prototype.polluted = 1;\nArray.prototype.push = null;\nfunction edgesAroundVertex(mesh, v) {\nreturn [];\n}');
  await run(page);
  assert.equal(await page.evaluate(() => ({}).polluted), undefined);
  assert.equal(await page.evaluate(() => typeof [].push), 'function');
  assert.equal(await page.evaluate(() => localStorage.getItem('probe')), 'kept');
  assert.equal(await page.evaluate(() => document.title.includes('Program the structure')), true);
  assert.deepEqual(page.problems, []);
});

test('what the function prints with console.log is shown under the drawing, for the case shown', async () => {
  const page = await openCode();
  await typeCode(page, 'function edgesAroundVertex(mesh, v) {\nconsole.log("asked", v, mesh.vertex(v).edge);\nreturn [];\n}');
  await run(page);
  // The slide's case fails first (an empty ring): v2 (index 1) stores e6 (index 5).
  await page.waitForFunction(() => !document.querySelector('#code-logs').hidden);
  assert.equal(await text(page, '#code-logs'), 'console.log:\nasked 1 5');
  assert.deepEqual(page.problems, []);
});

test('a syntax error is named with its line and column, under the editor and in it', async () => {
  const page = await openCode();
  await typeCode(page, 'function edgesAroundVertex(mesh, v) {\nconst x = ;\nreturn [];\n}');
  await run(page);
  const status = await text(page, '#code-status');
  assert.match(status, /^Line 2, column \d+: /, status);
  // The error's place is marked in the editor, on line 2.
  await page.waitForSelector('#code-editor .cm-error-mark');
  assert.equal(await page.locator('#code-editor .cm-error-mark').evaluate((el) => el.closest('.cm-line') === el.closest('.cm-content').children[1]), true);
  assert.deepEqual(page.problems, []);
});

test('the code is kept: reload, a share link in a fresh tab, the .js export and the history', async () => {
  const page = await openCode();
  const source = SOLUTIONS['edges-of-face'].right;
  await page.selectOption('#code-task', 'edges-of-face');
  await typeCode(page, source);
  await page.waitForFunction(() => /return edges/.test(window.wingspline.state.code['edges-of-face'] ?? ''));
  const kept = await page.evaluate(() => window.wingspline.state.code['edges-of-face']);
  await page.reload();
  await page.waitForSelector('#code-editor[data-ready=true]', { timeout: 20000 });
  assert.equal(await page.evaluate(() => window.wingspline.state.code['edges-of-face']), kept);
  assert.match(await page.locator('#code-editor .cm-content').innerText(), /r\.endLeft/);
  // The share link opens the same code in another context.
  const link = await page.evaluate(() => window.wingspline.shareUrl());
  const other = await env.openPage(link);
  await other.waitForSelector('#code-editor[data-ready=true]', { timeout: 20000 });
  assert.equal(await other.evaluate(() => window.wingspline.state.code['edges-of-face']), kept);
  assert.match(await other.locator('#code-editor .cm-content').innerText(), /r\.endLeft/);
  // The .js export is the code itself.
  await page.click('details.menu > summary');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-export="Your code (.js)"]')]);
  assert.equal(download.suggestedFilename(), 'edgesOfFace.js');
  assert.equal((await downloadedBytes(download)).toString('utf8'), kept);
  // Reset to the starter is one step of the history: undo brings the code back.
  await page.click('#code-reset');
  await page.waitForFunction(() => window.wingspline.state.code['edges-of-face'] === undefined);
  await page.click('#code-status');
  await page.keyboard.press('Control+z');
  await page.waitForFunction((k) => window.wingspline.state.code['edges-of-face'] === k, kept);
  await page.waitForFunction(() => /r\.endLeft/.test(document.querySelector('.code-editor-host').shadowRoot.querySelector('.cm-content').innerText));
  assert.deepEqual(page.problems, []);
  assert.deepEqual(other.problems, []);
});

test('the code exercise from the gallery: a wrong walk is named on the slide\'s mesh without the core\'s answer; the right one solves it; the hand-in carries the code and the grader, running it in Node, agrees', async () => {
  const context = await env.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  const page = await context.newPage();
  page.problems = [];
  page.on('pageerror', (err) => page.problems.push(err.message));
  await page.goto(`${env.site.url}exercises.html`);
  await page.waitForSelector('body[data-ready="true"]');
  await page.locator('[data-exercise="code-edges-around-vertex"] a').click();
  await page.waitForSelector('#exercise-panel');
  await page.waitForSelector('#code-editor[data-ready=true]', { timeout: 20000 });
  assert.equal(await page.evaluate(() => window.wingspline.state.task), 'edges-around-vertex');
  // The starter is in the editor, nobody's solution.
  assert.match(await page.textContent('#code-editor .cm-content'), /Walk counter-clockwise around v/);

  const check = async () => {
    await page.locator('#exercise-check').click();
    await page.waitForFunction(() => ['right', 'wrong', 'partial'].includes(document.querySelector('#exercise-feedback')?.dataset.result ?? ''), null, { timeout: 20000 });
    return page.locator('#exercise-feedback').innerText();
  };
  await typeCode(page, SOLUTIONS['edges-around-vertex'].wrong);
  const wrong = await check();
  // The slide's v2: the clockwise walk from e6 meets e2 second (lecture 000: e6 e5 e3 e2 CCW).
  assert.match(wrong, /On the slide's mesh \(lecture 000\), v2: your function returned \[e6 e2 e3 e5\]\. It parts from the core's answer at entry 2\./);
  assert.doesNotMatch(wrong, /e6 e5 e3 e2/, 'the core\'s answer is not shown at level hint before the hints');
  assert.equal(await page.locator('#exercise-feedback').getAttribute('data-result'), 'wrong');
  // The lesson's own results show the same run, without the core's answer either.
  assert.match(await page.textContent('#code-verdict'), /✗ \d of \d meshes passed/);
  assert.match(await page.textContent('#reads-line'), /It returned \[e6 e2 e3 e5\], not the core's answer\./);
  for (const sel of ['#reads-line', '#code-failure']) assert.doesNotMatch(await page.textContent(sel), /e6 e5 e3 e2/, sel);
  await typeCode(page, SOLUTIONS['edges-around-vertex'].right);
  assert.match(await check(), /Right\. All \d+ meshes passed\./);
  assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'solved');

  // Reload: the code and the progress are kept with the exercise.
  await page.evaluate(() => window.wingspline.flush());
  await page.reload();
  await page.waitForSelector('#exercise-panel');
  assert.equal(await page.locator('#exercise-status').getAttribute('data-status'), 'solved');
  assert.match(await page.evaluate(() => window.wingspline.state.code['edges-around-vertex']), /r\.startLeft/);

  // Handed in, and graded by the grader in Node from the file.
  await page.goto(`${env.site.url}exercises.html`);
  await page.waitForSelector('body[data-ready="true"]');
  await page.locator('#hand-in-name').fill('Grace');
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#hand-in-export').click()]);
  const submission = (await downloadedBytes(download)).toString('utf8');
  const { gradeFiles, RESULTS } = await import('../../../web/js/exercise/grade.js');
  const { GRADERS } = await import('../../../web/js/exercise/graders.js');
  const { LESSON_OBJECTS } = await import('../../../web/js/lessons/all.js');
  const { createNodeSandbox } = await import('../../../web/js/code/quickjs-node.js');
  const { loadWingspline } = await import('../../../dist/js/core/wingspline.js');
  const sandbox = createNodeSandbox();
  const exercise = fs.readFileSync(new URL('../../../web/exercises/code-edges-around-vertex.json', import.meta.url), 'utf8');
  const { rows } = await gradeFiles({
    api: await loadWingspline(), lessons: LESSON_OBJECTS, graders: GRADERS, run: (request) => sandbox.run(request),
    files: [{ name: 'ex.json', size: exercise.length, read: () => exercise }, { name: 'grace.json', size: submission.length, read: () => submission }],
  });
  assert.deepEqual(rows.map((r) => [r.student, r.result]), [['Grace', RESULTS.right]]);
  assert.deepEqual(page.problems, []);
});
