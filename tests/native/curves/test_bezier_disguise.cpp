// Lecture 002, "cubic b-spline -> cubic Bezier curve {0,0,0,0,1,1,1,1}".
// is_bezier_in_disguise says when a B-spline is exactly the Bezier curve of its control
// points; checked against the evaluator (the B-spline and the Bezier curve on the same
// points, at the same relative parameters), never against the function itself.
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/knot_vectors.h"

#include <cmath>
#include <random>

using namespace wingspline::curves;
using namespace curves_fixtures;

namespace {
// Largest distance between the B-spline on `knots` and the Bezier curve of the same points,
// over 41 parameters spread evenly over each one's domain.
double gap(const std::vector<double>& points, const std::vector<double>& knots, int degree) {
    Curve s = make_curve(CurveKind::BSpline, points);
    s.degree = degree;
    s.knots = knots;
    const Curve b = make_curve(CurveKind::Bezier, points);
    const CurveEvaluator es(s), eb(b);
    const double a = knots[degree], z = knots[knots.size() - 1 - degree];
    double worst = 0;
    for (int j = 0; j <= 40; ++j) {
        const double u = j / 40.0, t = a + u * (z - a);
        double ps[2], pb[2];
        es.evaluate(es.checked_params(&t, 1).data(), 1, 0, ps);
        eb.evaluate(eb.checked_params(&u, 1).data(), 1, 0, pb);
        worst = std::max(worst, std::hypot(ps[0] - pb[0], ps[1] - pb[1]));
    }
    return worst;
}
} // namespace

TEST_CASE("a clamped B-spline of one segment is its Bezier curve; nothing else is", "[curves][bspline][notation]") {
    // Lecture 002's example.
    CHECK(is_bezier_in_disguise({0, 0, 0, 0, 1, 1, 1, 1}, 3));
    std::mt19937 rng(18);
    std::uniform_real_distribution<double> coord(-5, 5), start(-3, 3), length(0.1, 4);
    for (int trial = 0; trial < 2000; ++trial) {
        const int p = 1 + trial % 5;
        const double a = start(rng), z = a + length(rng);
        std::vector<double> points;
        for (int i = 0; i < 2 * (p + 1); ++i) points.push_back(coord(rng));
        std::vector<double> knots(p + 1, a);
        knots.insert(knots.end(), p + 1, z);
        const double scale = 10; // the points' extent
        INFO("trial " << trial << " degree " << p);
        // Clamped, one segment: the same curve as the Bezier of the points.
        REQUIRE(is_bezier_in_disguise(knots, p));
        CHECK(gap(points, knots, p) <= 1e-12 * scale);
        // The outermost knots act on no span of the domain: moving them keeps the Bezier.
        std::vector<double> outer = knots;
        outer.front() = a - 1.5;
        outer.back() = z + 0.7;
        CHECK(is_bezier_in_disguise(outer, p));
        CHECK(gap(points, outer, p) <= 1e-12 * scale);
        // Unclamped ends (one segment): for p >= 2 not a Bezier, and the curves differ; a
        // degree-1 segment is its line whatever the end knots.
        std::vector<double> spread = knots;
        for (int j = 0; j < p; ++j) {
            spread[j] = a - (p - j) * 0.5;
            spread[spread.size() - 1 - j] = z + (p - j) * 0.5;
        }
        if (p == 1) {
            CHECK(is_bezier_in_disguise(spread, p));
            CHECK(gap(points, spread, p) <= 1e-12 * scale);
        } else {
            CHECK_FALSE(is_bezier_in_disguise(spread, p));
            CHECK(gap(points, spread, p) > 1e-6 * scale);
        }
        // Clamped with one more point (two segments): not one Bezier curve.
        std::vector<double> two(p + 1, a);
        two.push_back((a + z) / 2);
        two.insert(two.end(), p + 1, z);
        CHECK_FALSE(is_bezier_in_disguise(two, p));
    }
}
