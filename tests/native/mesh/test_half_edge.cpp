// The half-edge view (half_edge.h) against lecture 000's tables worked out by hand, its
// invariants on every generator and after thousands of random edits and undos (update()
// equal to a fresh build each time), its walks against the winged-edge walks and its query
// answers against the other representations'.
#include <catch2/catch.hpp>

#include "random_edits.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/half_edge.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace wingspline::mesh;
using namespace wingspline::test_edits;

namespace {

void require_valid(const HalfEdgeMesh& h, const WingedEdgeMesh& w) {
    const ValidationReport r = h.validate(w);
    INFO((r.first_error() ? r.first_error()->message : std::string()));
    REQUIRE(r.ok());
}

// "h3" -> 2, "v2" -> 1, "F1" -> 0, "-" -> kNone: the slides' 1-based labels.
int32_t label(const std::string& s) { return s == "-" ? kNone : std::stoi(s.substr(1)) - 1; }

// One half-edge row as the page shows it: h, origin, target, face, next, prev.
using Row = std::array<const char*, 6>;

void require_rows(const HalfEdgeMesh& h, const std::vector<Row>& rows, const std::vector<const char*>& vertices,
                  const std::vector<const char*>& faces) {
    REQUIRE(h.halfedge_count() == static_cast<int32_t>(rows.size()));
    for (const Row& r : rows) {
        const int32_t x = label(r[0]);
        INFO(r[0]);
        CHECK(h.origin(x) == label(r[1]));
        CHECK(h.target(x) == label(r[2]));
        CHECK(h.face(x) == label(r[3]));
        CHECK(h.next(x) == label(r[4]));
        CHECK(h.prev(x) == label(r[5]));
        CHECK(twin(x) == (x % 2 == 0 ? x + 1 : x - 1));
    }
    REQUIRE(h.vertex_count() == static_cast<int32_t>(vertices.size()));
    for (std::size_t v = 0; v < vertices.size(); ++v) CHECK(h.vertex_halfedge(static_cast<int32_t>(v)) == label(vertices[v]));
    REQUIRE(h.face_count() == static_cast<int32_t>(faces.size()));
    for (std::size_t f = 0; f < faces.size(); ++f) CHECK(h.face_halfedge(static_cast<int32_t>(f)) == label(faces[f]));
}

// The slide's vertex and face tables of the half-edge view of lecture 000, before and after
// flip e3, worked out by hand (half_edge.h's rules, applied to the winged-edge rows below).
//
// The slide (lecture 000):   e  S  E  L  R  SL SR EL ER
//                            e1 v1 v3 -  F1 e2 e2 e4 e3
//                            e2 v1 v2 F1 -  e1 e1 e3 e6
//                            e3 v2 v3 F1 F2 e2 e5 e1 e4
//                            e4 v3 v4 -  F2 e1 e3 e7 e5
//                            e5 v2 v4 F2 F3 e3 e6 e4 e7
//                            e6 v2 v5 F3 -  e5 e2 e7 e7
//                            e7 v4 v5 -  F3 e4 e5 e6 e6
//        v3 ------- v4
//       /  \  F2  /  \        F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4); every vertex
//     v1 F1 \    / F3 v5      is on the one boundary loop v1 -> v3 -> v4 -> v5 -> v2 -> v1
//       \    \  /   /         (the boundary half-edges h1, h7, h13, h12, h4).
//        ---- v2 ---
// e_k gives h(2k-1) = S -> E (face L) and h(2k) = E -> S (face R). next(S->E) is EL's half-edge
// leaving E, prev(S->E) SL's arriving at S; next(E->S) is SR's leaving S, prev(E->S) ER's
// arriving at E. E.g. h1 = e1 v1 -> v3: EL = e4 = v3 -> v4 leaves v3 as h7; SL = e2 = v1 -> v2
// arrives at v1 as h4 (v2 -> v1).
const std::vector<Row> kLectureRows = {
    // h     origin target face next   prev
    {"h1", "v1", "v3", "-", "h7", "h4"},    {"h2", "v3", "v1", "F1", "h3", "h5"},
    {"h3", "v1", "v2", "F1", "h5", "h2"},   {"h4", "v2", "v1", "-", "h1", "h12"},
    {"h5", "v2", "v3", "F1", "h2", "h3"},   {"h6", "v3", "v2", "F2", "h9", "h8"},
    {"h7", "v3", "v4", "-", "h13", "h1"},   {"h8", "v4", "v3", "F2", "h6", "h9"},
    {"h9", "v2", "v4", "F2", "h8", "h6"},   {"h10", "v4", "v2", "F3", "h11", "h14"},
    {"h11", "v2", "v5", "F3", "h14", "h10"}, {"h12", "v5", "v2", "-", "h4", "h13"},
    {"h13", "v4", "v5", "-", "h12", "h7"},  {"h14", "v5", "v4", "F3", "h10", "h11"},
};
// Every vertex is on the boundary: its outgoing boundary half-edge. F1 stores e1, whose L is
// not F1, so its E -> S side h2; F2 stores e3 (R = F2): h6; F3 stores e5 (R = F3): h10.
const std::vector<const char*> kLectureVertices = {"h1", "h4", "h7", "h13", "h12"};
const std::vector<const char*> kLectureFaces = {"h2", "h6", "h10"};

// After flip e3 (docs/api-mesh.md: e between (S,E,c) and (E,S,d) becomes d -> c): e3 = v4 -> v1
// with F1 = (v1 v2 v4) on its left and F2 = (v4 v3 v1) on its right. The winged-edge rows
// after it, as test_exercise_edit.cpp works them out by hand:
//   e1 v1 v3 - F2 e2 e3 e4 e4;  e2 v1 v2 F1 - e3 e1 e5 e6;  e3 v4 v1 F1 F2 e5 e4 e2 e1;
//   e4 v3 v4 - F2 e1 e1 e7 e3;  e5 v2 v4 F1 F3 e2 e6 e3 e7;  e6, e7 as before; v3 stores e1,
//   F1 stores e3.
const std::vector<Row> kFlippedRows = {
    {"h1", "v1", "v3", "-", "h7", "h4"},    {"h2", "v3", "v1", "F2", "h6", "h8"},
    {"h3", "v1", "v2", "F1", "h9", "h5"},   {"h4", "v2", "v1", "-", "h1", "h12"},
    {"h5", "v4", "v1", "F1", "h3", "h9"},   {"h6", "v1", "v4", "F2", "h8", "h2"},
    {"h7", "v3", "v4", "-", "h13", "h1"},   {"h8", "v4", "v3", "F2", "h2", "h6"},
    {"h9", "v2", "v4", "F1", "h5", "h3"},   {"h10", "v4", "v2", "F3", "h11", "h14"},
    {"h11", "v2", "v5", "F3", "h14", "h10"}, {"h12", "v5", "v2", "-", "h4", "h13"},
    {"h13", "v4", "v5", "-", "h12", "h7"},  {"h14", "v5", "v4", "F3", "h10", "h11"},
};
const std::vector<const char*> kFlippedFaces = {"h5", "h6", "h10"};

Operation flip(int32_t e) {
    const double args[] = {static_cast<double>(e)};
    return operation_from("flip-edge", args, 1);
}

std::vector<int32_t> sorted(std::vector<int32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

} // namespace

TEST_CASE("half-edge: the lecture mesh's tables, worked out by hand from the slide", "[mesh][half-edge]") {
    const WingedEdgeMesh w = lecture();
    const HalfEdgeMesh h = HalfEdgeMesh::build(w);
    require_valid(h, w);
    require_rows(h, kLectureRows, kLectureVertices, kLectureFaces);
}

TEST_CASE("half-edge: flip e3 and take it back, by update and by a fresh build", "[mesh][half-edge]") {
    WingedEdgeMesh w = lecture();
    HalfEdgeMesh h = HalfEdgeMesh::build(w);
    const ChangeRecord c = w.apply(flip(2));
    h.update(w, c);
    require_valid(h, w);
    require_rows(h, kFlippedRows, kLectureVertices, kFlippedFaces);
    REQUIRE(h == HalfEdgeMesh::build(w));
    const ChangeRecord u = w.undo(c);
    h.update(w, u);
    require_rows(h, kLectureRows, kLectureVertices, kLectureFaces);
}

TEST_CASE("half-edge: a removed edge's rows are empty until the mesh is compacted", "[mesh][half-edge]") {
    WingedEdgeMesh w = lecture();
    HalfEdgeMesh h = HalfEdgeMesh::build(w);
    const double args[] = {2}; // join-faces e3: F1 and F2 become one quad, e3 a gap
    const ChangeRecord c = w.apply(operation_from("join-faces", args, 1));
    REQUIRE(w.is_deleted(Edge(2)));
    h.update(w, c);
    require_valid(h, w);
    REQUIRE(h == HalfEdgeMesh::build(w));
    for (const int32_t x : {4, 5}) {
        CHECK(h.origin(x) == kNone);
        CHECK(h.face(x) == kNone);
        CHECK(h.next(x) == kNone);
        CHECK(h.prev(x) == kNone);
    }
    const int32_t removed_face = c.removed_faces.at(0).idx;
    CHECK(h.face_halfedge(removed_face) == kNone);
    w.compact();
    const HalfEdgeMesh compacted = HalfEdgeMesh::build(w);
    require_valid(compacted, w);
    CHECK(compacted.halfedge_count() == 12);
}

TEST_CASE("half-edge: valid on every generator; 4 int32 per half-edge, as many bytes as the edge table", "[mesh][half-edge]") {
    for (const Fixture& fx : fixtures()) {
        INFO(fx.name);
        const HalfEdgeMesh h = HalfEdgeMesh::build(fx.mesh);
        require_valid(h, fx.mesh);
        const std::size_t E = fx.mesh.edge_count(), V = fx.mesh.vertex_count(), F = fx.mesh.face_count();
        CHECK(h.storage().entries() == 8 * E + V + F);
        CHECK(h.storage().bytes() == 4 * (8 * E + V + F));
        // The winged edge's edge table is 8 int32 per edge too: the same bytes, other fields.
        CHECK(half_edge_storage(h, fx.mesh).bytes() == winged_edge_storage(fx.mesh).bytes());
    }
    for (const IndexedMesh& m : {grid(7, 5), uv_sphere(12, 9), open_fan(9)}) require_valid(HalfEdgeMesh::build(WingedEdgeMesh::build(m)), WingedEdgeMesh::build(m));
}

TEST_CASE("half-edge: validate() names a broken rule", "[mesh][half-edge]") {
    const WingedEdgeMesh w = lecture();
    const HalfEdgeMesh good = HalfEdgeMesh::build(w);
    // A view of another mesh is refused: the tables do not match this one's sizes.
    const HalfEdgeMesh other = HalfEdgeMesh::build(WingedEdgeMesh::build(cube()));
    CHECK(other.validate(w).has("half-edge-broken"));
    CHECK(good.validate(WingedEdgeMesh::build(cube())).first_error()->message.find("the half-edge tables hold 14") != std::string::npos);
    // The lecture mesh's view checked against the mesh after join-faces e3 (same table sizes:
    // e3 and a face stay as gaps): e3's rows should be empty, and the joined face has four
    // corners where the old loop has three.
    WingedEdgeMesh joined = lecture();
    const double args[] = {2};
    joined.apply(operation_from("join-faces", args, 1));
    const ValidationReport r = good.validate(joined);
    REQUIRE(!r.ok());
    bool names_gap = false, names_loop = false;
    for (const Problem& p : r.problems) {
        CHECK(p.code == "half-edge-broken");
        names_gap = names_gap || p.message.find("e3, which an edit removed") != std::string::npos;
        names_loop = names_loop || p.message.find("has 4 corners, but the next-loop") != std::string::npos;
    }
    CHECK(names_gap);
    CHECK(names_loop);
}

TEST_CASE("half-edge: update() equals a fresh build after thousands of random edits and undos", "[mesh][half-edge]") {
    std::size_t edits = 0, undos = 0;
    for (uint32_t seed = 1; seed <= 32; ++seed) {
        std::vector<Fixture> all = fixtures();
        Fixture& fx = all[seed % all.size()];
        WingedEdgeMesh& w = fx.mesh;
        HalfEdgeMesh h = HalfEdgeMesh::build(w);
        std::mt19937 rng(seed);
        std::vector<ChangeRecord> history;
        for (int round = 0; round < 250; ++round) {
            INFO(fx.name << " seed " << seed << " round " << round);
            if (!history.empty() && rng() % 4 == 0) {
                const std::size_t k = 1 + rng() % history.size();
                for (std::size_t i = 0; i < k; ++i) {
                    const ChangeRecord u = w.undo(history.back());
                    INFO("undo " << history.back().op);
                    history.pop_back();
                    h.update(w, u);
                    REQUIRE(h == HalfEdgeMesh::build(w));
                    require_valid(h, w);
                    ++undos;
                }
                continue;
            }
            const Operation op = operation_of(random_call(w, rng));
            if (!w.check(op).ok) continue;
            ChangeRecord c = w.apply(op);
            if (!c.changed()) continue;
            INFO(c.op);
            h.update(w, c);
            REQUIRE(h == HalfEdgeMesh::build(w));
            require_valid(h, w);
            history.push_back(std::move(c));
            ++edits;
        }
    }
    INFO("edits " << edits << ", undos " << undos);
    CHECK(edits >= 2000);
    CHECK(undos >= 1000);
}

namespace {
// Meshes the shared fixtures lack: a grid of quads with two holes (three boundary loops),
// a fan of 50 triangles around one vertex (valence 51, on the boundary), and a closed fan of
// 50 triangles plus a 50-gon cap (an interior vertex of valence 50 and a 50-sided face).
std::vector<Fixture> harder_fixtures() {
    IndexedMesh holes;
    constexpr int kN = 7;
    for (int y = 0; y <= kN; ++y)
        for (int x = 0; x <= kN; ++x) holes.add_vertex(x, y, 0);
    for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x) {
            if ((x == 2 && y == 2) || (x == 4 && y == 4)) continue; // the two holes
            const int32_t a = y * (kN + 1) + x;
            holes.add_face({a, a + 1, a + kN + 2, a + kN + 1});
        }
    IndexedMesh cone;
    constexpr int kK = 50;
    const int32_t apex = cone.add_vertex(0, 0, 1);
    for (int i = 0; i < kK; ++i) cone.add_vertex(std::cos(2 * M_PI * i / kK), std::sin(2 * M_PI * i / kK), 0);
    std::vector<int32_t> cap;
    for (int i = 0; i < kK; ++i) {
        cone.add_face({apex, 1 + i, 1 + (i + 1) % kK});
        cap.push_back(1 + (kK - i) % kK); // the cap's corners, CCW seen from below
    }
    cone.add_face(cap.data(), static_cast<int32_t>(cap.size()));
    std::vector<Fixture> out;
    out.push_back({"two holes", WingedEdgeMesh::build(holes)});
    out.push_back({"fan of 50", WingedEdgeMesh::build(open_fan(50))});
    out.push_back({"cone of 50 and its cap", WingedEdgeMesh::build(cone)});
    return out;
}

// The boundary loops of the winged edge, counted independently of the half-edge view: edges
// with a missing face, joined end to start.
int boundary_loops(const WingedEdgeMesh& w) {
    std::vector<std::pair<int32_t, int32_t>> sides; // (from, to) along the boundary, face on the left missing
    for (const EdgeRecord& r : w.edges()) {
        if (r.start == kNone) continue;
        if (r.left == kNone) sides.push_back({r.start, r.end});
        if (r.right == kNone) sides.push_back({r.end, r.start});
    }
    std::vector<int32_t> next_of(w.vertex_count(), kNone);
    for (const auto& [a, b] : sides) next_of[a] = b;
    std::vector<char> seen(w.vertex_count(), 0);
    int loops = 0;
    for (const auto& [a, b] : sides) {
        if (seen[a]) continue;
        ++loops;
        for (int32_t v = a; v != kNone && !seen[v]; v = next_of[v]) seen[v] = 1;
    }
    return loops;
}
} // namespace

