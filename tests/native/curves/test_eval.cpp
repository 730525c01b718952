// Evaluation of every family against analytic facts: partition of unity, non-negativity,
// endpoint interpolation where the comparison tables of lectures 001 and 003 say it holds
// (and not where they say it does not), de Casteljau = Bernstein, finite differences,
// affine invariance, subdivision and degree elevation leaving the curve unchanged.
#include <catch2/catch.hpp>

#include "curves_fixtures.h"
#include "wingspline/curves/bezier.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <cmath>

using namespace wingspline::curves;
using namespace curves_fixtures;

namespace {

Curve hermite_fixture() {
    Curve c = make_curve(CurveKind::Hermite, zigzag(4));
    c.tangents = {1, 0, 0, 2, -1, 1, 3, 3};
    return c;
}

Curve nurbs_fixture() {
    Curve c = clamped_with_double_knot();
    c.kind = CurveKind::Nurbs;
    c.weights = {1, 2, 0.5, 1, 3, 1, 0.25, 1};
    return c;
}

Curve cardinal_fixture(double tension) {
    Curve c = make_curve(CurveKind::Cardinal, zigzag(6));
    c.tension = tension;
    return c;
}

// Every family once, for the generic checks.
std::vector<std::pair<std::string, Curve>> all_families() {
    Curve rational_bezier = make_curve(CurveKind::Bezier, zigzag(5));
    rational_bezier.weights = {1, 0.5, 2, 1, 1.5};
    Curve interp = make_curve(CurveKind::Interpolation, zigzag(6));
    return {{"bezier", make_curve(CurveKind::Bezier, zigzag(6))},
            {"rational bezier", rational_bezier},
            {"uniform bspline", make_curve(CurveKind::BSpline, zigzag(7))},
            {"clamped bspline with double knot", clamped_with_double_knot()},
            {"unclamped quadratic", unclamped_quadratic()},
            {"nurbs", nurbs_fixture()},
            {"hermite", hermite_fixture()},
            {"catmull-rom", make_curve(CurveKind::CatmullRom, zigzag(6))},
            {"cardinal", cardinal_fixture(0.4)},
            {"interpolation", interp},
            {"bench bspline", bench_bspline()},
            {"bench nurbs", bench_bspline(true)}};
}

// True when u is within `gap` of a knot or segment joint (where a derivative may jump).
bool near_break(const Curve& c, double u, double gap) {
    if (!c.knots.empty()) {
        for (double t : c.knots)
            if (std::abs(u - t) < gap) return true;
        return false;
    }
    if (c.kind == CurveKind::Bezier || c.kind == CurveKind::Interpolation) return false;
    return std::abs(u - std::round(u)) < gap;
}

std::vector<double> domain_samples(const Curve& c, int n) {
    const CurveEvaluator ev(c);
    return linspace(ev.domain().start, ev.domain().end, n);
}

} // namespace

TEST_CASE("Bezier and B-spline and NURBS bases: partition of unity and non-negativity", "[curves][basis]") {
    std::vector<Curve> curves;
    for (int n = 1; n <= 10; ++n) curves.push_back(make_curve(CurveKind::Bezier, zigzag(n + 1)));
    for (int p = 1; p <= 5; ++p) {
        Curve c = make_curve(CurveKind::BSpline, zigzag(p + 4));
        c.degree = p;
        curves.push_back(c);
    }
    curves.push_back(clamped_with_double_knot());
    curves.push_back(unclamped_quadratic());
    curves.push_back(nurbs_fixture());
    curves.push_back(bench_bspline());
    for (const Curve& c : curves) {
        INFO(curve_kind_name(c.kind) << " degree " << curve_degree(c));
        const auto params = domain_samples(c, 57);
        const BlendingValues b = blending_functions(c, params);
        for (std::size_t j = 0; j < params.size(); ++j) {
            double sum = 0;
            for (int i = 0; i < b.count; ++i) {
                const double v = b.values[j * b.count + i];
                CHECK(v >= -kExact);
                sum += v;
            }
            CHECK(sum == Approx(1.0).margin(kSameCurve));
        }
    }
}

TEST_CASE("Cox-de Boor basis has local support: each function vanishes outside t_i..t_i+p+1", "[curves][basis]") {
    const Curve c = clamped_with_double_knot();
    const auto params = domain_samples(c, 101);
    const BlendingValues b = blending_functions(c, params);
    for (std::size_t j = 0; j < params.size(); ++j)
        for (int i = 0; i < b.count; ++i) {
            const bool inside = params[j] >= c.knots[i] && params[j] <= c.knots[i + 4];
            if (!inside) CHECK(b.values[j * b.count + i] == 0.0);
        }
}

