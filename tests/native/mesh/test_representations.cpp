// The four other representations of lectures 000 and 001 against the slides' tables,
// analytic storage counts, cross-representation agreement of the queries, and the
// asymptotic cost of each query (output-proportional walks versus whole-table scans).
#include <catch2/catch.hpp>

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"

#include <algorithm>
#include <string>

using namespace wingspline::mesh;

namespace {

int32_t label(const std::string& s) { return s == "-" ? kNone : std::stoi(s.substr(1)) - 1; }

struct Built {
    IndexedMesh faces;
    WingedEdgeMesh winged;
    Representations reps;
};

Built build_all(const IndexedMesh& faces, const BuildOptions& options = {}) {
    WingedEdgeMesh w = WingedEdgeMesh::build(faces, options);
    const ValidationReport r = w.validate();
    INFO((r.first_error() ? r.first_error()->message : std::string()));
    REQUIRE(r.ok());
    Representations reps = build_representations(faces, w);
    return {faces, std::move(w), std::move(reps)};
}

std::size_t corner_count(const IndexedMesh& m) { return m.face_vertices.size(); }

std::vector<int32_t> sorted(std::vector<int32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

const QueryKind kAllKinds[] = {QueryKind::FacesAroundVertex, QueryKind::EdgesAroundVertex, QueryKind::EdgesOfFace,
                               QueryKind::FacesOfEdge, QueryKind::NeighboursOfFace};

int32_t element_count(const WingedEdgeMesh& w, QueryKind kind) {
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex: return w.vertex_count();
    case QueryKind::FacesOfEdge: return w.edge_count();
    default: return w.face_count();
    }
}

// The answer from the winged edge's own traversal functions (written before the queries).
std::vector<int32_t> reference_answer(const WingedEdgeMesh& w, QueryKind kind, int32_t x) {
    switch (kind) {
    case QueryKind::FacesAroundVertex: return w.faces_around_vertex(x);
    case QueryKind::EdgesAroundVertex: return w.edges_around_vertex(x);
    case QueryKind::EdgesOfFace: return w.edges_of_face(x);
    case QueryKind::NeighboursOfFace: return w.face_neighbours(x);
    case QueryKind::FacesOfEdge: {
        std::vector<int32_t> out;
        for (int32_t f : w.faces_of_edge(x))
            if (f != kNone) out.push_back(f);
        return out;
    }
    }
    return {};
}

void check_all_queries_agree(const Built& b) {
    for (QueryKind kind : kAllKinds)
        for (int32_t x = 0; x < element_count(b.winged, kind); ++x) {
            const auto answers = answer_query(kind, x, b.reps, b.winged);
            const std::vector<int32_t> expected = sorted(reference_answer(b.winged, kind, x));
            for (int r = 0; r < kRepresentationCount; ++r) {
                INFO(representation_key(static_cast<Representation>(r)) << " kind " << static_cast<int>(kind) << " element " << x);
                CHECK(sorted(answers[r].answer) == expected);
                CHECK(answers[r].entries_read > 0);
            }
        }
}

} // namespace

TEST_CASE("lecture 000's tables: independent faces and vertex/face tables", "[mesh][representations]") {
    const NamedMesh ex = lecture_example();
    const Built b = build_all(ex.mesh, ex.options);
    // Slide: F1 (x1..)(x2..)(x3..), F2 (x2)(x4)(x3), F3 (x2)(x5)(x4).
    const int corners[3][3] = {{1, 2, 3}, {2, 4, 3}, {2, 5, 4}};
    const IndependentFaces& ind = b.reps.independent_faces;
    for (int f = 0; f < 3; ++f)
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                CHECK(ind.corner_positions[3 * (ind.face_offsets[f] + i) + k] ==
                      ex.mesh.positions[3 * (corners[f][i] - 1) + k]);
    const VertexFaceTables& t = b.reps.vertex_face_tables;
    CHECK(t.face_vertices == std::vector<int32_t>{0, 1, 2, 1, 3, 2, 1, 4, 3});
    CHECK(t.positions == ex.mesh.positions);
}

