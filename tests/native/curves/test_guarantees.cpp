// What each representation guarantees for every control polygon, against
// the comparison tables of lecture 003 (Hermite, Bezier, B-spline, Catmull-Rom) and lecture
// 001 (non-uniform B-spline), and against the joint classifier on random polygons: a
// generic polygon has exactly the guaranteed continuity, never less.
#include <catch2/catch.hpp>

#include "wingspline/curves/analysis.h"
#include "wingspline/curves/guarantees.h"

#include <random>

using namespace wingspline::curves;

namespace {
constexpr double kJointTolerance = 1e-9; // relative, as joint_continuity uses it

// A construction: slots are the control points (and tangents); maps[s] = 4 x slots.
struct Construction {
    int32_t slots = 0;
    std::vector<std::vector<double>> maps;
    std::vector<bool> is_point;
};
// Segment s reads geometry row r from slot rows[r] with weight 1.
std::vector<double> pick(int32_t slots, std::array<int, 4> rows) {
    std::vector<double> m(4 * static_cast<std::size_t>(slots), 0.0);
    for (int r = 0; r < 4; ++r) m[static_cast<std::size_t>(slots) * r + rows[r]] = 1;
    return m;
}
// Lecture 003's piecewise Bezier: segment i is P3i..P3i+3 (the joint shares P3).
Construction bezier_chain(int segments = 2) {
    Construction c{3 * segments + 1, {}, {}};
    c.is_point.assign(c.slots, true);
    for (int s = 0; s < segments; ++s) c.maps.push_back(pick(c.slots, {3 * s, 3 * s + 1, 3 * s + 2, 3 * s + 3}));
    return c;
}
// Windows of four (uniform B-spline, Catmull-Rom): segment i uses P_i..P_i+3.
Construction windows(int points = 7) {
    Construction c{points, {}, {}};
    c.is_point.assign(c.slots, true);
    for (int s = 0; s + 3 < points; ++s) c.maps.push_back(pick(c.slots, {s, s + 1, s + 2, s + 3}));
    return c;
}
// Hermite: slots P0..P(n-1), then tangents. Inherent: each segment its own two tangents
// (slots out_i, in_i+1); shared: one tangent per point.
Construction hermite(int points, bool shared) {
    const int tangents = shared ? points : 2 * (points - 1);
    Construction c{points + tangents, {}, {}};
    c.is_point.assign(c.slots, false);
    for (int i = 0; i < points; ++i) c.is_point[i] = true;
    for (int s = 0; s + 1 < points; ++s) {
        const int t0 = shared ? points + s : points + 2 * s;
        const int t1 = shared ? points + s + 1 : points + 2 * s + 1;
        c.maps.push_back(pick(c.slots, {s, s + 1, t0, t1}));
    }
    return c;
}
// Lecture 001 "Achieving Continuity": P4 = 2 P3 - P2 (collinear, equal legs); slot 4 unused.
Construction bezier_mirrored() {
    Construction c = bezier_chain(2);
    std::vector<double>& m = c.maps[1];
    m[static_cast<std::size_t>(c.slots) * 1 + 4] = 0;
    m[static_cast<std::size_t>(c.slots) * 1 + 3] = 2;
    m[static_cast<std::size_t>(c.slots) * 1 + 2] = -1;
    return c;
}
Guarantees of(BasisKind b, const Construction& c) { return chain_guarantees(b, c.slots, c.maps, c.is_point); }
} // namespace

