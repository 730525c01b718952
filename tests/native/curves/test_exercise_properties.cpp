// Exercise kind 5, "make the curve pass through a point": the closest point of a
// curve against analytic distances (a circle: | |X - c| - r |; a line segment: the distance to
// the segment), the verdict relative to the control polygon's size, and its invariance
// under scaling, rotation and translation.
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/conics.h"
#include "wingspline/curves/exercise.h"

#include <glm/glm.hpp>
#include <glm/gtx/rotate_vector.hpp>

#include <cmath>
#include <random>

using namespace wingspline::curves;
using curves_fixtures::expect_error;
using glm::dvec2;

namespace {

constexpr double kDistanceRel = 1e-9; // closest-point distance against the analytic one, relative to the curve's size
constexpr double kTolerance = 0.01;   // the exercise's relative tolerance
constexpr int kCases = 2000;
constexpr double kPi = 3.14159265358979323846;

Curve line(dvec2 a, dvec2 b) {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.dim = 2;
    c.points = {a.x, a.y, b.x, b.y};
    return c;
}

} // namespace

TEST_CASE("closest point on a NURBS circle: | |X - c| - r | for points inside and outside", "[exercise][property]") {
    std::mt19937_64 rng(1911);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int n = 0; n < kCases; ++n) {
        const dvec2 c(4 * u01(rng) - 2, 4 * u01(rng) - 2);
        const double r = 0.1 + 3 * u01(rng);
        const double rho = r * 3 * u01(rng), angle = 2 * kPi * u01(rng);
        const dvec2 X = c + rho * dvec2(std::cos(angle), std::sin(angle));
        const Curve circle = nurbs_circle({c.x, c.y}, 2, r);
        const ClosestPoint p = closest_point(circle, {X.x, X.y});
        INFO("r " << r << ", |X - c| " << rho);
        REQUIRE(std::abs(p.distance - std::abs(rho - r)) <= kDistanceRel * r);
        REQUIRE(std::abs(glm::length(dvec2(p.point[0], p.point[1]) - c) - r) <= kDistanceRel * r);
    }
}

