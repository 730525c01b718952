// The mesh's change model: checked mutators (check_<op> changes nothing, <op>
// refuses what its check refuses and leaves the structure bit-identical), versions that move
// exactly when something changed, change records, and the other representations derived
// from the current winged edge equal to the ones built from scratch.
#include <catch2/catch.hpp>

#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <random>
#include <string>
#include <type_traits>

using namespace wingspline::mesh;

// Element ids say what they are: a Face is not an Edge, and a plain int is neither.
static_assert(!std::is_convertible<Face, Edge>::value, "a face handle must not pass for an edge");
static_assert(!std::is_convertible<int32_t, Vertex>::value, "an index must be named as a vertex explicitly");
static_assert(!Vertex().is_valid() && Vertex().idx == kNone, "a default handle is the invalid sentinel");

namespace {

// Everything a WingedEdgeMesh stores, read through its public interface.
struct Snapshot {
    std::vector<double> positions;
    std::vector<int32_t> vertex_edge, edges, face_edge, face_set;
    MeshVersion version;
    bool operator==(const Snapshot& o) const {
        return positions == o.positions && vertex_edge == o.vertex_edge && edges == o.edges && face_edge == o.face_edge &&
               face_set == o.face_set && version == o.version;
    }
};

Snapshot snapshot(const WingedEdgeMesh& w) {
    Snapshot s;
    s.positions = w.positions();
    for (int32_t v = 0; v < w.vertex_count(); ++v) s.vertex_edge.push_back(w.vertex_edge(v));
    for (const EdgeRecord& r : w.edges())
        s.edges.insert(s.edges.end(), {r.start, r.end, r.left, r.right, r.start_left, r.start_right, r.end_left, r.end_right});
    for (int32_t f = 0; f < w.face_count(); ++f) s.face_edge.push_back(w.face_edge(f));
    s.face_set = w.face_set().face_vertices;
    s.version = w.version();
    return s;
}

void require_valid(const WingedEdgeMesh& w) {
    const ValidationReport r = w.validate();
    INFO((r.first_error() ? r.first_error()->message : std::string()));
    REQUIRE(r.ok());
}

// `after` is `before` turned to start at its element `first` (the same cyclic order).
bool is_rotation_from(const std::vector<int32_t>& before, const std::vector<int32_t>& after, int32_t first) {
    if (before.size() != after.size() || after.empty() || after.front() != first) return false;
    const auto k = std::find(before.begin(), before.end(), first) - before.begin();
    for (std::size_t i = 0; i < before.size(); ++i)
        if (after[i] != before[(k + i) % before.size()]) return false;
    return true;
}

// The incident edges of v from the face set alone: the sides (consecutive corners) at v.
bool side_of_faces_at(const IndexedMesh& m, const EdgeRecord& r, int32_t v) {
    for (int32_t f = 0; f < m.face_count(); ++f)
        for (int32_t i = 0; i < m.face_size(f); ++i) {
            const int32_t a = m.corner(f, i), b = m.corner(f, (i + 1) % m.face_size(f));
            if ((a == v || b == v) && std::minmax(a, b) == std::minmax(r.start, r.end)) return true;
        }
    return false;
}

struct Fixture {
    std::string name;
    IndexedMesh mesh;
    BuildOptions options;
};

std::vector<Fixture> fixtures() {
    const NamedMesh lecture = lecture_example(), foley = foley_example();
    IndexedMesh lonely = open_fan(3);
    lonely.add_vertex(5, 5, 0); // an isolated vertex: no edge to store
    return {{"lecture", lecture.mesh, lecture.options}, {"foley", foley.mesh, foley.options}, {"tetrahedron", tetrahedron(), {}},
            {"cube", cube(), {}}, {"fan with an isolated vertex", lonely, {}}, {"grid", grid(3, 2), {}}, {"sphere", uv_sphere(6, 4), {}}};
}

// The representations as arrays, for whole-structure comparison.
std::vector<std::vector<double>> all_doubles(const Representations& r) {
    return {r.independent_faces.corner_positions, r.vertex_face_tables.positions, r.adjacency_lists.positions,
            r.partial_adjacency_lists.positions, r.edge_list.positions};
}
std::vector<std::vector<int32_t>> all_ints(const Representations& r) {
    const AdjacencyLists& a = r.adjacency_lists;
    const PartialAdjacencyLists& p = r.partial_adjacency_lists;
    return {r.independent_faces.face_offsets, r.vertex_face_tables.face_offsets, r.vertex_face_tables.face_vertices,
            a.vertex_offsets, a.vertex_vertices, a.vertex_edges, a.vertex_face_offsets, a.vertex_faces, a.edge_vertices,
            a.edge_edge_offsets, a.edge_edges, a.edge_faces, a.face_offsets, a.face_vertices, a.face_edges, a.face_faces,
            p.vertex_offsets, p.vertex_edges, p.edge_vertices, p.edge_faces, p.face_offsets, p.face_edges,
            r.edge_list.edges, r.edge_list.polygon_offsets, r.edge_list.polygon_edges, r.corner_edge_names};
}

} // namespace

