#include "wingspline/curves/analysis.h"

#include "messages.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>

namespace wingspline::curves {

namespace {

double norm(const double* v, int d) {
    double s = 0;
    for (int k = 0; k < d; ++k) s += v[k] * v[k];
    return std::sqrt(s);
}

// |a x b| for dim 2 (as the z component) or 3; dim 1 gives 0.
double cross_norm(const double* a, const double* b, int d) {
    if (d == 2) return std::abs(a[0] * b[1] - a[1] * b[0]);
    if (d == 3) {
        const double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
        return std::sqrt(x * x + y * y + z * z);
    }
    return 0;
}

// The breakpoints of the curve inside [a, b] (knots or segment joints), a and b included.
std::vector<double> pieces(const Curve& c, const CurveEvaluator& ev, double a, double b) {
    std::vector<double> cuts = {a};
    std::vector<double> joints;
    if (c.kind == CurveKind::BSpline || c.kind == CurveKind::Nurbs) {
        joints = c.knots.empty() ? uniform_knots(control_point_count(c), curve_degree(c)) : c.knots;
    } else if (c.kind == CurveKind::Hermite || c.kind == CurveKind::CatmullRom || c.kind == CurveKind::Cardinal) {
        for (double s = ev.domain().start; s <= ev.domain().end; s += 1) joints.push_back(s);
    }
    for (double t : joints)
        if (t > a && t < b && t != cuts.back()) cuts.push_back(t);
    cuts.push_back(b);
    return cuts;
}

// 10-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double kGaussX[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                               0.9739065285171717};
constexpr double kGaussW[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                               0.0666713443086881};

double gauss_speed(const CurveEvaluator& ev, double a, double b) {
    const int d = ev.dim();
    const double m = (a + b) / 2, h = (b - a) / 2;
    double u[10];
    for (int i = 0; i < 5; ++i) {
        u[2 * i] = m - h * kGaussX[i];
        u[2 * i + 1] = m + h * kGaussX[i];
    }
    double der[30];
    ev.evaluate(u, 10, 1, der);
    double s = 0;
    for (int i = 0; i < 5; ++i) s += kGaussW[i] * (norm(der + 2 * i * d, d) + norm(der + (2 * i + 1) * d, d));
    return s * h;
}

double adaptive_length(const CurveEvaluator& ev, double a, double b, double whole, int depth) {
    const double m = (a + b) / 2;
    const double left = gauss_speed(ev, a, m), right = gauss_speed(ev, m, b);
    if (depth >= 30 || std::abs(left + right - whole) <= 1e-14 * std::max(1.0, std::abs(whole)))
        return left + right;
    return adaptive_length(ev, a, m, left, depth + 1) + adaptive_length(ev, m, b, right, depth + 1);
}

double length_on(const CurveEvaluator& ev, double a, double b) {
    return adaptive_length(ev, a, b, gauss_speed(ev, a, b), 0);
}

} // namespace

CurvatureValues curvature(const Curve& curve, const std::vector<double>& params) {
    const CurveEvaluator ev(curve);
    const auto u = ev.checked_params(params.data(), params.size());
    const int d = ev.dim();
    std::vector<double> jet(u.size() * 3 * d);
    ev.evaluate_all(u.data(), u.size(), 2, jet.data());
    CurvatureValues r;
    r.curvature.resize(u.size());
    r.speed.resize(u.size());
    r.tangent.assign(u.size() * d, 0.0);
    r.singular.assign(u.size(), 0);
    if (d == 2) r.signed_curvature.resize(u.size());
    for (std::size_t j = 0; j < u.size(); ++j) {
        const double* d1 = &jet[j * 3 * d + d];
        const double* d2 = &jet[j * 3 * d + 2 * d];
        const double speed = norm(d1, d);
        r.speed[j] = speed;
        if (!(speed > 1e-300)) {
            r.singular[j] = 1;
            r.curvature[j] = 0;
            if (d == 2) r.signed_curvature[j] = 0;
            continue;
        }
        for (int k = 0; k < d; ++k) r.tangent[j * d + k] = d1[k] / speed;
        const double s3 = speed * speed * speed;
        r.curvature[j] = cross_norm(d1, d2, d) / s3;
        if (d == 2) r.signed_curvature[j] = (d1[0] * d2[1] - d1[1] * d2[0]) / s3;
    }
    return r;
}

double arc_length(const Curve& curve, double a, double b) {
    const CurveEvaluator ev(curve);
    const double ab[2] = {a, b};
    const auto u = ev.checked_params(ab, 2);
    require(u[0] <= u[1], "invalid-argument",
            "the arc length runs from a to b with a <= b, but a = " + detail::num(a) + " > b = " + detail::num(b));
    const auto cuts = pieces(curve, ev, u[0], u[1]);
    double total = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) total += length_on(ev, cuts[i], cuts[i + 1]);
    return total;
}

