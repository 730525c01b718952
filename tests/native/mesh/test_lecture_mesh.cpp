// The mesh core against lecture 000's tables, analytic counts and invariants.
#include <catch2/catch.hpp>

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/mesh_io.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/winged_edge.h"

#include <cmath>
#include <string>

using namespace wingspline::mesh;

namespace {
constexpr double kCoordinateTolerance = 1e-12; // metres-free units of the positions

int32_t label(const std::string& s) { return s == "-" ? kNone : std::stoi(s.substr(1)) - 1; }

WingedEdgeMesh build_valid(const IndexedMesh& m, const BuildOptions& o = {}) {
    WingedEdgeMesh w = WingedEdgeMesh::build(m, o);
    const ValidationReport r = w.validate();
    INFO((r.first_error() ? r.first_error()->message : std::string()));
    REQUIRE(r.ok());
    return w;
}

std::string first_code(const IndexedMesh& m) {
    try {
        WingedEdgeMesh::build(m);
    } catch (const InvalidMesh& e) {
        return e.code();
    }
    return "accepted";
}
} // namespace

TEST_CASE("the lecture example reproduces the slide's edge, vertex and face tables", "[mesh][winged]") {
    // Lecture 000, written literally: e  S  E  L  R  SL SR EL ER
    const char* slide[7][9] = {
        {"e1", "v1", "v3", "-", "F1", "e2", "e2", "e4", "e3"}, {"e2", "v1", "v2", "F1", "-", "e1", "e1", "e3", "e6"},
        {"e3", "v2", "v3", "F1", "F2", "e2", "e5", "e1", "e4"}, {"e4", "v3", "v4", "-", "F2", "e1", "e3", "e7", "e5"},
        {"e5", "v2", "v4", "F2", "F3", "e3", "e6", "e4", "e7"}, {"e6", "v2", "v5", "F3", "-", "e5", "e2", "e7", "e7"},
        {"e7", "v4", "v5", "-", "F3", "e4", "e5", "e6", "e6"}};
    const NamedMesh ex = lecture_example();
    const WingedEdgeMesh w = build_valid(ex.mesh, ex.options);
    REQUIRE(w.edge_count() == 7);
    for (int e = 0; e < 7; ++e) {
        const EdgeRecord& r = w.edge(e);
        INFO(slide[e][0]);
        CHECK(r.start == label(slide[e][1]));
        CHECK(r.end == label(slide[e][2]));
        CHECK(r.left == label(slide[e][3]));
        CHECK(r.right == label(slide[e][4]));
        CHECK(r.start_left == label(slide[e][5]));
        CHECK(r.start_right == label(slide[e][6]));
        CHECK(r.end_left == label(slide[e][7]));
        CHECK(r.end_right == label(slide[e][8]));
    }
    const char* vertex_table[5] = {"e1", "e6", "e3", "e5", "e6"};
    for (int v = 0; v < 5; ++v) CHECK(w.vertex_edge(v) == label(vertex_table[v]));
    const char* face_table[3] = {"e1", "e3", "e5"};
    for (int f = 0; f < 3; ++f) CHECK(w.face_edge(f) == label(face_table[f]));
}

