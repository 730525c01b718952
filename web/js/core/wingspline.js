// @ts-check
/// <reference types="node" />
// The one JavaScript entry to the Wingspline core: `import { loadWingspline } from
// 'wingspline'` in Node, `import { loadWingspline } from './js/core/wingspline.js'` in a
// page. It loads the wasm modules once each and returns a plain API object; the raw embind
// names stay private to this folder. It runs in Node too (the reference above declares
// `process` and `node:fs/promises` for the type check).
//
// The core ships in parts (docs/architecture.md, "Module size"): 'mesh' (meshes, tables,
// walks, edits), 'subdivision' (meshes, tables, walks with mesh subdivision and curve
// sampling; no edits), 'curves' (curves, continuity, comparison, surfaces) and 'exercises'
// (the checkers of every exercise kind). Each is fetched only when asked for:
// loadWingspline() gives the whole API; a lesson page asks for its own part,
// loadWingspline({ parts: ['mesh'] }), and adds 'exercises' when an exercise opens. Asked for
// both 'mesh' and 'subdivision', one module with every mesh binding is fetched instead
// (wingspline-meshes: one module holds the meshes, so a mesh can be edited and subdivided).
import { WingsplineError } from './errors.js';
import { createApi } from './api.js';

export { WingsplineError } from './errors.js';

const isNode = typeof process !== 'undefined' && !!process.versions?.node && typeof window === 'undefined';

// Each part: its wasm file as a person would look for it on the site, its glue and its JS
// API maker, imported only when the part is asked for (a literal import() each).
const PARTS = {
  mesh: {
    file: 'wasm/wingspline-mesh.wasm',
    url: new URL('../../wasm/wingspline-mesh.wasm', import.meta.url),
    glue: () => import('../../wasm/wingspline-mesh.js'),
    maker: () => import('./mesh-part.js').then((m) => m.createMeshPart),
  },
  subdivision: {
    file: 'wasm/wingspline-subdivision.wasm',
    url: new URL('../../wasm/wingspline-subdivision.wasm', import.meta.url),
    glue: () => import('../../wasm/wingspline-subdivision.js'),
    maker: () => import('./mesh-part.js').then((m) => m.createSubdivisionPart),
  },
  // 'mesh' and 'subdivision' together (never asked for by this name).
  meshes: {
    file: 'wasm/wingspline-meshes.wasm',
    url: new URL('../../wasm/wingspline-meshes.wasm', import.meta.url),
    glue: () => import('../../wasm/wingspline-meshes.js'),
    maker: () => import('./mesh-part.js').then((m) => m.createMeshesPart),
  },
  curves: {
    file: 'wasm/wingspline-curves.wasm',
    url: new URL('../../wasm/wingspline-curves.wasm', import.meta.url),
    glue: () => import('../../wasm/wingspline-curves.js'),
    maker: () => import('./curves-part.js').then((m) => m.createCurvesPart),
  },
  exercises: {
    file: 'wasm/wingspline-exercises.wasm',
    url: new URL('../../wasm/wingspline-exercises.wasm', import.meta.url),
    glue: () => import('../../wasm/wingspline-exercises.js'),
    maker: () => import('./exercises-part.js').then((m) => m.createExercisesPart),
  },
};
const CORE_PARTS = Object.freeze(['mesh', 'subdivision', 'curves', 'exercises']);

let loading = null;


function coreLoadError(file, reason) {
  return new WingsplineError('core-load-failed', `The geometry core (${file}) could not be loaded: ${reason}. `
    + 'Check that the file is served, with type application/wasm, and reload.');
}

// Emscripten reports failures as "Aborted(<reason>). Build with -s ASSERTIONS=1 ...": keep the reason.
function plainReason(err) {
  const text = String(err?.message ?? err);
  return text.match(/^Aborted\((.*)\)(?:\. Build with .*)?$/s)?.[1] ?? text;
}

