#pragma once
// Small dense linear algebra for the curves core: the Vandermonde system of lecture 000
// and the (p+1)x(p+1) basis matrices of segments. Matrices are row-major.
#include <vector>

namespace wingspline::curves {

// Rows (u_i^n, u_i^(n-1), ..., u_i, 1) for i = 0..n (lecture 000, "Polynomials (Matrices)").
std::vector<double> vandermonde(const std::vector<double>& u);

// X with A X = B; A is n x n, B and X are n x m. Gaussian elimination with partial pivoting.
// Throws Error("singular-matrix") when A has no inverse.
std::vector<double> solve(std::vector<double> A, const std::vector<double>& B, int n, int m);

// The inverse of the n x n matrix A (throws "singular-matrix").
std::vector<double> inverse_n(const std::vector<double>& A, int n);

// (n x k) . (k x m)
std::vector<double> multiply_n(const std::vector<double>& A, const std::vector<double>& B, int n, int k, int m);

} // namespace wingspline::curves
