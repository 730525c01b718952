// Every bad input is refused with a stable code and a message that names the element.
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/bezier.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <limits>

using namespace wingspline::curves;
using namespace curves_fixtures;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
} // namespace

TEST_CASE("knot vector errors", "[curves][errors]") {
    Curve c = clamped_with_double_knot();
    c.knots[6] = 0.5; // t_5 = 2 > t_6 = 0.5
    expect_error([&] { validate(c); }, "decreasing-knots", "t_5 = 2 > t_6 = 0.5");
    c = clamped_with_double_knot();
    c.knots.pop_back();
    expect_error([&] { validate(c); }, "wrong-knot-count", "K + p + 1 = 12");
    c = clamped_with_double_knot();
    c.knots[7] = kNaN;
    expect_error([&] { validate(c); }, "non-finite-input", "t_7");
    c = clamped_with_double_knot();
    c.knots = {0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1}; // 0 five times for p = 3
    expect_error([&] { validate(c); }, "knot-multiplicity-exceeded", "at most p + 1 = 4");
    c = unclamped_quadratic();
    c.knots = {0, 1, 2, 2, 2, 2, 3, 4}; // t_p = t_K = 2
    expect_error([&] { validate(c); }, "knot-multiplicity-exceeded", "2 appears 4 times");
    // K = p + 1 = 3 points with t_2 = t_3: the domain [t_p, t_K] is a single value.
    c.points = zigzag(3);
    c.knots = {0, 1, 2, 2, 3, 4};
    expect_error([&] { validate(c); }, "empty-domain", "[2, 2]");
}

TEST_CASE("weight and degree and point count errors", "[curves][errors]") {
    Curve c = clamped_with_double_knot();
    c.kind = CurveKind::Nurbs;
    c.weights = {1, 1, 1, -2, 1, 1, 1, 1};
    expect_error([&] { validate(c); }, "invalid-weight", "w_3 of point 3 is -2");
    c.weights[3] = kInf;
    expect_error([&] { validate(c); }, "invalid-weight", "point 3");
    c.weights[3] = 0;
    expect_error([&] { validate(c); }, "invalid-weight", "point 3");
    c.weights.pop_back();
    expect_error([&] { validate(c); }, "wrong-weight-count", "8 control points but 7 weights");
    c = clamped_with_double_knot();
    c.degree = 21;
    c.knots.clear();
    expect_error([&] { validate(c); }, "degree-out-of-range", "from 1 to 20");
    c.degree = 8;
    expect_error([&] { validate(c); }, "too-few-points", "at least 9");
    expect_error([&] { validate(make_curve(CurveKind::Bezier, {1, 2})); }, "too-few-points", "at least 2");
    expect_error([&] { validate(make_curve(CurveKind::Bezier, zigzag(22))); }, "degree-out-of-range", "degree 21");
    expect_error([&] { validate(make_curve(CurveKind::CatmullRom, zigzag(3))); }, "too-few-points", "at least 4");
    expect_error([&] { validate(make_curve(CurveKind::Interpolation, zigzag(kMaxInterpolationPoints + 1))); }, "degree-out-of-range",
                 std::to_string(kMaxInterpolationPoints) + " points");
    Curve h = make_curve(CurveKind::Hermite, zigzag(3));
    h.tangents = {1, 0};
    expect_error([&] { validate(h); }, "wrong-tangent-count", "one tangent per point");
    expect_error([&] { validate(make_curve(CurveKind::Bezier, {0, 0, 1})); }, "invalid-points", "not a multiple of dim = 2");
    expect_error([&] { parse_curve_kind("bsplin"); }, "unknown-curve-kind", "'bsplin'");
}

TEST_CASE("non-finite inputs name the point and the component", "[curves][errors]") {
    Curve c = make_curve(CurveKind::Bezier, zigzag(4));
    c.points[5] = kNaN;
    expect_error([&] { validate(c); }, "non-finite-input", "point 2 (y)");
    Curve b = make_curve(CurveKind::Bezier, zigzag(4));
    expect_error([&] { evaluate_curve(b, {0.1, kNaN}); }, "non-finite-input", "parameter 1");
    expect_error([&] { de_casteljau(b.points, 2, kNaN); }, "non-finite-input", "t is");
}

TEST_CASE("parameters outside the domain are refused - rounding is tolerated", "[curves][errors]") {
    const Curve c = clamped_with_double_knot();
    expect_error([&] { evaluate_curve(c, {0, 5.001}); }, "parameter-out-of-range", "parameter 1 is u = 5.001, outside the domain [0, 5]");
    expect_error([&] { evaluate_curve(c, {-1e-6}); }, "parameter-out-of-range", "[0, 5]");
    const auto end = evaluate_curve(c, {5.0});
    const auto rounded = evaluate_curve(c, {5.0 + 1e-13});
    CHECK(rounded == end);
    expect_error([&] { evaluate_curve(make_curve(CurveKind::CatmullRom, zigzag(6)), {3.5}); },
                 "parameter-out-of-range", "[0, 3]");
}
