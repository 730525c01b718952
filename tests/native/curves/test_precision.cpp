// Trust: polynomial interpolation at any offset and scale,
// NURBS weights at any scale, and a linear-time conversion of B-splines to Bezier segments.
// Every expected value is recomputed independently here (de Casteljau in the test, the
// a-priori rounding bound of the monomial form, the weights' invariance under scaling).
#include "curves_fixtures.h"

#include "wingspline/curves/bezier.h"
#include "wingspline/curves/bspline_ops.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace wingspline::curves;
using namespace curves_fixtures;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// The interpolating polynomial at its own node: the data value, up to a few roundings
// relative to the largest data value (dimensionless factor of max |y|).
constexpr double kThroughData = 8 * kEps;

double max_abs(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

Curve interpolation(std::vector<double> points, std::vector<double> nodes, int dim = 2) {
    Curve c = make_curve(CurveKind::Interpolation, std::move(points), dim);
    c.nodes = std::move(nodes);
    return c;
}

// The largest miss |P(u_i) - y_i| over all nodes, as a fraction of max |y|.
double worst_miss_at_nodes(const Curve& c) {
    const int K = control_point_count(c);
    std::vector<double> u = c.nodes;
    if (u.empty())
        for (int i = 0; i < K; ++i) u.push_back(static_cast<double>(i) / (K - 1));
    const std::vector<double> P = evaluate_curve(c, u);
    double worst = 0;
    for (std::size_t i = 0; i < P.size(); ++i) worst = std::max(worst, std::abs(P[i] - c.points[i]));
    return worst / std::max(max_abs(c.points), DBL_MIN);
}

// Random strictly increasing nodes: gaps between 0.2 and 1 (relative), mapped to
// offset + scale * x with scale in 1e-6..1e6 and |offset| up to 1e6 x scale.
std::vector<double> random_nodes(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> unit(0, 1);
    for (;;) {
        const double scale = std::pow(10.0, -6 + 12 * unit(rng));
        const double offset = (unit(rng) < 0.5 ? -1 : 1) * scale * std::pow(10.0, -2 + 8 * unit(rng));
        std::vector<double> u;
        double x = 0;
        for (int i = 0; i < count; ++i) {
            u.push_back(offset + scale * x);
            x += 0.2 + 0.8 * unit(rng);
        }
        bool fine = true;
        const double spread = u.back() - u.front();
        for (int i = 1; i < count; ++i) fine = fine && u[i] - u[i - 1] > 1e-3 * spread;
        if (fine) return u;
    }
}

std::vector<double> random_values(std::mt19937_64& rng, int count, int dim) {
    std::uniform_real_distribution<double> unit(0, 1);
    std::normal_distribution<double> gauss(0, 1);
    const double size = std::pow(10.0, -6 + 12 * unit(rng));
    const double centre = size * std::pow(10.0, -3 + 6 * unit(rng));
    std::vector<double> y;
    for (int i = 0; i < count * dim; ++i) y.push_back(centre + size * gauss(rng));
    return y;
}

} // namespace

// ------------------------------------------------------------------ interpolation