TEST_CASE("Foley's edge list, lecture 001, written literally", "[mesh][representations][foley]") {
    const NamedMesh ex = foley_example();
    const Built b = build_all(ex.mesh, ex.options);
    // E1 = (V1, V2, P1, l)  E2 = (V2, V3, P2, l)  E3 = (V3, V4, P2, l)
    // E4 = (V4, V2, P1, P2) E5 = (V4, V1, P1, l)          (l = lambda = no polygon)
    const char* slide[5][4] = {{"V1", "V2", "P1", "-"}, {"V2", "V3", "P2", "-"}, {"V3", "V4", "P2", "-"},
                               {"V4", "V2", "P1", "P2"}, {"V4", "V1", "P1", "-"}};
    const EdgeList& list = b.reps.edge_list;
    REQUIRE(list.edges.size() == 4 * 5);
    for (int e = 0; e < 5; ++e)
        for (int k = 0; k < 4; ++k) {
            INFO("E" << e + 1 << " field " << k);
            CHECK(list.edges[4 * e + k] == label(slide[e][k]));
        }
    // P1 = (E1, E4, E5), P2 = (E2, E3, E4).
    CHECK(list.polygon_offsets == std::vector<int32_t>{0, 3, 6});
    CHECK(list.polygon_edges == std::vector<int32_t>{0, 3, 4, 1, 2, 3});
}

TEST_CASE("adjacency lists: the lecture example's relations", "[mesh][representations]") {
    const NamedMesh ex = lecture_example();
    const Built b = build_all(ex.mesh, ex.options);
    const AdjacencyLists& adj = b.reps.adjacency_lists;
    auto list = [](const std::vector<int32_t>& off, const std::vector<int32_t>& items, int32_t i) {
        return std::vector<int32_t>(items.begin() + off[i], items.begin() + off[i + 1]);
    };
    // v2 touches e2, e3, e5, e6 (slide), neighbours v1, v3, v4, v5, faces F1, F2, F3.
    CHECK(list(adj.vertex_offsets, adj.vertex_edges, 1) == std::vector<int32_t>{1, 2, 4, 5});
    CHECK(sorted(list(adj.vertex_offsets, adj.vertex_vertices, 1)) == std::vector<int32_t>{0, 2, 3, 4});
    CHECK(list(adj.vertex_face_offsets, adj.vertex_faces, 1) == std::vector<int32_t>{0, 1, 2});
    // e3 = v2->v3 with L = F1, R = F2 (slide); its neighbours are the other edges at v2 and v3.
    CHECK(adj.edge_vertices[2 * 2] == 1);
    CHECK(adj.edge_vertices[2 * 2 + 1] == 2);
    CHECK(adj.edge_faces[2 * 2] == 0);
    CHECK(adj.edge_faces[2 * 2 + 1] == 1);
    CHECK(sorted(list(adj.edge_edge_offsets, adj.edge_edges, 2)) == std::vector<int32_t>{0, 1, 3, 4, 5});
    // F2 = (v2 v4 v3): sides e5, e4, e3; across them F3, none, F1.
    CHECK(list(adj.face_offsets, adj.face_edges, 1) == std::vector<int32_t>{4, 3, 2});
    CHECK(list(adj.face_offsets, adj.face_faces, 1) == std::vector<int32_t>{2, kNone, 0});
}