ArcLengthParams arc_length_params(const Curve& curve, int n) {
    require(n >= 2 && n <= 10000000, "invalid-argument", "the number of parameters must be from 2 to 10000000");
    const CurveEvaluator ev(curve);
    const double a = ev.domain().start, b = ev.domain().end;
    // A table of cumulative lengths over fine cells (every polynomial piece in 64 cells),
    // then, for every target length, Newton's method on s(u) - target inside its cell with
    // bisection as the safeguard; s is integrated exactly (Gauss-Legendre) from the cell start.
    const auto cuts = pieces(curve, ev, a, b);
    std::vector<double> cell_u = {a};
    std::vector<double> cell_s = {0.0};
    constexpr int kCells = 64;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
        for (int c = 1; c <= kCells; ++c) {
            const double u1 = c == kCells ? cuts[i + 1] : cuts[i] + (cuts[i + 1] - cuts[i]) * c / kCells;
            cell_s.push_back(cell_s.back() + length_on(ev, cell_u.back(), u1));
            cell_u.push_back(u1);
        }
    ArcLengthParams r;
    r.total = cell_s.back();
    r.params.resize(n);
    r.lengths.resize(n);
    const int d = ev.dim();
    std::size_t cell = 0;
    for (int j = 0; j < n; ++j) {
        const double target = j == n - 1 ? r.total : r.total * j / (n - 1);
        r.lengths[j] = target;
        while (cell + 2 < cell_s.size() && cell_s[cell + 1] < target) ++cell;
        double lo = cell_u[cell], hi = cell_u[cell + 1];
        const double base = cell_s[cell];
        double u = cell_s[cell + 1] > base ? lo + (hi - lo) * (target - base) / (cell_s[cell + 1] - base) : lo;
        if (j == 0) u = a;
        else if (j == n - 1) u = b;
        else {
            for (int it = 0; it < 50; ++it) {
                const double f = base + length_on(ev, cell_u[cell], u) - target;
                if (std::abs(f) <= 1e-13 * std::max(1.0, r.total)) break;
                if (f > 0) hi = u;
                else lo = u;
                double der[3];
                ev.evaluate(&u, 1, 1, der);
                const double speed = norm(der, d);
                double next = speed > 0 ? u - f / speed : (lo + hi) / 2;
                if (!(next > lo && next < hi)) next = (lo + hi) / 2;
                u = next;
            }
        }
        r.params[j] = u;
    }
    return r;
}

