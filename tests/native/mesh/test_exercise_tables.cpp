// Exercise kinds 1 (the face table, the edge list, the adjacency lists) and 2 (predicting the
// walk): the checkers against the lectures' own tables and against answers made here from the
// faces alone (an edge = two neighbouring corners; the face running a -> b; the boundary as a
// face), independently of the core.
#include <catch2/catch.hpp>

#include "exercise_fixtures.h"

#include "wingspline/error.h"
#include "wingspline/mesh/exercise_tables.h"
#include "wingspline/mesh/exercise_walk.h"
#include "wingspline/mesh/generators.h"

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace wingspline::mesh;

namespace {

struct Faces {
    std::vector<int32_t> offsets, corners;
    int32_t vertices = 0;
    int32_t count() const { return static_cast<int32_t>(offsets.size()) - 1; }
    std::vector<int32_t> face(int32_t f) const { return {corners.begin() + offsets[f], corners.begin() + offsets[f + 1]}; }
};

Faces faces_of(const IndexedMesh& m) { return {m.face_offsets, m.face_vertices, m.vertex_count()}; }

// The reference, from the faces alone.
struct Ref {
    std::vector<std::pair<int32_t, int32_t>> pairs;         // edge -> (a, b) as first met
    std::map<std::pair<int32_t, int32_t>, int32_t> edge_of; // (min, max) -> edge
    std::map<std::pair<int32_t, int32_t>, int32_t> runs;    // (a, b) -> the face running a -> b
    std::vector<std::vector<int32_t>> sides;                // face -> its edges, in corner order
    std::vector<std::vector<int32_t>> at_vertex;            // vertex -> its edges
    std::vector<std::set<int32_t>> neighbours;

    explicit Ref(const Faces& f) : at_vertex(f.vertices), neighbours(f.vertices) {
        sides.resize(f.count());
        for (int32_t face = 0; face < f.count(); ++face) {
            const auto c = f.face(face);
            for (std::size_t i = 0; i < c.size(); ++i) {
                const int32_t u = c[i], v = c[(i + 1) % c.size()];
                runs[{u, v}] = face;
                const auto k = std::make_pair(std::min(u, v), std::max(u, v));
                auto it = edge_of.find(k);
                if (it == edge_of.end()) {
                    it = edge_of.emplace(k, static_cast<int32_t>(pairs.size())).first;
                    pairs.push_back({u, v});
                    at_vertex[u].push_back(it->second);
                    at_vertex[v].push_back(it->second);
                    neighbours[u].insert(v);
                    neighbours[v].insert(u);
                }
                sides[face].push_back(it->second);
            }
        }
    }
    int32_t edges() const { return static_cast<int32_t>(pairs.size()); }
    int32_t running(int32_t a, int32_t b) const {
        auto it = runs.find({a, b});
        return it == runs.end() ? kNone : it->second;
    }
    bool boundary(int32_t e) const { return running(pairs[e].first, pairs[e].second) == kNone || running(pairs[e].second, pairs[e].first) == kNone; }
    bool touches(int32_t e, int32_t v) const { return pairs[e].first == v || pairs[e].second == v; }
    // The other edge at x of the face (the boundary when kNone), as lecture 000's wings.
    int32_t other_edge_at(int32_t x, int32_t face, int32_t e) const {
        for (int32_t g : face == kNone ? at_vertex[x] : sides[face])
            if (g != e && touches(g, x) && (face != kNone || boundary(g))) return g;
        return kNone;
    }
};

std::vector<IndexedMesh> fixtures() { return wingspline::test_exercises::exercise_fixtures(); }

ListAnswer list_answer(const std::vector<std::vector<int32_t>>& rows) {
    ListAnswer a;
    a.offsets.push_back(0);
    for (const auto& r : rows) {
        a.cells.insert(a.cells.end(), r.begin(), r.end());
        a.offsets.push_back(static_cast<int32_t>(a.cells.size()));
    }
    return a;
}

std::vector<std::vector<int32_t>> rows_of(const ListAnswer& a) {
    std::vector<std::vector<int32_t>> out;
    for (std::size_t r = 0; r + 1 < a.offsets.size(); ++r) out.emplace_back(a.cells.begin() + a.offsets[r], a.cells.begin() + a.offsets[r + 1]);
    return out;
}

std::string describe(const std::vector<AnswerFinding>& list) {
    std::string s;
    for (const AnswerFinding& x : list)
        s += x.code + " " + table_name(x.table) + " row " + std::to_string(x.row) + " " + x.field + "[" + std::to_string(x.index) +
             "] " + std::to_string(x.given) + "->" + std::to_string(x.expected) + ": " + x.reason + "\n";
    return s;
}

// A different value for a cell: blank, none, a number past the range, or another number in range.
int32_t corrupt(int32_t old, int32_t range, std::mt19937& rng) {
    int32_t value = old;
    while (value == old) {
        const int kind = static_cast<int>(rng() % 6);
        value = kind == 0 ? kBlank : kind == 1 ? kNone : kind == 2 ? range + static_cast<int32_t>(rng() % 3) : static_cast<int32_t>(rng() % range);
    }
    return value;
}

const char* code_for(int32_t value, int32_t range, const char* otherwise) {
    return value == kBlank ? "blank" : value < 0 || value >= range ? "unknown-label" : otherwise;
}

// The edge list made here: edges renumbered by `to`, each run either way, P1 and P2 in either
// order, polygons listing their sides shuffled.
EdgeListAnswer random_edge_list(const Faces& f, const Ref& ref, std::mt19937& rng, std::vector<int32_t>& to) {
    const int32_t E = ref.edges();
    to.resize(E);
    for (int32_t e = 0; e < E; ++e) to[e] = e;
    std::shuffle(to.begin(), to.end(), rng);
    EdgeListAnswer a;
    a.edges.assign(4 * static_cast<std::size_t>(E), 0);
    for (int32_t e = 0; e < E; ++e) {
        auto [s, t] = ref.pairs[e];
        if (rng() % 2) std::swap(s, t);
        int32_t p1 = ref.running(s, t), p2 = ref.running(t, s);
        if (rng() % 2) std::swap(p1, p2);
        int32_t* c = &a.edges[4 * static_cast<std::size_t>(to[e])];
        c[0] = s, c[1] = t, c[2] = p1, c[3] = p2;
    }
    std::vector<std::vector<int32_t>> polygons;
    for (int32_t face = 0; face < f.count(); ++face) {
        std::vector<int32_t> p;
        for (int32_t e : ref.sides[face]) p.push_back(to[e]);
        std::shuffle(p.begin(), p.end(), rng);
        polygons.push_back(p);
    }
    a.polygons = list_answer(polygons);
    return a;
}

} // namespace

