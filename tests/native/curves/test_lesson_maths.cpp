// The mathematics that lived in the curve lessons' JavaScript, now in the
// core: knot vector presets (lecture 002, open/clamped and uniform knots), the segment that
// holds a parameter, and the continuity constraints kept while a control point is dragged
// (lecture 001 "Achieving Continuity", lecture 002 "C^n and G^n"). Checked against the
// lectures' formulas, exact fractions, and the joint classifier (analysis.h, independent of
// the constraint code) on thousands of random seeded chains.
#include <catch2/catch.hpp>

#include "wingspline/curves/analysis.h"
#include "wingspline/curves/constraints.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/knot_vectors.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace wingspline::curves;

namespace {

constexpr double kJointTolerance = 1e-9;  // relative, as joint_continuity reads it
constexpr double kFormulaRel = 1e-12;     // relative: a lecture formula met up to rounding
constexpr double kKnotRounding = 0.5e-9;  // the presets round new knots to whole billionths

std::string code_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const wingspline::Error& e) {
        return e.code();
    }
    return "no error";
}

double size_of(const std::vector<double>& v) {
    double m = 1e-300;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

// |a - b| (entries `first`..`first+1` of a dim-2 array) relative to the data's size.
bool same_point(const std::vector<double>& p, int i, double x, double y, double size) {
    return std::hypot(p[2 * i] - x, p[2 * i + 1] - y) <= kFormulaRel * size;
}

Curve bezier_segment(const std::vector<double>& p, int s) {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.dim = 2;
    c.points.assign(p.begin() + 8 * s, p.begin() + 8 * s + 8);
    return c;
}
Curve hermite_segment(const std::vector<double>& p, int s) {
    Curve c;
    c.kind = CurveKind::Hermite;
    c.dim = 2;
    c.points.assign(p.begin() + 8 * s, p.begin() + 8 * s + 4);
    c.tangents.assign(p.begin() + 8 * s + 4, p.begin() + 8 * s + 8);
    return c;
}
Curve segment_of(BasisKind family, const std::vector<double>& p, int s) {
    return family == BasisKind::Bezier ? bezier_segment(p, s) : hermite_segment(p, s);
}

} // namespace

TEST_CASE("clamped knots are p+1 zeros, the interior j/(K-p), p+1 ones (lecture 002)", "[curves][knots]") {
    // K = 7, p = 3: 0,0,0,0, 1/4, 1/2, 3/4, 1,1,1,1
    const auto t = clamped_knots(7, 3);
    const std::vector<double> expected = {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1};
    CHECK(t == expected);
    CHECK(is_clamped(t, 3));
    for (int p = 1; p <= 7; ++p) {
        for (int K = p + 1; K <= 24; ++K) {
            const auto k = clamped_knots(K, p);
            REQUIRE(k.size() == static_cast<std::size_t>(K + p + 1));
            for (int j = 0; j <= p; ++j) {
                CHECK(k[j] == 0.0);
                CHECK(k[K + j] == 1.0);
            }
            // interior knot j is the fraction j/(K-p), to the rounding of whole billionths
            for (int j = 1; j < K - p; ++j) CHECK(std::abs(k[p + j] * (K - p) - j) <= kKnotRounding * (K - p));
            CHECK(is_clamped(k, p));
        }
    }
    CHECK(code_of([] { clamped_knots(3, 3); }) == "too-few-points");
    CHECK(code_of([] { clamped_knots(5, 0); }) == "degree-out-of-range");
}

TEST_CASE("1/3 and 2/3 are rounded to whole billionths, half-way values upwards", "[curves][knots]") {
    const auto t = clamped_knots(5, 2); // interior 1/3, 2/3
    CHECK(t[3] == 0.333333333);
    CHECK(t[4] == 0.666666667);
}

