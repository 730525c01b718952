// NURBS conics, curvature, arc length, joint continuity, polynomial interpolation and
// bicubic patches against analytic values (lectures 000, 001, 002, 004).
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/analysis.h"
#include "wingspline/curves/bezier.h"
#include "wingspline/curves/bspline_ops.h"
#include "wingspline/curves/conics.h"
#include "wingspline/curves/patch.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <cmath>

using namespace wingspline::curves;
using namespace curves_fixtures;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kLength = 1e-12; // relative, arc lengths by Gauss-Legendre
constexpr double kJointTolerance = 1e-9;
} // namespace

TEST_CASE("the NURBS circle lies on the circle to 1e-12", "[curves][nurbs]") {
    for (int dim : {2, 3}) {
        const std::vector<double> center = dim == 2 ? std::vector<double>{1.5, -2} : std::vector<double>{1.5, -2, 0.75};
        const double r = 3.25;
        const Curve c = nurbs_circle(center, dim, r);
        CHECK(control_point_count(c) == 9);
        const auto u = linspace(0, 1, 10001);
        const auto p = evaluate_curve(c, u);
        for (std::size_t j = 0; j < u.size(); ++j) {
            CHECK(std::abs(distance(&p[dim * j], center.data(), 2) - r) < kCircle);
            if (dim == 3) CHECK(p[3 * j + 2] == Approx(0.75).margin(kExact));
        }
    }
}

TEST_CASE("NURBS arcs, the ellipse and the conic weights", "[curves][nurbs]") {
    const Curve arc = nurbs_arc({0, 0}, 2, 2, kPi / 6, kPi);
    const auto ends = evaluate_curve(arc, {0, 1});
    CHECK(ends[0] == Approx(2 * std::cos(kPi / 6)).margin(kExact));
    CHECK(ends[1] == Approx(2 * std::sin(kPi / 6)).margin(kExact));
    CHECK(ends[2] == Approx(-2).margin(kExact));
    for (double v : linspace(0, 1, 501)) {
        const auto p = evaluate_curve(arc, {v});
        CHECK(std::hypot(p[0], p[1]) == Approx(2).margin(kCircle));
    }
    const Curve e = nurbs_ellipse({1, 1}, 2, 3, 0.5);
    for (double v : linspace(0, 1, 501)) {
        const auto p = evaluate_curve(e, {v});
        const double x = (p[0] - 1) / 3, y = (p[1] - 1) / 0.5;
        CHECK(x * x + y * y == Approx(1).margin(1e-12));
    }
    // A quarter of the unit circle is the conic (1,0), (1,1), (0,1) with w = cos 45 degrees.
    const Curve quarter = nurbs_conic({1, 0}, {1, 1}, {0, 1}, 2, std::sqrt(0.5));
    for (double v : linspace(0, 1, 101)) {
        const auto p = evaluate_curve(quarter, {v});
        CHECK(std::hypot(p[0], p[1]) == Approx(1).margin(kCircle));
    }
    CHECK(std::string(conic_type(0.5)) == "ellipse");
    CHECK(std::string(conic_type(1.0)) == "parabola");
    CHECK(std::string(conic_type(2.0)) == "hyperbola");
    // w = 1: the parabola through (0,0), apex tangent towards (1,2), to (2,0): y = 2x - x^2
    const Curve parabola = nurbs_conic({0, 0}, {1, 2}, {2, 0}, 2, 1.0);
    for (double v : linspace(0, 1, 41)) {
        const auto p = evaluate_curve(parabola, {v});
        CHECK(p[1] == Approx(2 * p[0] - p[0] * p[0]).margin(kExact * 10));
    }
}

