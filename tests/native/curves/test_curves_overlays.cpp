// The curve explorer's overlays in the core: the curvature comb against a
// circle's analytic curvature vector, and the homogeneous lift of a NURBS's control points.
#include "curves_fixtures.h"

#include "wingspline/curves/conics.h"
#include "wingspline/curves/overlays.h"

#include <cmath>
#include <random>

using namespace wingspline::curves;
using curves_fixtures::expect_error;

TEST_CASE("curvature comb: on a circle every tooth points at the centre with length 1/r, at any scale",
          "[curves][overlays]") {
    std::mt19937_64 rng(53);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 300; ++trial) {
        const double r = std::pow(10.0, 4 * u(rng));
        const std::vector<double> c = {r * 10 * u(rng), r * 10 * u(rng)};
        const Curve circle = nurbs_circle(c, 2, r);
        std::vector<double> params;
        for (int j = 0; j <= 40; ++j) params.push_back(circle.knots.front() + (circle.knots.back() - circle.knots.front()) * j / 40);
        const CurvatureComb comb = curvature_comb(circle, params);
        INFO("trial " << trial << " radius " << r);
        CHECK(comb.singular == 0);
        CHECK(comb.max_curvature == Approx(1 / r).epsilon(1e-10));
        for (std::size_t j = 0; j < params.size(); ++j) {
            // kappa N = (c - p) / r^2 (counter-clockwise circle: it turns left, towards the centre)
            const double* t = &comb.teeth[4 * j];
            CHECK(t[2] == Approx((c[0] - t[0]) / (r * r)).margin(1e-9 / r));
            CHECK(t[3] == Approx((c[1] - t[1]) / (r * r)).margin(1e-9 / r));
        }
    }
    // a cusp: P' = 0 at u = 1/2 of this Bezier; the tooth there is 0, not NaN
    Curve cusp;
    cusp.points = {0, 0, 2, 2, 0, 2, 2, 0};
    const CurvatureComb k = curvature_comb(cusp, {0, 0.5, 1});
    CHECK(k.singular == 1);
    CHECK(k.teeth[4 * 1 + 2] == 0);
    CHECK(k.teeth[4 * 1 + 3] == 0);
    Curve space = cusp;
    space.dim = 3;
    space.points = {0, 0, 0, 1, 1, 1, 2, 0, 0, 3, 1, 1};
    expect_error([&] { curvature_comb(space, {0.5}); }, "invalid-dimension", "dim 2");
}

TEST_CASE("homogeneous lift: (w x, w y, w) with the weights as given", "[curves][overlays]") {
    CHECK(homogeneous_lift({1, 2, 3, 4}, 2, {0.5, 3}) == std::vector<double>{0.5, 1, 0.5, 9, 12, 3});
    CHECK(homogeneous_lift({1, 2, 3}, 3, {2}) == std::vector<double>{2, 4, 6, 2});
    expect_error([] { homogeneous_lift({1, 2, 3, 4}, 2, {1}); }, "wrong-weight-count", "2 points but 1 weights");
    expect_error([] { homogeneous_lift({1, 2, 3, 4}, 2, {1, 0}); }, "invalid-weight", "point 1");
    expect_error([] { homogeneous_lift({1, NAN}, 2, {1}); }, "non-finite-input", "point 0");
}
