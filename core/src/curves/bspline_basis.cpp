#include "wingspline/curves/bspline_basis.h"

namespace wingspline::curves {

void basis_functions(int span, double u, int degree, const double* t, double* N) {
    basis_functions_upto<kMaxDegree>(span, u, degree, t, N);
}

void basis_function_derivatives(int span, double u, int p, int n, const double* t, double* ders) {
    // ndu holds the basis functions (upper triangle) and the knot differences (lower
    // triangle) of the triangular Cox-de Boor scheme, as in The NURBS Book A2.3.
    double ndu[kMaxDegree + 1][kMaxDegree + 1];
    double left[kMaxDegree + 1];
    double right[kMaxDegree + 1];
    double a[2][kMaxDegree + 1];
    const int stride = p + 1;
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - t[span + 1 - j];
        right[j] = t[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= p; ++j) ders[j] = ndu[j][p];
    const int nd = n < p ? n : p;
    for (int r = 0; r <= p; ++r) {
        int s1 = 0;
        int s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= nd; ++k) {
            double d = 0.0;
            const int rk = r - k;
            const int pk = p - k;
            if (r >= k) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k * stride + r] = d;
            const int tmp = s1;
            s1 = s2;
            s2 = tmp;
        }
    }
    double factor = p;
    for (int k = 1; k <= nd; ++k) {
        for (int j = 0; j <= p; ++j) ders[k * stride + j] *= factor;
        factor *= (p - k);
    }
    for (int k = nd + 1; k <= n; ++k)
        for (int j = 0; j <= p; ++j) ders[k * stride + j] = 0.0;
}

} // namespace wingspline::curves
