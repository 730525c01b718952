// The comparison lesson's measurements in the core: convex hull, maps of the
// plane, distances, and the table's checks. Expected values are analytic (lecture formulas)
// or recomputed independently here (brute-force hulls in exact integer arithmetic, the map's
// matrix multiplied out by hand); thousands of seeded random cases for the general rules,
// including invariance of every verdict under scaling, translation and rotation.
#include "curves_fixtures.h"

#include "wingspline/curves/comparison.h"
#include "wingspline/curves/patch.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

using namespace wingspline::curves;
using curves_fixtures::expect_error;

namespace {

constexpr double kPi = 3.14159265358979323846;

// exact for small integers
long long cross_i(const std::vector<long long>& p, int o, int a, int b) {
    return (p[2 * a] - p[2 * o]) * (p[2 * b + 1] - p[2 * o + 1]) - (p[2 * a + 1] - p[2 * o + 1]) * (p[2 * b] - p[2 * o]);
}
bool on_segment(const std::vector<long long>& p, int i, int a, int b) {
    if (cross_i(p, a, b, i) != 0) return false;
    const auto within = [](long long v, long long s, long long t) { return std::min(s, t) <= v && v <= std::max(s, t); };
    return within(p[2 * i], p[2 * a], p[2 * b]) && within(p[2 * i + 1], p[2 * a + 1], p[2 * b + 1]);
}
bool in_triangle(const std::vector<long long>& p, int i, int a, int b, int c) {
    const long long d1 = cross_i(p, a, b, i), d2 = cross_i(p, b, c, i), d3 = cross_i(p, c, a, i);
    const bool neg = d1 < 0 || d2 < 0 || d3 < 0, pos = d1 > 0 || d2 > 0 || d3 > 0;
    return !(neg && pos);
}
// Extreme points by definition: not in a closed triangle or on a closed segment of others.
std::set<int> brute_force_extreme(const std::vector<long long>& p) {
    const int n = static_cast<int>(p.size() / 2);
    std::set<int> out;
    for (int i = 0; i < n; ++i) {
        bool inside = false;
        for (int a = 0; a < n && !inside; ++a) {
            if (a == i) continue;
            for (int b = a + 1; b < n && !inside; ++b) {
                if (b == i) continue;
                if (on_segment(p, i, a, b)) inside = true;
                for (int c = b + 1; c < n && !inside; ++c) {
                    if (c != i && cross_i(p, a, b, c) != 0 && in_triangle(p, i, a, b, c)) inside = true;
                }
            }
        }
        if (!inside) out.insert(i);
    }
    return out;
}

std::vector<long long> random_distinct_grid_points(std::mt19937_64& rng, int n, int range) {
    std::uniform_int_distribution<int> coord(-range, range);
    std::set<std::pair<long long, long long>> seen;
    std::vector<long long> p;
    while (static_cast<int>(p.size()) < 2 * n) {
        const long long x = coord(rng), y = coord(rng);
        if (!seen.insert({x, y}).second) continue;
        p.push_back(x);
        p.push_back(y);
    }
    return p;
}

// rotation by angle, uniform scale s, translation t
std::vector<double> similar(const std::vector<double>& p, double angle, double s, double tx, double ty) {
    std::vector<double> q(p.size());
    const double c = std::cos(angle) * s, sn = std::sin(angle) * s;
    for (std::size_t i = 0; i < p.size(); i += 2) {
        q[i] = c * p[i] - sn * p[i + 1] + tx;
        q[i + 1] = sn * p[i] + c * p[i + 1] + ty;
    }
    return q;
}

// The hull as a cyclic sequence, rotated to start at its smallest index (orientation kept).
std::vector<int32_t> canonical_cycle(std::vector<int32_t> c) {
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
}

Curve bezier(const std::vector<double>& p) {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.points = p;
    return c;
}
Curve window(CurveKind kind, const std::vector<double>& p) {
    Curve c;
    c.kind = kind;
    c.points = p;
    return c;
}
double extent_of(const std::vector<double>& p) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (std::size_t i = 0; i < p.size(); i += 2) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], p[i + k]);
            hi[k] = std::max(hi[k], p[i + k]);
        }
    }
    return std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

} // namespace

