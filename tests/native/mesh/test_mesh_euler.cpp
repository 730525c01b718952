// The Euler operations on the winged edge (split edge, split face, join faces,
// flip, collapse, poke). The lecture example's tables after each operation are worked out
// by hand below from lecture 000's conventions (L traverses S -> E; wing X-Y = the other
// edge at X of the face on side Y, the boundary walked as a face), not read from the code.
// Then thousands of random seeded operation sequences: validate(), Euler's formula, an
// independent rebuild from the face set, refusals bit-identical, the change record enough
// to replay (steps) and to undo (rows), recorded and unrecorded paths identical, compact().
#include <catch2/catch.hpp>

#include "mesh/unrecorded.h"
#include "mesh/random_edits.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/tables.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <random>
#include <sstream>
#include <string>

using namespace wingspline::mesh;

namespace {
using namespace wingspline::test_edits;
enum Op { SplitEdge, FlipEdge, CollapseEdge, JoinFaces, SplitFace, PokeFace }; // the registry's order (checked below)

int32_t label(const std::string& s) { return s == "-" ? kNone : std::stoi(s.substr(1)) - 1; }

// One edge-table row as the slide writes it: "e3: v2 v3 F1 F2 e2 e5 e1 e4" (S E L R SL SR EL ER).
std::string row_text(const WingedEdgeMesh& w, int32_t e) {
    const EdgeRecord& r = w.edge(e);
    const auto V = [](int32_t i) { return i == kNone ? std::string("-") : "v" + std::to_string(i + 1); };
    const auto F = [](int32_t i) { return i == kNone ? std::string("-") : "F" + std::to_string(i + 1); };
    const auto E = [](int32_t i) { return i == kNone ? std::string("-") : "e" + std::to_string(i + 1); };
    return "e" + std::to_string(e + 1) + ": " + V(r.start) + " " + V(r.end) + " " + F(r.left) + " " + F(r.right) + " " +
           E(r.start_left) + " " + E(r.start_right) + " " + E(r.end_left) + " " + E(r.end_right);
}

struct HandTables {
    std::vector<std::string> edges;        // every live edge row, in order; deleted rows as "eN: deleted"
    std::vector<std::string> vertex_edges; // "e1" ... or "deleted"
    std::vector<std::string> face_edges;
    std::vector<std::vector<int32_t>> faces; // 1-based corners as face_set() lists them; {} for a gap
};

void require_tables(const WingedEdgeMesh& w, const HandTables& t) {
    const ValidationReport rep = w.validate();
    INFO((rep.first_error() ? rep.first_error()->message : std::string()));
    REQUIRE(rep.ok());
    REQUIRE(w.edge_count() == static_cast<int32_t>(t.edges.size()));
    for (int32_t e = 0; e < w.edge_count(); ++e)
        CHECK((w.is_deleted(Edge(e)) ? "e" + std::to_string(e + 1) + ": deleted" : row_text(w, e)) == t.edges[e]);
    REQUIRE(w.vertex_count() == static_cast<int32_t>(t.vertex_edges.size()));
    for (int32_t v = 0; v < w.vertex_count(); ++v) {
        INFO("v" << v + 1);
        if (t.vertex_edges[v] == "deleted")
            CHECK(w.is_deleted(Vertex(v)));
        else
            CHECK(w.vertex_edge(v) == label(t.vertex_edges[v]));
    }
    REQUIRE(w.face_count() == static_cast<int32_t>(t.face_edges.size()));
    for (int32_t f = 0; f < w.face_count(); ++f) {
        INFO("F" << f + 1);
        if (t.face_edges[f] == "deleted")
            CHECK(w.is_deleted(Face(f)));
        else
            CHECK(w.face_edge(f) == label(t.face_edges[f]));
    }
    const IndexedMesh fs = w.face_set();
    REQUIRE(fs.face_count() == static_cast<int32_t>(t.faces.size()));
    for (int32_t f = 0; f < fs.face_count(); ++f) {
        std::vector<int32_t> got;
        for (int32_t i = 0; i < fs.face_size(f); ++i) got.push_back(fs.corner(f, i) + 1);
        INFO("F" << f + 1);
        CHECK(got == t.faces[f]);
    }
}


// The slide's rows (test_mesh.cpp checks the build against them).
const std::vector<std::string> kSlide = {"e1: v1 v3 - F1 e2 e2 e4 e3", "e2: v1 v2 F1 - e1 e1 e3 e6", "e3: v2 v3 F1 F2 e2 e5 e1 e4",
                                         "e4: v3 v4 - F2 e1 e3 e7 e5", "e5: v2 v4 F2 F3 e3 e6 e4 e7", "e6: v2 v5 F3 - e5 e2 e7 e7",
                                         "e7: v4 v5 - F3 e4 e5 e6 e6"};

// The three tables as flat arrays (the slide's tables: what the record must restore).
struct Tables {
    std::vector<double> positions;
    std::vector<int32_t> vertex_edge, edges, face_edge;
    bool operator==(const Tables& o) const {
        return positions == o.positions && vertex_edge == o.vertex_edge && edges == o.edges && face_edge == o.face_edge;
    }
};
Tables tables(const WingedEdgeMesh& w) {
    const Snapshot s = snapshot(w);
    return {s.positions, s.vertex_edge, s.edges, s.face_edge};
}

int field_index(const std::string& f) {
    static const char* names[8] = {"start", "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"};
    for (int i = 0; i < 8; ++i)
        if (f == names[i]) return i;
    return -1;
}
int32_t* cell(Tables& t, MeshTable table, int32_t row, const std::string& field) {
    if (table == MeshTable::Vertex) return field == "edge" ? &t.vertex_edge[row] : nullptr;
    if (table == MeshTable::Face) return field == "edge" ? &t.face_edge[row] : nullptr; // firstCorner is not a table cell
    const int k = field_index(field);
    return k < 0 ? nullptr : &t.edges[8 * static_cast<std::size_t>(row) + k];
}

// Replays the steps on the tables before the operation: new rows first (kNone), then every
// assignment in order, then the positions.
Tables replay(Tables t, const ChangeRecord& c) {
    for (const Vertex& v : c.added_vertices) {
        (void)v;
        t.vertex_edge.push_back(kNone);
        t.positions.insert(t.positions.end(), 3, 0.0);
    }
    for (std::size_t i = 0; i < c.added_edges.size(); ++i) t.edges.insert(t.edges.end(), 8, kNone);
    for (std::size_t i = 0; i < c.added_faces.size(); ++i) t.face_edge.push_back(kNone);
    for (const AssignmentStep& s : c.steps) {
        int32_t* p = cell(t, s.table, s.row, s.field);
        if (!p) continue;
        REQUIRE(*p == s.before); // each step starts from the value the previous ones left
        *p = s.after;
    }
    for (const PositionChange& p : c.positions)
        for (int k = 0; k < 3; ++k) t.positions[3 * p.vertex + k] = p.after[k];
    return t;
}

// Undoes an operation on the tables after it from its rows alone (each field's before),
// in reverse, then drops the rows it added (always the last ones).
Tables undo(Tables t, const ChangeRecord& c) {
    for (auto row = c.rows.rbegin(); row != c.rows.rend(); ++row)
        for (const FieldChange& f : row->fields)
            if (int32_t* p = cell(t, row->table, row->row, f.field)) *p = f.before;
    for (const PositionChange& p : c.positions)
        for (int k = 0; k < 3; ++k) t.positions[3 * p.vertex + k] = p.before[k];
    t.vertex_edge.resize(t.vertex_edge.size() - c.added_vertices.size());
    t.positions.resize(3 * t.vertex_edge.size());
    t.edges.resize(t.edges.size() - 8 * c.added_edges.size());
    t.face_edge.resize(t.face_edge.size() - c.added_faces.size());
    return t;
}

CheckResult check(const WingedEdgeMesh& w, const Call& c) { return w.check(operation_of(c)); }
ChangeRecord run(WingedEdgeMesh& w, const Call& c) { return w.apply(operation_of(c)); }
bool run_unrecorded(WingedEdgeMesh& w, const Call& c) { return apply_unrecorded(w, operation_of(c)); }

TEST_CASE("the registry lists every operation once, with its arguments", "[mesh][euler]") {
    const char* expected[] = {"split-edge", "flip-edge", "collapse-edge", "join-faces", "split-face", "poke-face", "split-vertex",
                              "set-vertex-edge", "set-face-edge"};
    REQUIRE(operations().size() == std::size(expected));
    for (std::size_t k = 0; k < std::size(expected); ++k) {
        const OperationEntry& e = operations()[k];
        CHECK(std::string(e.name) == expected[k]);
        CHECK(find_operation(e.name) == &e);
        REQUIRE(!e.arguments.empty());
        CHECK(e.arguments[0].kind != ElementKind::None); // every operation starts from an element
        CHECK(e.arguments[0].choices == nullptr);
        CHECK(e.arguments.size() <= 4);
    }
    CHECK(find_operation("explode") == nullptr);
    CHECK_THROWS_AS(operation("explode", Edge(0)), wingspline::Error);
    CHECK_THROWS_AS(operation("flip-edge", Edge(0), Edge(1)), wingspline::Error);
    // defaults: a number left out takes the entry's default, an element left out is none
    const Operation split = operation("split-edge", Edge(2));
    CHECK(split.args[0] == 2);
    CHECK(split.args[1] == 0.5);
    CHECK(operation("split-face", Face(1)).args[2] == kNone);
}

// The live part of the face set, gaps dropped and vertices renumbered, built again from
// scratch by WingedEdgeMesh::build: it must be accepted (a manifold, oriented mesh) and have
// the same counts; every live edge of w must be an edge of it with the same two faces.
void require_rebuild_agrees(const WingedEdgeMesh& w) {
    const IndexedMesh fs = w.face_set();
    std::vector<int32_t> vmap(w.vertex_count(), kNone), fmap(w.face_count(), kNone);
    IndexedMesh live;
    for (int32_t v = 0; v < w.vertex_count(); ++v)
        if (!w.is_deleted(Vertex(v))) {
            vmap[v] = live.vertex_count();
            live.add_vertex(fs.positions[3 * v], fs.positions[3 * v + 1], fs.positions[3 * v + 2]);
        }
    for (int32_t f = 0; f < fs.face_count(); ++f) {
        if (w.is_deleted(Face(f))) {
            REQUIRE(fs.face_size(f) == 0);
            continue;
        }
        std::vector<int32_t> c;
        for (int32_t i = 0; i < fs.face_size(f); ++i) c.push_back(vmap[fs.corner(f, i)]);
        fmap[f] = live.face_count();
        live.add_face(c.data(), static_cast<int32_t>(c.size()));
    }
    const WingedEdgeMesh r = WingedEdgeMesh::build(live);
    const MeshCounts a = w.counts(), b = r.counts();
    CHECK(a.vertices == b.vertices);
    CHECK(a.edges == b.edges);
    CHECK(a.faces == b.faces);
    CHECK(a.boundary_edges == b.boundary_edges);
    CHECK(a.boundary_loops == b.boundary_loops);
    for (int32_t e = 0; e < w.edge_count(); ++e) {
        if (w.is_deleted(Edge(e))) continue;
        const EdgeRecord& x = w.edge(e);
        bool found = false;
        for (int32_t g = 0; g < r.edge_count() && !found; ++g) {
            const EdgeRecord& y = r.edge(g);
            const auto fm = [&](int32_t f) { return f == kNone ? kNone : fmap[f]; };
            if (y.start == vmap[x.start] && y.end == vmap[x.end]) found = y.left == fm(x.left) && y.right == fm(x.right);
            if (y.start == vmap[x.end] && y.end == vmap[x.start]) found = y.left == fm(x.right) && y.right == fm(x.left);
        }
        INFO(row_text(w, e));
        CHECK(found);
    }
}


} // namespace

