// Exercise kind 4 (compute a value by hand): the expected values against the
// lectures' formulas (Bernstein polynomials, the uniform cubic B-spline's 1/6 (1, 4, 1), the
// slide's Bezier matrix, Boehm's rule recomputed in exact rational arithmetic), the worked
// lines, the verdict within the stated tolerance, and the errors.
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/exercise.h"
#include "wingspline/error.h"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace wingspline::curves;
using curves_fixtures::expect_error;

namespace {

constexpr double kValueRel = 1e-13; // relative error of a computed value against its formula
constexpr int kCases = 2000;        // random cases per property

Curve curve_of(CurveKind kind, int dim, std::vector<double> points) {
    Curve c;
    c.kind = kind;
    c.dim = dim;
    c.points = std::move(points);
    return c;
}
ValueSubject of_curve(const Curve& c) {
    ValueSubject s;
    s.curve = c;
    return s;
}
ValueAsk ask(const std::string& quantity) {
    ValueAsk a;
    a.quantity = quantity;
    return a;
}
bool close(double x, double y) { return std::abs(x - y) <= kValueRel * std::max(1.0, std::abs(y)); }

// n choose i as a whole number.
double choose(int n, int i) {
    double c = 1;
    for (int k = 1; k <= i; ++k) c = c * (n - i + k) / k;
    return std::round(c);
}

// An exact fraction of 64-bit integers (enough for Boehm's rule on small integer data).
struct Fraction {
    int64_t num = 0, den = 1;
    Fraction(int64_t n = 0, int64_t d = 1) : num(n), den(d) {
        if (den < 0) num = -num, den = -den;
        const int64_t g = std::gcd(num < 0 ? -num : num, den);
        if (g > 1) num /= g, den /= g;
    }
    double value() const { return static_cast<double>(num) / static_cast<double>(den); }
};
Fraction operator+(Fraction a, Fraction b) { return {a.num * b.den + b.num * a.den, a.den * b.den}; }
Fraction operator-(Fraction a, Fraction b) { return {a.num * b.den - b.num * a.den, a.den * b.den}; }
Fraction operator*(Fraction a, Fraction b) { return {a.num * b.num, a.den * b.den}; }
Fraction operator/(Fraction a, Fraction b) { return {a.num * b.den, a.den * b.num}; }

} // namespace

TEST_CASE("blend: Bezier blending functions are the Bernstein polynomials (lecture 001)", "[exercise][value]") {
    std::mt19937_64 rng(1901);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int n = 0; n < kCases; ++n) {
        const int degree = 1 + static_cast<int>(rng() % 7);
        std::vector<double> pts;
        for (int i = 0; i <= degree; ++i) pts.insert(pts.end(), {u01(rng), u01(rng)});
        const int i = static_cast<int>(rng() % (degree + 1));
        const double u = u01(rng);
        ValueAsk a = ask("blend");
        a.i = i;
        a.u = u;
        const WorkedValue w = worked_value(of_curve(curve_of(CurveKind::Bezier, 2, pts)), a);
        const double bernstein = choose(degree, i) * std::pow(u, i) * std::pow(1 - u, degree - i);
        INFO("degree " << degree << ", i " << i << ", u " << u);
        REQUIRE(w.expected.size() == 1);
        REQUIRE(close(w.expected[0], bernstein));
    }
}

TEST_CASE("blend: the task's example B_1,3(0.5) = 0.375, its working and the wrong answer 0.4", "[exercise][value]") {
    const Curve c = curve_of(CurveKind::Bezier, 2, {0, 0, 1, 2, 3, 2, 4, 0});
    ValueAsk a = ask("blend");
    a.i = 1;
    a.u = 0.5;
    const ValueCheck wrong = check_value_answer(of_curve(c), a, {0.4}, 0.001);
    CHECK(!wrong.correct);
    CHECK(wrong.worked.label == "B₁,₃(0.5)");
    CHECK(wrong.worked.expected == std::vector<double>{0.375}); // 3 / 8 exactly in binary
    CHECK(std::abs(wrong.distance - 0.025) <= 1e-15);
    CHECK(wrong.reason == "0.4 is 0.025 from B₁,₃(0.5) = 0.375; the tolerance is 0.001");
    REQUIRE(wrong.worked.working.size() == 2);
    CHECK(wrong.worked.working[0].find("B₁,₃(u) = C(3, 1) uⁱ (1 − u)ⁿ⁻ⁱ = 3 u¹ (1 − u)²") == 0);
    CHECK(wrong.worked.working[1] == "at u = 0.5: 3 · 0.5 · 0.25 = 0.375");
    const ValueCheck right = check_value_answer(of_curve(c), a, {0.3751}, 0.001);
    CHECK(right.correct);
    CHECK(right.reason.empty());
}

