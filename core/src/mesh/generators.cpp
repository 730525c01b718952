#include "wingspline/mesh/generators.h"

#include <cmath>
#include <string>

namespace wingspline::mesh {

namespace {
constexpr double kPi = 3.14159265358979323846;

// docs/benchmarks.md: "vertex coordinates written/used with 6 decimals".
double six_decimals(double x) { return std::round(x * 1e6) / 1e6; }

void require_range(int32_t value, int32_t lo, int32_t hi, const char* what) {
    require(value >= lo && value <= hi, "invalid-argument",
            std::string(what) + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                ", not " + std::to_string(value));
}
} // namespace

NamedMesh lecture_example() {
    NamedMesh n;
    IndexedMesh& m = n.mesh;
    m.add_vertex(0, 1, 0);  // v1
    m.add_vertex(1, 0, 0);  // v2
    m.add_vertex(1, 2, 0);  // v3
    m.add_vertex(2, 1, 0);  // v4
    m.add_vertex(2, -1, 0); // v5
    m.add_face({0, 1, 2});  // F1 = (v1 v2 v3)
    m.add_face({1, 3, 2});  // F2 = (v2 v4 v3)
    m.add_face({1, 4, 3});  // F3 = (v2 v5 v4)
    // The slide's edge table, S and E columns: e1 = v1->v3 ... e7 = v4->v5.
    n.options.edges = {{0, 2}, {0, 1}, {1, 2}, {2, 3}, {1, 3}, {1, 4}, {3, 4}};
    // The slide's vertex table (v1 e1, v2 e6, v3 e3, v4 e5, v5 e6) and face table (e1, e3, e5).
    n.options.vertex_edges = {0, 5, 2, 4, 5};
    n.options.face_edges = {0, 2, 4};
    return n;
}

NamedMesh foley_example() {
    NamedMesh n;
    IndexedMesh& m = n.mesh;
    m.add_vertex(0, 1, 0); // V1
    m.add_vertex(1, 0, 0); // V2
    m.add_vertex(2, 1, 0); // V3
    m.add_vertex(1, 2, 0); // V4
    m.add_face({0, 1, 3}); // P1 = (1, 2, 4)
    m.add_face({3, 1, 2}); // P2 = (4, 2, 3)
    // E1 = (V1, V2), E2 = (V2, V3), E3 = (V3, V4), E4 = (V4, V2), E5 = (V4, V1).
    n.options.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 1}, {3, 0}};
    // Foley lists P2 = (E2, E3, E4): its walk starts at E2, not at its first side V4-V2.
    n.options.face_edges = {0, 1};
    return n;
}

IndexedMesh tetrahedron() {
    IndexedMesh m;
    m.add_vertex(1, 1, 1);
    m.add_vertex(1, -1, -1);
    m.add_vertex(-1, 1, -1);
    m.add_vertex(-1, -1, 1);
    m.add_face({0, 1, 2});
    m.add_face({0, 3, 1});
    m.add_face({0, 2, 3});
    m.add_face({1, 3, 2});
    return m;
}

IndexedMesh cube() {
    IndexedMesh m;
    for (int i = 0; i < 8; ++i) m.add_vertex(i & 1, (i >> 1) & 1, (i >> 2) & 1); // index = x + 2y + 4z
    m.add_face({0, 2, 3, 1}); // z = 0
    m.add_face({4, 5, 7, 6}); // z = 1
    m.add_face({0, 1, 5, 4}); // y = 0
    m.add_face({2, 6, 7, 3}); // y = 1
    m.add_face({0, 4, 6, 2}); // x = 0
    m.add_face({1, 3, 7, 5}); // x = 1
    return m;
}

IndexedMesh open_fan(int32_t n) {
    require_range(n, 1, 100000, "the number of fan triangles");
    IndexedMesh m;
    m.add_vertex(0, 0, 0);
    for (int32_t k = 0; k <= n; ++k) {
        const double a = 1.5 * kPi * k / n;
        m.add_vertex(six_decimals(std::cos(a)), six_decimals(std::sin(a)), 0);
    }
    for (int32_t k = 1; k <= n; ++k) m.add_face({0, k, k + 1});
    return m;
}

IndexedMesh grid(int32_t nx, int32_t ny) {
    require_range(nx, 1, 4000, "nx");
    require_range(ny, 1, 4000, "ny");
    IndexedMesh m;
    m.positions.reserve(3 * static_cast<std::size_t>(nx + 1) * (ny + 1));
    for (int32_t j = 0; j <= ny; ++j)
        for (int32_t i = 0; i <= nx; ++i) {
            const double x = 2.0 * i / nx, y = 1.0 * j / ny;
            m.add_vertex(six_decimals(x), six_decimals(y), six_decimals(0.1 * std::sin(7 * x / nx) * std::cos(5 * y / ny)));
        }
    m.face_vertices.reserve(6 * static_cast<std::size_t>(nx) * ny);
    m.face_offsets.reserve(2 * static_cast<std::size_t>(nx) * ny + 1);
    for (int32_t j = 0; j < ny; ++j)
        for (int32_t i = 0; i < nx; ++i) {
            const int32_t v00 = j * (nx + 1) + i, v10 = v00 + 1, v01 = v00 + nx + 1, v11 = v01 + 1;
            m.add_face({v00, v10, v11});
            m.add_face({v00, v11, v01});
        }
    return m;
}

IndexedMesh uv_sphere(int32_t slices, int32_t stacks) {
    require_range(slices, 3, 10000, "slices");
    require_range(stacks, 2, 10000, "stacks");
    IndexedMesh m;
    const int32_t rings = stacks - 1;
    m.positions.reserve(3 * (static_cast<std::size_t>(slices) * rings + 2));
    m.add_vertex(0, 0, 1);
    for (int32_t i = 1; i <= rings; ++i) {
        const double phi = kPi * i / stacks;
        for (int32_t j = 0; j < slices; ++j) {
            const double theta = 2 * kPi * j / slices;
            m.add_vertex(six_decimals(std::sin(phi) * std::cos(theta)), six_decimals(std::sin(phi) * std::sin(theta)),
                         six_decimals(std::cos(phi)));
        }
    }
    const int32_t south = m.add_vertex(0, 0, -1);
    auto ring = [&](int32_t i, int32_t j) { return 1 + (i - 1) * slices + (j % slices); };
    m.face_vertices.reserve(6 * static_cast<std::size_t>(slices) * rings);
    m.face_offsets.reserve(2 * static_cast<std::size_t>(slices) * rings + 1);
    for (int32_t j = 0; j < slices; ++j) m.add_face({0, ring(1, j), ring(1, j + 1)});
    for (int32_t i = 1; i < rings; ++i)
        for (int32_t j = 0; j < slices; ++j) {
            const int32_t a = ring(i, j), b = ring(i, j + 1), c = ring(i + 1, j), d = ring(i + 1, j + 1);
            m.add_face({a, c, d});
            m.add_face({a, d, b});
        }
    for (int32_t j = 0; j < slices; ++j) m.add_face({ring(rings, j), south, ring(rings, j + 1)});
    return m;
}

} // namespace wingspline::mesh
