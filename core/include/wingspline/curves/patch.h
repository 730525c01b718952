#pragma once
// Bicubic patches (lecture 002): p(u, v) = u^T M P M^T v, u = [u^3 u^2 u 1]^T, for the
// Hermite and Bezier bases, sampled on a grid with normals and the corner twist vectors
// d^2 p / du dv.
#include "wingspline/curves/basis_matrix.h"

#include <vector>

namespace wingspline::curves {

// P is the 4x4 geometry matrix of 3D vectors: P[3*(4*i + j) + k] for row i, column j.
//  Bezier: the control points p_ij (i along u, j along v).
//  Hermite: rows [p(0,.), p(1,.), p_u(0,.), p_u(1,.)], columns [.(.,0), .(.,1), ._v(.,0), ._v(.,1)],
//    i.e. the corner points p(0,0) p(0,1) p(1,0) p(1,1) in the top-left 2x2 block, v-tangents
//    top-right, u-tangents bottom-left and the twist vectors p_uv bottom-right.
struct PatchSamples {
    int nu = 0, nv = 0;
    std::vector<double> positions; // positions[3*(nv*i + j) + k] at u = i/(nu-1), v = j/(nv-1)
    std::vector<double> normals;   // unit p_u x p_v (0 where it vanishes), same layout
    std::vector<double> du, dv;    // the partial derivatives, same layout
    std::vector<double> twists;    // p_uv at (0,0), (0,1), (1,0), (1,1): twists[3*c + k]
};
PatchSamples sample_patch(BasisKind kind, const std::vector<double>& P, int nu, int nv);

} // namespace wingspline::curves