TEST_CASE("convex hull: 3000 random grid polygons against the brute-force extreme points, at any scale and rotation",
          "[curves][comparison][hull]") {
    std::mt19937_64 rng(20261124);
    std::uniform_int_distribution<int> count(1, 12);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = count(rng);
        // a small grid: many collinear triples and points on hull edges
        const std::vector<long long> grid = random_distinct_grid_points(rng, n, 4);
        const std::vector<double> pts(grid.begin(), grid.end());
        const std::set<int> expected = brute_force_extreme(grid);
        const ConvexHull h = convex_hull(pts);
        INFO("trial " << trial << ", n = " << n);
        const std::set<int> got(h.indices.begin(), h.indices.end());
        REQUIRE(got.size() == h.indices.size()); // no repeats
        REQUIRE(got == expected);
        const int m = static_cast<int>(h.indices.size());
        if (m >= 3) {
            // counter-clockwise, strictly convex, every input point inside or on the hull
            for (int e = 0; e < m; ++e) {
                const int a = h.indices[e], b = h.indices[(e + 1) % m], c = h.indices[(e + 2) % m];
                REQUIRE(cross_i(grid, a, b, c) > 0);
                for (int i = 0; i < n; ++i) REQUIRE(cross_i(grid, a, b, i) >= 0);
            }
        }
        // The same hull after a similarity transform spanning twelve orders of magnitude:
        // the relative tolerance absorbs the rounding that rotation puts on collinear points.
        const double s = std::pow(10.0, -6 + 12 * unit(rng));
        const std::vector<double> moved = similar(pts, 2 * kPi * unit(rng), s, s * 100 * (unit(rng) - 0.5), s * 100 * (unit(rng) - 0.5));
        const ConvexHull hm = convex_hull(moved);
        INFO("scale " << s);
        REQUIRE(std::set<int>(hm.indices.begin(), hm.indices.end()) == expected);
        if (m >= 3) REQUIRE(canonical_cycle(hm.indices) == canonical_cycle(h.indices));
    }
}

TEST_CASE("convex hull: degenerate inputs and errors", "[curves][comparison][hull]") {
    CHECK(convex_hull({}).indices.empty());
    CHECK(convex_hull({2, 3}).indices == std::vector<int32_t>{0});
    CHECK(convex_hull({2, 3, 2, 3, 2, 3}).indices == std::vector<int32_t>{0}); // one point, repeated
    // collinear: the two ends, lowest x first
    CHECK(convex_hull({3, 3, 1, 1, 2, 2, 0, 0}).indices == std::vector<int32_t>{3, 0});
    // a square with its centre and edge midpoints: the four corners, counter-clockwise from (0,0)
    CHECK(convex_hull({1, 1, 0, 0, 2, 0, 2, 2, 0, 2, 1, 0, 2, 1}).indices == std::vector<int32_t>{1, 2, 3, 4});
    CHECK(convex_hull({0, 0, 4, 0, 0, 4}).tolerance == Approx(kHullTolerance * 16));
    expect_error([] { convex_hull({0, 0, 1}); }, "invalid-points", "multiple of dim = 2");
    expect_error([] { convex_hull({0, 0, 1, NAN}); }, "non-finite-input", "point 1");
}