TEST_CASE("half-edge: several boundary loops, valence 50 and a 50-gon, through random edits", "[mesh][half-edge]") {
    const std::vector<int> expected_loops = {3, 1, 0};
    std::size_t edits = 0;
    std::vector<Fixture> start = harder_fixtures();
    for (std::size_t k = 0; k < start.size(); ++k) {
        INFO(start[k].name);
        const HalfEdgeMesh h0 = HalfEdgeMesh::build(start[k].mesh);
        require_valid(h0, start[k].mesh);
        // Each boundary loop is one next-cycle of boundary half-edges.
        int cycles = 0;
        std::vector<char> seen(h0.halfedge_count(), 0);
        for (int32_t x = 0; x < h0.halfedge_count(); ++x) {
            if (!h0.is_boundary(x) || seen[x]) continue;
            ++cycles;
            for (int32_t y = x; !seen[y]; y = h0.next(y)) {
                REQUIRE(h0.is_boundary(y));
                seen[y] = 1;
            }
        }
        CHECK(cycles == expected_loops[k]);
        CHECK(boundary_loops(start[k].mesh) == expected_loops[k]);
        // Every vertex's walk meets exactly its valence, counted from the edge table.
        std::vector<int> valence(start[k].mesh.vertex_count(), 0);
        for (const EdgeRecord& r : start[k].mesh.edges()) ++valence[r.start], ++valence[r.end];
        for (int32_t v = 0; v < h0.vertex_count(); ++v) CHECK(static_cast<int>(h0.vertex_walk(v).size()) == valence[v]);
        for (uint32_t seed = 1; seed <= 8; ++seed) {
            std::vector<Fixture> again = harder_fixtures();
            WingedEdgeMesh& w = again[k].mesh;
            HalfEdgeMesh h = HalfEdgeMesh::build(w);
            std::mt19937 rng(100 + seed);
            for (int round = 0; round < 150; ++round) {
                const Operation op = operation_of(random_call(w, rng));
                if (!w.check(op).ok) continue;
                const ChangeRecord c = w.apply(op);
                if (!c.changed()) continue;
                INFO("seed " << seed << " round " << round << " " << c.op);
                h.update(w, c);
                REQUIRE(h == HalfEdgeMesh::build(w));
                require_valid(h, w);
                ++edits;
            }
        }
    }
    INFO("edits " << edits);
    CHECK(edits >= 1000);
}

