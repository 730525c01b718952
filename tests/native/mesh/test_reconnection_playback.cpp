// The reconnection phase of a subdivision step as pointer assignments
// (reconnection_playback, subdivision.h). Checked against:
//  * the next level's own tables: the steps, applied to empty tables, give them exactly,
//    and no entry is written twice;
//  * locality, recomputed from the face sets: every face that a step of old face f writes
//    (a face-table row, or an L or R value) has its corners among f's corners, the points on
//    f's sides and f's face point, and every edge row it writes joins two such points;
//  * hand counts: the tetrahedron under Loop (10 + 16 + 24 x 8 = 218 entries, by line) and
//    the cube under Catmull-Clark; the lecture's example (open: line 4 has work to do).
#include <catch2/catch.hpp>

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/subdivision.h"
#include "wingspline/mesh/winged_edge.h"

#include <array>
#include <map>
#include <random>
#include <set>

using namespace wingspline::mesh;

namespace {

struct Tables {
    std::vector<int32_t> vertex, face;
    std::vector<std::array<int32_t, 8>> edge;
};

int field_slot(const std::string& f) {
    static const char* names[] = {"start", "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"};
    for (int i = 0; i < 8; ++i)
        if (f == names[i]) return i;
    return -1;
}

std::array<int32_t, 8> row_of(const EdgeRecord& r) {
    return {r.start, r.end, r.left, r.right, r.start_left, r.start_right, r.end_left, r.end_right};
}

// Plays the steps into empty tables of the result's size; counts entries written twice.
Tables play(const ReconnectionPlayback& p, const WingedEdgeMesh& result, int& twice) {
    Tables t;
    t.vertex.assign(result.vertex_count(), kNone);
    t.face.assign(result.face_count(), kNone);
    t.edge.assign(result.edge_count(), {kNone, kNone, kNone, kNone, kNone, kNone, kNone, kNone});
    std::set<std::tuple<int, int32_t, int>> written;
    twice = 0;
    for (const AssignmentStep& s : p.steps) {
        REQUIRE(s.before == kNone);
        const int slot = s.table == MeshTable::Edge ? field_slot(s.field) : 0;
        REQUIRE(slot >= 0);
        if (!written.insert({static_cast<int>(s.table), s.row, slot}).second) ++twice;
        if (s.table == MeshTable::Vertex) t.vertex.at(s.row) = s.after;
        else if (s.table == MeshTable::Face) t.face.at(s.row) = s.after;
        else t.edge.at(s.row)[slot] = s.after;
    }
    return t;
}

void check_playback(const WingedEdgeMesh& in, Scheme scheme) {
    const WingedEdgeMesh out = subdivide(in, scheme, 1);
    const ReconnectionPlayback p = reconnection_playback(in, scheme, out);
    REQUIRE(p.steps.size() == p.source.size());
    REQUIRE(p.lines.size() == 6);
    int twice = 0;
    const Tables t = play(p, out, twice);
    CHECK(twice == 0);
    for (int32_t v = 0; v < out.vertex_count(); ++v) CHECK(t.vertex[v] == out.vertex_edge(v));
    for (int32_t g = 0; g < out.face_count(); ++g) CHECK(t.face[g] == out.face_edge(g));
    for (int32_t e = 0; e < out.edge_count(); ++e) CHECK(t.edge[e] == row_of(out.edge(e)));

    // Locality, from the face sets: the points that belong to old face f.
    const int32_t V = in.vertex_count(), E = in.edge_count();
    const IndexedMesh fin = in.face_set(), fout = out.face_set();
    std::map<std::pair<int32_t, int32_t>, int32_t> edge_of;
    for (int32_t e = 0; e < E; ++e) edge_of[{std::min(in.edge(e).start, in.edge(e).end), std::max(in.edge(e).start, in.edge(e).end)}] = e;
    const auto points_of = [&](int32_t f) {
        std::set<int32_t> pts;
        const int32_t a = fin.face_offsets[f], b = fin.face_offsets[f + 1];
        for (int32_t k = a; k < b; ++k) {
            const int32_t c = fin.face_vertices[k], d = fin.face_vertices[k + 1 < b ? k + 1 : a];
            pts.insert(c);
            pts.insert(V + edge_of.at({std::min(c, d), std::max(c, d)}));
        }
        if (scheme == Scheme::CatmullClark) pts.insert(V + E + f);
        return pts;
    };
    const auto face_inside = [&](int32_t g, const std::set<int32_t>& pts) {
        for (int32_t k = fout.face_offsets[g]; k < fout.face_offsets[g + 1]; ++k)
            if (!pts.count(fout.face_vertices[k])) return false;
        return true;
    };
    for (std::size_t i = 0; i < p.steps.size(); ++i) {
        const AssignmentStep& s = p.steps[i];
        if (s.phase < 1 || s.phase > 3) continue;
        const std::set<int32_t> pts = points_of(p.source[i]);
        INFO("step " << i << " of old face " << p.source[i] << ": " << s.field << " of row " << s.row);
        if (s.table == MeshTable::Face) CHECK(face_inside(s.row, pts));
        if (s.table == MeshTable::Edge) {
            CHECK(pts.count(out.edge(s.row).start) == 1);
            CHECK(pts.count(out.edge(s.row).end) == 1);
            if (s.field == "left" || s.field == "right") CHECK(face_inside(s.after, pts));
        }
    }
    // Line 0 and 4 belong to old edges: the row is one of that edge's halves.
    for (std::size_t i = 0; i < p.steps.size(); ++i) {
        const AssignmentStep& s = p.steps[i];
        if (s.phase == 0 || s.phase == 4) CHECK((s.row == 2 * p.source[i] || s.row == 2 * p.source[i] + 1));
        if (s.phase == 5) CHECK(p.source[i] == kNone);
    }
}

std::map<int32_t, int> per_line(const ReconnectionPlayback& p) {
    std::map<int32_t, int> n;
    for (const AssignmentStep& s : p.steps) ++n[s.phase];
    return n;
}

} // namespace