TEST_CASE("the same tables come out of the wing rule without the slide's numbering", "[mesh][winged]") {
    // Default build (the core numbers the edges itself): the same seven edges as the slide's
    // numbered build, each with the same faces and the same wings once the edges are matched by
    // their end points. The match is made here from the vertex pairs, independently of the core.
    const NamedMesh ex = lecture_example();
    const WingedEdgeMesh slide = build_valid(ex.mesh, ex.options);
    const WingedEdgeMesh w = build_valid(ex.mesh);
    REQUIRE(w.edge_count() == 7);
    CHECK(w.counts().boundary_edges == 5);
    // to_slide[e]: the slide's number of the default build's edge e (same start and end, or
    // reversed: then left/right and the wing pairs swap).
    std::vector<int32_t> to_slide(7, kNone);
    std::vector<bool> reversed(7, false);
    for (int32_t e = 0; e < 7; ++e)
        for (int32_t s = 0; s < 7; ++s) {
            const EdgeRecord &a = w.edge(e), &b = slide.edge(s);
            if (a.start == b.start && a.end == b.end) to_slide[e] = s;
            if (a.start == b.end && a.end == b.start) { to_slide[e] = s; reversed[e] = true; }
        }
    const auto mapped = [&](int32_t e) { return e == kNone ? kNone : to_slide[e]; };
    for (int32_t e = 0; e < 7; ++e) {
        REQUIRE(to_slide[e] != kNone);
        const EdgeRecord &a = w.edge(e), &b = slide.edge(to_slide[e]);
        if (!reversed[e]) {
            CHECK(a.left == b.left);
            CHECK(a.right == b.right);
            CHECK(mapped(a.start_left) == b.start_left);
            CHECK(mapped(a.start_right) == b.start_right);
            CHECK(mapped(a.end_left) == b.end_left);
            CHECK(mapped(a.end_right) == b.end_right);
        } else {
            // Walking the edge the other way swaps left and right, and the start's wings become the end's.
            CHECK(a.left == b.right);
            CHECK(a.right == b.left);
            CHECK(mapped(a.start_left) == b.end_right);
            CHECK(mapped(a.start_right) == b.end_left);
            CHECK(mapped(a.end_left) == b.start_right);
            CHECK(mapped(a.end_right) == b.start_left);
        }
    }
}

TEST_CASE("CCW around v2 is e6, e5, e3, e2; every ring covers its vertex's edges", "[mesh][traversal]") {
    const NamedMesh ex = lecture_example();
    const WingedEdgeMesh w = build_valid(ex.mesh, ex.options);
    CHECK(w.edges_around_vertex(1) == std::vector<int32_t>{label("e6"), label("e5"), label("e3"), label("e2")});
    // Degree of each vertex on the slide's picture: v1 2, v2 4, v3 3, v4 3, v5 2.
    const int degree[5] = {2, 4, 3, 3, 2};
    for (int v = 0; v < 5; ++v) CHECK(static_cast<int>(w.edges_around_vertex(v).size()) == degree[v]);
    // Edges of each face in CCW order, following the face's winding on the slide.
    CHECK(w.edges_of_face(0) == std::vector<int32_t>{label("e1"), label("e2"), label("e3")});
    CHECK(w.edges_of_face(1) == std::vector<int32_t>{label("e3"), label("e5"), label("e4")});
    CHECK(w.edges_of_face(2) == std::vector<int32_t>{label("e5"), label("e6"), label("e7")});
    // F2 = (v2 v4 v3) read from its face edge e3 (F2 is its Right face, so it starts at v3).
    CHECK(w.vertices_of_face(1) == std::vector<int32_t>{2, 1, 3});
    CHECK(w.faces_around_vertex(1) == std::vector<int32_t>{2, 1, 0});
}

TEST_CASE("walking every ring meets each edge once from each end", "[mesh][traversal]") {
    // Invariant: the walks visit 2E edges, and the neighbours met sum to the sum of S + E
    // over all edges (each edge is seen from its Start, giving E, and from its End, giving S).
    for (const IndexedMesh& m : {tetrahedron(), cube(), open_fan(5), grid(6, 3), uv_sphere(10, 6)}) {
        const WingedEdgeMesh w = build_valid(m);
        double ends = 0;
        for (int32_t e = 0; e < w.edge_count(); ++e) ends += w.edge(e).start + w.edge(e).end;
        const RingWalkTotals t = w.walk_every_ring();
        CHECK(t.visited == 2.0 * w.edge_count());
        CHECK(t.neighbour_sum == ends);
    }
}

TEST_CASE("the faces read back from the winged edge are the faces it was built from", "[mesh][winged]") {
    // Default face edge = the face's first side, so each face's walk starts at its first
    // corner: polygons (cube quads), a boundary (grid, fan) and a closed sphere.
    IndexedMesh mixed = grid(2, 2);
    IndexedMesh quads = cube();
    for (const IndexedMesh& m : {tetrahedron(), quads, open_fan(6), mixed, uv_sphere(8, 5)}) {
        const WingedEdgeMesh w = build_valid(m);
        const IndexedMesh back = w.face_set();
        CHECK(back.positions == m.positions);
        CHECK(back.face_offsets == m.face_offsets);
        CHECK(back.face_vertices == m.face_vertices);
        for (int32_t f = 0; f < w.face_count(); ++f) {
            const EdgeRecord& r = w.edge(w.face_edge(f));
            const int32_t s = r.left == f ? r.start : r.end, t = r.left == f ? r.end : r.start;
            CHECK(s == m.corner(f, 0));
            CHECK(t == m.corner(f, 1));
        }
    }
}

