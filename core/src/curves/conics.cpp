#include "wingspline/curves/conics.h"

#include "messages.h"
#include "wingspline/error.h"

#include <cmath>

namespace wingspline::curves {

namespace {

constexpr double kPi = 3.14159265358979323846;

void check_point(const std::vector<double>& p, int dim, const char* what) {
    require(dim == 2 || dim == 3, "invalid-dimension", "dim must be 2 or 3, not " + std::to_string(dim));
    require(p.size() == static_cast<std::size_t>(dim), "invalid-points",
            std::string(what) + " must have dim = " + std::to_string(dim) + " numbers, not " + std::to_string(p.size()));
    for (double v : p)
        require(std::isfinite(v), "non-finite-input", std::string(what) + " has a value that is not a finite number");
}

void check_positive(double v, const char* what) {
    require(std::isfinite(v) && v > 0, "invalid-argument", std::string(what) + " must be a positive number, not " + detail::num(v));
}

} // namespace

Curve nurbs_arc(const std::vector<double>& center, int dim, double radius, double start, double end) {
    check_point(center, dim, "the center");
    check_positive(radius, "the radius");
    require(std::isfinite(start) && std::isfinite(end), "non-finite-input", "the arc's angles must be finite numbers");
    const double sweep = end - start;
    require(sweep > 0 && sweep <= 2 * kPi + 1e-12, "invalid-argument",
            "the arc must sweep more than 0 and at most 2 pi radians, not " + detail::num(sweep));
    const int arcs = sweep <= kPi / 2 + 1e-12 ? 1 : sweep <= kPi + 1e-12 ? 2 : sweep <= 1.5 * kPi + 1e-12 ? 3 : 4;
    const double dtheta = sweep / arcs;
    const double w1 = std::cos(dtheta / 2);
    Curve c;
    c.kind = CurveKind::Nurbs;
    c.dim = dim;
    c.degree = 2;
    auto push = [&](double x, double y, double w) {
        c.points.push_back(center[0] + x);
        c.points.push_back(center[1] + y);
        if (dim == 3) c.points.push_back(center[2]);
        c.weights.push_back(w);
    };
    double angle = start;
    push(radius * std::cos(angle), radius * std::sin(angle), 1);
    for (int i = 0; i < arcs; ++i) {
        const double next = start + dtheta * (i + 1);
        // The middle point is where the end tangents meet: at angle (a + b)/2, distance r / cos(dtheta/2).
        const double mid = (angle + next) / 2;
        push(radius / w1 * std::cos(mid), radius / w1 * std::sin(mid), w1);
        if (i == arcs - 1 && sweep >= 2 * kPi - 1e-12) {
            // a full circle closes exactly on its first point
            const std::vector<double> first(c.points.begin(), c.points.begin() + dim);
            c.points.insert(c.points.end(), first.begin(), first.end());
            c.weights.push_back(1);
        } else {
            const double e = i == arcs - 1 ? end : next;
            push(radius * std::cos(e), radius * std::sin(e), 1);
        }
        angle = next;
    }
    c.knots = {0, 0, 0};
    for (int i = 1; i < arcs; ++i) {
        c.knots.push_back(static_cast<double>(i) / arcs);
        c.knots.push_back(static_cast<double>(i) / arcs);
    }
    c.knots.insert(c.knots.end(), {1, 1, 1});
    return c;
}

Curve nurbs_circle(const std::vector<double>& center, int dim, double radius) {
    return nurbs_arc(center, dim, radius, 0, 2 * kPi);
}

Curve nurbs_ellipse(const std::vector<double>& center, int dim, double rx, double ry) {
    check_positive(rx, "the semi-axis rx");
    check_positive(ry, "the semi-axis ry");
    Curve c = nurbs_circle(center, dim, 1);
    for (std::size_t i = 0; i < c.points.size(); i += dim) {
        c.points[i] = center[0] + rx * (c.points[i] - center[0]);
        c.points[i + 1] = center[1] + ry * (c.points[i + 1] - center[1]);
    }
    return c;
}

Curve nurbs_conic(const std::vector<double>& p0, const std::vector<double>& p1, const std::vector<double>& p2,
                  int dim, double w) {
    check_point(p0, dim, "P0");
    check_point(p1, dim, "P1");
    check_point(p2, dim, "P2");
    require(std::isfinite(w) && w > 0, "invalid-weight",
            "weight w_1 of point 1 is " + detail::num(w) + "; weights must be positive finite numbers");
    Curve c;
    c.kind = CurveKind::Nurbs;
    c.dim = dim;
    c.degree = 2;
    c.points = p0;
    c.points.insert(c.points.end(), p1.begin(), p1.end());
    c.points.insert(c.points.end(), p2.begin(), p2.end());
    c.weights = {1, w, 1};
    c.knots = {0, 0, 0, 1, 1, 1};
    return c;
}

const char* conic_type(double w) { return w < 1 ? "ellipse" : w == 1 ? "parabola" : "hyperbola"; }

} // namespace wingspline::curves