TEST_CASE("plane map: 2000 random maps against the matrix multiplied out by hand", "[curves][comparison][map]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        const double angle = 360 * u(rng), scale = 0.1 + 3 * std::abs(u(rng)), shear = u(rng);
        const double tx = 5 * u(rng), ty = 5 * u(rng), px = 0.05 * u(rng), py = 0.05 * u(rng);
        const bool perspective = trial % 2 == 1;
        const PlaneMap m = plane_map(perspective, angle, scale, shear, tx, ty, px, py);
        // L = scale * R(angle) * [1 shear; 0 1]
        const double r = angle * kPi / 180, R[4] = {std::cos(r), -std::sin(r), std::sin(r), std::cos(r)};
        const double L[4] = {scale * R[0], scale * (R[0] * shear + R[1]), scale * R[2], scale * (R[2] * shear + R[3])};
        std::vector<double> pts;
        for (int i = 0; i < 8; ++i) pts.push_back(4 * u(rng));
        const MappedPoints q = map_points(pts, 2, m);
        for (int i = 0; i < 4; ++i) {
            const double x = pts[2 * i], y = pts[2 * i + 1];
            const double w = perspective ? px * x + py * y + 1 : 1;
            CHECK(q.w[i] == Approx(w).epsilon(1e-14));
            CHECK(q.points[2 * i] == Approx((L[0] * x + L[1] * y + tx) / w).epsilon(1e-12).margin(1e-12));
            CHECK(q.points[2 * i + 1] == Approx((L[2] * x + L[3] * y + ty) / w).epsilon(1e-12).margin(1e-12));
        }
    }
}

TEST_CASE("plane map: affine maps commute with every polynomial curve, perspective only with the rational Bezier of weights w(P_i)",
          "[curves][comparison][map]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<double> p;
        for (int i = 0; i < 8; ++i) p.push_back(3 * u(rng));
        const double size = extent_of(p);
        const std::vector<double> params = domain_params(bezier(p), 41);
        const PlaneMap affine = plane_map(false, 360 * u(rng), 0.5 + std::abs(u(rng)), u(rng), u(rng), u(rng), 0, 0);
        for (CurveKind kind : {CurveKind::Bezier, CurveKind::BSpline, CurveKind::CatmullRom}) {
            const Curve c = window(kind, p);
            const std::vector<double> mapped_curve = map_points(evaluate_curve(c, params), 2, affine).points;
            const std::vector<double> curve_of_mapped = evaluate_curve(window(kind, map_points(p, 2, affine).points), params);
            CHECK(max_distance(mapped_curve, curve_of_mapped, 2).distance <= 1e-12 * 4 * size);
        }
        const PlaneMap persp = plane_map(true, 0, 1, 0, 0, 0, 0.15 * u(rng), 0.15 * u(rng));
        const MappedPoints q = map_points(p, 2, persp);
        Curve rational = bezier(q.points);
        rational.weights = q.w;
        const std::vector<double> mapped_curve = map_points(evaluate_curve(bezier(p), params), 2, persp).points;
        CHECK(max_distance(mapped_curve, evaluate_curve(rational, params), 2).distance <= 1e-12 * 4 * size);
    }
    // ... and the polynomial Bezier of the mapped points is visibly not the mapped curve
    const std::vector<double> p = {0, 0, 1, 2, 3, 2, 4, 0};
    const PlaneMap persp = plane_map(true, 0, 1, 0, 0, 0, 0.2, 0.1);
    const std::vector<double> params = domain_params(bezier(p), 41);
    CHECK(max_distance(map_points(evaluate_curve(bezier(p), params), 2, persp).points,
                       evaluate_curve(bezier(map_points(p, 2, persp).points), params), 2).distance > 1e-3);
}

TEST_CASE("plane map: a point behind the eye is refused and named", "[curves][comparison][map]") {
    const PlaneMap m = plane_map(true, 0, 1, 0, 0, 0, -0.5, 0); // w = 1 - x/2 <= 0 for x >= 2
    expect_error([&] { map_points({0, 0, 1, 0, 3, 1}, 2, m, "P"); }, "perspective-behind-eye", "P2 (3.00, 1.00)");
    expect_error([&] { map_points({0, 0, 2, 0}, 2, m); }, "perspective-behind-eye", "point 1");
    // an affine map ignores px, py
    CHECK(map_points({3, 1}, 2, plane_map(false, 0, 1, 0, 0, 0, -0.5, 0)).w[0] == 1);
    expect_error([&] { map_points({1e308, 0}, 2, plane_map(false, 0, 10, 0, 0, 0, 0, 0)); }, "non-finite-result", "point 0");
    expect_error([&] { map_points({0, 0, 1}, 2, m); }, "invalid-points", "multiple");
    expect_error([&] { map_points({0, 0, 1}, 3, m); }, "invalid-dimension", "dimension 2");
    expect_error([&] { plane_map(true, 0, NAN, 0, 0, 0, 0, 0); }, "non-finite-input", "scale");
}