// ------------------------------------------------------------------ the lectures' own tables
TEST_CASE("lecture 000's face table, Foley's edge list and the slide mesh's neighbours are accepted", "[mesh][exercise]") {
    const Faces lecture = faces_of(lecture_example().mesh);
    // "Vertex and Face Tables": F1 = V1 V2 V3, F2 = V2 V4 V3, F3 = V2 V5 V4 (0-based here).
    const ListAnswer slide = list_answer({{0, 1, 2}, {1, 3, 2}, {1, 4, 3}});
    CHECK(describe(check_faces_answer(lecture.offsets, lecture.corners, lecture.vertices, slide).findings).empty());
    // The same faces each from another corner.
    CHECK(check_faces_answer(lecture.offsets, lecture.corners, lecture.vertices, list_answer({{1, 2, 0}, {2, 1, 3}, {4, 3, 1}})).correct());
    // Lecture 001: E1 = (V1, V2, P1, l), E2 = (V2, V3, P2, l), E3 = (V3, V4, P2, l), E4 = (V4, V2, P1, P2),
    // E5 = (V4, V1, P1, l); P1 = (E1, E4, E5), P2 = (E2, E3, E4).
    const Faces foley = faces_of(foley_example().mesh);
    EdgeListAnswer e;
    e.edges = {0, 1, 0, kNone, 1, 2, 1, kNone, 2, 3, 1, kNone, 3, 1, 0, 1, 3, 0, 0, kNone};
    e.polygons = list_answer({{0, 3, 4}, {1, 2, 3}});
    const TableAnswerCheck fc = check_edge_list_answer(foley.offsets, foley.corners, foley.vertices, e);
    INFO(describe(fc.findings));
    CHECK(fc.correct());
    // The slide does not tie P1 to a side: E4 runs V4 -> V2 with P1 = (1, 2, 4) on its right.
    const Ref ref(foley);
    CHECK(ref.running(3, 1) == 1);
    CHECK(ref.running(1, 3) == 0);
    // Lecture 000's mesh: each vertex's neighbours read off its faces (v1: v2 v3; v2: v1 v3 v4 v5; ...).
    const ListAnswer adj = list_answer({{1, 2}, {0, 2, 3, 4}, {0, 1, 3}, {1, 2, 4}, {1, 3}});
    CHECK(describe(check_adjacency_answer(lecture.offsets, lecture.corners, lecture.vertices, adj).findings).empty());
}

