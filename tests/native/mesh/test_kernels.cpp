// The fast kernels (core/src/mesh/fast_kernels.cpp) against the lecture's reference path
// (docs/architecture.md, "Teaching path and fast kernels"), on thousands of random seeded
// meshes of mixed face degrees (3, 4, 6, 8), with holes and boundaries, isolated vertices,
// shuffled vertex and face numbers and rotated corners; some of them (a reversed face, a
// hole that leaves a bow-tie) are refused, and must be refused alike.
#include <catch2/catch.hpp>

#include "../../../core/src/mesh/fast_kernels.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace wingspline::mesh;

namespace {

// A jittered (nx+1) x (ny+1) grid of vertices; each cell is a quad, two triangles (either
// diagonal), the start of a hexagon or octagon spanning 2 or 3 cells of its row, or a hole.
// Then extra unused vertices, the vertex numbers shuffled, the faces shuffled and each
// face's corners rotated. With `flip`, one face is reversed (the mesh is then not oriented).
IndexedMesh random_mesh(std::mt19937& rng, bool flip) {
    std::uniform_int_distribution<int> size(1, 7);
    const int nx = size(rng), ny = size(rng);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3), unit(0.0, 1.0);
    const int grid_vertices = (nx + 1) * (ny + 1);
    const int extra = std::uniform_int_distribution<int>(0, 2)(rng);
    const int V = grid_vertices + extra;
    std::vector<int32_t> number(V);
    std::iota(number.begin(), number.end(), 0);
    std::shuffle(number.begin(), number.end(), rng);
    const auto at = [&](int i, int j) { return number[j * (nx + 1) + i]; };
    std::vector<std::vector<int32_t>> faces;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx;) {
            const double u = unit(rng);
            const int span = std::min(nx - i, u < 0.15 ? 3 : u < 0.35 ? 2 : 1);
            if (u > 0.93) { // a hole
                i += 1;
                continue;
            }
            if (span > 1) { // along the bottom row of `span` cells, back along the top
                std::vector<int32_t> f;
                for (int k = 0; k <= span; ++k) f.push_back(at(i + k, j));
                for (int k = span; k >= 0; --k) f.push_back(at(i + k, j + 1));
                faces.push_back(f);
            } else if (u < 0.65) {
                faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            } else if (u < 0.8) {
                faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                faces.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                faces.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
            i += span;
        }
    }
    if (faces.empty()) faces.push_back({at(0, 0), at(1, 0), at(1, 1)});
    std::shuffle(faces.begin(), faces.end(), rng);
    for (auto& f : faces) std::rotate(f.begin(), f.begin() + std::uniform_int_distribution<std::size_t>(0, f.size() - 1)(rng), f.end());
    if (flip) std::reverse(faces[0].begin(), faces[0].end());
    IndexedMesh m;
    m.positions.resize(3 * static_cast<std::size_t>(V));
    for (int v = 0; v < V; ++v) {
        const int i = v % (nx + 1), j = v / (nx + 1);
        const int32_t n = number[v]; // v >= grid_vertices: an extra vertex no face uses
        m.positions[3 * n] = i + jitter(rng);
        m.positions[3 * n + 1] = j + jitter(rng);
        m.positions[3 * n + 2] = 0.5 * jitter(rng);
    }
    m.face_offsets.assign(1, 0);
    for (const auto& f : faces) {
        m.face_vertices.insert(m.face_vertices.end(), f.begin(), f.end());
        m.face_offsets.push_back(static_cast<int32_t>(m.face_vertices.size()));
    }
    return m;
}

