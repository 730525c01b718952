#pragma once
// Knot vectors a lesson offers as presets (lecture 002, "general B-splines": uniform and
// open/clamped knot vectors; lecture 001, "non-uniform B-splines"), K + p + 1 entries for K
// control points of degree p, and which polynomial segment holds a parameter.
// New knot values (clamped interior knots, the spread ends of an unclamped vector) are
// rounded to whole billionths (kKnotSteps per unit) so that a share link holding them stays short and a value typed
// back round-trips; the knots already in a vector are kept as they are.
#include <vector>

namespace wingspline::curves {

constexpr double kKnotSteps = 1e9;

// Open/clamped: p+1 zeros, the K-p-1 interior knots j/(K-p) (j = 1..K-p-1), p+1 ones.
// Refuses degree outside 1..kMaxDegree ('degree-out-of-range') and count < p+1 ('too-few-points').
std::vector<double> clamped_knots(int count, int degree);

// The same domain [t_p, t_K] and interior knots, the p end knots on each side spread out
// with the first (last) non-empty spacing h of the domain (1 when the domain has none):
// t_j = t_p - (p - j) h for j < p, t_(K+i) = t_K + i h' for i = 1..p.
// Refuses a vector whose length is not K+p+1 for some K >= p+1 ('wrong-knot-count').
std::vector<double> unclamped_knots(const std::vector<double>& knots, int degree);

// True when the first p+1 knots are equal and the last p+1 knots are equal.
bool is_clamped(const std::vector<double>& knots, int degree);

// Lecture 002: "cubic b-spline -> cubic Bezier curve, {0,0,0,0,1,1,1,1}". True
// when the B-spline of degree p on these knots is exactly the Bezier curve of its p+1
// control points: 2p+2 knots, t_1 = .. = t_p < t_p+1 = .. = t_2p (clamped, except that the
// outermost knot on each side is free: it acts on no span of the domain, so a degree-1
// segment is always its Bezier line). Refuses what is_clamped refuses.
bool is_bezier_in_disguise(const std::vector<double>& knots, int degree);

} // namespace wingspline::curves