TEST_CASE("max distance: concentric circles are their radius apart, at the sample where it is largest",
          "[curves][comparison][distance]") {
    std::vector<double> a, b;
    for (int j = 0; j < 50; ++j) {
        const double t = 2 * kPi * j / 50;
        a.push_back(7 + 3 * std::cos(t));
        a.push_back(-2 + 3 * std::sin(t));
        b.push_back(7 + (j == 17 ? 1 : 2) * std::cos(t)); // radius 2, one sample at radius 1
        b.push_back(-2 + (j == 17 ? 1 : 2) * std::sin(t));
    }
    const MaxDistance d = max_distance(a, b, 2);
    CHECK(d.distance == Approx(2).epsilon(1e-14));
    CHECK(d.index == 17);
    CHECK(max_distance({0, 0, 0}, {1, 2, 2}, 3).distance == Approx(3).epsilon(1e-15));
    CHECK(max_distance({}, {}, 2).index == -1);
    expect_error([] { max_distance({0, 0}, {0, 0, 1, 1}, 2); }, "invalid-argument", "same number");
    expect_error([] { max_distance({0, 0, 1, NAN}, {0, 0, 1, 1}, 2); }, "non-finite-input", "point 1");
}

TEST_CASE("blending weights: lecture 003's convex hull row from the weights, minima at u = 1/3 analytic",
          "[curves][comparison][weights]") {
    const std::vector<double> p = {0, 0, 1, 2, 3, 2, 4, 0};
    for (CurveKind kind : {CurveKind::Bezier, CurveKind::BSpline}) {
        const BlendingWeightCheck b = blending_weight_check({window(kind, p)}, 101);
        CHECK(b.convex_hull);
        CHECK(b.min_weight >= -kWeightTolerance);
        CHECK(b.sum_error <= kWeightTolerance);
    }
    // Catmull-Rom: the weight of P0 is (-u^3 + 2u^2 - u)/2, smallest at u = 1/3: -2/27.
    const BlendingWeightCheck cr = blending_weight_check({window(CurveKind::CatmullRom, p)}, 4);
    CHECK_FALSE(cr.convex_hull);
    CHECK(cr.min_weight == Approx(-2.0 / 27).epsilon(1e-13));
    CHECK(cr.min_weight_at == Approx(1.0 / 3).epsilon(1e-15));
    // Bezier: B_1 = 3u(1-u)^2 is 0 at u = 0, the first sample
    CHECK(blending_weight_check({window(CurveKind::Bezier, p)}, 4).min_weight_at == 0);
    // Hermite: H2 = u^3 - 2u^2 + u weights a tangent vector, largest at u = 1/3: 4/27.
    Curve h;
    h.kind = CurveKind::Hermite;
    h.points = {0, 0, 1, 0};
    h.tangents = {1, 1, 1, -1};
    const BlendingWeightCheck hb = blending_weight_check({h}, 4);
    CHECK_FALSE(hb.weights_points);
    CHECK_FALSE(hb.convex_hull);
    CHECK(hb.tangent_weight == Approx(4.0 / 27).epsilon(1e-13));
    expect_error([] { blending_weight_check({}, 10); }, "invalid-argument", "at least one segment");
    expect_error([&] { blending_weight_check({h}, 1); }, "invalid-argument", "samples");
}