TEST_CASE("unclamped knots keep the domain and interior and spread the ends by the end spacing", "[curves][knots]") {
    const std::vector<double> clamped = {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1};
    const auto u = unclamped_knots(clamped, 3);
    const std::vector<double> expected = {-0.75, -0.5, -0.25, 0, 0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75};
    CHECK(u == expected);
    CHECK_FALSE(is_clamped(u, 3));
    // unequal end spacings: h = 0.1 at the start, 0.4 at the end; a double knot inside stays
    const std::vector<double> uneven = {0, 0, 0, 0.1, 0.5, 0.5, 0.6, 1, 1, 1};
    const auto v = unclamped_knots(uneven, 2);
    const std::vector<double> expected2 = {-0.2, -0.1, 0, 0.1, 0.5, 0.5, 0.6, 1, 1.4, 1.8};
    for (std::size_t j = 0; j < v.size(); ++j) CHECK(v[j] == Approx(expected2[j]).margin(kKnotRounding));
    // the curve on the new knots has the same domain [t_p, t_K]
    CHECK(v[2] == 0.0);
    CHECK(v[7] == 1.0);
    CHECK(code_of([] { unclamped_knots({0, 0, 1, 1}, 3); }) == "wrong-knot-count");
    CHECK(code_of([] { unclamped_knots({0, 0, 0, 1, 0.5, 1, 1, 1}, 2); }) == "decreasing-knots");
    CHECK(code_of([] { is_clamped({0, 0, 1, 1}, 1); }) == "no error");
    CHECK(code_of([] { is_clamped({0, 1}, 2); }) == "wrong-knot-count");
}

TEST_CASE("segment_at names the segment whose range holds t (checked against segment_matrices)", "[curves][segment]") {
    std::mt19937 rng(1402);
    std::uniform_real_distribution<double> coord(-5, 5);
    std::uniform_real_distribution<double> unit(0, 1);
    auto random_points = [&](int K) {
        std::vector<double> p(2 * K);
        for (double& x : p) x = coord(rng);
        return p;
    };
    for (int trial = 0; trial < 2000; ++trial) {
        Curve c;
        const int family = trial % 4;
        const int K = 4 + trial % 6;
        c.points = random_points(K);
        if (family == 0) { c.kind = CurveKind::Hermite; c.tangents = random_points(K); }
        if (family == 1) c.kind = CurveKind::CatmullRom;
        if (family == 2) { c.kind = CurveKind::BSpline; c.degree = 1 + trial % std::min(3, K - 1); }
        if (family == 3) {
            // a non-uniform vector with a repeated interior knot: empty spans are skipped
            c.kind = CurveKind::Nurbs;
            c.degree = 2;
            c.knots = clamped_knots(K, 2);
            if (K >= 5) c.knots[4] = c.knots[3];
            c.weights.assign(K, 1.0);
            c.weights[1] = 2.0;
        }
        const CurveEvaluator ev(c);
        const double t = trial % 10 == 0 ? ev.domain().end : ev.domain().start + unit(rng) * (ev.domain().end - ev.domain().start);
        const int s = segment_at(c, t);
        const SegmentMatrices m = segment_matrices(c, s);
        INFO("trial " << trial << " t " << t << " segment " << s);
        CHECK(m.start <= t);
        CHECK(t <= m.end);
        if (t < ev.domain().end) CHECK(t < m.end);
        else CHECK(s == m.segment_count - 1);
    }
    Curve h;
    h.kind = CurveKind::Hermite;
    h.points = {0, 0, 1, 0, 2, 0, 3, 0};
    h.tangents = {1, 0, 1, 0, 1, 0, 1, 0};
    CHECK(segment_at(h, 1.5) == 1);
    CHECK(segment_at(h, 1.0) == 1);
    CHECK(segment_at(h, 3.0) == 2);
    CHECK(code_of([&] { segment_at(h, 3.5); }) == "parameter-out-of-range");
    CHECK(code_of([&] { segment_at(h, std::nan("")); }) == "non-finite-input");
    Curve b;
    b.kind = CurveKind::BSpline;
    b.degree = 3;
    b.points = {0, 0, 1, 1, 2, 0, 3, 1, 4, 0, 5, 1};
    b.knots = {0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1}; // spans [0, .5) and [.5, 1]
    CHECK(segment_at(b, 0.49) == 0);
    CHECK(segment_at(b, 0.5) == 1);
    CHECK(segment_at(b, 1.0) == 1);
}