TEST_CASE("interpolation: any distinct nodes have an interpolant", "[curves][interpolation][trust]") {
    const std::vector<double> pts = {0, 1, 1, 3, 2, 0, 3, 2};
    SECTION("nodes 300..303 and 0, 1e-6, 2e-6, 3e-6 are accepted and interpolated") {
        for (const std::vector<double>& nodes : {std::vector<double>{300, 301, 302, 303}, std::vector<double>{0, 1e-6, 2e-6, 3e-6}}) {
            const Curve c = interpolation(pts, nodes);
            CHECK(worst_miss_at_nodes(c) <= kThroughData);
        }
    }
    SECTION("a cubic at nodes 200..203 reaches its end point") {
        const Curve c = interpolation(pts, {200, 201, 202, 203});
        const std::vector<double> end = evaluate_curve(c, {203.0});
        CHECK(std::abs(end[0] - 3) <= kThroughData * 3);
        CHECK(std::abs(end[1] - 2) <= kThroughData * 3);
    }
    SECTION("16 points at the default nodes pass through every point") {
        const Curve c = make_curve(CurveKind::Interpolation, zigzag(16));
        CHECK(worst_miss_at_nodes(c) <= kThroughData);
    }
    SECTION("up to kMaxInterpolationPoints points at the default nodes") {
        REQUIRE(kMaxInterpolationPoints >= 32);
        const Curve c = make_curve(CurveKind::Interpolation, zigzag(kMaxInterpolationPoints));
        CHECK(worst_miss_at_nodes(c) <= kThroughData);
        expect_error([&] { validate(make_curve(CurveKind::Interpolation, zigzag(kMaxInterpolationPoints + 1))); },
                    "degree-out-of-range", std::to_string(kMaxInterpolationPoints) + " points");
    }
    SECTION("nodes that nearly coincide relative to their spread are refused, naming them") {
        expect_error([&] { validate(interpolation({0, 0, 1, 1, 2, 0}, {0, 1e-12, 1})); }, "nodes-too-close", "u_0");
        expect_error([&] { validate(interpolation({0, 0, 1, 1, 2, 0}, {5e6, 5e6 + 1e-6, 5e6 + 1e4})); }, "nodes-too-close", "u_1");
        // the same relative gaps at another scale are accepted
        CHECK(worst_miss_at_nodes(interpolation({0, 0, 1, 1, 2, 0}, {0, 1e-6, 1})) <= kThroughData);
        CHECK(worst_miss_at_nodes(interpolation({0, 0, 1, 1, 2, 0}, {-3e-300, -2e-300, 7e-300})) <= kThroughData);
    }
}

TEST_CASE("interpolation passes through its data at random offsets and scales (property)",
          "[curves][interpolation][trust]") {
    std::mt19937_64 rng(20240613);
    std::uniform_int_distribution<int> count(2, kMaxInterpolationPoints);
    int checked = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const int K = count(rng);
        const int dim = trial % 2 ? 3 : 2;
        const Curve c = interpolation(random_values(rng, K, dim), random_nodes(rng, K), dim);
        INFO("trial " << trial << ", " << K << " points, u_0 = " << c.nodes.front() << ", u_n = " << c.nodes.back());
        const double miss = worst_miss_at_nodes(c);
        if (!(miss <= kThroughData)) FAIL_CHECK("misses its data by " << miss << " x max |y|");
        // derivatives exist and are finite everywhere on the domain
        const std::vector<double> all = evaluate_curve_all(c, linspace(c.nodes.front(), c.nodes.back(), 9), 2);
        for (double v : all) REQUIRE(std::isfinite(v));
        ++checked;
    }
    CHECK(checked == 3000);
}

TEST_CASE("interpolation: segmentMatrices' C agrees with evaluation to the rounding of the monomial form",
          "[curves][interpolation][trust]") {
    // Horner on C = V^-1 G (lecture 000's power form in the global u) rounds by at most
    // about n eps sum_k |c_k| |u|^k, and the expansion of V^-1 by n eps times the same sum of
    // the expansion with |u_m|: S(u) = sum_j |y_j| prod_(m != j) (|u| + |u_m|) / |u_j - u_m|.
    // The bound is 8 (n + 1) eps S(u): the form is shown, not evaluated, because S(u) can be
    // far above max |y| (the monomial basis is ill-conditioned away from 0).
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> count(2, 12);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        const int K = count(rng);
        std::vector<double> nodes = random_nodes(rng, K);
        if (trial % 4 == 0) nodes.clear(); // the default nodes i/n
        const Curve c = interpolation(random_values(rng, K, 2), nodes);
        const SegmentMatrices s = segment_matrices(c, 0);
        REQUIRE(s.C.size() == static_cast<std::size_t>(2 * K));
        const int n = K - 1;
        std::vector<double> u = nodes;
        if (u.empty())
            for (int i = 0; i <= n; ++i) u.push_back(static_cast<double>(i) / n);
        for (int q = 0; q < 8; ++q) {
            const double x = q < 2 ? u[q * n] : u.front() + (u.back() - u.front()) * unit(rng);
            const std::vector<double> P = evaluate_curve(c, {x});
            double bound = 0;
            for (int j = 0; j <= n; ++j) {
                double f = 1;
                for (int m = 0; m <= n; ++m)
                    if (m != j) f *= (std::abs(x) + std::abs(u[m])) / std::abs(u[j] - u[m]);
                bound += f * std::max(std::abs(c.points[2 * j]), std::abs(c.points[2 * j + 1]));
            }
            bound *= 8 * (n + 1) * kEps;
            for (int k = 0; k < 2; ++k) {
                double h = 0;
                for (int r = 0; r <= n; ++r) h = h * x + s.C[r * 2 + k];
                INFO("trial " << trial << ", K = " << K << ", u = " << x);
                if (!(std::abs(h - P[k]) <= bound)) FAIL_CHECK("Horner on C gives " << h << ", the curve " << P[k] << ", bound " << bound);
            }
        }
    }
}