// Fetches and compiles the wasm file ourselves (rather than in Emscripten's glue, which
// aborts with its own wording), so a failure names the file and the reason.
async function compileInBrowser({ file, url }) {
  let response;
  try {
    response = await fetch(url, { credentials: 'same-origin' });
  } catch (err) {
    throw coreLoadError(file, `the request failed (${err.message}); the page may be offline or the server unreachable`);
  }
  if (!response.ok) {
    throw coreLoadError(file, `the server answered ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`);
  }
  try {
    // Stream-compiled when served as application/wasm; any other type still compiles from the bytes.
    const streaming = /^application\/wasm\b/i.test(response.headers.get('content-type') ?? '');
    return streaming ? await WebAssembly.compileStreaming(response) : await WebAssembly.compile(await response.arrayBuffer());
  } catch (err) {
    if (err instanceof WebAssembly.CompileError) throw coreLoadError(file, `the file is not valid WebAssembly (${err.message})`);
    throw coreLoadError(file, `reading the file failed (${err.message})`);
  }
}

function instantiateInBrowser(create, file, module) {
  return new Promise((resolve, reject) => {
    create({
      instantiateWasm(imports, receive) {
        WebAssembly.instantiate(module, imports).then((instance) => {
          try {
            receive(instance, module);
          } catch (err) {
            reject(err);
          }
        }, (err) => reject(coreLoadError(file, `it does not fit this page's scripts (${err.message}); the site's files may come from different builds`)));
        return {};
      },
    }).then(resolve, reject);
  });
}

async function instantiate(part) {
  const { file, url, glue } = PARTS[part];
  const script = glue().then((m) => m.default, (err) => {
    throw coreLoadError(file, `its script (${file.replace(/\.wasm$/, '.js')}) could not be loaded (${err.message})`);
  });
  if (!isNode) {
    // The glue and the wasm are fetched at once.
    const [create, module] = await Promise.all([script, compileInBrowser(PARTS[part])]);
    return instantiateInBrowser(create, file, module);
  }
  // Emscripten 3.1.6's glue would call Node's fetch() on a file path; hand it the bytes.
  const { readFile } = await import('node:fs/promises');
  const [create, wasmBinary] = await Promise.all([script, readFile(url)]);
  return create({ wasmBinary });
}

/** @type {Map<string, Promise<any>>} each part's started module, once */
const started = new Map();
/** @type {Map<string, Promise<any>>} the API object for each set of parts, once */
const apis = new Map();

function startPart(part) {
  let loading = started.get(part);
  if (!loading) {
    loading = instantiate(part).catch((err) => {
      started.delete(part);
      if (err instanceof WingsplineError) throw err;
      throw new WingsplineError('core-load-failed', `The geometry core (${PARTS[part].file}) could not be started: ${plainReason(err)}. `
        + 'Reload the page; if this happens again, the site\'s files may come from different builds.');
    });
    started.set(part, loading);
  }
  return loading;
}

function partList(parts) {
  if (!Array.isArray(parts) || parts.length === 0 || !parts.every((p) => CORE_PARTS.includes(p))) {
    throw new WingsplineError('invalid-argument', `parts must be a non-empty list of ${CORE_PARTS.map((p) => `'${p}'`).join(', ')}, not ${JSON.stringify(parts)?.slice(0, 60)}`);
  }
  const both = parts.includes('mesh') && parts.includes('subdivision');
  return [...(both ? ['meshes'] : []), ...CORE_PARTS.filter((p) => parts.includes(p) && !(both && (p === 'mesh' || p === 'subdivision')))];
}

// Resolves to the API object over the parts asked for (all by default); every call with the
// same parts returns the same object, and each module is fetched and started once.
/** @param {{ parts?: string[] }} [options] */
export function loadWingspline({ parts = [...CORE_PARTS] } = {}) {
  let wanted;
  try {
    wanted = partList(parts);
  } catch (err) {
    return Promise.reject(err);
  }
  const key = wanted.join('+');
  let api = apis.get(key);
  if (!api) {
    api = Promise.all(wanted.map((p) => Promise.all([startPart(p), PARTS[p].maker()]))).then((started) => createApi(
      Object.fromEntries(wanted.map((p, i) => [p, started[i][0]])),
      Object.fromEntries(wanted.map((p, i) => [p, started[i][1]]))));
    api.catch(() => apis.delete(key));
    apis.set(key, api);
  }
  return api;
}
