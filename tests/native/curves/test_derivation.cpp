// The derivations of the cubic families in exact rational arithmetic, checked
// against the lectures' matrices (000/003: M_H, M_B, M_BS) and by independent recomputation.
#include <catch2/catch.hpp>

#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/derivation.h"

#include <vector>

using namespace wingspline::curves;

namespace {
// A matrix of integers over a common denominator, as on the slides.
std::vector<Rational> over(std::int64_t den, std::vector<std::int64_t> nums) {
    std::vector<Rational> r;
    for (auto n : nums) r.push_back(Rational(n, den));
    return r;
}
// Exact product of an r x k and a k x c rational matrix, computed here (not by the core).
std::vector<Rational> product(const std::vector<Rational>& a, const std::vector<Rational>& b, int r, int k, int c) {
    std::vector<Rational> p(r * c, Rational(0));
    for (int i = 0; i < r; ++i)
        for (int j = 0; j < c; ++j)
            for (int t = 0; t < k; ++t) p[c * i + j] = p[c * i + j] + a[k * i + t] * b[c * t + j];
    return p;
}
std::vector<Rational> identity(int n) {
    std::vector<Rational> m(n * n, Rational(0));
    for (int i = 0; i < n; ++i) m[n * i + i] = Rational(1);
    return m;
}
} // namespace

TEST_CASE("derivation: Hermite from its four constraints gives lecture 000's M_H, exactly", "[curves][derivation]") {
    const Derivation d = derive_cubic(BasisKind::Hermite);
    REQUIRE(d.size == 4);
    // [u^3 u^2 u 1] at u = 0, 1 and [3u^2 2u 1 0] at u = 0, 1 (lecture 000)
    CHECK(d.constraint == over(1, {0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 1, 0, 3, 2, 1, 0}));
    CHECK(d.basis == over(1, {2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0}));
    CHECK(product(d.constraint, d.basis, 4, 4, 4) == identity(4));
    CHECK(product(d.basis, d.constraint, 4, 4, 4) == identity(4));
}

TEST_CASE("derivation: Bezier from Hermite with R1 = 3(P2 - P1), R4 = 3(P4 - P3) gives M_B, exactly", "[curves][derivation]") {
    const Derivation h = derive_cubic(BasisKind::Hermite);
    const Derivation d = derive_cubic(BasisKind::Bezier);
    // G_H = [P1 P4 R1 R4] = S [P1 P2 P3 P4]
    CHECK(d.substitution == over(1, {1, 0, 0, 0, 0, 0, 0, 1, -3, 3, 0, 0, 0, 0, -3, 3}));
    CHECK(d.basis == over(1, {-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0}));
    CHECK(product(h.basis, d.substitution, 4, 4, 4) == d.basis);
}

TEST_CASE("derivation: the uniform B-spline from its C2 conditions gives lecture 003's M_BS = 1/6 [...]", "[curves][derivation]") {
    const Derivation d = derive_cubic(BasisKind::BSpline);
    REQUIRE(d.size == 16);
    CHECK(d.basis == over(6, {-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0}));
    // the 16 conditions hold for the answer: constraint . vec(M) = rhs (M read column by column,
    // the coefficients of one blending function after another)
    std::vector<Rational> x;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) x.push_back(d.basis[4 * r + c]);
    CHECK(product(d.constraint, x, 16, 16, 1) == d.rhs);
    CHECK(product(d.constraint, d.inverse, 16, 16, 16) == identity(16));
}

TEST_CASE("derivation: every derived matrix equals the slide matrix the curves are evaluated with", "[curves][derivation]") {
    for (BasisKind k : {BasisKind::Hermite, BasisKind::Bezier, BasisKind::BSpline}) {
        const Derivation d = derive_cubic(k);
        const Mat4 m = basis_matrix(k);
        for (int i = 0; i < 16; ++i) CHECK(d.basis[i].value() == Approx(m[i]).margin(1e-15));
    }
}

TEST_CASE("derivation: Catmull-Rom is refused with a clear error", "[curves][derivation][errors]") {
    CHECK_THROWS_WITH(derive_cubic(BasisKind::CatmullRom), Catch::Contains("Hermite, Bezier and the uniform B-spline"));
}