TEST_CASE("storage entries equal the analytic counts", "[mesh][representations][storage]") {
    for (const IndexedMesh& m : {lecture_example().mesh, cube(), grid(5, 3), open_fan(6), uv_sphere(8, 5)}) {
        const Built b = build_all(m);
        const std::size_t V = b.winged.vertex_count(), E = b.winged.edge_count(), F = b.winged.face_count();
        const std::size_t C = corner_count(m); // sum of face sizes = 2E - boundary edges
        const std::size_t B = b.winged.counts().boundary_edges;
        CHECK(C == 2 * E - B);
        const auto s = representation_storage(b.reps, b.winged);
        // Independent faces: 3 doubles per face corner + F + 1 offsets (faces vary in size).
        CHECK(s[0].entries() == 3 * C + (F + 1));
        CHECK(s[0].bytes() == 3 * C * 8 + (F + 1) * 4);
        // Vertex and face tables: 3V coordinates + F + 1 offsets + one index per corner.
        CHECK(s[1].entries() == 3 * V + (F + 1) + C);
        // Full adjacency: VV and VE 2E each + V + 1 offsets; VF C + V + 1; EV, EF 2E each;
        // EE = sum over edges of (deg S - 1) + (deg E - 1) = sum_v deg(v)^2 - 2E, + E + 1;
        // FV, FE, FF C each + F + 1.
        std::size_t sum_deg_sq = 0;
        for (std::size_t v = 0; v < V; ++v) {
            const std::size_t d = b.winged.edges_around_vertex(static_cast<int32_t>(v)).size();
            sum_deg_sq += d * d;
        }
        CHECK(s[2].entries() == 3 * V + (V + 1) + 4 * E + (V + 1) + C + 4 * E + (E + 1) + (sum_deg_sq - 2 * E) +
                                    (F + 1) + 3 * C);
        // Partial: VE 2E + V + 1; EV, EF 2E each; FE C + F + 1.
        CHECK(s[3].entries() == 3 * V + (V + 1) + 2 * E + 4 * E + (F + 1) + C);
        // Foley: vertex list 3V, edge list 4E (V1 V2 P1 P2), polygons C + F + 1.
        CHECK(s[4].entries() == 3 * V + 4 * E + (F + 1) + C);
        // Winged edge: 3V + V, 8E, F; and the same bytes as the structure's own count.
        CHECK(s[5].entries() == 4 * V + 8 * E + F);
        CHECK(s[5].bytes() == b.winged.bytes());
    }
}

TEST_CASE("every query agrees across all six representations", "[mesh][representations][queries]") {
    const NamedMesh ex = lecture_example();
    check_all_queries_agree(build_all(ex.mesh, ex.options));
    const NamedMesh foley = foley_example();
    check_all_queries_agree(build_all(foley.mesh, foley.options));
    check_all_queries_agree(build_all(cube()));
    check_all_queries_agree(build_all(tetrahedron()));
    check_all_queries_agree(build_all(grid(4, 3)));
    check_all_queries_agree(build_all(uv_sphere(6, 4)));
    check_all_queries_agree(build_all(open_fan(5)));
}

TEST_CASE("walks read in proportion to the answer, scans in proportion to the mesh", "[mesh][representations][queries]") {
    // The same interior grid vertex (valence 6 in docs/benchmarks.md's split) on a small and a 4x
    // larger grid: the winged edge and the adjacency lists read the same number of
    // entries; the scans of the face table, the coordinates and the edge list read more,
    // and in proportion to the corners / edges.
    const Built small = build_all(grid(8, 8));
    const Built large = build_all(grid(16, 16));
    const int32_t v_small = 4 * 9 + 4, v_large = 4 * 17 + 4; // (4, 4): interior in both
    const auto a = answer_query(QueryKind::FacesAroundVertex, v_small, small.reps, small.winged);
    const auto b = answer_query(QueryKind::FacesAroundVertex, v_large, large.reps, large.winged);
    const std::size_t valence = 6;
    REQUIRE(a[5].answer.size() == valence);
    REQUIRE(b[5].answer.size() == valence);
    // Winged edge: the vertex's edge, then per step S, the face swept and the next wing.
    CHECK(a[5].entries_read == 1 + 3 * valence);
    CHECK(b[5].entries_read == a[5].entries_read);
    CHECK(b[2].entries_read == a[2].entries_read); // adjacency list: 2 offsets + valence
    CHECK(a[2].entries_read == 2 + valence);
    CHECK(b[3].entries_read == a[3].entries_read);
    const std::size_t faces_small = small.winged.face_count(), faces_large = large.winged.face_count();
    REQUIRE(faces_large == 4 * faces_small);
    for (int r : {0, 1, 4}) {
        INFO(representation_key(static_cast<Representation>(r)));
        // At least one read per face (or per edge), so the count grows with the mesh.
        CHECK(a[r].entries_read >= faces_small);
        CHECK(b[r].entries_read >= faces_large);
        CHECK(b[r].entries_read > 3 * a[r].entries_read);
    }
    // Foley's edge list reads V1 of every edge, V2 unless V1 matched, and P1, P2 of each
    // incident edge: 2E - (edges starting at v) + 2 valence.
    std::size_t starting = 0;
    for (int32_t e : small.winged.edges_around_vertex(v_small)) starting += small.winged.edge(e).start == v_small;
    CHECK(a[4].entries_read == 2 * small.winged.edge_count() - starting + 2 * valence);
}

