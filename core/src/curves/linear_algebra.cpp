#include "wingspline/curves/linear_algebra.h"

#include "wingspline/error.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace wingspline::curves {

std::vector<double> vandermonde(const std::vector<double>& u) {
    const int n = static_cast<int>(u.size());
    std::vector<double> V(static_cast<std::size_t>(n * n));
    for (int i = 0; i < n; ++i) {
        double power = 1;
        for (int c = n - 1; c >= 0; --c) {
            V[i * n + c] = power;
            power *= u[i];
        }
    }
    return V;
}

std::vector<double> vandermonde_inverse(const std::vector<double>& u) {
    const int n = static_cast<int>(u.size());
    std::vector<double> M(static_cast<std::size_t>(n * n), 0.0);
    std::vector<double> a(static_cast<std::size_t>(n)), next(a.size());
    for (int j = 0; j < n; ++j) {
        std::fill(a.begin(), a.end(), 0.0);
        a[0] = 1; // ascending powers of u
        int degree = 0;
        for (int m = 0; m < n; ++m) {
            if (m == j) continue;
            // multiply by (u - u_m) / (u_j - u_m)
            const double inv = 1.0 / (u[j] - u[m]);
            std::fill(next.begin(), next.end(), 0.0);
            for (int k = 0; k <= degree; ++k) {
                next[k + 1] += a[k] * inv;
                next[k] -= u[m] * inv * a[k];
            }
            ++degree;
            std::swap(a, next);
        }
        for (int k = 0; k < n; ++k) M[(n - 1 - k) * n + j] = a[k];
    }
    const std::vector<double> V = vandermonde(u);
    for (std::size_t i = 0; i < M.size(); ++i) {
        require(std::isfinite(M[i]) && std::isfinite(V[i]), "vandermonde-out-of-range",
                "the Vandermonde matrix of these " + std::to_string(n) + " nodes (powers u_i^" + std::to_string(n - 1) +
                    ") or its inverse has entries beyond the range of double precision; the curve can still be "
                    "evaluated, but its matrix form cannot be shown. Use nodes nearer 0 or fewer points");
    }
    return M;
}

std::vector<double> solve(std::vector<double> A, const std::vector<double>& B, int n, int m) {
    std::vector<double> X = B;
    double scale = 0;
    for (double a : A) scale = std::max(scale, std::abs(a));
    for (int col = 0; col < n; ++col) {
        int pivot = col;
        for (int r = col + 1; r < n; ++r)
            if (std::abs(A[r * n + col]) > std::abs(A[pivot * n + col])) pivot = r;
        require(std::abs(A[pivot * n + col]) > 1e-300 && std::abs(A[pivot * n + col]) > 1e-14 * scale,
                "singular-matrix", "the matrix is singular, so the system has no unique solution");
        if (pivot != col) {
            for (int c = 0; c < n; ++c) std::swap(A[col * n + c], A[pivot * n + c]);
            for (int c = 0; c < m; ++c) std::swap(X[col * m + c], X[pivot * m + c]);
        }
        for (int r = col + 1; r < n; ++r) {
            const double f = A[r * n + col] / A[col * n + col];
            if (f == 0) continue;
            for (int c = col; c < n; ++c) A[r * n + c] -= f * A[col * n + c];
            for (int c = 0; c < m; ++c) X[r * m + c] -= f * X[col * m + c];
        }
    }
    for (int r = n - 1; r >= 0; --r)
        for (int c = 0; c < m; ++c) {
            double v = X[r * m + c];
            for (int k = r + 1; k < n; ++k) v -= A[r * n + k] * X[k * m + c];
            X[r * m + c] = v / A[r * n + r];
        }
    return X;
}

std::vector<double> inverse_n(const std::vector<double>& A, int n) {
    std::vector<double> I(static_cast<std::size_t>(n * n), 0.0);
    for (int i = 0; i < n; ++i) I[i * n + i] = 1;
    return solve(A, I, n, n);
}

std::vector<double> multiply_n(const std::vector<double>& A, const std::vector<double>& B, int n, int k, int m) {
    std::vector<double> R(static_cast<std::size_t>(n * m), 0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            double s = 0;
            for (int q = 0; q < k; ++q) s += A[i * k + q] * B[q * m + j];
            R[i * m + j] = s;
        }
    return R;
}

} // namespace wingspline::curves
