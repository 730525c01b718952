#include "wingspline/curves/analysis.h"

#include "messages.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace wingspline::curves {

namespace {

// |v|, scaled first so that squares neither underflow (|v| near 1e-300) nor overflow.
double norm(const double* v, int d) {
    double m = 0;
    for (int k = 0; k < d; ++k) m = std::max(m, std::abs(v[k]));
    if (!(m > 0) || !std::isfinite(m)) return m;
    double s = 0;
    for (int k = 0; k < d; ++k) s += (v[k] / m) * (v[k] / m);
    return m * std::sqrt(s);
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

// ---- scale first
// Every computation below works on a copy of the curve divided by a power of two near its
// largest coordinate: the copy's coordinates lie in [-1, 1], so P', P'', |P'|^3 and the
// Gauss-Legendre sums can neither overflow nor underflow, and the division by 2^e is exact
// (differences of the input's coordinates survive bit for bit; moving the copy to its centre
// first would round them away when one point is 1e300 and the others are near 1). Results
// are scaled back at the end (lengths times 2^e, curvatures divided by 2^e).
struct Normalised {
    Curve curve;        // points / 2^exponent, tangents / 2^exponent
    int exponent = 0;   // the scale is 2^exponent
};

// 2 max |Q - c| over the control points Q of both curves (same dim), c their centroid.
double spread(const Curve& a, const Curve& b) {
    const int d = a.dim;
    const std::size_t n = (a.points.size() + b.points.size()) / d;
    std::vector<double> c(d, 0.0);
    for (const Curve* x : {&a, &b})
        for (std::size_t i = 0; i < x->points.size(); ++i) c[i % d] += x->points[i] / static_cast<double>(n);
    double r2 = 0;
    for (const Curve* x : {&a, &b})
        for (std::size_t i = 0; i + d <= x->points.size(); i += d) {
            double s = 0;
            for (int k = 0; k < d; ++k) s += (x->points[i + k] - c[k]) * (x->points[i + k] - c[k]);
            r2 = std::max(r2, s);
        }
    return 2 * std::sqrt(r2);
}

Normalised normalised(const Curve& c, int exponent) {
    Normalised n;
    n.curve = c;
    n.exponent = exponent;
    for (double& x : n.curve.points) x = std::ldexp(x, -exponent);
    for (double& t : n.curve.tangents) t = std::ldexp(t, -exponent);
    return n;
}

// The exponent e with every |coordinate| and |tangent| of the curves below 2^e.
int common_exponent(const std::vector<const Curve*>& curves) {
    double extent = 0;
    for (const Curve* c : curves) {
        for (double x : c->points) extent = std::max(extent, std::abs(x));
        for (double t : c->tangents) extent = std::max(extent, std::abs(t));
    }
    int e = 0;
    if (extent > 0) std::frexp(extent, &e); // extent = m 2^e, 0.5 <= m < 1
    return e;
}

Normalised normalised(const Curve& c) {
    validate(c);
    return normalised(c, common_exponent({&c}));
}

// The rounding of a k-th derivative at u: kRoundingFloor * sum_i |N_i^(k)(u)| |Q_i| over the
// control items Q_i (points and Hermite tangents) of the normalised copy. Evaluation errs by
// about 1e-16 of that sum, so a derivative below it is zero and a difference below it is no
// difference; the factor 1e4 between them is the margin.
constexpr double kRoundingFloor = 1e-12;
double rounding_floor(const Curve& c, double u, int order) {
    const BlendingValues bv = blending_functions(c, {u}, order);
    const int K = control_point_count(c), d = c.dim;
    double s = 0;
    for (int i = 0; i < bv.count; ++i) {
        const double* q = i < K ? &c.points[i * d] : &c.tangents[(i - K) * d];
        s += std::abs(bv.values[i]) * norm(q, d);
    }
    return kRoundingFloor * s;
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

// Adaptive Gauss-Legendre with a hard budget: every call to this runs at most
// kLengthBudget 10-point rules, whatever the input, and reports 'not-converged' when the
// budget is spent before the error estimate meets the goal (a NaN estimate never meets it).
constexpr int kLengthBudget = 1 << 16;
constexpr int kLengthMaxDepth = 60;
struct LengthWork {
    const CurveEvaluator& ev;
    double goal; // absolute, in the normalised copy's units
    int rules = 0;
};

double adaptive_length(LengthWork& w, double a, double b, double whole, int depth) {
    const double m = (a + b) / 2;
    if (w.rules + 2 > kLengthBudget)
        throw Error("not-converged", "the arc length did not reach its accuracy within " + std::to_string(kLengthBudget) +
                                         " quadrature steps; the curve may have a cusp the quadrature cannot resolve");
    w.rules += 2;
    const double left = gauss_speed(w.ev, a, m), right = gauss_speed(w.ev, m, b);
    if (std::abs(left + right - whole) <= w.goal || depth >= kLengthMaxDepth || !(m > a && m < b)) return left + right;
    return adaptive_length(w, a, m, left, depth + 1) + adaptive_length(w, m, b, right, depth + 1);
}

// The length of the normalised copy between a and b (coordinates in [-1, 1], so no overflow).
double length_on(const CurveEvaluator& ev, double a, double b) {
    const double whole = gauss_speed(ev, a, b);
    LengthWork w{ev, 1e-15 * std::max(whole, 1e-300)};
    return adaptive_length(w, a, b, whole, 0);
}

// Scales a length of the normalised copy back; refuses one beyond the largest double.
double scaled_length(double normalised_length, int exponent) {
    const double L = std::ldexp(normalised_length, exponent);
    require(std::isfinite(L), "length-overflow",
            "the arc length is larger than the largest number a double can hold (about 1.8e308); "
            "use smaller coordinates");
    return L;
}

} // namespace

CurvatureValues curvature(const Curve& curve, const std::vector<double>& params) {
    // Computed on the normalised copy: kappa = kappa' / 2^e, speed 2^e |P'|.
    const Normalised n = normalised(curve);
    const CurveEvaluator ev(n.curve);
    const auto u = ev.checked_params(params.data(), params.size());
    const int d = ev.dim();
    std::vector<double> jet(u.size() * 3 * d);
    ev.evaluate_all(u.data(), u.size(), 2, jet.data());
    // |P'| is zero when it is below its rounding floor at u (the same test as jointContinuity's
    // zero tangent, so the lab's table and curvature plot agree). The floor needs the blending
    // functions at u, so it is computed only where |P'| is below a cheap bound of it: the
    // largest |coordinate| (<= 1) times the largest possible sum |N_i'| (2n per unit of parameter).
    double piece = ev.domain().end - ev.domain().start;
    if (n.curve.kind == CurveKind::BSpline || n.curve.kind == CurveKind::Nurbs) {
        const auto& t = n.curve.knots.empty() ? uniform_knots(control_point_count(n.curve), ev.degree()) : n.curve.knots;
        for (std::size_t i = 0; i + 1 < t.size(); ++i)
            if (t[i + 1] > t[i]) piece = std::min(piece, t[i + 1] - t[i]);
    } else if (n.curve.kind != CurveKind::Bezier && n.curve.kind != CurveKind::Interpolation) {
        piece = std::min(piece, 1.0);
    }
    const double cheap_bound = 1e3 * kRoundingFloor * 2 * std::max(1, ev.degree()) / piece;
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
        r.speed[j] = std::ldexp(speed, n.exponent);
        if (!(speed > cheap_bound) && !(speed > rounding_floor(n.curve, u[j], 1))) {
            r.singular[j] = 1;
            r.curvature[j] = 0;
            if (d == 2) r.signed_curvature[j] = 0;
            continue;
        }
        for (int k = 0; k < d; ++k) r.tangent[j * d + k] = d1[k] / speed;
        const double s3 = speed * speed * speed;
        r.curvature[j] = std::ldexp(cross_norm(d1, d2, d) / s3, -n.exponent);
        if (d == 2) r.signed_curvature[j] = std::ldexp((d1[0] * d2[1] - d1[1] * d2[0]) / s3, -n.exponent);
    }
    return r;
}

double arc_length(const Curve& curve, double a, double b) {
    const Normalised n = normalised(curve);
    const CurveEvaluator ev(n.curve);
    const double ab[2] = {a, b};
    const auto u = ev.checked_params(ab, 2);
    require(u[0] <= u[1], "invalid-argument",
            "the arc length runs from a to b with a <= b, but a = " + detail::num(a) + " > b = " + detail::num(b));
    const auto cuts = pieces(n.curve, ev, u[0], u[1]);
    double total = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) total += length_on(ev, cuts[i], cuts[i + 1]);
    return scaled_length(total, n.exponent);
}

