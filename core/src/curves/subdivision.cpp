// Chaikin and Lane-Riesenfeld cubic subdivision of a control polygon; see subdivision.h.
#include "wingspline/curves/subdivision.h"

#include "wingspline/error.h"

#include <cmath>

namespace wingspline::curves {

CurveSubdivision curve_subdivision_from_name(const std::string& name) {
    if (name == "chaikin") return CurveSubdivision::Chaikin;
    if (name == "cubic-bspline") return CurveSubdivision::CubicBSpline;
    throw Error("unknown-scheme", "unknown curve subdivision scheme '" + name.substr(0, 40) +
                                      "': use 'chaikin' (quadratic) or 'cubic-bspline'");
}

namespace {

int64_t points_after(int64_t n, CurveSubdivision scheme, bool closed) {
    if (closed) return 2 * n;
    return scheme == CurveSubdivision::Chaikin ? 2 * (n - 1) : 2 * n - 3;
}

// One step: out gets the new polygon.
void step(const std::vector<double>& p, int dim, CurveSubdivision scheme, bool closed, std::vector<double>& out) {
    const int64_t n = static_cast<int64_t>(p.size()) / dim;
    out.clear();
    out.reserve(static_cast<std::size_t>(points_after(n, scheme, closed) * dim));
    const auto at = [&](int64_t i, int k) { return p[static_cast<std::size_t>(((i % n + n) % n) * dim + k)]; };
    const auto push = [&](double a, int64_t i, double b, int64_t j, double c, int64_t l) {
        for (int k = 0; k < dim; ++k) out.push_back(a * at(i, k) + b * at(j, k) + c * at(l, k));
    };
    if (scheme == CurveSubdivision::Chaikin) {
        const int64_t legs = closed ? n : n - 1;
        for (int64_t i = 0; i < legs; ++i) {
            push(0.75, i, 0.25, i + 1, 0.0, i);
            push(0.25, i, 0.75, i + 1, 0.0, i);
        }
        return;
    }
    if (closed) {
        for (int64_t i = 0; i < n; ++i) {
            push(0.125, i - 1, 0.75, i, 0.125, i + 1);
            push(0.5, i, 0.5, i + 1, 0.0, i);
        }
        return;
    }
    push(0.5, 0, 0.5, 1, 0.0, 0);
    for (int64_t i = 1; i + 1 < n; ++i) {
        push(0.125, i - 1, 0.75, i, 0.125, i + 1);
        push(0.5, i, 0.5, i + 1, 0.0, i);
    }
}

} // namespace

std::vector<double> subdivide_curve(const std::vector<double>& points, int dim, CurveSubdivision scheme, bool closed,
                                    int steps) {
    require(dim >= 1 && dim <= 4, "invalid-dimension", "dim must be 1 to 4, not " + std::to_string(dim));
    require(points.size() % static_cast<std::size_t>(dim) == 0, "invalid-argument",
            "points must hold " + std::to_string(dim) + " numbers per point; " + std::to_string(points.size()) +
                " numbers is not a multiple of " + std::to_string(dim));
    require(steps >= 0 && steps <= 20, "invalid-argument", "steps must be a whole number from 0 to 20, not " + std::to_string(steps));
    for (std::size_t i = 0; i < points.size(); ++i)
        require(std::isfinite(points[i]), "non-finite-input",
                "point P" + std::to_string(i / dim) + " has a value that is not a finite number");
    const int64_t n = static_cast<int64_t>(points.size()) / dim;
    const int64_t needed = closed ? 3 : (scheme == CurveSubdivision::Chaikin ? 3 : 4);
    require(n >= needed, "too-few-points",
            std::string(scheme == CurveSubdivision::Chaikin ? "Chaikin's scheme" : "cubic B-spline subdivision") + " on " +
                (closed ? "a closed" : "an open") + " polygon needs at least " + std::to_string(needed) +
                " points; this polygon has " + std::to_string(n));
    int64_t count = n;
    for (int s = 0; s < steps; ++s) {
        count = points_after(count, scheme, closed);
        require(count <= kMaxSubdividedPoints, "too-large",
                std::to_string(steps) + " steps would make more than " + std::to_string(kMaxSubdividedPoints) +
                    " points; choose fewer steps");
    }
    std::vector<double> current = points, next;
    for (int s = 0; s < steps; ++s) {
        step(current, dim, scheme, closed, next);
        current.swap(next);
    }
    return current;
}

} // namespace wingspline::curves
