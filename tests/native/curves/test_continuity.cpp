// Trust: joint continuity that does not depend on the
// scale, position or orientation of the drawing; what each lecture's wording of G^n says;
// curvature that is undefined (not 0) where P' = 0 and right at any scale; arc length that
// terminates on any finite input.
#include <catch2/catch.hpp>

#include "wingspline/curves/analysis.h"
#include "wingspline/curves/conics.h"
#include "wingspline/error.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace wingspline::curves;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kJointTolerance = 1e-9;   // relative (docs/api-curves.md)
constexpr double kPerturbation = 1e-6;     // relative: the "must be detected" size
constexpr double kCurvatureRel = 1e-12;    // relative error of a curvature against its analytic value
constexpr double kLengthRel = 1e-12;       // relative error of an arc length against its analytic value

using Pt = std::array<double, 2>;
Pt operator+(Pt a, Pt b) { return {a[0] + b[0], a[1] + b[1]}; }
Pt operator-(Pt a, Pt b) { return {a[0] - b[0], a[1] - b[1]}; }
Pt operator*(double s, Pt a) { return {s * a[0], s * a[1]}; }
double len(Pt a) { return std::hypot(a[0], a[1]); }
Pt perp(Pt a) { return {-a[1], a[0]}; }
Pt rotated(Pt a, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * a[0] - s * a[1], s * a[0] + c * a[1]};
}

Curve bezier(const std::vector<Pt>& p) {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.dim = 2;
    for (const Pt& q : p) c.points.insert(c.points.end(), {q[0], q[1]});
    return c;
}

// A joint built to be exactly of one kind (lectures 001, 004): a cubic Bezier a = a0..a3 and
// b = b0..b3 with A1 = 3(a3 - a2), A2 = 6(a3 - 2 a2 + a1) at a's end and likewise at b's start.
// G^1: B1 = lambda A1 (lambda > 0); G^2: also B2 = lambda^2 A2 + beta A1 (the reparametrisation-
// invariant condition: same curvature vector). Every "not" is built with a margin of at least
// 5% of the size, far from any tolerance.
struct Joint {
    std::vector<Pt> a, b;
    int parametric = -1, geometric = -1;
};

enum class Kind { Gap, Corner, G1, G2, C1, C1G2, C2 };
constexpr Kind kKinds[] = {Kind::Gap, Kind::Corner, Kind::G1, Kind::G2, Kind::C1, Kind::C1G2, Kind::C2};

Pt random_point(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    return {u(rng), u(rng)};
}

// The end of a with |A1| >= 0.6 and a curvature of at least 0.1 (so a relative change of the
// curvature is a change of a quantity that is not itself rounding).
std::vector<Pt> random_a(std::mt19937_64& rng) {
    for (;;) {
        std::vector<Pt> a = {random_point(rng), random_point(rng), random_point(rng), random_point(rng)};
        const Pt A1 = 3.0 * (a[3] - a[2]);
        const Pt A2 = 6.0 * (a[3] - 2.0 * a[2] + a[1]);
        const double kappa = std::abs(A1[0] * A2[1] - A1[1] * A2[0]) / std::pow(len(A1), 3);
        if (len(A1) >= 0.6 && kappa >= 0.1 && kappa <= 10) return a;
    }
}