TEST_CASE("control point distances: which points the curve passes through does not depend on scale, place or rotation",
          "[curves][comparison][interpolation]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<double> p;
        for (int i = 0; i < 12; ++i) p.push_back(8 * u(rng));
        const double s = std::pow(10.0, -7 + 14 * u(rng));
        const std::vector<double> q = similar(p, 2 * kPi * u(rng), s, 1e3 * s * u(rng), -1e3 * s * u(rng));
        // Bezier: P0, P3 always; Catmull-Rom (ends repeated): every point
        for (const auto& pts : {p, q}) {
            const std::vector<double> first(pts.begin(), pts.begin() + 8);
            const std::vector<double> second(pts.begin() + 6, pts.end());
            const PointCurveDistances b = point_curve_distances(pts, 2, {bezier(first), bezier(second)}, 101);
            INFO("trial " << trial << " scale " << s);
            CHECK(std::count(b.interpolated.begin(), b.interpolated.end(), 0) == 1);
            CHECK(std::count(b.interpolated.begin(), b.interpolated.end(), 3) == 1);
            CHECK(std::count(b.interpolated.begin(), b.interpolated.end(), 5) == 1);
            std::vector<Curve> cr;
            std::vector<double> list(pts.begin(), pts.begin() + 2);
            list.insert(list.end(), pts.begin(), pts.end());
            list.insert(list.end(), pts.end() - 2, pts.end());
            for (std::size_t i = 0; i + 8 <= list.size(); i += 2) cr.push_back(window(CurveKind::CatmullRom, std::vector<double>(list.begin() + i, list.begin() + i + 8)));
            CHECK(point_curve_distances(pts, 2, cr, 101).interpolated == std::vector<int32_t>{0, 1, 2, 3, 4, 5});
        }
        // distances scale with s (rotation and translation keep them)
        const std::vector<double> pf(p.begin(), p.begin() + 8), qf(q.begin(), q.begin() + 8);
        const PointCurveDistances dp = point_curve_distances(pf, 2, {window(CurveKind::BSpline, pf)}, 101);
        const PointCurveDistances dq = point_curve_distances(qf, 2, {window(CurveKind::BSpline, qf)}, 101);
        for (int i = 0; i < 4; ++i) CHECK(dq.distances[i] == Approx(s * dp.distances[i]).epsilon(1e-8));
        CHECK(dq.farthest == dp.farthest);
        CHECK(dq.nearest_missed == dp.nearest_missed);
    }
}

TEST_CASE("control point distances: analytic, a straight uniform B-spline misses its end points by a sixth of a chord",
          "[curves][comparison][interpolation]") {
    // Collinear equally spaced P0..P3 at x = 0, 3, 6, 9: the segment runs from (P0+4P1+P2)/6 = 3
    // to 6, so P0 and P3 are 3 away, P1 and P2 are on the curve.
    const std::vector<double> p = {0, 1, 3, 1, 6, 1, 9, 1};
    const PointCurveDistances d = point_curve_distances(p, 2, {window(CurveKind::BSpline, p)}, 7);
    CHECK(d.distances[0] == Approx(3).epsilon(1e-14));
    CHECK(d.distances[3] == Approx(3).epsilon(1e-14));
    CHECK(d.interpolated == std::vector<int32_t>{1, 2});
    CHECK(d.farthest == 0);
    CHECK(d.nearest_missed == 0);
    CHECK(d.tolerance == Approx(kInterpolationTolerance * 9));
    expect_error([&] { point_curve_distances({0, 0, 0}, 2, {window(CurveKind::BSpline, p)}, 7); }, "invalid-points", "multiple");
    expect_error([&] { point_curve_distances(p, 3, {window(CurveKind::BSpline, p)}, 7); }, "invalid-points", "multiple");
}

