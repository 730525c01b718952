// Exercise kind 1: the winged-edge table checker against lecture 000's own table and
// against correct tables made here, independently of the core, from the faces alone.
#include <catch2/catch.hpp>

#include "wingspline/mesh/exercise_check.h"
#include "wingspline/mesh/generators.h"

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace wingspline::mesh;

namespace {

const char* const kEdgeFields[8] = {"start", "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"};

int32_t label(const std::string& s) { return s == "-" ? kNone : std::stoi(s.substr(1)) - 1; }

struct FaceSet {
    std::vector<int32_t> offsets, corners;
    int32_t vertices = 0;
};

FaceSet face_set_of(const IndexedMesh& m) { return {m.face_offsets, m.face_vertices, m.vertex_count()}; }

// The lecture's table, read from the slide (lecture 000): e  S  E  L  R  S:L S:R E:L E:R
WingedEdgeAnswer slide_answer() {
    const char* slide[7][9] = {
        {"e1", "v1", "v3", "-", "F1", "e2", "e2", "e4", "e3"}, {"e2", "v1", "v2", "F1", "-", "e1", "e1", "e3", "e6"},
        {"e3", "v2", "v3", "F1", "F2", "e2", "e5", "e1", "e4"}, {"e4", "v3", "v4", "-", "F2", "e1", "e3", "e7", "e5"},
        {"e5", "v2", "v4", "F2", "F3", "e3", "e6", "e4", "e7"}, {"e6", "v2", "v5", "F3", "-", "e5", "e2", "e7", "e7"},
        {"e7", "v4", "v5", "-", "F3", "e4", "e5", "e6", "e6"}};
    WingedEdgeAnswer a;
    for (auto& row : slide)
        for (int k = 1; k < 9; ++k) a.edges.push_back(label(row[k]));
    for (const char* e : {"e1", "e6", "e3", "e5", "e6"}) a.vertex_edges.push_back(label(e));
    for (const char* e : {"e1", "e3", "e5"}) a.face_edges.push_back(label(e));
    return a;
}

// Walking a row's edge the other way: S and E swap, L and R swap, S:L <-> E:R, S:R <-> E:L
// (wing X:Y is the other edge at X of the face on side Y; the new Start is the old End and
// the new Left the old Right).
void flip_row(WingedEdgeAnswer& a, int32_t r) {
    int32_t* c = &a.edges[8 * r];
    std::swap(c[0], c[1]);
    std::swap(c[2], c[3]);
    std::swap(c[4], c[7]);
    std::swap(c[5], c[6]);
}

// Renames the edges: row r becomes row to[r], and every edge reference follows.
WingedEdgeAnswer renumber(const WingedEdgeAnswer& a, const std::vector<int32_t>& to) {
    const auto ref = [&](int32_t e) { return e < 0 ? e : to[e]; };
    WingedEdgeAnswer b = a;
    for (std::size_t r = 0; r < to.size(); ++r) {
        for (int k = 0; k < 4; ++k) b.edges[8 * to[r] + k] = a.edges[8 * r + k];
        for (int k = 4; k < 8; ++k) b.edges[8 * to[r] + k] = ref(a.edges[8 * r + k]);
    }
    for (auto& e : b.vertex_edges) e = ref(e);
    for (auto& e : b.face_edges) e = ref(e);
    return b;
}

AnswerCheck check(const FaceSet& f, const WingedEdgeAnswer& a) {
    return check_winged_edge_answer(f.offsets, f.corners, f.vertices, a);
}

std::string describe(const AnswerCheck& c) {
    std::string s;
    for (const AnswerFinding& x : c.findings) s += x.code + " " + x.field + " row " + std::to_string(x.row) + ": " + x.reason + "\n";
    return s;
}

// ------------------------------------------------------------------ independent reference
// The winged edge recomputed from the definition in lecture 000, from the faces alone: an edge
// is a pair of neighbouring corners; L runs S->E, R runs E->S; wing X:Y is the other edge at X
// among the sides of the face on side Y, the boundary's edges counting as a face. (Every
// fixture here has one boundary gap at most per vertex, where that is unambiguous.)
struct Reference {
    std::vector<std::pair<int32_t, int32_t>> pairs;         // edge -> (a, b) as first met
    std::map<std::pair<int32_t, int32_t>, int32_t> edge_of; // (min, max) -> edge
    std::map<std::pair<int32_t, int32_t>, int32_t> runs;    // (a, b) -> the face running a -> b
    std::vector<std::vector<int32_t>> sides;                // face -> its edges
    std::vector<std::vector<int32_t>> at_vertex;            // vertex -> its edges
    std::vector<char> boundary;                             // edge -> 1 on the boundary