Joint make_joint(Kind kind, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0, 1);
    auto sign = [&] { return u01(rng) < 0.5 ? -1.0 : 1.0; };
    Joint j;
    j.a = random_a(rng);
    const Pt J = j.a[3];
    const Pt A1 = 3.0 * (J - j.a[2]);
    const Pt A2 = 6.0 * (J - 2.0 * j.a[2] + j.a[1]);
    const Pt N = (1 / len(A1)) * perp(A1);
    double lambda = 1;
    if (kind == Kind::G1 || kind == Kind::G2) lambda = u01(rng) < 0.5 ? 0.3 + 0.6 * u01(rng) : 1.2 + 1.8 * u01(rng);
    const Pt B1 = lambda * A1;
    double beta = 0;
    if (kind == Kind::G2 || kind == Kind::C1G2) beta = sign() * (0.2 + 1.8 * u01(rng));
    Pt B2 = lambda * lambda * A2 + beta * A1;
    // Not G^2: a normal component of 5%..50% of the size, times |B1|^2 (a curvature change
    // of at least 0.05 against curvatures of at most 10).
    if (kind == Kind::G1 || kind == Kind::C1) B2 = B2 + (sign() * (0.05 + 0.45 * u01(rng)) * len(B1) * len(B1)) * N;
    Pt b0 = J, b1 = J + (1.0 / 3) * B1;
    if (kind == Kind::Gap) {
        b0 = J + (0.05 + 0.45 * u01(rng)) * rotated({1, 0}, 2 * kPi * u01(rng));
        b1 = random_point(rng);
    } else if (kind == Kind::Corner) {
        const double angle = sign() * (0.2 + (kPi - 0.4) * u01(rng));
        b1 = J + ((0.3 + u01(rng)) / 3) * rotated(A1, angle);
    }
    const Pt b2 = 2.0 * b1 - b0 + (1.0 / 6) * B2;
    j.b = {b0, b1, b2, random_point(rng)};
    switch (kind) {
    case Kind::Gap: j.parametric = -1, j.geometric = -1; break;
    case Kind::Corner: j.parametric = 0, j.geometric = 0; break;
    case Kind::G1: j.parametric = 0, j.geometric = 1; break;
    case Kind::G2: j.parametric = 0, j.geometric = 2; break;
    case Kind::C1: j.parametric = 1, j.geometric = 1; break;
    case Kind::C1G2: j.parametric = 1, j.geometric = 2; break;
    case Kind::C2: j.parametric = 2, j.geometric = 2; break;
    }
    return j;
}

// A similarity: scale 10^(-8..8), rotation, translation of up to 10 sizes.
struct Similarity {
    double scale = 1, angle = 0;
    Pt shift{0, 0};
    Pt operator()(Pt p) const { return scale * rotated(p, angle) + shift; }
};
Similarity random_similarity(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    Similarity s;
    s.scale = std::pow(10.0, 8 * u(rng));
    s.angle = kPi * u(rng);
    s.shift = (10 * s.scale) * Pt{u(rng), u(rng)};
    return s;
}
std::vector<Pt> moved(const std::vector<Pt>& p, const Similarity& s) {
    std::vector<Pt> r;
    for (const Pt& q : p) r.push_back(s(q));
    return r;
}

JointContinuity verdict(const std::vector<Pt>& a, const std::vector<Pt>& b) {
    return joint_continuity(bezier(a), bezier(b), kJointTolerance);
}

std::string describe(const std::vector<Pt>& a, const std::vector<Pt>& b) {
    std::string s = "a:";
    for (const Pt& p : a) s += " (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ")";
    s += " b:";
    for (const Pt& p : b) s += " (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ")";
    return s;
}

} // namespace

TEST_CASE("joint continuity: constructed joints keep their verdict under scaling 1e-8..1e8, rotation and translation",
          "[curves][continuity][trust][property]") {
    std::mt19937_64 rng(20240613);
    int checked = 0;
    for (int i = 0; i < 4200; ++i) {
        const Kind kind = kKinds[i % 7];
        const Joint j = make_joint(kind, rng);
        const Similarity s = i < 7 ? Similarity{} : random_similarity(rng);
        const auto a = moved(j.a, s), b = moved(j.b, s);
        const JointContinuity v = verdict(a, b);
        INFO("joint " << i << " scale " << s.scale << " " << describe(a, b));
        REQUIRE(v.parametric == j.parametric);
        REQUIRE(v.geometric == j.geometric);
        // Lecture 004: "In general, C^i implies G^i ... Exception when the tangents are zero".
        REQUIRE_FALSE(v.evidence.zero_tangent);
        REQUIRE(v.geometric >= v.parametric);
        ++checked;
    }
    CHECK(checked == 4200);
}

