#include "wingspline/curves/comparison.h"

#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/bezier.h"
#include "wingspline/curves/bspline_ops.h"
#include "wingspline/curves/patch.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>

namespace wingspline::curves {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string fixed2(double x) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.2f", x);
    return buf;
}

void require_finite(const std::vector<double>& v, int dim, const char* what) {
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i])) {
            throw Error("non-finite-input", std::string(what) + " has a value that is not a finite number at point " +
                                                std::to_string(i / dim) + ", component " + std::to_string(i % dim));
        }
    }
}

// The larger side of the bounding box of points (stride dim), accumulated into lo/hi.
void grow_box(const std::vector<double>& p, int dim, std::vector<double>& lo, std::vector<double>& hi) {
    for (std::size_t i = 0; i + dim <= p.size(); i += dim) {
        for (int k = 0; k < dim; ++k) {
            lo[k] = std::min(lo[k], p[i + k]);
            hi[k] = std::max(hi[k], p[i + k]);
        }
    }
}
double box_extent(const std::vector<double>& lo, const std::vector<double>& hi) {
    double e = 0;
    for (std::size_t k = 0; k < lo.size(); ++k) if (hi[k] >= lo[k]) e = std::max(e, hi[k] - lo[k]);
    return e;
}

double distance(const double* a, const double* b, int dim) {
    double s = 0;
    for (int k = 0; k < dim; ++k) s = std::hypot(s, a[k] - b[k]);
    return s;
}

void require_samples(int samples) {
    require(samples >= 2 && samples <= 1000000, "invalid-argument",
            "the number of samples must be a whole number from 2 to 1000000, not " + std::to_string(samples));
}

// The four geometry rows of one cubic segment in the Bezier basis (lecture 002: q = M_B^-1 M G).
std::vector<double> bezier_rows(const Curve& c, std::size_t index) {
    const auto which = [&] { return "segment " + std::to_string(index); };
    if (c.kind == CurveKind::Bezier && c.weights.empty()) return c.points;
    const std::size_t four = 4 * static_cast<std::size_t>(c.dim);
    if (c.kind == CurveKind::Hermite) {
        if (c.points.size() != 2 * static_cast<std::size_t>(c.dim) || c.tangents.size() != c.points.size())
            throw Error("invalid-argument", which() + ": a Hermite segment has 2 points and 2 tangents");
        std::vector<double> g(c.points);
        g.insert(g.end(), c.tangents.begin(), c.tangents.end());
        return convert_basis(g, c.dim, BasisKind::Hermite, BasisKind::Bezier);
    }
    const bool window = (c.kind == CurveKind::BSpline && c.knots.empty() && (c.degree == 0 || c.degree == 3)) ||
                        c.kind == CurveKind::CatmullRom;
    if (!window || c.points.size() != four)
        throw Error("invalid-argument", which() + ": the split check takes Bezier curves and single cubic Hermite, uniform B-spline or Catmull-Rom segments");
    return convert_basis(c.points, c.dim, c.kind == CurveKind::CatmullRom ? BasisKind::CatmullRom : BasisKind::BSpline,
                         BasisKind::Bezier);
}

} // namespace