TEST_CASE("curvature: 1/r on a circle, 0 on a line, sign by turning direction", "[curves][curvature]") {
    const Curve circle = nurbs_circle({0, 0}, 2, 4);
    const auto k = curvature(circle, linspace(0, 1, 97));
    for (std::size_t j = 0; j < k.curvature.size(); ++j) {
        CHECK(k.curvature[j] == Approx(0.25).margin(1e-12));
        CHECK(k.signed_curvature[j] == Approx(0.25).margin(1e-12)); // counter-clockwise
        CHECK(std::hypot(k.tangent[2 * j], k.tangent[2 * j + 1]) == Approx(1).margin(kExact * 10));
    }
    const Curve line = make_curve(CurveKind::Bezier, {0, 0, 1, 1, 2, 2, 3, 3});
    for (double v : curvature(line, linspace(0, 1, 11)).curvature) CHECK(v == Approx(0).margin(kExact));
    // a cusp: P1 = P2 = P3 gives P'(1) = 0, reported as singular, not NaN
    const Curve cusp = make_curve(CurveKind::Bezier, {0, 0, 1, 1, 1, 1, 1, 1});
    const auto c = curvature(cusp, {1.0});
    CHECK(c.singular[0] == 1);
    CHECK(c.curvature[0] == 0.0);
}

TEST_CASE("arc length: the circumference, a straight Bezier, and additivity", "[curves][arclength]") {
    const double r = 2.5;
    CHECK(arc_length(nurbs_circle({0, 0}, 2, r), 0, 1) == Approx(2 * kPi * r).epsilon(kLength));
    // control points evenly on a line: the curve is the segment, length |P3 - P0| = 5
    const Curve line = make_curve(CurveKind::Bezier, {0, 0, 1, 4.0 / 3, 2, 8.0 / 3, 3, 4});
    CHECK(arc_length(line, 0, 1) == Approx(5).epsilon(kLength));
    const Curve c = clamped_with_double_knot();
    const double whole = arc_length(c, 0, 5);
    CHECK(arc_length(c, 0, 2.2) + arc_length(c, 2.2, 5) == Approx(whole).epsilon(kLength));
}

TEST_CASE("arc-length parameters split the curve into equal lengths", "[curves][arclength]") {
    for (const Curve& c : {clamped_with_double_knot(), nurbs_circle({0, 0}, 2, 1)}) {
        const ArcLengthParams a = arc_length_params(c, 17);
        const double step = a.total / 16;
        for (int j = 0; j < 16; ++j) {
            CHECK(a.params[j] < a.params[j + 1]);
            CHECK(arc_length(c, a.params[j], a.params[j + 1]) == Approx(step).epsilon(1e-10));
        }
    }
}