TEST_CASE("joint continuity: a relative change of 1e-6 is detected at every scale", "[curves][continuity][trust][property]") {
    std::mt19937_64 rng(1306);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int i = 0; i < 3000; ++i) {
        const Similarity s = random_similarity(rng);
        const int test = i % 5;
        Joint j = make_joint(test == 0 ? Kind::Corner : test == 3 ? Kind::C2 : kKinds[4 + i % 3], rng);
        if (test == 4) j = make_joint(i % 2 ? Kind::G2 : Kind::C1G2, rng);
        const Pt J = j.b[0];
        const Pt B1 = 3.0 * (j.b[1] - j.b[0]);
        const Pt B2 = 6.0 * (j.b[2] - 2.0 * j.b[1] + j.b[0]);
        double size = 0; // the diagonal of the joint's bounding box
        {
            Pt lo = j.a[0], hi = j.a[0];
            for (const auto* poly : {&j.a, &j.b})
                for (const Pt& p : *poly)
                    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
            size = len(hi - lo);
        }
        std::vector<Pt> b = j.b;
        int want_parametric = j.parametric, want_geometric = j.geometric;
        const Pt direction = rotated({1, 0}, 2 * kPi * u01(rng));
        switch (test) {
        case 0: // C0 -> C-1: move the start of b by 1e-6 of the size (its neighbours with it)
            for (Pt& p : b) p = p + (kPerturbation * size) * direction;
            want_parametric = want_geometric = -1;
            break;
        case 1: // C1 -> G1 only: b' 1e-6 longer, same direction;
            // b'' times (1 + 1e-6)^2: a reparametrisation, the shape keeps its G^k
            b[1] = J + ((1 + kPerturbation) / 3) * B1;
            b[2] = 2.0 * b[1] - b[0] + ((1 + kPerturbation) * (1 + kPerturbation) / 6) * B2;
            want_parametric = 0;
            break;
        case 2: // G1 -> G0: b' turned by 1e-6 radians
            b[1] = J + (1.0 / 3) * rotated(B1, kPerturbation * (u01(rng) < 0.5 ? -1 : 1));
            want_parametric = 0;
            want_geometric = 0;
            break;
        case 3: // C2 -> C1: b'' changed by 1e-6 of its length along the tangent (the shape keeps G2)
            b[2] = b[2] + (kPerturbation * len(B2) / 6 / len(B1)) * B1;
            want_parametric = 1;
            want_geometric = 2;
            break;
        case 4: { // G2 -> G1: the curvature changed by 1e-6 of itself
            const double kappa = std::abs(B1[0] * B2[1] - B1[1] * B2[0]) / std::pow(len(B1), 3);
            b[2] = b[2] + (kPerturbation * kappa * len(B1) / 6) * perp(B1);
            want_parametric = std::min(j.parametric, 1);
            want_geometric = 1;
            break;
        }
        }
        const auto a = moved(j.a, s), bm = moved(b, s);
        const JointContinuity v = verdict(a, bm);
        INFO("case " << test << " joint " << i << " scale " << s.scale << " " << describe(a, bm));
        REQUIRE(v.parametric == want_parametric);
        REQUIRE(v.geometric == want_geometric);
    }
}

TEST_CASE("joint continuity: the issue's examples at scales 1e-6 and 1e6", "[curves][continuity][trust]") {
    const std::vector<Pt> a = {{0, 0}, {1, 1}, {2, 1}, {3, 0}};
    for (double scale : {1e-6, 1.0, 1e6}) {
        INFO("scale " << scale);
        const Similarity s{scale, 0, {0, 0}};
        // a gap of 1e-4 of the size is a gap
        CHECK(verdict(moved(a, s), moved({{3, 1e-4}, {4, -1}, {5, 0}, {6, 1}}, s)).parametric == -1);
        // a 90-degree corner is C0, G0
        const JointContinuity corner = verdict(moved(a, s), moved({{3, 0}, {4, 1}, {5, 0}, {6, 1}}, s));
        CHECK(corner.parametric == 0);
        CHECK(corner.geometric == 0);
        CHECK(corner.evidence.tangent_angle == Approx(kPi / 2));
        // C1 with the second derivative 1% longer: the curvature differs by 1%, not G2
        // a: A1 = (3, -3), A2 = 6 (P3 - 2 P2 + P1) = (0, -6); b: B1 = (3, -3), B2 = 1.01 A2
        const JointContinuity c1 = verdict(moved(a, s), moved({{3, 0}, {4, -1}, {5, -2 - 1.01}, {6, 0}}, s));
        CHECK(c1.parametric == 1);
        CHECK(c1.geometric == 1);
        CHECK(c1.evidence.curvature_b / c1.evidence.curvature_a == Approx(1.01).epsilon(1e-9));
    }
}