TEST_CASE("blend: the uniform cubic B-spline is 1/6 (1, 4, 1) at a knot and (1-t)^3/6 .. t^3/6 between", "[exercise][value]") {
    // Four points, uniform knots t_j = j - 3: one segment over [0, 1] (lecture 002, B(u - i)).
    const Curve c = curve_of(CurveKind::BSpline, 2, {0, 0, 1, 1, 2, 1, 3, 0});
    std::mt19937_64 rng(1902);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int n = 0; n < kCases; ++n) {
        const double t = n == 0 ? 0.0 : u01(rng);
        const double analytic[4] = {std::pow(1 - t, 3) / 6, (3 * t * t * t - 6 * t * t + 4) / 6, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6,
                                    t * t * t / 6};
        for (int i = 0; i < 4; ++i) {
            ValueAsk a = ask("blend");
            a.i = i;
            a.u = t;
            const WorkedValue w = worked_value(of_curve(c), a);
            INFO("t " << t << ", i " << i);
            REQUIRE(close(w.expected[0], analytic[i]));
            // The worked line recomputes it from the slide's matrix: its last number is the value.
            const std::string& last = w.working.back();
            REQUIRE(std::abs(std::stod(last.substr(last.rfind("= ") + 2)) - analytic[i]) <= 1e-5);
        }
    }
    ValueAsk a = ask("blend");
    a.i = 1;
    a.u = 0.0;
    CHECK(worked_value(of_curve(c), a).label == "N₁,₃(0)");
}

TEST_CASE("point: a cubic Bezier at 1/2 is (P0 + 3 P1 + 3 P2 + P3) / 8; Hermite from H0..H3", "[exercise][value]") {
    std::mt19937_64 rng(1903);
    std::uniform_real_distribution<double> u11(-1, 1);
    for (int n = 0; n < kCases; ++n) {
        std::vector<double> p(8);
        for (double& x : p) x = u11(rng);
        ValueAsk a = ask("point");
        a.u = 0.5;
        const WorkedValue w = worked_value(of_curve(curve_of(CurveKind::Bezier, 2, p)), a);
        for (int k = 0; k < 2; ++k) REQUIRE(close(w.expected[k], (p[k] + 3 * p[2 + k] + 3 * p[4 + k] + p[6 + k]) / 8));
        // Hermite (lecture 000): P(u) = H0 p0 + H1 p1 + H2 t0 + H3 t1.
        Curve h = curve_of(CurveKind::Hermite, 2, {p[0], p[1], p[2], p[3]});
        h.tangents = {p[4], p[5], p[6], p[7]};
        const double u = (u11(rng) + 1) / 2;
        const double H[4] = {2 * u * u * u - 3 * u * u + 1, -2 * u * u * u + 3 * u * u, u * u * u - 2 * u * u + u, u * u * u - u * u};
        a.u = u;
        const WorkedValue wh = worked_value(of_curve(h), a);
        for (int k = 0; k < 2; ++k) REQUIRE(close(wh.expected[k], H[0] * p[k] + H[1] * p[2 + k] + H[2] * p[4 + k] + H[3] * p[6 + k]));
    }
    ValueAsk a = ask("point");
    a.u = 0.5;
    const WorkedValue w = worked_value(of_curve(curve_of(CurveKind::Bezier, 2, {0, 0, 1, 2, 3, 2, 4, 0})), a);
    CHECK(w.label == "P(0.5)");
    CHECK(w.working.back() == "P(0.5) = 0.125 · P₀(0, 0) + 0.375 · P₁(1, 2) + 0.375 · P₂(3, 2) + 0.125 · P₃(4, 0) = (2, 1.5)");
}

