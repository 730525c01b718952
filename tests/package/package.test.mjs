// Package and scripts: `npm pack` gives a tarball a student installs in an empty
// folder; `import { loadWingspline } from 'wingspline'` then works in Node, and the same
// installed files work from a page without a bundler. Packed once and installed once
// (offline: the package has no runtime dependencies) for the whole file.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync, spawnSync } from 'node:child_process';
import { repoRoot, startSite, launchBrowser } from '../helpers/browser.mjs';

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
    'dist/wasm/wingspline-core.js', 'dist/wasm/wingspline-core.wasm', 'dist/index.html', 'types/wingspline.d.ts']) {
    assert.ok(packed.includes(file), `${file} is in the tarball (it holds ${packed.length} files)`);
  }
  const stray = packed.filter((f) => /^(tests|build|node_modules|core|scripts|web)\//.test(f) || f.endsWith('.tgz'));
  assert.deepEqual(stray, [], 'no tests, build output, sources or dependencies in the tarball');
  const manifest = JSON.parse(fs.readFileSync(path.join(installed, 'package.json'), 'utf8'));
  assert.deepEqual(Object.keys(manifest.dependencies ?? {}), [], 'no runtime dependencies: it installs offline');
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