TEST_CASE("Catmull-Rom: partition of unity but negative weights (no convex hull - lecture 003)", "[curves][basis]") {
    const Curve c = make_curve(CurveKind::CatmullRom, zigzag(6));
    const auto params = domain_samples(c, 41);
    const BlendingValues b = blending_functions(c, params);
    double most_negative = 0;
    for (std::size_t j = 0; j < params.size(); ++j) {
        double sum = 0;
        for (int i = 0; i < b.count; ++i) {
            sum += b.values[j * b.count + i];
            most_negative = std::min(most_negative, b.values[j * b.count + i]);
        }
        CHECK(sum == Approx(1.0).margin(kSameCurve));
    }
    // The outer weights are -u(1-u)^2/2 etc.: -2/27 at u = 1/3.
    CHECK(most_negative < -0.07);
}

TEST_CASE("Hermite blending functions are lecture 000's H0..H3", "[curves][basis]") {
    Curve c = make_curve(CurveKind::Hermite, {0, 0, 1, 0});
    c.tangents = {1, 0, 1, 0};
    for (double u : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        const BlendingValues b = blending_functions(c, {u});
        REQUIRE(b.count == 4); // p_0, p_1, t_0, t_1
        CHECK(b.values[0] == Approx(2 * u * u * u - 3 * u * u + 1).margin(kExact));
        CHECK(b.values[1] == Approx(-2 * u * u * u + 3 * u * u).margin(kExact));
        CHECK(b.values[2] == Approx(u * u * u - 2 * u * u + u).margin(kExact));
        CHECK(b.values[3] == Approx(u * u * u - u * u).margin(kExact));
        const BlendingValues d = blending_functions(c, {u}, 1);
        CHECK(d.values[0] == Approx(6 * u * u - 6 * u).margin(kExact));
        CHECK(d.values[2] == Approx(3 * u * u - 4 * u + 1).margin(kExact));
    }
}

TEST_CASE("uniform cubic B-spline blending functions are lecture 002's b(u)", "[curves][basis]") {
    // Segment 0 of the uniform B-spline uses P_0..P_3 with local u = t.
    const Curve c = make_curve(CurveKind::BSpline, zigzag(4));
    for (double u : {0.0, 0.25, 0.5, 1.0}) {
        const BlendingValues b = blending_functions(c, {u});
        const double s = 1 - u;
        CHECK(b.values[0] == Approx(s * s * s / 6).margin(kExact));
        CHECK(b.values[1] == Approx((4 - 6 * u * u + 3 * u * u * u) / 6).margin(kExact));
        CHECK(b.values[2] == Approx((1 + 3 * u + 3 * u * u - 3 * u * u * u) / 6).margin(kExact));
        CHECK(b.values[3] == Approx(u * u * u / 6).margin(kExact));
    }
}

TEST_CASE("interpolation facts of the comparison tables (lectures 001 - 003)", "[curves][interpolation]") {
    const auto pts = zigzag(6);
    auto point = [&](int i) { return std::vector<double>{pts[2 * i], pts[2 * i + 1]}; };
    auto at = [](const Curve& c, double u) { return evaluate_curve(c, {u}); };
    auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
        return distance(a.data(), b.data(), 2) < kSameCurve;
    };
    SECTION("Bezier interpolates its end points only") {
        const Curve c = make_curve(CurveKind::Bezier, pts);
        CHECK(same(at(c, 0), point(0)));
        CHECK(same(at(c, 1), point(5)));
        for (int i = 1; i < 5; ++i)
            for (double u : linspace(0, 1, 201)) CHECK_FALSE(same(at(c, u), point(i)));
    }
    SECTION("clamped B-spline interpolates its end points") {
        const Curve c = clamped_with_double_knot();
        CHECK(same(at(c, 0), {c.points[0], c.points[1]}));
        CHECK(same(at(c, 5), {c.points[14], c.points[15]}));
    }
    SECTION("uniform B-spline interpolates no control point") {
        const Curve c = make_curve(CurveKind::BSpline, pts);
        // At a joint the point is (P_i + 4 P_i+1 + P_i+2)/6 (lecture 002), not a control point.
        const auto p0 = at(c, 0);
        CHECK(p0[0] == Approx((pts[0] + 4 * pts[2] + pts[4]) / 6).margin(kExact));
        CHECK(p0[1] == Approx((pts[1] + 4 * pts[3] + pts[5]) / 6).margin(kExact));
        for (int i = 0; i < 6; ++i)
            for (double u : linspace(0, 3, 301)) CHECK_FALSE(same(at(c, u), point(i)));
    }
    SECTION("Hermite interpolates all its points with the given tangents") {
        const Curve c = hermite_fixture();
        for (int i = 0; i < 4; ++i) {
            CHECK(same(at(c, i), {c.points[2 * i], c.points[2 * i + 1]}));
            const auto d = evaluate_curve(c, {static_cast<double>(i)}, 1);
            CHECK(same(d, {c.tangents[2 * i], c.tangents[2 * i + 1]}));
        }
    }
    SECTION("Catmull-Rom interpolates the inner points P_1..P_K-2, not P_0 or P_K-1") {
        const Curve c = make_curve(CurveKind::CatmullRom, pts);
        for (int i = 1; i <= 4; ++i) CHECK(same(at(c, i - 1), point(i)));
        for (double u : linspace(0, 3, 301)) {
            CHECK_FALSE(same(at(c, u), point(0)));
            CHECK_FALSE(same(at(c, u), point(5)));
        }
        // and its tangent there is (P_i+1 - P_i-1)/2 (lecture 002)
        const auto d = evaluate_curve(c, {1.0}, 1);
        CHECK(d[0] == Approx((pts[6] - pts[2]) / 2).margin(kExact));
        CHECK(d[1] == Approx((pts[7] - pts[3]) / 2).margin(kExact));
    }
    SECTION("the interpolating polynomial passes through every point at its node") {
        Curve c = make_curve(CurveKind::Interpolation, pts);
        c.nodes = {0, 0.1, 0.3, 0.6, 0.8, 1};
        for (int i = 0; i < 6; ++i) CHECK(distance(at(c, c.nodes[i]).data(), &pts[2 * i], 2) < 1e-9);
    }
}