// ------------------------------------------------------------------ NURBS weights

namespace {

Curve random_nurbs(std::mt19937_64& rng, bool bezier) {
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> small(1, 16);
    const int p = 1 + static_cast<int>(unit(rng) * 4);
    const int K = p + 1 + (bezier ? 0 : static_cast<int>(unit(rng) * 6));
    Curve c = make_curve(bezier ? CurveKind::Bezier : CurveKind::Nurbs, {});
    c.degree = bezier ? 0 : p;
    for (int i = 0; i < 2 * K; ++i) c.points.push_back(2 * unit(rng) - 1);
    for (int i = 0; i < K; ++i) c.weights.push_back(small(rng)); // integers 1..16
    if (!bezier) {
        c.knots.assign(static_cast<std::size_t>(p + 1), 0.0);
        double t = 0;
        for (int i = 0; i < K - p - 1; ++i) c.knots.push_back(t += 0.25 + unit(rng));
        c.knots.insert(c.knots.end(), static_cast<std::size_t>(p + 1), t + 0.25 + unit(rng));
    }
    return c;
}

} // namespace

TEST_CASE("NURBS: weights w and c w give the same curve for c from 1e-320 to 1e300",
          "[curves][nurbs][trust]") {
    // c = 2^e, e in [-1074, 1019], weights integers 1..16: c w is exact (subnormal too), so
    // the two curves are the same curve and must agree to rounding (kSameCurve, relative to
    // the largest value compared), finite everywhere.
    std::mt19937_64 rng(1305);
    std::uniform_int_distribution<int> exponent(-1074, 1019);
    for (int trial = 0; trial < 2000; ++trial) {
        const Curve a = random_nurbs(rng, trial % 5 == 0);
        Curve b = a;
        const int e = trial < 4 ? std::vector<int>{-1074, -1063, 1019, 996}[trial] : exponent(rng);
        for (double& w : b.weights) w = std::ldexp(w, e);
        INFO("trial " << trial << ", c = 2^" << e << ", kind " << curve_kind_name(a.kind));
        const CurveEvaluator ea(a);
        const Domain d = ea.domain();
        const std::vector<double> u = linspace(d.start, d.end, 11);
        const std::vector<double> pa = evaluate_curve_all(a, u, 2);
        const std::vector<double> pb = evaluate_curve_all(b, u, 2);
        const double size = std::max(1.0, max_abs(pa));
        for (std::size_t i = 0; i < pa.size(); ++i) {
            REQUIRE(std::isfinite(pb[i]));
            if (!(std::abs(pa[i] - pb[i]) <= kSameCurve * size)) FAIL_CHECK("value " << i << ": " << pa[i] << " vs " << pb[i]);
        }
        // the algorithms a lesson animates: finite, and the same points
        const DeBoorSteps sa = de_boor(a, 0.5 * (d.start + d.end)), sb = de_boor(b, 0.5 * (d.start + d.end));
        for (std::size_t r = 0; r < sa.levels.size(); ++r)
            for (std::size_t i = 0; i < sa.levels[r].size(); ++i) {
                REQUIRE(std::isfinite(sb.levels[r][i]));
                CHECK(std::abs(sa.levels[r][i] - sb.levels[r][i]) <= kSameCurve * size);
            }
        for (double w : sb.level_weights.back()) CHECK((std::isfinite(w) && w > 0));
        const auto ba = to_bezier_segments(a), bb = to_bezier_segments(b);
        REQUIRE(ba.size() == bb.size());
        for (std::size_t s = 0; s < ba.size(); ++s)
            for (std::size_t i = 0; i < ba[s].points.size(); ++i) {
                REQUIRE(std::isfinite(bb[s].points[i]));
                CHECK(std::abs(ba[s].points[i] - bb[s].points[i]) <= kSameCurve * size);
            }
        const KnotInsertion ka = insert_knot(a, 0.3 * d.start + 0.7 * d.end), kb = insert_knot(b, 0.3 * d.start + 0.7 * d.end);
        for (std::size_t i = 0; i < ka.curve.points.size(); ++i) {
            REQUIRE(std::isfinite(kb.curve.points[i]));
            CHECK(std::abs(ka.curve.points[i] - kb.curve.points[i]) <= kSameCurve * size);
        }
        if (a.kind == CurveKind::Bezier) {
            const DeCasteljauSteps ca = de_casteljau(a.points, 2, 0.4, a.weights), cb = de_casteljau(b.points, 2, 0.4, b.weights);
            for (int k = 0; k < 2; ++k) {
                REQUIRE(std::isfinite(cb.levels.back()[k]));
                CHECK(std::abs(ca.levels.back()[k] - cb.levels.back()[k]) <= kSameCurve * size);
            }
        }
    }
}