TEST_CASE("building from a face set it may take gives the same tables and keeps a refused one", "[mesh][winged]") {
    const IndexedMesh source = grid(5, 4);
    const WingedEdgeMesh copied = build_valid(source);
    IndexedMesh taken = source;
    const WingedEdgeMesh moved = WingedEdgeMesh::build(std::move(taken));
    REQUIRE(moved.validate().ok());
    REQUIRE(moved.edge_count() == copied.edge_count());
    for (int32_t e = 0; e < copied.edge_count(); ++e) {
        const EdgeRecord &a = copied.edge(e), &b = moved.edge(e);
        CHECK(std::vector<int32_t>{a.start, a.end, a.left, a.right, a.start_left, a.start_right, a.end_left, a.end_right} ==
              std::vector<int32_t>{b.start, b.end, b.left, b.right, b.start_left, b.start_right, b.end_left, b.end_right});
    }
    CHECK(moved.positions() == source.positions);
    // Refused (an edge shared by three faces): the caller's positions are still there.
    IndexedMesh fin;
    for (int i = 0; i < 5; ++i) fin.add_vertex(i, i * i, 0);
    fin.add_face({0, 1, 2});
    fin.add_face({1, 0, 3});
    fin.add_face({0, 1, 4});
    const std::vector<double> before = fin.positions;
    CHECK_THROWS_AS(WingedEdgeMesh::build(std::move(fin)), InvalidMesh);
    CHECK(fin.positions == before); // NOLINT(bugprone-use-after-move): the contract under test
    // Refused late: two closed tetrahedra sharing one vertex (found only by the ring walk),
    // and a face edge that is not a side of its face (the last check before the move).
    IndexedMesh cones;
    for (int i = 0; i < 7; ++i) cones.add_vertex(i, i % 3, i * 0.5);
    for (const int32_t o : {0, 3}) { // apex 0 shared; tetrahedra (0, 1, 2, 3) and (0, 4, 5, 6)
        const int32_t a = o == 0 ? 1 : 4, b = a + 1, c = a + 2;
        cones.add_face({0, a, b});
        cones.add_face({0, b, c});
        cones.add_face({0, c, a});
        cones.add_face({a, c, b});
    }
    const std::vector<double> cones_before = cones.positions;
    CHECK_THROWS_AS(WingedEdgeMesh::build(std::move(cones)), InvalidMesh);
    CHECK(cones.positions == cones_before); // NOLINT(bugprone-use-after-move)
    IndexedMesh tet = tetrahedron();
    BuildOptions wrong_face_edge;
    wrong_face_edge.face_edges = {0, 0, 0, 0}; // e1 is not a side of every face
    const std::vector<double> tet_before = tet.positions;
    CHECK_THROWS_WITH(WingedEdgeMesh::build(std::move(tet), wrong_face_edge), Catch::Contains("is not a side of"));
    CHECK(tet.positions == tet_before); // NOLINT(bugprone-use-after-move)
}