TEST_CASE("a face listed clockwise is one finding that says the lecture goes counter-clockwise", "[mesh][exercise]") {
    const Faces lecture = faces_of(lecture_example().mesh);
    const TableAnswerCheck c = check_faces_answer(lecture.offsets, lecture.corners, lecture.vertices, list_answer({{0, 1, 2}, {1, 2, 3}, {1, 4, 3}}));
    INFO(describe(c.findings));
    REQUIRE(c.findings.size() == 1);
    CHECK(c.findings[0].code == "clockwise");
    CHECK(c.findings[0].row == 1);
    CHECK(c.findings[0].table == MeshTable::Face);
    CHECK(c.findings[0].reason.find("face F2") == 0);
    CHECK(c.findings[0].reason.find("counter-clockwise") != std::string::npos);
    // The worked answer turns it round, from the corner the student started at.
    CHECK(rows_of(worked_faces_answer(lecture.offsets, lecture.corners, lecture.vertices, list_answer({{0, 1, 2}, {1, 2, 3}, {1, 4, 3}}))) ==
          std::vector<std::vector<int32_t>>{{0, 1, 2}, {1, 3, 2}, {1, 4, 3}});
}

TEST_CASE("the right corners in a wrong order, a missing corner and an extra one", "[mesh][exercise]") {
    const Faces cube_faces = faces_of(cube());
    const Ref ref(cube_faces);
    std::vector<std::vector<int32_t>> rows;
    for (int32_t f = 0; f < cube_faces.count(); ++f) rows.push_back(cube_faces.face(f));
    const auto q = rows[0];
    auto wrong = rows;
    wrong[0] = {q[0], q[2], q[1], q[3]}; // neither way round
    TableAnswerCheck c = check_faces_answer(cube_faces.offsets, cube_faces.corners, cube_faces.vertices, list_answer(wrong));
    INFO(describe(c.findings));
    REQUIRE(!c.findings.empty());
    for (const AnswerFinding& x : c.findings) CHECK(x.code == "wrong-order");
    wrong[0] = {q[0], q[1], q[2]};
    c = check_faces_answer(cube_faces.offsets, cube_faces.corners, cube_faces.vertices, list_answer(wrong));
    REQUIRE(c.findings.size() == 1);
    CHECK(c.findings[0].code == "missing-vertex");
    CHECK(c.findings[0].expected == q[3]);
    CHECK(c.findings[0].index == kNone);
    int32_t outside = 0;
    while (std::count(q.begin(), q.end(), outside)) ++outside;
    wrong[0] = {q[0], q[1], q[2], q[3], outside};
    c = check_faces_answer(cube_faces.offsets, cube_faces.corners, cube_faces.vertices, list_answer(wrong));
    REQUIRE(c.findings.size() == 1);
    CHECK(c.findings[0].code == "extra-vertex");
    CHECK(c.findings[0].given == outside);
    CHECK(c.findings[0].index == 4);
    CHECK(c.findings[0].reason.find("v" + std::to_string(outside + 1) + " is not a corner of F1") != std::string::npos);
}