TEST_CASE("joint continuity on constructed joints (lectures 001, 004)", "[curves][continuity]") {
    auto bez = [](std::vector<double> p) { return make_curve(CurveKind::Bezier, std::move(p)); };
    const Curve a = bez({0, 0, 1, 1, 2, 1, 3, 0});
    SECTION("C-1: the curves do not meet") {
        const JointContinuity j = joint_continuity(a, bez({3, 0.5, 4, 0, 5, 0, 6, 1}), kJointTolerance);
        CHECK(j.parametric == -1);
        CHECK(j.geometric == -1);
        CHECK(j.evidence.position_gap == Approx(0.5));
    }
    SECTION("C0 only: a corner") {
        const JointContinuity j = joint_continuity(a, bez({3, 0, 4, 1, 5, 0, 6, 1}), kJointTolerance);
        CHECK(j.parametric == 0);
        CHECK(j.geometric == 0);
        CHECK(j.evidence.tangent_angle == Approx(kPi / 2));
    }
    SECTION("G1 but not C1: same direction, twice as long") {
        // a'(1) = 3 (P3 - P2) = (3, -3); b'(0) = 3 (Q1 - Q0) = (6, -6)
        const JointContinuity j = joint_continuity(a, bez({3, 0, 5, -2, 6, 0, 7, 1}), kJointTolerance);
        CHECK(j.parametric == 0);
        CHECK(j.geometric == 1);
        CHECK(j.evidence.ratio == Approx(2));
    }
    SECTION("C1 but not C2 (and not G2)") {
        // Q1 = 2 P3 - P2 (lecture 001's J - P02 = P11 - J)
        const JointContinuity j = joint_continuity(a, bez({3, 0, 4, -1, 6, 0, 7, 2}), kJointTolerance);
        CHECK(j.parametric == 1);
        CHECK(j.geometric == 1);
        CHECK(j.evidence.d1_gap == Approx(0).margin(1e-12));
        CHECK(j.evidence.d2_gap > 1);
    }
    SECTION("C2: neighbouring Bezier pieces of a cubic B-spline") {
        const auto pieces = to_bezier_segments(make_curve(CurveKind::BSpline, zigzag(6)));
        const JointContinuity j = joint_continuity(bez(pieces[0].points), bez(pieces[1].points), kJointTolerance);
        CHECK(j.parametric == 2);
        CHECK(j.geometric == 2);
        CHECK(j.evidence.curvature_a == Approx(j.evidence.curvature_b).epsilon(1e-9));
    }
    SECTION("G2 but not C1: one circle, two speeds") {
        const Curve quarter = nurbs_arc({0, 0}, 2, 1, 0, kPi / 2);
        const Curve half = nurbs_arc({0, 0}, 2, 1, kPi / 2, 3 * kPi / 2);
        const JointContinuity j = joint_continuity(quarter, half, kJointTolerance);
        CHECK(j.parametric == 0);
        CHECK(j.geometric == 2);
        CHECK(j.evidence.curvature_a == Approx(1).epsilon(1e-12));
        CHECK(j.evidence.curvature_b == Approx(1).epsilon(1e-12));
    }
    SECTION("the exception to C1 => G1: zero tangents on both sides") {
        const Curve a0 = bez({0, 0, 1, 1, 3, 0, 3, 0});  // P2 = P3: a'(1) = 0
        const Curve b0 = bez({3, 0, 3, 0, 4, 2, 6, 1});  // Q0 = Q1: b'(0) = 0
        const JointContinuity j = joint_continuity(a0, b0, kJointTolerance);
        CHECK(j.parametric >= 1);
        CHECK(j.geometric == 0);
        CHECK(j.evidence.zero_tangent);
        CHECK_FALSE(j.evidence.notes.empty());
    }
}

TEST_CASE("polynomial interpolation: lecture 000's Vandermonde system and Runge's wiggles", "[curves][interpolation]") {
    // 11 equispaced samples of Runge's f(x) = 1/(1 + 25 x^2) on [-1, 1]: the interpolant
    // misses f by up to 1.9156 near the ends (the classical figure), while the data never
    // exceed 1: the wiggles that motivate splines.
    Curve c = make_curve(CurveKind::Interpolation, {});
    for (int i = 0; i <= 10; ++i) {
        const double x = -1 + 0.2 * i;
        c.points.insert(c.points.end(), {x, 1 / (1 + 25 * x * x)});
        c.nodes.push_back(x);
    }
    double worst = 0;
    for (double u : linspace(-1, 1, 20001)) worst = std::max(worst, std::abs(evaluate_curve(c, {u})[1] - 1 / (1 + 25 * u * u)));
    CHECK(worst == Approx(1.9156).margin(5e-4));
    // C = V^-1 P: x(u) = u exactly, so the x column is (0, ..., 0, 1, 0)
    const SegmentMatrices s = segment_matrices(c, 0);
    for (int r = 0; r <= 10; ++r) CHECK(s.C[2 * r] == Approx(r == 9 ? 1.0 : 0.0).margin(1e-9));
}

