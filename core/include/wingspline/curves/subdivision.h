#pragma once
// Subdivision of a control polygon: the curve side of the mesh's Loop and
// Catmull-Clark rules.
//  * Chaikin's corner cutting: every leg P_i P_(i+1) gives 3/4 P_i + 1/4 P_(i+1) and
//    1/4 P_i + 3/4 P_(i+1). Converges to the uniform quadratic B-spline of the polygon.
//  * Lane-Riesenfeld cubic: the edge point (P_i + P_(i+1))/2 and the vertex point
//    (P_(i-1) + 6 P_i + P_(i+1))/8, in the order V_0, E_0, V_1, E_1, ... Converges to the
//    uniform cubic B-spline; one step is knot insertion at the middle of every span.
// Closed polygons wrap around (n points -> 2n). Open polygons have no end rule: a step makes
// exactly the points of the same uniform B-spline (unclamped: it starts at the middle of
// the first leg (quadratic) or at (P_0 + 4 P_1 + P_2)/6 (cubic)) over the halved knots, so
// the polygon shortens at its ends: Chaikin n -> 2(n - 1) points (Q_0, R_0, Q_1, ...),
// cubic n -> 2n - 3 (E_0, V_1, E_1, ..., V_(n-2), E_(n-2)).
#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::curves {

enum class CurveSubdivision { Chaikin, CubicBSpline };
// "chaikin" | "cubic-bspline"; anything else: Error("unknown-scheme").
CurveSubdivision curve_subdivision_from_name(const std::string& name);

// The largest polygon a subdivision may make (points), so that a step count cannot
// exhaust the memory: Error("too-large") beyond it.
inline constexpr int64_t kMaxSubdividedPoints = 4000000;

// points[dim*i + k]. Refuses: "invalid-dimension" (dim outside 1..4), "invalid-argument"
// (points not a multiple of dim, steps outside 0..20), "non-finite-input" (naming the
// point), "too-few-points" (open: 3 for Chaikin, 4 for cubic; closed: 3), "too-large".
std::vector<double> subdivide_curve(const std::vector<double>& points, int dim, CurveSubdivision scheme, bool closed,
                                    int steps);

} // namespace wingspline::curves