TEST_CASE("the lecture's joint formulas hold after a drag (Bezier C1, C2; Hermite C2)", "[curves][constraints]") {
    // two Bezier segments, L0..L3 then R0..R3; drag L2 with C2 kept: the right side follows
    const std::vector<double> p = {0, 0, 1, 2, 2, 2, 3, 0, 3, 0, 4, -1, 5, 1, 6, 0};
    const auto c2 = drag_with_constraint(p, 2, BasisKind::Bezier, JointConstraint::C2, 2, {2.5, 1.5});
    const double size = size_of(c2);
    CHECK(same_point(c2, 2, 2.5, 1.5, size));
    CHECK(same_point(c2, 4, c2[6], c2[7], size)); // C0: R0 = L3
    // C1: J - L2 = R1 - J, i.e. R1 = 2 J - L2
    CHECK(same_point(c2, 5, 2 * c2[6] - c2[4], 2 * c2[7] - c2[5], size));
    // C2: R2 = L1 - 4 L2 + 4 L3
    CHECK(same_point(c2, 6, c2[2] - 4 * c2[4] + 4 * c2[6], c2[3] - 4 * c2[5] + 4 * c2[7], size));
    // Hermite: P''(1) = 6p0 - 6p1 + 2t0 + 4t1 equals Q''(0) = -6q0 + 6q1 - 4s0 - 2s1
    const std::vector<double> h = {0, 0, 2, 1, 1, 3, 2, 0, 2, 1, 4, 0, 1, 1, 0, -2};
    const auto hc = drag_with_constraint(h, 2, BasisKind::Hermite, JointConstraint::C2, 2, {0.5, 2.5});
    for (int k = 0; k < 2; ++k) {
        const double left = 6 * hc[k] - 6 * hc[2 + k] + 2 * hc[4 + k] + 4 * hc[6 + k];
        const double right = -6 * hc[8 + k] + 6 * hc[10 + k] - 4 * hc[12 + k] - 2 * hc[14 + k];
        CHECK(std::abs(left - right) <= kFormulaRel * 6 * size_of(hc));
    }
    // free: only the dragged entry moves
    const auto free = drag_with_constraint(p, 2, BasisKind::Bezier, JointConstraint::Free, 5, {9, 9});
    for (std::size_t j = 0; j < p.size(); ++j) CHECK(free[j] == (j == 10 || j == 11 ? 9.0 : p[j]));
}

TEST_CASE("every joint keeps the chosen continuity after any drag (random chains, classifier)", "[curves][constraints]") {
    std::mt19937 rng(14005);
    std::uniform_real_distribution<double> coord(-4, 4);
    const JointConstraint modes[] = {JointConstraint::C0, JointConstraint::G1, JointConstraint::C1, JointConstraint::C2};
    const int wanted_parametric[] = {0, 0, 1, 2};
    const int wanted_geometric[] = {0, 1, 1, 2};
    int checked = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const BasisKind family = trial % 2 ? BasisKind::Hermite : BasisKind::Bezier;
        const int m = (trial / 2) % 4;
        const int segments = 2 + trial % 4;
        // the data at a random scale and offset: verdicts must not depend on either
        const double scale = std::pow(10.0, (trial % 13) - 6);
        const double offset = scale * coord(rng) * 100;
        std::vector<double> p(8 * segments);
        for (double& x : p) x = offset + scale * coord(rng);
        if (family == BasisKind::Hermite) for (int s = 0; s < segments; ++s) for (int j = 4; j < 8; ++j) p[8 * s + j] -= offset;
        p = enforce_constraint(p, 2, family, modes[m]);
        const int index = static_cast<int>(rng() % (4 * segments));
        const std::vector<double> to = {offset + scale * coord(rng), offset + scale * coord(rng)};
        const auto q = drag_with_constraint(p, 2, family, modes[m], index, family == BasisKind::Hermite && index % 4 >= 2
                                                                                   ? std::vector<double>{to[0] - offset, to[1] - offset}
                                                                                   : to);
        INFO("trial " << trial << " family " << (family == BasisKind::Bezier ? "bezier" : "hermite") << " mode " << m << " index " << index);
        for (int j = 1; j < segments; ++j) {
            const auto v = joint_continuity(segment_of(family, q, j - 1), segment_of(family, q, j), kJointTolerance);
            CHECK(v.parametric >= wanted_parametric[m]);
            CHECK(v.geometric >= wanted_geometric[m]);
            ++checked;
        }
    }
    CHECK(checked > 8000);
}