TEST_CASE("half-edge: the walks meet the winged-edge walks' edges in the same order", "[mesh][half-edge]") {
    std::mt19937 rng(7);
    for (Fixture& fx : fixtures()) {
        WingedEdgeMesh& w = fx.mesh;
        for (int k = 0; k < 40; ++k) { // a few edits first, so that gaps and moved edges are walked too
            const Operation op = operation_of(random_call(w, rng));
            if (w.check(op).ok) w.apply(op);
        }
        const HalfEdgeMesh h = HalfEdgeMesh::build(w);
        for (int32_t v = 0; v < w.vertex_count(); ++v) {
            if (w.is_deleted(Vertex(v)) || w.vertex_edge(v) == kNone) continue;
            INFO(fx.name << " v" << v + 1);
            const std::vector<TraversalStep> wing = w.traversal_steps(v);
            // Started where the winged-edge walk starts (the outgoing half-edge along v's edge).
            const int32_t e0 = w.vertex_edge(v);
            const int32_t start = w.edge(e0).start == v ? 2 * e0 : 2 * e0 + 1;
            const std::vector<HalfEdgeStep> half = h.vertex_walk(v, start);
            REQUIRE(half.size() == wing.size());
            for (std::size_t i = 0; i < half.size(); ++i) {
                CHECK(edge_of_half_edge(half[i].halfedge) == wing[i].edge);
                CHECK(h.origin(half[i].halfedge) == v);
                CHECK(half[i].next == twin(half[i].read));
                CHECK(edge_of_half_edge(half[i].next) == wing[i].next);
            }
            // From v's own half-edge: the same ring, turned to begin at the boundary (if any).
            const std::vector<HalfEdgeStep> own = h.vertex_walk(v);
            REQUIRE(own.size() == wing.size());
            const auto at = std::find_if(wing.begin(), wing.end(), [&](const TraversalStep& s) { return s.edge == edge_of_half_edge(own[0].halfedge); });
            REQUIRE(at != wing.end());
            const std::size_t offset = static_cast<std::size_t>(at - wing.begin());
            for (std::size_t i = 0; i < own.size(); ++i) CHECK(edge_of_half_edge(own[i].halfedge) == wing[(i + offset) % wing.size()].edge);
        }
        for (int32_t f = 0; f < w.face_count(); ++f) {
            if (w.is_deleted(Face(f))) continue;
            INFO(fx.name << " F" << f + 1);
            const std::vector<FaceStep> wing = w.face_edge_steps(f);
            const std::vector<HalfEdgeStep> half = h.face_walk(f);
            REQUIRE(half.size() == wing.size());
            for (std::size_t i = 0; i < half.size(); ++i) {
                CHECK(edge_of_half_edge(half[i].halfedge) == wing[i].edge);
                CHECK(h.face(half[i].halfedge) == f);
                CHECK(edge_of_half_edge(half[i].next) == wing[i].next);
            }
        }
    }
}