TEST_CASE("joint continuity: what each lecture's wording of G^n says (lectures 001, 003, 004)", "[curves][continuity][trust]") {
    const std::vector<Pt> a = {{0, 0}, {1, 1}, {2, 1}, {3, 0}}; // A1 = (3, -3), A2 = (0, -6)
    auto wording = [](const JointContinuity& j, const std::string& id) {
        for (const auto& w : j.wordings)
            if (w.id == id) return w;
        FAIL("no wording " << id);
        return LectureWording{};
    };
    SECTION("the three readings are reported with the lectures' words") {
        const JointContinuity j = verdict(a, {{3, 0}, {4, -1}, {5, -3}, {6, 0}});
        REQUIRE(j.wordings.size() == 3);
        CHECK(wording(j, "curvature-vector").geometric == j.geometric);
        CHECK(wording(j, "proportional").source == "lectures 001, 004");
        CHECK(wording(j, "proportional").wording.find("proportional") != std::string::npos);
        CHECK(wording(j, "direction").source == "lecture 003");
        CHECK(wording(j, "direction").wording.find("direction of the n th derivative") != std::string::npos);
        for (const auto& w : j.wordings) CHECK_FALSE(w.reason.empty());
    }
    SECTION("P'' in the same direction but twice as long: the wordings say G2, the curvature doubles") {
        // B1 = A1, B2 = 2 A2 = (0, -12): b2 = 2 b1 - b0 + B2/6 = (5, -4)
        const JointContinuity j = verdict(a, {{3, 0}, {4, -1}, {5, -4}, {6, 0}});
        CHECK(j.geometric == 1);
        CHECK(j.evidence.curvature_b == Approx(2 * j.evidence.curvature_a));
        CHECK(wording(j, "proportional").geometric == 2);
        CHECK(wording(j, "direction").geometric == 2);
    }
    SECTION("a reparametrised joint: P'' gains a tangent part, the curvature is unchanged (G2), the wordings say G1") {
        // B1 = A1, B2 = A2 + A1 = (3, -9): b2 = (5, -2) + (0.5, -1.5) = (5.5, -3.5)
        const JointContinuity j = verdict(a, {{3, 0}, {4, -1}, {5.5, -3.5}, {6, 0}});
        CHECK(j.parametric == 1);
        CHECK(j.geometric == 2);
        CHECK(wording(j, "proportional").geometric == 1);
        CHECK(wording(j, "direction").geometric == 1);
    }
    SECTION("P'' reversed: proportional (factor -1) but not the same direction, and not G2") {
        // A2 = (0, -6) at a's end; B2 = (0, 6): b2 = (5, -2) + (0, 1) = (5, -1)
        const JointContinuity j = verdict(a, {{3, 0}, {4, -1}, {5, -1}, {6, 0}});
        CHECK(j.geometric == 1);
        CHECK(wording(j, "proportional").geometric == 2);
        CHECK(wording(j, "direction").geometric == 1);
    }
    SECTION("P'' = 0 on one side: its direction is undefined (lecture 003 cannot say G2)") {
        const std::vector<Pt> line = {{0, 3}, {1, 2}, {2, 1}, {3, 0}}; // A2 = 0
        const JointContinuity j = verdict(line, {{3, 0}, {4, -1}, {5, -2}, {6, -3}});
        CHECK(j.parametric == 2);
        CHECK(j.geometric == 2);
        CHECK(wording(j, "proportional").geometric == 2);
        CHECK(wording(j, "direction").geometric == 1);
    }
}

