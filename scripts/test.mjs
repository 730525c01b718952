// npm test: set up, build, then run the test layers and print one summary.
//   types    tsc --noEmit -p jsconfig.json: the shell and every lesson.js against the JSDoc
//            lesson contract (web/js/app/contract.js); tsc -p tsconfig.examples.json: the
//            package's declarations (types/) against examples/ and deliberate misuses
//   scripts  node --test tests/scripts (how these layers count node:test results)
//   native   Catch2 (build/native, built by the layer: build() makes only the wasm module and dist/)
//   wasm     node --test tests/wasm   (the JS API over the wasm module)
//   lessons  node --test tests/lessons (the DOM-free lesson modules over the real core)
//   package  node --test tests/package (npm pack + install + import, examples/, npm start)
//   browser  node --test tests/browser (playwright-core + Debian's Chromium)
//   asan     the native suite again under ASan + UBSan (build/native-asan, built by the layer)
//   fuzz     libFuzzer targets, a few seconds each (build/fuzz, clang++-14, built by the layer)
// The layers are listed in scripts/lib/test-layers.mjs. A node:test layer is counted from
// node:test's events (scripts/lib/count-reporter.mjs), whichever reporter Node prints.
import { setup } from './setup.mjs';
import { build } from './build.mjs';
import { log } from './lib/run.mjs';
import { layers } from './lib/test-layers.mjs';

const only = process.argv.slice(2);
try {
  await setup();
  await build();
} catch (err) {
  process.stderr.write(`[wingspline] ${err.message}\n`);
  process.exit(1);
}

const results = [];
for (const layer of layers) {
  if (only.length > 0 && !only.includes(layer.name)) continue;
  log(`--- ${layer.name} tests ---`);
  const started = Date.now();
  const r = await layer.run();
  results.push({ name: layer.name, ...r, seconds: (Date.now() - started) / 1000 });
}

const failed = results.filter((r) => r.code !== 0 || r.fail > 0 || r.pass === 0);
process.stdout.write('\n[wingspline] test summary\n');
for (const r of results) {
  const status = failed.includes(r) ? 'FAIL' : 'ok  ';
  process.stdout.write(`  ${status} ${r.name.padEnd(9)} ${String(r.pass).padStart(5)} passed  ` +
    `${String(r.fail).padStart(3)} failed  ${String(r.skip ?? 0).padStart(3)} skipped  ` +
    `(${r.seconds.toFixed(1)} s)\n`);
}
const total = results.reduce((a, r) => ({ pass: a.pass + r.pass, fail: a.fail + r.fail }), { pass: 0, fail: 0 });
process.stdout.write(`  total: ${total.pass} passed, ${total.fail} failed\n`);
if (failed.length > 0) {
  process.stdout.write(`[wingspline] FAILED: ${failed.map((r) => r.name).join(', ')}` +
    ' (a layer with zero passing tests also counts as failed)\n');
  process.exit(1);
}
process.stdout.write('[wingspline] all tests passed\n');
