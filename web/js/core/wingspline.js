// The one JavaScript entry to the Wingspline core: `import { loadWingspline } from
// 'wingspline'` in Node, `import { loadWingspline } from './js/core/wingspline.js'` in a
// page. It loads the wasm module once and returns a plain API object; the raw embind
// names stay private to this folder.
import createWingsplineCore from '../../wasm/wingspline-core.js';
import { unwrap } from './errors.js';
import { createMeshApi } from './mesh-api.js';
import { createCurvesApi } from './curves-api.js';

export { WingsplineError } from './errors.js';

let loading = null;

const isNode = typeof process !== 'undefined' && !!process.versions?.node && typeof window === 'undefined';

async function instantiate() {
  const options = {};
  if (isNode) {
    // Emscripten 3.1.6's glue would call Node's fetch() on a file path; hand it the bytes.
    const { readFile } = await import('node:fs/promises');
    options.wasmBinary = await readFile(new URL('../../wasm/wingspline-core.wasm', import.meta.url));
  }
  return createWingsplineCore(options);
}

function createApi(raw) {
  const version = raw.version();
  return Object.freeze({
    version,
    // {linearBytes: size of the wasm memory, heapInUse: bytes malloc has handed out}; the
    // leak tests of both cores watch heapInUse across thousands of calls.
    memoryUsage() {
      const { linearBytes, heapInUse } = unwrap(raw.memoryUsage());
      return { linearBytes, heapInUse };
    },
    ...createMeshApi(raw),
    ...createCurvesApi(raw),
  });
}

// Resolves to the API object; every call after the first returns the same object.
export function loadWingspline() {
  if (!loading) {
    loading = instantiate().then(createApi).catch((err) => {
      loading = null;
      throw err;
    });
  }
  return loading;
}
