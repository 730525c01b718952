#pragma once
// Plane equations Ax + By + Cz + D = 0 of the faces: from three vertices by the cross
// product P1P2 x P1P3 (lecture 001) and by Newell's formula over all vertices (lecture 003,
// A = 1/2 sum (z_i + z_i+1)(y_i - y_i+1), ...), with the planarity residual.
#include "wingspline/mesh/winged_edge.h"

#include <array>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace wingspline::mesh {

struct FacePlane {
    glm::dvec4 cross;  // (A, B, C) = P1P2 x P1P3 of the face's first three corners; D by substitution of P1
    std::array<int32_t, 3> cross_corners; // the vertices used as P1, P2, P3 (so a lesson can show them)
    glm::dvec4 newell; // (A, B, C) = Newell's sums (half the cross product for a triangle); D through the centroid
    double residual;   // max distance of a vertex from the Newell plane (same units as positions)
    // Newell's unit normal (A, B, C) / |(A, B, C)|; (0, 0, 0) for a degenerate face.
    glm::dvec3 unit_normal() const {
        const glm::dvec3 n(newell);
        const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        return len > 0 ? n / len : glm::dvec3(0.0);
    }
};

// Newell's (A, B, C) of the polygon corners[0..n) with positions[3*v + k].
glm::dvec3 newell_vector(const double* positions, const int32_t* corners, int32_t n);

// The planes of the faces as given: face f's corners are face_vertices[face_offsets[f] ..
// face_offsets[f+1]) in the order the mesh was built from (P1, P2, P3 = its first three
// corners, lecture 001), positions the winged edge's current ones. Throws
// Error("mismatched-face-set") when the face set does not have the mesh's face count.
std::vector<FacePlane> face_planes(const WingedEdgeMesh& mesh, const std::vector<int32_t>& face_offsets,
                                   const std::vector<int32_t>& face_vertices);
// The same with each face read back from the winged edge (from its stored edge): the faces
// as given only when the mesh was built with the default face edges.
std::vector<FacePlane> face_planes(const WingedEdgeMesh& mesh);
// The planes of faces first .. first + count - 1 alone (each face as face_set() lists it,
// read by face_corners: O(their sides), whatever the mesh's size): what a table shows for
// the rows in view. Throws Error("invalid-element") for a range outside the faces.
std::vector<FacePlane> face_planes(const WingedEdgeMesh& mesh, int32_t first, int32_t count);
// Unit normals by Newell's method, normals[3*f + k]; a degenerate face gets (0, 0, 0).
void newell_normals(const WingedEdgeMesh& mesh, std::vector<double>& normals);
// The same into out[0 .. 3F), which the caller owns (no allocation, no zero fill).
// (The fast kernel, fast_kernels.cpp; the same normals as newell_normals_reference.)
void newell_normals(const WingedEdgeMesh& mesh, double* out);
// The lecture's path: each face's corners read by the face walk, newell_vector of them,
// divided by its length. Slower; the tests check newell_normals against it.
void newell_normals_reference(const WingedEdgeMesh& mesh, std::vector<double>& normals);

} // namespace wingspline::mesh