TEST_CASE("moving a vertex rewrites one point, except in independent faces", "[mesh][representations]") {
    Built b = build_all(cube());
    // Cube vertex 0 is a corner of 3 quads: 3 copies in the independent faces.
    const glm::dvec3 p(-0.5, -0.25, -0.125);
    b.winged.set_position(0, p);
    const auto changed = set_vertex_position(b.reps, 0, p);
    CHECK(changed == std::array<int32_t, 5>{3, 1, 1, 1, 1});
    std::size_t copies = 0;
    const auto& xyz = b.reps.independent_faces.corner_positions;
    for (std::size_t c = 0; c < xyz.size() / 3; ++c)
        copies += xyz[3 * c] == p.x && xyz[3 * c + 1] == p.y && xyz[3 * c + 2] == p.z;
    CHECK(copies == 3);
    CHECK(b.reps.edge_list.positions[0] == p.x);
    CHECK(b.reps.adjacency_lists.positions[2] == p.z);
    // The scans still find the moved point.
    check_all_queries_agree(b);
}

TEST_CASE("a different face set is refused, not silently mislabelled", "[mesh][representations]") {
    const WingedEdgeMesh w = WingedEdgeMesh::build(cube());
    REQUIRE(w.validate().ok());
    IndexedMesh other = cube();
    std::swap(other.face_vertices[0], other.face_vertices[1]);
    try {
        build_representations(other, w);
        FAIL("accepted another face set");
    } catch (const wingspline::Error& e) {
        CHECK(e.code() == "mismatched-face-set");
    }
    CHECK_THROWS_AS(answer_query(QueryKind::FacesOfEdge, 12, build_representations(cube(), w), w), wingspline::Error);
    CHECK_THROWS_AS(query_kind("faces-of-vertex"), wingspline::Error);
}

TEST_CASE("a gap left by an edit is read as a face with no corners: one offset, no more", "[mesh][representations][queries]") {
    // Join two faces of the cube so that the last face is the one removed; the scans of the
    // vertex/face tables then meet a gap at the table's end. Each query there reads exactly
    // what it reads on the compacted mesh (same face order, compact() keeps it) plus the
    // gap's one offset entry, and answers the same under the renumbering.
    const OperationEntry* join = find_operation("join-faces");
    REQUIRE(join != nullptr);
    const WingedEdgeMesh start = WingedEdgeMesh::build(cube());
    const int32_t last = start.face_count() - 1;
    int tried = 0;
    for (int32_t e = 0; e < start.edge_count(); ++e) {
        WingedEdgeMesh gapped = start;
        const Operation op{join, {static_cast<double>(e)}};
        if (!gapped.check(op).ok) continue;
        const ChangeRecord change = gapped.apply(op);
        if (std::none_of(change.removed_faces.begin(), change.removed_faces.end(), [&](Face f) { return f.idx == last; })) continue;
        ++tried;
        REQUIRE(gapped.validate().ok());
        WingedEdgeMesh compacted = gapped;
        const Renumbering map = compacted.compact();
        RepresentationCache gapped_cache, compacted_cache;
        const Representations& g = gapped_cache.of(gapped);
        const Representations& c = compacted_cache.of(compacted);
        const auto table = static_cast<int>(Representation::VertexFaceTables);
        const auto renumbered = [](std::vector<int32_t> v, const std::vector<int32_t>& to) {
            for (int32_t& x : v) x = to[x];
            std::sort(v.begin(), v.end());
            return v;
        };
        const auto sorted = [](std::vector<int32_t> v) { std::sort(v.begin(), v.end()); return v; };
        for (int32_t x = 0; x < gapped.edge_count(); ++x) {
            if (gapped.is_deleted(Edge(x))) continue;
            const auto a = answer_query(QueryKind::FacesOfEdge, x, g, gapped);
            const auto b = answer_query(QueryKind::FacesOfEdge, map.edges[x], c, compacted);
            CHECK(a[table].entries_read == b[table].entries_read + 1);
            CHECK(renumbered(a[table].answer, map.faces) == sorted(b[table].answer));
        }
        for (int32_t f = 0; f < gapped.face_count(); ++f) {
            if (gapped.is_deleted(Face(f))) continue;
            const auto a = answer_query(QueryKind::NeighboursOfFace, f, g, gapped);
            const auto b = answer_query(QueryKind::NeighboursOfFace, map.faces[f], c, compacted);
            CHECK(a[table].entries_read == b[table].entries_read + 1);
            CHECK(renumbered(a[table].answer, map.faces) == sorted(b[table].answer));
        }
    }
    CHECK(tried > 0);
}