    explicit Reference(const FaceSet& f) : at_vertex(f.vertices) {
        const int32_t F = static_cast<int32_t>(f.offsets.size()) - 1;
        sides.resize(F);
        for (int32_t face = 0; face < F; ++face) {
            const int32_t b = f.offsets[face], n = f.offsets[face + 1] - b;
            for (int32_t i = 0; i < n; ++i) {
                const int32_t u = f.corners[b + i], v = f.corners[b + (i + 1) % n];
                runs[{u, v}] = face;
                const auto key = std::make_pair(std::min(u, v), std::max(u, v));
                auto it = edge_of.find(key);
                if (it == edge_of.end()) {
                    it = edge_of.emplace(key, static_cast<int32_t>(pairs.size())).first;
                    pairs.push_back({u, v});
                    at_vertex[u].push_back(it->second);
                    at_vertex[v].push_back(it->second);
                }
                sides[face].push_back(it->second);
            }
        }
        for (const auto& p : pairs) boundary.push_back(!runs.count({p.first, p.second}) || !runs.count({p.second, p.first}));
    }
    int32_t edges() const { return static_cast<int32_t>(pairs.size()); }
    int32_t face_running(int32_t a, int32_t b) const {
        auto it = runs.find({a, b});
        return it == runs.end() ? kNone : it->second;
    }
    bool touches(int32_t e, int32_t v) const { return pairs[e].first == v || pairs[e].second == v; }
    int32_t other_edge_at(int32_t x, int32_t face, int32_t e) const {
        for (int32_t g : face == kNone ? at_vertex[x] : sides[face])
            if (g != e && touches(g, x) && (face != kNone || boundary[g])) return g;
        return kNone;
    }
    // Edge e's row, run from s to t, in the reference numbering.
    std::array<int32_t, 8> row(int32_t e, int32_t s, int32_t t) const {
        const int32_t L = face_running(s, t), R = face_running(t, s);
        return {s, t, L, R, other_edge_at(s, L, e), other_edge_at(s, R, e), other_edge_at(t, L, e), other_edge_at(t, R, e)};
    }
};

// A correct answer in a random numbering and orientation, with a random incident edge per
// vertex and a random side per face.
WingedEdgeAnswer random_correct_answer(const Reference& ref, std::mt19937& rng) {
    const int32_t E = ref.edges();
    std::vector<int32_t> to(E);
    for (int32_t e = 0; e < E; ++e) to[e] = e;
    std::shuffle(to.begin(), to.end(), rng);
    const auto ref_label = [&](int32_t e) { return e == kNone ? kNone : to[e]; };
    WingedEdgeAnswer a;
    a.edges.assign(8 * static_cast<std::size_t>(E), 0);
    for (int32_t e = 0; e < E; ++e) {
        auto [s, t] = ref.pairs[e];
        if (rng() % 2) std::swap(s, t);
        const auto r = ref.row(e, s, t);
        for (int k = 0; k < 8; ++k) a.edges[8 * to[e] + k] = k < 4 ? r[k] : ref_label(r[k]);
    }
    for (const auto& list : ref.at_vertex) a.vertex_edges.push_back(list.empty() ? kNone : to[list[rng() % list.size()]]);
    for (const auto& list : ref.sides) a.face_edges.push_back(to[list[rng() % list.size()]]);
    return a;
}

} // namespace