TEST_CASE("G1 keeps the moved leg's length; a leg without direction leaves the other side", "[curves][constraints]") {
    // L2 = (2, 2), J = (3, 0), R1 = (3, -1): after G1 with the left as master R1 lies on the
    // ray from J away from L2, at its old distance 1.
    const std::vector<double> p = {0, 0, 1, 2, 2, 2, 3, 0, 3, 0, 3, -1, 5, 1, 6, 0};
    const auto g = enforce_constraint(p, 2, BasisKind::Bezier, JointConstraint::G1);
    const double dx = 3 - 2, dy = 0 - 2, n = std::hypot(dx, dy);
    CHECK(g[10] == Approx(3 + dx / n).epsilon(kFormulaRel));
    CHECK(g[11] == Approx(dy / n).epsilon(kFormulaRel));
    // L2 = J: no direction; R1 is left where it was (the joint stays C0)
    std::vector<double> d = p;
    d[4] = 3; d[5] = 0;
    const auto gd = enforce_constraint(d, 2, BasisKind::Bezier, JointConstraint::G1);
    CHECK(gd[10] == 3.0);
    CHECK(gd[11] == -1.0);
}

TEST_CASE("a new segment continues the chain and keeps the mode", "[curves][constraints]") {
    const std::vector<double> p = {0, 0, 1, 2, 2, 2, 3, 0, 3, 0, 4, -2, 5, 1, 6, 0};
    const auto b = append_segment(p, 2, BasisKind::Bezier, JointConstraint::C1);
    REQUIRE(b.size() == 24);
    // starts at the old end point; C1 at the new joint: R1 = 2 J - L2
    CHECK(b[16] == 6.0);
    CHECK(b[17] == 0.0);
    CHECK(b[18] == Approx(2 * 6 - 5));
    CHECK(b[19] == Approx(2 * 0 - 1));
    // windows of four: P_n = P_n-1 + (P_n-1 - P_n-3) / 2
    const std::vector<double> w = {0, 0, 1, 1, 2, 0, 3, 1};
    const auto c = append_segment(w, 2, BasisKind::CatmullRom, JointConstraint::Free);
    REQUIRE(c.size() == 10);
    CHECK(c[8] == 3 + (3 - 1) / 2.0);
    CHECK(c[9] == 1 + (1 - 1) / 2.0);
    CHECK(code_of([&] { drag_with_constraint(w, 2, BasisKind::BSpline, JointConstraint::C1, 0, {0, 0}); }) == "unsupported-curve-kind");
    CHECK(code_of([&] { drag_with_constraint(p, 2, BasisKind::Bezier, JointConstraint::C1, 8, {0, 0}); }) == "invalid-argument");
    CHECK(code_of([&] { drag_with_constraint({0, 0, 1, 1, 2, 2}, 2, BasisKind::Bezier, JointConstraint::C1, 0, {0, 0}); }) == "wrong-point-count");
    CHECK(code_of([&] { drag_with_constraint(p, 2, BasisKind::Bezier, JointConstraint::C1, 0, {0, std::nan("")}); }) == "non-finite-input");
    CHECK(code_of([] { parse_joint_constraint("C3"); }) == "invalid-argument");
}