TEST_CASE("query_cost_growth equals real counted grids (968 and 9,800 faces here; 100,352 and 1,002,528 in [.big])", "[mesh][representations][queries]") {
    constexpr int kWE = static_cast<int>(Representation::WingedEdge);
    constexpr int kEL = static_cast<int>(Representation::EdgeList);
    // The lecture's walks at the grid's middle elements (an interior vertex of valence 6, an
    // interior edge, an interior triangle): the vertex's or face's edge, then per step the
    // record, (the face or neighbour swept,) the next wing; faces of an edge: L and R.
    const std::vector<std::pair<QueryKind, int64_t>> walks{
        {QueryKind::FacesAroundVertex, 1 + 3 * 6}, {QueryKind::EdgesAroundVertex, 1 + 2 * 6},
        {QueryKind::EdgesOfFace, 1 + 2 * 3},       {QueryKind::NeighboursOfFace, 1 + 3 * 3},
        {QueryKind::FacesOfEdge, 2}};
    for (const auto& [kind, winged_reads] : walks) {
        INFO(static_cast<int>(kind));
        const QueryCostGrowth g = query_cost_growth(kind, {22, 70});
        CHECK(g.n == std::vector<int32_t>{22, 70});
        CHECK(g.faces == std::vector<int64_t>{968, 9800});
        CHECK(g.reads[0] == query_reads_on_grid(kind, 22));
        CHECK(g.reads[1] == query_reads_on_grid(kind, 70));
        CHECK(g.reads[0][kWE] == winged_reads);
        CHECK(g.reads[1][kWE] == winged_reads);
    }
    // The half-edge view at the same elements: the vertex's (face's) half-edge, then per step
    // (the face or the twin's face swept,) one prev (next); faces of an edge: face(2e), face(2e+1).
    // One read per step fewer than the winged edge, which first tests which side it is on.
    const std::vector<std::pair<QueryKind, int64_t>> half_edge_walks{
        {QueryKind::FacesAroundVertex, 1 + 2 * 6}, {QueryKind::EdgesAroundVertex, 1 + 6},
        {QueryKind::EdgesOfFace, 1 + 3},           {QueryKind::NeighboursOfFace, 1 + 2 * 3},
        {QueryKind::FacesOfEdge, 2}};
    for (const auto& [kind, reads] : half_edge_walks) {
        INFO(static_cast<int>(kind));
        const QueryCostGrowth g = query_cost_growth(kind, {22, 70, 224, 708});
        CHECK(g.half_edge_reads == std::vector<int64_t>{reads, reads, reads, reads});
        CHECK(half_edge_query_reads_on_grid(kind, 22) == reads);
    }
    // Foley's edge list must inspect every edge for a vertex's edges: it grows with E
    // (E = 3n^2 + 2n on the grid), at least one read per edge at every size up to a million faces.
    const QueryCostGrowth v = query_cost_growth(QueryKind::EdgesAroundVertex, {22, 70, 224, 708});
    for (std::size_t i = 0; i < v.n.size(); ++i) {
        const int64_t n = v.n[i];
        CHECK(v.reads[i][kEL] >= 3 * n * n + 2 * n);
    }
    CHECK_THROWS_AS(query_cost_growth(QueryKind::FacesOfEdge, {21}), wingspline::Error);
    CHECK_THROWS_AS(query_cost_growth(QueryKind::FacesOfEdge, {4002}), wingspline::Error);
}

TEST_CASE("query_cost_growth equals real counted grids of 100,352 and 1,002,528 faces", "[.big][mesh][representations][queries]") {
    const QueryCostGrowth g = query_cost_growth(QueryKind::FacesAroundVertex, {224, 708});
    CHECK(g.reads[0] == query_reads_on_grid(QueryKind::FacesAroundVertex, 224));
    CHECK(g.reads[1] == query_reads_on_grid(QueryKind::FacesAroundVertex, 708));
}
