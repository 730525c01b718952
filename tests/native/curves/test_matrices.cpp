// The lecture's matrices entry for entry, in both conventions, and the matrix form of every
// segment against the evaluator (lectures 000-003).
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/bezier.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

using namespace wingspline::curves;
using namespace curves_fixtures;

namespace {
void check_equal(const Mat4& a, const Mat4& b, double tol = kExact) {
    for (int i = 0; i < 16; ++i) {
        INFO("entry " << i / 4 << "," << i % 4);
        CHECK(a[i] == Approx(b[i]).margin(tol));
    }
}
void check_equal(const std::vector<double>& a, const Mat4& b, double tol = kExact) {
    REQUIRE(a.size() == 16);
    Mat4 m;
    std::copy(a.begin(), a.end(), m.begin());
    check_equal(m, b, tol);
}
} // namespace

TEST_CASE("the four slide matrices of lecture 003 - entry for entry", "[curves][matrices]") {
    check_equal(basis_matrix(BasisKind::Hermite), slide_hermite(), 0);
    check_equal(basis_matrix(BasisKind::Bezier), slide_bezier(), 0);
    check_equal(basis_matrix(BasisKind::BSpline), scaled(slide_bspline_times6(), 1.0 / 6));
    check_equal(basis_matrix(BasisKind::CatmullRom), scaled(slide_catmull_rom_times2(), 0.5));
}

TEST_CASE("lecture 001's transposed convention: Q(t) = G M T uses M^T", "[curves][matrices]") {
    // 001 writes the constraint matrix and M_H transposed; its M_H is the inverse of its
    // constraint matrix, and its M_B = M_HB . M_H is the transpose of 003's M_Bezier (which
    // is symmetric, so equal to it).
    check_equal(lecture001_hermite(), transpose(basis_matrix(BasisKind::Hermite)), 0);
    check_equal(inverse(lecture001_hermite_constraints()), lecture001_hermite());
    check_equal(multiply(lecture001_bezier_to_hermite(), lecture001_hermite()), lecture001_bezier());
    check_equal(transpose(basis_matrix(BasisKind::Bezier)), lecture001_bezier(), 0);
}

TEST_CASE("lecture 002's derivations give lecture 003's matrices", "[curves][matrices]") {
    // B-spline: 002 writes M_s for ascending powers (c0 c1 c2 c3); reversing the rows gives
    // 003's matrix for [u^3 u^2 u 1].
    const Mat4 asc = scaled(lecture002_bspline_ascending_times6(), 1.0 / 6);
    Mat4 reversed{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) reversed[4 * r + c] = asc[4 * (3 - r) + c];
    check_equal(reversed, basis_matrix(BasisKind::BSpline));
    // Catmull-Rom: solving 002's four conditions B c = A P gives M = B^-1 A (ascending), whose
    // reversed rows are 003's M_CR. (002's printed M_R has a slip in its first row, "0" for
    // the last entry; 003 and the conditions agree on 1/2.)
    const Mat4 m = multiply(inverse(lecture002_endpoint_rows()), lecture002_catmull_conditions());
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) reversed[4 * r + c] = m[4 * (3 - r) + c];
    check_equal(reversed, basis_matrix(BasisKind::CatmullRom));
}

TEST_CASE("cardinal spline: tension 0 is Catmull-Rom - tension 1 gives zero tangents", "[curves][matrices]") {
    check_equal(cardinal_matrix(0.0), basis_matrix(BasisKind::CatmullRom));
    // tension 1: s = 0, the segment is the Hermite curve from P_i to P_i+1 with zero tangents.
    const Mat4 m = cardinal_matrix(1.0);
    const Mat4 expected = {0, 2, -2, 0, 0, -3, 3, 0, 0, 0, 0, 0, 0, 1, 0, 0};
    check_equal(m, expected);
}

TEST_CASE("lecture 002's G_B^L and G_B^R are the subdivision matrices at 1/2", "[curves][matrices][bezier]") {
    std::vector<double> SL, SR;
    bezier_subdivision_matrices(3, 0.5, SL, SR);
    check_equal(SL, scaled(lecture002_GBL_times8(), 1.0 / 8));
    check_equal(SR, scaled(lecture002_GBR_times8(), 1.0 / 8));
}

