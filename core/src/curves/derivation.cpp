#include "wingspline/curves/derivation.h"

#include "wingspline/error.h"

#include <cstdlib>
#include <numeric>

namespace wingspline::curves {

namespace {
using Wide = __int128;
std::int64_t narrow(Wide x) {
    require(x <= INT64_MAX && x >= -INT64_MAX, "overflow", "an exact fraction grew beyond 64 bits");
    return static_cast<std::int64_t>(x);
}
Rational make(Wide n, Wide d) {
    require(d != 0, "singular-matrix", "division by zero in an exact derivation");
    if (d < 0) n = -n, d = -d;
    Wide a = n < 0 ? -n : n, b = d;
    while (b != 0) {
        const Wide t = a % b;
        a = b;
        b = t;
    }
    if (a > 1) n /= a, d /= a;
    return Rational(narrow(n), narrow(d));
}
std::vector<Rational> ints(std::initializer_list<int> v) {
    std::vector<Rational> r;
    for (int x : v) r.emplace_back(x);
    return r;
}
std::vector<Rational> multiply(const std::vector<Rational>& a, const std::vector<Rational>& b, int n) {
    std::vector<Rational> p(n * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) p[n * i + j] = p[n * i + j] + a[n * i + k] * b[n * k + j];
    return p;
}
// d-th derivative of [u^3 u^2 u 1] at u (u = 0 or 1).
std::vector<int> powers(int d, int u) {
    if (d == 0) return {u * u * u, u * u, u, 1};
    if (d == 1) return {3 * u * u, 2 * u, 1, 0};
    return {6 * u, 2, 0, 0};
}
} // namespace

Rational::Rational(std::int64_t n, std::int64_t d) : n_(n), d_(d) {
    require(d != 0, "singular-matrix", "a fraction with denominator 0");
    if (d_ < 0) n_ = -n_, d_ = -d_;
    const std::int64_t g = std::gcd(n_ < 0 ? -n_ : n_, d_);
    if (g > 1) n_ /= g, d_ /= g;
}
Rational operator+(const Rational& a, const Rational& b) { return make(Wide(a.n_) * b.d_ + Wide(b.n_) * a.d_, Wide(a.d_) * b.d_); }
Rational operator-(const Rational& a, const Rational& b) { return make(Wide(a.n_) * b.d_ - Wide(b.n_) * a.d_, Wide(a.d_) * b.d_); }
Rational operator*(const Rational& a, const Rational& b) { return make(Wide(a.n_) * b.n_, Wide(a.d_) * b.d_); }
Rational operator/(const Rational& a, const Rational& b) { return make(Wide(a.n_) * b.d_, Wide(a.d_) * b.n_); }

std::vector<Rational> inverse(const std::vector<Rational>& m, int n) {
    std::vector<Rational> a = m, r(n * n);
    for (int i = 0; i < n; ++i) r[n * i + i] = Rational(1);
    for (int c = 0; c < n; ++c) {
        int p = c;
        while (p < n && a[n * p + c] == Rational(0)) ++p;
        require(p < n, "singular-matrix", "the conditions do not determine the matrix (they are not independent)");
        for (int k = 0; k < n; ++k) std::swap(a[n * c + k], a[n * p + k]), std::swap(r[n * c + k], r[n * p + k]);
        const Rational pivot = a[n * c + c];
        for (int k = 0; k < n; ++k) a[n * c + k] = a[n * c + k] / pivot, r[n * c + k] = r[n * c + k] / pivot;
        for (int i = 0; i < n; ++i) {
            if (i == c || a[n * i + c] == Rational(0)) continue;
            const Rational f = a[n * i + c];
            for (int k = 0; k < n; ++k) a[n * i + k] = a[n * i + k] - f * a[n * c + k], r[n * i + k] = r[n * i + k] - f * r[n * c + k];
        }
    }
    return r;
}

Derivation derive_cubic(BasisKind kind) {
    Derivation d;
    d.family = basis_kind_name(kind);
    if (kind == BasisKind::Hermite || kind == BasisKind::Bezier) {
        d.size = 4;
        // P(0), P(1), P'(0), P'(1) of P(u) = [u^3 u^2 u 1] [a b c d]^T (lecture 000)
        d.constraint = ints({0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 1, 0, 3, 2, 1, 0});
        d.inverse = inverse(d.constraint, 4);
        d.basis = d.inverse;
        d.conditions = {"P(0) = P1", "P(1) = P4", "P'(0) = R1", "P'(1) = R4"};
        if (kind == BasisKind::Bezier) {
            // P1 = P1, P4 = P4, R1 = 3 (P2 - P1), R4 = 3 (P4 - P3)
            d.substitution = ints({1, 0, 0, 0, 0, 0, 0, 1, -3, 3, 0, 0, 0, 0, -3, 3});
            d.basis = multiply(d.inverse, d.substitution, 4);
        }
        return d;
    }
    require(kind == BasisKind::BSpline, "unsupported-curve-kind",
            "a derivation is shown for Hermite, Bezier and the uniform B-spline, not for " + d.family);
    // Unknowns x[4c + r]: the coefficient of u^(3-r) in b_c. One row per condition.
    d.size = 16;
    d.constraint.assign(16 * 16, Rational(0));
    d.rhs.assign(16, Rational(0));
    int row = 0;
    auto add = [&](int c, int deriv, int u, int sign) {
        const std::vector<int> t = powers(deriv, u);
        for (int r = 0; r < 4; ++r) d.constraint[16 * row + 4 * c + r] = d.constraint[16 * row + 4 * c + r] + Rational(sign * t[r]);
    };
    for (int deriv = 0; deriv < 3; ++deriv) {
        const std::string q(deriv, '\'');
        auto b = [&](int c, int u) { return "b" + std::to_string(c) + q + "(" + std::to_string(u) + ")"; };
        add(0, deriv, 1, 1), ++row;                                     // b_0^(d)(1) = 0
        d.conditions.push_back(b(0, 1) + " = 0");
        for (int c = 0; c < 3; ++c) {
            add(c + 1, deriv, 1, 1), add(c, deriv, 0, -1), ++row;       // b_(c+1)(1) = b_c(0)
            d.conditions.push_back(b(c + 1, 1) + " = " + b(c, 0));
        }
        add(3, deriv, 0, 1), ++row;                                     // b_3^(d)(0) = 0
        d.conditions.push_back(b(3, 0) + " = 0");
    }
    d.conditions.push_back("b0(0) + b1(0) + b2(0) + b3(0) = 1");
    for (int c = 0; c < 4; ++c) add(c, 0, 0, 1);                        // sum_c b_c(0) = 1
    d.rhs[row] = Rational(1);
    d.inverse = inverse(d.constraint, 16);
    d.basis.assign(16, Rational(0));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d.basis[4 * r + c] = d.inverse[16 * (4 * c + r) + 15]; // x = A^-1 e_16
    return d;
}

} // namespace wingspline::curves
