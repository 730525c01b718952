// @ts-check
/// <reference types="node" />
// The one JavaScript entry to the Wingspline core: `import { loadWingspline } from
// 'wingspline'` in Node, `import { loadWingspline } from './js/core/wingspline.js'` in a
// page. It loads the wasm module once and returns a plain API object; the raw embind
// names stay private to this folder. It runs in Node too (the reference above declares
// `process` and `node:fs/promises` for the type check).
import createWingsplineCore from '../../wasm/wingspline-core.js';
import { WingsplineError } from './errors.js';
import { createApi } from './api.js';

export { WingsplineError } from './errors.js';

let loading = null;

const isNode = typeof process !== 'undefined' && !!process.versions?.node && typeof window === 'undefined';

// Where the site serves the core, as a person would look for it.
const WASM_FILE = 'wasm/wingspline-core.wasm';
const WASM_URL = new URL('../../wasm/wingspline-core.wasm', import.meta.url);

function coreLoadError(reason) {
  return new WingsplineError('core-load-failed', `The geometry core (${WASM_FILE}) could not be loaded: ${reason}. `
    + 'Check that the file is served, with type application/wasm, and reload.');
}

// Emscripten reports failures as "Aborted(<reason>). Build with -s ASSERTIONS=1 ...": keep the reason.
function plainReason(err) {
  const text = String(err?.message ?? err);
  return text.match(/^Aborted\((.*)\)(?:\. Build with .*)?$/s)?.[1] ?? text;
}

// Fetches and compiles the wasm file ourselves (rather than in Emscripten's glue, which
// aborts with its own wording), so a failure names the file and the reason.
async function compileInBrowser() {
  let response;
  try {
    response = await fetch(WASM_URL, { credentials: 'same-origin' });
  } catch (err) {
    throw coreLoadError(`the request failed (${err.message}); the page may be offline or the server unreachable`);
  }
  if (!response.ok) {
    throw coreLoadError(`the server answered ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`);
  }
  try {
    // Stream-compiled when served as application/wasm; any other type still compiles from the bytes.
    const streaming = /^application\/wasm\b/i.test(response.headers.get('content-type') ?? '');
    return streaming ? await WebAssembly.compileStreaming(response) : await WebAssembly.compile(await response.arrayBuffer());
  } catch (err) {
    if (err instanceof WebAssembly.CompileError) throw coreLoadError(`the file is not valid WebAssembly (${err.message})`);
    throw coreLoadError(`reading the file failed (${err.message})`);
  }
}

function instantiateInBrowser(module) {
  return new Promise((resolve, reject) => {
    createWingsplineCore({
      instantiateWasm(imports, receive) {
        WebAssembly.instantiate(module, imports).then((instance) => {
          try {
            receive(instance, module);
          } catch (err) {
            reject(err);
          }
        }, (err) => reject(coreLoadError(`it does not fit this page's scripts (${err.message}); the site's files may come from different builds`)));
        return {};
      },
    }).then(resolve, reject);
  });
}

async function instantiate() {
  if (!isNode) return instantiateInBrowser(await compileInBrowser());
  // Emscripten 3.1.6's glue would call Node's fetch() on a file path; hand it the bytes.
  const { readFile } = await import('node:fs/promises');
  return createWingsplineCore({ wasmBinary: await readFile(WASM_URL) });
}

// Resolves to the API object; every call after the first returns the same object.
export function loadWingspline() {
  if (!loading) {
    loading = instantiate().then(createApi).catch((err) => {
      loading = null;
      if (err instanceof WingsplineError) throw err;
      throw new WingsplineError('core-load-failed', `The geometry core (${WASM_FILE}) could not be started: ${plainReason(err)}. `
        + 'Reload the page; if this happens again, the site\'s files may come from different builds.');
    });
  }
  return loading;
}
