// @ts-check
// The API object over started core modules: the one place the parts of the API are put
// together. wingspline.js starts the shipped modules it was asked for ('mesh', 'subdivision'
// or both as 'meshes', 'curves', 'exercises') with their JS parts (mesh-part.js, curves-part.js, exercises-part.js) and
// calls this; the benchmark starts the bench module (every binding plus its timing entry
// points) and hands it as every part, so its meshes are the product's. Not part of the
// package's exports.
import { unwrap, WingsplineError } from './errors.js';

/**
 * @param {Record<string, any>} parts each started module's embind functions, by part ('mesh',
 *   'subdivision', 'meshes', 'curves', 'exercises')
 * @param {Record<string, (raw: any) => object>} makers each part's API maker (mesh-part.js,
 *   curves-part.js, exercises-part.js), for the parts given
 */
export function createApi(parts, makers) {
  const raws = [...new Set(Object.values(parts).filter(Boolean))];
  if (raws.length === 0) throw new WingsplineError('invalid-argument', 'createApi needs at least one started module');
  // Both modules are built from one source and report its version (package.json); files from
  // two builds would disagree on it.
  const version = raws[0].version();
  for (const raw of raws) {
    if (raw.version() !== version) {
      throw new WingsplineError('core-load-failed', `The geometry core's modules come from different builds (${version} and ${raw.version()}). `
        + 'Reload the page; if this happens again, the site\'s files are out of step.');
    }
  }
  return Object.freeze({
    version,
    // {linearBytes: size of the wasm memory, heapInUse: bytes malloc has handed out}, over
    // the modules started; the leak tests of both cores watch heapInUse across thousands of calls.
    memoryUsage() {
      let linearBytes = 0;
      let heapInUse = 0;
      for (const raw of raws) {
        const one = unwrap(raw.memoryUsage());
        linearBytes += one.linearBytes;
        heapInUse += one.heapInUse;
      }
      return { linearBytes, heapInUse };
    },
    // Every error code the API can give, with what it means (the core's one list, error_codes.h,
    // compiled into each module): [{code, group, meaning}], frozen.
    errorCodes: Object.freeze(unwrap(raws[0].errorCodes()).codes.map((/** @type {any} */ c) => Object.freeze({ code: c.code, group: c.group, meaning: c.meaning }))),
    ...Object.assign({}, ...Object.keys(parts).map((part) => makers[part](parts[part]))),
  });
}
