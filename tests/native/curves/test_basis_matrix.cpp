// The lecture's cubic basis matrices, checked against their own derivations rather than
// against the code's output.
#include <catch2/catch.hpp>

#include "wingspline/curves/basis_matrix.h"
#include "wingspline/error.h"

using namespace wingspline::curves;

namespace {
constexpr double kExact = 1e-14; // matrix entries are small rationals: exact to rounding

double eval_row(const Mat4& m, int col, double u) {
    // [u^3 u^2 u 1] . column `col` of M: the blending function for control `col`.
    return u * u * u * m[col] + u * u * m[4 + col] + u * m[8 + col] + m[12 + col];
}
} // namespace

TEST_CASE("M_Hermite is the inverse of the lecture's constraint matrix", "[curves][basis]") {
    const Mat4 inv = inverse(hermite_constraint_matrix());
    const Mat4 slide = {2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0}; // lecture 000
    const Mat4 m = basis_matrix(BasisKind::Hermite);
    for (int i = 0; i < 16; ++i) {
        CHECK(inv[i] == Approx(slide[i]).margin(kExact));
        CHECK(m[i] == slide[i]);
    }
    const Mat4 id = multiply(hermite_constraint_matrix(), m);
    for (int i = 0; i < 16; ++i) CHECK(id[i] == Approx(i % 5 == 0 ? 1.0 : 0.0).margin(kExact));
}

TEST_CASE("Bezier blending functions are the Bernstein polynomials", "[curves][basis]") {
    const Mat4 m = basis_matrix(BasisKind::Bezier);
    for (double u = 0; u <= 1.0; u += 0.125) {
        const double s = 1 - u;
        CHECK(eval_row(m, 0, u) == Approx(s * s * s).margin(kExact));
        CHECK(eval_row(m, 1, u) == Approx(3 * u * s * s).margin(kExact));
        CHECK(eval_row(m, 2, u) == Approx(3 * u * u * s).margin(kExact));
        CHECK(eval_row(m, 3, u) == Approx(u * u * u).margin(kExact));
    }
}

TEST_CASE("every cubic basis is a partition of unity", "[curves][basis]") {
    for (auto kind : {BasisKind::Bezier, BasisKind::BSpline, BasisKind::CatmullRom}) {
        const Mat4 m = basis_matrix(kind);
        for (double u = 0; u <= 1.0; u += 0.0625) {
            double sum = 0;
            for (int c = 0; c < 4; ++c) sum += eval_row(m, c, u);
            CHECK(sum == Approx(1.0).margin(kExact));
        }
    }
}

TEST_CASE("basis names parse and unknown names are refused with a code", "[curves][basis]") {
    CHECK(parse_basis_kind("catmull-rom") == BasisKind::CatmullRom);
    try {
        parse_basis_kind("bezir");
        FAIL("expected an error");
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == "unknown-basis");
        CHECK(std::string(e.what()).find("bezir") != std::string::npos);
    }
}

TEST_CASE("a singular matrix is refused, not inverted into infinities", "[curves][basis]") {
    Mat4 singular = basis_matrix(BasisKind::Bezier);
    for (int j = 0; j < 4; ++j) singular[4 + j] = singular[j]; // two equal rows
    CHECK_THROWS_AS(inverse(singular), wingspline::Error);
}