TEST_CASE("split check: every family's halves trace the original, at any scale; Boehm refinement keeps the curve",
          "[curves][comparison][subdivision]") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 1000; ++trial) {
        const double s = std::pow(10.0, 6 * u(rng));
        std::vector<double> p;
        for (int i = 0; i < 8; ++i) p.push_back(s * u(rng));
        const double size = extent_of(p);
        Curve h;
        h.kind = CurveKind::Hermite;
        h.points = {p[0], p[1], p[2], p[3]};
        h.tangents = {p[4], p[5], p[6], p[7]};
        for (const Curve& c : {bezier(p), window(CurveKind::BSpline, p), window(CurveKind::CatmullRom, p), h}) {
            const SplitCheck sc = split_check({c, c});
            CHECK(sc.segments == 2);
            CHECK(sc.error <= 1e-13 * 8 * size);
        }
        // a non-uniform cubic B-spline on 6 points: 3 spans, 3 knots inserted
        std::vector<double> q;
        for (int i = 0; i < 12; ++i) q.push_back(s * u(rng));
        Curve nubs = window(CurveKind::BSpline, q);
        nubs.degree = 3;
        nubs.knots = {0, 0.6, 1.0, 2.2, 3.0, 3.5, 4.8, 5.4, 6.5, 7.0};
        const KnotRefinementCheck k = knot_refinement_check(nubs, 101);
        CHECK(k.inserted == 3);
        CHECK(k.points_before == 6);
        CHECK(k.points_after == 9);
        CHECK(k.error <= 1e-13 * 8 * extent_of(q));
    }
    Curve h;
    h.kind = CurveKind::Hermite;
    h.points = {0, 0, 1, 0, 2, 0};
    h.tangents = {1, 0, 1, 0, 1, 0};
    expect_error([&] { split_check({bezier({0, 0, 1, 1}), h}); }, "invalid-argument", "segment 1");
    expect_error([] { split_check({}); }, "invalid-argument", "at least one segment");
}

namespace {
// a random 4x4 net of 3D entries, scaled by s and moved by t
std::vector<double> random_net(std::mt19937_64& rng, double s, double t) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> net(48);
    for (double& x : net) x = s * u(rng) + t;
    return net;
}
// B's row r := A's row q (4 entries of 3 numbers)
void copy_row(const std::vector<double>& a, int q, std::vector<double>& b, int r) {
    std::copy(a.begin() + 12 * q, a.begin() + 12 * (q + 1), b.begin() + 12 * r);
}
} // namespace

TEST_CASE("patch corners: every corner is its net entry (lecture 002), at any scale and far from the origin",
          "[curves][comparison][patch]") {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        const double s = std::pow(10.0, -6 + 12 * u(rng));
        const double t = s * std::pow(10.0, 9 * u(rng)); // up to 1e9 patch sizes away
        for (BasisKind kind : {BasisKind::Bezier, BasisKind::Hermite}) {
            const PatchCornerCheck c = patch_corner_check(kind, random_net(rng, s, t));
            INFO("trial " << trial << " scale " << s << " offset " << t);
            for (int k = 0; k < 4; ++k) CHECK(c.interpolated[k]);
        }
    }
    const std::vector<double> net(48, 1.0);
    CHECK(patch_corner_check(BasisKind::Bezier, net).entry == std::array<int32_t, 4>{0, 3, 12, 15});
    CHECK(patch_corner_check(BasisKind::Hermite, net).entry == std::array<int32_t, 4>{0, 1, 4, 5});
    expect_error([] { patch_corner_check(BasisKind::Bezier, std::vector<double>(45, 0.0)); }, "wrong-point-count", "");
}

