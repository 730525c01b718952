#pragma once
// Bezier curves of any degree (lectures 001, 002): Bernstein polynomials, de Casteljau's
// construction with every intermediate point, subdivision, degree elevation; rational
// Bezier curves work in homogeneous coordinates (w x, w y, w z, w).
// Points are flat: points[dim*i + k]; weights (optional) one per point, > 0.
#include <vector>

namespace wingspline::curves {

// B_i^n(t) = C(n,i) t^i (1-t)^(n-i), i = 0..n (lecture 001).
std::vector<double> bernstein(int n, double t);

// de Casteljau (lecture 001): B_i^r = (1-t) B_i^(r-1) + t B_i+1^(r-1). Level r holds n+1-r
// points; level 0 is the control polygon, level n the point on the curve.
struct DeCasteljauSteps {
    int degree = 0;
    int dim = 2;
    std::vector<std::vector<double>> levels;        // levels[r][dim*i + k]
    std::vector<std::vector<double>> level_weights; // rational only: the weights of each level
};
DeCasteljauSteps de_casteljau(const std::vector<double>& points, int dim, double t,
                              const std::vector<double>& weights = {});

struct BezierSplit {
    std::vector<double> left, right;                 // n+1 points each
    std::vector<double> left_weights, right_weights; // rational only
};
// The two halves at t: left = the first point of every level, right = the last point of
// every level in reverse order. Both together trace exactly the original curve.
BezierSplit subdivide_bezier(const std::vector<double>& points, int dim, double t,
                             const std::vector<double>& weights = {});

// The (n+1)x(n+1) matrices S_L, S_R with left = S_L P, right = S_R P at parameter t; for n = 3,
// t = 1/2 these are lecture 002's G_B^L and G_B^R.
void bezier_subdivision_matrices(int n, double t, std::vector<double>& SL, std::vector<double>& SR);

// Degree n -> n+1: Q_i = i/(n+1) P_i-1 + (1 - i/(n+1)) P_i. Rational: in homogeneous coords.
struct ElevatedBezier {
    std::vector<double> points;
    std::vector<double> weights; // rational only
};
ElevatedBezier elevate_bezier(const std::vector<double>& points, int dim, const std::vector<double>& weights = {});

// The (n+1)x(n+1) matrix M_n of P(t) = [t^n ... t 1] M_n G for the Bernstein basis (n = 3:
// lecture 003's M_Bezier). Entry (r, i) is the coefficient of t^(n-r) in B_i^n.
std::vector<double> bezier_power_matrix(int n);

} // namespace wingspline::curves
