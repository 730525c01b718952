#pragma once
// Exact conics as NURBS (lecture 002: "quadratic NURBS can be used to represent quadrics").
// A circular arc of sweep <= 90 degrees is a rational quadratic Bezier with middle weight
// cos(sweep/2); longer arcs join such pieces with double knots (The NURBS Book A7.1).
#include "wingspline/curves/curve.h"

namespace wingspline::curves {

// The arc of radius r about center (dim numbers; 3D arcs lie in the plane z = center z)
// from angle `start` to `end` (radians, end > start, sweep <= 2 pi), degree 2.
Curve nurbs_arc(const std::vector<double>& center, int dim, double radius, double start, double end);
// The full circle: 9 points, weights 1, sqrt(2)/2, ..., knots 0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1.
Curve nurbs_circle(const std::vector<double>& center, int dim, double radius);
// The axis-aligned ellipse with semi-axes rx, ry (the circle's control net scaled: NURBS
// are affine invariant).
Curve nurbs_ellipse(const std::vector<double>& center, int dim, double rx, double ry);
// The conic through P0 and P2 with tangents towards P1: a rational quadratic Bezier with
// weights 1, w, 1 (w < 1 ellipse, w = 1 parabola, w > 1 hyperbola), as a NURBS.
Curve nurbs_conic(const std::vector<double>& p0, const std::vector<double>& p1, const std::vector<double>& p2,
                  int dim, double w);
// "ellipse" | "parabola" | "hyperbola" for the middle weight of a conic arc.
const char* conic_type(double w);

} // namespace wingspline::curves