TEST_CASE("half-edge: around v2 of the lecture CCW from its boundary half-edge h4: e2, e6, e5, e3", "[mesh][half-edge]") {
    const WingedEdgeMesh w = lecture();
    const HalfEdgeMesh h = HalfEdgeMesh::build(w);
    // h4 (v2 -> v1, boundary); prev(h4) = h12, twin h11 (e6); prev(h11) = h10, twin h9 (e5);
    // prev(h9) = h6, twin h5 (e3); prev(h5) = h3, twin h4: back at the start.
    const std::vector<HalfEdgeStep> steps = h.vertex_walk(label("v2"));
    REQUIRE(steps.size() == 4);
    const int32_t expected[4][3] = {{4, 12, 11}, {11, 10, 9}, {9, 6, 5}, {5, 3, 4}}; // h, prev(h), twin(prev(h)), 1-based
    for (int i = 0; i < 4; ++i) {
        CHECK(steps[i].halfedge == expected[i][0] - 1);
        CHECK(steps[i].read == expected[i][1] - 1);
        CHECK(steps[i].next == expected[i][2] - 1);
    }
    // Along F2 from h6: h6 -> h9 -> h8 -> h6.
    const std::vector<HalfEdgeStep> face = h.face_walk(label("F2"));
    REQUIRE(face.size() == 3);
    CHECK(face[0].halfedge == 5);
    CHECK(face[1].halfedge == 8);
    CHECK(face[2].halfedge == 7);
    CHECK(face[2].next == 5);
}