TEST_CASE("NURBS: a uniform weight cancels at every magnitude", "[curves][nurbs][trust]") {
    const Curve plain = clamped_with_double_knot();
    const std::vector<double> u = linspace(0, 5, 41);
    const std::vector<double> expected = evaluate_curve_all(plain, u, 2);
    for (double w : {std::numeric_limits<double>::denorm_min(), 1e-320, 1e-300, 1.0, 1e300, DBL_MAX}) {
        INFO("all weights " << w);
        Curve c = plain;
        c.kind = CurveKind::Nurbs;
        c.weights.assign(8, w);
        const std::vector<double> got = evaluate_curve_all(c, u, 2);
        const double size = max_abs(expected);
        for (std::size_t i = 0; i < got.size(); ++i) {
            REQUIRE(std::isfinite(got[i]));
            CHECK(std::abs(got[i] - expected[i]) <= kSameCurve * size);
        }
    }
}

TEST_CASE("NURBS: weights whose ratio leaves the range of double are refused", "[curves][nurbs][trust]") {
    Curve c = clamped_with_double_knot();
    c.kind = CurveKind::Nurbs;
    c.weights = {1, 1, 1e300, 1, 1, 1, 1e-10, 1};
    expect_error([&] { validate(c); }, "weight-ratio-out-of-range", "w_6");
    c.weights[6] = 1e-2; // ratio 1e302 is still too far
    expect_error([&] { validate(c); }, "weight-ratio-out-of-range", "w_2");
    c.weights[2] = 1e250; // ratio 1e252: fine
    for (double v : evaluate_curve(c, linspace(0, 5, 21))) CHECK(std::isfinite(v));
}

// ------------------------------------------------------------------ B-spline -> Bezier