// ---------------------------------------------------------------- convex hull
ConvexHull convex_hull(const std::vector<double>& points) {
    require(points.size() % 2 == 0, "invalid-points",
            "points has " + std::to_string(points.size()) + " numbers, which is not a multiple of dim = 2");
    require_finite(points, 2, "points");
    const int32_t n = static_cast<int32_t>(points.size() / 2);
    std::vector<double> lo(2, std::numeric_limits<double>::infinity()), hi(2, -std::numeric_limits<double>::infinity());
    grow_box(points, 2, lo, hi);
    const double extent = box_extent(lo, hi);
    ConvexHull hull;
    hull.tolerance = kHullTolerance * extent * extent;
    std::vector<int32_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    const auto x = [&](int32_t i) { return points[2 * i]; };
    const auto y = [&](int32_t i) { return points[2 * i + 1]; };
    std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return x(a) < x(b) || (x(a) == x(b) && y(a) < y(b)); });
    // Exact repeats: the first index stands for all of them.
    order.erase(std::unique(order.begin(), order.end(), [&](int32_t a, int32_t b) { return x(a) == x(b) && y(a) == y(b); }),
                order.end());
    if (order.size() < 3) {
        hull.indices = order;
        return hull;
    }
    const auto cross = [&](int32_t o, int32_t a, int32_t b) {
        return (x(a) - x(o)) * (y(b) - y(o)) - (y(a) - y(o)) * (x(b) - x(o));
    };
    // Keep only strict left turns: a turn within the tolerance is a straight line.
    const auto chain = [&](auto first, auto last) {
        std::vector<int32_t> c;
        for (auto it = first; it != last; ++it) {
            while (c.size() >= 2 && cross(c[c.size() - 2], c.back(), *it) <= hull.tolerance) c.pop_back();
            c.push_back(*it);
        }
        c.pop_back();
        return c;
    };
    std::vector<int32_t> lower = chain(order.begin(), order.end());
    const std::vector<int32_t> upper = chain(order.rbegin(), order.rend());
    lower.insert(lower.end(), upper.begin(), upper.end());
    hull.indices = lower;
    return hull;
}

// ---------------------------------------------------------------- maps of the plane
PlaneMap plane_map(bool perspective, double angle_degrees, double scale, double shear, double tx, double ty,
                   double px, double py) {
    const double values[] = {angle_degrees, scale, shear, tx, ty, px, py};
    const char* names[] = {"angle", "scale", "shear", "tx", "ty", "px", "py"};
    for (int i = 0; i < 7; ++i) {
        require(std::isfinite(values[i]), "non-finite-input",
                std::string("the map's ") + names[i] + " is not a finite number");
    }
    const double r = angle_degrees * kPi / 180;
    const double cs = std::cos(r) * scale;
    const double sn = std::sin(r) * scale;
    PlaneMap m;
    m.a = cs;
    m.b = cs * shear - sn;
    m.c = sn;
    m.d = sn * shear + cs;
    m.tx = tx;
    m.ty = ty;
    m.px = perspective ? px : 0;
    m.py = perspective ? py : 0;
    return m;
}

MappedPoints map_points(const std::vector<double>& points, int dim, const PlaneMap& m, const std::string& what) {
    require(dim == 2, "invalid-dimension", "maps of the plane take points of dimension 2, not " + std::to_string(dim));
    require(points.size() % 2 == 0, "invalid-points",
            "points has " + std::to_string(points.size()) + " numbers, which is not a multiple of dim = 2");
    require_finite(points, 2, "points");
    MappedPoints out;
    const std::size_t n = points.size() / 2;
    out.points.resize(2 * n);
    out.w.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = points[2 * i], y = points[2 * i + 1];
        const double w = m.px * x + m.py * y + 1;
        // Built only for a message: a string per point would cost more than the map itself.
        const auto where = [&] { return what + std::to_string(i) + " (" + fixed2(x) + ", " + fixed2(y) + ")"; };
        if (!(w > 0)) {
            throw Error("perspective-behind-eye", "the perspective map sends " + where() + " behind the eye (w = " + fixed2(w) +
                                                      " ≤ 0); use smaller perspective coefficients");
        }
        const double X = (m.a * x + m.b * y + m.tx) / w;
        const double Y = (m.c * x + m.d * y + m.ty) / w;
        if (!std::isfinite(X) || !std::isfinite(Y)) {
            throw Error("non-finite-result", "the map sends " + where() + " beyond the largest number (w = " + std::to_string(w) +
                                                 " is almost 0: the point is almost level with the eye); use smaller perspective coefficients");
        }
        out.points[2 * i] = X;
        out.points[2 * i + 1] = Y;
        out.w[i] = w;
    }
    return out;
}