TEST_CASE("half-edge: the lecture's queries give the other representations' answers", "[mesh][half-edge]") {
    std::mt19937 rng(11);
    for (Fixture& fx : fixtures()) {
        WingedEdgeMesh& w = fx.mesh;
        for (int k = 0; k < 20; ++k) {
            const Operation op = operation_of(random_call(w, rng));
            if (w.check(op).ok) w.apply(op);
        }
        const HalfEdgeMesh h = HalfEdgeMesh::build(w);
        const Representations reps = build_representations(w.face_set(), w);
        for (const QueryKind kind : {QueryKind::FacesAroundVertex, QueryKind::EdgesAroundVertex, QueryKind::EdgesOfFace,
                                     QueryKind::FacesOfEdge, QueryKind::NeighboursOfFace}) {
            const ElementKind of = query_element_kind(kind);
            const int32_t n = count_of(w, of);
            for (int32_t x = 0; x < n; ++x) {
                if (!is_live(w, of, x)) continue;
                INFO(fx.name << " query " << static_cast<int>(kind) << " element " << x);
                const QueryAnswer half = half_edge_answer(kind, x, h, w);
                const auto all = answer_query(kind, x, reps, w);
                for (const QueryAnswer& a : all) CHECK(sorted(half.answer) == sorted(a.answer));
                const QueryAnswer& wing = all[static_cast<int>(Representation::WingedEdge)];
                // The face queries start where the winged edge's do; so does a vertex whose
                // half-edge runs along its winged-edge edge.
                if (of != ElementKind::Vertex || edge_of_half_edge(h.vertex_halfedge(x)) == w.vertex_edge(x))
                    CHECK(half.answer == wing.answer);
                // The walks read a constant number of entries per step, as the winged edge does:
                // one pointer per step where the winged edge reads the row's S (or L) and a wing.
                if (kind == QueryKind::EdgesAroundVertex || kind == QueryKind::EdgesOfFace)
                    CHECK(half.entries_read == 1 + half.answer.size());
            }
        }
    }
    const WingedEdgeMesh w = lecture();
    CHECK_THROWS_AS(half_edge_answer(QueryKind::EdgesOfFace, 3, HalfEdgeMesh::build(w), w), wingspline::Error);
}