// ------------------------------------------------------------------ property tests
TEST_CASE("face tables: any rotation accepted, one corrupted corner named with its expected vertex", "[mesh][exercise][property]") {
    const auto meshes = fixtures();
    std::mt19937 rng(1900);
    int accepted = 0, named = 0, clockwise = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Faces f = faces_of(meshes[trial % meshes.size()]);
        std::vector<std::vector<int32_t>> rows;
        for (int32_t face = 0; face < f.count(); ++face) {
            auto c = f.face(face);
            std::rotate(c.begin(), c.begin() + rng() % c.size(), c.end());
            rows.push_back(c);
        }
        const ListAnswer right = list_answer(rows);
        const TableAnswerCheck ok = check_faces_answer(f.offsets, f.corners, f.vertices, right);
        INFO("trial " << trial << "\n" << describe(ok.findings));
        REQUIRE(ok.correct());
        REQUIRE(rows_of(worked_faces_answer(f.offsets, f.corners, f.vertices, right)) == rows);
        ++accepted;
        // One face turned round: one finding, "clockwise", on that face.
        const int32_t turned = static_cast<int32_t>(rng() % f.count());
        auto flipped = rows;
        std::reverse(flipped[turned].begin(), flipped[turned].end());
        const TableAnswerCheck cw = check_faces_answer(f.offsets, f.corners, f.vertices, list_answer(flipped));
        REQUIRE(cw.findings.size() == 1);
        CHECK(cw.findings[0].code == "clockwise");
        CHECK(cw.findings[0].row == turned);
        ++clockwise;
        // One cell changed.
        const int32_t face = static_cast<int32_t>(rng() % f.count());
        const int32_t i = static_cast<int32_t>(rng() % rows[face].size());
        auto wrong = rows;
        const int32_t old = wrong[face][i], value = corrupt(old, f.vertices, rng);
        wrong[face][i] = value;
        const TableAnswerCheck c = check_faces_answer(f.offsets, f.corners, f.vertices, list_answer(wrong));
        INFO("face " << face << " corner " << i << " " << old << " -> " << value << "\n" << describe(c.findings));
        REQUIRE(c.findings.size() == 1);
        const AnswerFinding& x = c.findings[0];
        CHECK(x.table == MeshTable::Face);
        CHECK(x.row == face);
        CHECK(x.field == "vertices");
        CHECK(x.index == i);
        CHECK(x.given == value);
        CHECK(x.expected == old);
        CHECK(x.code == code_for(value, f.vertices, "wrong-vertex"));
        CHECK(x.reason.find("face " + face_label(face) + ", corner " + std::to_string(i + 1)) == 0);
        CHECK(rows_of(worked_faces_answer(f.offsets, f.corners, f.vertices, list_answer(wrong))) == rows);
        ++named;
    }
    CHECK(accepted == 3000);
    CHECK(named == 3000);
    CHECK(clockwise == 3000);
}