// Closed meshes too (every edge has two faces): shuffled spheres, cube, tetrahedron.
IndexedMesh random_closed_mesh(std::mt19937& rng) {
    const int kind = std::uniform_int_distribution<int>(0, 2)(rng);
    IndexedMesh m = kind == 0 ? uv_sphere(std::uniform_int_distribution<int>(3, 12)(rng), std::uniform_int_distribution<int>(2, 8)(rng))
                    : kind == 1 ? cube()
                                : tetrahedron();
    const int32_t V = m.vertex_count();
    std::vector<int32_t> number(V);
    std::iota(number.begin(), number.end(), 0);
    std::shuffle(number.begin(), number.end(), rng);
    std::vector<double> moved(m.positions.size());
    for (int32_t v = 0; v < V; ++v)
        for (int k = 0; k < 3; ++k) moved[3 * number[v] + k] = m.positions[3 * v + k];
    m.positions = moved;
    for (int32_t& c : m.face_vertices) c = number[c];
    return m;
}

// "" if built, else the codes of the refusal's problems.
std::string refusal(const IndexedMesh& mesh, bool fast, WingedEdgeMesh& out) {
    try {
        out = fast ? WingedEdgeMesh::build(mesh) : WingedEdgeMesh::build_reference(mesh);
        return "";
    } catch (const InvalidMesh& e) {
        std::string codes;
        for (const Problem& p : e.report().problems) codes += p.code + " ";
        return codes.empty() ? "(no problem listed)" : codes;
    }
}

void require_same_tables(const WingedEdgeMesh& fast, const WingedEdgeMesh& ref) {
    REQUIRE(fast.vertex_count() == ref.vertex_count());
    REQUIRE(fast.edge_count() == ref.edge_count());
    REQUIRE(fast.face_count() == ref.face_count());
    for (int32_t e = 0; e < ref.edge_count(); ++e) {
        const EdgeRecord& a = fast.edge(e);
        const EdgeRecord& b = ref.edge(e);
        INFO("edge " << e);
        REQUIRE(std::vector<int32_t>{a.start, a.end, a.left, a.right, a.start_left, a.start_right, a.end_left, a.end_right} ==
                std::vector<int32_t>{b.start, b.end, b.left, b.right, b.start_left, b.start_right, b.end_left, b.end_right});
    }
    for (int32_t v = 0; v < ref.vertex_count(); ++v) REQUIRE(fast.vertex_edge(v) == ref.vertex_edge(v));
    for (int32_t f = 0; f < ref.face_count(); ++f) REQUIRE(fast.face_edge(f) == ref.face_edge(f));
    REQUIRE(fast.positions() == ref.positions());
}

// The fast ring walk meets, vertex by vertex, the edges edges_around_vertex lists and the
// neighbours vertices_around_vertex lists, in the same order; the fast face walk meets the
// sides between consecutive corners of vertices_of_face.
void require_same_walks(const WingedEdgeMesh& m) {
    std::vector<std::vector<int32_t>> ring_edges(m.vertex_count()), ring_neighbours(m.vertex_count());
    detail::walk_every_ring_fast(m, [&](int32_t v, int32_t e, int32_t w) {
        ring_edges[v].push_back(e);
        ring_neighbours[v].push_back(w);
    });
    double visited = 0, neighbour_sum = 0;
    for (int32_t v = 0; v < m.vertex_count(); ++v) {
        INFO("vertex " << v);
        REQUIRE(ring_edges[v] == m.edges_around_vertex(v));
        REQUIRE(ring_neighbours[v] == m.vertices_around_vertex(v));
        visited += static_cast<double>(ring_edges[v].size());
        for (int32_t w : ring_neighbours[v]) neighbour_sum += w;
    }
    const RingWalkTotals totals = m.walk_every_ring();
    REQUIRE(totals.visited == visited);
    REQUIRE(totals.neighbour_sum == neighbour_sum);
    for (int32_t f = 0; f < m.face_count(); ++f) {
        std::vector<int32_t> sides;
        detail::walk_face_sides_fast(m.edges().data(), m.face_edge(f), f, [&](int32_t a, int32_t b) {
            sides.push_back(a);
            sides.push_back(b);
        });
        const std::vector<int32_t> c = m.vertices_of_face(f);
        std::vector<int32_t> expected;
        for (std::size_t i = 0; i < c.size(); ++i) {
            expected.push_back(c[i]);
            expected.push_back(c[(i + 1) % c.size()]);
        }
        INFO("face " << f);
        REQUIRE(sides == expected);
    }
}