JointContinuity joint_continuity(const Curve& a, const Curve& b, double tolerance) {
    require(std::isfinite(tolerance) && tolerance > 0, "invalid-argument",
            "the tolerance must be a positive number, not " + detail::num(tolerance));
    require(a.dim == b.dim, "dimension-mismatch",
            "curve a has dim " + std::to_string(a.dim) + " but curve b has dim " + std::to_string(b.dim));
    const CurveEvaluator ea(a), eb(b);
    const int d = a.dim;
    JointContinuity r;
    JointEvidence& e = r.evidence;
    e.tolerance = tolerance;
    e.a_derivatives.resize(3 * d);
    e.b_derivatives.resize(3 * d);
    const double ua = ea.domain().end, ub = eb.domain().start;
    ea.evaluate_all(&ua, 1, 2, e.a_derivatives.data());
    eb.evaluate_all(&ub, 1, 2, e.b_derivatives.data());
    const double* A = e.a_derivatives.data();
    const double* B = e.b_derivatives.data();
    auto gap = [&](int order) {
        double s = 0;
        for (int k = 0; k < d; ++k) s += (A[order * d + k] - B[order * d + k]) * (A[order * d + k] - B[order * d + k]);
        return std::sqrt(s);
    };
    auto same = [&](double g, double x, double y) { return g <= tolerance * std::max({1.0, x, y}); };
    e.position_gap = gap(0);
    e.d1_gap = gap(1);
    e.d2_gap = gap(2);
    const double na1 = norm(A + d, d), nb1 = norm(B + d, d);
    const double na2 = norm(A + 2 * d, d), nb2 = norm(B + 2 * d, d);
    const bool c0 = same(e.position_gap, norm(A, d), norm(B, d));
    const bool c1 = c0 && same(e.d1_gap, na1, nb1);
    const bool c2 = c1 && same(e.d2_gap, na2, nb2);
    r.parametric = c2 ? 2 : c1 ? 1 : c0 ? 0 : -1;
    e.zero_tangent = na1 <= tolerance || nb1 <= tolerance;
    // Curvature vectors kappa N = (P'' - (P''.T) T) / |P'|^2.
    std::vector<double> ka(d, 0.0), kb(d, 0.0);
    double tangent_gap = 0;
    if (!e.zero_tangent) {
        e.ratio = nb1 / na1;
        double dot = 0;
        for (int k = 0; k < d; ++k) dot += A[d + k] * B[d + k];
        e.tangent_angle = std::acos(std::clamp(dot / (na1 * nb1), -1.0, 1.0));
        double pa = 0, pb = 0;
        for (int k = 0; k < d; ++k) {
            pa += A[2 * d + k] * A[d + k] / na1;
            pb += B[2 * d + k] * B[d + k] / nb1;
            const double ta = A[d + k] / na1, tb = B[d + k] / nb1;
            tangent_gap += (ta - tb) * (ta - tb);
        }
        tangent_gap = std::sqrt(tangent_gap);
        for (int k = 0; k < d; ++k) {
            ka[k] = (A[2 * d + k] - pa * A[d + k] / na1) / (na1 * na1);
            kb[k] = (B[2 * d + k] - pb * B[d + k] / nb1) / (nb1 * nb1);
        }
        e.curvature_a = norm(ka.data(), d);
        e.curvature_b = norm(kb.data(), d);
        double g = 0;
        for (int k = 0; k < d; ++k) g += (ka[k] - kb[k]) * (ka[k] - kb[k]);
        e.curvature_vector_gap = std::sqrt(g);
    }
    const bool g0 = c0;
    const bool g1 = g0 && !e.zero_tangent && tangent_gap <= tolerance;
    const bool g2 = g1 && same(e.curvature_vector_gap, e.curvature_a, e.curvature_b);
    r.geometric = g2 ? 2 : g1 ? 1 : g0 ? 0 : -1;
    if (!c0) e.notes.push_back("the curves do not meet: the gap is " + detail::num(e.position_gap));
    if (c0 && e.zero_tangent)
        e.notes.push_back(c1 ? "both tangent vectors are zero: C1 holds but G1 does not (the exception to C1 => G1)"
                             : "a tangent vector is zero, so the tangent direction (G1) is undefined");
    if (g1 && !c1) e.notes.push_back("same tangent direction, different length (ratio " + detail::num(e.ratio) + "): G1 but not C1");
    return r;
}

} // namespace wingspline::curves