TEST_CASE("edge lists: any numbering, direction and P1/P2 order accepted; one corrupted cell named", "[mesh][exercise][property]") {
    const auto meshes = fixtures();
    std::mt19937 rng(1901);
    int accepted = 0, named = 0, ends_elsewhere = 0, ambiguous = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const Faces f = faces_of(meshes[trial % meshes.size()]);
        const Ref ref(f);
        std::vector<int32_t> to;
        const EdgeListAnswer right = random_edge_list(f, ref, rng, to);
        const TableAnswerCheck ok = check_edge_list_answer(f.offsets, f.corners, f.vertices, right);
        INFO("trial " << trial << "\n" << describe(ok.findings));
        REQUIRE(ok.correct());
        const EdgeListAnswer same = worked_edge_list_answer(f.offsets, f.corners, f.vertices, right);
        REQUIRE(same.edges == right.edges);
        REQUIRE(rows_of(same.polygons) == rows_of(right.polygons));
        ++accepted;

        const int32_t E = ref.edges();
        const int32_t polygon_cells = static_cast<int32_t>(right.polygons.cells.size());
        const int32_t cell = static_cast<int32_t>(rng() % (4 * E + polygon_cells));
        EdgeListAnswer wrong = right;
        if (cell < 4 * E) {
            const int32_t row = cell / 4, column = cell % 4;
            const int32_t old = right.edges[cell];
            const int32_t range = column < 2 ? f.vertices : f.count();
            const int32_t value = corrupt(old, range, rng);
            wrong.edges[cell] = value;
            const TableAnswerCheck c = check_edge_list_answer(f.offsets, f.corners, f.vertices, wrong);
            INFO("row " << row << " column " << column << " " << old << " -> " << value << "\n" << describe(c.findings));
            REQUIRE(c.findings.size() == 1);
            const AnswerFinding& x = c.findings[0];
            CHECK(x.table == MeshTable::Edge);
            const char* fields[4] = {"v1", "v2", "p1", "p2"};
            const int32_t other_end = column < 2 ? right.edges[4 * row + 1 - column] : kNone;
            const bool pair_is_edge = column < 2 && value >= 0 && value < f.vertices && value != other_end &&
                                      ref.edge_of.count({std::min(value, other_end), std::max(value, other_end)});
            // The row now names the edge of another row: when the two rows give the same P1, P2
            // (so the polygons list both alike), nothing tells which of them was meant for it.
            int32_t twin = kNone;
            if (pair_is_edge) {
                twin = to[ref.edge_of.at({std::min(value, other_end), std::max(value, other_end)})];
                std::vector<int32_t> a = {right.edges[4 * row + 2], right.edges[4 * row + 3]}, b = {right.edges[4 * twin + 2], right.edges[4 * twin + 3]};
                std::sort(a.begin(), a.end());
                std::sort(b.begin(), b.end());
                if (a != b) twin = kNone;
            }
            const int32_t named_row = x.row;
            if (twin != kNone && named_row == twin) {
                ++ambiguous;
                CHECK(x.code == "duplicate-edge");
                CHECK(x.expected == old); // the twin read as the edge the changed row lost
                CHECK(check_edge_list_answer(f.offsets, f.corners, f.vertices, worked_edge_list_answer(f.offsets, f.corners, f.vertices, wrong)).correct());
                ++named;
                continue;
            }
            CHECK(x.row == row);
            if (column < 2) {
                // V1 = V2 after the change: either end may be the wrong one; the finding names one.
                CHECK((x.field == "v1" || x.field == "v2"));
                const int32_t other = other_end;
                if (x.field == fields[column]) {
                    CHECK(x.given == value);
                    CHECK(x.expected == old);
                } else {
                    CHECK(value == other);
                    CHECK(x.expected == old);
                    ++ends_elsewhere;
                }
                CHECK(x.code == code_for(value, range, pair_is_edge ? "duplicate-edge" : "not-an-edge"));
            } else {
                // P1 and P2 are a pair in either order: written equal, either one is the wrong one.
                const int32_t other = right.edges[4 * row + (column == 2 ? 3 : 2)];
                if (value == other) CHECK((x.field == "p1" || x.field == "p2"));
                else CHECK(x.field == fields[column]);
                CHECK(x.given == value);
                CHECK(x.expected == old);
                CHECK(x.code == (value == kBlank ? "blank" : value >= range ? "unknown-label" : "wrong-face"));
            }
            CHECK(x.reason.find("row " + edge_label(row) + ": ") == 0);
            const EdgeListAnswer worked = worked_edge_list_answer(f.offsets, f.corners, f.vertices, wrong);
            CHECK(check_edge_list_answer(f.offsets, f.corners, f.vertices, worked).correct());
            if (x.field == fields[column]) CHECK(worked.edges == right.edges);
        } else {
            const int32_t k = cell - 4 * E;
            const int32_t face = static_cast<int32_t>(std::upper_bound(right.polygons.offsets.begin(), right.polygons.offsets.end(), k) -
                                                      right.polygons.offsets.begin()) - 1;
            const int32_t i = k - right.polygons.offsets[face];
            const int32_t old = right.polygons.cells[k], value = corrupt(old, E, rng);
            wrong.polygons.cells[k] = value;
            const TableAnswerCheck c = check_edge_list_answer(f.offsets, f.corners, f.vertices, wrong);
            INFO("polygon " << face << " item " << i << " " << old << " -> " << value << "\n" << describe(c.findings));
            REQUIRE(c.findings.size() == 1);
            const AnswerFinding& x = c.findings[0];
            CHECK(x.table == MeshTable::Face);
            CHECK(x.row == face);
            CHECK(x.field == "edges");
            // A side written twice: the list is a set, so either copy may be named.
            const auto row_cells = rows_of(wrong.polygons)[face];
            if (std::count(row_cells.begin(), row_cells.end(), value) > 1) CHECK(row_cells[x.index] == value);
            else CHECK(x.index == i);
            CHECK(x.given == value);
            CHECK(x.expected == old);
            CHECK(x.code == code_for(value, E, "not-on-face"));
            CHECK(x.reason.find("polygon " + face_label(face) + ", item " + std::to_string(x.index + 1) + ": ") == 0);
            // The worked polygons: the row restored (in the order written, the copy named replaced).
            auto worked_rows = rows_of(worked_edge_list_answer(f.offsets, f.corners, f.vertices, wrong).polygons);
            auto right_rows = rows_of(right.polygons);
            if (std::count(row_cells.begin(), row_cells.end(), value) > 1) {
                std::sort(worked_rows[face].begin(), worked_rows[face].end());
                std::sort(right_rows[face].begin(), right_rows[face].end());
            }
            CHECK(worked_rows == right_rows);
        }
        ++named;
    }
    CHECK(accepted == 4000);
    CHECK(named == 4000);
    CHECK(ends_elsewhere > 0);
    CHECK(ambiguous < 100); // rare: two boundary edges of one polygon at one vertex
}