ArcLengthParams arc_length_params(const Curve& curve, int n) {
    require(n >= 2 && n <= 10000000, "invalid-argument", "the number of parameters must be from 2 to 10000000");
    const Normalised normal = normalised(curve);
    const CurveEvaluator ev(normal.curve);
    const double a = ev.domain().start, b = ev.domain().end;
    // A table of cumulative lengths over fine cells (every polynomial piece in 64 cells),
    // then, for every target length, Newton's method on s(u) - target inside its cell with
    // bisection as the safeguard; s is integrated exactly (Gauss-Legendre) from the cell start.
    const auto cuts = pieces(normal.curve, ev, a, b);
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
    r.total = cell_s.back(); // normalised units until the end
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
                if (std::abs(f) <= 1e-13 * r.total) break;
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
    r.total = scaled_length(r.total, normal.exponent);
    for (double& s : r.lengths) s = std::ldexp(s, normal.exponent);
    r.lengths.back() = r.total;
    return r;
}

namespace {

std::string short_num(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
}

double distance(const double* x, const double* y, int d) {
    double g[3] = {0, 0, 0};
    for (int k = 0; k < d; ++k) g[k] = x[k] - y[k];
    return norm(g, d);
}

// |unit(x) - sign * unit(y)| for non-zero x, y: 0 when they point the same way (sign 1).
double direction_gap(const double* x, const double* y, int d, double sign = 1) {
    const double nx = norm(x, d), ny = norm(y, d);
    double s = 0;
    for (int k = 0; k < d; ++k) {
        const double g = x[k] / nx - sign * y[k] / ny;
        s += g * g;
    }
    return std::sqrt(s);
}

// The two lecture wordings of G^n read literally, next to the core's.
void add_wordings(JointContinuity& r, const double* A, const double* B, int d, double tolerance, double floor2, bool c2) {
    const JointEvidence& e = r.evidence;
    const bool g1 = r.geometric >= 1;
    const double* A2 = A + 2 * d;
    const double* B2 = B + 2 * d;
    const bool zero_a2 = norm(A2, d) <= floor2, zero_b2 = norm(B2, d) <= floor2;
    // A zero P'' has no direction (lecture 003 cannot say G2 there, even at a C2 joint).
    const bool same_dir2 = !zero_a2 && !zero_b2 && (c2 || direction_gap(A2, B2, d) <= tolerance);
    const bool opposite2 = !zero_a2 && !zero_b2 && direction_gap(A2, B2, d, -1) <= tolerance;
    const bool proportional2 = same_dir2 || opposite2 || (zero_a2 && zero_b2);
    const std::string kappas = "kappa- = " + short_num(e.curvature_a) + ", kappa+ = " + short_num(e.curvature_b);
    const std::string below_g2 = r.parametric < 0 ? "the curves do not meet"
                                 : e.zero_tangent ? "a first derivative is the zero vector, so the tangent direction is undefined"
                                                  : "the first derivatives do not point the same way (angle " +
                                                        short_num(e.tangent_angle * 180 / 3.14159265358979323846) + " degrees)";
    LectureWording core{"curvature-vector", "the core (lecture 004's osculating circle)",
                        "G2: same unit tangent and same curvature vector kappa N", r.geometric, ""};
    core.reason = !g1 ? below_g2
                  : r.geometric == 2 ? "the curvature vectors agree (" + kappas + "): one osculating circle; this does not change when either side is reparametrised"
                                     : "the curvature vectors differ (" + kappas + ")";
    auto literal = [&](const char* id, const char* source, const char* words, bool holds2, const std::string& why_not) {
        LectureWording w{id, source, words, !g1 ? r.geometric : holds2 ? 2 : 1, ""};
        if (!g1) w.reason = below_g2 + " (the same at order 1 in every reading)";
        else if (w.geometric == r.geometric)
            w.reason = std::string(holds2 ? "P''+ and P''- satisfy it" : why_not) + "; the same verdict as the curvature vector here";
        else if (holds2)
            w.reason = "P''+ and P''- satisfy it, yet the curvature differs (" + kappas +
                       "): curvature also depends on |P'|^2 and only on the part of P'' across the tangent, so this wording "
                       "accepts a joint whose osculating circles differ";
        else
            w.reason = why_not + ", yet the curvature vectors agree (" + kappas +
                       "): P''+ differs from P''- by a part along the tangent, which changes the speed (a reparametrisation), "
                       "not the shape; this wording is stricter than the shape";
        r.wordings.push_back(w);
    };
    r.wordings.push_back(core);
    literal("proportional", "lectures 001, 004",
            "G2: both first and second parametric derivatives are proportional at the boundary (001); "
            "all derivatives up to the k-th order are proportional (004)",
            proportional2,
            zero_a2 != zero_b2 ? std::string("P'' is the zero vector on one side only, so P''+ is no multiple of P''-")
                               : std::string("P''+ is not a multiple of P''-"));
    literal("direction", "lecture 003", "G^n: the direction of the n th derivative of the curve is continuous", same_dir2,
            zero_a2 || zero_b2 ? std::string("P'' is the zero vector on a side, so the direction of the 2nd derivative is undefined")
            : opposite2        ? std::string("P''+ points opposite to P''- (proportional with a negative factor, which lectures 001 and 004 allow)")
                               : std::string("P''+ and P''- point in different directions"));
}

} // namespace