TEST_CASE("mg: entries of C = M G equal the slide's Bezier matrix times the geometry (lecture 003)", "[exercise][value]") {
    const Mat4 M = curves_fixtures::slide_bezier();
    std::mt19937_64 rng(1904);
    std::uniform_real_distribution<double> u11(-1, 1);
    for (int n = 0; n < kCases / 10; ++n) {
        std::vector<double> G(8);
        for (double& x : G) x = u11(rng);
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 2; ++col) {
                ValueAsk a = ask("mg");
                a.segment = 0;
                a.row = row;
                a.col = col;
                const WorkedValue w = worked_value(of_curve(curve_of(CurveKind::Bezier, 2, G)), a);
                double expected = 0;
                for (int j = 0; j < 4; ++j) expected += M[4 * row + j] * G[2 * j + col];
                REQUIRE(close(w.expected[0], expected));
            }
    }
    ValueAsk a = ask("mg");
    a.segment = 0;
    a.row = 1;
    a.col = 1;
    const WorkedValue w = worked_value(of_curve(curve_of(CurveKind::Bezier, 2, {0, 0, 1, 2, 3, 2, 4, 0})), a);
    // Written as the question counts (row 2, column 2 = y, segment 1; lecture 003's Bezier row 2 is 3 -6 3 0).
    CHECK(w.label == "(M G)₂,₂, row 2, column 2 (y), of segment 1");
    CHECK(w.working.back() == "(M G)₂,₂ = Σⱼ M₂,ⱼ Gⱼ,₂ = 3 · 0 + (-6) · 2 + 3 · 2 + 0 · 0 = -6");
}

TEST_CASE("boehm: inserting a knot into a uniform cubic B-spline, against exact rational arithmetic", "[exercise][value]") {
    std::mt19937_64 rng(1905);
    for (int n = 0; n < kCases; ++n) {
        const int p = 1 + static_cast<int>(rng() % 4), K = p + 1 + static_cast<int>(rng() % 5);
        std::vector<double> pts;
        for (int i = 0; i < 2 * K; ++i) pts.push_back(static_cast<double>(static_cast<int>(rng() % 41) - 20));
        Curve c = curve_of(CurveKind::BSpline, 2, pts);
        c.degree = p;
        // Uniform knots t_j = j - p: the domain is [0, K - p]; u = m / 8 strictly inside it.
        const int m = 1 + static_cast<int>(rng() % (8 * (K - p) - 1));
        const Fraction u(m, 8);
        auto knot = [&](int j) { return Fraction(j - p); };
        int k = p;
        while (k < K - 1 && knot(k + 1).value() <= u.value()) ++k;
        for (int index = 0; index <= K; ++index) {
            Fraction q[2];
            for (int x = 0; x < 2; ++x) {
                auto P = [&](int i) { return Fraction(static_cast<int64_t>(pts[2 * i + x])); };
                if (index <= k - p) q[x] = P(index);
                else if (index >= k + 1) q[x] = P(index - 1);
                else {
                    const Fraction a = (u - knot(index)) / (knot(index + p) - knot(index));
                    q[x] = (Fraction(1) - a) * P(index - 1) + a * P(index);
                }
            }
            ValueAsk ak = ask("boehm");
            ak.u = u.value();
            ak.index = index;
            const WorkedValue w = worked_value(of_curve(c), ak);
            INFO("p " << p << ", K " << K << ", u " << u.value() << ", index " << index);
            REQUIRE(w.expected.size() == 2);
            for (int x = 0; x < 2; ++x) REQUIRE(std::abs(w.expected[x] - q[x].value()) <= 1e-13 * std::max(1.0, std::abs(q[x].value())));
        }
    }
    // The working of one new point: cubic, points P_i = (i, i^2), u = 1/2 in the span k = 3.
    Curve c = curve_of(CurveKind::BSpline, 2, {0, 0, 1, 1, 2, 4, 3, 9, 4, 16});
    ValueAsk ak = ask("boehm");
    ak.u = 0.5;
    ak.index = 2;
    const WorkedValue w = worked_value(of_curve(c), ak);
    CHECK(w.label == "Q₂ after inserting the knot u = 0.5");
    // a_2 = (u - u_2) / (u_5 - u_2) = (0.5 - (-1)) / (2 - (-1)) = 0.5; Q_2 = 0.5 P_1 + 0.5 P_2.
    CHECK(w.working[1] == "a₂ = (u − u₂) / (u₅ − u₂) = (0.5 − (-1)) / (2 − (-1)) = 0.5");
    CHECK(w.working[2] == "Q₂ = (1 − a₂) P₁ + a₂ P₂ = 0.5 · (1, 1) + 0.5 · (2, 4) = (1.5, 2.5)");
}

