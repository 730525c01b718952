// What the 3D view asks the core: the bounding box it turns about and the
// vertex normal that tells which side of the CCW walk is seen, against analytic values.
#include <catch2/catch.hpp>

#include "wingspline/error.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/winged_edge.h"

#include <cmath>

using namespace wingspline::mesh;

namespace {
constexpr double kRelativeTolerance = 1e-12; // unitless: relative to the size of the compared value

IndexedMesh scaled_moved(IndexedMesh m, double s, glm::dvec3 t) {
    for (std::size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = s * m.positions[i] + t[static_cast<int>(i % 3)];
    return m;
}
} // namespace

TEST_CASE("bounding box of the unit cube, scaled and moved", "[mesh][view]") {
    // cube(): 6 quads on [0,1]^3, so the box is [0,1]^3 and its centre (1/2, 1/2, 1/2); a
    // scale s and a move t map the box to [t, t + s] and the centre to t + s/2.
    for (double s : {1e-8, 1.0, 1e8}) {
        const glm::dvec3 t(3.0, -7.0, 0.25);
        const BoundingBox b = bounding_box(WingedEdgeMesh::build(scaled_moved(cube(), s, t)));
        for (int k = 0; k < 3; ++k) {
            const double size = std::abs(t[k]) + s;
            CHECK(std::abs(b.min[k] - t[k]) <= kRelativeTolerance * size);
            CHECK(std::abs(b.max[k] - (t[k] + s)) <= kRelativeTolerance * size);
            CHECK(std::abs(b.centre()[k] - (t[k] + s / 2)) <= kRelativeTolerance * size);
        }
    }
}

TEST_CASE("vertex normal of a cube corner points out along the diagonal, at every scale", "[mesh][view]") {
    // Three unit squares meet at each corner, with outward normals along the three axes away
    // from the centre: their sum is (+-1, +-1, +-1), i.e. (corner - centre) / |corner - centre|.
    for (double s : {1e-90, 1e-8, 1.0, 1e8, 5e8}) { // within the mesh limits (maxCoordinate 1e9)
        const IndexedMesh m = scaled_moved(cube(), s, glm::dvec3(0.0));
        const WingedEdgeMesh w = WingedEdgeMesh::build(m);
        for (int32_t v = 0; v < w.vertex_count(); ++v) {
            const glm::dvec3 n = vertex_normal(w, v);
            for (int k = 0; k < 3; ++k) {
                const double expected = (m.positions[3 * v + k] > s / 2 ? 1.0 : -1.0) / std::sqrt(3.0);
                CHECK(std::abs(n[k] - expected) <= kRelativeTolerance);
            }
        }
    }
}

TEST_CASE("vertex normal of a flat fan is the plane's normal; out of range is refused", "[mesh][view]") {
    // open_fan(n): triangles around a hub in z = 0, CCW seen from +z, so every normal is +z.
    const WingedEdgeMesh w = WingedEdgeMesh::build(open_fan(5));
    for (int32_t v = 0; v < w.vertex_count(); ++v) {
        const glm::dvec3 n = vertex_normal(w, v);
        CHECK(std::abs(n.x) <= kRelativeTolerance);
        CHECK(std::abs(n.y) <= kRelativeTolerance);
        CHECK(std::abs(n.z - 1.0) <= kRelativeTolerance);
    }
    try {
        vertex_normal(w, w.vertex_count());
        FAIL("accepted a vertex out of range");
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == "invalid-element");
    }
}