TEST_CASE("patch join: shared boundary rows give C0, matched legs C1; a shift d of B's boundary row is a gap |d| and 3|d|",
          "[curves][comparison][patch]") {
    std::mt19937_64 rng(37);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 1000; ++trial) {
        const double s = std::pow(10.0, 6 * u(rng));
        const double t = s * std::pow(10.0, 6 * (0.5 + 0.5 * u(rng))); // up to 1e6 patch sizes away
        const std::vector<double> a = random_net(rng, s, t);
        // Bezier: C0 shares row 3 of A as row 0 of B; C1 also sets q1j = 2 p3j - p2j.
        std::vector<double> b = random_net(rng, s, t);
        copy_row(a, 3, b, 0);
        PatchJoinCheck j = patch_join_check(BasisKind::Bezier, a, b, 9);
        INFO("trial " << trial << " scale " << s << " offset " << t);
        CHECK(j.c0);
        CHECK_FALSE(j.c1);
        for (int k = 0; k < 12; ++k) b[12 + k] = 2 * a[36 + k] - a[24 + k];
        j = patch_join_check(BasisKind::Bezier, a, b, 9);
        CHECK(j.c1);
        // shift B's row 0 by d: the edge moves by d (partition of unity), p_u = 3 (q1 - q0) by -3d
        const double d[3] = {s * 1e-6 * (1.5 + 0.5 * u(rng)), s * 1e-6 * u(rng), s * 1e-6 * u(rng)}; // a gap of 1e-6 sizes
        for (int e = 0; e < 4; ++e) for (int k = 0; k < 3; ++k) b[3 * e + k] += d[k];
        j = patch_join_check(BasisKind::Bezier, a, b, 9);
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        CHECK_FALSE(j.c0);
        // rounding of coordinates up to 1e6 s: about 1e-10 s, here 1e-4 of the gap
        CHECK(j.position_gap == Approx(len).epsilon(1e-3));
        CHECK(j.du_gap == Approx(3 * len).epsilon(1e-3));
        // Hermite: rows [p(0,.), p(1,.), p_u(0,.), p_u(1,.)]; C0 shares p(1,.) as p(0,.), C1 also p_u
        std::vector<double> hb = random_net(rng, s, t);
        copy_row(a, 1, hb, 0);
        CHECK(patch_join_check(BasisKind::Hermite, a, hb, 9).c0);
        CHECK_FALSE(patch_join_check(BasisKind::Hermite, a, hb, 9).c1);
        copy_row(a, 3, hb, 2);
        CHECK(patch_join_check(BasisKind::Hermite, a, hb, 9).c1);
    }
}

TEST_CASE("tangents from the points: central differences are exact for points on a parabola; chords at the ends",
          "[curves][comparison][tangents]") {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 1000; ++trial) {
        // P_i = a + b i + c i^2: (P_i+1 - P_i-1)/2 = b + 2 c i = P'(i); P_1 - P_0 = b + c
        const int n = 2 + trial % 9;
        const double a[2] = {u(rng), u(rng)}, b[2] = {u(rng), u(rng)}, c[2] = {u(rng), u(rng)};
        std::vector<double> p;
        for (int i = 0; i < n; ++i) for (int k = 0; k < 2; ++k) p.push_back(a[k] + b[k] * i + c[k] * i * i);
        const std::vector<double> t = catmull_rom_tangents(p, 2);
        for (int k = 0; k < 2; ++k) {
            CHECK(t[k] == Approx(b[k] + c[k]).margin(1e-13));
            CHECK(t[2 * (n - 1) + k] == Approx(b[k] + c[k] * (2 * n - 3)).margin(1e-12));
            for (int i = 1; i + 1 < n; ++i) CHECK(t[2 * i + k] == Approx(b[k] + 2 * c[k] * i).margin(1e-12));
        }
    }
    expect_error([] { catmull_rom_tangents({1, 2}, 2); }, "too-few-points", "at least 2");
    expect_error([] { catmull_rom_tangents({1, 2, NAN, 0}, 2); }, "non-finite-input", "point 1");
}