// ---------------------------------------------------------------- an edit in half-edge terms

namespace {

// The six columns of a view as plain arrays, to replay a record on.
struct Tables {
    std::vector<int32_t> columns[4]; // origin, face, next, prev: in HalfEdgeField's order
    std::vector<int32_t> vertex, face;
    explicit Tables(const HalfEdgeMesh& h)
        : columns{h.origins(), h.faces(), h.nexts(), h.prevs()}, vertex(h.vertex_halfedges()), face(h.face_halfedges()) {}
    int32_t& at(const HalfEdgeAssignment& a) {
        if (a.table == HalfEdgeTable::Vertex) return vertex.at(a.row);
        if (a.table == HalfEdgeTable::Face) return face.at(a.row);
        return columns[static_cast<int>(a.field)].at(a.row);
    }
    // Rows the edit added start empty (kNone in every field), as the view's arrays grow.
    void grow_to(const HalfEdgeMesh& h) {
        for (auto& c : columns) c.resize(std::max(c.size(), h.origins().size()), kNone);
        vertex.resize(std::max(vertex.size(), h.vertex_halfedges().size()), kNone);
        face.resize(std::max(face.size(), h.face_halfedges().size()), kNone);
    }
    void shrink_to(const HalfEdgeMesh& h) {
        for (auto& c : columns) c.resize(h.origins().size());
        vertex.resize(h.vertex_halfedges().size());
        face.resize(h.face_halfedges().size());
    }
    bool operator==(const HalfEdgeMesh& h) const {
        return columns[0] == h.origins() && columns[1] == h.faces() && columns[2] == h.nexts() && columns[3] == h.prevs() &&
               vertex == h.vertex_halfedges() && face == h.face_halfedges();
    }
};

// Replays `record` on the view `before`: every entry's before must be what the row holds
// then (so no entry is listed twice), and after must differ from it.
Tables replay(const HalfEdgeMesh& before, const HalfEdgeMesh& after, const std::vector<HalfEdgeAssignment>& record) {
    Tables t(before);
    t.grow_to(after);
    for (const HalfEdgeAssignment& a : record) {
        INFO("table " << static_cast<int>(a.table) << " row " << a.row << " field " << static_cast<int>(a.field));
        int32_t& cell = t.at(a);
        CHECK(cell == a.before);
        CHECK(a.before != a.after);
        cell = a.after;
    }
    // Rows an undo dropped: the record left them empty first.
    for (const auto& c : t.columns)
        for (std::size_t x = after.origins().size(); x < c.size(); ++x) CHECK(c[x] == kNone);
    t.shrink_to(after);
    return t;
}

// Entries attributed to a winged-edge step come first, in the steps' order, and that step
// names the entry's element (an edge of a half-edge row, the vertex, the face).
void require_followable(const std::vector<HalfEdgeAssignment>& record, const ChangeRecord& c) {
    int32_t last = 0;
    bool reached = false;
    for (const HalfEdgeAssignment& a : record) {
        if (a.step == kNone) { reached = true; continue; }
        REQUIRE(!reached);
        REQUIRE(a.step >= last);
        last = a.step;
        const AssignmentStep& s = c.steps.at(a.step);
        const MeshTable named = a.table == HalfEdgeTable::HalfEdge ? MeshTable::Edge : a.table == HalfEdgeTable::Vertex ? MeshTable::Vertex : MeshTable::Face;
        CHECK(s.table == named);
        CHECK(s.row == (a.table == HalfEdgeTable::HalfEdge ? edge_of_half_edge(a.row) : a.row));
    }
}

} // namespace