TEST_CASE("Bezier patch: corner interpolation and lecture 002's twist vector", "[curves][patch]") {
    std::vector<double> P;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) P.insert(P.end(), {double(i), double(j), std::sin(i + 2.0 * j)});
    const PatchSamples s = sample_patch(BasisKind::Bezier, P, 5, 4);
    CHECK(s.positions.size() == 5 * 4 * 3);
    auto at = [&](int i, int j, int k) { return P[3 * (4 * i + j) + k]; };
    auto grid = [&](int i, int j, int k) { return s.positions[3 * (4 * i + j) + k]; };
    for (int k = 0; k < 3; ++k) {
        CHECK(grid(0, 0, k) == Approx(at(0, 0, k)).margin(kExact));
        CHECK(grid(0, 3, k) == Approx(at(0, 3, k)).margin(kExact));
        CHECK(grid(4, 0, k) == Approx(at(3, 0, k)).margin(kExact));
        CHECK(grid(4, 3, k) == Approx(at(3, 3, k)).margin(kExact));
        // d2p/dudv(0,0) = 9 (p00 - p01 - p10 + p11)
        CHECK(s.twists[k] == Approx(9 * (at(0, 0, k) - at(0, 1, k) - at(1, 0, k) + at(1, 1, k))).margin(1e-12));
        // dp/du(0,0) = 3 (p10 - p00)
        CHECK(s.du[k] == Approx(3 * (at(1, 0, k) - at(0, 0, k))).margin(1e-12));
    }
}

TEST_CASE("Hermite patch reproduces its geometry matrix at the corners", "[curves][patch]") {
    // G_H rows [p(0,.), p(1,.), p_u(0,.), p_u(1,.)], columns [(.,0), (.,1), _v(.,0), _v(.,1)]
    std::vector<double> G(48);
    for (int q = 0; q < 48; ++q) G[q] = std::cos(0.7 * q) * (q % 5 + 1);
    const PatchSamples s = sample_patch(BasisKind::Hermite, G, 2, 2);
    auto g = [&](int i, int j, int k) { return G[3 * (4 * i + j) + k]; };
    for (int k = 0; k < 3; ++k) {
        CHECK(s.positions[k] == Approx(g(0, 0, k)).margin(1e-12));          // p(0,0)
        CHECK(s.positions[3 + k] == Approx(g(0, 1, k)).margin(1e-12));      // p(0,1)
        CHECK(s.positions[6 + k] == Approx(g(1, 0, k)).margin(1e-12));      // p(1,0)
        CHECK(s.du[k] == Approx(g(2, 0, k)).margin(1e-12));                 // p_u(0,0)
        CHECK(s.dv[k] == Approx(g(0, 2, k)).margin(1e-12));                 // p_v(0,0)
        CHECK(s.twists[k] == Approx(g(2, 2, k)).margin(1e-12));             // p_uv(0,0)
        CHECK(s.twists[9 + k] == Approx(g(3, 3, k)).margin(1e-12));         // p_uv(1,1)
    }
    // a flat patch in z = 0 has normals (0, 0, +-1)
    std::vector<double> flat;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) flat.insert(flat.end(), {double(i), double(j) * 0.5, 0});
    const PatchSamples f = sample_patch(BasisKind::Bezier, flat, 3, 3);
    for (int q = 0; q < 9; ++q) CHECK(std::abs(f.normals[3 * q + 2]) == Approx(1).margin(kExact));
}

TEST_CASE("inherent continuity row of the comparison tables (lectures 001 and 003)", "[curves][continuity]") {
    // Neighbouring segments of each family, each as its own curve, joined where a ends.
    const auto p = zigzag(5);
    auto points = [&](int first, int count) { return std::vector<double>(p.begin() + 2 * first, p.begin() + 2 * (first + count)); };
    // Hermite: C1 by construction (shared point and tangent), not C2 in general
    Curve ha = make_curve(CurveKind::Hermite, points(0, 2));
    ha.tangents = {1, 0, 2, -1};
    Curve hb = make_curve(CurveKind::Hermite, points(1, 2));
    hb.tangents = {2, -1, 0, 3};
    CHECK(joint_continuity(ha, hb, kJointTolerance).parametric == 1);
    // Bezier: two cubics sharing an end point are C0 (and G0) only
    const JointContinuity bz = joint_continuity(make_curve(CurveKind::Bezier, points(0, 4)),
                                                make_curve(CurveKind::Bezier, {p[6], p[7], 5, 5, 6, 0, 7, 1}), kJointTolerance);
    CHECK(bz.parametric == 0);
    CHECK(bz.geometric == 0);
    // uniform B-spline: C2 (and G2)
    const JointContinuity bs = joint_continuity(make_curve(CurveKind::BSpline, points(0, 4)),
                                                make_curve(CurveKind::BSpline, points(1, 4)), kJointTolerance);
    CHECK(bs.parametric == 2);
    CHECK(bs.geometric == 2);
    // Catmull-Rom: C1 (and G1) but not C2
    const JointContinuity cr = joint_continuity(make_curve(CurveKind::CatmullRom, points(0, 4)),
                                                make_curve(CurveKind::CatmullRom, points(1, 4)), kJointTolerance);
    CHECK(cr.parametric == 1);
    CHECK(cr.geometric == 1);
}