JointContinuity joint_continuity(const Curve& a, const Curve& b, double tolerance) {
    require(std::isfinite(tolerance) && tolerance > 0 && tolerance < 1e-3, "invalid-argument",
            "the tolerance is relative and must be above 0 and below 1e-3, not " + detail::num(tolerance));
    require(a.dim == b.dim, "dimension-mismatch",
            "curve a has dim " + std::to_string(a.dim) + " but curve b has dim " + std::to_string(b.dim));
    validate(a);
    validate(b);
    // Everything is decided on the normalised pair (one power-of-two scale for both),
    // so the verdict does not depend on where the drawing is, how it
    // is turned or how large it is; the evidence is scaled back to the caller's units.
    const int ex = common_exponent({&a, &b});
    const Normalised na = normalised(a, ex), nb = normalised(b, ex);
    const CurveEvaluator ea(na.curve), eb(nb.curve);
    const int d = a.dim;
    std::vector<double> jet_a(3 * d), jet_b(3 * d);
    const double ua = ea.domain().end, ub = eb.domain().start;
    ea.evaluate_all(&ua, 1, 2, jet_a.data());
    eb.evaluate_all(&ub, 1, 2, jet_b.data());
    const double* A = jet_a.data();
    const double* B = jet_b.data();
    // The size of the configuration: twice the largest distance of a control point of either
    // curve from the centroid of all of them (no rotation or shift changes it).
    const double size = spread(na.curve, nb.curve);
    // Rounding floors per side (a zero tangent is judged on its own side) and for a difference.
    double floor_a[3], floor_b[3], floor_k[3];
    for (int k = 0; k < 3; ++k) {
        floor_a[k] = rounding_floor(na.curve, ua, k);
        floor_b[k] = rounding_floor(nb.curve, ub, k);
        floor_k[k] = std::max(floor_a[k], floor_b[k]);
    }

    JointContinuity r;
    JointEvidence& e = r.evidence;
    e.tolerance = tolerance;
    e.a_derivatives.resize(3 * d);
    e.b_derivatives.resize(3 * d);
    for (int k = 0; k < 3 * d; ++k) {
        e.a_derivatives[k] = std::ldexp(A[k], ex);
        e.b_derivatives[k] = std::ldexp(B[k], ex);
    }
    const double gap0 = distance(A, B, d), gap1 = distance(A + d, B + d, d), gap2 = distance(A + 2 * d, B + 2 * d, d);
    e.position_gap = std::ldexp(gap0, ex);
    e.size = std::ldexp(size, ex);
    e.d1_gap = std::ldexp(gap1, ex);
    e.d2_gap = std::ldexp(gap2, ex);
    const double na1 = norm(A + d, d), nb1 = norm(B + d, d);
    const double na2 = norm(A + 2 * d, d), nb2 = norm(B + 2 * d, d);
    // Equal: the difference is at most `tolerance` of the larger of the two (positions: of the
    // configuration's size), or below the rounding floor of that order.
    auto same = [&](double g, double scale, int order) { return g <= std::max(tolerance * scale, floor_k[order]); };
    // Each statement on its own (a student judges them one by one), then the
    // verdict from them: C^k needs every equality up to order k.
    const bool eq0 = same(gap0, size, 0);
    const bool eq1 = same(gap1, std::max(na1, nb1), 1);
    const bool eq2 = same(gap2, std::max(na2, nb2), 2);
    const bool c0 = eq0;
    const bool c1 = c0 && eq1;
    const bool c2 = c1 && eq2;
    r.parametric = c2 ? 2 : c1 ? 1 : c0 ? 0 : -1;
    e.relative_gap = c0 || size == 0 ? 0 : gap0 / size;
    e.zero_tangent_a = na1 <= floor_a[1];
    e.zero_tangent_b = nb1 <= floor_b[1];
    e.zero_tangent = e.zero_tangent_a || e.zero_tangent_b;
    // Curvature vectors kappa N = (P'' - (P''.T) T) / |P'|^2 (lecture 004), each side on its own
    // power-of-two scale (|P'| near 1, so |P'|^2 cannot underflow when one side is far smaller
    // than the other), returned in the caller's units: kappa(c J) = kappa(J) / c.
    std::vector<double> ka(d, 0.0), kb(d, 0.0);
    auto curvature_vector = [&](const double* J, double speed, std::vector<double>& out) {
        int f = 0;
        std::frexp(speed, &f);
        double j1[3] = {0, 0, 0}, j2[3] = {0, 0, 0};
        for (int k = 0; k < d; ++k) j1[k] = std::ldexp(J[d + k], -f), j2[k] = std::ldexp(J[2 * d + k], -f);
        const double v = norm(j1, d);
        double along = 0;
        for (int k = 0; k < d; ++k) along += j2[k] * j1[k] / v;
        for (int k = 0; k < d; ++k) out[k] = std::ldexp((j2[k] - along * j1[k] / v) / (v * v), -f - ex);
        return norm(out.data(), d);
    };
    if (!e.zero_tangent_a) e.curvature_a = curvature_vector(A, na1, ka);
    if (!e.zero_tangent_b) e.curvature_b = curvature_vector(B, nb1, kb);
    bool same_direction = false, equal_curvature = false;
    if (!e.zero_tangent) {
        e.ratio = nb1 / na1;
        // The angle between the unit tangents u, v as 2 atan2(|u - v|, |u + v|) (Kahan): right
        // for every angle, where acos of u.v loses the small ones (1e-9 rad read 0).
        double diff[3], sum[3];
        for (int k = 0; k < d; ++k) {
            const double u = A[d + k] / na1, w = B[d + k] / nb1;
            diff[k] = u - w;
            sum[k] = u + w;
        }
        const double kgap = distance(ka.data(), kb.data(), d);
        if (c0) {
            e.tangent_angle = 2 * std::atan2(norm(diff, d), norm(sum, d));
            e.curvature_vector_gap = kgap;
        }
        // The rounding of a curvature vector (caller's units): floor2 / |P'|^2 + 2 floor1 |P''| / |P'|^3.
        const double m1 = std::ldexp(std::min(na1, nb1), ex), m2 = std::ldexp(std::max(na2, nb2), ex);
        const double f1 = std::ldexp(floor_k[1], ex), f2 = std::ldexp(floor_k[2], ex);
        const double kappa_floor = f2 / m1 / m1 + 2 * (f1 / m1) * (m2 / m1) / m1;
        // Equal derivatives imply the same direction and curvature where the tangents are
        // non-zero (lecture 004: C^k => G^k), so the equalities count here.
        same_direction = eq1 || direction_gap(A + d, B + d, d) <= tolerance;
        equal_curvature = (eq1 && eq2) || kgap <= std::max(tolerance * std::max(e.curvature_a, e.curvature_b), kappa_floor);
    }
    e.meet = eq0;
    e.equal_first = eq1;
    e.equal_second = eq2;
    e.same_direction = same_direction;
    e.equal_curvature = equal_curvature;
    const bool g1 = c0 && same_direction;
    const bool g2 = g1 && equal_curvature;
    r.geometric = g2 ? 2 : g1 ? 1 : c0 ? 0 : -1;
    if (!c0)
        e.notes.push_back("C-1: the joint is discontinuous, V1(1) != V2(0) (lecture 004); the gap is " + detail::num(e.position_gap) +
                          ", " + detail::num(e.relative_gap) + " of the size of the two curves");
    if (c0 && e.zero_tangent)
        e.notes.push_back(c1 ? "both tangent vectors are zero: C1 holds but G1 does not (the exception to C1 => G1)"
                             : "a tangent vector is zero, so the tangent direction (G1) is undefined");
    if (g1 && !c1) e.notes.push_back("same tangent direction, different length (ratio " + detail::num(e.ratio) + "): G1 but not C1");
    add_wordings(r, A, B, d, tolerance, floor_k[2], c2);
    return r;
}

} // namespace wingspline::curves