TEST_CASE("the slide's own table is accepted with no findings", "[mesh][exercise]") {
    const FaceSet f = face_set_of(lecture_example().mesh);
    const AnswerCheck c = check(f, slide_answer());
    INFO(describe(c));
    CHECK(c.correct());
}

TEST_CASE("the slide's table renumbered, e5 flipped, is accepted; so is every edge flipped alone", "[mesh][exercise]") {
    const FaceSet f = face_set_of(lecture_example().mesh);
    // e1..e7 -> e4 e7 e1 e2 e6 e3 e5 (0-based)
    WingedEdgeAnswer renumbered = renumber(slide_answer(), {3, 6, 0, 1, 5, 2, 4});
    flip_row(renumbered, 5); // the slide's e5 is row e6 now
    CHECK(renumbered.edges[8 * 5 + 0] == 3); // S = v4 after the flip
    const AnswerCheck c = check(f, renumbered);
    INFO(describe(c));
    CHECK(c.correct());
    const AnswerCheck as_on_slide = check(f, slide_answer());
    for (int32_t r = 0; r < 7; ++r) {
        WingedEdgeAnswer flipped = slide_answer();
        flip_row(flipped, r);
        const AnswerCheck one = check(f, flipped);
        INFO("flipped e" << r + 1 << "\n" << describe(one));
        CHECK(one.correct());
        CHECK(one.row_reversed[r] != as_on_slide.row_reversed[r]); // read as the same edge, the other way
    }
}

TEST_CASE("row e5 with S:L = e2 is named with the definition's reason", "[mesh][exercise]") {
    const FaceSet f = face_set_of(lecture_example().mesh);
    WingedEdgeAnswer a = slide_answer();
    a.edges[8 * label("e5") + 4] = label("e2");
    const AnswerCheck c = check(f, a);
    REQUIRE(c.findings.size() == 1);
    const AnswerFinding& x = c.findings[0];
    CHECK(x.table == MeshTable::Edge);
    CHECK(x.row == label("e5"));
    CHECK(x.field == "startLeft");
    CHECK(x.given == label("e2"));
    CHECK(x.expected == label("e3")); // the slide's S:L of e5
    CHECK(x.code == "wrong-wing");
    // The reason names the row, the column, both values, the vertex and the face it is found around.
    for (const char* word : {"row e5", "S:L", "is e3, not e2", "v2", "F2", "counter-clockwise"}) {
        INFO(x.reason << " / " << word);
        CHECK(x.reason.find(word) != std::string::npos);
    }
}

TEST_CASE("a boundary wing is explained by the boundary acting as a face", "[mesh][exercise]") {
    const FaceSet f = face_set_of(lecture_example().mesh);
    WingedEdgeAnswer a = slide_answer();
    a.edges[8 * label("e1") + 4] = label("e3"); // the slide: S:L of e1 = e2, around v1 along the boundary
    const AnswerCheck c = check(f, a);
    REQUIRE(c.findings.size() == 1);
    CHECK(c.findings[0].expected == label("e2"));
    CHECK(c.findings[0].reason.find("boundary") != std::string::npos);
}

