// Trust, for meshes: neighbours are a set in every representation, the cross product
// plane uses the face's own first three corners, BOM and CRLF files read, and one set of
// mesh limits enforced where values enter.
#include <catch2/catch.hpp>

#include "mesh/unrecorded.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/mesh_io.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>

using namespace wingspline::mesh;

namespace {

std::vector<int32_t> sorted(std::vector<int32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

bool has_repeats(const std::vector<int32_t>& v) {
    return std::set<int32_t>(v.begin(), v.end()).size() != v.size();
}

// Two quads sharing two edges (v2-v3 and v3-v4): v3 is an interior vertex of degree 2.
IndexedMesh two_faces_sharing_two_edges() {
    IndexedMesh m;
    m.add_vertex(0, 0, 0);
    m.add_vertex(2, 0, 0);
    m.add_vertex(1, 1, 0);
    m.add_vertex(0, 2, 0);
    m.add_vertex(3, 3, 0);
    m.add_face({0, 1, 2, 3});
    m.add_face({3, 2, 1, 4});
    return m;
}

// The answer of each query computed from the indexed face set alone (no representation):
// the oracle every representation must agree with, as a set.
struct Oracle {
    const IndexedMesh& m;
    const WingedEdgeMesh& w;
    std::map<std::pair<int32_t, int32_t>, int32_t> edge_of; // undirected end points -> edge number

    Oracle(const IndexedMesh& mesh, const WingedEdgeMesh& winged) : m(mesh), w(winged) {
        for (int32_t e = 0; e < w.edge_count(); ++e)
            edge_of[std::minmax(w.edge(e).start, w.edge(e).end)] = e;
    }
    std::vector<std::pair<int32_t, int32_t>> sides(int32_t f) const {
        std::vector<std::pair<int32_t, int32_t>> out;
        for (int32_t i = 0; i < m.face_size(f); ++i)
            out.push_back(std::minmax(m.corner(f, i), m.corner(f, (i + 1) % m.face_size(f))));
        return out;
    }
    std::vector<int32_t> answer(QueryKind kind, int32_t x) const {
        std::set<int32_t> out;
        switch (kind) {
        case QueryKind::FacesAroundVertex:
            for (int32_t f = 0; f < m.face_count(); ++f)
                for (int32_t i = 0; i < m.face_size(f); ++i)
                    if (m.corner(f, i) == x) out.insert(f);
            break;
        case QueryKind::EdgesAroundVertex:
            for (const auto& [ends, e] : edge_of)
                if (ends.first == x || ends.second == x) out.insert(e);
            break;
        case QueryKind::EdgesOfFace:
            for (const auto& s : sides(x)) out.insert(edge_of.at(s));
            break;
        case QueryKind::FacesOfEdge:
            for (int32_t f = 0; f < m.face_count(); ++f)
                for (const auto& s : sides(f))
                    if (edge_of.at(s) == x) out.insert(f);
            break;
        case QueryKind::NeighboursOfFace: {
            const auto mine = sides(x);
            for (int32_t g = 0; g < m.face_count(); ++g)
                if (g != x)
                    for (const auto& s : sides(g))
                        if (std::find(mine.begin(), mine.end(), s) != mine.end()) out.insert(g);
            break;
        }
        }
        return {out.begin(), out.end()};
    }
};

const QueryKind kKinds[] = {QueryKind::FacesAroundVertex, QueryKind::EdgesAroundVertex, QueryKind::EdgesOfFace,
                            QueryKind::FacesOfEdge, QueryKind::NeighboursOfFace};

// Every query on every element: each representation's answer has no repeats and is, as a
// set, the oracle's. Returns how many answers were compared.
int check_every_query(const IndexedMesh& m) {
    const WingedEdgeMesh w = WingedEdgeMesh::build(m);
    const Representations reps = build_representations(m, w);
    const Oracle oracle(m, w);
    int compared = 0;
    for (QueryKind kind : kKinds) {
        const int32_t n = kind == QueryKind::FacesAroundVertex || kind == QueryKind::EdgesAroundVertex ? w.vertex_count()
                          : kind == QueryKind::FacesOfEdge                                             ? w.edge_count()
                                                                                                       : w.face_count();
        for (int32_t x = 0; x < n; ++x) {
            const std::vector<int32_t> expected = oracle.answer(kind, x);
            const auto answers = answer_query(kind, x, reps, w);
            for (int r = 0; r < kRepresentationCount; ++r) {
                INFO(representation_key(static_cast<Representation>(r)) << " query " << static_cast<int>(kind) << " element " << x);
                CHECK_FALSE(has_repeats(answers[r].answer));
                CHECK(sorted(answers[r].answer) == expected);
                ++compared;
            }
        }
    }
    return compared;
}

// A random valid mesh: a grid, some interior edges split by a new vertex (the two faces
// then share two edges), some neighbouring faces merged into one polygon (which may then
// wrap around a neighbour). Every step that would make the mesh invalid is undone.
IndexedMesh random_mesh(std::mt19937& rng) {
    std::uniform_int_distribution<int> size(1, 4);
    const IndexedMesh g = grid(size(rng), size(rng));
    std::vector<std::vector<int32_t>> faces;
    for (int32_t f = 0; f < g.face_count(); ++f) {
        faces.emplace_back();
        for (int32_t i = 0; i < g.face_size(f); ++i) faces.back().push_back(g.corner(f, i));
    }
    std::vector<double> positions = g.positions;
    auto assemble = [&](const std::vector<std::vector<int32_t>>& fs) {
        IndexedMesh m;
        m.positions = positions;
        for (const auto& f : fs) m.add_face(f.data(), static_cast<int32_t>(f.size()));
        return m;
    };
    // Finds face h != f holding the directed side b -> a; returns its index or -1.
    auto across = [&](int32_t f, int32_t a, int32_t b) {
        for (int32_t h = 0; h < static_cast<int32_t>(faces.size()); ++h) {
            if (h == f) continue;
            const auto& c = faces[h];
            for (std::size_t i = 0; i < c.size(); ++i)
                if (c[i] == b && c[(i + 1) % c.size()] == a) return h;
        }
        return -1;
    };
    std::uniform_int_distribution<int> steps(0, 6);
    const int splits = steps(rng), merges = steps(rng);
    for (int s = 0; s < splits; ++s) {
        const int32_t f = std::uniform_int_distribution<int32_t>(0, static_cast<int32_t>(faces.size()) - 1)(rng);
        const std::size_t i = std::uniform_int_distribution<std::size_t>(0, faces[f].size() - 1)(rng);
        const int32_t a = faces[f][i], b = faces[f][(i + 1) % faces[f].size()];
        const int32_t h = across(f, a, b);
        if (h < 0) continue;
        const int32_t mid = static_cast<int32_t>(positions.size() / 3);
        for (int k = 0; k < 3; ++k) positions.push_back(0.5 * (positions[3 * a + k] + positions[3 * b + k]));
        faces[f].insert(faces[f].begin() + static_cast<std::ptrdiff_t>(i) + 1, mid);
        auto& c = faces[h];
        for (std::size_t j = 0; j < c.size(); ++j)
            if (c[j] == b && c[(j + 1) % c.size()] == a) {
                c.insert(c.begin() + static_cast<std::ptrdiff_t>(j) + 1, mid);
                break;
            }
    }
    for (int s = 0; s < merges && faces.size() > 1; ++s) {
        const int32_t f = std::uniform_int_distribution<int32_t>(0, static_cast<int32_t>(faces.size()) - 1)(rng);
        const std::size_t i = std::uniform_int_distribution<std::size_t>(0, faces[f].size() - 1)(rng);
        const int32_t a = faces[f][i], b = faces[f][(i + 1) % faces[f].size()];
        const int32_t h = across(f, a, b);
        if (h < 0) continue;
        // f = a b p..., h = b a q...: without the side a-b the loop is b p... a q...
        std::vector<int32_t> merged;
        const auto& cf = faces[f];
        for (std::size_t k = 1; k <= cf.size(); ++k) merged.push_back(cf[(i + k) % cf.size()]); // b p... a
        const auto& ch = faces[h];
        std::size_t j = 0;
        while (!(ch[j] == b && ch[(j + 1) % ch.size()] == a)) ++j;
        for (std::size_t k = 2; k < ch.size(); ++k) merged.push_back(ch[(j + k) % ch.size()]); // q...
        auto next = faces;
        next[f] = merged;
        next.erase(next.begin() + h);
        if (validate_indexed(assemble(next)).ok()) faces = std::move(next);
    }
    return assemble(faces);
}

} // namespace

TEST_CASE("neighbours-of-face is the set of distinct faces in every representation (two faces sharing two edges)",
          "[mesh][queries][trust]") {
    const IndexedMesh m = two_faces_sharing_two_edges();
    const WingedEdgeMesh w = WingedEdgeMesh::build(m);
    REQUIRE(w.validate().ok());
    const Representations reps = build_representations(m, w);
    for (int32_t f = 0; f < 2; ++f) {
        const auto answers = answer_query(QueryKind::NeighboursOfFace, f, reps, w);
        for (int r = 0; r < kRepresentationCount; ++r) {
            INFO(representation_key(static_cast<Representation>(r)) << " F" << f + 1);
            CHECK(answers[r].answer == std::vector<int32_t>{1 - f});
        }
        CHECK(w.face_neighbours(f) == std::vector<int32_t>{1 - f});
    }
    check_every_query(m);
}

TEST_CASE("property: on random meshes every representation answers every query with the oracle's set",
          "[mesh][queries][trust][property]") {
    std::mt19937 rng(20240613);
    int meshes = 0, with_double_neighbours = 0, compared = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        const IndexedMesh m = random_mesh(rng);
        REQUIRE(validate_indexed(m).ok());
        ++meshes;
        // Count meshes where some pair of faces shares two or more edges (where a list of
        // neighbours would name a face twice).
        const WingedEdgeMesh w = WingedEdgeMesh::build(m);
        bool doubled = false;
        for (int32_t f = 0; f < w.face_count() && !doubled; ++f) {
            std::map<int32_t, int> across;
            for (int32_t e : w.edges_of_face(f)) {
                const int32_t g = w.edge(e).left == f ? w.edge(e).right : w.edge(e).left;
                if (g != kNone && ++across[g] > 1) doubled = true;
            }
        }
        with_double_neighbours += doubled;
        compared += check_every_query(m);
    }
    INFO(meshes << " meshes, " << with_double_neighbours << " with two faces sharing two edges, " << compared << " answers");
    CHECK(with_double_neighbours > 300);
}