TEST_CASE("set-vertex-edge: accepted exactly for incident edges, refused ones change nothing", "[mesh][change]") {
    int accepted = 0, refused = 0;
    for (const Fixture& fx : fixtures()) {
        INFO(fx.name);
        WingedEdgeMesh w = WingedEdgeMesh::build(fx.mesh, fx.options);
        require_valid(w);
        const int32_t euler = w.counts().euler();
        for (int32_t v = 0; v < w.vertex_count(); ++v)
            for (int32_t e = 0; e < w.edge_count(); ++e) {
                INFO("v" << v + 1 << " e" << e + 1);
                const bool incident = side_of_faces_at(fx.mesh, w.edge(e), v);
                const Snapshot before = snapshot(w);
                const CheckResult check = w.check(operation("set-vertex-edge", Vertex(v), Edge(e)));
                REQUIRE(snapshot(w) == before); // the check changes nothing
                REQUIRE(check.ok == incident);
                if (!incident) {
                    ++refused;
                    CHECK(check.code == "edge-not-incident");
                    CHECK_THAT(check.message, Catch::Contains(edge_label(e)) && Catch::Contains(vertex_label(v)));
                    CHECK_THROWS_WITH(w.apply(operation("set-vertex-edge", Vertex(v), Edge(e))), check.message);
                    CHECK(snapshot(w) == before);
                    continue;
                }
                ++accepted;
                const std::vector<int32_t> ring = w.edges_around_vertex(v);
                const ChangeRecord change = w.apply(operation("set-vertex-edge", Vertex(v), Edge(e)));
                require_valid(w);
                CHECK(w.counts().euler() == euler);
                CHECK(w.vertex_edge(v) == e);
                CHECK(is_rotation_from(ring, w.edges_around_vertex(v), e)); // the walk starts at e
                const Snapshot after = snapshot(w);
                const bool moved = before.vertex_edge[v] != e;
                CHECK(after.version.topology == before.version.topology + (moved ? 1u : 0u));
                CHECK(after.version.geometry == before.version.geometry);
                CHECK(change.op == "set-vertex-edge");
                CHECK(change.before == before.version);
                CHECK(change.after == after.version);
                CHECK(change.added_edges.empty());
                CHECK(change.removed_edges.empty());
                // Exactly one row, one field, before and after; every other entry is as it was.
                REQUIRE(change.rows.size() == (moved ? 1u : 0u));
                if (moved) {
                    CHECK(change.rows[0].table == MeshTable::Vertex);
                    CHECK(change.rows[0].row == v);
                    REQUIRE(change.rows[0].fields.size() == 1);
                    CHECK(change.rows[0].fields[0].field == "edge");
                    CHECK(change.rows[0].fields[0].before == before.vertex_edge[v]);
                    CHECK(change.rows[0].fields[0].after == e);
                }
                Snapshot expected = before;
                expected.vertex_edge[v] = e;
                expected.version = after.version;
                CHECK(after == expected);
            }
    }
    CHECK(accepted > 100);
    CHECK(refused > 1000);
}

