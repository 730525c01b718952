#include "wingspline/curves/bspline_ops.h"

#include "messages.h"
#include "wingspline/curves/bspline_basis.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>

namespace wingspline::curves {

Curve as_explicit_bspline(const Curve& curve) {
    validate(curve);
    require(curve.kind == CurveKind::Bezier || curve.kind == CurveKind::BSpline || curve.kind == CurveKind::Nurbs,
            "unsupported-curve-kind",
            std::string("this operation works on bezier, bspline and nurbs curves, not on '") +
                curve_kind_name(curve.kind) + "'");
    Curve c = curve;
    const int K = control_point_count(curve);
    const int p = curve_degree(curve);
    c.degree = p;
    if (curve.kind == CurveKind::Bezier) c.knots = bezier_knots(p);
    else if (c.knots.empty()) c.knots = uniform_knots(K, p);
    const bool rational = is_rational(curve);
    c.kind = rational ? CurveKind::Nurbs : CurveKind::BSpline;
    if (rational && c.weights.empty()) c.weights.assign(static_cast<std::size_t>(K), 1.0);
    return c;
}

namespace {

int last_span(const std::vector<double>& t, int K) {
    int l = K - 1;
    while (t[l] == t[l + 1]) --l;
    return l;
}
int first_span(const std::vector<double>& t, int p) {
    int l = p;
    while (t[l] == t[l + 1]) ++l;
    return l;
}

void check_parameter(const Curve& c, double u, const char* what) {
    const int K = control_point_count(c);
    const int p = c.degree;
    const double a = c.knots[p], b = c.knots[K];
    // Messages are built only on failure (this runs once per evaluated parameter).
    if (!std::isfinite(u))
        throw Error("non-finite-input", std::string(what) + " is " + detail::num(u) + ", not a finite number");
    const double slack = kParameterSlack * std::max({1.0, std::abs(a), std::abs(b)});
    if (!(u >= a - slack && u <= b + slack))
        throw Error("parameter-out-of-range",
                    std::string(what) + " = " + detail::num(u) + " is outside the domain " + detail::range(a, b));
}

std::vector<double> homogeneous(const Curve& c) { return to_homogeneous(c.points, c.dim, c.weights); }

void project(const std::vector<double>& h, int d, bool rational, int shift, std::vector<double>& points,
             std::vector<double>* weights) {
    if (rational) from_homogeneous(h, d, shift, points, weights);
    else points = h;
}

} // namespace

DeBoorSteps de_boor(const Curve& curve, double u) {
    const Curve c = as_explicit_bspline(curve);
    const int K = control_point_count(c);
    const int p = c.degree;
    const int d = c.dim;
    check_parameter(c, u, "u");
    u = std::clamp(u, c.knots[p], c.knots[K]);
    const bool rational = c.kind == CurveKind::Nurbs;
    const int hd = rational ? d + 1 : d;
    const std::vector<double> h = homogeneous(c);
    const int shift = weight_shift(c.weights);
    const auto& t = c.knots;
    DeBoorSteps s;
    s.degree = p;
    s.span = find_span_in(t.data(), first_span(t, p), last_span(t, K), u);
    const int l = s.span;
    s.first_index = l - p;
    std::vector<double> level(h.begin() + (l - p) * hd, h.begin() + (l + 1) * hd);
    for (int r = 0; r <= p; ++r) {
        std::vector<double> pts, w;
        project(level, d, rational, shift, pts, &w);
        s.levels.push_back(pts);
        if (rational) s.level_weights.push_back(w);
        if (r == p) break;
        // Level r+1, entry j is d_i with i = l-p+r+1+j (lecture 001's d_i^k with alpha
        // = (u - t_i) / (t_i+p-r - t_i)).
        const int count = p - r;
        std::vector<double> next(static_cast<std::size_t>(count * hd));
        std::vector<double> alpha(static_cast<std::size_t>(count));
        for (int j = 0; j < count; ++j) {
            const int i = l - p + r + 1 + j;
            const double a = (u - t[i]) / (t[i + p - r] - t[i]);
            alpha[j] = a;
            for (int k = 0; k < hd; ++k) next[j * hd + k] = (1 - a) * level[j * hd + k] + a * level[(j + 1) * hd + k];
        }
        s.alphas.push_back(alpha);
        level = std::move(next);
    }
    return s;
}

KnotInsertion insert_knot(const Curve& curve, double u) {
    const Curve c = as_explicit_bspline(curve);
    const int K = control_point_count(c);
    const int p = c.degree;
    const int d = c.dim;
    check_parameter(c, u, "the new knot u");
    u = std::clamp(u, c.knots[p], c.knots[K]);
    const auto& t = c.knots;
    int multiplicity = 0;
    for (double v : t) multiplicity += v == u ? 1 : 0;
    require(multiplicity <= p, "knot-multiplicity-exceeded",
            "the knot " + detail::num(u) + " already appears " + std::to_string(multiplicity) +
                " times; a degree-" + std::to_string(p) + " B-spline allows at most p + 1 = " + std::to_string(p + 1));
    const bool rational = c.kind == CurveKind::Nurbs;
    const int hd = rational ? d + 1 : d;
    const std::vector<double> h = homogeneous(c);
    const int shift = weight_shift(c.weights);
    KnotInsertion r;
    const int k = find_span_in(t.data(), first_span(t, p), last_span(t, K), u);
    r.span = k;
    r.inserted_index = k + 1;
    std::vector<double> q(static_cast<std::size_t>((K + 1) * hd));
    for (int i = 0; i <= k - p; ++i)
        for (int m = 0; m < hd; ++m) q[i * hd + m] = h[i * hd + m];
    for (int i = k - p + 1; i <= k; ++i) {
        // Boehm: Q_i = a_i P_i + (1 - a_i) P_i-1, a_i = (u - t_i)/(t_i+p - t_i); the
        // denominator is positive because t_i <= t_k < t_k+1 <= t_i+p.
        const double a = (u - t[i]) / (t[i + p] - t[i]);
        r.recomputed.push_back(i);
        r.alphas.push_back(a);
        if (a > 0 && a < 1) r.new_points.push_back(i);
        for (int m = 0; m < hd; ++m) q[i * hd + m] = a * h[i * hd + m] + (1 - a) * h[(i - 1) * hd + m];
    }
    for (int i = k + 1; i <= K; ++i)
        for (int m = 0; m < hd; ++m) q[i * hd + m] = h[(i - 1) * hd + m];
    r.curve = c;
    r.curve.knots.insert(r.curve.knots.begin() + k + 1, u);
    project(q, d, rational, shift, r.curve.points, rational ? &r.curve.weights : nullptr);
    return r;
}

std::vector<BezierSegment> to_bezier_segments(const Curve& curve, std::size_t* work) {
    const Curve c = as_explicit_bspline(curve);
    const int K = control_point_count(c);
    const int p = c.degree;
    const int d = c.dim;
    const bool rational = c.kind == CurveKind::Nurbs;
    const int hd = rational ? d + 1 : d;
    const std::vector<double> h = homogeneous(c);
    const int shift = weight_shift(c.weights);
    const auto& t = c.knots;
    // Each span [a, b) = [t_l, t_l+1) is converted on its own from the p + 1 points
    // P_l-p..P_l and the 2p knots U_k = t_l-p+1+k (k = 0..2p-1) that act on it: inserting a
    // and then b locally until each has multiplicity p (two de Boor triangles, lecture 001)
    // gives its Bezier points f(a^(p-j), b^j). Work O(p^2) per span, so O(K p^2) in all
    // (inserting every knot into the whole curve copied all K points each time: O(K^2)).
    std::vector<BezierSegment> segments;
    std::vector<double> q(static_cast<std::size_t>((p + 1) * hd)), right(q.size());
    std::size_t ops = 0;
    auto combine = [&](int i, double alpha) { // q_i = (1 - alpha) q_i-1 + alpha q_i
        for (int k = 0; k < hd; ++k) q[i * hd + k] = (1 - alpha) * q[(i - 1) * hd + k] + alpha * q[i * hd + k];
        ops += static_cast<std::size_t>(hd);
    };
    for (int l = p; l < K; ++l) {
        if (!(t[l] < t[l + 1])) continue;
        const double* U = &t[l - p + 1];
        const double a = U[p - 1], b = U[p];
        std::copy(h.begin() + static_cast<std::ptrdiff_t>(l - p) * hd, h.begin() + static_cast<std::ptrdiff_t>(l + 1) * hd, q.begin());
        // Triangle at a: after level r, q_p = f(a^r, U_p..U_2p-1-r); keep them (right[p-r]).
        std::copy(q.begin() + p * hd, q.end(), right.begin() + p * hd);
        for (int r = 1; r <= p; ++r) {
            for (int i = p; i >= r; --i) combine(i, (a - U[i - 1]) / (U[i + p - r] - U[i - 1]));
            std::copy(q.begin() + p * hd, q.end(), right.begin() + (p - r) * hd);
        }
        ops += static_cast<std::size_t>(2 * (p + 1) * hd);
        // Triangle at b on the knots (a^p, U_p..U_2p-1): entry i is final after level i,
        // and then it is f(a^(p-i), b^i), the Bezier point i.
        q = right;
        for (int r = 1; r <= p; ++r)
            for (int i = p; i >= r; --i) combine(i, (b - a) / (U[i + p - r] - a));
        BezierSegment seg;
        seg.start = a;
        seg.end = b;
        project(q, d, rational, shift, seg.points, rational ? &seg.weights : nullptr);
        ops += static_cast<std::size_t>((p + 1) * hd);
        segments.push_back(std::move(seg));
    }
    if (work) *work += ops;
    return segments;
}

std::vector<KnotInfo> knot_multiplicities(const Curve& curve) {
    const Curve c = as_explicit_bspline(curve);
    const int p = c.degree;
    const double a = c.knots[p];
    const double b = c.knots[control_point_count(c)];
    std::vector<KnotInfo> out;
    for (std::size_t i = 0; i < c.knots.size();) {
        std::size_t j = i;
        while (j < c.knots.size() && c.knots[j] == c.knots[i]) ++j;
        KnotInfo k;
        k.value = c.knots[i];
        k.multiplicity = static_cast<int>(j - i);
        k.first_index = static_cast<int>(i);
        k.interior = k.value > a && k.value < b;
        k.continuity = p - k.multiplicity;
        out.push_back(k);
        i = j;
    }
    return out;
}

} // namespace wingspline::curves