// ====================================================================== the lecture example

TEST_CASE("split-edge e3 of the lecture mesh: hand-worked tables and the steps in order", "[mesh][euler]") {
    WingedEdgeMesh w = lecture();
    const ChangeRecord c = w.apply(operation("split-edge", Edge(label("e3")), 0.5));
    // New v6 at the midpoint of v2 (1,0) and v3 (1,2); new e8 = v6 -> v3 with e3's faces.
    require_tables(w, {{"e1: v1 v3 - F1 e2 e2 e4 e8", kSlide[1], "e3: v2 v6 F1 F2 e2 e5 e8 e8", "e4: v3 v4 - F2 e1 e8 e7 e5", kSlide[4],
                        kSlide[5], kSlide[6], "e8: v6 v3 F1 F2 e3 e3 e1 e4"},
                       {"e1", "e6", "e8", "e5", "e6", "e8"},
                       {"e1", "e3", "e5"},
                       {{1, 2, 6, 3}, {2, 4, 3, 6}, {2, 5, 4}}});
    CHECK(w.position(5) == glm::dvec3(1, 1, 0));
    CHECK(c.added_vertices == std::vector<Vertex>{Vertex(5)});
    CHECK(c.added_edges == std::vector<Edge>{Edge(7)});
    // The algorithm's order: the new vertex's edge, the new edge's row, e3's end and wings,
    // the two neighbours at v3, v3's edge.
    std::vector<std::string> steps;
    for (const AssignmentStep& s : c.steps)
        steps.push_back(std::string(table_name(s.table)) + " " + std::to_string(s.row + 1) + " " + s.field + " " +
                        std::to_string(s.before + 1) + "->" + std::to_string(s.after + 1));
    CHECK(steps == std::vector<std::string>{"vertex 6 edge 0->8", "edge 8 start 0->6", "edge 8 end 0->3", "edge 8 left 0->1",
                                            "edge 8 right 0->2", "edge 8 startLeft 0->3", "edge 8 startRight 0->3",
                                            "edge 8 endLeft 0->1", "edge 8 endRight 0->4", "edge 3 end 3->6", "edge 3 endLeft 1->8",
                                            "edge 3 endRight 4->8", "edge 1 endRight 3->8", "edge 4 startRight 3->8",
                                            "vertex 3 edge 3->8"});
    CHECK(c.before == MeshVersion{0, 0});
    CHECK(c.after == MeshVersion{1, 1});
    CHECK(w.counts().euler() == 1);
    // The lines the player highlights: the new vertex's edge is line 0, the new edge's eight
    // fields line 1, e3's three line 2, the neighbours at v3 and v3's edge line 3.
    REQUIRE(c.phases.size() == 4);
    std::vector<int32_t> phase_of_step;
    for (const AssignmentStep& s : c.steps) phase_of_step.push_back(s.phase);
    CHECK(phase_of_step == std::vector<int32_t>{0, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 3, 3, 3});
}

