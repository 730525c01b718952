#pragma once
// What a 3D view of a mesh needs from the core: the axis-aligned
// bounding box, whose centre the view turns about, and a vertex's normal, which tells
// whether the counter-clockwise walk around the vertex is seen from its front or its back.
#include "wingspline/mesh/winged_edge.h"

#include <glm/vec3.hpp>

#include <vector>

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

// Picking in an orthographic view: the faces seen along the view direction.
// `towards` points from the mesh to the viewer (any length > 0); `point` is any point on the
// line of sight through the pointer. A face is hit where the line passes inside its outline
// projected on the view plane (the crossing-number test, half-open so a point on a side
// shared by two faces is inside exactly one); `face` is the hit face nearest the viewer,
// its depth taken on the first fan triangle (v0, vi, vi+1) containing the point (-1: none).
// `near` lists the faces whose projection comes within `radius` (world units, measured in
// the view plane) of the line: the hit face first, then faces turned towards the viewer by
// distance (a face turned away is hidden behind the front of a closed mesh), at most
// `max_near`. Removed faces are skipped. Every comparison is of lengths in the view
// plane, so the answer does not change when the mesh, point and radius are moved,
// turned or scaled together. Throws Error("invalid-argument") for a zero or non-finite
// direction, a negative or non-finite radius or point.
struct PickNear {
    int32_t face;
    double distance; // world units in the view plane; 0: the line passes through the face
};
struct PickResult {
    int32_t face = -1;
    std::vector<PickNear> near;
};
PickResult pick_faces(const WingedEdgeMesh& mesh, const glm::dvec3& point, const glm::dvec3& towards, double radius,
                      int32_t max_near);

// The same pick, many times at one view of a big mesh: the vertices' coordinates in the view
// plane and a uniform grid of the edges' boxes there (about eight edges per cell), made once per
// mesh version and view direction (build: O(V + E)); each pick then reads the edges in the
// cells along its half-line and within its radius, O(sqrt(E)) for an even mesh instead of
// O(V + E), and answers exactly as pick_faces (tests/native/mesh/test_picking.cpp compares
// them on random points, radii and views). `fits` says whether it was built for this mesh's
// version and this direction (the caller keeps one per mesh and builds it again when not).
class PickGrid {
public:
    bool fits(const WingedEdgeMesh& mesh, const glm::dvec3& towards) const;
    // Throws as pick_faces for a bad direction.
    void build(const WingedEdgeMesh& mesh, const glm::dvec3& towards);
    // `mesh` must be the one it was built for, unchanged (fits). Throws as pick_faces.
    PickResult pick(const WingedEdgeMesh& mesh, const glm::dvec3& point, double radius, int32_t max_near);
    std::size_t bytes() const;

private:
    int32_t column(double x) const;
    int32_t row(double y) const;
    bool built_ = false;
    MeshVersion version_;
    glm::dvec3 towards_{0.0};
    int32_t vertices_ = 0;
    glm::dvec3 n_{0.0}, a_{0.0}, b_{0.0};
    std::vector<double> pa_, pb_; // each vertex's view-plane coordinates
    double x0_ = 0, y0_ = 0, h_ = 1;
    int32_t nx_ = 1, ny_ = 1;
    std::vector<int32_t> cell_start_, cell_edges_; // CSR: the edges of cell (row y, column x) at y nx + x
    std::vector<char> odd_;                        // per face, the crossings' parity during a pick (0 between picks)
};

// A lighter picture of a big mesh for drawing while the view moves: vertex
// clustering (Rossignac and Borrel 1993). The bounding box is cut into cubic cells of side
// `cell`; each occupied cell becomes one vertex at the mean of its vertices; each fan
// triangle of each face becomes a triangle of cells, dropped when two corners share a cell.
// `cell` is chosen (from the box's size, then refined) so that about `target_triangles`
// remain; a mesh with no more triangles than that, or one whose clustering keeps under an
// eighth of them (a strip thinner than a cell), is returned as its own fan triangles with
// cell 0. Every proxy vertex lies within one cell diagonal of a vertex of the mesh.
struct DisplayProxy {
    std::vector<double> positions;  // xyz per proxy vertex
    std::vector<int32_t> triangles; // three proxy vertices per triangle
    double cell = 0;                // the cell side used (0: the mesh itself)
};
DisplayProxy display_proxy(const WingedEdgeMesh& mesh, int32_t target_triangles);

} // namespace wingspline::mesh