TEST_CASE("blank cells are findings with the value they should hold", "[mesh][exercise]") {
    const FaceSet f = face_set_of(lecture_example().mesh);
    const WingedEdgeAnswer slide = slide_answer();
    WingedEdgeAnswer a = slide;
    a.edges[8 * label("e4") + 2] = kBlank; // L of e4: none (boundary)
    a.edges[8 * label("e6") + 7] = kBlank; // E:R of e6: e7
    a.edges[8 * label("e2") + 0] = kBlank; // S of e2: v1 (E = v2 given)
    a.vertex_edges[1] = kBlank;
    const AnswerCheck c = check(f, a);
    INFO(describe(c));
    REQUIRE(c.findings.size() == 4);
    for (const AnswerFinding& x : c.findings) CHECK(x.code == "blank");
    CHECK(c.findings[0].row == label("e2"));
    CHECK(c.findings[0].field == "start");
    CHECK(c.findings[0].expected == 0);
    CHECK(c.findings[1].row == label("e4"));
    CHECK(c.findings[1].expected == kNone);
    CHECK(c.findings[2].row == label("e6"));
    CHECK(c.findings[2].expected == label("e7"));
    CHECK(c.findings[3].table == MeshTable::Vertex);
    // Any edge at v2 is right for the vertex table: e2, e3, e5 or e6.
    const std::vector<int32_t> at_v2 = {label("e2"), label("e3"), label("e5"), label("e6")};
    CHECK(std::count(at_v2.begin(), at_v2.end(), c.findings[3].expected) == 1);
    // The worked answer fills the blanks from the mesh, in the student's numbering: the slide.
    const WingedEdgeAnswer worked = worked_winged_edge_answer(f.offsets, f.corners, f.vertices, a);
    CHECK(worked.edges == slide.edges);
    CHECK(check(f, worked).correct());
}

TEST_CASE("a missing row, a duplicate row and unknown labels", "[mesh][exercise]") {
    const FaceSet f = face_set_of(lecture_example().mesh);
    SECTION("e7 left out: one missing edge v4-v5, and each reference to e7 names an unknown row") {
        WingedEdgeAnswer a = slide_answer();
        a.edges.resize(6 * 8);
        const AnswerCheck c = check(f, a);
        INFO(describe(c));
        // The slide names e7 in E:L of e4, E:R of e5, E:L and E:R of e6.
        int unknown = 0, missing = 0;
        for (const AnswerFinding& x : c.findings) {
            if (x.code == "unknown-label") {
                ++unknown;
                CHECK(x.given == 6);
            }
            if (x.code == "missing-edge") {
                ++missing;
                CHECK(x.reason.find("v4-v5") != std::string::npos);
            }
        }
        CHECK(unknown == 4);
        CHECK(missing == 1);
        CHECK(c.findings.size() == 5);
    }
    SECTION("e3 written twice: the second row is a duplicate") {
        WingedEdgeAnswer a = slide_answer();
        a.edges.insert(a.edges.end(), a.edges.begin() + 8 * 2, a.edges.begin() + 8 * 3);
        const AnswerCheck c = check(f, a);
        INFO(describe(c));
        REQUIRE(c.findings.size() == 1);
        CHECK(c.findings[0].code == "duplicate-edge");
        CHECK(c.findings[0].row == 7);
        CHECK(c.findings[0].reason.find("e3") != std::string::npos);
    }
    SECTION("S-E not an edge, a face and a vertex that do not exist") {
        WingedEdgeAnswer a = slide_answer();
        a.edges[8 * label("e1") + 1] = 3; // v1-v4 is no edge of the mesh
        a.edges[8 * label("e3") + 3] = 7; // F8
        a.edges[8 * label("e7") + 0] = 9; // v10
        const AnswerCheck c = check(f, a);
        INFO(describe(c));
        REQUIRE(c.findings.size() == 3);
        CHECK(c.findings[0].code == "not-an-edge");
        CHECK(c.findings[0].field == "end"); // v1 is kept: the missing edge v1-v3 starts there
        CHECK(c.findings[0].expected == 2);
        CHECK(c.findings[1].code == "unknown-label");
        CHECK(c.findings[1].expected == 1);
        CHECK(c.findings[2].code == "unknown-label");
        CHECK(c.findings[2].expected == 3);
    }
}