TEST_CASE("planes(): the cross product uses the face's own first three corners, whatever its stored edge",
          "[mesh][planes][trust]") {
    // A non-planar quad: P1 = (0,0,0), P2 = (1,0,0), P3 = (1,1,1), P4 = (0,1,0).
    IndexedMesh m;
    m.add_vertex(0, 0, 0);
    m.add_vertex(1, 0, 0);
    m.add_vertex(1, 1, 1);
    m.add_vertex(0, 1, 0);
    m.add_face({0, 1, 2, 3});
    // Lecture 001: (A, B, C) = P1P2 x P1P3 = (1,0,0) x (1,1,1) = (0, -1, 1); D = -(A,B,C).P1 = 0.
    for (int stored_side = 0; stored_side < 4; ++stored_side) {
        BuildOptions options;
        const WingedEdgeMesh probe = WingedEdgeMesh::build(m);
        // The edge along side stored_side (corner i -> i + 1) becomes the face's stored edge.
        const int32_t a = stored_side, b = (stored_side + 1) % 4;
        for (int32_t e = 0; e < probe.edge_count(); ++e)
            if (std::minmax(probe.edge(e).start, probe.edge(e).end) == std::minmax(a, b)) options.face_edges = {e};
        const WingedEdgeMesh w = WingedEdgeMesh::build(m, options);
        REQUIRE(w.face_edge(0) == options.face_edges[0]);
        const auto planes = face_planes(w, m.face_offsets, m.face_vertices);
        INFO("stored side " << stored_side);
        CHECK(planes[0].cross == glm::dvec4(0, -1, 1, 0));
        CHECK(planes[0].cross_corners == std::array<int32_t, 3>{0, 1, 2});
    }
}