TEST_CASE("set-face-edge: accepted exactly for the face's sides; the face set stays, the walk moves", "[mesh][change]") {
    int accepted = 0, refused = 0;
    for (const Fixture& fx : fixtures()) {
        INFO(fx.name);
        WingedEdgeMesh w = WingedEdgeMesh::build(fx.mesh, fx.options);
        const std::vector<int32_t> faces_as_given = fx.mesh.face_vertices;
        for (int32_t f = 0; f < w.face_count(); ++f)
            for (int32_t e = 0; e < w.edge_count(); ++e) {
                INFO("F" << f + 1 << " e" << e + 1);
                // A side of f: two consecutive corners of f as given.
                bool side = false;
                for (int32_t i = 0; i < fx.mesh.face_size(f); ++i)
                    side |= std::minmax(fx.mesh.corner(f, i), fx.mesh.corner(f, (i + 1) % fx.mesh.face_size(f))) ==
                            std::minmax(w.edge(e).start, w.edge(e).end);
                const Snapshot before = snapshot(w);
                const CheckResult check = w.check(operation("set-face-edge", Face(f), Edge(e)));
                REQUIRE(snapshot(w) == before);
                REQUIRE(check.ok == side);
                if (!side) {
                    ++refused;
                    CHECK(check.code == "edge-not-on-face");
                    CHECK_THROWS_WITH(w.apply(operation("set-face-edge", Face(f), Edge(e))), check.message);
                    CHECK(snapshot(w) == before);
                    continue;
                }
                ++accepted;
                const std::vector<int32_t> loop = w.edges_of_face(f);
                const ChangeRecord change = w.apply(operation("set-face-edge", Face(f), Edge(e)));
                require_valid(w);
                CHECK(w.face_edge(f) == e);
                CHECK(is_rotation_from(loop, w.edges_of_face(f), e));
                CHECK(w.face_set().face_vertices == faces_as_given); // the faces as given, always
                const bool moved = before.face_edge[f] != e;
                CHECK(w.version().topology == before.version.topology + (moved ? 1u : 0u));
                REQUIRE(change.rows.size() == (moved ? 1u : 0u));
                if (moved) {
                    CHECK(change.rows[0].table == MeshTable::Face);
                    CHECK(change.rows[0].row == f);
                    CHECK(change.rows[0].fields[0].before == before.face_edge[f]);
                    CHECK(change.rows[0].fields[0].after == e);
                }
            }
    }
    CHECK(accepted > 50);
    CHECK(refused > 500);
}

TEST_CASE("out-of-range and isolated elements are refused with the element named", "[mesh][change]") {
    IndexedMesh m = open_fan(3);
    m.add_vertex(5, 5, 0);
    WingedEdgeMesh w = WingedEdgeMesh::build(m);
    const Snapshot before = snapshot(w);
    const int32_t isolated = w.vertex_count() - 1;
    const CheckResult lonely = w.check(operation("set-vertex-edge", Vertex(isolated), Edge(0)));
    CHECK(lonely.code == "edge-not-incident");
    CHECK_THAT(lonely.message, Catch::Contains(vertex_label(isolated) + " belongs to no face"));
    CHECK(w.check(operation("set-vertex-edge", Vertex(-1), Edge(0))).code == "invalid-element");
    CHECK(w.check(operation("set-vertex-edge", Vertex(0), Edge(w.edge_count()))).code == "invalid-element");
    CHECK(w.check(operation("set-face-edge", Face(w.face_count()), Edge(0))).code == "invalid-element");
    CHECK_THAT(w.check(operation("set-face-edge", Face(0), Edge(kNone))).message, Catch::Contains("-1 names no edge (it stands for none)"));
    CHECK_THROWS_AS(w.apply(operation("set-face-edge", Face(7), Edge(0))), wingspline::Error);
    CHECK(snapshot(w) == before);
    CHECK_FALSE(w.has_garbage()); // no operation deletes yet
}

TEST_CASE("lecture 000: v2 stores e3 instead of e6 and its walk starts there", "[mesh][change]") {
    const NamedMesh ex = lecture_example();
    WingedEdgeMesh w = WingedEdgeMesh::build(ex.mesh, ex.options);
    // Slide: v2's edge is e6; CCW around v2 is e6, e5, e3, e2.
    REQUIRE(w.vertex_edge(1) == 5);
    const ChangeRecord c = w.apply(operation("set-vertex-edge", Vertex(1), Edge(2)));
    CHECK(w.edges_around_vertex(1) == std::vector<int32_t>{2, 1, 5, 4}); // e3, e2, e6, e5
    CHECK(c.rows.size() == 1);
    CHECK(w.version() == MeshVersion{1, 0});
    // F2's edge is e3 on the slide; its sides are e3, e4, e5 (CCW: e3, e5, e4).
    w.apply(operation("set-face-edge", Face(1), Edge(4)));
    CHECK(w.edges_of_face(1) == std::vector<int32_t>{4, 3, 2});
    CHECK(w.version() == MeshVersion{2, 0});
    // Choosing again what is stored changes nothing, not even the version.
    CHECK_FALSE(w.apply(operation("set-face-edge", Face(1), Edge(4))).changed());
    CHECK(w.version() == MeshVersion{2, 0});
}

TEST_CASE("positions move the geometry version only, and only when they change", "[mesh][change]") {
    WingedEdgeMesh w = WingedEdgeMesh::build(tetrahedron());
    CHECK(w.version() == MeshVersion{0, 0});
    w.set_position(0, w.position(0));
    CHECK(w.version() == MeshVersion{0, 0});
    w.set_position(0, {0.5, 0.25, 2});
    CHECK(w.version() == MeshVersion{0, 1});
    CHECK_THROWS(w.set_position(0, {1e300, 0, 0}));
    CHECK(w.version() == MeshVersion{0, 1});
}