TEST_CASE("malformed answers and meshes are errors with a code, not findings", "[mesh][exercise]") {
    const FaceSet f = face_set_of(lecture_example().mesh);
    const auto code_of = [&](const FaceSet& faces, const WingedEdgeAnswer& a) {
        try {
            check(faces, a);
        } catch (const wingspline::Error& e) {
            return e.code();
        }
        return std::string("accepted");
    };
    WingedEdgeAnswer a = slide_answer();
    a.edges.pop_back();
    CHECK(code_of(f, a) == "invalid-answer");
    a = slide_answer();
    a.vertex_edges.pop_back();
    CHECK(code_of(f, a) == "invalid-answer");
    a = slide_answer();
    a.face_edges.push_back(0);
    CHECK(code_of(f, a) == "invalid-answer");
    a = slide_answer();
    a.edges[3] = -3;
    CHECK(code_of(f, a) == "invalid-answer");
    FaceSet bad = f;
    bad.corners[0] = 11;
    CHECK(code_of(bad, slide_answer()) == "index-out-of-range");
    bad = f;
    bad.offsets.back() = 100;
    CHECK(code_of(bad, slide_answer()) == "invalid-faces");
    bad = f;
    bad.vertices = -1;
    CHECK(code_of(bad, slide_answer()) == "invalid-faces");
}

TEST_CASE("random correct tables are accepted; one corrupted cell is named with its expected value", "[mesh][exercise][property]") {
    // Fixtures: the lecture mesh, closed solids, fans and grids (boundaries), a closed sphere.
    std::vector<IndexedMesh> meshes = {lecture_example().mesh, cube(), tetrahedron(), uv_sphere(5, 4)};
    for (int n = 1; n <= 6; ++n) meshes.push_back(open_fan(n));
    for (int nx = 1; nx <= 4; ++nx)
        for (int ny = 1; ny <= 3; ++ny) meshes.push_back(grid(nx, ny));
    std::mt19937 rng(19);
    int accepted = 0, corrupted = 0, still_right = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const FaceSet f = face_set_of(meshes[trial % meshes.size()]);
        const Reference ref(f);
        const WingedEdgeAnswer right = random_correct_answer(ref, rng);
        const AnswerCheck ok = check(f, right);
        INFO("trial " << trial << "\n" << describe(ok));
        REQUIRE(ok.correct());
        ++accepted;
        // The worked answer of a correct table is that table.
        const WingedEdgeAnswer worked_right = worked_winged_edge_answer(f.offsets, f.corners, f.vertices, right);
        REQUIRE(worked_right.edges == right.edges);
        REQUIRE(worked_right.vertex_edges == right.vertex_edges);
        REQUIRE(worked_right.face_edges == right.face_edges);

        // One cell changed to a blank, "none", a label beyond the table or another label.
        const int32_t E = ref.edges(), V = f.vertices, F = static_cast<int32_t>(f.offsets.size()) - 1;
        const int32_t cells = 8 * E + V + F;
        const int32_t cell = static_cast<int32_t>(rng() % cells);
        MeshTable table = MeshTable::Edge;
        int32_t row = cell / 8, column = cell % 8, old = 0, range = 0;
        WingedEdgeAnswer wrong = right;
        int32_t* slot = nullptr;
        if (cell < 8 * E) {
            slot = &wrong.edges[cell];
            range = column < 2 ? V : column < 4 ? F : E;
        } else if (cell < 8 * E + V) {
            table = MeshTable::Vertex;
            row = cell - 8 * E;
            slot = &wrong.vertex_edges[row];
            range = E;
        } else {
            table = MeshTable::Face;
            row = cell - 8 * E - V;
            slot = &wrong.face_edges[row];
            range = E;
        }
        old = *slot;
        int32_t value = old;
        while (value == old) {
            const int kind = static_cast<int>(rng() % 6);
            value = kind == 0 ? kBlank : kind == 1 ? kNone : kind == 2 ? range + static_cast<int32_t>(rng() % 3)
                                                                       : static_cast<int32_t>(rng() % range);
        }
        *slot = value;
        // Still right? Only the vertex and face tables have a choice: any incident edge, any side.
        std::vector<int32_t> label_to_ref(E);
        for (int32_t e = 0; e < E; ++e)
            label_to_ref[e] = ref.edge_of.at(
                {std::min(right.edges[8 * e], right.edges[8 * e + 1]), std::max(right.edges[8 * e], right.edges[8 * e + 1])});
        const auto acceptable = [&](int32_t v) {
            if (v < 0 || v >= E) return false;
            const int32_t e = label_to_ref[v];
            return table == MeshTable::Vertex ? ref.touches(e, row)
                                              : std::count(ref.sides[row].begin(), ref.sides[row].end(), e) > 0;
        };
        const AnswerCheck c = check(f, wrong);
        INFO("table " << table_name(table) << " row " << row << " column " << column << " " << old << " -> " << value << "\n"
                      << describe(c));
        if (table != MeshTable::Edge && acceptable(value)) {
            CHECK(c.correct());
            ++still_right;
            continue;
        }
        ++corrupted;
        // Exactly one finding, on that row and column, giving the value written and the right one.
        REQUIRE(c.findings.size() == 1);
        const AnswerFinding& x = c.findings[0];
        CHECK(x.table == table);
        CHECK(x.row == row);
        if (table == MeshTable::Edge && column < 2) {
            // The pair S-E as a whole is wrong; the check names the end it could not match.
            CHECK((x.field == "start" || x.field == "end"));
            if (x.field == kEdgeFields[column]) {
                CHECK(x.given == value);
                CHECK(x.expected == old);
            }
        } else {
            CHECK(x.field == (table == MeshTable::Edge ? kEdgeFields[column] : "edge"));
            CHECK(x.given == value);
            if (table == MeshTable::Edge) CHECK(x.expected == old);
            else CHECK(acceptable(x.expected));
        }
        const char* code = value == kBlank ? "blank" : value >= range || (column < 2 && value == kNone && table == MeshTable::Edge) ? "unknown-label" : nullptr;
        if (code) CHECK(x.code == code);
        // The worked answer restores the table (the rows as they were; the vertex/face tables right).
        const WingedEdgeAnswer worked = worked_winged_edge_answer(f.offsets, f.corners, f.vertices, wrong);
        CHECK(worked.edges == right.edges);
        CHECK(check(f, worked).correct());
    }
    CHECK(accepted == 4000);
    CHECK(corrupted > 3000);
    CHECK(still_right > 0);
}