TEST_CASE("patch-point: a bicubic Bezier patch is sum B_i(u) B_j(v) P_ij (lecture 002)", "[exercise][value]") {
    std::mt19937_64 rng(1906);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int n = 0; n < kCases / 4; ++n) {
        ValueSubject s;
        s.is_patch = true;
        s.patch_kind = BasisKind::Bezier;
        s.patch_points.resize(48);
        for (double& x : s.patch_points) x = 2 * u01(rng) - 1;
        ValueAsk a = ask("patch-point");
        a.u = u01(rng);
        a.v = u01(rng);
        const WorkedValue w = worked_value(s, a);
        for (int k = 0; k < 3; ++k) {
            double expected = 0;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    expected += choose(3, i) * std::pow(*a.u, i) * std::pow(1 - *a.u, 3 - i) * choose(3, j) * std::pow(*a.v, j) *
                                std::pow(1 - *a.v, 3 - j) * s.patch_points[3 * (4 * i + j) + k];
            REQUIRE(close(w.expected[k], expected));
        }
        // Hermite: the corner p(1, 0) is the geometry entry in row 1, column 0 (patch.h's layout).
        s.patch_kind = BasisKind::Hermite;
        a.u = 1.0;
        a.v = 0.0;
        const WorkedValue h = worked_value(s, a);
        for (int k = 0; k < 3; ++k) REQUIRE(close(h.expected[k], s.patch_points[3 * 4 + k]));
    }
}

TEST_CASE("values: bad asks and answers get stable codes naming the field", "[exercise][value]") {
    const ValueSubject s = of_curve(curve_of(CurveKind::Bezier, 2, {0, 0, 1, 2, 3, 2, 4, 0}));
    expect_error([&] { worked_value(s, ask("tangent")); }, "unknown-quantity", "ask.quantity is 'tangent'");
    expect_error([&] { worked_value(s, ask("blend")); }, "invalid-argument", "ask.u is missing");
    ValueAsk a = ask("blend");
    a.u = 0.5;
    expect_error([&] { worked_value(s, a); }, "invalid-argument", "ask.i is missing");
    a.i = 4;
    expect_error([&] { worked_value(s, a); }, "invalid-argument", "ask.i is 4; the blending function's index i (0-based) runs from 0 to 3");
    a.i = 1;
    a.u = 1.5;
    expect_error([&] { worked_value(s, a); }, "parameter-out-of-range", "1.5");
    a.u = 0.5;
    {
        // A wrong count of numbers is a wrong answer said plainly (the student's mistake), not an error.
        const ValueCheck count = check_value_answer(s, a, {0.1, 0.2}, 0.01);
        CHECK_FALSE(count.correct);
        CHECK(count.code == "wrong-count");
        CHECK(count.message == "The answer is a single number; you typed two numbers.");
    }
    expect_error([&] { check_value_answer(s, a, {0.1}, -1); }, "invalid-argument", "tolerance");
    expect_error([&] { check_value_answer(s, a, {NAN}, 0.01); }, "non-finite-input", "given[0]");
    ValueAsk pp = ask("patch-point");
    pp.u = pp.v = 0.5;
    expect_error([&] { worked_value(s, pp); }, "invalid-argument", "subject must be {patch");
    ValueAsk mg = ask("mg");
    mg.segment = 0;
    mg.row = 0;
    mg.col = 2;
    expect_error([&] { worked_value(s, mg); }, "invalid-argument", "ask.col is 2");
    ValueAsk b = ask("boehm");
    b.u = 0.5;
    b.index = 0;
    expect_error([&] { worked_value(of_curve(curve_of(CurveKind::CatmullRom, 2, {0, 0, 1, 1, 2, 0, 3, 1})), b); }, "unsupported-curve-kind",
                 "catmull-rom");
}