TEST_CASE("derived representations after random operations equal those built from scratch", "[mesh][change][representations]") {
    std::mt19937 rng(20240514);
    for (const Fixture& fx : fixtures()) {
        INFO(fx.name);
        WingedEdgeMesh w = WingedEdgeMesh::build(fx.mesh, fx.options);
        RepresentationCache cache;
        cache.of(w);
        for (int round = 0; round < 40; ++round) {
            // One random accepted operation: a vertex or a face stores another of its edges.
            if (rng() % 2 == 0) {
                const int32_t v = static_cast<int32_t>(rng() % w.vertex_count());
                const std::vector<int32_t> ring = w.edges_around_vertex(v);
                if (!ring.empty()) w.apply(operation("set-vertex-edge", Vertex(v), Edge(ring[rng() % ring.size()])));
            } else {
                const int32_t f = static_cast<int32_t>(rng() % w.face_count());
                const std::vector<int32_t> loop = w.edges_of_face(f);
                w.apply(operation("set-face-edge", Face(f), Edge(loop[rng() % loop.size()])));
            }
            if (round % 3 == 0) {
                const int32_t v = static_cast<int32_t>(rng() % w.vertex_count());
                const glm::dvec3 p(round * 0.25, -0.5 * round, 1.0 / (round + 1));
                w.set_position(v, p);
                cache.follow_position(w, v, p);
            }
            require_valid(w);
            CHECK(w.counts().euler() == WingedEdgeMesh::build(fx.mesh, fx.options).counts().euler());
        }
        // One more change of the topology after the last followed move: derived exactly once.
        w.apply(operation("set-face-edge", Face(0), Edge(w.edges_of_face(0)[1])));
        const int32_t derived_before = cache.derivations();
        const Representations& now = cache.of(w);
        CHECK(cache.version() == w.version());
        CHECK(cache.derivations() == derived_before + 1); // the topology moved on: derived again
        cache.of(w);
        CHECK(cache.derivations() == derived_before + 1); // same version: nothing derived

        // From scratch: the original face set with today's positions, the same edge numbering
        // and the same stored edges, built and derived anew.
        IndexedMesh faces = fx.mesh;
        faces.positions = w.positions();
        BuildOptions same;
        for (const EdgeRecord& r : w.edges()) same.edges.push_back({r.start, r.end});
        for (int32_t v = 0; v < w.vertex_count(); ++v) same.vertex_edges.push_back(w.vertex_edge(v));
        for (int32_t f = 0; f < w.face_count(); ++f) same.face_edges.push_back(w.face_edge(f));
        const WingedEdgeMesh fresh = WingedEdgeMesh::build(faces, same);
        const Representations scratch = build_representations(faces, fresh);
        CHECK(all_ints(now) == all_ints(scratch));
        CHECK(all_doubles(now) == all_doubles(scratch));
        Snapshot a = snapshot(w), b = snapshot(fresh);
        a.version = b.version = {};
        CHECK(a == b);
    }
}

TEST_CASE("the cache follows one move in place and derives again when the topology moved", "[mesh][change][representations]") {
    const NamedMesh ex = lecture_example();
    WingedEdgeMesh w = WingedEdgeMesh::build(ex.mesh, ex.options);
    RepresentationCache cache;
    CHECK_FALSE(cache.built());
    // v2 is a corner of F1, F2, F3: three copies in independent faces, one elsewhere.
    w.set_position(1, {1, 0.5, 0});
    CHECK(cache.follow_position(w, 1, {1, 0.5, 0}) == std::array<int32_t, 5>{3, 1, 1, 1, 1});
    CHECK(cache.derivations() == 1);
    w.set_position(1, {1, 0.25, 0});
    cache.follow_position(w, 1, {1, 0.25, 0});
    CHECK(cache.derivations() == 1); // followed in place
    CHECK(cache.of(w).vertex_face_tables.positions[4] == 0.25);
    w.apply(operation("set-vertex-edge", Vertex(0), Edge(1)));
    w.set_position(1, {1, 0, 0});
    cache.follow_position(w, 1, {1, 0, 0});
    CHECK(cache.derivations() == 2);
    CHECK(cache.version() == w.version());
    CHECK(cache.of(w).independent_faces.corner_positions[4] == 0); // F1's second corner is v2: y = 0
}