TEST_CASE("de Casteljau equals the Bernstein form for degrees 1..10", "[curves][bezier]") {
    for (int n = 1; n <= 10; ++n) {
        const auto pts = zigzag(n + 1);
        for (double t : linspace(0, 1, 13)) {
            const auto steps = de_casteljau(pts, 2, t);
            REQUIRE(steps.levels.size() == static_cast<std::size_t>(n + 1));
            for (int r = 0; r <= n; ++r) CHECK(steps.levels[r].size() == static_cast<std::size_t>(2 * (n + 1 - r)));
            const auto b = bernstein(n, t);
            double x = 0, y = 0;
            for (int i = 0; i <= n; ++i) {
                x += b[i] * pts[2 * i];
                y += b[i] * pts[2 * i + 1];
            }
            CHECK(steps.levels[n][0] == Approx(x).margin(kSameCurve));
            CHECK(steps.levels[n][1] == Approx(y).margin(kSameCurve));
            const auto p = evaluate_curve(make_curve(CurveKind::Bezier, pts), {t});
            CHECK(p[0] == Approx(x).margin(kSameCurve));
            CHECK(p[1] == Approx(y).margin(kSameCurve));
        }
    }
}

TEST_CASE("subdivision at any t and degree elevation leave the curve unchanged", "[curves][bezier]") {
    const auto pts = zigzag(5);
    const Curve whole = make_curve(CurveKind::Bezier, pts);
    for (double t : {0.5, 0.2, 0.85}) {
        const BezierSplit s = subdivide_bezier(pts, 2, t);
        const Curve left = make_curve(CurveKind::Bezier, s.left);
        const Curve right = make_curve(CurveKind::Bezier, s.right);
        for (double v : linspace(0, 1, 21)) {
            const auto a = evaluate_curve(left, {v});
            const auto b = evaluate_curve(whole, {v * t});
            CHECK(distance(a.data(), b.data(), 2) < kSameCurve);
            const auto c = evaluate_curve(right, {v});
            const auto d = evaluate_curve(whole, {t + v * (1 - t)});
            CHECK(distance(c.data(), d.data(), 2) < kSameCurve);
        }
    }
    Curve rational = whole;
    rational.weights = {1, 3, 0.5, 2, 1};
    const ElevatedBezier e = elevate_bezier(pts, 2, rational.weights);
    Curve elevated = make_curve(CurveKind::Bezier, e.points);
    elevated.weights = e.weights;
    const ElevatedBezier plain = elevate_bezier(pts, 2);
    const Curve elevated_plain = make_curve(CurveKind::Bezier, plain.points);
    CHECK(curve_degree(elevated) == 5);
    for (double v : linspace(0, 1, 31)) {
        const auto a = evaluate_curve(elevated, {v});
        const auto b = evaluate_curve(rational, {v});
        CHECK(distance(a.data(), b.data(), 2) < kSameCurve);
        const auto c = evaluate_curve(elevated_plain, {v});
        const auto d = evaluate_curve(whole, {v});
        CHECK(distance(c.data(), d.data(), 2) < kSameCurve);
    }
}

TEST_CASE("the uniform cubic B-spline by Cox-de Boor equals the slide's matrix form", "[curves][bspline]") {
    const auto pts = zigzag(7);
    const Curve c = make_curve(CurveKind::BSpline, pts);
    const Mat4 M = scaled(slide_bspline_times6(), 1.0 / 6);
    for (int seg = 0; seg < 4; ++seg)
        for (double u : linspace(0, 1, 9)) {
            const auto p = evaluate_curve(c, {seg + u});
            for (int k = 0; k < 2; ++k) {
                double v = 0;
                const double U[4] = {u * u * u, u * u, u, 1};
                for (int r = 0; r < 4; ++r)
                    for (int col = 0; col < 4; ++col) v += U[r] * M[4 * r + col] * pts[2 * (seg + col) + k];
                CHECK(p[k] == Approx(v).margin(kSameCurve));
            }
        }
}

