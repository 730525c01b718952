// Builds what serving the site needs, incrementally (CMake decides what is stale):
//   build/wasm    the core + bindings -> wingspline-{mesh,subdivision,curves,exercises}.{js,wasm},
//                 a module per lesson group and one for the exercise checkers (em++)
//   dist/         the static site: web/ with its scripts and style sheets minified (esbuild:
//                 whitespace, comments and local names; every file keeps its path and its
//                 imports), each lesson page's scripts bundled under dist/js/bundle/, and the
//                 wasm modules under dist/wasm/; the code sandbox's worker bundled with QuickJS
//                 (dist/js/code/sandbox-worker.js) and QuickJS's wasm (dist/wasm/quickjs.wasm)
// `npm start` and `npm test` run build(). The native build (build/native: the core, the
// Catch2 tests and the native benchmark, g++) is buildNative(), run by what needs it: the
// native test layer (scripts/lib/test-layers.mjs) and `npm run bench`; the sanitizer and
// fuzz builds are their layers' own. Each CMake build and the site assembly holds its lock
// (scripts/lib/build-lock.mjs), so two project commands at once never write one folder.
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { repoRoot, log, must } from './lib/run.mjs';
import { withBuildLock } from './lib/build-lock.mjs';
import { writeServiceWorkerManifest } from './lib/site-manifest.mjs';
import { lessonPage } from './lib/lesson-page.mjs';
import { exerciseIndex } from './lib/exercise-index.mjs';
import { guidePages } from './lib/guides.mjs';

const jobs = ['-j', '2'];

function cmakeBuild(dir, configure, targets = []) {
  const buildDir = path.join(repoRoot, 'build', dir);
  return withBuildLock(dir, async () => {
    // Configured again when CMakeLists.txt changed since: a target it adds is unknown to the
    // old build files, and `cmake --build --target` stops before re-running cmake itself.
    const cache = path.join(buildDir, 'CMakeCache.txt');
    if (!fs.existsSync(cache) || fs.statSync(path.join(repoRoot, 'CMakeLists.txt')).mtimeMs > fs.statSync(cache).mtimeMs) {
      log(`configuring build/${dir}`);
      await configure(buildDir);
    }
    log(`building build/${dir}`);
    await must('cmake', ['--build', buildDir, ...jobs, ...targets.flatMap((t) => ['--target', t])]);
  });
}

export async function buildNative({ sanitize = false } = {}) {
  const dir = sanitize ? 'native-asan' : 'native';
  await cmakeBuild(dir, (buildDir) => must('cmake', ['-S', repoRoot, '-B', buildDir,
    '-DCMAKE_BUILD_TYPE=' + (sanitize ? 'Debug' : 'Release'),
    ...(sanitize ? ['-DWINGSPLINE_SANITIZE=ON'] : [])]));
}

// The shipped modules (wingspline-mesh, -subdivision, -curves, -exercises: what the site
// serves, one per lesson group and one for the exercise checkers; -meshes: every mesh
// binding, for the package's whole API, no page loads it); with bench, also the bench module (wingspline-core-bench: every binding with
// the same flags plus core/bench), which `npm run bench` and the wasm tests of the
// benchmark's hooks load.
export const SHIPPED_MODULES = ['wingspline-mesh', 'wingspline-subdivision', 'wingspline-meshes', 'wingspline-curves', 'wingspline-exercises'];
export async function buildWasm({ bench = false } = {}) {
  await cmakeBuild('wasm', (buildDir) => must('emcmake',
    ['cmake', '-S', repoRoot, '-B', buildDir, '-DCMAKE_BUILD_TYPE=Release']),
  [...SHIPPED_MODULES, ...(bench ? ['wingspline-core-bench'] : [])]);
}

// What the site serves of a script or a style sheet: the same code without its comments,
// whitespace and long local names (esbuild's minifier; names are kept for stack traces and
// error names, and nothing is bundled, so every module keeps its path and its imports).
// The lesson pages' budget (300 KB gzip each, docs/architecture.md "Module size") counts
// what is served; the readable source stays in web/.
// esbuild is a dev dependency that setup() installs, so it is imported when the site is
// assembled, not when this file is: `npm test` on a clean clone imports this file first.
function minified(esbuild, name, text) {
  const loader = name.endsWith('.css') ? 'css' : 'js';
  return esbuild.transformSync(text, { loader, minify: true, legalComments: 'none', target: 'es2022' }).code;
}
const MINIFIED = /\.(m?js|css)$/;