TEST_CASE("patch basis conversion: lecture 002's Hermite entries of a Bezier net, the same surface, and back again",
          "[curves][comparison][patch]") {
    std::mt19937_64 rng(43);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto e = [](int i, int j) { return 3 * (4 * i + j); };
    for (int trial = 0; trial < 1000; ++trial) {
        const double s = std::pow(10.0, 6 * u(rng));
        const double t = s * std::pow(10.0, 3 * (1 + u(rng)));
        const std::vector<double> p = random_net(rng, s, t);
        const std::vector<double> h = convert_patch_basis(p, BasisKind::Bezier, BasisKind::Hermite);
        double size = 0;
        for (double x : p) size = std::max(size, std::abs(x));
        INFO("trial " << trial << " scale " << s << " offset " << t);
        for (int k = 0; k < 3; ++k) {
            // corners in the top-left block
            CHECK(h[e(0, 0) + k] == Approx(p[e(0, 0) + k]).margin(1e-14 * size));
            CHECK(h[e(0, 1) + k] == Approx(p[e(0, 3) + k]).margin(1e-14 * size));
            CHECK(h[e(1, 0) + k] == Approx(p[e(3, 0) + k]).margin(1e-14 * size));
            CHECK(h[e(1, 1) + k] == Approx(p[e(3, 3) + k]).margin(1e-14 * size));
            // p_u(0,0) = 3 (p10 - p00), p_v(0,0) = 3 (p01 - p00), p_uv(0,0) = 9 (p00 - p01 - p10 + p11)
            CHECK(h[e(2, 0) + k] == Approx(3 * (p[e(1, 0) + k] - p[e(0, 0) + k])).margin(1e-13 * size));
            CHECK(h[e(0, 2) + k] == Approx(3 * (p[e(0, 1) + k] - p[e(0, 0) + k])).margin(1e-13 * size));
            CHECK(h[e(2, 2) + k] == Approx(9 * (p[e(0, 0) + k] - p[e(0, 1) + k] - p[e(1, 0) + k] + p[e(1, 1) + k])).margin(1e-12 * size));
        }
        const PatchSamples a = sample_patch(BasisKind::Bezier, p, 5, 5);
        const PatchSamples b = sample_patch(BasisKind::Hermite, h, 5, 5);
        CHECK(max_distance(a.positions, b.positions, 3).distance <= 1e-13 * size);
        const std::vector<double> back = convert_patch_basis(h, BasisKind::Hermite, BasisKind::Bezier);
        CHECK(max_distance(back, p, 3).distance <= 1e-13 * size);
    }
    expect_error([] { convert_patch_basis(std::vector<double>(48, 0.0), BasisKind::BSpline, BasisKind::Bezier); }, "unknown-basis", "hermite and bezier");
    expect_error([] { convert_patch_basis(std::vector<double>(47, 0.0), BasisKind::Hermite, BasisKind::Bezier); }, "wrong-point-count", "48");
}

TEST_CASE("patch basis conversion: an entry that is zero exactly is stored as 0 at every scale", "[curves][comparison][patch]") {
    // A bilinear Bezier net p_ij = o + (i/3) a + (j/3) b is a flat parallelogram: its Hermite
    // twists p_uv are 0 exactly, and so is every component along a x b. The conversion's
    // rounding leaves ulp-sized values there; they are stored as 0.
    std::mt19937_64 rng(47);
    std::uniform_real_distribution<double> u(-1, 1);
    int rounded = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const double s = std::pow(10.0, 6 * u(rng));
        const double o[3] = {s * u(rng), s * u(rng), 0}, a[3] = {s * u(rng), s * u(rng), 0}, b[3] = {s * u(rng), s * u(rng), 0};
        std::vector<double> p;
        for (int i = 0; i < 4; ++i) for (int j = 0; j < 4; ++j) for (int k = 0; k < 3; ++k) p.push_back(o[k] + a[k] * i / 3 + b[k] * j / 3);
        const std::vector<double> h = convert_patch_basis(p, BasisKind::Bezier, BasisKind::Hermite);
        INFO("trial " << trial << " scale " << s);
        for (int c : {10, 11, 14, 15}) for (int k = 0; k < 3; ++k) CHECK(h[3 * c + k] == 0); // the twist block
        for (int e = 0; e < 16; ++e) CHECK(h[3 * e + 2] == 0);
        // the unsnapped value, recomputed: 9 (p00 - p01 - p10 + p11) in floating point
        for (int k = 0; k < 2; ++k) rounded += (p[k] - p[3 + k] - p[12 + k] + p[15 + k]) != 0;
    }
    INFO("nets whose twist rounds to a nonzero value before snapping: " << rounded);
    CHECK(rounded > 0); // the case the snap is for does occur
}