TEST_CASE("first and second derivatives match central finite differences", "[curves][derivatives]") {
    const double h = 1e-5;
    for (const auto& [name, c] : all_families()) {
        INFO(name);
        const CurveEvaluator ev(c);
        const int d = c.dim;
        // Stay inside one polynomial piece: sample points away from knots/joints by h.
        for (double s : linspace(0.03, 0.97, 15)) {
            const double u = ev.domain().start + s * (ev.domain().end - ev.domain().start) + 0.0123;
            if (u + h > ev.domain().end || near_break(c, u, 4 * h)) continue;
            const auto all = evaluate_curve_all(c, {u - h, u, u + h}, 2);
            const int stride = 3 * d;
            for (int k = 0; k < d; ++k) {
                const double pm = all[k], pp = all[2 * stride + k];
                const double d1 = all[stride + d + k], d2 = all[stride + 2 * d + k];
                const double scale = std::max(1.0, std::abs(d1));
                CHECK((pp - pm) / (2 * h) == Approx(d1).margin(kFiniteDiff * scale * 10));
                const double fd1 = (all[2 * stride + d + k] - all[d + k]) / (2 * h);
                CHECK(fd1 == Approx(d2).margin(kFiniteDiff * std::max(1.0, std::abs(d2)) * 10));
            }
        }
    }
}

TEST_CASE("evaluate(order) agrees with evaluate_all and derivatives beyond the degree vanish", "[curves][derivatives]") {
    const Curve c = clamped_with_double_knot();
    const auto params = domain_samples(c, 11);
    const auto all = evaluate_curve_all(c, params, 4);
    for (int order = 0; order <= 4; ++order) {
        const auto one = evaluate_curve(c, params, order);
        for (std::size_t j = 0; j < params.size(); ++j)
            for (int k = 0; k < 2; ++k) CHECK(one[2 * j + k] == Approx(all[10 * j + 2 * order + k]).margin(kSameCurve));
    }
    for (std::size_t j = 0; j < params.size(); ++j) CHECK(all[10 * j + 8] == 0.0);
}

TEST_CASE("affine invariance: transforming the points transforms the curve", "[curves][invariance]") {
    // x' = A x + b with A = [[2, 1], [-0.5, 1.5]], b = (3, -1); Hermite tangents take A only.
    const double A[4] = {2, 1, -0.5, 1.5};
    const double b[2] = {3, -1};
    auto apply = [&](std::vector<double> v, bool translate) {
        for (std::size_t i = 0; i < v.size(); i += 2) {
            const double x = v[i], y = v[i + 1];
            v[i] = A[0] * x + A[1] * y + (translate ? b[0] : 0);
            v[i + 1] = A[2] * x + A[3] * y + (translate ? b[1] : 0);
        }
        return v;
    };
    for (const auto& [name, c] : all_families()) {
        if (c.dim != 2) continue;
        INFO(name);
        Curve moved = c;
        moved.points = apply(c.points, true);
        moved.tangents = apply(c.tangents, false);
        const auto params = domain_samples(c, 23);
        const auto a = apply(evaluate_curve(c, params), true);
        const auto m = evaluate_curve(moved, params);
        for (std::size_t i = 0; i < a.size(); ++i) CHECK(m[i] == Approx(a[i]).margin(1e-9));
    }
}

TEST_CASE("increasing - decreasing and random parameter orders give identical points", "[curves][bspline]") {
    const Curve c = bench_bspline(true);
    const CurveEvaluator ev(c);
    auto forward = linspace(ev.domain().start, ev.domain().end, 997);
    std::vector<double> backward(forward.rbegin(), forward.rend());
    std::vector<double> shuffled = forward;
    for (std::size_t i = 0; i < shuffled.size(); ++i) std::swap(shuffled[i], shuffled[(i * 7919) % shuffled.size()]);
    const auto f = evaluate_curve(c, forward);
    const auto b = evaluate_curve(c, backward);
    const auto s = evaluate_curve(c, shuffled);
    for (std::size_t j = 0; j < forward.size(); ++j)
        for (int k = 0; k < 3; ++k) {
            CHECK(b[3 * (forward.size() - 1 - j) + k] == f[3 * j + k]);
            const std::size_t where = std::find(shuffled.begin(), shuffled.end(), forward[j]) - shuffled.begin();
            CHECK(s[3 * where + k] == f[3 * j + k]);
        }
}
