// The built sites a browser benchmark measures in one run: this worktree's dist/ by default,
// or several named in an environment variable, `before=/tmp/dist-old,after=dist`, so that a
// commit can quote before and after from one run (docs/benchmarks.md).
import path from 'node:path';
import { repoRoot } from '../../helpers/browser.mjs';

/** @param {string} variable e.g. 'WINGSPLINE_WALK_SITES' @returns {{ label: string, root: string }[]} */
export function benchSites(variable) {
  const spec = process.env[variable];
  if (!spec) return [{ label: '', root: path.join(repoRoot, 'dist') }];
  return spec.split(',').map((entry) => {
    const [label, dir] = entry.split('=');
    return { label, root: path.resolve(repoRoot, dir) };
  });
}

// Median and p95 of a list of times (ms).
export function msSummary(times) {
  const sorted = [...times].sort((a, b) => a - b);
  return { median_ms: sorted[Math.floor(sorted.length / 2)], p95_ms: sorted[Math.floor(0.95 * (sorted.length - 1))] };
}
