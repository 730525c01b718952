// The lectures' notation: a basis matrix written as the slides write it, one
// fraction in front of a matrix of integers (1/6 [...] for the uniform B-spline, 1/2 [...]
// for Catmull-Rom). The expected integer matrices are typed from the lecture text
// (003_55ddbc47c7ee2ef3.txt and 002_5284cf65dc3cb6f3.txt), not from the code.
#include <catch2/catch.hpp>

#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/segment.h"

#include <cmath>
#include <numeric>
#include <random>
#include <vector>

using namespace wingspline::curves;

namespace {
std::vector<double> flat(const Mat4& m) { return {m.begin(), m.end()}; }

void check_form(const std::vector<double>& values, long long denominator, const std::vector<long long>& integers) {
    const auto form = rational_form(values);
    REQUIRE(form.has_value());
    CHECK(form->denominator == denominator);
    CHECK(form->numerators == integers);
}
} // namespace

TEST_CASE("rational form of the lecture 003 basis matrices", "[curves][basis][notation]") {
    // M_Hermite (lecture 000 / 003): integers, denominator 1.
    check_form(flat(basis_matrix(BasisKind::Hermite)), 1, {2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0});
    // M_Bezier (lecture 003).
    check_form(flat(basis_matrix(BasisKind::Bezier)), 1, {-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0});
    // M_B-spline = 1/6 [-1 3 -3 1; 3 -6 3 0; -3 0 3 0; 1 4 1 0] (lecture 003).
    check_form(flat(basis_matrix(BasisKind::BSpline)), 6, {-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0});
    // M_CR = 1/2 [-1 3 -3 1; 2 -5 4 -1; -1 0 1 0; 0 2 0 0] (lecture 003).
    check_form(flat(basis_matrix(BasisKind::CatmullRom)), 2, {-1, 3, -3, 1, 2, -5, 4, -1, -1, 0, 1, 0, 0, 2, 0, 0});
    // The cardinal spline at tension 0 is Catmull-Rom, so the same form.
    check_form(flat(cardinal_matrix(0.0)), 2, {-1, 3, -3, 1, 2, -5, 4, -1, -1, 0, 1, 0, 0, 2, 0, 0});
}

TEST_CASE("rational form: the smallest common denominator, property over random fractions", "[curves][basis][notation]") {
    // Random integer matrices N and denominators d, reduced by hand (gcd of d and all of N):
    // the form of N/d computed in floating point must give back exactly the reduced pair.
    std::mt19937 rng(1802);
    std::uniform_int_distribution<int> entry(-60, 60), den(1, 120), size(1, 64);
    for (int trial = 0; trial < 4000; ++trial) {
        const int d = den(rng);
        std::vector<long long> n(static_cast<std::size_t>(size(rng)));
        for (auto& x : n) x = entry(rng);
        long long g = d;
        for (long long x : n) g = std::gcd(g, std::llabs(x));
        std::vector<double> values;
        for (long long x : n) values.push_back(static_cast<double>(x) / d);
        std::vector<long long> reduced;
        for (long long x : n) reduced.push_back(x / g);
        INFO("trial " << trial << " d " << d);
        check_form(values, d / g, reduced);
    }
}

TEST_CASE("rational form refuses what is not a small fraction, and scales with the entries", "[curves][basis][notation]") {
    CHECK_FALSE(rational_form({std::sqrt(2.0), 1.0}).has_value());
    CHECK_FALSE(rational_form({1.0 / 1009.0}).has_value());           // denominator above the limit
    CHECK_FALSE(rational_form({std::nan(""), 1.0}).has_value());
    CHECK_FALSE(rational_form({INFINITY}).has_value());
    CHECK(rational_form({1.0 / 1009.0}, 2000)->denominator == 1009);  // the limit is a parameter
    // Large entries: 1e6/3 is still 1/3 [1000000].
    const auto big = rational_form({1e6 / 3.0, -2e6 / 3.0});
    REQUIRE(big.has_value());
    CHECK(big->denominator == 3);
    CHECK(big->numerators == std::vector<long long>{1000000, -2000000});
    // All zeros: 0 with denominator 1.
    check_form({0.0, -0.0}, 1, {0, 0});
}

TEST_CASE("rational form of a uniform cubic B-spline segment is lecture 003's 1/6 matrix", "[curves][basis][notation]") {
    // The segment matrix the curve explorer shows for a uniform knot vector (computed from the
    // knots, not copied from basis_matrix) has the slide's exact form.
    Curve c;
    c.kind = CurveKind::BSpline;
    c.degree = 3;
    c.dim = 2;
    c.points = {0, 0, 1, 2, 2, -1, 3, 1, 4, 0, 5, 2};
    c.knots = {-3, -2, -1, 0, 1, 2, 3, 4, 5, 6};
    for (int s = 0; s < segment_count(c); ++s) {
        const SegmentMatrices m = segment_matrices(c, s);
        check_form(m.M, 6, {-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0});
    }
}
