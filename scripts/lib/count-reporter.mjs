// A node:test reporter that counts results from the runner's events and writes the counts
// as one JSON object, { pass, fail, cancelled, skip, todo, failed: [names] }, to its
// destination. `npm test` passes it with --test-reporter-destination=<file> beside the spec
// reporter on stdout, so the counts never depend on the text of a human-readable reporter
// (which reporter Node uses by default changed in Node 23).
//
// What counts (the same as the summary node:test prints itself):
// - every test:pass / test:fail of a test or subtest, at any depth; suites (describe) are
//   containers and are not counted;
// - a skipped test is `skip`, a todo test is `todo` whether it passed or failed: neither is
//   ever a pass;
// - a test cancelled (its parent ended first, the run was interrupted, or it timed out) is
//   `cancelled`, and the layer counts it as failed;
// - a test file that fails outside any test (it throws while loading, or exits with a
//   non-zero code) is reported by the runner as a failing test named after the file, and
//   counts as one failure.

/** @param {{ type: string, data?: any }} event */
export function classify(event) {
  if (event.type !== 'test:pass' && event.type !== 'test:fail') return null;
  const data = event.data ?? {};
  if (data.details?.type === 'suite') return null;
  if (data.skip !== undefined && data.skip !== false) return 'skip';
  if (data.todo !== undefined && data.todo !== false) return 'todo';
  if (event.type === 'test:pass') return 'pass';
  const failureType = data.details?.error?.failureType;
  return failureType === 'cancelledByParent' || failureType === 'testTimeoutFailure' ? 'cancelled' : 'fail';
}

/** @param {AsyncIterable<{ type: string, data?: any }>} source */
export default async function* countReporter(source) {
  const counts = { pass: 0, fail: 0, cancelled: 0, skip: 0, todo: 0, failed: /** @type {string[]} */ ([]) };
  for await (const event of source) {
    const kind = classify(event);
    if (kind === null) continue;
    counts[kind] += 1;
    if (kind === 'fail' || kind === 'cancelled') {
      const where = event.data.file ? ` (${event.data.file})` : '';
      counts.failed.push(`${event.data.name}${where}`);
    }
  }
  yield `${JSON.stringify(counts)}\n`;
}