TEST_CASE("a large table with every S left blank: each row is matched by its E and its wings", "[mesh][exercise]") {
    // 2,400 triangles, 3,669 edges: each row keeps only E, so the check must find each row's edge
    // among the edges at E that agree with the row's faces and wings (one blank finding per row).
    const FaceSet f = face_set_of(grid(40, 30));
    const Reference ref(f);
    std::mt19937 rng(1919);
    const WingedEdgeAnswer right = random_correct_answer(ref, rng);
    WingedEdgeAnswer a = right;
    const int32_t E = ref.edges();
    for (int32_t r = 0; r < E; ++r) a.edges[8 * r] = kBlank;
    // Two rows with both ends blank take an edge by the rest of the row.
    a.edges[8 * 7 + 1] = kBlank;
    a.edges[8 * 100 + 1] = kBlank;
    const AnswerCheck c = check(f, a);
    REQUIRE(c.findings.size() == static_cast<std::size_t>(E + 2));
    int32_t wrong_expectation = 0;
    for (const AnswerFinding& x : c.findings) {
        CHECK(x.code == "blank");
        wrong_expectation += x.expected != right.edges[8 * x.row + (x.field == "start" ? 0 : 1)];
    }
    // Both-blank rows: any unmatched edge is a defensible reading; the ones given here are
    // matched by their faces and wings once every other row has taken its own edge.
    CHECK(wrong_expectation == 0);
    CHECK(worked_winged_edge_answer(f.offsets, f.corners, f.vertices, a).edges == right.edges);
}