TEST_CASE("Euler characteristic and analytic counts of generated meshes", "[mesh][counts]") {
    SECTION("closed meshes: V - E + F = 2, no boundary") {
        for (const IndexedMesh& m : {tetrahedron(), cube(), uv_sphere(12, 7)}) {
            const MeshCounts c = build_valid(m).counts();
            CHECK(c.euler() == 2);
            CHECK(c.boundary_loops == 0);
        }
    }
    SECTION("sphere slices x stacks: V = s(t-1)+2, F = 2s(t-1), E = 3F/2") {
        const int s = 9, t = 5;
        const MeshCounts c = build_valid(uv_sphere(s, t)).counts();
        CHECK(c.vertices == s * (t - 1) + 2);
        CHECK(c.faces == 2 * s * (t - 1));
        CHECK(c.edges == 3 * s * (t - 1));
    }
    SECTION("grid nx x ny: V = (nx+1)(ny+1), F = 2 nx ny, E = nx(ny+1) + ny(nx+1) + nx ny, one loop") {
        const int nx = 7, ny = 4;
        const MeshCounts c = build_valid(grid(nx, ny)).counts();
        CHECK(c.vertices == (nx + 1) * (ny + 1));
        CHECK(c.faces == 2 * nx * ny);
        CHECK(c.edges == nx * (ny + 1) + ny * (nx + 1) + nx * ny);
        CHECK(c.boundary_loops == 1);
        CHECK(c.boundary_edges == 2 * (nx + ny));
        CHECK(c.euler() == 1);
    }
    SECTION("open fan of n triangles: one loop, n + 2 boundary edges") {
        const MeshCounts c = build_valid(open_fan(5)).counts();
        CHECK(c.faces == 5);
        CHECK(c.boundary_loops == 1);
        CHECK(c.boundary_edges == 5 + 2);
    }
    SECTION("storage equals the analytic entry count: 8 ints per edge, 4 per vertex table row") {
        const WingedEdgeMesh w = build_valid(cube());
        CHECK(w.bytes() == 8 * (3 * 8 + 4) + 12 * 32 + 6 * 4);
    }
}

TEST_CASE("Foley's edge list: P1 = (E1, E4, E5), P2 = (E2, E3, E4)", "[mesh][foley]") {
    const NamedMesh ex = foley_example();
    const WingedEdgeMesh w = build_valid(ex.mesh, ex.options);
    CHECK(w.edges_of_face(0) == std::vector<int32_t>{0, 3, 4});
    CHECK(w.edges_of_face(1) == std::vector<int32_t>{1, 2, 3});
    // E4 = (V4, V2, P1, P2): both polygons share it.
    CHECK(w.edge(3).start == 3);
    CHECK(w.edge(3).end == 1);
    CHECK(std::min(w.edge(3).left, w.edge(3).right) == 0);
    CHECK(std::max(w.edge(3).left, w.edge(3).right) == 1);
}

TEST_CASE("every validation code on a named tiny fixture", "[mesh][validation]") {
    IndexedMesh quad_pair; // two triangles sharing v1-v3:  v4---v3
    quad_pair.add_vertex(0, 0, 0); //                           | F2 / |
    quad_pair.add_vertex(1, 0, 0); //                           |  / F1|
    quad_pair.add_vertex(1, 1, 0); //                           v1---v2
    quad_pair.add_vertex(0, 1, 0);
    auto with = [&](std::initializer_list<std::initializer_list<int32_t>> faces) {
        IndexedMesh m = quad_pair;
        m.face_offsets = {0};
        m.face_vertices.clear();
        for (auto f : faces) m.add_face(f);
        return m;
    };
    CHECK(first_code(with({{0, 1, 2}, {0, 2, 3}})) == "accepted");
    CHECK(first_code(with({})) == "empty-mesh");
    CHECK(first_code(with({{0, 1, 9}})) == "index-out-of-range");
    CHECK(first_code(with({{0, 1, 1}})) == "repeated-vertex");
    CHECK(first_code(with({{0, 1}})) == "too-few-vertices");
    // F1 = (v1 v2 v3) and F2 = (v3 v1 v4) both run v3 -> v1: inconsistent orientation.
    const ValidationReport flipped = validate_indexed(with({{0, 1, 2}, {2, 0, 3}}));
    REQUIRE(flipped.has("inconsistent-orientation"));
    CHECK(flipped.problems.front().faces == std::vector<int32_t>{0, 1});
    CHECK(validate_indexed(with({{0, 1, 2}, {1, 2, 0}})).has("duplicate-face"));
    // Three triangles on edge v1-v3: non-manifold edge.
    IndexedMesh fin = with({{0, 1, 2}, {0, 2, 3}});
    const int32_t apex = fin.add_vertex(0.5, 0.5, 1);
    fin.add_face({2, 0, apex});
    const ValidationReport r = validate_indexed(fin);
    REQUIRE(r.has("non-manifold-edge"));
    CHECK(r.problems.front().message.find("edge v1-v3 is shared by 3 faces") != std::string::npos);
    CHECK(first_code(fin) == "non-manifold-edge");
    // Bow-tie: two triangles touching only at v1.   v3  v2
    IndexedMesh bow;                              //  \ F1|
    bow.add_vertex(0, 0, 0);                      //   v1
    bow.add_vertex(1, 1, 0);                      //  |F2 \.
    bow.add_vertex(-1, 1, 0);                     // v4  v5
    bow.add_vertex(-1, -1, 0);
    bow.add_vertex(1, -1, 0);
    bow.add_face({0, 1, 2});
    bow.add_face({0, 3, 4});
    CHECK(first_code(bow) == "non-manifold-vertex");
    // A pillow: the same triangle twice, opposite orientations.
    CHECK(first_code(with({{0, 1, 2}, {0, 2, 1}})) == "duplicate-face");
    IndexedMesh nan_mesh = with({{0, 1, 2}});
    nan_mesh.positions[4] = std::nan("");
    CHECK(first_code(nan_mesh) == "non-finite-coordinate");
    // Found by fuzz_mesh_build: finite but huge coordinates made Newell's sums overflow.
    IndexedMesh huge = with({{0, 1, 2}});
    huge.positions[3] = 1e200;
    CHECK(first_code(huge) == "coordinate-out-of-range");
    // Isolated v4 is a warning: the mesh builds, v4 has no edge.
    const WingedEdgeMesh w = WingedEdgeMesh::build(with({{0, 1, 2}}));
    CHECK(w.vertex_edge(3) == kNone);
    CHECK(w.validate().ok());
    CHECK(w.validate().has("isolated-vertex"));
}