TEST_CASE("curvature: undefined (flagged) where P' = 0 at every scale; right at 1e-150 and 1e160", "[curves][curvature][trust]") {
    // The parabola of quadratic Bezier (-1, 1), (0, -1), (1, 1): at t = 1/2, P' = (2, 0),
    // P'' = (0, 8), kappa = |P' x P''| / |P'|^3 = 16 / 8 = 2 (lecture 004); scaled by s: 2 / s.
    for (double s : {1e-300, 1e-150, 1e-8, 1.0, 1e8, 1e160, 1e300}) {
        INFO("scale " << s);
        const Curve c = bezier({{-s, s}, {0, -s}, {s, s}});
        const CurvatureValues k = curvature(c, {0.5});
        REQUIRE(std::isfinite(k.curvature[0]));
        CHECK(k.curvature[0] == Approx(2 / s).epsilon(kCurvatureRel));
        CHECK(k.signed_curvature[0] == Approx(2 / s).epsilon(kCurvatureRel));
        CHECK(k.singular[0] == 0);
    }
    // A cusp: P0 = (0,0), P1 = (1,1), P2 = (0,1), P3 = (1,0) has P'(1/2) = 0 exactly.
    for (double s : {1e-305, 1e-150, 1e-8, 1.0, 1e8, 1e160}) {
        for (double shift : {0.0, 3.0, -1000.0}) {
            INFO("scale " << s << " shift " << shift);
            const double t = shift * s;
            const Curve c = bezier({{t, t}, {t + s, t + s}, {t, t + s}, {t + s, t}});
            const CurvatureValues k = curvature(c, {0.25, 0.5, 0.75});
            CHECK(k.singular[0] == 0);
            CHECK(k.singular[1] == 1);
            CHECK(k.singular[2] == 0);
            CHECK(std::isfinite(k.curvature[0]));
            CHECK(k.curvature[0] > 0);
        }
    }
}

TEST_CASE("joint evidence: the curvature on a side with P' = 0 is undefined, not 0", "[curves][continuity][curvature][trust]") {
    for (double s : {1e-8, 1.0, 1e8}) {
        INFO("scale " << s);
        const Similarity m{s, 0.3, {2 * s, -s}};
        const JointContinuity j = verdict(moved({{0, 0}, {1, 1}, {3, 0}, {3, 0}}, m), moved({{3, 0}, {4, 1}, {4, 2}, {6, 1}}, m));
        CHECK(j.evidence.zero_tangent);
        CHECK(j.evidence.zero_tangent_a);
        CHECK_FALSE(j.evidence.zero_tangent_b);
        CHECK(j.evidence.curvature_b > 0);
        CHECK(j.geometric == 0);
    }
}

TEST_CASE("joint continuity at 1e300: finite curvature (the continuity lab's inspector)", "[curves][continuity][curvature][trust]") {
    // Lecture 004: kappa of a' = (3, -3), a'' = (0, -6) is |a' x a''| / |a'|^3 = 18 / 18^1.5.
    for (double s : {1e-300, 1e300}) {
        const Similarity m{s, 0, {0, 0}};
        const JointContinuity j = verdict(moved({{0, 0}, {1, 1}, {2, 1}, {3, 0}}, m), moved({{3, 0}, {4, -1}, {5, -3}, {6, 0}}, m));
        INFO("scale " << s);
        REQUIRE(std::isfinite(j.evidence.curvature_a));
        CHECK(j.evidence.curvature_a == Approx(18 / std::pow(18, 1.5) / s).epsilon(kCurvatureRel));
        CHECK(j.parametric == 2);
    }
}

namespace {
// Runs f and fails if it takes longer than a second (it used to run for hours).
template <class F> auto within_a_second(F f) {
    const auto start = std::chrono::steady_clock::now();
    auto r = f();
    CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.0);
    return r;
}
} // namespace