TEST_CASE("lecture 003's table: inherent and easily achieved continuity, interpolation", "[curves][guarantees]") {
    // Inherent continuity: C0 G0 | C0 G0 | C2 G2 | C1 G1.
    const Guarantees h = of(BasisKind::Hermite, hermite(5, false));
    CHECK(h.parametric == 0); CHECK(h.geometric == 0); CHECK(h.joints == 3);
    const Guarantees b = of(BasisKind::Bezier, bezier_chain(3));
    CHECK(b.parametric == 0); CHECK(b.geometric == 0); CHECK(b.joints == 2);
    const Guarantees s = of(BasisKind::BSpline, windows(7));
    CHECK(s.parametric == 2); CHECK(s.geometric == 2);
    const Guarantees r = of(BasisKind::CatmullRom, windows(7));
    CHECK(r.parametric == 1); CHECK(r.geometric == 1);
    // Easily achieved: Hermite sharing tangents and Bezier mirrored are C1 G1.
    const Guarantees hs = of(BasisKind::Hermite, hermite(5, true));
    CHECK(hs.parametric == 1); CHECK(hs.geometric == 1);
    const Guarantees bm = of(BasisKind::Bezier, bezier_mirrored());
    CHECK(bm.parametric == 1); CHECK(bm.geometric == 1);
    // Interpolates some / all: Hermite all points (never its tangents), Bezier every third,
    // the B-spline none, Catmull-Rom every point its segments run between (P1..P5 of 7).
    CHECK(h.interpolated == std::vector<int32_t>{0, 1, 2, 3, 4});
    CHECK(b.interpolated == std::vector<int32_t>{0, 3, 6, 9});
    CHECK(s.interpolated.empty());
    CHECK(r.interpolated == std::vector<int32_t>{1, 2, 3, 4, 5});
}

TEST_CASE("lecture 001's non-uniform B-spline: C^(p-m) at a knot of multiplicity m", "[curves][guarantees]") {
    // Unequal gaps, simple knots: C2 G2, no control point interpolated (YES NO NO ... C2 G2).
    const std::vector<double> simple{0, 0.6, 1, 2.2, 3, 3.5, 4.8, 5.4, 6.5, 7, 8};
    const Guarantees g = bspline_guarantees(simple, 3, 7);
    CHECK(g.parametric == 2); CHECK(g.geometric == 2); CHECK(g.joints == 3);
    CHECK(g.interpolated.empty());
    // A double interior knot: p - m = 1; a triple one: 0, and the curve passes through the
    // control point whose basis function is 1 there (lecture 001: "C0 ... interpolates").
    const Guarantees d = bspline_guarantees({0, 0, 0, 0, 1, 2, 2, 3, 4, 4, 4, 4}, 3, 8);
    CHECK(d.parametric == 1);
    const Guarantees t = bspline_guarantees({0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2}, 3, 7);
    CHECK(t.parametric == 0);
    // Clamped: both ends interpolated; the triple knot at 1 interpolates P3.
    CHECK(t.interpolated == std::vector<int32_t>{0, 3, 6});
    // Scale of the parameter does not change a guarantee.
    for (double k : {1e-6, 1e6}) {
        std::vector<double> scaled = simple;
        for (double& x : scaled) x *= k;
        const Guarantees gs = bspline_guarantees(scaled, 3, 7);
        CHECK(gs.parametric == 2); CHECK(gs.geometric == 2);
    }
    CHECK_THROWS_WITH(bspline_guarantees({0, 1, 0, 2, 3, 4, 5, 6}, 3, 4), Catch::Contains("must not decrease"));
}

TEST_CASE("a guarantee is tight: random polygons reach exactly it at every joint", "[curves][guarantees]") {
    // Independent check with the joint classifier on real curves (2000 seeded polygons).
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> coord(-5, 5);
    const struct { BasisKind basis; CurveKind kind; int parametric, geometric; } families[] = {
        {BasisKind::Bezier, CurveKind::Bezier, 0, 0}, {BasisKind::BSpline, CurveKind::BSpline, 2, 2},
        {BasisKind::CatmullRom, CurveKind::CatmullRom, 1, 1}};
    for (const auto& f : families) {
        const Guarantees g = f.basis == BasisKind::Bezier ? of(f.basis, bezier_chain(2)) : of(f.basis, windows(5));
        REQUIRE(g.parametric == f.parametric);
        REQUIRE(g.geometric == f.geometric);
        for (int trial = 0; trial < 2000; ++trial) {
            std::vector<double> p(14);
            for (double& x : p) x = coord(rng);
            const int shift = f.basis == BasisKind::Bezier ? 3 : 1;
            Curve a; a.kind = f.kind; a.dim = 2; a.points.assign(p.begin(), p.begin() + 8);
            Curve b; b.kind = f.kind; b.dim = 2; b.points.assign(p.begin() + 2 * shift, p.begin() + 2 * shift + 8);
            if (f.basis == BasisKind::Bezier) b.points[0] = a.points[6], b.points[1] = a.points[7];
            const JointContinuity j = joint_continuity(a, b, kJointTolerance);
            CHECK(j.parametric == std::min(g.parametric, 2));
            CHECK(j.geometric == g.geometric);
        }
    }
}