TEST_CASE("half-edge record: flip e3 of the lecture mesh, worked out by hand", "[mesh][half-edge]") {
    // kLectureRows against kFlippedRows above, entry by entry (1-based labels): the rows of
    // e1, e4 and e6, e7 stay; e2's S -> E (h3) gets a new next and prev (F1 is now v1 v2 v4);
    // e3's both halves (h5, h6) turn to v4 -> v1 and v1 -> v4; e4's E -> S (h8) and e5's
    // S -> E (h9, now on F1) follow; e1's E -> S (h2) is now on F2. F1 stores e3 now, on whose
    // left it lies, so its half-edge is e3's S -> E, h5; F2 keeps h6, every vertex its own.
    struct Entry {
        HalfEdgeTable table;
        const char* row;
        HalfEdgeField field;
        const char* before;
        const char* after;
    };
    using T = HalfEdgeTable;
    using Fd = HalfEdgeField;
    const std::vector<Entry> by_hand = {
        {T::HalfEdge, "h2", Fd::Face, "F1", "F2"}, {T::HalfEdge, "h2", Fd::Next, "h3", "h6"}, {T::HalfEdge, "h2", Fd::Prev, "h5", "h8"},
        {T::HalfEdge, "h3", Fd::Next, "h5", "h9"}, {T::HalfEdge, "h3", Fd::Prev, "h2", "h5"},
        {T::HalfEdge, "h5", Fd::Origin, "v2", "v4"}, {T::HalfEdge, "h5", Fd::Next, "h2", "h3"}, {T::HalfEdge, "h5", Fd::Prev, "h3", "h9"},
        {T::HalfEdge, "h6", Fd::Origin, "v3", "v1"}, {T::HalfEdge, "h6", Fd::Next, "h9", "h8"}, {T::HalfEdge, "h6", Fd::Prev, "h8", "h2"},
        {T::HalfEdge, "h8", Fd::Next, "h6", "h2"}, {T::HalfEdge, "h8", Fd::Prev, "h9", "h6"},
        {T::HalfEdge, "h9", Fd::Face, "F2", "F1"}, {T::HalfEdge, "h9", Fd::Next, "h8", "h5"}, {T::HalfEdge, "h9", Fd::Prev, "h6", "h3"},
        {T::Face, "F1", Fd::HalfEdge, "h2", "h5"},
    };
    WingedEdgeMesh w = lecture();
    HalfEdgeMesh h = HalfEdgeMesh::build(w);
    const HalfEdgeMesh before = h;
    const ChangeRecord c = w.apply(flip(2));
    std::vector<HalfEdgeAssignment> record;
    h.update(w, c, &record);
    require_rows(h, kFlippedRows, kLectureVertices, kFlippedFaces);
    REQUIRE(record.size() == by_hand.size()); // 17 entries: 16 half-edge fields and F1's half-edge
    for (const Entry& e : by_hand) {
        INFO(e.row << " field " << static_cast<int>(e.field));
        const auto found = std::find_if(record.begin(), record.end(), [&](const HalfEdgeAssignment& a) {
            return a.table == e.table && a.row == label(e.row) && a.field == e.field;
        });
        REQUIRE(found != record.end());
        CHECK(found->before == label(e.before));
        CHECK(found->after == label(e.after));
    }
    // Grouped as the winged-edge record names the edges: e3's two halves first (the flip's
    // first line rewrites e3's row), and each half-edge's fields together.
    require_followable(record, c);
    CHECK(edge_of_half_edge(record.front().row) == 2);
    CHECK(replay(before, h, record) == h);
    // The record without the view's rows: an update without it writes the same view.
    HalfEdgeMesh quiet = before;
    quiet.update(w, c);
    CHECK(quiet == h);
}