TEST_CASE("arc length terminates and is right near 1e308, 1e-308, for subnormals and mixed sizes", "[curves][arclength][trust]") {
    const double big = 1.5e308;
    SECTION("a straight cubic Bezier of length 1.5e308 (evenly spaced points: constant speed)") {
        const Curve c = bezier({{0, 0}, {big / 3, 0}, {2 * (big / 3), 0}, {big, 0}});
        CHECK(within_a_second([&] { return arc_length(c, 0, 1); }) == Approx(big).epsilon(kLengthRel));
        const ArcLengthParams p = within_a_second([&] { return arc_length_params(c, 5); });
        CHECK(p.total == Approx(big).epsilon(kLengthRel));
        for (int j = 0; j < 5; ++j) CHECK(p.params[j] == Approx(j / 4.0).margin(1e-12));
    }
    SECTION("a curved Bezier with coordinates near +-1e308: the length of the unit shape times 1e308") {
        // The quarter circle as a NURBS arc has length pi/2 r (lecture 002's conics).
        for (double r : {1e308, 1e-308, 1e-320}) {
            INFO("radius " << r);
            const Curve arc = nurbs_arc({0, 0}, 2, r, 0, kPi / 2);
            CHECK(within_a_second([&] { return arc_length(arc, 0, 1); }) == Approx(kPi / 2 * r).epsilon(r < 1e-310 ? 1e-3 : kLengthRel));
        }
    }
    SECTION("subnormal coordinates: a straight line of length 3000 * 2^-1074") {
        const double d = std::numeric_limits<double>::denorm_min();
        const Curve c = bezier({{0, 0}, {1000 * d, 0}, {2000 * d, 0}, {3000 * d, 0}});
        CHECK(within_a_second([&] { return arc_length(c, 0, 1); }) == Approx(3000 * d).epsilon(kLengthRel));
    }
    SECTION("mixed: from 1e-308 to 1e308 along a line") {
        const Curve c = bezier({{1e-308, 1e-308}, {1e308 / 3, 0}, {2 * (1e308 / 3), 0}, {1e308, 0}});
        CHECK(within_a_second([&] { return arc_length(c, 0, 1); }) == Approx(1e308).epsilon(kLengthRel));
    }
    SECTION("a length beyond the largest double is refused with a clear code, quickly") {
        const Curve c = bezier({{-big, -big}, {-big / 3, -big / 3}, {big / 3, big / 3}, {big, big}});
        const auto start = std::chrono::steady_clock::now();
        try {
            arc_length(c, 0, 1);
            FAIL("no error");
        } catch (const wingspline::Error& e) {
            CHECK(e.code() == "length-overflow");
            CHECK(std::string(e.what()).find("largest") != std::string::npos);
        }
        CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.0);
        CHECK_THROWS_AS(arc_length_params(c, 10), wingspline::Error);
    }
}

