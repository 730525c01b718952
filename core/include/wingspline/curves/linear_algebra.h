#pragma once
// Small dense linear algebra for the curves core: the Vandermonde system of lecture 000
// and the (p+1)x(p+1) basis matrices of segments. Matrices are row-major.
#include <vector>

namespace wingspline::curves {

// Rows (u_i^n, u_i^(n-1), ..., u_i, 1) for i = 0..n (lecture 000, "Polynomials (Matrices)").
std::vector<double> vandermonde(const std::vector<double>& u);

// V^-1 for distinct nodes u (any offset and scale): column j holds the power coefficients
// of the Lagrange polynomial L_j (row r multiplies u^(n-r)), expanded factor by factor.
// Throws Error("vandermonde-out-of-range") when V or V^-1 has an entry beyond double range.
std::vector<double> vandermonde_inverse(const std::vector<double>& u);

// X with A X = B; A is n x n, B and X are n x m. Gaussian elimination with partial pivoting.
// Throws Error("singular-matrix") when A has no inverse.
std::vector<double> solve(std::vector<double> A, const std::vector<double>& B, int n, int m);

// The inverse of the n x n matrix A (throws "singular-matrix").
std::vector<double> inverse_n(const std::vector<double>& A, int n);

// (n x k) . (k x m)
std::vector<double> multiply_n(const std::vector<double>& A, const std::vector<double>& B, int n, int k, int m);

} // namespace wingspline::curves