TEST_CASE("edge lists: a missing row and lambda on either side", "[mesh][exercise]") {
    const Faces foley = faces_of(foley_example().mesh);
    EdgeListAnswer e;
    e.edges = {0, 1, kNone, 0, 1, 2, 1, kNone, 2, 3, kNone, 1, 3, 1, 1, 0, 3, 0, 0, kNone};
    e.polygons = list_answer({{0, 3, 4}, {1, 2, 3}});
    CHECK(check_edge_list_answer(foley.offsets, foley.corners, foley.vertices, e).correct());
    // Without E3 (the rows after it move up): the edge V3-V4 has no row, and P2 does not list it.
    EdgeListAnswer missing;
    missing.edges = {0, 1, 0, kNone, 1, 2, 1, kNone, 3, 1, 0, 1, 3, 0, 0, kNone};
    missing.polygons = list_answer({{0, 2, 3}, {1, 2}});
    const TableAnswerCheck c = check_edge_list_answer(foley.offsets, foley.corners, foley.vertices, missing);
    INFO(describe(c.findings));
    REQUIRE(c.findings.size() == 2);
    CHECK(c.findings[0].code == "missing-edge");
    CHECK(c.findings[0].expected == 4); // the worked answer gives it the next number, e5
    CHECK(c.findings[0].reason.find("v3-v4") != std::string::npos);
    CHECK(c.findings[1].code == "missing-edge");
    CHECK(c.findings[1].table == MeshTable::Face);
    CHECK(c.findings[1].row == 1);
    CHECK(c.findings[1].expected == 4);
}

TEST_CASE("adjacency lists: any order accepted; one corrupted neighbour named with the one expected", "[mesh][exercise][property]") {
    const auto meshes = fixtures();
    std::mt19937 rng(1902);
    int accepted = 0, named = 0, removed = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Faces f = faces_of(meshes[trial % meshes.size()]);
        const Ref ref(f);
        std::vector<std::vector<int32_t>> rows;
        for (int32_t v = 0; v < f.vertices; ++v) {
            std::vector<int32_t> n(ref.neighbours[v].begin(), ref.neighbours[v].end());
            std::shuffle(n.begin(), n.end(), rng);
            rows.push_back(n);
        }
        const ListAnswer right = list_answer(rows);
        const TableAnswerCheck ok = check_adjacency_answer(f.offsets, f.corners, f.vertices, right);
        INFO("trial " << trial << "\n" << describe(ok.findings));
        REQUIRE(ok.correct());
        REQUIRE(rows_of(worked_adjacency_answer(f.offsets, f.corners, f.vertices, right)) == rows);
        ++accepted;
        const int32_t v = static_cast<int32_t>(rng() % f.vertices);
        if (rows[v].empty()) continue;
        const int32_t i = static_cast<int32_t>(rng() % rows[v].size());
        auto wrong = rows;
        const int32_t old = rows[v][i], value = corrupt(old, f.vertices, rng);
        wrong[v][i] = value;
        const TableAnswerCheck c = check_adjacency_answer(f.offsets, f.corners, f.vertices, list_answer(wrong));
        INFO("vertex " << v << " item " << i << " " << old << " -> " << value << "\n" << describe(c.findings));
        REQUIRE(c.findings.size() == 1);
        const AnswerFinding& x = c.findings[0];
        CHECK(x.table == MeshTable::Vertex);
        CHECK(x.row == v);
        CHECK(x.field == "vertices");
        if (std::count(wrong[v].begin(), wrong[v].end(), value) > 1) CHECK(wrong[v][x.index] == value); // either copy
        else CHECK(x.index == i);
        CHECK(x.given == value);
        CHECK(x.expected == old);
        CHECK(x.code == code_for(value, f.vertices, "not-adjacent"));
        CHECK(x.reason.find("vertex " + vertex_label(v) + ", item " + std::to_string(x.index + 1) + ": ") == 0);
        auto worked_rows = rows_of(worked_adjacency_answer(f.offsets, f.corners, f.vertices, list_answer(wrong)));
        auto right_rows = rows;
        if (std::count(wrong[v].begin(), wrong[v].end(), value) > 1) {
            std::sort(worked_rows[v].begin(), worked_rows[v].end());
            std::sort(right_rows[v].begin(), right_rows[v].end());
        }
        CHECK(worked_rows == right_rows);
        ++named;
        // A neighbour left out: missing-vertex, expecting it.
        auto shorter = rows;
        shorter[v].erase(shorter[v].begin() + i);
        const TableAnswerCheck m = check_adjacency_answer(f.offsets, f.corners, f.vertices, list_answer(shorter));
        REQUIRE(m.findings.size() == 1);
        CHECK(m.findings[0].code == "missing-vertex");
        CHECK(m.findings[0].expected == old);
        CHECK(m.findings[0].index == kNone);
        ++removed;
    }
    CHECK(accepted == 3000);
    CHECK(named > 2500);
    CHECK(removed == named);
}

