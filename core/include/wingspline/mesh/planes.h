#pragma once
// Plane equations Ax + By + Cz + D = 0 of the faces: from three vertices by the cross
// product P1P2 x P1P3 (lecture 001) and by Newell's formula over all vertices (lecture 003,
// A = 1/2 sum (z_i + z_i+1)(y_i - y_i+1), ...), with the planarity residual.
#include "wingspline/mesh/winged_edge.h"

#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace wingspline::mesh {

struct FacePlane {
    glm::dvec4 cross;  // (A, B, C) = P1P2 x P1P3 of the first three vertices; D by substitution of P1
    glm::dvec4 newell; // (A, B, C) = Newell's sums (half the cross product for a triangle); D through the centroid
    double residual;   // max distance of a vertex from the Newell plane (same units as positions)
};

// Newell's (A, B, C) of the polygon corners[0..n) with positions[3*v + k].
glm::dvec3 newell_vector(const double* positions, const int32_t* corners, int32_t n);

std::vector<FacePlane> face_planes(const WingedEdgeMesh& mesh);
// Unit normals by Newell's method, normals[3*f + k]; a degenerate face gets (0, 0, 0).
void newell_normals(const WingedEdgeMesh& mesh, std::vector<double>& normals);
// The same into out[0 .. 3F), which the caller owns (no allocation, no zero fill).
void newell_normals(const WingedEdgeMesh& mesh, double* out);

} // namespace wingspline::mesh