TEST_CASE("cardinal spline is the Hermite spline with tangents (1-c)(P_i+1 - P_i-1)/2", "[curves][cardinal]") {
    const auto p = zigzag(6);
    for (double c : {0.0, 0.3, 0.9}) {
        Curve card = make_curve(CurveKind::Cardinal, p);
        card.tension = c;
        // Hermite through P1..P4 with those tangents
        Curve h = make_curve(CurveKind::Hermite, std::vector<double>(p.begin() + 2, p.begin() + 10));
        for (int i = 1; i <= 4; ++i)
            for (int k = 0; k < 2; ++k) h.tangents.push_back((1 - c) * (p[2 * (i + 1) + k] - p[2 * (i - 1) + k]) / 2);
        for (double u : linspace(0, 3, 31)) {
            const auto a = evaluate_curve(card, {u});
            const auto b = evaluate_curve(h, {u});
            CHECK(distance(a.data(), b.data(), 2) < kSameCurve);
        }
    }
}

TEST_CASE("rational de Casteljau: levels in homogeneous coordinates give the NURBS point", "[curves][bezier]") {
    // the quarter circle as a rational quadratic Bezier
    const std::vector<double> pts = {1, 0, 1, 1, 0, 1};
    const std::vector<double> w = {1, std::sqrt(0.5), 1};
    for (double t : linspace(0, 1, 9)) {
        const auto steps = de_casteljau(pts, 2, t, w);
        REQUIRE(steps.level_weights.size() == 3);
        CHECK(std::hypot(steps.levels[2][0], steps.levels[2][1]) == Approx(1).margin(kCircle));
        Curve c = make_curve(CurveKind::Bezier, pts);
        c.weights = w;
        const auto p = evaluate_curve(c, {t});
        CHECK(distance(p.data(), steps.levels[2].data(), 2) < kSameCurve);
    }
    const BezierSplit s = subdivide_bezier(pts, 2, 0.3, w);
    Curve right = make_curve(CurveKind::Bezier, s.right);
    right.weights = s.right_weights;
    for (double v : linspace(0, 1, 11)) {
        const auto p = evaluate_curve(right, {v});
        CHECK(std::hypot(p[0], p[1]) == Approx(1).margin(kCircle));
    }
}

TEST_CASE("segment matrices of a NURBS are homogeneous: C = M G reproduces (w x, w y, w)", "[curves][matrices][nurbs]") {
    const Curve circle = nurbs_circle({0, 0}, 2, 1);
    for (int s = 0; s < segment_count(circle); ++s) {
        const SegmentMatrices m = segment_matrices(circle, s);
        REQUIRE(m.homogeneous);
        REQUIRE(m.columns == 3);
        for (double u : {0.0, 0.4, 1.0}) {
            double h[3];
            for (int k = 0; k < 3; ++k) h[k] = u * u * m.C[k] + u * m.C[3 + k] + m.C[6 + k];
            const auto p = evaluate_curve(circle, {m.start + u * (m.end - m.start)});
            CHECK(h[0] / h[2] == Approx(p[0]).margin(kSameCurve));
            CHECK(h[1] / h[2] == Approx(p[1]).margin(kSameCurve));
        }
    }
}
