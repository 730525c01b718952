#include "wingspline/mesh/view_geometry.h"

#include "wingspline/error.h"
#include "wingspline/mesh/planes.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

namespace wingspline::mesh {

BoundingBox bounding_box(const WingedEdgeMesh& mesh) {
    // Over the live vertices: a vertex removed by an edit keeps its row but is not drawn.
    BoundingBox box;
    const int32_t n = mesh.vertex_count();
    int32_t v0 = 0;
    while (v0 < n && mesh.is_deleted(Vertex(v0))) ++v0;
    if (v0 == n) return box;
    box.min = box.max = mesh.position(v0);
    for (int32_t v = v0 + 1; v < n; ++v) {
        if (mesh.is_deleted(Vertex(v))) continue;
        const glm::dvec3 p = mesh.position(v);
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return box;
}

glm::dvec3 vertex_normal(const WingedEdgeMesh& mesh, int32_t v) {
    if (v < 0 || v >= mesh.vertex_count())
        throw Error("invalid-element", "vertex index " + std::to_string(v) + " is out of range: the mesh has vertices 0 to " +
                                           std::to_string(mesh.vertex_count() - 1));
    if (mesh.is_deleted(Vertex(v)))
        throw Error("deleted-element", vertex_label(v) + " was removed by an edit (its number stays a gap until the mesh is compacted)");
    glm::dvec3 sum(0.0);
    for (int32_t f : mesh.faces_around_vertex(v)) {
        const std::vector<int32_t> c = mesh.vertices_of_face(f);
        const glm::dvec3 n = newell_vector(mesh.positions().data(), c.data(), static_cast<int32_t>(c.size()));
        sum += n;
    }
    // Divided by its largest component first, so a tiny sum does not underflow in length().
    const double big = std::max({std::abs(sum.x), std::abs(sum.y), std::abs(sum.z)});
    if (!(big > 0)) return glm::dvec3(0.0);
    const glm::dvec3 s = sum / big;
    return s / glm::length(s);
}

} // namespace wingspline::mesh