// Copies src into dst where size or mtime differ; removes what src no longer has. Scripts and
// style sheets are written minified, with the source's mtime, and rewritten when it changes.
// `keep`: names in dst written by other steps; `skip`: names in src that are not copied.
function mirror(esbuild, src, dst, keep = new Set(), skip = new Set()) {
  fs.mkdirSync(dst, { recursive: true });
  const wanted = new Set(fs.readdirSync(src).filter((name) => !skip.has(name)));
  for (const name of fs.readdirSync(dst)) {
    if (!wanted.has(name) && !keep.has(name)) fs.rmSync(path.join(dst, name), { recursive: true, force: true });
  }
  for (const name of wanted) {
    const from = path.join(src, name);
    const to = path.join(dst, name);
    const st = fs.statSync(from);
    if (st.isDirectory()) {
      mirror(esbuild, from, to);
    } else if (MINIFIED.test(name)) {
      const old = fs.existsSync(to) ? fs.statSync(to) : null;
      if (!old || old.mtimeMs !== st.mtimeMs) {
        fs.writeFileSync(to, minified(esbuild, name, fs.readFileSync(from, 'utf8')));
        fs.utimesSync(to, st.atime, st.mtime);
      }
    } else {
      const old = fs.existsSync(to) ? fs.statSync(to) : null;
      if (!old || old.size !== st.size || old.mtimeMs < st.mtimeMs) {
        fs.copyFileSync(from, to);
      }
    }
  }
}

// Every lesson page is the one frame (web/templates/lesson.html) with the lesson's id and
// title from the registry, so the pages cannot drift apart.
async function lessonPages() {
  const { lessons } = await import(pathToFileURL(path.join(repoRoot, 'web', 'js', 'lessons', 'registry.js')).href);
  return lessons.map((lesson) => ({ id: lesson.id, file: lesson.page, html: lessonPage({ ...lesson, script: `js/${BUNDLE_DIR}/${lesson.id}.js` }) }));
}

// Each lesson page runs one bundle of its module graph (dist/js/bundle/<id>.js), minified,
// with the code the pages share in shared chunks and what a page imports on demand (the core's
// parts, the exercise player and maker) in chunks of its own, fetched when needed: one file
// compresses better than eighty, and a page's bytes are the budget's (docs/architecture.md,
// "Module size"). The folder is two levels under dist/, as web/js/<folder>/ is, so the paths
// the code builds from import.meta.url (the wasm modules, the service worker, the import
// worker) point where they do from the unbundled files. The unbundled minified files stay in
// dist/js/ for the package, the import worker and the other pages.
const BUNDLE_DIR = 'bundle';
async function bundleLessonPages(esbuild, dist, pages) {
  const outdir = path.join(dist, 'js', BUNDLE_DIR);
  fs.rmSync(outdir, { recursive: true, force: true });
  await esbuild.build({
    entryPoints: Object.fromEntries(pages.map((p) => [p.id, path.join(repoRoot, 'web', 'js', 'lessons', p.id, 'page.js')])),
    bundle: true, splitting: true, format: 'esm', outdir, chunkNames: 'chunk-[hash]',
    // WINGSPLINE_READABLE=1 keeps the bundles' names and layout, for a CPU profile that names
    // functions (the weight test then fails: the budget counts minified bytes).
    minify: process.env.WINGSPLINE_READABLE !== '1', legalComments: 'none', target: 'es2022', logLevel: 'warning',
    // The wasm glue is built into dist/wasm/, not web/; Node's modules are only reached in Node.
    external: ['../../wasm/*', 'node:*'],
  });
}