TEST_CASE("flip-edge e3 of the lecture mesh: e3 becomes v4 -> v1", "[mesh][euler]") {
    WingedEdgeMesh w = lecture();
    w.apply(operation("flip-edge", Edge(label("e3"))));
    // F1 = (v1 v2 v4), F2 = (v4 v3 v1). v3 loses e3 and stores the edge after it along F1's
    // old walk (e1); F1's stored e1 left F1, so F1 stores e3.
    require_tables(w, {{"e1: v1 v3 - F2 e2 e3 e4 e4", "e2: v1 v2 F1 - e3 e1 e5 e6", "e3: v4 v1 F1 F2 e5 e4 e2 e1",
                        "e4: v3 v4 - F2 e1 e1 e7 e3", "e5: v2 v4 F1 F3 e2 e6 e3 e7", kSlide[5], kSlide[6]},
                       {"e1", "e6", "e1", "e5", "e6"},
                       {"e3", "e3", "e5"},
                       {{1, 2, 4}, {1, 4, 3}, {2, 5, 4}}});
    // and back: e3 = v4 -> v1 flips to v3 -> v2; its left face F1 becomes (c S d) = (v2 v4 v3)
    // (listed from its walk start v3, as F1 lost v1) and F2 = (v3 v1 v2) (listed from v1):
    // the lecture's two triangles again, with their numbers exchanged.
    w.apply(operation("flip-edge", Edge(label("e3"))));
    const IndexedMesh fs = w.face_set();
    CHECK(fs.face_vertices == std::vector<int32_t>{2, 1, 3, 0, 1, 2, 1, 4, 3});
    CHECK(row_text(w, 2) == "e3: v3 v2 F1 F2 e4 e1 e5 e2");
}

