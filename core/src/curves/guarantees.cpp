#include "wingspline/curves/guarantees.h"

#include "wingspline/curves/bspline_basis.h"
#include "wingspline/curves/curve.h"
#include "wingspline/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace wingspline::curves {
namespace {

using Vec = std::vector<double>;

double max_abs(const Vec& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}
double dot(const Vec& a, const Vec& b) {
    double s = 0;
    for (std::size_t j = 0; j < a.size(); ++j) s += a[j] * b[j];
    return s;
}
// a - k b
Vec minus(const Vec& a, double k, const Vec& b) {
    Vec r(a.size());
    for (std::size_t j = 0; j < a.size(); ++j) r[j] = a[j] - k * b[j];
    return r;
}
bool negligible(const Vec& v, double scale) { return max_abs(v) <= kGuaranteeTolerance * scale; }

// C^k and G^k guaranteed at one joint from the coefficient vectors a[d] (left) and b[d]
// (right), d = 0..a.size()-1.
void joint_levels(const std::vector<Vec>& a, const std::vector<Vec>& b, int& parametric, int& geometric) {
    const int orders = static_cast<int>(a.size());
    parametric = -1;
    for (int d = 0; d < orders; ++d) {
        const double scale = std::max(max_abs(a[d]), max_abs(b[d]));
        if (!negligible(minus(a[d], 1, b[d]), scale)) break;
        parametric = d;
    }
    geometric = std::min(parametric, 2);
    if (parametric < 0 || geometric >= 2 || orders < 3) return;
    // G1: the left tangent is a positive multiple lambda of the right one, for every polygon.
    const double bb = dot(b[1], b[1]);
    if (!(bb > 0)) return;
    const double lambda = dot(a[1], b[1]) / bb;
    const double scale1 = std::max(max_abs(a[1]), max_abs(b[1]));
    if (!(lambda > 0) || !negligible(minus(a[1], lambda, b[1]), scale1)) return;
    geometric = std::max(geometric, 1);
    // G2: a_2 - lambda^2 b_2 lies along b_1 (the curvature vectors agree).
    const Vec r = minus(a[2], lambda * lambda, b[2]);
    const double mu = dot(r, b[1]) / bb;
    const double scale2 = std::max({max_abs(a[2]), lambda * lambda * max_abs(b[2]), std::abs(mu) * max_abs(b[1])});
    if (negligible(minus(r, mu, b[1]), scale2)) geometric = 2;
}

// [u^3 u^2 u 1] differentiated d times.
std::array<double, 4> power_row(double u, int d) {
    switch (d) {
    case 0: return {u * u * u, u * u, u, 1};
    case 1: return {3 * u * u, 2 * u, 1, 0};
    case 2: return {6 * u, 2, 0, 0};
    default: return {6, 0, 0, 0};
    }
}

// row . M . S, S a 4 x slots row-major map.
Vec through(const std::array<double, 4>& row, const Mat4& M, const Vec& S, int32_t slots) {
    std::array<double, 4> rm{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) rm[c] += row[r] * M[4 * r + c];
    Vec out(slots, 0.0);
    for (int r = 0; r < 4; ++r)
        for (int32_t j = 0; j < slots; ++j) out[j] += rm[r] * S[static_cast<std::size_t>(slots) * r + j];
    return out;
}

// Slot j, where `position` (a coefficient vector of a curve point) is e_j.
int32_t unit_slot(const Vec& position) {
    const double scale = std::max(1.0, max_abs(position));
    for (std::size_t j = 0; j < position.size(); ++j) {
        if (std::abs(position[j] - 1) > kGuaranteeTolerance * scale) continue;
        Vec rest = position;
        rest[j] = 0;
        if (negligible(rest, scale)) return static_cast<int32_t>(j);
    }
    return -1;
}

void finish(Guarantees& g, std::vector<bool>& hit, const std::vector<bool>* is_point) {
    for (std::size_t j = 0; j < hit.size(); ++j)
        if (hit[j] && (!is_point || (*is_point)[j])) g.interpolated.push_back(static_cast<int32_t>(j));
    if (g.joints == 0) { g.parametric = 3; g.geometric = 2; }
}

} // namespace

