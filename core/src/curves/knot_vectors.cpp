#include "wingspline/curves/knot_vectors.h"

#include "wingspline/curves/curve.h"
#include "wingspline/error.h"

#include <cmath>
#include <string>

namespace wingspline::curves {

namespace {

// x rounded to a multiple of 1 / kKnotSteps (1e-9) with the operations of JavaScript's
// Math.round(x * 1e9) / 1e9, so the knots are the ones the lesson always wrote: the nearest
// whole number of billionths, half-way values upwards.
double quantize(double x) {
    const double y = x * kKnotSteps;
    double r = std::floor(y);
    if (y - r >= 0.5) r += 1.0;
    return r / kKnotSteps;
}

void check_degree(int degree) {
    require(degree >= 1 && degree <= kMaxDegree, "degree-out-of-range",
            "the degree must be a whole number from 1 to " + std::to_string(kMaxDegree) + ", not " + std::to_string(degree));
}

void check_knot_values(const std::vector<double>& knots) {
    for (std::size_t j = 0; j < knots.size(); ++j) {
        require(std::isfinite(knots[j]), "non-finite-input", "knot " + std::to_string(j) + " is not a finite number");
        if (j > 0)
            require(knots[j - 1] <= knots[j], "decreasing-knots",
                    "knot " + std::to_string(j - 1) + " is larger than knot " + std::to_string(j) + "; knots must not decrease");
    }
}

} // namespace

std::vector<double> clamped_knots(int count, int degree) {
    check_degree(degree);
    require(count >= degree + 1, "too-few-points",
            "a B-spline of degree " + std::to_string(degree) + " needs at least " + std::to_string(degree + 1) +
                " control points, not " + std::to_string(count));
    const int interior = count - degree - 1;
    std::vector<double> t;
    t.reserve(static_cast<std::size_t>(count + degree + 1));
    for (int j = 0; j <= degree; ++j) t.push_back(0.0);
    for (int j = 1; j <= interior; ++j) t.push_back(quantize(static_cast<double>(j) / (interior + 1)));
    for (int j = 0; j <= degree; ++j) t.push_back(1.0);
    return t;
}

std::vector<double> unclamped_knots(const std::vector<double>& knots, int degree) {
    check_degree(degree);
    const int n = static_cast<int>(knots.size());
    require(n >= 2 * degree + 2, "wrong-knot-count",
            "a B-spline of degree " + std::to_string(degree) + " has at least " + std::to_string(2 * degree + 2) +
                " knots (K + p + 1 with K >= p + 1), not " + std::to_string(n));
    check_knot_values(knots);
    const double a = knots[degree];
    const double b = knots[n - 1 - degree];
    double first_step = 0;
    double last_step = 0;
    for (int i = degree + 1; i <= n - 1 - degree; ++i) {
        const double step = knots[i] - knots[i - 1];
        if (step > 0) {
            if (first_step == 0) first_step = step;
            last_step = step;
        }
    }
    const double h = first_step > 0 ? first_step : 1.0;
    const double h_end = last_step > 0 ? last_step : 1.0;
    std::vector<double> out = knots;
    for (int j = degree - 1; j >= 0; --j) out[j] = quantize(a - (degree - j) * h);
    for (int j = n - degree; j < n; ++j) out[j] = quantize(b + (j - (n - 1 - degree)) * h_end);
    return out;
}

bool is_clamped(const std::vector<double>& knots, int degree) {
    check_degree(degree);
    const int n = static_cast<int>(knots.size());
    require(n >= 2 * degree + 2, "wrong-knot-count",
            "a B-spline of degree " + std::to_string(degree) + " has at least " + std::to_string(2 * degree + 2) +
                " knots, not " + std::to_string(n));
    for (int j = 1; j <= degree; ++j)
        if (knots[j] != knots[0] || knots[n - 1 - j] != knots[n - 1]) return false;
    return true;
}

bool is_bezier_in_disguise(const std::vector<double>& knots, int degree) {
    is_clamped(knots, degree); // the same refusals (degree, knot count)
    const int p = degree;
    if (knots.size() != static_cast<std::size_t>(2 * p + 2)) return false;
    // One segment [t_p, t_p+1]; its basis functions read t_1 .. t_2p only (the outermost
    // knot on each side acts on no span of the domain), and are Bernstein's exactly when
    // t_1 = .. = t_p and t_p+1 = .. = t_2p.
    for (int j = 1; j < p; ++j)
        if (knots[j] != knots[p] || knots[p + 1 + j] != knots[p + 1]) return false;
    return knots[p] < knots[p + 1];
}

} // namespace wingspline::curves
