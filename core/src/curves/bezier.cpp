#include "wingspline/curves/bezier.h"

#include "messages.h"
#include "wingspline/curves/curve.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>

namespace wingspline::curves {

namespace {

double binomial(int n, int k) {
    if (k < 0 || k > n) return 0;
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

// Validates a Bezier control polygon (and weights) with the same rules as a 'bezier' curve.
int checked_degree(const std::vector<double>& points, int dim, const std::vector<double>& weights) {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.dim = dim;
    c.points = points;
    c.weights = weights;
    validate(c);
    return control_point_count(c) - 1;
}

void check_t(double t) {
    // Messages are built only on failure (this runs once per evaluated parameter).
    if (!std::isfinite(t))
        throw Error("non-finite-input", "the parameter t is " + detail::num(t) + ", not a finite number");
    if (!(t >= -kParameterSlack && t <= 1 + kParameterSlack))
        throw Error("parameter-out-of-range", "the parameter t = " + detail::num(t) + " is outside the Bezier domain [0, 1]");
}

} // namespace

std::vector<double> bernstein(int n, double t) {
    std::vector<double> b(static_cast<std::size_t>(n + 1));
    for (int i = 0; i <= n; ++i) b[i] = binomial(n, i) * std::pow(t, i) * std::pow(1 - t, n - i);
    return b;
}

DeCasteljauSteps de_casteljau(const std::vector<double>& points, int dim, double t, const std::vector<double>& weights) {
    const int n = checked_degree(points, dim, weights);
    check_t(t);
    t = std::fmin(1.0, std::fmax(0.0, t));
    const bool rational = !weights.empty();
    const int hd = rational ? dim + 1 : dim;
    std::vector<double> level = to_homogeneous(points, dim, weights);
    DeCasteljauSteps r;
    r.degree = n;
    r.dim = dim;
    for (int step = 0; step <= n; ++step) {
        if (rational) {
            std::vector<double> p, w;
            from_homogeneous(level, dim, weight_shift(weights), p, &w);
            r.levels.push_back(p);
            r.level_weights.push_back(w);
        } else {
            r.levels.push_back(level);
        }
        if (step == n) break;
        const int count = n - step; // points of the next level
        std::vector<double> next(static_cast<std::size_t>(count * hd));
        for (int i = 0; i < count; ++i)
            for (int k = 0; k < hd; ++k)
                next[i * hd + k] = (1 - t) * level[i * hd + k] + t * level[(i + 1) * hd + k];
        level = std::move(next);
    }
    return r;
}

BezierSplit subdivide_bezier(const std::vector<double>& points, int dim, double t, const std::vector<double>& weights) {
    const DeCasteljauSteps steps = de_casteljau(points, dim, t, weights);
    const int n = steps.degree;
    BezierSplit s;
    for (int r = 0; r <= n; ++r) {
        for (int k = 0; k < dim; ++k) s.left.push_back(steps.levels[r][k]);
        if (!weights.empty()) s.left_weights.push_back(steps.level_weights[r][0]);
    }
    for (int r = n; r >= 0; --r) {
        const auto& level = steps.levels[r];
        const int last = n - r;
        for (int k = 0; k < dim; ++k) s.right.push_back(level[last * dim + k]);
        if (!weights.empty()) s.right_weights.push_back(steps.level_weights[r][last]);
    }
    return s;
}

void bezier_subdivision_matrices(int n, double t, std::vector<double>& SL, std::vector<double>& SR) {
    require(n >= 1 && n <= kMaxDegree, "degree-out-of-range",
            "the Bezier degree must be from 1 to " + std::to_string(kMaxDegree) + ", not " + std::to_string(n));
    check_t(t);
    const int m = n + 1;
    SL.assign(static_cast<std::size_t>(m * m), 0.0);
    SR.assign(static_cast<std::size_t>(m * m), 0.0);
    // Left point i is the first point of level i: sum_j B_j^i(t) P_j. Right point i is the
    // last point of level n-i: sum_j B_j^(n-i)(t) P_(i+j).
    for (int i = 0; i <= n; ++i) {
        const auto bl = bernstein(i, t);
        for (int j = 0; j <= i; ++j) SL[i * m + j] = bl[j];
        const auto br = bernstein(n - i, t);
        for (int j = 0; j <= n - i; ++j) SR[i * m + i + j] = br[j];
    }
}

ElevatedBezier elevate_bezier(const std::vector<double>& points, int dim, const std::vector<double>& weights) {
    const int n = checked_degree(points, dim, weights);
    require(n + 1 <= kMaxDegree, "degree-out-of-range",
            "elevating degree " + std::to_string(n) + " would exceed the largest degree " + std::to_string(kMaxDegree));
    const bool rational = !weights.empty();
    const int hd = rational ? dim + 1 : dim;
    const std::vector<double> h = to_homogeneous(points, dim, weights);
    std::vector<double> q(static_cast<std::size_t>((n + 2) * hd));
    for (int i = 0; i <= n + 1; ++i) {
        const double a = static_cast<double>(i) / (n + 1);
        for (int k = 0; k < hd; ++k) {
            const double prev = i > 0 ? h[(i - 1) * hd + k] : 0.0;
            const double cur = i <= n ? h[i * hd + k] : 0.0;
            q[i * hd + k] = a * prev + (1 - a) * cur;
        }
    }
    ElevatedBezier e;
    if (rational) from_homogeneous(q, dim, weight_shift(weights), e.points, &e.weights);
    else e.points = std::move(q);
    return e;
}

std::vector<double> bezier_power_matrix(int n) {
    const int m = n + 1;
    std::vector<double> M(static_cast<std::size_t>(m * m), 0.0);
    // B_i^n(t) = C(n,i) t^i (1-t)^(n-i) = sum_k C(n,i) C(n-i,k) (-1)^k t^(i+k).
    for (int i = 0; i <= n; ++i)
        for (int k = 0; k <= n - i; ++k) {
            const int power = i + k;
            M[(n - power) * m + i] = binomial(n, i) * binomial(n - i, k) * ((k % 2) ? -1.0 : 1.0);
        }
    return M;
}

} // namespace wingspline::curves