Guarantees chain_guarantees(BasisKind basis, int32_t slots, const std::vector<std::vector<double>>& maps,
                            const std::vector<bool>& is_point) {
    require(slots >= 1 && slots <= 4096, "invalid-argument", "the construction needs 1 to 4096 slots, not " + std::to_string(slots));
    require(!maps.empty(), "invalid-argument", "the construction needs at least one segment");
    require(is_point.size() == static_cast<std::size_t>(slots), "invalid-argument",
            "give one point/vector flag per slot: " + std::to_string(slots) + " slots, " + std::to_string(is_point.size()) + " flags");
    for (std::size_t s = 0; s < maps.size(); ++s) {
        require(maps[s].size() == 4 * static_cast<std::size_t>(slots), "invalid-argument",
                "segment " + std::to_string(s) + " maps 4 geometry rows from " + std::to_string(slots) + " slots, so it needs " +
                    std::to_string(4 * slots) + " weights, not " + std::to_string(maps[s].size()));
        for (double w : maps[s]) require(std::isfinite(w), "non-finite-input", "segment " + std::to_string(s) + " has a weight that is not a finite number");
    }
    const Mat4 M = basis_matrix(basis);
    Guarantees g;
    std::vector<bool> hit(slots, false);
    for (std::size_t s = 0; s < maps.size(); ++s) {
        for (double u : {0.0, 1.0}) {
            const int32_t j = unit_slot(through(power_row(u, 0), M, maps[s], slots));
            if (j >= 0) hit[j] = true;
        }
        if (s == 0) continue;
        std::vector<Vec> a, b;
        for (int d = 0; d <= 3; ++d) {
            a.push_back(through(power_row(1, d), M, maps[s - 1], slots));
            b.push_back(through(power_row(0, d), M, maps[s], slots));
        }
        int c = 0, gk = 0;
        joint_levels(a, b, c, gk);
        g.parametric = g.joints ? std::min(g.parametric, c) : c;
        g.geometric = g.joints ? std::min(g.geometric, gk) : gk;
        ++g.joints;
    }
    finish(g, hit, &is_point);
    return g;
}

Guarantees bspline_guarantees(const std::vector<double>& knots, int degree, int32_t count) {
    Curve c;
    c.kind = CurveKind::BSpline;
    c.dim = 1;
    c.degree = degree;
    c.points.assign(static_cast<std::size_t>(std::max(count, 0)), 0.0);
    c.knots = knots;
    validate(c); // the curve API's own checks and messages (knot count, order, multiplicity)
    const int p = degree;
    const int K = count;
    const int orders = p + 1;
    std::vector<double> left(static_cast<std::size_t>(orders) * (p + 1)), right(left.size());
    const auto over_points = [&](const std::vector<double>& ders, int span, int d) {
        Vec v(K, 0.0);
        for (int r = 0; r <= p; ++r) v[span - p + r] = ders[static_cast<std::size_t>(d) * (p + 1) + r];
        return v;
    };
    Guarantees g;
    std::vector<bool> hit(K, false);
    const auto mark_unit = [&](int span, const std::vector<double>& ders) {
        const int32_t j = unit_slot(over_points(ders, span, 0));
        if (j >= 0) hit[j] = true;
    };
    // Every distinct knot value of the domain [t_p, t_K]: ends for interpolation, interior
    // ones also as joints. Left span l: t_l < t = t_{l+1}; right span: t_l <= t < t_{l+1}.
    for (int i = p; i <= K;) {
        const double t = knots[i];
        int next = i;
        while (next <= K && knots[next] == t) ++next;
        const int left_span = i - 1;  // knots[i-1] < t (i is the first index of value t)
        const int right_span = next - 1;
        const bool has_left = i > p, has_right = next <= K;
        if (has_left) {
            basis_function_derivatives(left_span, t, p, p, knots.data(), left.data());
            mark_unit(left_span, left);
        }
        if (has_right) {
            basis_function_derivatives(right_span, t, p, p, knots.data(), right.data());
            mark_unit(right_span, right);
        }
        if (has_left && has_right) {
            std::vector<Vec> a, b;
            for (int d = 0; d < orders; ++d) {
                a.push_back(over_points(left, left_span, d));
                b.push_back(over_points(right, right_span, d));
            }
            int ck = 0, gk = 0;
            joint_levels(a, b, ck, gk);
            g.parametric = g.joints ? std::min(g.parametric, ck) : ck;
            g.geometric = g.joints ? std::min(g.geometric, gk) : gk;
            ++g.joints;
        }
        i = next;
    }
    finish(g, hit, nullptr);
    return g;
}

} // namespace wingspline::curves
