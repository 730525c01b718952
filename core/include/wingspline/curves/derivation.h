#pragma once
// The derivations of the cubic families, in exact rational arithmetic, so the panel
// can show the slides' fractions and the tests can compare without a tolerance:
//   Hermite (lecture 000): the constraint matrix C (rows [u^3 u^2 u 1] at u = 0, 1 and
//     [3u^2 2u 1 0] at u = 0, 1), M_H = C^-1.
//   Bezier (lectures 000, 003): G_H = [P1 P4 R1 R4] = S G_B with R1 = 3 (P2 - P1),
//     R4 = 3 (P4 - P3); M_B = M_H S.
//   Uniform B-spline (lectures 002, 003): the blending functions b_0..b_3 of one segment are
//     unknown cubics (16 coefficients); C2 at the joints (b_(c+1)^(d)(1) = b_c^(d)(0) for
//     d = 0, 1, 2, with b_-1 = b_4 = 0: each point's blending function is C2 where it enters
//     and leaves its four segments) gives 15 conditions, the partition of unity at u = 0 the
//     16th; solved exactly, M_BS = 1/6 [-1 3 -3 1; 3 -6 3 0; -3 0 3 0; 1 4 1 0].
#include "wingspline/curves/basis_matrix.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::curves {

// num / den in lowest terms, den > 0. Arithmetic throws Error("overflow") beyond 64 bits.
class Rational {
public:
    Rational(std::int64_t n = 0, std::int64_t d = 1);
    std::int64_t num() const { return n_; }
    std::int64_t den() const { return d_; }
    double value() const { return static_cast<double>(n_) / static_cast<double>(d_); }
    friend Rational operator+(const Rational& a, const Rational& b);
    friend Rational operator-(const Rational& a, const Rational& b);
    friend Rational operator*(const Rational& a, const Rational& b);
    friend Rational operator/(const Rational& a, const Rational& b);
    friend bool operator==(const Rational& a, const Rational& b) { return a.n_ == b.n_ && a.d_ == b.d_; }
    friend bool operator!=(const Rational& a, const Rational& b) { return !(a == b); }

private:
    std::int64_t n_, d_;
};

struct Derivation {
    std::string family;
    int size = 0;                       // the constraint system is size x size
    std::vector<Rational> constraint;   // row-major: the conditions (Bezier: Hermite's)
    std::vector<Rational> inverse;      // its inverse (Hermite: M_H)
    std::vector<Rational> rhs;          // B-spline: the right-hand side (0 ... 0 1); else empty
    std::vector<Rational> substitution; // Bezier: S, G_H = S G_B (4 x 4); else empty
    std::vector<Rational> basis;        // the resulting 4 x 4 basis matrix, row-major
    std::vector<std::string> conditions; // one line per constraint row, in the lectures' labels
};

// Throws Error("unsupported-curve-kind") for Catmull-Rom (its derivation is not one of the three).
Derivation derive_cubic(BasisKind kind);

// Exact Gauss-Jordan inverse of an n x n rational matrix; Error("singular-matrix").
std::vector<Rational> inverse(const std::vector<Rational>& m, int n);

} // namespace wingspline::curves