// The code sandbox's worker imports npm packages (QuickJS), so it is bundled on its own, to
// dist/js/code/sandbox-worker.js over the minified unbundled copy the mirror wrote. Its one
// address: sandbox.js asks for '../code/sandbox-worker.js' from import.meta.url, which is that
// file from dist/js/code/sandbox.js and from a lesson bundle in dist/js/bundle/ alike (both two
// folders under dist/). The worker finds the QuickJS wasm the same way, at
// '../../wasm/quickjs.wasm' (copied below from the npm package, never fetched from elsewhere).
// The service worker's manifest lists both, as every file of dist/, so the sandbox works offline.
const QUICKJS_WASM = ['@jitl', 'quickjs-wasmfile-release-sync', 'dist', 'emscripten-module.wasm'];
async function bundleSandboxWorker(esbuild, dist) {
  await esbuild.build({
    entryPoints: [path.join(repoRoot, 'web', 'js', 'code', 'sandbox-worker.js')],
    outfile: path.join(dist, 'js', 'code', 'sandbox-worker.js'),
    bundle: true, format: 'esm', platform: 'browser', minify: process.env.WINGSPLINE_READABLE !== '1',
    legalComments: 'none', target: 'es2022', logLevel: 'warning', external: ['node:*'],
  });
}

export function assembleSite() {
  return withBuildLock('dist', assembleSiteNow);
}

async function assembleSiteNow() {
  const esbuild = await import('esbuild');
  const dist = path.join(repoRoot, 'dist');
  const pages = await lessonPages();
  // The guides (dist/guide/, from docs/ by scripts/lib/guides.mjs) are pages like the lessons'
  // (their one page module is not bundled: it is not a lesson's).
  const guides = guidePages();
  mirror(esbuild, path.join(repoRoot, 'web'), dist, new Set(['wasm', 'sw-manifest.js', 'guide', ...pages.map((p) => p.file), ...guides.map((p) => p.file)]), new Set(['templates']));
  await bundleLessonPages(esbuild, dist, pages);
  await bundleSandboxWorker(esbuild, dist);
  pages.push(...guides);
  fs.mkdirSync(path.join(dist, 'guide'), { recursive: true });
  for (const name of fs.readdirSync(path.join(dist, 'guide'))) {
    if (!pages.some((p) => p.file === `guide/${name}`)) fs.rmSync(path.join(dist, 'guide', name), { recursive: true, force: true });
  }
  for (const { file, html } of pages) {
    const target = path.join(dist, file);
    if (!fs.existsSync(target) || fs.readFileSync(target, 'utf8') !== html) fs.writeFileSync(target, html);
  }
  const wasmOut = path.join(dist, 'wasm');
  fs.mkdirSync(wasmOut, { recursive: true });
  const shipped = SHIPPED_MODULES.flatMap((m) => [`${m}.js`, `${m}.wasm`]);
  // A module no longer shipped (a renamed one) leaves dist/ too.
  for (const name of fs.readdirSync(wasmOut)) if (!shipped.includes(name) && name !== 'quickjs.wasm') fs.rmSync(path.join(wasmOut, name), { force: true });
  const quickjs = path.join(repoRoot, 'node_modules', ...QUICKJS_WASM);
  const quickjsOut = path.join(wasmOut, 'quickjs.wasm');
  if (!fs.existsSync(quickjsOut) || !fs.readFileSync(quickjsOut).equals(fs.readFileSync(quickjs))) fs.copyFileSync(quickjs, quickjsOut);
  for (const file of shipped) {
    const from = path.join(repoRoot, 'build', 'wasm', file);
    const to = path.join(wasmOut, file);
    const old = fs.existsSync(to) ? fs.statSync(to) : null;
    const st = fs.statSync(from);
    if (file.endsWith('.js')) {
      // Emscripten's glue, minified as the site's scripts are (its names kept: embind reads them).
      if (!old || old.mtimeMs !== st.mtimeMs) {
        fs.writeFileSync(to, minified(esbuild, file, fs.readFileSync(from, 'utf8')));
        fs.utimesSync(to, st.atime, st.mtime);
      }
    } else if (!old || old.size !== st.size || old.mtimeMs < st.mtimeMs) fs.copyFileSync(from, to);
  }
  const index = JSON.stringify(await exerciseIndex(repoRoot), null, 1) + '\n';
  fs.mkdirSync(path.join(dist, 'exercises'), { recursive: true });
  fs.writeFileSync(path.join(dist, 'exercises', 'index.json'), index);
  writeServiceWorkerManifest(dist);
}

export async function build() {
  await buildWasm();
  await assembleSite();
  log('site assembled in dist/');
}

if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  try {
    await build();
  } catch (err) {
    process.stderr.write(`[wingspline] build failed: ${err.message}\n`);
    process.exit(1);
  }
}
