#pragma once
// Named fixtures and tolerances for the curves tests. Matrices are typed here literally from
// the slides (lecture file and heading given), never copied from the code's output.
#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/curve.h"

#include "wingspline/error.h"

#include "../../bench/native/bench_curve.h" // bench_bspline: docs/benchmarks.md's B-spline, shared with the benchmark

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace curves_fixtures {

// Runs f, expects an Error with `code` whose message contains `fragment`.
template <class F> void expect_error(F&& f, const std::string& code, const std::string& fragment) {
    try {
        f();
        FAIL("expected error " << code);
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == code);
        INFO("message: " << e.what());
        CHECK(std::string(e.what()).find(fragment) != std::string::npos);
    }
}

using wingspline::curves::Curve;
using wingspline::curves::CurveKind;
using wingspline::curves::Mat4;

// Tolerances (model units unless stated).
constexpr double kExact = 1e-14;       // small rational matrix entries: exact up to rounding
constexpr double kSameCurve = 1e-12;   // two evaluations of the same curve by different routes
constexpr double kCircle = 1e-12;      // NURBS circle: | |P - c| - r | (the figure)
constexpr double kFiniteDiff = 1e-6;   // central differences, step 1e-5: O(h^2) + rounding/h

// ---- lecture 003 (one-page summary), C = M G with P(u) = [u^3 u^2 u 1] C
inline Mat4 slide_hermite() { return {2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0}; }
inline Mat4 slide_bezier() { return {-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0}; }
inline Mat4 slide_bspline_times6() { return {-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0}; }
inline Mat4 slide_catmull_rom_times2() { return {-1, 3, -3, 1, 2, -5, 4, -1, -1, 0, 1, 0, 0, 2, 0, 0}; }
// ---- lecture 001 (Q(t) = G M T, M written transposed): the Hermite constraint matrix and M_H
inline Mat4 lecture001_hermite_constraints() { return {0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 1, 1, 1, 1, 0, 0}; }
inline Mat4 lecture001_hermite() { return {2, -3, 0, 1, -2, 3, 0, 0, 1, -2, 1, 0, 1, -1, 0, 0}; }
// lecture 001: M_B = M_HB . M_H (both in the transposed convention)
inline Mat4 lecture001_bezier_to_hermite() { return {1, 0, -3, 0, 0, 0, 3, 0, 0, 0, 0, -3, 0, 1, 0, 3}; }
inline Mat4 lecture001_bezier() { return {-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0}; }
// ---- lecture 002: B-spline M_s in ascending powers (c0..c3), times 6
inline Mat4 lecture002_bspline_ascending_times6() { return {1, 4, 1, 0, -3, 0, 3, 0, 3, -6, 3, 0, -1, 3, -3, 1}; }
// lecture 002, Catmull-Rom: the conditions p(0)=p1, p(1)=p2, p'(0)=(p2-p0)/2, p'(1)=(p3-p1)/2
// as (rows of A) P = B c with c = (c0 c1 c2 c3).
inline Mat4 lecture002_catmull_conditions() { return {0, 1, 0, 0, 0, 0, 1, 0, -0.5, 0, 0.5, 0, 0, -0.5, 0, 0.5}; }
inline Mat4 lecture002_endpoint_rows() { return {1, 0, 0, 0, 1, 1, 1, 1, 0, 1, 0, 0, 0, 1, 2, 3}; }
// lecture 002: subdivision of a cubic Bezier at 1/2, times 8
inline Mat4 lecture002_GBL_times8() { return {8, 0, 0, 0, 4, 4, 0, 0, 2, 4, 2, 0, 1, 3, 3, 1}; }
inline Mat4 lecture002_GBR_times8() { return {1, 3, 3, 1, 0, 2, 4, 2, 0, 0, 4, 4, 0, 0, 0, 8}; }

inline Mat4 scaled(Mat4 m, double s) {
    for (double& v : m) v *= s;
    return m;
}

// ---- curves
// docs/benchmarks.md's cubic Bezier: P0=(0,0,0), P1=(1,2,0.5), P2=(3,2,1), P3=(4,0,1.5).
inline Curve bench_bezier() {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.dim = 3;
    c.points = {0, 0, 0, 1, 2, 0.5, 3, 2, 1, 4, 0, 1.5};
    return c;
}

// A zig-zag polygon in the plane: P_i = (i, (-1)^i (1 + i/4)); no three points collinear.
inline std::vector<double> zigzag(int count) {
    std::vector<double> p;
    for (int i = 0; i < count; ++i) p.insert(p.end(), {static_cast<double>(i), (i % 2 ? -1.0 : 1.0) * (1 + i / 4.0)});
    return p;
}

inline Curve make_curve(CurveKind kind, std::vector<double> points, int dim = 2) {
    Curve c;
    c.kind = kind;
    c.dim = dim;
    c.points = std::move(points);
    return c;
}

// A degree-3 B-spline on the zig-zag with a non-uniform, clamped knot vector that has an
// interior double knot at 2:  t = [0 0 0 0 | 1 2 2 3.5 | 5 5 5 5], K = 8.
inline Curve clamped_with_double_knot() {
    Curve c = make_curve(CurveKind::BSpline, zigzag(8));
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 1, 2, 2, 3.5, 5, 5, 5, 5};
    return c;
}

// An unclamped, non-uniform degree-2 B-spline: t = [0 0.5 1 2 2.5 4 4.5 6], K = 5, domain [1, 2.5].
inline Curve unclamped_quadratic() {
    Curve c = make_curve(CurveKind::BSpline, zigzag(5));
    c.degree = 2;
    c.knots = {0, 0.5, 1, 2, 2.5, 4, 4.5, 6};
    return c;
}

inline std::vector<double> linspace(double a, double b, int n) {
    std::vector<double> v(n);
    for (int i = 0; i < n; ++i) v[i] = a + (b - a) * i / (n - 1);
    v[n - 1] = b;
    return v;
}

inline double distance(const double* a, const double* b, int dim) {
    double s = 0;
    for (int k = 0; k < dim; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(s);
}

} // namespace curves_fixtures
