#pragma once
// Algorithms on B-splines and NURBS that a lesson animates (lectures 001, 002):
// de Boor's construction with every intermediate point, Boehm's knot insertion one knot at
// a time, conversion to Bezier segments, and the continuity C^(p-m) at every knot.
// Bezier curves and uniform B-splines (no knots) are accepted and treated as the B-spline
// with their implicit knots (bezier_knots / uniform_knots). Rational curves work in
// homogeneous coordinates and report the weights of every intermediate point.
#include "wingspline/curves/curve.h"

#include <cstddef>
#include <vector>

namespace wingspline::curves {

// The curve as an explicit B-spline/NURBS: kind BSpline or Nurbs, knots filled in, weights
// filled in (all 1 when rational without weights).
Curve as_explicit_bspline(const Curve& curve);

struct DeBoorSteps {
    int span = 0;        // l with t_l <= u < t_l+1 (u = t_K: the last span)
    int degree = 0;
    int first_index = 0; // level 0 holds P_(l-p) .. P_l; entry j of level r is d_(l-p+r+j)^r
    std::vector<std::vector<double>> levels;        // levels[r][dim*j + k], p+1-r points
    std::vector<std::vector<double>> level_weights; // rational only
    std::vector<std::vector<double>> alphas;        // alphas[r-1][j]: d = (1-a) d_left + a d_right
};
DeBoorSteps de_boor(const Curve& curve, double u);

struct KnotInsertion {
    Curve curve;                    // K+1 points, K+p+2 knots; the same curve
    int span = 0;                   // the span k the knot went into
    int inserted_index = 0;         // index of the new knot in the new knot vector
    std::vector<int> recomputed;    // Q_i = a_i P_i + (1-a_i) P_i-1 for i = k-p+1..k
    std::vector<double> alphas;     // a_i for those i
    std::vector<int> new_points;    // the i with 0 < a_i < 1: genuinely new points
};
// Boehm's algorithm (one knot). Refuses u outside the domain and a knot that already has
// multiplicity p+1 ('knot-multiplicity-exceeded').
KnotInsertion insert_knot(const Curve& curve, double u);

struct BezierSegment {
    std::vector<double> points;  // p+1 points
    std::vector<double> weights; // rational only
    double start = 0, end = 1;   // the span of the B-spline parameter it covers
};
// Knot insertion until every knot in the domain has multiplicity p: each span becomes a
// Bezier curve of degree p (with u = (t - start)/(end - start)).
// work (optional): incremented by the number of control-point values copied or combined,
// the measure of the algorithm's cost that the tests check for linear growth.
std::vector<BezierSegment> to_bezier_segments(const Curve& curve, std::size_t* work = nullptr);

struct KnotInfo {
    double value = 0;
    int multiplicity = 0;
    int first_index = 0;
    bool interior = false;  // t_p < value < t_K: a joint of two segments
    int continuity = 0;     // C^(p - m) at an interior knot (-1: the curve may jump)
};
std::vector<KnotInfo> knot_multiplicities(const Curve& curve);

} // namespace wingspline::curves
