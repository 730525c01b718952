// @ts-check
// The sandbox under Node (the grader's command line): the same QuickJS build the site ships
// (@jitl/quickjs-wasmfile-release-sync), loaded from the npm package, and the same runner.
// QuickJS is the isolation, so the engine runs in this process, synchronously per request.
import { newQuickJSWASMModuleFromVariant } from 'quickjs-emscripten-core';
import releaseSync from '@jitl/quickjs-wasmfile-release-sync';
import { runStudentCode, checkSyntax } from './runner.js';

/** @typedef {import('./runner.js').RunRequest} RunRequest */
/** @typedef {import('quickjs-emscripten-core').QuickJSWASMModule} QuickJSWASMModule */

/**
 * A sandbox that keeps its engine between runs: run(request) resolves to what runStudentCode
 * returns. After a case that broke the engine at the host level (engineFailed: the host's
 * stack overflowed inside the wasm) the next run loads a new engine.
 */
export function createNodeSandbox() {
  /** @type {Promise<QuickJSWASMModule> | null} */
  let engine = null;
  return {
    /** @param {RunRequest} request */
    async run(request) {
      engine ??= newQuickJSWASMModuleFromVariant(releaseSync);
      const out = runStudentCode(await engine, request);
      if ('results' in out && out.results.some((r) => r.engineFailed)) engine = null;
      return out;
    },
    /** @param {string} source */
    async checkSyntax(source) {
      engine ??= newQuickJSWASMModuleFromVariant(releaseSync);
      return checkSyntax(await engine, source);
    },
  };
}

/**
 * Runs one request in a fresh engine of this process: {results} or {error} (runner.js).
 * @param {RunRequest} request
 */
export async function runInNode(request) {
  const engine = await newQuickJSWASMModuleFromVariant(releaseSync);
  return runStudentCode(engine, request);
}
