// @ts-check
// The page's side of the code sandbox: a module worker (sandbox-worker.js) runs the student's
// code, so the page stays responsive, and a watchdog ends a worker that does not answer in
// time (budgetMs per case + 1.5 s, counted from the moment the worker has loaded its engine):
// the run resolves with a timeout error and the next run starts a fresh worker. One run at a
// time; a second run while one is going resolves with a 'busy' error at once.
//
// The worker's address is '../code/sandbox-worker.js' from this module: from
// dist/js/code/sandbox.js and from a lesson bundle in dist/js/bundle/ alike (both two folders
// under dist/), it is dist/js/code/sandbox-worker.js, the bundle the build writes.

/** @typedef {import('./runner.js').RunRequest} RunRequest */
/** @typedef {import('./runner.js').RunError | { kind: 'busy'|'disposed', message: string, line: null, column: null }} SandboxError */
/** @typedef {{ results: import('./runner.js').CaseResult[] } | { error: SandboxError }} SandboxAnswer */

const WATCHDOG_SLACK_MS = 1500;
const DEFAULT_BUDGET_MS = 1500;
const ENGINE_LOAD_MS = 60_000;

/**
 * @param {{ url?: string | URL, loadMs?: number }} [options] the worker's address (tests; default
 *   above) and how long its engine may take to load (default ENGINE_LOAD_MS)
 * @returns {{ run(request: RunRequest): Promise<SandboxAnswer>, dispose(): void }}
 */
export function createSandbox({ url, loadMs = ENGINE_LOAD_MS } = {}) {
  const workerUrl = url ?? new URL('../code/sandbox-worker.js', import.meta.url);
  /** @type {Worker | null} */
  let worker = null;
  let busy = false;
  let disposed = false;
  let nextId = 1;
  /** @type {((answer: SandboxAnswer) => void) | null} */
  let settleCurrent = null;

  /** @type {Promise<true | string> | null} the engine loaded (true) or why not */
  let ready = null;
  const stop = () => {
    worker?.terminate();
    worker = null;
    ready = null;
  };
  // Resolves when the worker has loaded its engine, or with why it could not (in loadMs at
  // most, so a run never waits for ever).
  /** @param {Worker} w @returns {Promise<true | string>} */
  const readyOf = (w) => new Promise((resolve) => {
    const give = setTimeout(() => resolve(`the sandbox's engine did not load within ${loadMs / 1000} s: check the connection and run again`), loadMs);
    /** @param {MessageEvent} event */
    const onReady = (event) => {
      if (event.data?.ready === undefined) return;
      clearTimeout(give);
      w.removeEventListener('message', onReady);
      resolve(event.data.ready === true ? true : `the sandbox's engine could not be loaded (${event.data.message}): reload the page`);
    };
    w.addEventListener('message', onReady);
    w.addEventListener('error', () => { clearTimeout(give); resolve('the sandbox could not be started: reload the page'); }, { once: true });
  });
  /** @param {SandboxError['kind']} kind @param {string} message @returns {SandboxAnswer} */
  const failure = (kind, message) => ({ error: { kind, message, line: null, column: null } });

  return {
    run(request) {
      if (disposed) return Promise.resolve(failure('disposed', 'this sandbox was closed'));
      if (busy) return Promise.resolve(failure('busy', 'your code is still running: wait for that run to finish'));
      busy = true;
      if (!worker) {
        worker = new Worker(workerUrl, { type: 'module', name: 'code-sandbox' });
        ready = readyOf(worker);
      }
      const w = worker;
      const loaded = ready;
      const id = nextId++;
      const cases = Array.isArray(request?.cases) ? request.cases.length : 0;
      const limit = (request?.budgetMs ?? DEFAULT_BUDGET_MS) * Math.max(1, cases) + WATCHDOG_SLACK_MS;
      return new Promise((resolve) => {
        /** @type {ReturnType<typeof setTimeout> | undefined} */
        let timer;
        /** @param {MessageEvent} event */
        const onMessage = (event) => {
          if (event.data?.id !== id) return;
          const { id: _, ...answer } = event.data;
          settle(answer);
        };
        /** @param {Event} event */
        const onError = (event) => {
          event.preventDefault();
          stop();
          settle(failure('engine', `the sandbox stopped: ${/** @type {ErrorEvent} */ (event).message ?? 'unknown error'}`));
        };
        /** @param {SandboxAnswer} answer */
        const settle = (answer) => {
          clearTimeout(timer);
          w.removeEventListener('message', onMessage);
          w.removeEventListener('error', onError);
          w.removeEventListener('messageerror', onError);
          busy = false;
          settleCurrent = null;
          resolve(answer);
        };
        settleCurrent = settle;
        w.addEventListener('message', onMessage);
        w.addEventListener('error', onError);
        w.addEventListener('messageerror', onError);
        // The watchdog starts once the engine is loaded (the worker says so), not before.
        loaded?.then((ok) => {
          if (settleCurrent !== settle) return;
          if (ok !== true) { stop(); settle(failure('engine', ok)); return; }
          timer = setTimeout(() => {
            stop();
            settle(failure('timeout', `your code did not finish within ${limit / 1000} s and was stopped: is there a loop that never ends?`));
          }, limit);
          w.postMessage({ id, request });
        });
      });
    },
    dispose() {
      disposed = true;
      stop();
      settleCurrent?.(failure('disposed', 'this sandbox was closed'));
    },
  };
}
