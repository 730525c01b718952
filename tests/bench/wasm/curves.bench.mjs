// Curve tasks of docs/benchmarks.md on the wasm build, through the public JS batch API (one
// call per repetition over N = 10^6 parameters, validation and both copies across the
// boundary included); checksum = sum of x + y + z of every evaluated point, folded after
// each timed call.
import { loadWingspline } from 'wingspline';
import { wants, timeRuns, report } from './harness.mjs';

const api = await loadWingspline();
const N = 1_000_000;
const REPETITIONS = 7;

const bezier = { kind: 'bezier', dim: 3, points: [0, 0, 0, 1, 2, 0.5, 3, 2, 1, 4, 0, 1.5] };

function bspline(nurbs) {
  const points = [];
  const weights = [];
  for (let i = 0; i < 64; i += 1) {
    const r = 1 + i / 64;
    points.push(r * Math.cos(0.3 * i), r * Math.sin(0.3 * i), 0.05 * i);
    weights.push(1 + 0.5 * Math.sin(0.7 * i) ** 2);
  }
  const u = (i) => i + 0.25 * Math.sin(i);
  const knots = [u(0), u(0), u(0)];
  for (let i = 0; i <= 61; i += 1) knots.push(u(i));
  knots.push(u(61), u(61), u(61));
  const curve = { kind: nurbs ? 'nurbs' : 'bspline', dim: 3, degree: 3, points: Float64Array.from(points), knots: Float64Array.from(knots) };
  if (nurbs) curve.weights = Float64Array.from(weights);
  return curve;
}

function params(end) {
  const t = new Float64Array(N);
  for (let j = 0; j < N; j += 1) t[j] = (end * j) / (N - 1);
  return t;
}

// The output buffer is reused across repetitions through the API's `out` option, as a
// lesson does when it redraws: the timing then holds the evaluation and the copies, not
// the operating system's page faults for a fresh 24 MB array.
function run(task, input, curve, end, withD1) {
  const t = params(end);
  const out = new Float64Array(N * 3 * (withD1 ? 2 : 1));
  // Only the batch call is timed; the checksum over its output is folded after each timing.
  const seconds = [];
  let checksum = 0;
  for (let r = 0; r < REPETITIONS; r += 1) {
    out.fill(0);
    seconds.push(...timeRuns(1, () => {
      if (withD1) api.evaluateWithDerivatives(curve, t, 1, { out });
      else api.evaluateCurve(curve, t, { out });
    }, { warmUp: r === 0 }));
    const stride = withD1 ? 6 : 3;
    let s = 0;
    for (let j = 0; j < N; j += 1) s += out[j * stride] + out[j * stride + 1] + out[j * stride + 2];
    checksum = s;
  }
  report({ task, input, n: N, seconds, checksum });
}

const u61 = 61 + 0.25 * Math.sin(61);
if (wants('curve_bezier3_eval')) run('curve_bezier3_eval', 'bezier3 N=1e6', bezier, 1, false);
if (wants('curve_bspline_eval')) run('curve_bspline_eval', 'bspline K=64 p=3 N=1e6', bspline(false), u61, false);
if (wants('curve_bspline_eval_d1')) run('curve_bspline_eval_d1', 'bspline K=64 p=3 N=1e6', bspline(false), u61, true);
if (wants('curve_nurbs_eval')) run('curve_nurbs_eval', 'nurbs K=64 p=3 N=1e6', bspline(true), u61, false);
if (wants('curve_nurbs_eval_d1')) run('curve_nurbs_eval_d1', 'nurbs K=64 p=3 N=1e6', bspline(true), u61, true);
