// @ts-check
// The code sandbox's module worker: loads QuickJS once (the release-sync build's wasm, served
// by the site from dist/wasm/quickjs.wasm, never fetched from elsewhere) and answers each
// {id, request} with {id, results} or {id, error} from runStudentCode. The build bundles this
// file with its npm imports into dist/js/code/sandbox-worker.js (scripts/build.mjs,
// bundleSandboxWorker), so the wasm is two folders up, as the core's modules are.
import { newQuickJSWASMModuleFromVariant, newVariant } from 'quickjs-emscripten-core';
import releaseSync from '@jitl/quickjs-wasmfile-release-sync';
import { runStudentCode } from './runner.js';

/** @typedef {import('quickjs-emscripten-core').QuickJSWASMModule} QuickJSWASMModule */

/** @param {import('./runner.js').CaseResult[]} results */
function traceBuffers(results) {
  return results.flatMap((r) => [r.trace.op, r.trace.table, r.trace.row, r.trace.field, r.trace.value, r.trace.positions].map((a) => a.buffer));
}

/** @typedef {{ addEventListener(type: 'message', listener: (event: MessageEvent) => void): void,
 *   postMessage(message: unknown, transfer: Transferable[]): void }} WorkerScope */

/** @param {WorkerScope} scope */
function serve(scope) {
  const wasmLocation = new URL('../../wasm/quickjs.wasm', import.meta.url).href;
  /** @type {Promise<QuickJSWASMModule> | null} */
  let engine = null;
  const load = () => (engine ??= newQuickJSWASMModuleFromVariant(newVariant(releaseSync, { wasmLocation })));
  // Loaded at once and announced ({ready}): the page's watchdog then times the student's code,
  // not the engine's download and compilation (slow on a school network or laptop).
  load().then(() => scope.postMessage({ ready: true }, []), (err) => {
    engine = null;
    scope.postMessage({ ready: false, message: String(err?.message ?? err) }, []);
  });
  scope.addEventListener('message', async (event) => {
    const { id, request } = event.data ?? {};
    try {
      const out = runStudentCode(await load(), request);
      // A case that broke the engine at the host level leaves it unusable: load a new one.
      if ('results' in out && out.results.some((r) => r.engineFailed)) engine = null;
      scope.postMessage({ id, ...out }, 'results' in out ? traceBuffers(out.results) : []);
    } catch (err) {
      engine = null;
      scope.postMessage({ id, error: { kind: 'engine', line: null, column: null, message: `the sandbox failed: ${err?.message ?? err}` } }, []);
    }
  });
}

serve(/** @type {WorkerScope} */ (/** @type {unknown} */ (self)));
