#pragma once
// docs/benchmarks.md's B-spline, used by the curve benchmarks and by the native curve tests
// (tests/native/curves/curves_fixtures.h): K = 64, p = 3, breakpoints u_i = i + 0.25 sin(i),
// clamped; NURBS weights 1 + 0.5 sin^2(0.7 i).
#include "wingspline/curves/curve.h"

#include <cmath>

inline wingspline::curves::Curve bench_bspline(bool nurbs = false) {
    using namespace wingspline::curves;
    Curve c;
    c.kind = nurbs ? CurveKind::Nurbs : CurveKind::BSpline;
    c.dim = 3;
    c.degree = 3;
    for (int i = 0; i < 64; ++i) {
        const double r = 1 + i / 64.0;
        c.points.insert(c.points.end(), {r * std::cos(0.3 * i), r * std::sin(0.3 * i), 0.05 * i});
        if (nurbs) c.weights.push_back(1 + 0.5 * std::sin(0.7 * i) * std::sin(0.7 * i));
    }
    const auto u = [](int i) { return i + 0.25 * std::sin(i); };
    c.knots = {u(0), u(0), u(0)};
    for (int i = 0; i <= 61; ++i) c.knots.push_back(u(i));
    c.knots.insert(c.knots.end(), {u(61), u(61), u(61)});
    return c;
}
