// B-spline algorithms: de Boor with every level, Boehm's knot insertion, conversion to
// Bezier segments, continuity C^(p-m) at a knot of multiplicity m (lectures 001, 002).
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/bezier.h"
#include "wingspline/curves/bspline_ops.h"
#include "wingspline/error.h"

#include <cmath>

using namespace wingspline::curves;
using namespace curves_fixtures;

namespace {

Curve nurbs_fixture() {
    Curve c = clamped_with_double_knot();
    c.kind = CurveKind::Nurbs;
    c.weights = {1, 2, 0.5, 1, 3, 1, 0.25, 1};
    return c;
}

std::vector<Curve> spline_fixtures() {
    return {clamped_with_double_knot(), unclamped_quadratic(), nurbs_fixture(),
            make_curve(CurveKind::BSpline, zigzag(7)), bench_bspline(true)};
}

// max |a(u) - b(u)| over n samples of a's domain.
double max_distance(const Curve& a, const Curve& b, int n = 301) {
    const CurveEvaluator ev(a);
    const auto u = linspace(ev.domain().start, ev.domain().end, n);
    const auto pa = evaluate_curve(a, u), pb = evaluate_curve(b, u);
    double m = 0;
    for (int j = 0; j < n; ++j) m = std::max(m, distance(&pa[a.dim * j], &pb[a.dim * j], a.dim));
    return m;
}

} // namespace

TEST_CASE("de Boor: every level and the point of the curve", "[curves][bspline][deboor]") {
    for (const Curve& c : spline_fixtures()) {
        const CurveEvaluator ev(c);
        const int p = curve_degree(c);
        for (double s : {0.0, 0.13, 0.5, 0.77, 1.0}) {
            const double u = ev.domain().start + s * (ev.domain().end - ev.domain().start);
            const DeBoorSteps steps = de_boor(c, u);
            REQUIRE(steps.levels.size() == static_cast<std::size_t>(p + 1));
            for (int r = 0; r <= p; ++r) CHECK(steps.levels[r].size() == static_cast<std::size_t>(c.dim * (p + 1 - r)));
            // level 0 is the control points P_(l-p) .. P_l
            for (int k = 0; k < c.dim * (p + 1); ++k)
                CHECK(steps.levels[0][k] == Approx(c.points[c.dim * steps.first_index + k]).margin(kExact * 10));
            const auto point = evaluate_curve(c, {u});
            CHECK(distance(steps.levels[p].data(), point.data(), c.dim) < kSameCurve);
            for (const auto& a : steps.alphas)
                for (double alpha : a) CHECK((alpha >= 0 && alpha <= 1));
        }
    }
}

TEST_CASE("de Boor on the uniform cubic at a joint gives (P_i + 4 P_i+1 + P_i+2)/6", "[curves][bspline][deboor]") {
    const Curve c = make_curve(CurveKind::BSpline, zigzag(6));
    const DeBoorSteps s = de_boor(c, 1.0);
    const auto& p = c.points;
    CHECK(s.levels[3][0] == Approx((p[2] + 4 * p[4] + p[6]) / 6).margin(kExact));
    CHECK(s.levels[3][1] == Approx((p[3] + 4 * p[5] + p[7]) / 6).margin(kExact));
}

TEST_CASE("knot insertion leaves the curve unchanged", "[curves][bspline][insertion]") {
    for (const Curve& c : spline_fixtures()) {
        const CurveEvaluator ev(c);
        const int K = control_point_count(c);
        // (the ends of a clamped curve already have multiplicity p+1; see the next test cases)
        const bool clamped = !c.knots.empty() && c.knots[0] == c.knots[curve_degree(c)];
        for (double s : clamped ? std::vector<double>{0.31, 0.5, 0.9} : std::vector<double>{0.0, 0.31, 0.5, 0.9, 1.0}) {
            const double u = ev.domain().start + s * (ev.domain().end - ev.domain().start);
            const KnotInsertion k = insert_knot(c, u);
            CHECK(control_point_count(k.curve) == K + 1);
            CHECK(k.curve.knots.size() == static_cast<std::size_t>(K + 1 + curve_degree(c) + 1));
            CHECK(k.curve.knots[k.inserted_index] == u);
            CHECK(max_distance(c, k.curve) < kSameCurve);
            CHECK(k.recomputed.size() == static_cast<std::size_t>(curve_degree(c)));
        }
    }
    // an existing knot: 2 in the fixture already has multiplicity 2; inserting it once more
    // keeps the curve and lowers the continuity there from C1 to C0
    const Curve c = clamped_with_double_knot();
    const KnotInsertion k = insert_knot(c, 2.0);
    CHECK(max_distance(c, k.curve) < kSameCurve);
    for (const auto& info : knot_multiplicities(k.curve))
        if (info.value == 2.0) CHECK(info.continuity == 0);
}