TEST_CASE("a UTF-8 byte-order mark and CRLF line ends are read as editors write them", "[mesh][io][trust]") {
    const std::string off = "\xEF\xBB\xBFOFF\r\n# a comment\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    const IndexedMesh a = parse_off(off);
    CHECK(a.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    CHECK(a.face_vertices == std::vector<int32_t>{0, 1, 2});
    const std::string obj = "\xEF\xBB\xBFv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n";
    const IndexedMesh b = parse_obj(obj);
    CHECK(b.positions == a.positions);
    CHECK(b.face_vertices == a.face_vertices);
    // Line numbers still count CRLF lines: the bad token is on line 5.
    try {
        parse_off("\xEF\xBB\xBFOFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 x 0\r\n3 0 1 2\r\n");
        FAIL("accepted a bad number");
    } catch (const ParseError& e) {
        CHECK(e.line() == 5);
        CHECK(std::string(e.what()).find("'x'") != std::string::npos);
    }
    // A BOM anywhere else is not whitespace.
    CHECK_THROWS_AS(parse_off("OFF\n\xEF\xBB\xBF" "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), ParseError);
}

TEST_CASE("one set of mesh limits: moving a vertex beyond the coordinate bound is refused and changes nothing",
          "[mesh][limits][trust]") {
    WingedEdgeMesh w = WingedEdgeMesh::build(tetrahedron());
    const std::vector<double> before = w.positions();
    for (double x : {1e300, -1e300, 2 * kMaxCoordinate, std::nan(""), HUGE_VAL}) {
        INFO("x = " << x);
        try {
            w.set_position(1, {x, 0, 0});
            FAIL("accepted");
        } catch (const wingspline::Error& e) {
            CHECK(std::string(e.code()) == (std::isnan(x) || std::isinf(x) ? "non-finite-coordinate" : "coordinate-out-of-range"));
            CHECK(std::string(e.what()).find("v2") != std::string::npos);
        }
        CHECK(w.positions() == before);
    }
    w.set_position(1, {kMaxCoordinate, -kMaxCoordinate, kMaxCoordinate}); // the bound itself is allowed
    std::vector<double> normals;
    newell_normals(w, normals);
    for (double n : normals) CHECK(std::isfinite(n));
    // Building refuses the same bound.
    IndexedMesh m = tetrahedron();
    m.positions[0] = 5e9;
    CHECK(validate_indexed(m).has("coordinate-out-of-range"));
}

TEST_CASE("file limits: corners per face, coordinates and counts are refused at import, naming the line",
          "[mesh][limits][io][trust]") {
    auto polygon_off = [](int n, double x0) {
        std::string s = "OFF\n" + std::to_string(n) + " 1 0\n";
        for (int i = 0; i < n; ++i) {
            const double t = 2 * M_PI * i / n;
            s += std::to_string(i == 0 ? x0 : std::cos(t)) + " " + std::to_string(std::sin(t)) + " 0\n";
        }
        s += std::to_string(n);
        for (int i = 0; i < n; ++i) s += " " + std::to_string(i);
        return s + "\n";
    };
    CHECK(parse_off(polygon_off(kMaxFaceCorners, 1)).face_size(0) == kMaxFaceCorners);
    try {
        parse_off(polygon_off(kMaxFaceCorners + 1, 1));
        FAIL("accepted a 1001-corner face");
    } catch (const ParseError& e) {
        CHECK(std::string(e.code()) == "face-too-large");
        CHECK(e.line() == 2 + 1001 + 1);
        CHECK(std::string(e.what()).find("1001") != std::string::npos);
        CHECK(std::string(e.what()).find("1000") != std::string::npos);
    }
    try {
        parse_off(polygon_off(3, 5e9));
        FAIL("accepted x = 5e9");
    } catch (const ParseError& e) {
        CHECK(std::string(e.code()) == "coordinate-out-of-range");
        CHECK(e.line() == 3);
    }
    try {
        parse_obj("v 0 0 0\nv 1 0 0\nv 0 -2e9 0\nf 1 2 3\n");
        FAIL("accepted y = -2e9");
    } catch (const ParseError& e) {
        CHECK(std::string(e.code()) == "coordinate-out-of-range");
        CHECK(e.line() == 3);
    }
    // An OFF header over the limits is refused from the header alone (no vertex line follows).
    try {
        parse_off("OFF\n" + std::to_string(kFileLimits.max_vertices + 1) + " 1 0\n");
        FAIL("accepted the header");
    } catch (const ParseError& e) {
        CHECK(std::string(e.code()) == "too-large");
        CHECK(e.line() == 2);
        CHECK(std::string(e.what()).find(std::to_string(kFileLimits.max_vertices + 1)) != std::string::npos);
        CHECK(std::string(e.what()).find(std::to_string(kFileLimits.max_vertices)) != std::string::npos);
    }
    CHECK_THROWS_AS(parse_off("OFF\n3 " + std::to_string(kFileLimits.max_faces + 1) + " 0\n"), ParseError);
    // OBJ: refused at the first vertex over the limit.
    std::string many;
    for (int i = 0; i <= kFileLimits.max_vertices; ++i) many += "v 0 0 0\n";
    try {
        parse_obj(many);
        FAIL("accepted one vertex more than the limit");
    } catch (const ParseError& e) {
        CHECK(std::string(e.code()) == "too-large");
        CHECK(e.line() == kFileLimits.max_vertices + 1);
    }
    // Counts can be lifted for large files (benchmarks); the other limits stay.
    CHECK(parse_obj(many, kUnlimitedCounts).vertex_count() == kFileLimits.max_vertices + 1);
}

TEST_CASE("streamed reading (TextSource) gives the same mesh and the same line numbers for every piece size",
          "[mesh][io][trust]") {
    const std::string off = "\xEF\xBB\xBFOFF\r\n# c\r\n4 2 0\r0 0 0\n1 0 0\r\n1 1 0\r\n0 1 0\r\n\r\n3 0 1 2\r\n3 0 2 3";
    const std::string obj = "\xEF\xBB\xBFv 0 0 0\r\nv 1 0 0\rv 1 1 0\r\n\r\nv 0 1 0\nf 1 2 3\r\nf 1 3 4\r\n";
    const std::string bad = "OFF\r\n4 2 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n3 0 1 2\r\n3 0 2 oops\r\n";
    const IndexedMesh a = parse_off(off), b = parse_obj(obj);
    CHECK(a.face_vertices == b.face_vertices);
    for (std::size_t piece = 1; piece <= 13; ++piece) {
        INFO("piece " << piece);
        // A source that hands out at most `piece` bytes per call, so lines, CRLFs and the
        // byte-order mark are cut at every place.
        auto source_of = [piece](const std::string& text) {
            return TextSource([&text, piece](char* out, std::size_t capacity, std::size_t offset) -> std::size_t {
                if (offset >= text.size()) return 0;
                const std::size_t k = std::min({capacity, piece, text.size() - offset});
                text.copy(out, k, offset);
                return k;
            });
        };
        const IndexedMesh sa = parse_off(source_of(off));
        CHECK(sa.positions == a.positions);
        CHECK(sa.face_vertices == a.face_vertices);
        const IndexedMesh sb = parse_obj(source_of(obj));
        CHECK(sb.positions == b.positions);
        CHECK(sb.face_vertices == b.face_vertices);
        try {
            parse_off(source_of(bad));
            FAIL("accepted");
        } catch (const ParseError& e) {
            CHECK(e.line() == 8);
        }
    }
}

// ------------------------------------------------------------ what edits make, files hold
namespace {

//          x (the ear)         A regular n-gon F1 = (v1 ... vn), counter-clockwise, and a
//         / \ F2               triangle F2 = (v2 v1 x) on its side v1-v2 (e1), outside it.
//       v1---v2                Joining them across e1 makes a face of n + 1 corners.
//      /  F1   ...
IndexedMesh polygon_with_ear(int32_t n) {
    IndexedMesh m;
    for (int32_t i = 0; i < n; ++i) m.add_vertex(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0);
    const double mid = M_PI / n; // outside the side v1-v2
    const int32_t x = m.add_vertex(2 * std::cos(mid), 2 * std::sin(mid), 0);
    std::vector<int32_t> all(n);
    for (int32_t i = 0; i < n; ++i) all[i] = i;
    m.add_face(all.data(), n);
    m.add_face({1, 0, x});
    return m;
}

std::vector<int32_t> edge_table(const WingedEdgeMesh& w) {
    std::vector<int32_t> t;
    for (const EdgeRecord& r : w.edges()) t.insert(t.end(), {r.start, r.end, r.left, r.right, r.start_left, r.start_right, r.end_left, r.end_right});
    return t;
}

// The mesh's own OFF export, read back and built: the same live counts and face sizes.
void require_export_reads_back(const WingedEdgeMesh& w) {
    const IndexedMesh live = w.live_face_set();
    const IndexedMesh back = parse_off(format_off(live));
    REQUIRE(validate_indexed(back).ok());
    const MeshCounts a = w.counts(), b = WingedEdgeMesh::build(back).counts();
    CHECK((a.vertices == b.vertices && a.edges == b.edges && a.faces == b.faces && a.boundary_loops == b.boundary_loops));
    CHECK(back.face_vertices == live.face_vertices);
}

} // namespace

TEST_CASE("join-faces and split-edge make no face over kMaxFaceCorners: at the limit the export reads back, one over is refused",
          "[mesh][limits][euler][trust]") {
    REQUIRE(kMaxFaceCorners == 1000);
    {
        // A 999-gon and the ear: the joined face has 999 + 3 - 2 = 1000 corners.
        WingedEdgeMesh w = WingedEdgeMesh::build(polygon_with_ear(kMaxFaceCorners - 1));
        REQUIRE(w.edge(0).start == 0);
        REQUIRE(w.edge(0).end == 1);
        REQUIRE(w.check(operation("join-faces", Edge(0))).ok);
        w.apply(operation("join-faces", Edge(0)));
        REQUIRE(w.validate().ok());
        CHECK(w.vertices_of_face(0).size() == 1000u);
        require_export_reads_back(w);
    }
    {
        // A 1000-gon and the ear: 1001 corners, refused before anything changes.
        WingedEdgeMesh w = WingedEdgeMesh::build(polygon_with_ear(kMaxFaceCorners));
        const std::vector<int32_t> before = edge_table(w);
        const MeshVersion version = w.version();
        const CheckResult r = w.check(operation("join-faces", Edge(0)));
        CHECK(r.code == "face-too-large");
        CHECK(r.message == "joining F1 and F2 would make a face of 1001 corners; a face may have at most 1000");
        CHECK_THROWS_AS(w.apply(operation("join-faces", Edge(0))), wingspline::Error);
        CHECK(!apply_unrecorded(w, operation("join-faces", Edge(0))));
        CHECK(edge_table(w) == before);
        CHECK(w.version() == version);
        REQUIRE(w.validate().ok());
        require_export_reads_back(w);
        // Splitting a side of the 1000-gon would give it 1001 corners too; a side of the ear only
        // grows the ear.
        const CheckResult s = w.check(operation("split-edge", Edge(5), 0.5));
        CHECK(s.code == "face-too-large");
        CHECK(s.message == "splitting e6 would give F1 1001 corners; a face may have at most 1000");
        CHECK_THROWS_AS(w.apply(operation("split-edge", Edge(5), 0.5)), wingspline::Error);
        CHECK(edge_table(w) == before);
        const int32_t ear_side = w.edge_count() - 1; // x -> v2, first met walking F2
        REQUIRE(w.edge(ear_side).left == 1);
        REQUIRE(w.edge(ear_side).right == kNone);
        w.apply(operation("split-edge", Edge(ear_side), 0.5));
        REQUIRE(w.validate().ok());
        require_export_reads_back(w);
    }
    {
        // A 999-gon's side split: 1000 corners, allowed.
        WingedEdgeMesh w = WingedEdgeMesh::build(polygon_with_ear(kMaxFaceCorners - 1));
        w.apply(operation("split-edge", Edge(5), 0.5));
        CHECK(w.vertices_of_face(0).size() == 1000u);
        require_export_reads_back(w);
    }
}

TEST_CASE("a face set with a face over kMaxFaceCorners is refused by validation and the build, as by the readers",
          "[mesh][limits][trust]") {
    const IndexedMesh ok = polygon_with_ear(kMaxFaceCorners), over = polygon_with_ear(kMaxFaceCorners + 1);
    CHECK(validate_indexed(ok).ok());
    CHECK_NOTHROW(WingedEdgeMesh::build(ok));
    const ValidationReport r = validate_indexed(over);
    REQUIRE(r.first_error() != nullptr);
    CHECK(r.first_error()->code == "face-too-large");
    CHECK(r.first_error()->message == "F1 has 1001 corners; a face may have at most 1000");
    CHECK(r.first_error()->faces == std::vector<int32_t>{0});
    try {
        WingedEdgeMesh::build(over);
        FAIL("built a 1001-corner face");
    } catch (const InvalidMesh& e) {
        CHECK(std::string(e.code()) == "face-too-large");
    }
    // The reader says the same words at the face's line.
    try {
        parse_off(format_off(over));
        FAIL("read a 1001-corner face");
    } catch (const ParseError& e) {
        CHECK(std::string(e.what()) == "line " + std::to_string(e.line()) + ": F1 has 1001 corners; a face may have at most 1000");
    }
}

TEST_CASE("edits keep the element counts within what a mesh file may hold", "[mesh][limits][euler][trust][large]") {
    // 1000 x 1000 quads, two triangles each: exactly kFileLimits.max_faces faces.
    WingedEdgeMesh w = WingedEdgeMesh::build(grid(1000, 1000));
    REQUIRE(w.face_count() == kFileLimits.max_faces);
    const std::vector<int32_t> before = edge_table(w);
    // Poking a triangle makes two more faces: refused, nothing changed.
    const CheckResult poke = w.check(operation("poke-face", Face(7)));
    CHECK(poke.code == "too-large");
    CHECK(poke.message == "poking F8 would make 2000002 faces; a mesh may have at most 2000000, as many as a mesh file may hold");
    CHECK_THROWS_AS(w.apply(operation("poke-face", Face(7))), wingspline::Error);
    CHECK(!apply_unrecorded(w, operation("poke-face", Face(7))));
    CHECK(edge_table(w) == before);
    // A split edge adds a vertex, no face: allowed.
    CHECK(w.check(operation("split-edge", Edge(0), 0.5)).ok);
    // Joining the first quad's two triangles across its diagonal e3 leaves a gap; splitting
    // the quad again comes back to the limit, with one row more than it.
    REQUIRE((w.edge(2).left == 0 && w.edge(2).right == 1));
    const Vertex a(w.edge(2).start), b(w.edge(2).end);
    w.apply(operation("join-faces", Edge(2)));
    REQUIRE(w.check(operation("split-face", Face(0), a, b)).ok);
    w.apply(operation("split-face", Face(0), a, b));
    CHECK(w.counts().faces == kFileLimits.max_faces);
    CHECK(w.face_count() == kFileLimits.max_faces + 1);
    // The gap is counted out, the live faces are at the limit: poking is refused again.
    CHECK(w.check(operation("poke-face", Face(7))).code == "too-large");
    CHECK(w.validate().ok());

    // Vertices: kFileLimits.max_vertices of them (one triangle, the others isolated).
    IndexedMesh m;
    m.positions.assign(3 * static_cast<std::size_t>(kFileLimits.max_vertices), 0.0);
    m.positions[3] = 1, m.positions[7] = 1;
    m.add_face({0, 1, 2});
    const WingedEdgeMesh v = WingedEdgeMesh::build(m);
    const CheckResult split = v.check(operation("split-edge", Edge(0), 0.5));
    CHECK(split.code == "too-large");
    CHECK(split.message == "splitting e1 would make 2000001 vertices; a mesh may have at most 2000000, as many as a mesh file may hold");
    CHECK(v.check(operation("poke-face", Face(0))).code == "too-large");
}
