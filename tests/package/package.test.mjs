// Package and scripts: `npm pack` gives a tarball a student installs in an empty
// folder; `import { loadWingspline } from 'wingspline'` then works in Node, and the same
// installed files work from a page without a bundler. Packed once and installed once
// (offline: its two runtime dependencies, QuickJS for the code sandbox, come from npm's cache,
// where setup's `npm ci` put them) for the whole file.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync, spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { repoRoot, startSite, launchBrowser } from '../helpers/browser.mjs';
import { csvObjects } from '../helpers/csv.mjs';
import { slideWalk, FLIP_E3 } from '../helpers/lecture-slide.mjs';
import { CORRECT } from '../helpers/code-solutions.mjs';

const pageDir = path.join(repoRoot, 'tests', 'package', 'page');
let tmp;
let tarball;
let packed; // npm pack --json's file list
let packLog; // what npm pack printed before its report (the prepack build)
let installed; // <tmp>/app/node_modules/wingspline

const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });

before(() => {
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-pack-'));
  // The prepack script (scripts/build.mjs) prints its log before npm's JSON report.
  const r = spawnSync('npm', ['pack', '--json', '--pack-destination', tmp], { cwd: repoRoot, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const start = r.stdout.search(/^\[\s*\{/m);
  packLog = r.stderr + r.stdout.slice(0, start);
  const report = JSON.parse(r.stdout.slice(start));
  packed = report[0].files.map((f) => f.path);
  tarball = path.join(tmp, report[0].filename);
  const app = path.join(tmp, 'app');
  fs.mkdirSync(app);
  fs.writeFileSync(path.join(app, 'package.json'), JSON.stringify({ name: 'homework', private: true, type: 'module' }));
  npm(['install', '--offline', '--no-audit', '--no-fund', '--ignore-scripts', tarball], app);
  installed = path.join(app, 'node_modules', 'wingspline');
});

after(() => fs.rmSync(tmp, { recursive: true, force: true }));

// The Bernstein form of lecture 002, computed here: P(u) = sum_i C(3,i) u^i (1-u)^(3-i) P_i.
function bezierPoint(points, u) {
  const b = [(1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u * u * (1 - u), u ** 3];
  return [0, 1].map((k) => b.reduce((s, w, i) => s + w * points[2 * i + k], 0));
}

// Tolerance: 1e-12 relative to the control polygon's size (coordinates up to 4).
function checkProbe(result) {
  assert.equal(result.error, undefined, result.error);
  const control = [0, 0, 1, 2, 3, 2, 4, 0];
  result.params.forEach((u, j) => {
    const [x, y] = bezierPoint(control, u);
    assert.ok(Math.abs(result.points[2 * j] - x) <= 4e-12 && Math.abs(result.points[2 * j + 1] - y) <= 4e-12,
      `P(${u}) = (${result.points.slice(2 * j, 2 * j + 2)}), the Bernstein form gives (${x}, ${y})`);
  });
  assert.deepEqual(result.points.slice(4, 6), [2, 1.5], 'P(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8 = (2, 1.5), exact in binary');
  // Lecture 000's slide: the CCW walk around v2 starting at its edge e6 reads e6 e5 e3 e2.
  assert.deepEqual(result.walk.map((e) => `e${e + 1}`), ['e6', 'e5', 'e3', 'e2']);
  assert.equal(result.liveDuring, result.liveBefore + 1, 'the built mesh is live until disposed');
  assert.equal(result.liveAfter, result.liveBefore, 'dispose frees the mesh in the core');
  assert.equal(result.disposed, true);
  assert.equal(result.afterDispose, 'disposed');
}

test('npm pack builds first (prepack) and the tarball holds the built module, the site, the declarations, README and LICENSE, and no tests or build output', () => {
  assert.match(packLog, /prepack/, 'npm ran the prepack script');
  assert.match(packLog, /\[wingspline\] site assembled in dist\//, 'the prepack script built the site');
  for (const file of ['package.json', 'README.md', 'LICENSE', 'dist/js/core/wingspline.js', 'dist/js/core/mesh-api.js',
    ...['mesh', 'subdivision', 'meshes', 'curves', 'exercises'].flatMap((m) => [`dist/wasm/wingspline-${m}.js`, `dist/wasm/wingspline-${m}.wasm`]), 'dist/index.html', 'types/wingspline.d.ts', 'scripts/wingspline.mjs']) {
    assert.ok(packed.includes(file), `${file} is in the tarball (it holds ${packed.length} files)`);
  }
  // (scripts/wingspline.mjs is the package's command, `npx wingspline grade`; no other script ships)
  const stray = packed.filter((f) => (/^(tests|build|node_modules|core|scripts|web)\//.test(f) && f !== 'scripts/wingspline.mjs') || f.endsWith('.tgz'));
  assert.deepEqual(stray, [], 'no tests, build output, sources or dependencies in the tarball');
  const manifest = JSON.parse(fs.readFileSync(path.join(installed, 'package.json'), 'utf8'));
  // QuickJS for the code sandbox (web/js/code/), pinned: the grader runs submissions in it.
  assert.deepEqual(manifest.dependencies, { '@jitl/quickjs-wasmfile-release-sync': '0.32.0', 'quickjs-emscripten-core': '0.32.0' });
  for (const file of ['dist/js/code/sandbox-worker.js', 'dist/js/code/runner.js', 'dist/wasm/quickjs.wasm']) {
    assert.ok(packed.includes(file), `${file} is in the tarball`);
  }
});

test('installed in an empty folder, `import { loadWingspline } from \'wingspline\'` works in Node: a curve point, the slide\'s walk, dispose', () => {
  const app = path.dirname(path.dirname(installed));
  fs.copyFileSync(path.join(pageDir, 'probe.mjs'), path.join(app, 'probe.mjs'));
  fs.writeFileSync(path.join(app, 'homework.mjs'), [
    "import { loadWingspline, WingsplineError } from 'wingspline';",
    "import { probe } from './probe.mjs';",
    'const result = await probe(loadWingspline);',
    "result.errorClass = typeof WingsplineError === 'function' && WingsplineError.name;",
    'process.stdout.write(JSON.stringify(result));',
  ].join('\n'));
  const result = JSON.parse(execFileSync(process.execPath, ['homework.mjs'], { cwd: app, encoding: 'utf8' }));
  checkProbe(result);
  assert.equal(result.errorClass, 'WingsplineError');
  assert.match(result.version, /\d/);
});

test('installed, the package says where it comes from and exports its manifest and its wasm: both resolve by name, from import and require', () => {
  const app = path.dirname(path.dirname(installed));
  const manifest = JSON.parse(fs.readFileSync(path.join(installed, 'package.json'), 'utf8'));
  // What a registry user expects to find (npm's package.json fields): a repository, a home page,
  // where to report bugs, keywords and an author, and a changelog in the tarball.
  assert.equal(manifest.repository?.type, 'git');
  assert.match(manifest.repository?.url ?? '', /^git\+https:\/\/\S+\.git$/);
  assert.match(manifest.homepage ?? '', /^https:\/\//);
  assert.match(manifest.bugs?.url ?? '', /^https:\/\/\S+\/issues$/);
  assert.ok(Array.isArray(manifest.keywords) && manifest.keywords.includes('webassembly') && manifest.keywords.includes('winged-edge'));
  assert.ok(typeof manifest.author === 'string' && manifest.author.length > 0);
  assert.ok(packed.includes('CHANGELOG.md'), 'the changelog is in the tarball');
  // The core's modules (one per lesson group, docs/architecture.md "Module size"), each
  // exported as its wasm file: found by import and by require, and each a valid module.
  const modules = ['wingspline-mesh', 'wingspline-subdivision', 'wingspline-meshes', 'wingspline-curves', 'wingspline-exercises'];
  fs.writeFileSync(path.join(app, 'resolve.mjs'), [
    "import { createRequire } from 'node:module';",
    "import { fileURLToPath } from 'node:url';",
    'const require = createRequire(import.meta.url);',
    `const modules = ${JSON.stringify(modules)};`,
    'process.stdout.write(JSON.stringify({',
    "  manifest: fileURLToPath(import.meta.resolve('wingspline/package.json')),",
    "  requiredManifest: require.resolve('wingspline/package.json'),",
    "  wasm: modules.map((m) => fileURLToPath(import.meta.resolve(`wingspline/dist/wasm/${m}.wasm`))),",
    "  requiredWasm: modules.map((m) => require.resolve(`wingspline/dist/wasm/${m}.wasm`)),",
    '}));',
  ].join('\n'));
  const found = JSON.parse(execFileSync(process.execPath, ['resolve.mjs'], { cwd: app, encoding: 'utf8' }));
  const real = (file) => fs.realpathSync(file);
  assert.equal(real(found.manifest), real(path.join(installed, 'package.json')));
  assert.equal(real(found.requiredManifest), real(path.join(installed, 'package.json')));
  modules.forEach((m, i) => {
    assert.equal(real(found.wasm[i]), real(path.join(installed, 'dist', 'wasm', `${m}.wasm`)));
    assert.equal(real(found.requiredWasm[i]), real(found.wasm[i]));
    const wasm = fs.readFileSync(found.wasm[i]);
    assert.deepEqual([...wasm.subarray(0, 4)], [0x00, 0x61, 0x73, 0x6d], `${m}.wasm is a wasm module (\\0asm)`);
    assert.ok(WebAssembly.validate(wasm), `${m}.wasm is a valid one`);
  });
});

test('installed, the declarations reach a TypeScript student through the package\'s exports: a right use type-checks, a misuse does not', () => {
  const app = path.dirname(path.dirname(installed));
  const tsc = path.join(repoRoot, 'node_modules', 'typescript', 'bin', 'tsc');
  const run = () => spawnSync(process.execPath, [tsc, '--noEmit', '--pretty', 'false', '--strict', '--module', 'nodenext',
    '--moduleResolution', 'nodenext', '--target', 'es2022', '--lib', 'es2022', '--types', '', 'check.mts'], { cwd: app, encoding: 'utf8' });
  const head = "import { loadWingspline, type Curve } from 'wingspline';\nconst api = await loadWingspline();\n"
    + "const c: Curve = { kind: 'bezier', dim: 2, points: [0, 0, 1, 1] };\n";
  fs.writeFileSync(path.join(app, 'check.mts'), `${head}const p: Float64Array = api.evaluateCurve(c, [0.5]);\nexport { p };\n`);
  const right = run();
  assert.equal(right.status, 0, right.stdout + right.stderr);
  fs.writeFileSync(path.join(app, 'check.mts'), `${head}api.evaluateCurve(c, 'half');\n`);
  const wrong = run();
  assert.notEqual(wrong.status, 0);
  assert.match(wrong.stdout, /check\.mts\(4,\d+\): error TS2345/, wrong.stdout);
});

test('the installed dist/ served as it is works from a page without a bundler (headless Chromium)', async () => {
  const site = await startSite({ root: path.join(installed, 'dist'), overlays: [pageDir] });
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage();
    const problems = [];
    page.on('pageerror', (err) => problems.push(err.message));
    page.on('console', (msg) => { if (msg.type() === 'error') problems.push(msg.text()); });
    await page.goto(new URL('probe.html', site.url).href);
    await page.waitForSelector('body[data-result]', { state: 'attached', timeout: 15000 }).catch((err) => { throw new Error(`${err.message}; page problems: ${problems.join(' | ')}`); });
    checkProbe(JSON.parse(await page.getAttribute('body', 'data-result')));
    assert.deepEqual(problems, []);
  } finally {
    await browser.close();
    await site.close();
  }
});

// ---- `npx wingspline grade`, from the installed package in its empty folder. The lecturer's
// exercise files are the gallery's; the submissions are written here by hand in the documented
// format (docs/exercises.md), with the hashes and digests computed here with node:crypto (the
// SHA-256 of the JSON text), and right answers worked out from the lectures.
const sha = (text) => `sha256-${createHash('sha256').update(text).digest('hex')}`;
const galleryFile = (id) => fs.readFileSync(path.join(repoRoot, 'web', 'exercises', `${id}.json`), 'utf8');
const exerciseSha = (id) => sha(JSON.stringify(JSON.parse(galleryFile(id))));
function submissionText({ student, exercises, tamper }) {
  const body = { format: 'wingspline-submission', version: 1, app: '0.1.0', student, madeAt: '2026-11-27T21:00:00.000Z', exercises };
  const file = { ...body, digest: sha(JSON.stringify(body)) };
  if (tamper) tamper(file);
  return JSON.stringify(file, null, 2);
}
const entry = (id, answer, extra = {}) => ({ id, hash: exerciseSha(id), title: id, lesson: id.split('-')[0], kind: '', feedback: 'check', status: 'started', checks: 2, hintsShown: 0, sawWorked: false, answer, ...extra });

// Lecture 003's Hermite matrix times the geometry [P0 P1 R0 R1] (x), first row: 2 -2 1 1.
function hermiteMgFirstEntry() {
  const { state } = JSON.parse(galleryFile('comparison-hermite-mg'));
  const [p0, p1] = state.points;
  const [r0, r1] = state.hermite.own;
  return 2 * p0[0] - 2 * p1[0] + r0[0] + r1[0];
}

test('`npx wingspline grade` in the empty folder: right, wrong, tampered, damaged, oversized and other-version files each get their row; the CSV runs nothing', () => {
  const app = path.dirname(path.dirname(installed));
  const work = path.join(app, 'course');
  const exercises = path.join(work, 'homework-3');
  const uploads = path.join(work, 'uploads');
  for (const dir of [exercises, path.join(uploads, 'ada'), path.join(uploads, 'bob'), path.join(uploads, 'eve'), path.join(uploads, 'zed')]) fs.mkdirSync(dir, { recursive: true });
  const ids = ['comparison-hermite-mg', 'mesh-walk-along-f1', 'subdivision-catmull-clark-cube-counts', 'mesh-edit-flip-e3'];
  for (const id of ids) fs.writeFileSync(path.join(exercises, `${id}.json`), galleryFile(id));
  const mg = hermiteMgFirstEntry();
  assert.ok(Math.abs(mg - 1.4) < 1e-12, `the M G entry of the lecture's formula: ${mg}`);
  // The walk along F1 as the slide's tables give it, predicted from its second edge on, then
  // back to the first (the walk closes); picks are edge numbers as the page shows them (e5 = 5).
  const walk = slideWalk('face', 'F1').map((e) => Number(e.slice(1)));
  const picks = [...walk.slice(1), walk[0]];
  // One Catmull-Clark step of the cube (V 8, E 12, F 6 quads; lecture 004): a new point per
  // vertex, edge and face; each quad becomes four, each edge two plus one per face side.
  const [V, E, F, corners] = [8, 12, 6, 24];
  const counts = { vertices: String(V + E + F), edges: String(2 * E + corners), faces: String(corners) };
  // The rows flip e3 rewrites, worked by hand from lecture 000's conventions (FLIP_E3): the
  // answer as the edit kind keeps it, per table its rows' cells as typed.
  const flip = (cells) => Object.fromEntries(Object.entries(cells).map(([t, rows]) => [t, { cells: rows, removed: rows.map(() => false), labels: [] }]));
  const wrongFlip = { ...FLIP_E3, edges: FLIP_E3.edges.map((row, r) => (r === 2 ? row.map((c, k) => (k === 4 ? 'e2' : c)) : row)) };
  fs.writeFileSync(path.join(uploads, 'ada', 'wingspline-submission-ada.json'), submissionText({ student: 'Ada Lovelace', exercises: [
    entry('comparison-hermite-mg', String(mg)), entry('mesh-walk-along-f1', { picks }, { status: 'solved' }),
    entry('subdivision-catmull-clark-cube-counts', counts), entry('mesh-edit-flip-e3', flip(FLIP_E3))] }));
  fs.writeFileSync(path.join(uploads, 'bob', 'wingspline-submission-bob.json'), submissionText({ student: 'Bob', exercises: [entry('comparison-hermite-mg', '3'),
    entry('subdivision-catmull-clark-cube-counts', { ...counts, edges: String(2 * E) }), entry('mesh-edit-flip-e3', flip(wrongFlip))] }));
  // Eve's file: edited after export (her wrong answer marked solved), a name made to run in a spreadsheet.
  fs.writeFileSync(path.join(uploads, 'eve', 'wingspline-submission-eve.json'), submissionText({
    student: '=HYPERLINK("http://example.invalid","x")', exercises: [entry('comparison-hermite-mg', '3'), entry('mesh-walk-along-f1', { picks: [walk[0]] })],
    tamper: (f) => { f.exercises[0].status = 'solved'; f.exercises[0].checks = 1; } }));
  // Zed: an answer to another version of the M G exercise; a damaged file; a file far too large.
  fs.writeFileSync(path.join(uploads, 'zed', 'a-other-version.json'), submissionText({ student: 'Zed', exercises: [
    entry('comparison-hermite-mg', String(mg), { hash: sha('an older version') })] }));
  fs.writeFileSync(path.join(uploads, 'zed', 'b-cut.json'), submissionText({ student: 'Zed', exercises: [] }).slice(0, 60));
  fs.writeFileSync(path.join(uploads, 'zed', 'c-huge.json'), ' '.repeat(5 * 1024 * 1024));
  // Mallory uploads exercise files: one with the id of the lecturer's M G exercise whose answer
  // is now 3, one of a new id. Neither replaces nor adds an exercise: each is a row.
  fs.mkdirSync(path.join(uploads, 'mallory'), { recursive: true });
  const forged = JSON.parse(galleryFile('comparison-hermite-mg'));
  forged.question = `${forged.question} (forged)`;
  forged.state.points[0][0] += (3 - mg) / 2; // the first entry of M G is then 3
  fs.writeFileSync(path.join(uploads, 'mallory', 'comparison-hermite-mg.json'), JSON.stringify(forged));
  fs.writeFileSync(path.join(uploads, 'mallory', 'bonus.json'), JSON.stringify({ ...forged, id: 'bonus-exercise' }));

  const out = path.join(work, 'grades');
  const r = spawnSync('npx', ['--offline', 'wingspline', 'grade', 'homework-3', 'uploads', '--out', out], { cwd: work, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  assert.match(r.stdout, /Graded 8 submission files against 4 exercises: 4 of 20 answers right/);
  const rows = csvObjects(fs.readFileSync(path.join(out, 'gradebook.csv'), 'utf8'));
  const at = (file, exercise) => rows.find((x) => x['submission file'].endsWith(file) && x.exercise === exercise);
  const ada = at('ada.json', 'comparison-hermite-mg');
  assert.equal(ada.result, 'right');
  assert.equal(ada.score, '1');
  assert.match(ada.note, /name as typed in the file .*ada\.json; not verified/);
  assert.equal(at('ada.json', 'mesh-walk-along-f1').result, 'right');
  assert.equal(at('ada.json', 'subdivision-catmull-clark-cube-counts').result, 'right');
  assert.equal(at('ada.json', 'mesh-edit-flip-e3').result, 'right');
  const bobEdit = at('bob.json', 'mesh-edit-flip-e3');
  assert.equal(bobEdit.result, 'wrong');
  assert.match(bobEdit.reason, /Row e3, column S:L/);
  assert.doesNotMatch(bobEdit.reason, /\be5\b/, 'the right wing (e5) is not told');
  const bobCounts = at('bob.json', 'subdivision-catmull-clark-cube-counts');
  assert.equal(bobCounts.result, 'wrong');
  assert.ok(!bobCounts.reason.includes(counts.edges), `the reason does not give E: ${bobCounts.reason}`);
  const bob = at('bob.json', 'comparison-hermite-mg');
  assert.equal(bob.result, 'wrong');
  assert.equal(bob.score, '0');
  assert.ok(bob.reason.length > 0, 'a wrong answer has its reason');
  assert.ok(!bob.reason.includes('1.4'), `the reason does not give the value: ${bob.reason}`);
  assert.equal(at('bob.json', 'mesh-walk-along-f1').result, 'not handed in');
  const eve = at('eve.json', 'comparison-hermite-mg');
  assert.equal(eve.result, 'wrong');
  assert.match(eve.note, /changed after it was exported/);
  assert.match(eve.note, /the file says solved; the check says not/);
  assert.equal(eve['student (as typed, unverified)'], '\'=HYPERLINK("http://example.invalid","x")', 'the name is text, not a formula');
  assert.equal(at('eve.json', 'mesh-walk-along-f1').result, 'wrong', 'a walk stopped after one edge is not the walk');
  assert.equal(at('a-other-version.json', 'comparison-hermite-mg').result, 'answered a different version');
  assert.equal(rows.filter((x) => x['submission file'].endsWith('b-cut.json'))[0].result, 'damaged file');
  assert.match(rows.filter((x) => x['submission file'].endsWith('c-huge.json'))[0].reason, /5\.0 MB; a submission is at most 4\.0 MB/);
  for (const name of ['mallory/comparison-hermite-mg.json', 'mallory/bonus.json']) {
    const mine = rows.filter((x) => x['submission file'].endsWith(name));
    assert.equal(mine.length, 1, `${name}: one row`);
    assert.equal(mine[0].result, 'an exercise file among the submissions');
  }
  assert.ok(!rows.some((x) => x.exercise === 'bonus-exercise'), 'an uploaded exercise adds no exercise');
  // The totals, one row per submission file, for the course's gradebook.
  const totals = csvObjects(fs.readFileSync(path.join(out, 'gradebook-totals.csv'), 'utf8'));
  const adaTotal = totals.find((x) => x['submission file'].endsWith('ada.json'));
  assert.deepEqual([adaTotal.right, adaTotal.of, adaTotal.percent], ['4', '4', '100']);
  const bobTotal = totals.find((x) => x['submission file'].endsWith('bob.json'));
  assert.deepEqual([bobTotal.right, bobTotal.of, bobTotal.percent], ['0', '4', '0']);
  assert.equal(totals.length, 8);
  // No cell of the CSV starts with a character a spreadsheet would run.
  for (const row of rows) for (const [k, v] of Object.entries(row)) assert.ok(!/^[=+\-@]/.test(v), `${k}: ${v}`);
  const md = fs.readFileSync(path.join(out, 'gradebook.md'), 'utf8');
  assert.match(md, /^# Gradebook/);
  assert.match(md, /wingspline\\-submission\\-ada\\\.json \| Ada Lovelace \| 4 \| 4 \|/);

  // Without the exercise files: told, and a non-zero exit.
  const none = spawnSync('npx', ['--offline', 'wingspline', 'grade', 'uploads/bob'], { cwd: work, encoding: 'utf8' });
  assert.equal(none.status, 1);
  assert.match(none.stderr, /no exercise file could be used/);
  const help = spawnSync('npx', ['--offline', 'wingspline', '--help'], { cwd: work, encoding: 'utf8' });
  assert.match(help.stdout, /Usage: wingspline grade/);
});

// Code handed in: the code exercise's submissions hold the code lesson's state (the code per
// task), and the installed grader runs it in the package's QuickJS sandbox (its runtime
// dependencies, installed from the local npm cache like the rest).
test('`npx wingspline grade` over a folder of code submissions: the lecture\'s rule right, the starter and an endless loop wrong with their reasons', () => {
  const app = path.dirname(path.dirname(installed));
  const work = path.join(app, 'course-code');
  const exercises = path.join(work, 'homework-code');
  const uploads = path.join(work, 'uploads');
  fs.mkdirSync(exercises, { recursive: true });
  fs.mkdirSync(uploads, { recursive: true });
  const id = 'code-edges-around-vertex';
  fs.writeFileSync(path.join(exercises, `${id}.json`), galleryFile(id));
  const { state } = JSON.parse(galleryFile(id));
  const handIn = (student, code) => submissionText({ student, exercises: [entry(id, null, { kind: 'code', lesson: 'code', state: { ...state, code } })] });
  fs.writeFileSync(path.join(uploads, 'grace.json'), handIn('Grace', { 'edges-around-vertex': CORRECT['edges-around-vertex'] }));
  fs.writeFileSync(path.join(uploads, 'alan.json'), handIn('Alan', {}));
  fs.writeFileSync(path.join(uploads, 'mallory.json'), handIn('Mallory', { 'edges-around-vertex': 'function edgesAroundVertex(mesh, v) {\n  while (true) {}\n}' }));
  const out = path.join(work, 'grades');
  const started = Date.now();
  const r = spawnSync('npx', ['--offline', 'wingspline', 'grade', 'homework-code', 'uploads', '--out', out], { cwd: work, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  assert.match(r.stdout, /Graded 3 submission files against 1 exercise: 1 of 3 answers right/);
  const rows = csvObjects(fs.readFileSync(path.join(out, 'gradebook.csv'), 'utf8'));
  const of = (file) => rows.find((x) => x['submission file'].endsWith(file));
  assert.equal(of('grace.json').result, 'right');
  // The starter returns []: the slide's v2 is asked first (its walk is e6 e5 e3 e2).
  assert.equal(of('alan.json').result, 'wrong');
  assert.match(of('alan.json').reason, /^On the slide's mesh \(lecture 000\), v2: your function returned \[\]\./);
  assert.equal(of('mallory.json').result, 'wrong');
  assert.match(of('mallory.json').reason, /line 2/i);
  // The endless loop costs one mesh's budget (1.5 s), not one per mesh.
  assert.ok(Date.now() - started < 60_000, `${Date.now() - started} ms`);
});