TEST_CASE("malformed table answers are invalid-answer errors naming the row", "[mesh][exercise]") {
    const Faces lecture = faces_of(lecture_example().mesh);
    const auto code_of = [](auto&& call) -> std::string {
        try {
            call();
        } catch (const wingspline::Error& e) {
            return e.code() + ": " + e.what();
        }
        return "";
    };
    CHECK(code_of([&] { check_faces_answer(lecture.offsets, lecture.corners, lecture.vertices, list_answer({{0, 1, 2}, {1, 3, 2}})); })
              .find("invalid-answer: the face table has 2 rows; the mesh has 3") == 0);
    CHECK(code_of([&] { check_faces_answer(lecture.offsets, lecture.corners, lecture.vertices, list_answer({{0, 1, 2}, {1, -3, 2}, {1, 4, 3}})); })
              .find("invalid-answer: the face table, F2, item 2 holds -3") == 0);
    CHECK(code_of([&] { check_adjacency_answer(lecture.offsets, lecture.corners, lecture.vertices, ListAnswer{{0, 1}, {1}}); })
              .find("invalid-answer: the adjacency list has 1 rows") == 0);
    EdgeListAnswer e;
    e.edges = {0, 1, 0};
    e.polygons = list_answer({{}, {}, {}});
    CHECK(code_of([&] { check_edge_list_answer(lecture.offsets, lecture.corners, lecture.vertices, e); }).find("invalid-answer: the edge list has 3 cells") == 0);
    e.edges = {0, 1, 0, -5};
    CHECK(code_of([&] { check_edge_list_answer(lecture.offsets, lecture.corners, lecture.vertices, e); }).find("invalid-answer: row e1, p2 holds -5") == 0);
    CHECK(code_of([&] { check_faces_answer({0, 3}, {0, 1}, 3, list_answer({{0, 1}})); }).find("invalid-faces") == 0);
}

// ------------------------------------------------------------------ kind 2: the walk
TEST_CASE("the walk around v2 on the slide: e6, e5, e3, e2, back to e6", "[mesh][exercise][walk]") {
    const NamedMesh n = lecture_example();
    const WingedEdgeMesh mesh = WingedEdgeMesh::build(n.mesh, n.options);
    // Read off the slide: v2's edge is e6; v2 is the Start of e6, e5 and e3 (S:L: e5, e3, e2)
    // and the End of e2 (E:R: e6).
    const int32_t walk[5] = {5, 4, 2, 1, 5};
    for (int32_t k = 1; k <= 4; ++k) {
        const WalkStepCheck c = check_walk_step(mesh, false, 1, k, walk[k]);
        CHECK(c.correct);
        CHECK(c.expected == walk[k]);
        CHECK(c.done == (k == 4));
    }
    const WalkStepCheck right = check_walk_step(mesh, false, 1, 1, 4);
    CHECK(right.reason == "e5: v2 is the Start of e6, so the CCW walk around v2 reads its S:L column, e5");
    const WalkStepCheck wrong = check_walk_step(mesh, false, 1, 4, 3);
    CHECK(!wrong.correct);
    CHECK(wrong.reason == "not e4: v2 is the End of e2, so the CCW walk around v2 reads its E:R column, which is e6; that is the first edge "
                          "again, so the walk is closed");
    // Along F2 from its table's edge e3: F2 is the Right face of e3 (S:R = e5), then the Left of e5 (E:L = e4).
    const WalkStepCheck face = check_walk_step(mesh, true, 1, 1, 4);
    CHECK(face.correct);
    CHECK(face.reason == "e5: F2 is the Right face of e3, so the walk along F2 reads its S:R column, e5");
    CHECK(check_walk_step(mesh, true, 1, 2, 3).correct);
}