TEST_CASE("join-faces e3 of the lecture mesh, then split-face F1 v2-v3 puts the edge back as e8", "[mesh][euler]") {
    WingedEdgeMesh w = lecture();
    const ChangeRecord j = w.apply(operation("join-faces", Edge(label("e3"))));
    // F1 = (v1 v2 v4 v3); F2 and e3 are gaps; v3 stored e3 and now stores e1 (after e3 in F1).
    require_tables(w, {{"e1: v1 v3 - F1 e2 e2 e4 e4", "e2: v1 v2 F1 - e1 e1 e5 e6", "e3: deleted", "e4: v3 v4 - F1 e1 e1 e7 e5",
                        "e5: v2 v4 F1 F3 e2 e6 e4 e7", kSlide[5], kSlide[6]},
                       {"e1", "e6", "e1", "e5", "e6"},
                       {"e1", "deleted", "e5"},
                       {{1, 2, 4, 3}, {}, {2, 5, 4}}});
    CHECK(j.removed_edges == std::vector<Edge>{Edge(2)});
    CHECK(j.removed_faces == std::vector<Face>{Face(1)});
    const MeshCounts k = w.counts();
    CHECK((k.vertices == 5 && k.edges == 6 && k.faces == 2 && k.euler() == 1));

    w.apply(operation("split-face", Face(0), Vertex(1), Vertex(2)));
    // e8 = v2 -> v3 with F1 (v3 v1 v2) on its left, the new F4 (v2 v4 v3) on its right:
    // e3's old row with F4 for F2.
    require_tables(w, {{"e1: v1 v3 - F1 e2 e2 e4 e8", "e2: v1 v2 F1 - e1 e1 e8 e6", "e3: deleted", "e4: v3 v4 - F4 e1 e8 e7 e5",
                        "e5: v2 v4 F4 F3 e8 e6 e4 e7", kSlide[5], kSlide[6], "e8: v2 v3 F1 F4 e2 e5 e1 e4"},
                       {"e1", "e6", "e1", "e5", "e6"},
                       {"e1", "deleted", "e5", "e8"},
                       {{1, 2, 3}, {}, {2, 5, 4}, {3, 2, 4}}});
}

TEST_CASE("collapse-edge e4 of the lecture mesh: v4 merges into v3, F2 goes", "[mesh][euler]") {
    WingedEdgeMesh w = lecture();
    const ChangeRecord c = w.apply(operation("collapse-edge", Edge(label("e4")), 0.5));
    // v3 moves to the midpoint of (1,2) and (2,1). F2 = (v2 v4 v3) is the triangle on e4's
    // right: it goes with e5 (its edge at v4); e3 (v2-v3) takes e5's place in F3 = (v2 v5 v3).
    require_tables(w, {{"e1: v1 v3 - F1 e2 e2 e7 e3", kSlide[1], "e3: v2 v3 F1 F3 e2 e6 e1 e7", "e4: deleted", "e5: deleted",
                        "e6: v2 v5 F3 - e3 e2 e7 e7", "e7: v3 v5 - F3 e1 e3 e6 e6"},
                       {"e1", "e6", "e3", "deleted", "e6"},
                       {"e1", "deleted", "e3"},
                       {{1, 2, 3}, {}, {2, 5, 3}}});
    CHECK(w.position(2) == glm::dvec3(1.5, 1.5, 0));
    CHECK(c.removed_vertices == std::vector<Vertex>{Vertex(3)});
    CHECK(c.removed_edges == std::vector<Edge>{Edge(3), Edge(4)});
    CHECK(c.removed_faces == std::vector<Face>{Face(1)});
    CHECK(w.counts().euler() == 1);
}