// ---------------------------------------------------------------- distances
MaxDistance max_distance(const std::vector<double>& a, const std::vector<double>& b, int dim) {
    require(dim >= 1 && dim <= 3, "invalid-dimension", "dim must be 1, 2 or 3, not " + std::to_string(dim));
    require(a.size() == b.size() && a.size() % dim == 0, "invalid-argument",
            "the two point lists must hold the same number of points of dimension " + std::to_string(dim) + " (" +
                std::to_string(a.size()) + " and " + std::to_string(b.size()) + " numbers)");
    require_finite(a, dim, "the first point list");
    require_finite(b, dim, "the second point list");
    MaxDistance r;
    for (std::size_t j = 0; j < a.size(); j += dim) {
        const double d = distance(&a[j], &b[j], dim);
        if (r.index < 0 || d > r.distance) {
            r.distance = d;
            r.index = static_cast<int32_t>(j / dim);
        }
    }
    return r;
}

std::vector<double> domain_params(const Curve& curve, int n) {
    require_samples(n);
    const Domain d = CurveEvaluator(curve).domain();
    std::vector<double> u(n);
    for (int j = 0; j < n; ++j) u[j] = d.start + ((d.end - d.start) * j) / (n - 1);
    u[n - 1] = d.end;
    return u;
}

// ---------------------------------------------------------------- the table's measurements
BlendingWeightCheck blending_weight_check(const std::vector<Curve>& segments, int samples) {
    require(!segments.empty(), "invalid-argument", "the weight check needs at least one segment");
    require_samples(samples);
    BlendingWeightCheck r;
    r.min_weight = std::numeric_limits<double>::infinity();
    for (const Curve& c : segments) {
        const std::vector<double> params = domain_params(c, samples);
        const BlendingValues b = blending_functions(c, params, 0);
        // Hermite: items 0..K-1 are points, K..2K-1 tangent vectors (curve.h).
        const int points = c.kind == CurveKind::Hermite ? b.count / 2 : b.count;
        for (int j = 0; j < samples; ++j) {
            double sum = 0;
            for (int i = 0; i < b.count; ++i) {
                const double w = b.values[static_cast<std::size_t>(b.count) * j + i];
                if (i >= points) {
                    r.tangent_weight = std::max(r.tangent_weight, std::abs(w));
                    continue;
                }
                sum += w;
                if (w < r.min_weight) {
                    r.min_weight = w;
                    r.min_weight_at = params[j];
                }
            }
            r.sum_error = std::max(r.sum_error, std::abs(sum - 1));
        }
    }
    r.weights_points = r.tangent_weight <= kWeightTolerance;
    r.convex_hull = r.weights_points && r.min_weight >= -kWeightTolerance && r.sum_error <= kWeightTolerance;
    return r;
}

PointCurveDistances point_curve_distances(const std::vector<double>& points, int dim, const std::vector<Curve>& segments,
                                          int samples) {
    require(dim == 2 || dim == 3, "invalid-dimension", "dim must be 2 or 3, not " + std::to_string(dim));
    require(points.size() % dim == 0, "invalid-points",
            "points has " + std::to_string(points.size()) + " numbers, which is not a multiple of dim = " + std::to_string(dim));
    require_finite(points, dim, "points");
    require(!segments.empty(), "invalid-argument", "the distance check needs at least one segment");
    std::vector<double> lo(dim, std::numeric_limits<double>::infinity()), hi(dim, -std::numeric_limits<double>::infinity());
    grow_box(points, dim, lo, hi);
    std::vector<std::vector<double>> sampled;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        require(segments[s].dim == dim, "invalid-dimension",
                "segment " + std::to_string(s) + " has dimension " + std::to_string(segments[s].dim) + ", the points " + std::to_string(dim));
        sampled.push_back(evaluate_curve(segments[s], domain_params(segments[s], samples)));
        grow_box(sampled.back(), dim, lo, hi);
    }
    PointCurveDistances r;
    r.tolerance = kInterpolationTolerance * box_extent(lo, hi);
    const std::size_t n = points.size() / dim;
    r.distances.assign(n, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < n; ++i) {
        for (const auto& s : sampled) {
            for (std::size_t j = 0; j < s.size(); j += dim) r.distances[i] = std::min(r.distances[i], distance(&points[dim * i], &s[j], dim));
        }
        const auto id = static_cast<int32_t>(i);
        if (r.distances[i] <= r.tolerance) r.interpolated.push_back(id);
        else if (r.nearest_missed < 0 || r.distances[i] < r.distances[r.nearest_missed]) r.nearest_missed = id;
        if (r.farthest < 0 || r.distances[i] > r.distances[r.farthest]) r.farthest = id;
    }
    return r;
}

