// Curve tasks of docs/benchmarks.md on the native build: one batch call per repetition over
// N = 10^6 parameters; checksum = sum of x + y + z of every evaluated point.
#include "bench.h"
#include "bench_curve.h"

#include "wingspline/curves/curve.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace wingspline::curves;

constexpr int kN = 1000000;
constexpr int kRepetitions = 7;

Curve bench_bezier() {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.dim = 3;
    c.points = {0, 0, 0, 1, 2, 0.5, 3, 2, 1, 4, 0, 1.5};
    return c;
}

std::vector<double> params(double end) {
    std::vector<double> t(kN);
    for (int j = 0; j < kN; ++j) t[j] = end * j / (kN - 1);
    return t;
}

// One batch evaluation per repetition, as the public API does it: validate and prepare the
// curve, check the parameters, evaluate (point only, or point and first derivative).
void run(const char* task, const char* input, const Curve& curve, double end, bool with_d1) {
    const std::vector<double> t = params(end);
    std::vector<double> out(static_cast<std::size_t>(kN) * 3 * (with_d1 ? 2 : 1));
    double checksum = 0;
    std::vector<double> seconds;
    for (int r = 0; r < kRepetitions; ++r) {
        std::fill(out.begin(), out.end(), 0.0);
        // timed: the batch call (prepare the curve, check the params, evaluate)
        const auto one = wingspline::bench::time_runs(1, [&] {
            const CurveEvaluator ev(curve);
            const auto u = ev.checked_params(t.data(), t.size());
            if (with_d1) ev.evaluate_all(u.data(), u.size(), 1, out.data());
            else ev.evaluate(u.data(), u.size(), 0, out.data());
        });
        seconds.push_back(one[0]);
        double s = 0;
        const int stride = with_d1 ? 6 : 3;
        for (int j = 0; j < kN; ++j) s += out[j * stride] + out[j * stride + 1] + out[j * stride + 2];
        checksum = s;
    }
    wingspline::bench::report(task, input, kN, seconds, checksum);
}

} // namespace

WINGSPLINE_BENCH(curves) {
    const double u61 = 61 + 0.25 * std::sin(61.0);
    if (ctx.wants("curve_bezier3_eval")) run("curve_bezier3_eval", "bezier3 N=1e6", bench_bezier(), 1.0, false);
    if (ctx.wants("curve_bspline_eval")) run("curve_bspline_eval", "bspline K=64 p=3 N=1e6", bench_bspline(false), u61, false);
    if (ctx.wants("curve_bspline_eval_d1")) run("curve_bspline_eval_d1", "bspline K=64 p=3 N=1e6", bench_bspline(false), u61, true);
    if (ctx.wants("curve_nurbs_eval")) run("curve_nurbs_eval", "nurbs K=64 p=3 N=1e6", bench_bspline(true), u61, false);
    if (ctx.wants("curve_nurbs_eval_d1")) run("curve_nurbs_eval_d1", "nurbs K=64 p=3 N=1e6", bench_bspline(true), u61, true);
}
