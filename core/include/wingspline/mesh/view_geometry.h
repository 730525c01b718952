#pragma once
// What a 3D view of a mesh needs from the core (issue 13 item 11): the axis-aligned
// bounding box, whose centre the view turns about, and a vertex's normal, which tells
// whether the counter-clockwise walk around the vertex is seen from its front or its back.
#include "wingspline/mesh/winged_edge.h"

#include <glm/vec3.hpp>

namespace wingspline::mesh {

struct BoundingBox {
    glm::dvec3 min{0.0}, max{0.0}; // componentwise extremes of the positions (all 0 for no vertex)
    glm::dvec3 centre() const { return 0.5 * (min + max); }
};

BoundingBox bounding_box(const WingedEdgeMesh& mesh);

// The sum of the Newell vectors (area times unit normal) of the faces around v, scaled to
// unit length: each face weighs by its area. (0, 0, 0) for an isolated vertex or faces
// whose vectors cancel. Throws Error("invalid-element") for v out of range.
glm::dvec3 vertex_normal(const WingedEdgeMesh& mesh, int32_t v);

} // namespace wingspline::mesh