// Fast normals equal the reference (lecture 003's Newell vector of the corners, scaled to
// unit length) to rounding: both sum the same terms in the same order and differ only in
// how they divide by the length. Tolerance: 4 ulp of 1 per component (they are unit vectors).
void require_same_normals(const WingedEdgeMesh& m) {
    std::vector<double> fast, ref;
    newell_normals(m, fast);
    newell_normals_reference(m, ref);
    REQUIRE(fast.size() == ref.size());
    const double tolerance = 4 * std::numeric_limits<double>::epsilon();
    for (std::size_t i = 0; i < ref.size(); ++i) {
        INFO("normal component " << i);
        REQUIRE(std::abs(fast[i] - ref[i]) <= tolerance);
    }
}

} // namespace

TEST_CASE("fast build, ring walk, face walk and normals agree with the lecture's path on 3000 random meshes",
          "[mesh][kernels]") {
    std::mt19937 rng(20240614);
    int built = 0, refused = 0, with_boundary = 0, mixed = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        INFO("trial " << trial);
        const bool closed = trial % 5 == 4;
        const IndexedMesh mesh = closed ? random_closed_mesh(rng) : random_mesh(rng, trial % 11 == 3);
        WingedEdgeMesh fast, ref;
        const std::string fast_refusal = refusal(mesh, true, fast);
        const std::string ref_refusal = refusal(mesh, false, ref);
        REQUIRE(fast_refusal == ref_refusal);
        if (!fast_refusal.empty()) {
            ++refused;
            continue;
        }
        ++built;
        with_boundary += fast.counts().boundary_edges > 0;
        int degrees = 0;
        for (int32_t f = 0; f < mesh.face_count(); ++f) degrees |= 1 << std::min(mesh.face_offsets[f + 1] - mesh.face_offsets[f], 9);
        mixed += (degrees & (1 << 3)) && (degrees & ~(1 << 3));
        require_same_tables(fast, ref);
        REQUIRE(fast.validate().problems.size() == static_cast<std::size_t>(fast.counts().isolated_vertices));
        require_same_walks(fast);
        require_same_normals(fast);
    }
    // The generator covers what it claims (else the agreement above would prove little).
    CHECK(built > 2000);
    CHECK(refused > 100);
    CHECK(with_boundary > 1500);
    CHECK(mixed > 1000);
}

TEST_CASE("the reference build reproduces the lecture's tables with the slide's numbering", "[mesh][kernels]") {
    const NamedMesh lecture = lecture_example();
    const WingedEdgeMesh ref = WingedEdgeMesh::build_reference(lecture.mesh, lecture.options);
    // The slide (lecture 000): e1 = [v1, v3], R = F1, wings e2 e2 e4 e3 (0-based below).
    const EdgeRecord& e1 = ref.edge(0);
    REQUIRE(std::vector<int32_t>{e1.start, e1.end, e1.left, e1.right, e1.start_left, e1.start_right, e1.end_left, e1.end_right} ==
            std::vector<int32_t>{0, 2, kNone, 0, 1, 1, 3, 2});
    require_same_tables(WingedEdgeMesh::build(lecture.mesh, lecture.options), ref);
}

TEST_CASE("fast and reference normals agree at every scale (1e-6 and 1e6 times a random mesh)", "[mesh][kernels]") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        IndexedMesh mesh = random_mesh(rng, false);
        const double scale = trial % 2 ? 1e-6 : 1e6;
        for (double& c : mesh.positions) c *= scale;
        WingedEdgeMesh m;
        if (!refusal(mesh, true, m).empty()) continue;
        require_same_normals(m);
    }
}
