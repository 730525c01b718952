#pragma once
// Quantities the curve explorer draws over a curve (lectures 001, 002, 004), computed in the
// core so the lesson only draws them: the curvature comb and the
// homogeneous lift of a NURBS's control points.
#include "wingspline/curves/curve.h"

#include <vector>

namespace wingspline::curves {

// The comb (lecture 004): at every parameter the point and the curvature vector kappa N,
// N the left normal (-t_y, t_x) of the unit tangent and kappa the signed curvature, so a
// tooth stands on the side the curve turns to with length |kappa| (1/r on a circle of radius
// r, pointing at its centre). dim 2 only. Where P' = 0 (a cusp) the tooth is the zero
// vector, never NaN, and counts as singular.
struct CurvatureComb {
    std::vector<double> teeth;  // teeth[4*j + 0..1]: the point, [4*j + 2..3]: kappa N
    double max_curvature = 0;   // the largest |kappa| over the parameters
    int singular = 0;           // parameters where P' = 0
};
CurvatureComb curvature_comb(const Curve& curve, const std::vector<double>& params);

// The control points lifted to homogeneous coordinates (w x, w y, [w z,] w), stride dim + 1,
// with the weights as given (lectures 001, 002: the NURBS is the shadow of this polynomial
// B-spline on the plane w = 1). Throws 'wrong-weight-count', 'invalid-weight' (w <= 0 or not
// finite, naming the point), 'non-finite-input', 'invalid-points'.
std::vector<double> homogeneous_lift(const std::vector<double>& points, int dim, const std::vector<double>& weights);

} // namespace wingspline::curves
