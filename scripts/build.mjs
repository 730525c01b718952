// Builds what serving the site needs, incrementally (CMake decides what is stale):
//   build/wasm    the core + bindings -> wingspline-core.{js,wasm} (em++)
//   dist/         the static site: web/ plus the wasm module under dist/wasm/
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
    if (!fs.existsSync(path.join(buildDir, 'CMakeCache.txt'))) {
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

// The shipped module (wingspline-core: what the site serves); with bench, also the bench
// module (wingspline-core-bench: the same bindings and flags plus core/bench), which
// `npm run bench` and the wasm tests of the benchmark's hooks load.
export async function buildWasm({ bench = false } = {}) {
  await cmakeBuild('wasm', (buildDir) => must('emcmake',
    ['cmake', '-S', repoRoot, '-B', buildDir, '-DCMAKE_BUILD_TYPE=Release']),
  ['wingspline-core', ...(bench ? ['wingspline-core-bench'] : [])]);
}

// Copies src into dst where size or mtime differ; removes what src no longer has.
// `keep`: names in dst written by other steps; `skip`: names in src that are not copied.
function mirror(src, dst, keep = new Set(), skip = new Set()) {
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
      mirror(from, to);
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
  return lessons.map((lesson) => ({ file: lesson.page, html: lessonPage(lesson) }));
}

export function assembleSite() {
  return withBuildLock('dist', assembleSiteNow);
}

async function assembleSiteNow() {
  const dist = path.join(repoRoot, 'dist');
  const pages = await lessonPages();
  // The guides (dist/guide/, from docs/ by scripts/lib/guides.mjs) are pages like the lessons'.
  pages.push(...guidePages());
  mirror(path.join(repoRoot, 'web'), dist, new Set(['wasm', 'sw-manifest.js', 'guide', ...pages.map((p) => p.file)]), new Set(['templates']));
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
  for (const file of ['wingspline-core.js', 'wingspline-core.wasm']) {
    const from = path.join(repoRoot, 'build', 'wasm', file);
    const to = path.join(wasmOut, file);
    const old = fs.existsSync(to) ? fs.statSync(to) : null;
    const st = fs.statSync(from);
    if (!old || old.size !== st.size || old.mtimeMs < st.mtimeMs) fs.copyFileSync(from, to);
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