TEST_CASE("every step of every walk: the rule's edge accepted, every other edge refused with it", "[mesh][exercise][walk][property]") {
    int steps = 0, refusals = 0;
    for (const IndexedMesh& m : fixtures()) {
        const Faces f = faces_of(m);
        const Ref ref(f);
        const WingedEdgeMesh mesh = WingedEdgeMesh::build(m);
        // The core's edge numbers -> the reference's, by vertex pair.
        std::vector<int32_t> to_ref(mesh.edge_count()), to_core(ref.edges());
        for (int32_t e = 0; e < mesh.edge_count(); ++e) {
            const int32_t a = mesh.edge(e).start, b = mesh.edge(e).end;
            to_ref[e] = ref.edge_of.at({std::min(a, b), std::max(a, b)});
            to_core[to_ref[e]] = e;
        }
        for (int around_face = 0; around_face < 2; ++around_face) {
            const int32_t count = around_face ? f.count() : f.vertices;
            for (int32_t x = 0; x < count; ++x) {
                // The walk from the table's edge, by the definition: around v, from the edge
                // v-w, the other edge at v of the face running v -> w (the boundary as a face);
                // along f, the side after it in corner order.
                std::vector<int32_t> walk = {to_ref[around_face ? mesh.face_edge(x) : mesh.vertex_edge(x)]};
                while (true) {
                    const int32_t e = walk.back();
                    int32_t next;
                    if (around_face) {
                        const auto& s = ref.sides[x];
                        next = s[(std::find(s.begin(), s.end(), e) - s.begin() + 1) % s.size()];
                    } else {
                        const int32_t w = ref.pairs[e].first == x ? ref.pairs[e].second : ref.pairs[e].first;
                        next = ref.other_edge_at(x, ref.running(x, w), e);
                    }
                    walk.push_back(next);
                    if (next == walk.front() || walk.size() > 64) break;
                }
                REQUIRE(walk.back() == walk.front());
                const int32_t n = static_cast<int32_t>(walk.size()) - 1;
                for (int32_t k = 1; k <= n; ++k) {
                    const int32_t want = to_core[walk[k]];
                    const WalkStepCheck ok = check_walk_step(mesh, around_face, x, k, want);
                    INFO((around_face ? "face " : "vertex ") << x << " step " << k << ": " << ok.reason);
                    REQUIRE(ok.correct);
                    CHECK(ok.done == (k == n));
                    CHECK(ok.reason.find(edge_label(want) + ": ") == 0);
                    ++steps;
                    for (int32_t g = -2; g <= mesh.edge_count(); ++g) {
                        if (g == want) continue;
                        const WalkStepCheck no = check_walk_step(mesh, around_face, x, k, g);
                        CHECK(!no.correct);
                        CHECK(no.expected == want);
                        CHECK(no.reason.find(", which is " + edge_label(want)) != std::string::npos);
                        ++refusals;
                    }
                }
                CHECK_THROWS_WITH(check_walk_step(mesh, around_face, x, n + 1, 0), Catch::Contains("closes it"));
                CHECK_THROWS_WITH(check_walk_step(mesh, around_face, x, 0, 0), Catch::Contains("a step is 1 to"));
            }
        }
    }
    CHECK(steps > 1000);
    CHECK(refusals > 10000);
}

TEST_CASE("walk errors: no such vertex or face, a vertex with no edge", "[mesh][exercise][walk]") {
    IndexedMesh m = tetrahedron();
    m.positions.insert(m.positions.end(), {5.0, 5.0, 5.0}); // v5 on no face
    const WingedEdgeMesh mesh = WingedEdgeMesh::build(m);
    const auto code_of = [&](bool face, int32_t x) -> std::string {
        try {
            check_walk_step(mesh, face, x, 1, 0);
        } catch (const wingspline::Error& e) {
            return e.code();
        }
        return "";
    };
    CHECK(code_of(false, 4) == "no-walk");
    CHECK(code_of(false, 5) == "index-out-of-range");
    CHECK(code_of(true, 4) == "index-out-of-range");
    CHECK(code_of(true, -1) == "index-out-of-range");
}

TEST_CASE("a reason stays a sentence on a large exercise: a hub's long list is cut", "[mesh][exercise]") {
    const Faces fan = faces_of(open_fan(40)); // vertex 0 has 41 neighbours
    std::vector<std::vector<int32_t>> rows(fan.vertices);
    const TableAnswerCheck c = check_adjacency_answer(fan.offsets, fan.corners, fan.vertices, list_answer(rows));
    const AnswerFinding& hub = c.findings.front();
    REQUIRE(hub.row == 0);
    CHECK(hub.code == "missing-vertex");
    CHECK(hub.reason.find("... (41 in all)") != std::string::npos);
    CHECK(hub.reason.size() < 300);
}
