#pragma once
// Keeping a continuity while a control point is dragged (lecture 001 "Achieving
// Continuity", lecture 002 "C^n and G^n"). A piecewise curve is stored as 4 entries per
// segment: Bezier P0..P3, or Hermite p0, p1 and the tangent vectors t0, t1; entries are
// `dim` numbers each, entry i at points[dim*i ...]. Joint j sits between segment j-1 (left,
// L) and segment j (right, R). A constraint moves control points of the side that is not
// the master so that the joint satisfies:
//   C0  the segments share the end point: L3 = R0 (Hermite: L.p1 = R.p0)
//   G1  also L2, J, R1 collinear with J between them: R1 - J = a (J - L2), a > 0, the moved
//       leg keeping its length (Hermite: R.t0 = a L.t1, the moved tangent keeping its length)
//   C1  a = 1: J - L2 = R1 - J (Hermite: the joint shares one tangent)
//   C2  also equal second derivatives: Bezier 6(L1 - 2L2 + L3) = 6(R0 - 2R1 + R2), so
//       R2 = L1 - 4 L2 + 4 L3; Hermite P''(1) = 6p0 - 6p1 + 2t0 + 4t1 = -6q0 + 6q1 - 4s0 - 2s1 = Q''(0)
// G1 needs the master's direction: a leg J - L2 (Hermite: a tangent) of length at most
// kDegenerateLeg times the size of what it is compared with (the larger of |J|, both legs;
// Hermite: both tangents) is rounding noise with no direction, and G1 then leaves the other
// side as it is (the joint keeps C0). Unitless, so the rule is the same at every scale.
#include "wingspline/curves/basis_matrix.h"

#include <string>
#include <vector>

namespace wingspline::curves {

enum class JointConstraint { Free, C0, G1, C1, C2 };
// "free", "C0", "G1", "C1", "C2"; anything else: 'invalid-argument'.
JointConstraint parse_joint_constraint(const std::string& name);

constexpr double kDegenerateLeg = 1e-12;

// Moves entry `index` to `to` and restores `mode` at every joint, working outwards from the
// dragged segment (each joint's master is the side nearer the drag). Moving a Bezier joint's
// end point carries its two neighbouring legs along, so the joint keeps its shape. `family`
// is Bezier or Hermite ('unsupported-curve-kind' otherwise).
std::vector<double> drag_with_constraint(const std::vector<double>& points, int dim, BasisKind family,
                                         JointConstraint mode, int index, const std::vector<double>& to);

// `mode` applied at every joint, left to right (the left side is the master).
std::vector<double> enforce_constraint(const std::vector<double>& points, int dim, BasisKind family, JointConstraint mode);

// One more segment after the last: Bezier, the last segment moved along its chord L3 - L0;
// Hermite, continuing from its end point p1 to p1 + (p1 - p0) with tangents t1, t0; then
// `mode` applied at every joint. Shared-point families (B-spline, Catmull-Rom windows of
// four) get one more point P_n = P_n-1 + (P_n-1 - P_n-3) / 2.
std::vector<double> append_segment(const std::vector<double>& points, int dim, BasisKind family, JointConstraint mode);

} // namespace wingspline::curves