TEST_CASE("Boehm's new points are the lecture's convex combinations", "[curves][bspline][insertion]") {
    // Uniform cubic, insert u = 1.5 into the span [1, 2) (knots t_j = j - 3): a_i = (u - t_i)/(t_i+3 - t_i)
    const Curve c = make_curve(CurveKind::BSpline, zigzag(6));
    const KnotInsertion k = insert_knot(c, 1.5);
    REQUIRE(k.span == 4);
    REQUIRE(k.recomputed == std::vector<int>({2, 3, 4}));
    CHECK(k.alphas[0] == Approx((1.5 - (-1)) / 3).margin(kExact));
    CHECK(k.alphas[1] == Approx((1.5 - 0) / 3).margin(kExact));
    CHECK(k.alphas[2] == Approx((1.5 - 1) / 3).margin(kExact));
    const double a = k.alphas[0];
    CHECK(k.curve.points[4] == Approx(a * c.points[4] + (1 - a) * c.points[2]).margin(kExact));
}

TEST_CASE("a knot of multiplicity p+1 cannot be inserted again", "[curves][bspline][insertion][errors]") {
    try {
        insert_knot(clamped_with_double_knot(), 0.0);
        FAIL("expected an error");
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == "knot-multiplicity-exceeded");
    }
    CHECK_THROWS_AS(insert_knot(clamped_with_double_knot(), 5.5), wingspline::Error);
}

TEST_CASE("conversion to Bezier segments traces the same curve span by span", "[curves][bspline][bezier]") {
    for (const Curve& c : spline_fixtures()) {
        const auto segments = to_bezier_segments(c);
        int spans = 0;
        const std::vector<double> knots = c.knots.empty() ? uniform_knots(control_point_count(c), curve_degree(c)) : c.knots;
        for (int l = curve_degree(c); l < control_point_count(c); ++l) spans += knots[l] < knots[l + 1] ? 1 : 0;
        REQUIRE(segments.size() == static_cast<std::size_t>(spans));
        for (const auto& s : segments) {
            Curve bez = make_curve(CurveKind::Bezier, s.points, c.dim);
            bez.weights = s.weights;
            REQUIRE(curve_degree(bez) == curve_degree(c));
            for (double v : linspace(0, 1, 11)) {
                const auto a = evaluate_curve(bez, {v});
                const auto b = evaluate_curve(c, {s.start + v * (s.end - s.start)});
                CHECK(distance(a.data(), b.data(), c.dim) < 1e-11);
            }
        }
    }
}

TEST_CASE("a clamped cubic on 0,0,0,0,1,1,1,1 is the Bezier curve (lecture 002)", "[curves][bspline][bezier]") {
    Curve b = make_curve(CurveKind::BSpline, zigzag(4));
    b.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    CHECK(max_distance(b, make_curve(CurveKind::Bezier, zigzag(4))) < kSameCurve);
}

TEST_CASE("a knot of multiplicity m gives C^(p-m): the next derivative jumps", "[curves][bspline][continuity]") {
    const Curve c = clamped_with_double_knot(); // p = 3; knots 1 and 3.5 simple, 2 double
    const auto info = knot_multiplicities(c);
    REQUIRE(info.size() == 5);
    const std::vector<double> values = {0, 1, 2, 3.5, 5};
    const std::vector<int> mult = {4, 1, 2, 1, 4};
    for (std::size_t i = 0; i < 5; ++i) {
        CHECK(info[i].value == values[i]);
        CHECK(info[i].multiplicity == mult[i]);
        CHECK(info[i].interior == (i > 0 && i < 4));
    }
    CHECK(info[1].continuity == 2);
    CHECK(info[2].continuity == 1);
    // Left-hand limits from the span before the knot vs the value at the knot (right side):
    // derivatives up to p-m agree, derivative p-m+1 jumps.
    auto jump = [&](double knot, int order) {
        const double h = 1e-7;
        const auto left = evaluate_curve(c, {knot - h}, order);
        const auto right = evaluate_curve(c, {knot}, order);
        return distance(left.data(), right.data(), 2);
    };
    CHECK(jump(2.0, 1) < 1e-5);
    CHECK(jump(2.0, 2) > 0.1);
    CHECK(jump(1.0, 2) < 1e-5);
    CHECK(jump(1.0, 3) > 0.1);
}