TEST_CASE("poke-face F1 of the lecture mesh: three triangles around the centroid", "[mesh][euler]") {
    WingedEdgeMesh w = lecture();
    w.apply(operation("poke-face", Face(0)));
    // F1's stored edge e1 runs v3 -> v1 along F1, so the corners are v3, v1, v2; spokes
    // e8 = v6->v3, e9 = v6->v1, e10 = v6->v2; F1 = (v3 v1 v6), F4 = (v1 v2 v6), F5 = (v2 v3 v6).
    require_tables(w, {{"e1: v1 v3 - F1 e2 e9 e4 e8", "e2: v1 v2 F4 - e9 e1 e10 e6", "e3: v2 v3 F5 F2 e10 e5 e8 e4", kSlide[3],
                        kSlide[4], kSlide[5], kSlide[6], "e8: v6 v3 F1 F5 e9 e10 e1 e3", "e9: v6 v1 F4 F1 e10 e8 e2 e1",
                        "e10: v6 v2 F5 F4 e8 e9 e3 e2"},
                       {"e1", "e6", "e3", "e5", "e6", "e8"},
                       {"e1", "e3", "e5", "e2", "e3"},
                       {{1, 6, 3}, {2, 4, 3}, {2, 5, 4}, {1, 2, 6}, {2, 3, 6}}});
    CHECK(w.position(5).x == Approx(2.0 / 3.0).epsilon(1e-15));
    CHECK(w.position(5).y == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("refusals on the lecture mesh and the tetrahedron say why and change nothing", "[mesh][euler]") {
    struct Case {
        std::string mesh;
        Call call;
        std::string code, text;
    };
    const std::vector<Case> cases = {
        {"lecture", {FlipEdge, 0, 0, 0, 0.5}, "boundary-edge", "e1 is on the boundary"},
        {"lecture", {JoinFaces, 1, 0, 0, 0.5}, "boundary-edge", "e2 is on the boundary"},
        {"lecture", {CollapseEdge, 2, 0, 0, 0.5}, "would-pinch", "v2 and v3 are both on the boundary but e3 is not"},
        {"lecture", {SplitFace, 0, 0, 1, 0.5}, "adjacent-corners", "F1 is a triangle: every two of its corners are joined by a side"},
        {"lecture", {SplitFace, 0, 0, 3, 0.5}, "not-a-corner", "v4 is not a corner of F1"},
        {"lecture", {SplitFace, 0, 2, 2, 0.5}, "adjacent-corners", "so no new edge can split it"}, // (a triangle, whatever the corners)
        {"lecture", {SplitEdge, 2, 0, 0, 1.0}, "invalid-parameter", "t = 1 is not strictly between 0 and 1"},
        {"lecture", {SplitEdge, 7, 0, 0, 0.5}, "invalid-element", "there is no e8: the mesh has edges e1 to e7"},
        {"lecture", {PokeFace, -1, 0, 0, 0.5}, "invalid-element", "-1 names no face (it stands for none): the mesh has faces F1 to F3"},
        {"tetrahedron", {FlipEdge, 0, 0, 0, 0.5}, "edge-exists", "that already exists"},
        {"tetrahedron", {CollapseEdge, 0, 0, 0, 0.5}, "degenerate-vertex", "would leave"},
    };
    for (const Case& k : cases) {
        WingedEdgeMesh w = k.mesh == "lecture" ? lecture() : WingedEdgeMesh::build(tetrahedron());
        const Snapshot before = snapshot(w);
        const CheckResult r = check(w, k.call);
        INFO(k.code << ": " << r.message);
        CHECK(!r.ok);
        CHECK(r.code == k.code);
        CHECK(r.message.find(k.text) != std::string::npos);
        CHECK(snapshot(w) == before);
        try {
            run(w, k.call);
            FAIL("accepted");
        } catch (const wingspline::Error& e) {
            CHECK(std::string(e.code()) == k.code);
            CHECK(std::string(e.what()) == r.message);
        }
        CHECK(snapshot(w) == before);
        CHECK(!run_unrecorded(w, k.call));
        CHECK(snapshot(w) == before);
    }
    // The tetrahedron's flip names the edge it would create: e1 = v1 -> v2 between
    // (v1 v2 v3) and (v2 v1 v4) would become v4 - v3, which is an edge already.
    WingedEdgeMesh t = WingedEdgeMesh::build(tetrahedron());
    const EdgeRecord& r0 = t.edge(0);
    const std::string msg = t.check(operation("flip-edge", Edge(0))).message;
    CHECK(msg.rfind("flipping e1 would create an edge ", 0) == 0);
    const int32_t c = t.vertices_of_face(r0.left)[0] + t.vertices_of_face(r0.left)[1] + t.vertices_of_face(r0.left)[2] - r0.start - r0.end;
    CHECK(msg.find(vertex_label(c)) != std::string::npos);
}

// ====================================================================== random sequences

TEST_CASE("random seeded operation sequences: valid, Euler, rebuild, refusals, record, unrecorded twin", "[mesh][euler]") {
    std::vector<int> accepted(kOps), refused(kOps);
    std::map<std::string, std::set<int>> accepted_on; // fixture -> operations accepted there
    // 1200 sequences of 40 operations (300 in the sanitizer build, see CMakeLists.txt).
#ifdef WINGSPLINE_SANITIZED
    constexpr uint32_t kSequences = 300;
#else
    constexpr uint32_t kSequences = 1200;
#endif
    for (uint32_t seed = 1; seed <= kSequences; ++seed) {
        std::vector<Fixture> all = fixtures();
        Fixture& fx = all[seed % all.size()];
        WingedEdgeMesh w = std::move(fx.mesh);
        WingedEdgeMesh twin = w; // the unrecorded path
        std::mt19937 rng(seed);
        const int32_t euler = w.counts().euler();
        for (int step = 0; step < 40; ++step) {
            const Call call = random_call(w, rng);
            INFO(fx.name << " seed " << seed << " step " << step << " " << op_name(call.op) << " " << call.a << " " << call.b << " "
                         << call.c << " t=" << call.t);
            const Snapshot before = snapshot(w);
            const Tables tables_before = tables(w);
            const CheckResult verdict = check(w, call);
            CHECK(snapshot(w) == before); // a check changes nothing
            if (!verdict.ok) {
                ++refused[call.op];
                CHECK(!verdict.code.empty());
                CHECK(!verdict.message.empty());
                CHECK_THROWS_AS(run(w, call), wingspline::Error);
                REQUIRE(snapshot(w) == before);
                REQUIRE(!run_unrecorded(twin, call));
                continue;
            }
            ++accepted[call.op];
            accepted_on[fx.name].insert(call.op);
            const ChangeRecord c = run(w, call);
            // Every assignment belongs to one of the algorithm's lines, in the order they run.
            int32_t last_phase = 0;
            for (const AssignmentStep& s : c.steps) {
                REQUIRE(s.phase >= last_phase);
                REQUIRE(s.phase < static_cast<int32_t>(c.phases.size()));
                last_phase = s.phase;
            }
            REQUIRE(run_unrecorded(twin, call));
            REQUIRE(snapshot(twin) == snapshot(w));
            const ValidationReport rep = w.validate();
            INFO((rep.first_error() ? rep.first_error()->message : std::string()));
            REQUIRE(rep.ok());
            CHECK(w.counts().euler() == euler);
            // Every accepted operation changes the tables, but storing the edge already stored
            // (set-vertex-edge, set-face-edge), which changes nothing and keeps the version.
            const bool nothing = c.steps.empty() && c.positions.empty();
            if (nothing) CHECK(std::string(op_name(call.op)).rfind("set-", 0) == 0);
            CHECK(w.version().topology == before.version.topology + (nothing ? 0 : 1));
            CHECK(c.before == before.version);
            CHECK(c.after == w.version());
            require_rebuild_agrees(w);
            // the steps replay the operation; the rows undo it
            CHECK(replay(tables_before, c) == tables(w));
            CHECK(undo(tables(w), c) == tables_before);
        }
        // compact: same counts, valid, each live face's cycle the same under the renumbering
        const MeshCounts k = w.counts();
        const IndexedMesh fs = w.face_set();
        const Renumbering map = w.compact();
        REQUIRE(w.validate().ok());
        CHECK(!w.has_garbage());
        const MeshCounts k2 = w.counts();
        CHECK((k2.vertices == k.vertices && k2.edges == k.edges && k2.faces == k.faces && k2.boundary_loops == k.boundary_loops));
        CHECK(w.vertex_count() == k.vertices);
        const IndexedMesh fs2 = w.face_set();
        for (int32_t f = 0; f < fs.face_count(); ++f) {
            if (map.faces[f] == kNone) {
                CHECK(fs.face_size(f) == 0);
                continue;
            }
            const int32_t g = map.faces[f];
            REQUIRE(fs2.face_size(g) == fs.face_size(f));
            for (int32_t i = 0; i < fs.face_size(f); ++i) CHECK(fs2.corner(g, i) == map.vertices[fs.corner(f, i)]);
        }
        require_rebuild_agrees(w);
    }
    // every operation ran on closed and open meshes of triangles, and (but the flip, which
    // needs two triangles) on closed and open polygon meshes
    for (const char* name : {"sphere", "tetrahedron", "grid", "lecture", "fan", "cube", "hexagons"})
        for (int op = 0; op < kOps; ++op) {
            if (op == FlipEdge && (std::string(name) == "cube" || std::string(name) == "hexagons")) continue;
            INFO(name << " " << op_name(op));
            CHECK(accepted_on[name].count(op) == 1);
        }
    for (int op = 0; op < kOps; ++op) {
        INFO(op_name(op) << " accepted " << accepted[op] << " refused " << refused[op]);
        CHECK(accepted[op] >= 20);
        CHECK(refused[op] >= 5);
    }
}

TEST_CASE("the other representations follow an edited mesh with gaps, numbered as the winged edge", "[mesh][euler]") {
    WingedEdgeMesh w = lecture();
    w.apply(operation("collapse-edge", Edge(label("e4")), 0.5)); // gaps: v4, e4, e5, F2
    RepresentationCache cache;
    const Representations& r = cache.of(w);
    // F2 is a gap: no corners in the vertex and face tables; F3 keeps its number.
    CHECK(r.vertex_face_tables.face_offsets == std::vector<int32_t>{0, 3, 3, 6});
    CHECK(r.vertex_face_tables.face_vertices == std::vector<int32_t>{0, 1, 2, 1, 4, 2});
    // the edge list: removed e4, e5 have no vertices and no faces
    for (int32_t e : {3, 4})
        for (int k = 0; k < 4; ++k) CHECK(r.edge_list.edges[4 * e + k] == kNone);
    // v4 (a gap) has no edges in the adjacency lists; v3 has e1, e3, e7
    const AdjacencyLists& a = r.adjacency_lists;
    CHECK(a.vertex_offsets[4] - a.vertex_offsets[3] == 0);
    std::vector<int32_t> at_v3(a.vertex_edges.begin() + a.vertex_offsets[2], a.vertex_edges.begin() + a.vertex_offsets[3]);
    CHECK(at_v3 == std::vector<int32_t>{0, 2, 6});
    const MeshCounts k = w.counts();
    CHECK((k.vertices == 4 && k.edges == 5 && k.faces == 2 && k.boundary_loops == 1 && k.isolated_vertices == 0));
}

TEST_CASE("the bounding box leaves out a removed vertex", "[mesh][euler]") {
    WingedEdgeMesh w = lecture();
    w.apply(operation("collapse-edge", Edge(label("e7")), 0.0)); // v5 = (2, -1), the only vertex below y = 0, merges into v4
    REQUIRE(w.is_deleted(Vertex(4)));
    const BoundingBox box = bounding_box(w);
    CHECK(box.min == glm::dvec3(0, 0, 0));
    CHECK(box.max == glm::dvec3(2, 2, 0));
}

TEST_CASE("join-faces refuses to leave a dangling edge at a vertex of valence 2", "[mesh][euler]") {
    // F1 = (v1 v2 v3 v4) and F2 = (v1 v4 v3 v5) share e = v3-v4 and v4-v1: v4 has only those
    // two edges. Removing v3-v4 would leave v4-v1 with the joined face on both sides.
    IndexedMesh m;
    m.add_vertex(0, 0, 0), m.add_vertex(2, 0, 0), m.add_vertex(2, 2, 0), m.add_vertex(1, 1, 0), m.add_vertex(0, 2, 0);
    m.add_face({0, 1, 2, 3});
    m.add_face({0, 3, 2, 4});
    WingedEdgeMesh w = WingedEdgeMesh::build(m);
    int32_t e = kNone;
    for (int32_t i = 0; i < w.edge_count(); ++i)
        if (std::minmax(w.edge(i).start, w.edge(i).end) == std::minmax(2, 3)) e = i;
    REQUIRE(e != kNone);
    const Snapshot before = snapshot(w);
    const CheckResult r = w.check(operation("join-faces", Edge(e)));
    CHECK(r.code == "faces-touch-elsewhere");
    CHECK(r.message == "F1 and F2 also meet at v1: joining them across " + edge_label(e) + " would make a face that passes v1 twice");
    CHECK_THROWS(w.apply(operation("join-faces", Edge(e))));
    CHECK(snapshot(w) == before);
}

TEST_CASE("what a split of e3 makes each representation rewrite, counted by hand", "[mesh][euler]") {
    const WingedEdgeMesh before = lecture();
    const Representations reps_before = build_representations(before.face_set(), before);
    // Nothing changed: nothing rewritten.
    CHECK(rewritten_entries(before, reps_before, before, reps_before) == std::array<int64_t, kRepresentationCount>{});
    WingedEdgeMesh after = before;
    const ChangeRecord change = after.apply(operation("split-edge", Edge(label("e3")), 0.5));
    const Representations reps_after = build_representations(after.face_set(), after);
    const auto n = rewritten_entries(before, reps_before, after, reps_after);
    // The same from the change record alone (what the binding computes, with no copy of the mesh).
    CHECK(rewritten_entries(change, reps_before, after, reps_after) == n);
    // Winged edge: v6's row (x, y, z, edge) and v3's edge: 5; e8's row (8), e3's E, E:L, E:R,
    // e1's E:R and e4's S:R: 13; the face table is unchanged. 18 = the 15 assignments + v6's xyz.
    CHECK(n[static_cast<int>(Representation::WingedEdge)] == 18);
    // Independent faces: F1 (v1 v2 v3) -> (v1 v2 v6 v3) rewrites its last two corners (6
    // numbers), F2 (v2 v4 v3) -> (v2 v4 v3 v6) gains one corner (3); F3 is unchanged.
    CHECK(n[static_cast<int>(Representation::IndependentFaces)] == 9);
    // Vertex and face tables: v6's xyz (3); F1's list from its third reference on (2), F2's new
    // fourth reference (1).
    CHECK(n[static_cast<int>(Representation::VertexFaceTables)] == 6);
}

TEST_CASE("an edit's cost from its change record equals the comparison of the two states, on random edits", "[mesh][euler]") {
    // The binding counts the winged edge's rewritten entries from the change record instead
    // of copying the mesh; the comparison of both states (rewritten_entries over two meshes)
    // is the independent recomputation.
    int compared = 0;
    for (const Fixture& fx : fixtures()) {
        for (uint32_t seed = 1; seed <= 12; ++seed) {
            std::mt19937 rng(seed);
            WingedEdgeMesh w = fx.mesh;
            for (int step = 0; step < 12; ++step) {
                const Call call = random_call(w, rng);
                if (!check(w, call).ok) continue;
                const WingedEdgeMesh before = w;
                const Representations reps_before = build_representations(before.face_set(), before);
                const ChangeRecord change = run(w, call);
                const Representations reps_after = build_representations(w.face_set(), w);
                INFO(fx.name << " seed " << seed << " step " << step << " " << op_name(call.op));
                CHECK(rewritten_entries(change, reps_before, w, reps_after) == rewritten_entries(before, reps_before, w, reps_after));
                ++compared;
            }
        }
    }
    CHECK(compared > 300);
}

// ====================================================================== split vertex

namespace {
// Each live face as its corners from the lowest-numbered one, so that two listings of one
// face compare equal wherever they start; sorted, gaps left out.
std::vector<std::vector<int32_t>> canonical_faces(const WingedEdgeMesh& w) {
    std::vector<std::vector<int32_t>> out;
    for (int32_t f = 0; f < w.face_count(); ++f) {
        if (w.is_deleted(Face(f))) continue;
        std::vector<int32_t> c = w.vertices_of_face(f);
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.push_back(c);
    }
    std::sort(out.begin(), out.end());
    return out;
}
} // namespace

TEST_CASE("split-vertex: the fan between a and b moves to a new vertex; V+1, E+3, F+2; collapse with t = 0 undoes it",
          "[mesh][euler][split-vertex]") {
    // Every (v, a, b) of every fixture with a few values of t: each split that the check
    // accepts is a valid mesh with the counts and positions of the definition, and
    // collapsing the new edge with t = 0 gives the face set and positions back.
    int splits = 0;
    for (const Fixture& fx : fixtures()) {
        for (int32_t v = 0; v < fx.mesh.vertex_count(); ++v) {
            const std::vector<int32_t> ring = fx.mesh.vertices_around_vertex(v);
            for (const int32_t a : ring)
                for (const int32_t b : ring) {
                    WingedEdgeMesh w = fx.mesh;
                    const double t = 0.25 + 0.25 * ((a + b) % 3);
                    INFO(fx.name << " v" << v + 1 << " a v" << a + 1 << " b v" << b + 1 << " t " << t);
                    const CheckResult c = w.check(operation("split-vertex", Vertex(v), Vertex(a), Vertex(b), t));
                    if (a == b) {
                        CHECK(c.code == "same-vertex");
                        continue;
                    }
                    REQUIRE(c.ok);
                    const MeshCounts before = w.counts();
                    const auto faces_before = canonical_faces(w);
                    const glm::dvec3 pv = w.position(v);
                    // The neighbours that move: strictly between a and b counter-clockwise.
                    std::vector<int32_t> moved;
                    const std::size_t ia = std::find(ring.begin(), ring.end(), a) - ring.begin();
                    for (std::size_t k = (ia + 1) % ring.size(); ring[k] != b; k = (k + 1) % ring.size()) moved.push_back(ring[k]);
                    glm::dvec3 centre = w.position(a) + w.position(b);
                    for (const int32_t u : moved) centre += w.position(u);
                    centre /= static_cast<double>(moved.size() + 2);

                    const ChangeRecord r = w.apply(operation("split-vertex", Vertex(v), Vertex(a), Vertex(b), t));
                    const ValidationReport rep = w.validate();
                    INFO((rep.first_error() ? rep.first_error()->message : std::string()));
                    REQUIRE(rep.ok());
                    const MeshCounts after = w.counts();
                    CHECK(after.vertices == before.vertices + 1);
                    CHECK(after.edges == before.edges + 3);
                    CHECK(after.faces == before.faces + 2);
                    CHECK(after.euler() == before.euler());
                    REQUIRE(r.added_vertices.size() == 1);
                    REQUIRE(r.added_edges.size() == 3);
                    REQUIRE(r.added_faces.size() == 2);
                    const int32_t nw = r.added_vertices[0].idx, ne = r.added_edges[0].idx;
                    // Positions: v stays, w = (1 - t) v + t c (relative to the mesh's size).
                    CHECK(w.position(v) == pv);
                    const glm::dvec3 expected = (1.0 - t) * pv + t * centre;
                    for (int k = 0; k < 3; ++k) CHECK(w.position(nw)[k] == Approx(expected[k]).margin(1e-12 * (1 + std::abs(expected[k]))));
                    // w's neighbours: v, a, b and the moved ones; v keeps the others.
                    std::vector<int32_t> around_w = w.vertices_around_vertex(nw);
                    std::sort(around_w.begin(), around_w.end());
                    std::vector<int32_t> want = moved;
                    want.insert(want.end(), {v, a, b});
                    std::sort(want.begin(), want.end());
                    CHECK(around_w == want);
                    // The new triangles are (v, a, w) and (v, w, b).
                    const auto has_face = [&](std::vector<int32_t> f) {
                        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
                        const auto all = canonical_faces(w);
                        return std::find(all.begin(), all.end(), f) != all.end();
                    };
                    CHECK(has_face({v, a, nw}));
                    CHECK(has_face({v, nw, b}));
                    // The inverse: collapse e = v -> w keeping v where it is.
                    REQUIRE(w.edge(ne).start == v);
                    REQUIRE(w.edge(ne).end == nw);
                    const CheckResult back = w.check(operation("collapse-edge", Edge(ne), 0.0));
                    INFO(back.message);
                    REQUIRE(back.ok);
                    w.apply(operation("collapse-edge", Edge(ne), 0.0));
                    REQUIRE(w.validate().ok());
                    CHECK(canonical_faces(w) == faces_before);
                    CHECK(w.position(v) == pv);
                    ++splits;
                }
        }
    }
    CHECK(splits > 500);
}

TEST_CASE("split-vertex refusals say why and change nothing", "[mesh][euler][split-vertex]") {
    WingedEdgeMesh w = lecture();
    const Snapshot before = snapshot(w);
    struct Case {
        Operation op;
        std::string code, text;
    };
    // v3 (index 2) is joined to v1, v2, v4, v5 on the slide's mesh; v6 (index 5) is not.
    const std::vector<Case> cases = {
        {operation("split-vertex", Vertex(2), Vertex(0), Vertex(0)), "same-vertex", "both are v1"},
        {operation("split-vertex", Vertex(2), Vertex(0), Vertex(2)), "not-a-neighbour", "v3 is not joined to v3"},
        {operation("split-vertex", Vertex(0), Vertex(1), Vertex(3)), "not-a-neighbour", "v4 is not joined to v1: choose two of v1's neighbours"},
        {operation("split-vertex", Vertex(2), Vertex(0), Vertex(1), 1.0), "invalid-parameter", "t = 1 is not strictly between 0 and 1"},
        {operation("split-vertex", Vertex(9), Vertex(0), Vertex(1)), "invalid-element", "there is no v10"},
        {operation("split-vertex", Vertex(2), Vertex(0)), "invalid-element", "-1 names no vertex"},
    };
    for (const Case& k : cases) {
        const CheckResult r = w.check(k.op);
        INFO(k.code << ": " << r.message);
        CHECK(!r.ok);
        CHECK(r.code == k.code);
        CHECK(r.message.find(k.text) != std::string::npos);
        CHECK_THROWS_AS(w.apply(k.op), wingspline::Error);
        CHECK(!apply_unrecorded(w, k.op));
        CHECK(snapshot(w) == before);
    }
}

TEST_CASE("every operation of the registry has its unrecorded run, found by name", "[mesh][euler]") {
    // The runs are kept apart from the registry (so the page's modules leave them out): a
    // new operation without one would be found missing here, not in a benchmark.
    for (const OperationEntry& e : operations()) {
        INFO(e.name);
        REQUIRE(unrecorded_run(e) != nullptr);
    }
}