SplitCheck split_check(const std::vector<Curve>& segments) {
    require(!segments.empty(), "invalid-argument", "the split check needs at least one segment");
    static const std::vector<double> quarter = {0, 0.25, 0.5, 0.75, 1};
    SplitCheck r;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const Curve& c = segments[s];
        const BezierSplit halves = subdivide_bezier(bezier_rows(c, s), c.dim, 0.5);
        const Domain d = CurveEvaluator(c).domain();
        std::vector<double> at;
        for (double q : quarter) at.push_back(d.start + q / 2 * (d.end - d.start));
        for (double q : quarter) at.push_back(d.start + (0.5 + q / 2) * (d.end - d.start));
        const std::vector<double> original = evaluate_curve(c, at);
        Curve half;
        half.kind = CurveKind::Bezier;
        half.dim = c.dim;
        half.points = halves.left;
        std::vector<double> both = evaluate_curve(half, quarter);
        half.points = halves.right;
        const std::vector<double> right = evaluate_curve(half, quarter);
        both.insert(both.end(), right.begin(), right.end());
        r.error = std::max(r.error, max_distance(both, original, c.dim).distance);
        r.segments += 1;
    }
    return r;
}

KnotRefinementCheck knot_refinement_check(const Curve& curve, int samples) {
    const std::vector<double> params = domain_params(curve, samples);
    KnotRefinementCheck r;
    r.points_before = control_point_count(curve);
    Curve refined = curve;
    for (const BezierSegment& span : to_bezier_segments(curve)) {
        refined = insert_knot(refined, (span.start + span.end) / 2).curve;
        r.inserted += 1;
    }
    r.points_after = control_point_count(refined);
    r.error = max_distance(evaluate_curve(refined, params), evaluate_curve(curve, params), curve.dim).distance;
    return r;
}

std::vector<double> catmull_rom_tangents(const std::vector<double>& points, int dim) {
    require(dim == 2 || dim == 3, "invalid-dimension", "dim must be 2 or 3, not " + std::to_string(dim));
    require(points.size() % dim == 0, "invalid-points",
            "points has " + std::to_string(points.size()) + " numbers, which is not a multiple of dim = " + std::to_string(dim));
    require_finite(points, dim, "points");
    const std::size_t n = points.size() / dim;
    require(n >= 2, "too-few-points", "tangents from the points need at least 2 points, not " + std::to_string(n));
    std::vector<double> t(points.size());
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t before = i == 0 ? 0 : i - 1, after = i + 1 == n ? n - 1 : i + 1;
        const double half = (i == 0 || i + 1 == n) ? 1.0 : 0.5;
        for (int k = 0; k < dim; ++k) t[dim * i + k] = half * (points[dim * after + k] - points[dim * before + k]);
    }
    return t;
}