TEST_CASE("Newell equals the cross product on planar faces and gives the analytic normal", "[mesh][planes]") {
    const WingedEdgeMesh w = build_valid(cube());
    const auto planes = face_planes(w);
    // Cube face z = 0 has outward normal (0, 0, -1) and area 1.
    CHECK(planes[0].newell.z == Approx(-1.0));
    for (const FacePlane& p : planes) {
        CHECK(p.residual == Approx(0).margin(kCoordinateTolerance));
        const double nc = std::sqrt(p.cross.x * p.cross.x + p.cross.y * p.cross.y + p.cross.z * p.cross.z);
        const double nn = std::sqrt(p.newell.x * p.newell.x + p.newell.y * p.newell.y + p.newell.z * p.newell.z);
        CHECK(p.cross.x / nc == Approx(p.newell.x / nn).margin(kCoordinateTolerance));
        CHECK(p.cross.y / nc == Approx(p.newell.y / nn).margin(kCoordinateTolerance));
        CHECK(p.cross.z / nc == Approx(p.newell.z / nn).margin(kCoordinateTolerance));
        CHECK(nn == Approx(1.0)); // Newell with the 1/2 factor = area of the unit square
    }
    // A skew quad: lift one corner by h; the residual is h/4 of the mean plane... bounded by h.
    IndexedMesh skew;
    skew.add_vertex(0, 0, 0);
    skew.add_vertex(1, 0, 0);
    skew.add_vertex(1, 1, 0.2);
    skew.add_vertex(0, 1, 0);
    skew.add_face({0, 1, 2, 3});
    const auto sp = face_planes(build_valid(skew));
    CHECK(sp[0].residual > 0.01);
    CHECK(sp[0].residual < 0.2);
    // newell_normals (one walk per face) equals face_planes' Newell vector, normalised, on
    // every face of a sphere, a grid with a boundary and the cube's quads.
    for (const IndexedMesh& m : {uv_sphere(9, 5), grid(4, 3), cube()}) {
        const WingedEdgeMesh mesh = build_valid(m);
        std::vector<double> unit;
        newell_normals(mesh, unit);
        const auto reference = face_planes(mesh);
        REQUIRE(unit.size() == 3 * reference.size());
        for (std::size_t f = 0; f < reference.size(); ++f) {
            const glm::dvec4& q = reference[f].newell;
            const double len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
            CHECK(unit[3 * f] == Approx(q.x / len).margin(kCoordinateTolerance));
            CHECK(unit[3 * f + 1] == Approx(q.y / len).margin(kCoordinateTolerance));
            CHECK(unit[3 * f + 2] == Approx(q.z / len).margin(kCoordinateTolerance));
        }
    }
    std::vector<double> n;
    newell_normals(build_valid(tetrahedron()), n);
    // Outward: the tetrahedron is centred at the origin, so normal . vertex > 0.
    CHECK(n[0] + n[1] - n[2] > 0); // face (0,1,2) normal ~ (1,1,-1)/sqrt3
}