TEST_CASE("the Bernstein power matrix of degree 3 is the slide's M_Bezier", "[curves][matrices][bezier]") {
    check_equal(bezier_power_matrix(3), slide_bezier(), 0);
    // degree 2: (1-t)^2, 2t(1-t), t^2 -> rows t^2: [1 -2 1], t: [-2 2 0], 1: [1 0 0]
    const auto m2 = bezier_power_matrix(2);
    const std::vector<double> expected = {1, -2, 1, -2, 2, 0, 1, 0, 0};
    for (int i = 0; i < 9; ++i) CHECK(m2[i] == expected[i]);
}

TEST_CASE("segment matrices: M is the slide's and u^T C is the curve", "[curves][matrices][segment]") {
    struct Case {
        const char* name;
        Curve curve;
        Mat4 slide;
    };
    Curve hermite = make_curve(CurveKind::Hermite, zigzag(4));
    hermite.tangents = {1, 0, 0, 2, -1, 1, 3, 3};
    Curve uniform = make_curve(CurveKind::BSpline, zigzag(6));
    const std::vector<Case> cases = {
        {"hermite", hermite, slide_hermite()},
        {"bezier", make_curve(CurveKind::Bezier, zigzag(4)), slide_bezier()},
        {"uniform bspline", uniform, scaled(slide_bspline_times6(), 1.0 / 6)},
        {"catmull-rom", make_curve(CurveKind::CatmullRom, zigzag(6)), scaled(slide_catmull_rom_times2(), 0.5)},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        const int count = segment_count(c.curve);
        for (int s = 0; s < count; ++s) {
            const SegmentMatrices m = segment_matrices(c.curve, s);
            check_equal(m.M, c.slide, 0);
            for (double u : {0.0, 0.3, 0.75, 1.0}) {
                const double t = m.start + u * (m.end - m.start);
                const auto p = evaluate_curve(c.curve, {t});
                for (int k = 0; k < 2; ++k) {
                    const double v = u * u * u * m.C[k] + u * u * m.C[2 + k] + u * m.C[4 + k] + m.C[6 + k];
                    CHECK(v == Approx(p[k]).margin(kSameCurve));
                }
            }
        }
    }
}

TEST_CASE("segment matrices of a non-uniform B-spline reproduce the Cox-de Boor curve", "[curves][matrices][segment]") {
    for (const Curve& c : {clamped_with_double_knot(), unclamped_quadratic()}) {
        const int p = curve_degree(c);
        for (int s = 0; s < segment_count(c); ++s) {
            const SegmentMatrices m = segment_matrices(c, s);
            // Horner on the rows of C = M G reproduces the curve anywhere on the span.
            for (double u : {0.0, 0.25, 0.5, 1.0}) {
                const double t = m.start + u * (m.end - m.start);
                const auto point = evaluate_curve(c, {t});
                for (int k = 0; k < 2; ++k) {
                    double v = 0;
                    for (int r = 0; r <= p; ++r) v = v * u + m.C[r * 2 + k];
                    CHECK(v == Approx(point[k]).margin(kSameCurve));
                }
            }
        }
    }
}

TEST_CASE("basis conversion q = M^-1 M_B P gives the same segment (lecture 002)", "[curves][matrices]") {
    const std::vector<double> bezier = {0, 0, 1, 2, 3, 2, 4, 0};
    // Bezier -> Hermite: p0, p3, 3(p1-p0), 3(p3-p2) (lecture 002's derivation).
    const auto h = convert_basis(bezier, 2, BasisKind::Bezier, BasisKind::Hermite);
    const std::vector<double> expected = {0, 0, 4, 0, 3, 6, 3, -6};
    for (int i = 0; i < 8; ++i) CHECK(h[i] == Approx(expected[i]).margin(kExact * 10));
    // Bezier -> B-spline -> Catmull-Rom -> Bezier is the identity.
    auto q = convert_basis(bezier, 2, BasisKind::Bezier, BasisKind::BSpline);
    q = convert_basis(q, 2, BasisKind::BSpline, BasisKind::CatmullRom);
    q = convert_basis(q, 2, BasisKind::CatmullRom, BasisKind::Bezier);
    for (int i = 0; i < 8; ++i) CHECK(q[i] == Approx(bezier[i]).margin(1e-12));
}

TEST_CASE("segment errors name the valid range", "[curves][matrices][errors]") {
    const Curve c = make_curve(CurveKind::CatmullRom, zigzag(5));
    try {
        segment_matrices(c, 2);
        FAIL("expected an error");
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == "segment-out-of-range");
        CHECK(std::string(e.what()).find("0 to 1") != std::string::npos);
    }
}