TEST_CASE("blend: Hermite H0..H3 (lecture 000), Catmull-Rom 1/2 [..] and a NURBS R_i,2 against their formulas", "[exercise][value]") {
    std::mt19937_64 rng(1907);
    std::uniform_real_distribution<double> u01(0, 1);
    Curve h = curve_of(CurveKind::Hermite, 2, {0, 0, 1, 0});
    h.tangents = {1, 1, 1, -1};
    Curve cr = curve_of(CurveKind::CatmullRom, 2, {0, 0, 1, 1, 2, 0, 3, 1});
    for (int n = 0; n < kCases; ++n) {
        const double u = u01(rng);
        // Hermite items: p0, p1 (i = 0, 1), then t0, t1 (i = 2, 3).
        const double H[4] = {2 * u * u * u - 3 * u * u + 1, -2 * u * u * u + 3 * u * u, u * u * u - 2 * u * u + u, u * u * u - u * u};
        // Catmull-Rom (lecture 003, times 2): rows (-1 3 -3 1), (2 -5 4 -1), (-1 0 1 0), (0 2 0 0).
        const double C[4] = {(-u * u * u + 2 * u * u - u) / 2, (3 * u * u * u - 5 * u * u + 2) / 2, (-3 * u * u * u + 4 * u * u + u) / 2,
                             (u * u * u - u * u) / 2};
        for (int i = 0; i < 4; ++i) {
            ValueAsk a = ask("blend");
            a.i = i;
            a.u = u;
            const WorkedValue wh = worked_value(of_curve(h), a);
            const WorkedValue wc = worked_value(of_curve(cr), a);
            INFO("u " << u << ", i " << i);
            REQUIRE(close(wh.expected[0], H[i]));
            REQUIRE(close(wc.expected[0], C[i]));
            // The worked line (the column of the slide's matrix) ends with the same value.
            for (const WorkedValue* w : {&wh, &wc}) {
                const std::string& last = w->working.back();
                REQUIRE(std::abs(std::stod(last.substr(last.rfind("= ") + 2)) - w->expected[0]) <= 1e-5);
            }
        }
    }
    // The quarter circle: weights 1, sqrt(2)/2, 1; at u = 1/2, N = (1/4, 1/2, 1/4) and
    // R_1,2 = (sqrt(2)/2 . 1/2) / (1/4 + sqrt(2)/4 + 1/4) = sqrt(2) / (2 + sqrt(2)) (lecture 001, NURBS).
    Curve q = curve_of(CurveKind::Nurbs, 2, {1, 0, 1, 1, 0, 1});
    q.degree = 2;
    q.knots = {0, 0, 0, 1, 1, 1};
    q.weights = {1, std::sqrt(0.5), 1};
    ValueAsk a = ask("blend");
    a.i = 1;
    a.u = 0.5;
    const WorkedValue w = worked_value(of_curve(q), a);
    CHECK(w.label == "R₁,₂(0.5)");
    CHECK(close(w.expected[0], std::sqrt(2.0) / (2 + std::sqrt(2.0))));
}

TEST_CASE("boehm: on a NURBS the new point is the combination in homogeneous coordinates", "[exercise][value]") {
    Curve q = curve_of(CurveKind::Nurbs, 2, {1, 0, 1, 1, 0, 1});
    q.degree = 2;
    q.knots = {0, 0, 0, 1, 1, 1};
    q.weights = {1, std::sqrt(0.5), 1};
    // u = 1/2 in the span k = 2, p = 2: Q_1 from P_0, P_1 with a_1 = 1/2, Q_2 from P_1, P_2 with a_2 = 1/2.
    for (int index = 1; index <= 2; ++index) {
        ValueAsk a = ask("boehm");
        a.u = 0.5;
        a.index = index;
        const WorkedValue w = worked_value(of_curve(q), a);
        const double w0 = q.weights[index - 1], w1 = q.weights[index];
        for (int x = 0; x < 2; ++x) {
            const double expected = (0.5 * w0 * q.points[2 * (index - 1) + x] + 0.5 * w1 * q.points[2 * index + x]) / (0.5 * w0 + 0.5 * w1);
            CHECK(close(w.expected[x], expected));
        }
        CHECK(w.working.back().find(index == 1 ? "Q₁ = (0.5 · 1 · (1, 0) + 0.5 · 0.707107 · (1, 1))" : "Q₂ = (0.5 · 0.707107 · (1, 1) + 0.5 · 1 · (0, 1))") == 0);
    }
}