TEST_CASE("half-edge record: every operation on random meshes, replayed on the view before, gives the view after", "[mesh][half-edge]") {
    std::vector<int> applied(kOps, 0);
    std::size_t undos = 0;
    for (uint32_t seed = 1; seed <= 32; ++seed) {
        std::vector<Fixture> all = fixtures();
        Fixture& fx = all[seed % all.size()];
        WingedEdgeMesh& w = fx.mesh;
        HalfEdgeMesh h = HalfEdgeMesh::build(w);
        std::mt19937 rng(seed * 7919);
        std::vector<ChangeRecord> history;
        for (int round = 0; round < 200; ++round) {
            INFO(fx.name << " seed " << seed << " round " << round);
            const HalfEdgeMesh before = h;
            std::vector<HalfEdgeAssignment> record;
            if (!history.empty() && rng() % 5 == 0) {
                const ChangeRecord u = w.undo(history.back());
                history.pop_back();
                h.update(w, u, &record);
                ++undos;
            } else {
                const Call call = random_call(w, rng);
                const Operation op = operation_of(call);
                if (!w.check(op).ok) continue;
                ChangeRecord c = w.apply(op);
                if (!c.changed()) continue;
                INFO(c.op);
                h.update(w, c, &record);
                require_followable(record, c);
                ++applied[call.op];
                history.push_back(std::move(c));
            }
            // Computed independently: the view built afresh from the winged edge after the edit.
            const HalfEdgeMesh fresh = HalfEdgeMesh::build(w);
            REQUIRE(h == fresh);
            REQUIRE(replay(before, fresh, record) == fresh);
        }
    }
    for (int op = 0; op < kOps; ++op) {
        INFO(op_name(op));
        const std::string name = op_name(op);
        for (const char* edit : {"flip-edge", "split-edge", "split-face", "join-faces", "collapse-edge", "poke-face", "split-vertex"})
            if (name == edit) CHECK(applied[op] >= 20);
    }
    CHECK(undos >= 400);
}