namespace {

// de Casteljau in homogeneous coordinates, written here independently of the core.
std::vector<double> bezier_point(const BezierSegment& s, int dim, double t) {
    const int n = static_cast<int>(s.points.size()) / dim;
    const bool rational = !s.weights.empty();
    const int hd = dim + 1;
    std::vector<double> h(static_cast<std::size_t>(n * hd));
    for (int i = 0; i < n; ++i) {
        const double w = rational ? s.weights[i] : 1.0;
        for (int k = 0; k < dim; ++k) h[i * hd + k] = w * s.points[i * dim + k];
        h[i * hd + dim] = w;
    }
    for (int r = 1; r < n; ++r)
        for (int i = 0; i < n - r; ++i)
            for (int k = 0; k < hd; ++k) h[i * hd + k] = (1 - t) * h[i * hd + k] + t * h[(i + 1) * hd + k];
    std::vector<double> p(dim);
    for (int k = 0; k < dim; ++k) p[k] = h[k] / h[dim];
    return p;
}

Curve random_spline(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0, 1);
    const int p = 1 + static_cast<int>(unit(rng) * 6);
    const int K = p + 1 + static_cast<int>(unit(rng) * 25);
    Curve c = make_curve(unit(rng) < 0.3 ? CurveKind::Nurbs : CurveKind::BSpline, {}, 3);
    c.degree = p;
    for (int i = 0; i < 3 * K; ++i) c.points.push_back(10 * unit(rng) - 5);
    if (c.kind == CurveKind::Nurbs)
        for (int i = 0; i < K; ++i) c.weights.push_back(0.2 + 3 * unit(rng));
    // knots: random steps, some of them 0 (repeated knots up to multiplicity p + 1), clamped
    // or not at either end
    const int m = K + p + 1;
    for (;;) {
        c.knots.clear();
        double t = 0;
        for (int j = 0; j < m; ++j) {
            c.knots.push_back(t);
            t += unit(rng) < 0.25 ? 0 : 0.1 + unit(rng);
        }
        if (unit(rng) < 0.5) std::fill(c.knots.begin(), c.knots.begin() + p + 1, c.knots[p]);
        if (unit(rng) < 0.5) std::fill(c.knots.end() - p - 1, c.knots.end(), c.knots[K]);
        try {
            validate(c);
            return c;
        } catch (const wingspline::Error&) {
        }
    }
}

} // namespace

TEST_CASE("bsplineToBezier: every segment is the B-spline on its span (property)", "[curves][bspline][trust]") {
    std::mt19937_64 rng(16);
    for (int trial = 0; trial < 1500; ++trial) {
        const Curve c = random_spline(rng);
        const int K = control_point_count(c), p = c.degree;
        INFO("trial " << trial << ", K = " << K << ", p = " << p);
        const auto segments = to_bezier_segments(c);
        std::vector<double> spans;
        for (int l = p; l < K; ++l)
            if (c.knots[l] < c.knots[l + 1]) spans.push_back(l);
        REQUIRE(segments.size() == spans.size());
        double size = max_abs(c.points);
        for (std::size_t s = 0; s < segments.size(); ++s) {
            const int l = static_cast<int>(spans[s]);
            CHECK(segments[s].start == c.knots[l]);
            CHECK(segments[s].end == c.knots[l + 1]);
            REQUIRE(segments[s].points.size() == static_cast<std::size_t>(3 * (p + 1)));
            for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
                const double x = segments[s].start + t * (segments[s].end - segments[s].start);
                const std::vector<double> want = evaluate_curve(c, {std::min(x, segments[s].end)});
                // at the right end of a span the B-spline gives the right-hand value; the
                // segment's end is the left-hand limit: compare only inside or at the domain end
                if (t == 1.0 && l != spans.back()) continue;
                const std::vector<double> got = bezier_point(segments[s], 3, t);
                for (int k = 0; k < 3; ++k)
                    if (!(std::abs(got[k] - want[k]) <= kSameCurve * 10 * size))
                        FAIL_CHECK("segment " << s << " at t = " << t << ": " << got[k] << " vs " << want[k]);
            }
        }
    }
}

TEST_CASE("bsplineToBezier does work linear in the number of control points", "[curves][bspline][trust]") {
    // The work counter counts control-point values copied or combined. Each span is
    // converted from its own p + 1 points and 2p knots, so the work per segment must not
    // grow with K (it did: every knot insertion copied the whole polygon).
    auto work_per_segment = [](int K, int p) {
        Curve c = make_curve(CurveKind::BSpline, zigzag(K));
        c.degree = p;
        std::size_t work = 0;
        const auto segments = to_bezier_segments(c, &work);
        REQUIRE(segments.size() == static_cast<std::size_t>(K - p));
        return static_cast<double>(work) / segments.size();
    };
    for (int p : {1, 3, 5}) {
        const double small = work_per_segment(500, p), large = work_per_segment(8000, p);
        INFO("degree " << p << ": " << small << " per segment at K = 500, " << large << " at K = 8000");
        CHECK(large <= 1.05 * small);
        CHECK(large <= 2.0 * (p + 1) * (p + 1) * 2); // two triangles of (p+1)^2 / 2 steps, dim 2
    }
}
