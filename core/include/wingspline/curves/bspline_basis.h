#pragma once
// The B-spline basis on a knot vector t_0 <= ... <= t_{K+p} (lecture 002, "general
// B-splines"; lecture 001, "non-uniform B-splines"). The Cox-de Boor recursion
//   N_i,0(u) = 1 if t_i <= u < t_{i+1}, else 0
//   N_i,p(u) = (u - t_i)/(t_{i+p} - t_i) N_i,p-1(u) + (t_{i+p+1} - u)/(t_{i+p+1} - t_{i+1}) N_i+1,p-1(u)
// with 0/0 taken as 0, evaluated in the triangular form of Piegl & Tiller (The NURBS Book,
// A2.2 and A2.3): only the p+1 functions that are non-zero on the span are computed, with
// no division by a zero-length interval (inside a non-empty span every denominator is > 0).
#include "wingspline/curves/curve.h"

#include <cstddef>

namespace wingspline::curves {

// The span l (t_l <= u < t_{l+1}, non-empty) holding u, searched in [first, last]; u beyond
// t_{last+1} gives `last` (the rule: u = t_K belongs to the last span).
inline int find_span_in(const double* knots, int first, int last, double u) {
    if (u >= knots[last]) return last;
    if (u <= knots[first]) return first;
    int lo = first;
    int hi = last; // invariant: knots[lo] <= u < knots[hi]
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (u < knots[mid]) hi = mid;
        else lo = mid;
    }
    return lo;
}

// One row of the Cox-de Boor triangle: N[0..j-1] (degree j-1) -> N[0..j] (degree j) at u,
// filling left[j], right[j] (A2.2's inner loop, shared by every basis routine here).
inline void raise_basis_degree(int span, double u, int j, const double* t, double* left, double* right, double* N) {
    left[j] = u - t[span + 1 - j];
    right[j] = t[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
        const double temp = N[r] / (right[r + 1] + left[j - r]);
        N[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
    }
    N[j] = saved;
}

// N[0..degree] = N_{span-degree+r, degree}(u), r = 0..degree (The NURBS Book, A2.2), for any
// degree <= MaxP. One body for both uses: basis_functions (the degree known at run time)
// and basis_functions_fixed<P> (known at compile time, so the loops unroll).
template <int MaxP>
inline void basis_functions_upto(int span, double u, int degree, const double* t, double* N) {
    double left[MaxP + 1];
    double right[MaxP + 1];
    N[0] = 1.0;
    for (int j = 1; j <= degree; ++j) raise_basis_degree(span, u, j, t, left, right, N);
}

template <int P> inline void basis_functions_fixed(int span, double u, const double* t, double* N) {
    basis_functions_upto<P>(span, u, P, t, N);
}

void basis_functions(int span, double u, int degree, const double* knots, double* N);

// ders[k*(p+1) + r] = d^k/du^k N_{span-p+r, p}(u), k = 0..n (A2.3). Orders above p are 0.
void basis_function_derivatives(int span, double u, int degree, int n, const double* knots, double* ders);

} // namespace wingspline::curves