// ---------------------------------------------------------------- bicubic patches
namespace {
// relative * extent + the evaluation's rounding (kPatchRounding times the largest |coordinate|)
double surface_tolerance(const std::vector<double>& positions, double relative) {
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -std::numeric_limits<double>::infinity());
    grow_box(positions, 3, lo, hi);
    double magnitude = 0;
    for (double x : positions) magnitude = std::max(magnitude, std::abs(x));
    return relative * box_extent(lo, hi) + kPatchRounding * magnitude;
}
std::vector<double> row_of(const std::vector<double>& values, int nv, int i) {
    return std::vector<double>(values.begin() + 3 * nv * i, values.begin() + 3 * nv * (i + 1));
}
} // namespace

PatchCornerCheck patch_corner_check(BasisKind kind, const std::vector<double>& net) {
    const PatchSamples s = sample_patch(kind, net, 2, 2); // checks kind, size and values
    PatchCornerCheck r;
    r.entry = kind == BasisKind::Bezier ? std::array<int32_t, 4>{0, 3, 12, 15} : std::array<int32_t, 4>{0, 1, 4, 5};
    r.tolerance = surface_tolerance(s.positions, kCornerTolerance);
    for (int c = 0; c < 4; ++c) {
        r.distance[c] = distance(&s.positions[3 * c], &net[3 * r.entry[c]], 3);
        r.interpolated[c] = r.distance[c] <= r.tolerance;
    }
    return r;
}

PatchJoinCheck patch_join_check(BasisKind kind, const std::vector<double>& a, const std::vector<double>& b, int samples) {
    require_samples(samples);
    const PatchSamples A = sample_patch(kind, a, samples, samples);
    const PatchSamples B = sample_patch(kind, b, samples, samples);
    PatchJoinCheck r;
    std::vector<double> both = A.positions;
    both.insert(both.end(), B.positions.begin(), B.positions.end());
    r.tolerance = surface_tolerance(both, kJoinTolerance);
    r.position_gap = max_distance(row_of(A.positions, samples, samples - 1), row_of(B.positions, samples, 0), 3).distance;
    r.du_gap = max_distance(row_of(A.du, samples, samples - 1), row_of(B.du, samples, 0), 3).distance;
    r.c0 = r.position_gap <= r.tolerance;
    r.c1 = r.c0 && r.du_gap <= r.tolerance;
    return r;
}

std::vector<double> convert_patch_basis(const std::vector<double>& net, BasisKind from, BasisKind to) {
    require((from == BasisKind::Bezier || from == BasisKind::Hermite) && (to == BasisKind::Bezier || to == BasisKind::Hermite),
            "unknown-basis", "patches are converted between the hermite and bezier bases");
    require(net.size() == 48, "wrong-point-count",
            "a bicubic patch needs a 4 x 4 geometry matrix of 3D vectors (48 numbers), not " + std::to_string(net.size()));
    require_finite(net, 3, "the net");
    const auto at = [](int i, int j) { return 3 * (4 * i + j); };
    std::vector<double> cols(48), out(48);
    for (int j = 0; j < 4; ++j) { // down column j (along u)
        std::vector<double> g;
        for (int i = 0; i < 4; ++i) g.insert(g.end(), net.begin() + at(i, j), net.begin() + at(i, j) + 3);
        const std::vector<double> q = convert_basis(g, 3, from, to);
        for (int i = 0; i < 4; ++i) std::copy(q.begin() + 3 * i, q.begin() + 3 * i + 3, cols.begin() + at(i, j));
    }
    for (int i = 0; i < 4; ++i) { // along row i (along v)
        const std::vector<double> q = convert_basis(std::vector<double>(cols.begin() + at(i, 0), cols.begin() + at(i, 0) + 12), 3, from, to);
        std::copy(q.begin(), q.end(), out.begin() + at(i, 0));
    }
    double size = 0;
    for (double x : net) size = std::max(size, std::abs(x));
    for (double& x : out) if (std::abs(x) < kNetSnap * size) x = 0;
    return out;
}

} // namespace wingspline::curves
