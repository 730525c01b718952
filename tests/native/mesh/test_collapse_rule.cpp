// collapse-edge against its rule, on random polygon meshes: a collapse is refused exactly
// when its result would not be a valid mesh, or would change the Euler characteristic or
// the number of boundary loops. The result is worked out here without the winged edge's
// operation: the face list with E renamed S, repeated neighbouring corners merged and faces
// left with fewer than three corners dropped, checked by validate_indexed() (what the page
// checks an imported file with) and built again by WingedEdgeMesh::build. The check must
// accept exactly the legal collapses, and an accepted collapse must leave that face list.
#include <catch2/catch.hpp>

#include "mesh/unrecorded.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <random>

#include <glm/vec2.hpp>
#include <string>
#include <vector>

using namespace wingspline::mesh;

namespace {

// A face as a cycle: rotated to start at its smallest corner, so two listings of one
// polygon compare equal whichever corner they start from.
std::vector<int32_t> cycle(std::vector<int32_t> c) {
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
}

std::vector<int32_t> corners(const IndexedMesh& m, int32_t f) {
    return {m.face_vertices.begin() + m.face_offsets[f], m.face_vertices.begin() + m.face_offsets[f + 1]};
}

// What collapsing S -> E (E into S) leaves, from the face set alone.
struct Expected {
    bool legal = false;
    std::string why;                        // why it is not legal (for the failure message)
    std::vector<std::vector<int32_t>> faces; // per face number: its cycle, {} for a gap or a face that goes
};

Expected expected_collapse(const WingedEdgeMesh& w, int32_t e) {
    const int32_t S = w.edge(e).start, E = w.edge(e).end;
    const IndexedMesh before = w.face_set(); // gaps: faces with no corners, vertices kept
    IndexedMesh merged;
    merged.positions = before.positions;
    Expected out;
    out.faces.resize(before.face_count());
    for (int32_t f = 0; f < before.face_count(); ++f) {
        std::vector<int32_t> c;
        for (int32_t v : corners(before, f)) {
            const int32_t x = v == E ? S : v;
            if (c.empty() || c.back() != x) c.push_back(x);
        }
        while (c.size() > 1 && c.front() == c.back()) c.pop_back();
        if (c.size() < 3) continue;
        merged.add_face(c.data(), static_cast<int32_t>(c.size()));
        out.faces[f] = cycle(c);
    }
    // Valid as the page's import checks a file (validateMesh: every problem), and held by the
    // winged edge.
    const ValidationReport report = validate_indexed(merged);
    if (!report.ok()) {
        out.why = "invalid: " + report.first_error()->message;
        return out;
    }
    MeshCounts after;
    try {
        after = WingedEdgeMesh::build(merged).counts();
    } catch (const InvalidMesh& err) {
        out.why = std::string("invalid: ") + err.what();
        return out;
    }
    // The rebuilt mesh holds every row: the gaps and E as isolated vertices, not counted.
    int32_t gaps = 1;
    for (int32_t v = 0; v < w.vertex_count(); ++v) gaps += w.is_deleted(Vertex(v));
    const MeshCounts now = w.counts();
    const int32_t chi_after = after.vertices - gaps - after.edges + after.faces;
    if (chi_after != now.euler()) {
        out.why = "Euler characteristic " + std::to_string(now.euler()) + " -> " + std::to_string(chi_after);
        return out;
    }
    if (after.boundary_loops != now.boundary_loops) {
        out.why = "boundary loops " + std::to_string(now.boundary_loops) + " -> " + std::to_string(after.boundary_loops);
        return out;
    }
    out.legal = true;
    return out;
}

// ---------------------------------------------------------------- random polygon meshes
IndexedMesh quads(int32_t nx, int32_t ny, bool wrap_x, bool wrap_y, bool hole) {
    // An nx x ny grid of quads; wrapped in x and y it is a torus; `hole` leaves out the
    // middle quad (an annulus: two boundary loops).
    IndexedMesh m;
    const int32_t cols = wrap_x ? nx : nx + 1, rows = wrap_y ? ny : ny + 1;
    for (int32_t j = 0; j < rows; ++j)
        for (int32_t i = 0; i < cols; ++i) m.add_vertex(i, j, (i * 7 + j * 3) % 5 * 0.1);
    const auto at = [&](int32_t i, int32_t j) { return (j % rows) * cols + (i % cols); };
    for (int32_t j = 0; j < ny; ++j)
        for (int32_t i = 0; i < nx; ++i) {
            if (hole && i == nx / 2 && j == ny / 2) continue;
            m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

IndexedMesh two_components() {
    IndexedMesh m = tetrahedron();
    const IndexedMesh g = grid(2, 2);
    const int32_t offset = m.vertex_count();
    m.positions.insert(m.positions.end(), g.positions.begin(), g.positions.end());
    for (int32_t f = 0; f < g.face_count(); ++f) {
        std::vector<int32_t> c = corners(g, f);
        for (int32_t& v : c) v += offset;
        m.add_face(c.data(), static_cast<int32_t>(c.size()));
    }
    return m;
}

std::vector<WingedEdgeMesh> starting_meshes() {
    const NamedMesh lecture = lecture_example(), foley = foley_example();
    std::vector<WingedEdgeMesh> out;
    for (const IndexedMesh& m : {tetrahedron(), cube(), uv_sphere(6, 4), grid(3, 2), open_fan(5), quads(3, 3, false, false, false),
                                 quads(3, 3, false, false, true), quads(4, 3, true, true, false), quads(4, 2, true, false, false),
                                 two_components()})
        out.push_back(WingedEdgeMesh::build(m));
    out.push_back(WingedEdgeMesh::build(lecture.mesh, lecture.options));
    out.push_back(WingedEdgeMesh::build(foley.mesh, foley.options));
    return out;
}

// A few random operations the mesh's checks allow (joins make polygons and vertices of
// valence 2, splits long faces, pokes fans); collapses too, so the meshes have gaps.
void random_edits(WingedEdgeMesh& w, std::mt19937& rng, int count) {
    const auto pick = [&](int32_t n) { return static_cast<int32_t>(rng() % static_cast<uint32_t>(n)); };
    for (int i = 0; i < count; ++i) {
        switch (rng() % 6) {
        case 0: apply_unrecorded(w, operation("split-edge", Edge(pick(w.edge_count())), 0.25 + 0.5 * (rng() % 3) / 2.0)); break;
        case 1: {
            const int32_t f = pick(w.face_count());
            if (w.is_deleted(Face(f))) break;
            const std::vector<int32_t> c = w.vertices_of_face(f);
            apply_unrecorded(w, operation("split-face", Face(f), Vertex(c[pick(static_cast<int32_t>(c.size()))]), Vertex(c[pick(static_cast<int32_t>(c.size()))])));
            break;
        }
        case 2:
        case 3: apply_unrecorded(w, operation("join-faces", Edge(pick(w.edge_count())))); break;
        case 4: apply_unrecorded(w, operation("flip-edge", Edge(pick(w.edge_count())))); break;
        default:
            if (rng() % 3 == 0) apply_unrecorded(w, operation("poke-face", Face(pick(w.face_count()))));
            else apply_unrecorded(w, operation("collapse-edge", Edge(pick(w.edge_count())), 0.5));
        }
    }
    if (rng() % 2 == 0) w.compact();
}

} // namespace

TEST_CASE("collapse-edge is refused exactly when the result would be invalid or change chi or the boundary loops",
          "[mesh][euler][collapse]") {
    const std::vector<WingedEdgeMesh> start = starting_meshes();
    // 3000 meshes, every live edge (600 in the sanitizer build).
#ifdef WINGSPLINE_SANITIZED
    constexpr uint32_t kMeshes = 600;
#else
    constexpr uint32_t kMeshes = 3000;
#endif
    int64_t legal = 0, illegal = 0, polygon_meshes = 0, formerly_refused = 0;
    for (uint32_t seed = 1; seed <= kMeshes; ++seed) {
        std::mt19937 rng(seed);
        WingedEdgeMesh w = start[seed % start.size()];
        random_edits(w, rng, static_cast<int>(rng() % 30));
        REQUIRE(w.validate().ok());
        bool polygons = false;
        for (int32_t f = 0; f < w.face_count(); ++f) polygons |= !w.is_deleted(Face(f)) && w.vertices_of_face(f).size() > 3;
        polygon_meshes += polygons;
        for (int32_t e = 0; e < w.edge_count(); ++e) {
            if (w.is_deleted(Edge(e))) continue;
            const Expected want = expected_collapse(w, e);
            const CheckResult verdict = w.check(operation("collapse-edge", Edge(e), 0.5));
            INFO("seed " << seed << " collapse " << edge_label(e) << ": " << verdict.code << " " << verdict.message << " / "
                         << (want.legal ? "legal" : want.why));
            REQUIRE(verdict.ok == want.legal);
            if (!verdict.ok) {
                ++illegal;
                continue;
            }
            ++legal;
            WingedEdgeMesh after = w;
            after.apply(operation("collapse-edge", Edge(e), 0.5));
            const ValidationReport rep = after.validate();
            INFO((rep.first_error() ? rep.first_error()->message : std::string()));
            REQUIRE(rep.ok());
            const IndexedMesh got = after.face_set();
            REQUIRE(got.face_count() == static_cast<int32_t>(want.faces.size()));
            for (int32_t f = 0; f < got.face_count(); ++f) {
                INFO(face_label(f));
                CHECK(after.is_deleted(Face(f)) == want.faces[f].empty());
                if (!after.is_deleted(Face(f))) CHECK(cycle(corners(got, f)) == want.faces[f]);
            }
            // Accepted although a triangle side's third corner had three edges, all inside:
            // what the former rule (four edges needed) refused.
            for (const int32_t f : {w.edge(e).left, w.edge(e).right}) {
                if (f == kNone || w.vertices_of_face(f).size() != 3) continue;
                for (const int32_t c : w.vertices_of_face(f)) {
                    if (c == w.edge(e).start || c == w.edge(e).end) continue;
                    const std::vector<int32_t> ring = w.edges_around_vertex(c);
                    const bool inside = std::all_of(ring.begin(), ring.end(), [&](int32_t x) { return w.edge(x).left != kNone && w.edge(x).right != kNone; });
                    formerly_refused += ring.size() == 3 && inside;
                }
            }
        }
    }
    INFO(legal << " legal collapses (" << formerly_refused << " of them refused by the former rule), " << illegal << " refused, on " << kMeshes << " meshes (" << polygon_meshes << " with polygons)");
    CHECK(legal > 10 * kMeshes);
    CHECK(illegal > kMeshes);
    CHECK(polygon_meshes > kMeshes / 2);
    CHECK(formerly_refused > 0);
}

TEST_CASE("collapse-edge keeps a vertex of valence 2 between two polygons, as join-faces makes one", "[mesh][euler][collapse]") {
    //   v4 (-1,1)        v5 (1,1)       F1 = (v1 v2 v3), F2 = (v3 v2 v5 v4), F3 = (v3 v4 v6 v1).
    //        \  F2     /                v3 has three edges (to v1, v2, v4). Collapsing e1 = v1-v2
    //   F3    v3 (0,0)- v2 (1,0)        takes F1 with it and leaves v3 with two edges, between
    //        /   F1  /                  the quads (v3 v1 v5 v4) and (v3 v4 v6 v1): a valid mesh,
    //   v6 (-1,-1)  v1 (0,-1)           as joinFaces makes from the same start.
    IndexedMesh m;
    for (const auto& p : {glm::dvec2(0, -1), glm::dvec2(1, 0), glm::dvec2(0, 0), glm::dvec2(-1, 1), glm::dvec2(1, 1), glm::dvec2(-1, -1)})
        m.add_vertex(p.x, p.y, 0);
    m.add_face({0, 1, 2});
    m.add_face({2, 1, 4, 3});
    m.add_face({2, 3, 5, 0});
    WingedEdgeMesh w = WingedEdgeMesh::build(m);
    REQUIRE(w.edge(0).start == 0);
    REQUIRE(w.edge(0).end == 1);
    const CheckResult verdict = w.check(operation("collapse-edge", Edge(0), 0.5));
    INFO(verdict.code << " " << verdict.message);
    REQUIRE(verdict.ok);
    w.apply(operation("collapse-edge", Edge(0), 0.5));
    REQUIRE(w.validate().ok());
    const IndexedMesh got = w.live_face_set();
    REQUIRE(got.face_count() == 2);
    // v2 merged into v1 (v1 keeps its number); live vertices renumbered: v3 -> 1, v4 -> 2, v5 -> 3, v6 -> 4.
    CHECK(cycle(corners(got, 0)) == cycle({1, 0, 3, 2}));
    CHECK(cycle(corners(got, 1)) == cycle({1, 2, 4, 0}));
    const MeshCounts k = w.counts();
    CHECK((k.vertices == 5 && k.edges == 6 && k.faces == 2 && k.boundary_loops == 1));
}
