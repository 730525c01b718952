// Exercise kind 5, "make the curve pass through a point": the closest point of a curve to a
// point, and the verdict relative to the size of the control polygon (scale invariant).
#include "wingspline/curves/exercise.h"

#include "exercise_text.h"
#include "messages.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wingspline::curves {

using exercise_text::fmt;
using exercise_text::vec;

namespace {

constexpr int kSamplesPerSegment = 64;   // a cubic piece turns at most twice: 64 samples find every basin
constexpr int kMaxSamples = 1 << 16;
constexpr int kNewtonStarts = 16;        // the best local minima of the samples refined
constexpr int kNewtonSteps = 60;

struct Sampler {
    const CurveEvaluator& ev;
    const std::vector<double>& x;
    int d;
    // Squared distance and D'(u)/2 = (P - x).P', D''(u)/2 = P'.P' + (P - x).P''.
    void at(double u, double& dist2, double& f, double& fp, std::vector<double>& p) const {
        double jet[9];
        ev.evaluate_all(&u, 1, 2, jet);
        dist2 = f = 0;
        fp = 0;
        for (int k = 0; k < d; ++k) {
            const double r = jet[k] - x[k];
            p[k] = jet[k];
            dist2 += r * r;
            f += r * jet[d + k];
            fp += jet[d + k] * jet[d + k] + r * jet[2 * d + k];
        }
    }
};

// The sample parameters: kSamplesPerSegment on every polynomial piece (so a short knot span is
// sampled as densely as a long one), the domain ends included.
std::vector<double> sample_params(const Curve& curve, const Domain& dom) {
    const int segments = segment_count(curve);
    std::vector<double> u;
    if (segments * kSamplesPerSegment > kMaxSamples) {
        for (int j = 0; j <= kMaxSamples; ++j) u.push_back(dom.start + (dom.end - dom.start) * j / kMaxSamples);
    } else {
        for (int s = 0; s < segments; ++s) {
            const SegmentMatrices m = segment_matrices(curve, s);
            for (int j = 0; j < kSamplesPerSegment; ++j) u.push_back(m.start + (m.end - m.start) * j / kSamplesPerSegment);
        }
        u.push_back(dom.end);
    }
    for (double& v : u) v = std::clamp(v, dom.start, dom.end);
    return u;
}

} // namespace

double control_polygon_diameter(const Curve& curve) {
    validate(curve);
    const int d = curve.dim, K = control_point_count(curve);
    double best = 0;
    for (int i = 0; i < K; ++i)
        for (int j = i + 1; j < K; ++j) {
            double s = 0;
            for (int k = 0; k < d; ++k) {
                const double g = curve.points[i * d + k] - curve.points[j * d + k];
                s += g * g;
            }
            best = std::max(best, s);
        }
    return std::sqrt(best);
}

ClosestPoint closest_point(const Curve& curve, const std::vector<double>& x) {
    validate(curve);
    const int d = curve.dim;
    require(static_cast<int>(x.size()) == d, "invalid-argument",
            "the point has " + std::to_string(x.size()) + " coordinates, but the curve is " + std::to_string(d) + "D");
    for (int k = 0; k < d; ++k)
        require(std::isfinite(x[k]), "non-finite-input", "point[" + std::to_string(k) + "] is not a finite number");
    const CurveEvaluator ev(curve);
    const Domain dom = ev.domain();
    const Sampler s{ev, x, d};
    const std::vector<double> u = sample_params(curve, dom);
    const std::size_t n = u.size();
    std::vector<double> dist2(n);
    std::vector<double> p(d);
    double f = 0, fp = 0;
    for (std::size_t j = 0; j < n; ++j) s.at(u[j], dist2[j], f, fp, p);
    // Local minima of the samples (ends included), best first.
    std::vector<std::size_t> minima;
    for (std::size_t j = 0; j < n; ++j)
        if ((j == 0 || dist2[j] <= dist2[j - 1]) && (j + 1 == n || dist2[j] <= dist2[j + 1])) minima.push_back(j);
    std::sort(minima.begin(), minima.end(), [&](std::size_t a, std::size_t b) { return dist2[a] < dist2[b]; });
    if (minima.size() > kNewtonStarts) minima.resize(kNewtonStarts);

    ClosestPoint best;
    best.point.assign(d, 0.0);
    double best2 = std::numeric_limits<double>::infinity();
    auto keep = [&](double uu, double dd, const std::vector<double>& pp) {
        if (dd < best2) best2 = dd, best.u = uu, best.point = pp;
    };
    for (std::size_t j : minima) {
        // Newton's method on D'(u) = 0, kept inside the bracket of the neighbouring samples
        // (a step that leaves it, or a non-convex spot, bisects instead).
        double lo = u[j == 0 ? 0 : j - 1], hi = u[j + 1 == n ? j : j + 1], uu = u[j];
        for (int step = 0; step < kNewtonSteps; ++step) {
            double dd = 0;
            s.at(uu, dd, f, fp, p);
            keep(uu, dd, p);
            if (f > 0) hi = uu;
            else lo = uu;
            double next = fp > 0 ? uu - f / fp : (lo + hi) / 2;
            if (!(next >= lo && next <= hi)) next = (lo + hi) / 2;
            if (next == uu || hi - lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(uu))) break;
            uu = next;
        }
    }
    best.distance = std::sqrt(best2);
    return best;
}

PropertyCheck check_passes_through(const Curve& curve, const std::vector<double>& point, double tolerance) {
    require(std::isfinite(tolerance) && tolerance > 0 && tolerance < 1, "invalid-argument",
            "tolerance is relative to the size of the control polygon and must be above 0 and below 1, not " + detail::num(tolerance));
    const double size = control_polygon_diameter(curve);
    require(size > 0, "degenerate-curve",
            "all control points are at the same place, so the curve is a single point; move a point away first");
    const ClosestPoint c = closest_point(curve, point);
    PropertyCheck r;
    r.distance = c.distance;
    r.size = size;
    r.relative_distance = c.distance / size;
    r.u = c.u;
    r.closest = c.point;
    r.holds = c.distance <= tolerance * size;
    const int d = curve.dim;
    const std::string where = vec(point.data(), d);
    const std::string at = " (at u = " + fmt(c.u) + ", P(u) = " + vec(c.point.data(), d) + ")";
    const std::string rel = fmt(r.relative_distance) + " of the control polygon's size " + fmt(size);
    r.reason = r.holds ? "the curve passes within " + fmt(c.distance) + " of " + where + at + ": " + rel +
                             ", within the tolerance " + fmt(tolerance)
                       : "the curve comes no closer than " + fmt(c.distance) + " to " + where + at + ": " + rel +
                             ", more than the tolerance " + fmt(tolerance) + "; move control points so the curve passes closer";
    return r;
}

} // namespace wingspline::curves