TEST_CASE("S and E written the other way round, the rest right: one finding says to swap them", "[mesh][exercise]") {
    // Row e5 as v4 -> v2 with the slide's L, R and wings (which fit v2 -> v4): L, R and all four
    // wings would each be wrong for v4 -> v2; the one mistake is the order of S and E.
    const FaceSet f = face_set_of(lecture_example().mesh);
    WingedEdgeAnswer a = slide_answer();
    std::swap(a.edges[8 * label("e5")], a.edges[8 * label("e5") + 1]);
    const AnswerCheck c = check(f, a);
    INFO(describe(c));
    REQUIRE(c.findings.size() == 1);
    CHECK(c.findings[0].code == "swapped-ends");
    CHECK(c.findings[0].row == label("e5"));
    CHECK(c.findings[0].field == "start");
    CHECK(c.findings[0].given == 3);
    CHECK(c.findings[0].expected == 1);
    CHECK(c.findings[0].reason.find("swap") != std::string::npos);
    // The worked answer puts S and E back and keeps the rest: the slide's table.
    CHECK(worked_winged_edge_answer(f.offsets, f.corners, f.vertices, a).edges == slide_answer().edges);
}

// Review findings: feedback never contradicts itself or the worked answer.
TEST_CASE("a row that is no edge, with an edge elsewhere missing: the reason claims only what was looked at", "[mesh][exercise]") {
    // Row e7 (v4-v5) replaced by v1-v2, which is e2's pair: every edge at v1 and v2 has its
    // row, but v4-v5 has none. Before, the reason said "every edge of the mesh already has its
    // row, so this one can go", while a missing-edge finding named v4-v5 and the worked answer
    // gave it this very row.
    const FaceSet f = face_set_of(lecture_example().mesh);
    WingedEdgeAnswer a = slide_answer();
    a.edges[8 * label("e7") + 0] = 0;
    a.edges[8 * label("e7") + 1] = 1;
    const AnswerCheck c = check(f, a);
    INFO(describe(c));
    bool missing = false, duplicate = false;
    for (const AnswerFinding& x : c.findings) {
        CHECK(x.reason.find("can go") == std::string::npos);
        CHECK(x.reason.find("every edge of the mesh already") == std::string::npos);
        missing = missing || (x.code == "missing-edge" && x.reason.find("v4-v5") != std::string::npos);
        if (x.code == "duplicate-edge") {
            duplicate = true;
            CHECK(x.row == label("e7"));
            CHECK(x.reason.find("every edge at v1 and at v2 already has its row") != std::string::npos);
        }
    }
    CHECK(missing);
    CHECK(duplicate);
}

TEST_CASE("both ends wrong, the rest right: S and E are named, no swap is suggested", "[mesh][exercise]") {
    // Row e5 written S = v4, E = v1 (v4-v1 is no edge) with the slide's L, R and wings, which are
    // those of v2 -> v4. Before: "E is v2" and also "S and E are the other way round", and the
    // faces and wings read backwards.
    const FaceSet f = face_set_of(lecture_example().mesh);
    WingedEdgeAnswer a = slide_answer();
    a.edges[8 * label("e5") + 0] = 3;
    a.edges[8 * label("e5") + 1] = 0;
    const AnswerCheck c = check(f, a);
    INFO(describe(c));
    REQUIRE(c.findings.size() == 2);
    for (const AnswerFinding& x : c.findings) {
        CHECK(x.row == label("e5"));
        CHECK(x.code == "not-an-edge");
    }
    CHECK(c.findings[0].field == "start");
    CHECK(c.findings[0].expected == 1); // v2
    CHECK(c.findings[1].field == "end");
    CHECK(c.findings[1].expected == 3); // v4
    CHECK(worked_winged_edge_answer(f.offsets, f.corners, f.vertices, a).edges == slide_answer().edges);
}