TEST_CASE("OFF and OBJ readers: forms, comments, negative indices, line-numbered errors", "[mesh][io]") {
    const IndexedMesh off = parse_off("# a comment\nOFF\n3 1 0\n0 0 0\n1 0 0 # trailing\n0 1 0\n3 0 1 2\n");
    CHECK(off.vertex_count() == 3);
    CHECK(off.face_vertices == std::vector<int32_t>{0, 1, 2});
    const IndexedMesh obj = parse_obj("v 0 0 0\nv 1 0 0\nvt 0 0\nvn 0 0 1\nv 0 1 0\nf 1/1/1 2//1 -1\n");
    CHECK(obj.face_vertices == std::vector<int32_t>{0, 1, 2});
    try {
        parse_off("OFF\n3 1 0\n0 0 0\n1 zero 0\n");
        FAIL("accepted a bad number");
    } catch (const ParseError& e) {
        CHECK(e.code() == "parse-error");
        CHECK(e.line() == 4);
    }
    try {
        parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n");
        FAIL("accepted a truncated file");
    } catch (const ParseError& e) {
        CHECK(e.code() == "truncated-file");
    }
    try {
        parse_obj("v 0 0 0\nf 1 2 3\n");
        FAIL("accepted a dangling reference");
    } catch (const ParseError& e) {
        CHECK(e.code() == "index-out-of-range");
        CHECK(e.line() == 2);
    }
    // Faces and vertices are named as in every other message (F1, v1), with the file's
    // own 0-based index where the file uses it.
    try {
        parse_off("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 0\n3 0 1 2\n3 1 3 2\n3 1 7 3\n");
        FAIL("accepted an index past the vertices");
    } catch (const ParseError& e) {
        CHECK(e.code() == "index-out-of-range");
        CHECK(e.line() == 10);
        CHECK(std::string(e.what()) == "line 10: F3 refers to vertex 7, that is v8 (an OFF file counts its vertices from 0), but the file has vertices v1 to v5");
    }
    try {
        parse_off("OFF\n0 1 0\n3 0 1 2\n");
        FAIL("accepted a face without vertices");
    } catch (const ParseError& e) {
        CHECK(std::string(e.what()) == "line 3: F1 refers to vertex 0, that is v1 (an OFF file counts its vertices from 0), but the file has no vertices");
    }
    try {
        parse_off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        FAIL("accepted a missing face");
    } catch (const ParseError& e) {
        CHECK(e.code() == "truncated-file");
        CHECK(e.line() == 7);
        CHECK(std::string(e.what()) == "line 7: the file ends after 1 of 2 faces; expected F2");
    }
    try {
        parse_off("OFF\n3 1 0\n0 0 0\n1 0\n");
        FAIL("accepted a short vertex line");
    } catch (const ParseError& e) {
        CHECK(std::string(e.what()) == "line 4: expected x y z of v2 (called 1 in the face lines), found 2 number(s)");
    }
    // Numbers are read from the token only (a view into the text): a number glued to a
    // comment, a NUL inside a number, and an integer too large for 32 bits.
    CHECK(parse_off("OFF\n3 1 0\n0 0 0#c\n1 0 0\n0 1 0\n3 0 1 2\n").vertex_count() == 3);
    try {
        const std::string with_nul("OFF\n3 1 0\n0 0 0\n1 0\0 0\n0 1 0\n3 0 1 2\n", 37);
        parse_off(with_nul);
        FAIL("accepted a NUL inside a number");
    } catch (const ParseError& e) {
        CHECK(e.code() == "parse-error");
        CHECK(e.line() == 4);
    }
    CHECK_THROWS_AS(parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999\n"), ParseError);
    // Round trip bit for bit.
    const IndexedMesh s = uv_sphere(7, 4);
    CHECK(parse_off(format_off(s)).positions == s.positions);
    CHECK(parse_obj(format_obj(s)).face_vertices == s.face_vertices);
}
