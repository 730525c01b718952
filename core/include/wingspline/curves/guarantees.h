#pragma once
// What a representation guarantees for EVERY control polygon (the comparison
// tables of lectures 001 and 003), as opposed to what one polygon happens to do.
//
// The structural argument: at a joint, the d-th derivative from the left and from the right
// are linear in the control data, with coefficient vectors a_d and b_d over the "slots" (the
// control points and tangent vectors the construction is built from). A property holds for
// every polygon exactly when it holds for these coefficient vectors:
//   C^k  <=> a_d = b_d for d = 0..k;
//   G^1  <=> C^0 and a_1 = lambda b_1 with lambda > 0 (tangent directions agree);
//   G^2  <=> G^1 and a_2 - lambda^2 b_2 = mu b_1 (equal curvature vectors, the core's
//            reparametrisation-invariant definition used by joint_continuity);
//   slot j is interpolated <=> at some segment end the position's coefficient vector is e_j.
// Coefficients are compared with a relative tolerance kGuaranteeTolerance times the largest
// coefficient compared (they are small rationals such as 1/6 or 3/h).
#include "wingspline/curves/basis_matrix.h"

#include <cstdint>
#include <vector>

namespace wingspline::curves {

constexpr double kGuaranteeTolerance = 1e-12; // unitless, relative to the largest coefficient

struct Guarantees {
    int parametric = 3;             // weakest C^k over the joints (-1: not even C0; 3 with no joint)
    int geometric = 2;              // weakest G^k over the joints, k <= 2
    int joints = 0;
    std::vector<int32_t> interpolated; // slots every polygon's curve passes through, ascending
};

// A chain of uniform cubic segments of one basis, P_s(u) = [u^3 u^2 u 1] M G_s with
// G_s = S_s x: maps[s] is the 4 x slots matrix S_s (row-major, maps[s][slots*r + j]: weight
// of slot j in geometry row r). Consecutive segments meet at a joint (end of s = start of s+1).
// is_point[j]: slot j is a point (a tangent vector is never "interpolated").
// Throws Error("invalid-argument") for sizes that do not fit.
Guarantees chain_guarantees(BasisKind basis, int32_t slots, const std::vector<std::vector<double>>& maps,
                            const std::vector<bool>& is_point);

// A B-spline of the given degree on `knots` (count + degree + 1 of them) with `count` control
// points: the joints are the distinct interior knots of the domain [t_p, t_count]; a_d, b_d
// are the basis functions' d-th derivatives there from the left and from the right span.
// Throws what the B-spline evaluation throws for its knots (wrong-knot-count, decreasing-knots,
// knot-multiplicity-exceeded, empty-domain) and Error("invalid-argument").
Guarantees bspline_guarantees(const std::vector<double>& knots, int degree, int32_t count);

} // namespace wingspline::curves