// C^-1 (lecture 004: "the joint is discontinuous, V1(1) != V2(0)") with the gap
// measured relative to the size of the curves: twice the largest distance of a control point
// of either curve from the centroid of all of them, which no rotation or shift changes and a
// scaling multiplies.
// The test recomputes size and gap from the points, independently of the core.
TEST_CASE("joint continuity: C-1 reports the gap relative to the size of the curves, the same at every similarity",
          "[curves][continuity][gap]") {
    std::mt19937_64 rng(180418);
    auto spread = [](const std::vector<Pt>& a, const std::vector<Pt>& b) {
        std::vector<Pt> all = a;
        all.insert(all.end(), b.begin(), b.end());
        Pt c{0, 0};
        for (const Pt& p : all) c = c + (1.0 / all.size()) * p;
        double r = 0;
        for (const Pt& p : all) r = std::max(r, len(p - c));
        return 2 * r;
    };
    for (int i = 0; i < 3000; ++i) {
        const Joint j = make_joint(Kind::Gap, rng);
        const Similarity s = i == 0 ? Similarity{} : random_similarity(rng);
        const auto a = moved(j.a, s), b = moved(j.b, s);
        const double size = spread(a, b);
        const double gap = len(b[0] - a[3]);
        const JointContinuity v = verdict(a, b);
        INFO("case " << i << " " << describe(a, b));
        REQUIRE(v.parametric == -1);
        REQUIRE(v.geometric == -1);
        CHECK(v.evidence.size == Approx(size).epsilon(1e-12));
        CHECK(v.evidence.relative_gap == Approx(gap / size).epsilon(1e-12));
        // the same joint before the similarity: the same relative gap
        CHECK(v.evidence.relative_gap == Approx(verdict(j.a, j.b).evidence.relative_gap).epsilon(1e-12));
    }
    // an analytic case: centroid (3, 0.2575) (the eight points sum to (24, 2.06)); the farthest
    // point is (6, 1): |(6, 1) - c| = sqrt(9 + 0.7425^2), gap 0.06
    const std::vector<Pt> a = {{0, 0}, {1, 1}, {2, 1}, {3, 0}};
    const std::vector<Pt> b = {{3, 0.06}, {4, -1}, {5, 0}, {6, 1}};
    for (double scale : {1e-8, 1e-3, 1.0, 1e5, 1e8}) {
        const Similarity m{scale, 0.7, {3 * scale, -5 * scale}};
        const JointContinuity v = verdict(moved(a, m), moved(b, m));
        INFO("scale " << scale);
        CHECK(v.parametric == -1);
        CHECK(v.evidence.position_gap == Approx(0.06 * scale).epsilon(1e-12));
        CHECK(v.evidence.relative_gap == Approx(0.06 / (2 * std::sqrt(9 + 0.7425 * 0.7425))).epsilon(1e-12));
    }
    // a joint that meets has no gap
    CHECK(verdict(a, {{3, 0}, {4, -1}, {5, 0}, {6, 1}}).evidence.relative_gap == 0);
}

// The angle between the two tangents at a joint, for angles from 1e-9 rad to pi - 1e-9: the
// angle's error stays under 1e-13 rad (plus 1e-12 of the angle). Built from exact-angle
// tangents: u at a random direction phi, and u turned by theta; the points' rounding moves the
// angle by about 1e-16 rad. acos of the normalised dot product lost the small angles (a C2
// joint read 2.1e-8 rad; 1e-9 rad read 0): the half-angle form 2 atan2(|u - v|, |u + v|)
// of unit vectors keeps them.
TEST_CASE("joint evidence: the tangent angle is right from 1e-9 rad to pi - 1e-9", "[curves][continuity][trust][property]") {
    std::mt19937_64 rng(20261124);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int test = 0; test < 3000; ++test) {
        const double theta = test % 2 ? std::pow(10.0, -9 + 9.4 * unit(rng)) : kPi - std::pow(10.0, -9 + 9.4 * unit(rng));
        if (!(theta > 0 && theta < kPi)) continue;
        const double phi = 2 * kPi * unit(rng);
        const Pt p3{unit(rng) - 0.5, unit(rng) - 0.5};
        const double la = 0.5 + unit(rng), lb = 0.5 + unit(rng);
        const Pt ua = rotated({1, 0}, phi), ub = rotated({1, 0}, phi + theta);
        const std::vector<Pt> a = {p3 - 3 * la * ua + perp(ua), p3 - 2 * la * ua, p3 - la * ua, p3};
        const std::vector<Pt> b = {p3, p3 + lb * ub, p3 + 2 * lb * ub - perp(ub), p3 + 3 * lb * ub};
        const JointContinuity v = verdict(a, b);
        // The exact angle of the rounded points' tangents differs from theta by the rounding.
        INFO("case " << test << " theta " << theta << " got " << v.evidence.tangent_angle);
        REQUIRE(std::abs(v.evidence.tangent_angle - theta) <= 1e-13 + 1e-12 * theta);
    }
    // Equal tangents (a C1 joint built exactly): the angle is 0, not a rounding of acos.
    const JointContinuity straight = verdict({{0, 0}, {1, 1}, {2, 1}, {3, 1}}, {{3, 1}, {4, 1}, {5, 2}, {6, 0}});
    CHECK(straight.evidence.tangent_angle == 0.0);
}