TEST_CASE("Reconnection playback: the tetrahedron under Loop, counted by hand", "[subdivision][reconnection]") {
    const WingedEdgeMesh in = WingedEdgeMesh::build(tetrahedron());
    const WingedEdgeMesh out = subdivide(in, Scheme::Loop, 1);
    const ReconnectionPlayback p = reconnection_playback(in, Scheme::Loop, out);
    // Closed: every entry of V' = 10, F' = 16, E' = 24 rows of 8 is written once: 218.
    CHECK(p.steps.size() == 10 + 16 + 24 * 8);
    // Line 0: 6 edges x 2 halves x (S, E) = 24. Line 1: 4 faces x 4 new faces = 16.
    // Line 2: 4 faces x 3 inner edges x 8 = 96. Line 3: 12 halves x 2 sides x 3 = 72.
    // Line 4: no boundary. Line 5: 10 vertices.
    const auto n = per_line(p);
    CHECK(n.at(0) == 24);
    CHECK(n.at(1) == 16);
    CHECK(n.at(2) == 96);
    CHECK(n.at(3) == 72);
    CHECK(n.count(4) == 0);
    CHECK(n.at(5) == 10);
    check_playback(in, Scheme::Loop);
}

TEST_CASE("Reconnection playback: the cube under Catmull-Clark, counted by hand", "[subdivision][reconnection]") {
    const WingedEdgeMesh in = WingedEdgeMesh::build(cube());
    const WingedEdgeMesh out = subdivide(in, Scheme::CatmullClark, 1);
    const ReconnectionPlayback p = reconnection_playback(in, Scheme::CatmullClark, out);
    // V' = 8 + 12 + 6 = 26, F' = 24 quads, E' = 2 x 12 + 24 = 48: 26 + 24 + 48 x 8 = 434.
    CHECK(p.steps.size() == 26 + 24 + 48 * 8);
    const auto n = per_line(p);
    CHECK(n.at(0) == 12 * 2 * 2);
    CHECK(n.at(1) == 24);
    CHECK(n.at(2) == 24 * 8);
    CHECK(n.at(3) == 24 * 2 * 3);
    CHECK(n.at(5) == 26);
    check_playback(in, Scheme::CatmullClark);
}

TEST_CASE("Reconnection playback: the lecture's example has a boundary, walked as a face", "[subdivision][reconnection]") {
    const NamedMesh lecture = lecture_example();
    const WingedEdgeMesh in = WingedEdgeMesh::build(lecture.mesh, lecture.options);
    const WingedEdgeMesh out = subdivide(in, Scheme::Loop, 1);
    const ReconnectionPlayback p = reconnection_playback(in, Scheme::Loop, out);
    // 5 of the 7 edges are on the boundary (all but v2v3 and v2v4, each between two faces): each of
    // their 2 halves gets 2 wings on its open side in line 4: 5 x 2 x 2 = 20.
    const auto n = per_line(p);
    CHECK(n.at(4) == 20);
    check_playback(in, Scheme::Loop);
    check_playback(in, Scheme::CatmullClark);
}

TEST_CASE("Reconnection playback: random meshes, both schemes", "[subdivision][reconnection]") {
    std::mt19937 rng(20261128);
    std::uniform_int_distribution<int> pick(0, 3);
    for (int i = 0; i < 200; ++i) {
        const int kind = pick(rng);
        WingedEdgeMesh m = WingedEdgeMesh::build(kind == 0 ? uv_sphere(5 + pick(rng), 4 + pick(rng))
                                                 : kind == 1 ? grid(2 + pick(rng), 2 + pick(rng))
                                                 : kind == 2 ? open_fan(3 + pick(rng))
                                                             : tetrahedron());
        const bool triangles = pick(rng) < 2; // else joins make polygons of every size
        for (int k = 0; k < 8; ++k) {
            const int32_t e = std::uniform_int_distribution<int32_t>(0, m.edge_count() - 1)(rng);
            if (m.is_deleted(Edge(e))) continue;
            const Operation flip = operation("flip-edge", Edge(e));
            const Operation join = operation("join-faces", Edge(e));
            if (pick(rng) < 2 && m.check(flip).ok) m.apply(flip);
            else if (!triangles && m.check(join).ok) m.apply(join);
        }
        m.compact();
        INFO("mesh " << i);
        if (triangles) check_playback(m, Scheme::Loop);
        check_playback(m, Scheme::CatmullClark);
    }
}