TEST_CASE("closest point on a line segment: the perpendicular foot or the nearer end", "[exercise][property]") {
    std::mt19937_64 rng(1912);
    std::uniform_real_distribution<double> u11(-1, 1);
    for (int n = 0; n < kCases; ++n) {
        const dvec2 a(u11(rng), u11(rng)), b(u11(rng), u11(rng)), X(2 * u11(rng), 2 * u11(rng));
        if (glm::length(b - a) < 0.1) continue;
        const double t = std::clamp(glm::dot(X - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
        const double expected = glm::length(X - (a + t * (b - a)));
        const ClosestPoint p = closest_point(line(a, b), {X.x, X.y});
        REQUIRE(std::abs(p.distance - expected) <= kDistanceRel * glm::length(b - a));
        REQUIRE(std::abs(p.u - t) <= 1e-6);
    }
}

TEST_CASE("passes-through: relative to the control polygon's size, the same verdict at every scale and turn", "[exercise][property]") {
    // The circle's control polygon is the square around it: its diameter is the diagonal 2 sqrt(2) r.
    const Curve unit = nurbs_circle({0, 0}, 2, 1);
    CHECK(std::abs(control_polygon_diameter(unit) - 2 * std::sqrt(2.0)) <= 1e-15 * 4);
    std::mt19937_64 rng(1913);
    std::uniform_real_distribution<double> u01(0, 1), u11(-1, 1);
    const double size = 2 * std::sqrt(2.0);
    for (int n = 0; n < kCases; ++n) {
        // A point at a known distance from the unit circle: 0.5x or 2x the allowed distance.
        const bool inside_tolerance = n % 2 == 0;
        const double gap = (inside_tolerance ? 0.5 : 2.0) * kTolerance * size;
        const double theta = 2 * kPi * u01(rng);
        const dvec2 X = (1 + (u01(rng) < 0.5 ? gap : -gap)) * dvec2(std::cos(theta), std::sin(theta));
        // The whole drawing scaled by 10^(-6..6), turned and moved.
        const double scale = std::pow(10.0, 6 * u11(rng)), angle = kPi * u11(rng);
        const dvec2 shift = 10 * scale * dvec2(u11(rng), u11(rng));
        const dvec2 c = shift;
        const dvec2 Y = scale * glm::rotate(X, angle) + shift;
        const PropertyCheck r = check_passes_through(nurbs_circle({c.x, c.y}, 2, scale), {Y.x, Y.y}, kTolerance);
        INFO("scale " << scale << ", gap " << gap);
        REQUIRE(r.holds == inside_tolerance);
        REQUIRE(std::abs(r.relative_distance - gap / size) <= 1e-8);
    }
}

TEST_CASE("passes-through: the reason names the distance, the closest u and the tolerance", "[exercise][property]") {
    // The segment from (0, 0) to (4, 0): size 4; the point (2, 1) is 1 away at u = 0.5.
    const PropertyCheck r = check_passes_through(line({0, 0}, {4, 0}), {2, 1}, 0.1);
    CHECK(!r.holds);
    CHECK(r.reason == "the curve comes no closer than 1 to (2, 1) (at u = 0.5, P(u) = (2, 0)): 0.25 of the control polygon's size 4, "
                      "more than the tolerance 0.1; move control points so the curve passes closer");
    const PropertyCheck ok = check_passes_through(line({0, 0}, {4, 0}), {2, 0.2}, 0.1);
    CHECK(ok.holds);
    CHECK(ok.reason.find("the curve passes within 0.2 of (2, 0.2)") == 0);
    expect_error([] { check_passes_through(line({0, 0}, {4, 0}), {2, 1}, 0); }, "invalid-argument", "tolerance");
    expect_error([] { check_passes_through(line({0, 0}, {4, 0}), {2, 1, 0}, 0.1); }, "invalid-argument", "3 coordinates");
    expect_error([] { check_passes_through(line({1, 1}, {1, 1}), {2, 1}, 0.1); }, "degenerate-curve", "single point");
}

TEST_CASE("closest point: the same straight line y = 0, x in [0, 3], drawn by every polynomial family", "[exercise][property]") {
    auto with = [](CurveKind kind, std::vector<double> points) {
        Curve c;
        c.kind = kind;
        c.dim = 2;
        c.points = std::move(points);
        return c;
    };
    Curve hermite = with(CurveKind::Hermite, {0, 0, 1, 0, 2, 0, 3, 0});
    hermite.tangents = {1, 0, 1, 0, 1, 0, 1, 0};
    Curve bspline = with(CurveKind::BSpline, {0, 0, 1, 0, 2, 0, 3, 0});
    bspline.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    const Curve lines[] = {with(CurveKind::Bezier, {0, 0, 1, 0, 2, 0, 3, 0}), bspline, hermite,
                           with(CurveKind::CatmullRom, {-1, 0, 0, 0, 1, 0, 2, 0, 3, 0, 4, 0}),
                           with(CurveKind::Interpolation, {0, 0, 1, 0, 2, 0, 3, 0})};
    std::mt19937_64 rng(1914);
    std::uniform_real_distribution<double> u01(0, 1);
    for (const Curve& c : lines) {
        for (int n = 0; n < 200; ++n) {
            const double x = 3 * u01(rng), h = 2 * u01(rng) - 1;
            const ClosestPoint p = closest_point(c, {x, h});
            INFO(curve_kind_name(c.kind) << " at (" << x << ", " << h << ")");
            REQUIRE(std::abs(p.distance - std::abs(h)) <= kDistanceRel * 3);
            REQUIRE(std::abs(p.point[0] - x) <= 1e-6);
        }
    }
}
