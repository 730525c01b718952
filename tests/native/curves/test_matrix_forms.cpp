// The lectures' notation: the three ways the lectures write one cubic basis matrix.
//   descending (000, 003): P(u) = [u^3 u^2 u 1] M G
//   ascending  (002):      p(u) = u^T C, u = (1, u, u^2, u^3), C = M g
//   transposed (001):      Q(t) = G M T, T = [t^3 t^2 t 1]^T a column
// Every expected matrix is typed from the lecture text (002_5284cf65dc3cb6f3.txt,
// 001_7dd064aa3628c1d6.txt, 003_55ddbc47c7ee2ef3.txt) or recomputed here in integers from
// the lecture's own conditions; none is copied from the code's output.
#include <catch2/catch.hpp>

#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <cmath>
#include <string>
#include <vector>

using namespace wingspline::curves;

namespace {
using IntMat = std::vector<long long>; // 4x4 row-major integers

void check_form(BasisKind kind, MatrixForm form, long long denominator, const IntMat& integers) {
    const Mat4 m = basis_matrix(kind, form);
    const auto r = rational_form(std::vector<double>(m.begin(), m.end()));
    REQUIRE(r.has_value());
    CHECK(r->denominator == denominator);
    CHECK(r->numerators == integers);
}

IntMat mul(const IntMat& a, const IntMat& b) {
    IntMat r(16, 0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[4 * i + j] += a[4 * i + k] * b[4 * k + j];
    return r;
}
IntMat scaled(const IntMat& a, long long s) {
    IntMat r = a;
    for (auto& x : r) x *= s;
    return r;
}
} // namespace

TEST_CASE("lecture 002's ascending form: u = (1, u, u^2, u^3), C = M g", "[curves][basis][notation]") {
    // Hermite: 002 prints b(u) = M_H^T u = (2u^3 - 3u^2 + 1, -2u^3 + 3u^2, u^3 - 2u^2 + u, u^3 - u^2);
    // column i of M_H holds b_i's coefficients of 1, u, u^2, u^3.
    const IntMat hermite = {1, 0, 0, 0, 0, 0, 1, 0, -3, 3, -2, -1, 2, -2, 1, 1};
    check_form(BasisKind::Hermite, MatrixForm::Ascending, 1, hermite);
    // ... and M_H = A_H^-1 with 002's A_H = [1 0 0 0; 1 1 1 1; 0 1 0 0; 0 1 2 3].
    const IntMat A_H = {1, 0, 0, 0, 1, 1, 1, 1, 0, 1, 0, 0, 0, 1, 2, 3};
    CHECK(mul(A_H, hermite) == IntMat{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    // Bezier: 002's b(u) = M_B^T u = ((1-u)^3, 3u(1-u)^2, 3u^2(1-u), u^3), expanded.
    check_form(BasisKind::Bezier, MatrixForm::Ascending, 1, {1, 0, 0, 0, -3, 3, 0, 0, 3, -6, 3, 0, -1, 3, -3, 1});
    // B-spline: 002 prints M_s = B^-1 A = 1/6 (1 4 1 0; -3 0 3 0; 3 -6 3 0; -1 3 -3 1).
    check_form(BasisKind::BSpline, MatrixForm::Ascending, 6, {1, 4, 1, 0, -3, 0, 3, 0, 3, -6, 3, 0, -1, 3, -3, 1});
    // Catmull-Rom: 002's printed M_R has a slip (first row ends in 0, rows in descending
    // order); the form is what 002's own conditions give: B (2 M_R) = 2 A with
    // B = [1 0 0 0; 1 1 1 1; 0 1 0 0; 0 1 2 3] and A = [0 1 0 0; 0 0 1 0; -1/2 0 1/2 0; 0 -1/2 0 1/2].
    const IntMat cr2 = {0, 2, 0, 0, -1, 0, 1, 0, 2, -5, 4, -1, -1, 3, -3, 1};
    check_form(BasisKind::CatmullRom, MatrixForm::Ascending, 2, cr2);
    const IntMat B = {1, 0, 0, 0, 1, 1, 1, 1, 0, 1, 0, 0, 0, 1, 2, 3};
    const IntMat twoA = {0, 2, 0, 0, 0, 0, 2, 0, -1, 0, 1, 0, 0, -1, 0, 1};
    CHECK(mul(B, cr2) == twoA);
}

TEST_CASE("lecture 001's transposed form: Q(t) = G M T", "[curves][basis][notation]") {
    // 001 prints M_H = [2 -3 0 1; -2 3 0 0; 1 -2 1 0; 1 -1 0 0] and
    // M_B = [-1 3 -3 1; 3 -6 3 0; -3 3 0 0; 1 0 0 0].
    check_form(BasisKind::Hermite, MatrixForm::Transposed, 1, {2, -3, 0, 1, -2, 3, 0, 0, 1, -2, 1, 0, 1, -1, 0, 0});
    check_form(BasisKind::Bezier, MatrixForm::Transposed, 1, {-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0});
    // 001 prints M_B as the product M_HB . M_H: check that product in integers too.
    const IntMat M_HB = {1, 0, -3, 0, 0, 0, 3, 0, 0, 0, 0, -3, 0, 1, 0, 3};
    const IntMat M_H = {2, -3, 0, 1, -2, 3, 0, 0, 1, -2, 1, 0, 1, -1, 0, 0};
    CHECK(mul(M_HB, M_H) == IntMat{-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0});
    // 001 has no printed B-spline or Catmull-Rom matrix: 003's, transposed.
    check_form(BasisKind::BSpline, MatrixForm::Transposed, 6, {-1, 3, -3, 1, 3, -6, 0, 4, -3, 3, 3, 1, 1, 0, 0, 0});
    check_form(BasisKind::CatmullRom, MatrixForm::Transposed, 2, {-1, 2, -1, 0, 3, -5, 0, 2, -3, 4, 1, 0, 1, -1, 0, 0});
}

TEST_CASE("descending form is lecture 003's matrix; forms of any square matrix", "[curves][basis][notation]") {
    // 003: M_h = [2 -2 1 1; -3 3 -2 -1; 0 0 1 0; 1 0 0 0], C_i = 1/6 [-1 3 -3 1; 3 -6 3 0; -3 0 3 0; 1 4 1 0].
    check_form(BasisKind::Hermite, MatrixForm::Descending, 1, {2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0});
    check_form(BasisKind::BSpline, MatrixForm::Descending, 6, {-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0});
    // Any degree: a 2x3 coefficient block in each form (rows multiply u^1, u^0 descending).
    const std::vector<double> c = {1, 2, 3, 4, 5, 6};
    CHECK(matrix_in_form(c, 2, 3, MatrixForm::Descending) == c);
    CHECK(matrix_in_form(c, 2, 3, MatrixForm::Ascending) == std::vector<double>{4, 5, 6, 1, 2, 3});
    CHECK(matrix_in_form(c, 2, 3, MatrixForm::Transposed) == std::vector<double>{1, 4, 2, 5, 3, 6});
    CHECK(parse_matrix_form("ascending") == MatrixForm::Ascending);
    CHECK(std::string(matrix_form_name(MatrixForm::Transposed)) == "transposed");
    try {
        parse_matrix_form("upside-down");
        FAIL("an unknown form must be refused");
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == "unknown-form");
    }
    try {
        matrix_in_form(c, 4, 4, MatrixForm::Ascending);
        FAIL("a size that does not match must be refused");
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == "invalid-argument");
    }
}

TEST_CASE("a segment in each form: C = M g (002) and G M = C^T (001) hold for the shown matrices", "[curves][basis][notation]") {
    // A degree-5 Bezier and a clamped cubic B-spline: the product of the shown M and G is
    // the shown C in every form (recomputed here), and the ascending C evaluates to the curve.
    Curve bezier;
    bezier.kind = CurveKind::Bezier;
    bezier.dim = 2;
    bezier.points = {0, 0, 1, 3, 2, -1, 4, 2, 5, 0, 7, 1};
    Curve spline;
    spline.kind = CurveKind::BSpline;
    spline.dim = 2;
    spline.degree = 3;
    spline.points = {0, 0, 1, 2, 2, -1, 3, 1, 4, 0, 5, 2};
    spline.knots = {0, 0, 0, 0, 1, 3, 4, 4, 4, 4};
    for (const Curve& c : {bezier, spline}) {
        const CurveEvaluator eval(c);
        for (int seg = 0; seg < segment_count(c); ++seg) {
            const SegmentMatrices s = segment_matrices(c, seg);
            const int n = s.degree + 1, d = s.columns;
            const double scale = 8; // the points' extent (unit: the points' unit)
            for (MatrixForm form : {MatrixForm::Descending, MatrixForm::Ascending, MatrixForm::Transposed}) {
                const SegmentForm f = segment_in_form(s, form);
                REQUIRE(f.m_size == n);
                for (int i = 0; i < f.g_rows; ++i)
                    for (int j = 0; j < f.g_cols; ++j) {
                        double sum = 0;
                        if (form == MatrixForm::Transposed) // (G M)_ij with G d x n, M n x n
                            for (int k = 0; k < n; ++k) sum += f.G[n * i + k] * f.M[n * k + j];
                        else // (M G)_ij with M n x n, G n x d
                            for (int k = 0; k < n; ++k) sum += f.M[n * i + k] * f.G[d * k + j];
                        CHECK(std::abs(sum - f.C[f.g_cols * i + j]) <= 1e-12 * scale);
                    }
                if (form != MatrixForm::Ascending) continue;
                // p(u) = u^T C with u = (1, u, .., u^p): Horner from the last row.
                for (double u : {0.0, 0.3, 0.77, 1.0}) {
                    const double t = s.start + u * (s.end - s.start);
                    double expected[2];
                    eval.evaluate(eval.checked_params(&t, 1).data(), 1, 0, expected);
                    for (int k = 0; k < d; ++k) {
                        double v = 0;
                        for (int r = n - 1; r >= 0; --r) v = v * u + f.C[d * r + k];
                        CHECK(std::abs(v - expected[k]) <= 1e-12 * scale);
                    }
                }
            }
        }
    }
}
