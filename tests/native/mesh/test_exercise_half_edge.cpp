// The half-edge exercises (exercise_half_edge.h): the table check against lecture 000's
// half-edge table written out by hand, and against tables made here from the faces alone (a
// half-edge = a corner pair a -> b of a face or of the boundary loop; its face the one running
// a -> b; next the following side of that face or the boundary leaving b), renumbered at
// random; and the half-edge walk against the walk rules applied to those tables.
#include <catch2/catch.hpp>

#include "exercise_fixtures.h"

#include "wingspline/error.h"
#include "wingspline/mesh/exercise_half_edge.h"
#include "wingspline/mesh/generators.h"

#include <algorithm>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace wingspline::mesh;

namespace {

// The half-edge structure of a face set, from its faces alone (never from the core's view):
// half-edges numbered in the order first met, a free numbering the tests then permute.
struct Ref {
    int32_t V = 0, F = 0;
    std::vector<std::pair<int32_t, int32_t>> he; // (origin, target)
    std::vector<int32_t> face, next, prev, twin;
    std::map<std::pair<int32_t, int32_t>, int32_t> of; // (a, b) -> half-edge

    explicit Ref(const IndexedMesh& m) : V(m.vertex_count()), F(static_cast<int32_t>(m.face_offsets.size()) - 1) {
        std::map<std::pair<int32_t, int32_t>, int32_t> runs;
        auto add = [&](int32_t a, int32_t b) {
            if (of.count({a, b})) return;
            of[{a, b}] = static_cast<int32_t>(he.size());
            he.push_back({a, b});
        };
        for (int32_t f = 0; f < F; ++f)
            for (int32_t i = m.face_offsets[f]; i < m.face_offsets[f + 1]; ++i) {
                const int32_t a = m.face_vertices[i];
                const int32_t b = m.face_vertices[i + 1 < m.face_offsets[f + 1] ? i + 1 : m.face_offsets[f]];
                runs[{a, b}] = f;
                add(a, b);
                add(b, a);
            }
        const int32_t n = static_cast<int32_t>(he.size());
        face.assign(n, kNone), next.assign(n, kNone), prev.assign(n, kNone), twin.assign(n, kNone);
        std::map<int32_t, int32_t> boundary_leaving; // vertex -> its outgoing boundary half-edge
        for (int32_t h = 0; h < n; ++h) {
            const auto it = runs.find(he[h]);
            face[h] = it == runs.end() ? kNone : it->second;
            twin[h] = of.at({he[h].second, he[h].first});
            if (face[h] == kNone) boundary_leaving[he[h].first] = h;
        }
        for (int32_t f = 0; f < F; ++f) {
            const int32_t first = m.face_offsets[f], last = m.face_offsets[f + 1];
            for (int32_t i = first; i < last; ++i) {
                const int32_t a = m.face_vertices[i], b = m.face_vertices[i + 1 < last ? i + 1 : first];
                const int32_t c = m.face_vertices[i + 2 < last ? i + 2 : first + (i + 2 - last)];
                next[of.at({a, b})] = of.at({b, c});
            }
        }
        for (int32_t h = 0; h < n; ++h)
            if (face[h] == kNone) next[h] = boundary_leaving.at(he[h].second);
        for (int32_t h = 0; h < n; ++h) prev[next[h]] = h;
    }
    int32_t count() const { return static_cast<int32_t>(he.size()); }
    bool on_boundary(int32_t v) const {
        for (int32_t h = 0; h < count(); ++h)
            if (he[h].first == v && face[h] == kNone) return true;
        return false;
    }
    // Right for vertex v's cell: leaves v, and is a boundary one when v is on the boundary.
    bool vertex_ok(int32_t v, int32_t h) const { return he[h].first == v && (!on_boundary(v) || face[h] == kNone); }
};

// A right answer under a numbering: row r is the half-edge perm[r]; each vertex and face takes
// a right half-edge chosen with `rng`.
HalfEdgeAnswer answer_of(const Ref& ref, const std::vector<int32_t>& perm, std::mt19937& rng) {
    const int32_t n = ref.count();
    std::vector<int32_t> row(n);
    for (int32_t r = 0; r < n; ++r) row[perm[r]] = r;
    HalfEdgeAnswer a;
    for (int32_t r = 0; r < n; ++r) {
        const int32_t h = perm[r];
        for (int32_t x : {ref.he[h].first, ref.face[h], row[ref.next[h]], row[ref.prev[h]], row[ref.twin[h]]}) a.halfedges.push_back(x);
    }
    for (int32_t v = 0; v < ref.V; ++v) {
        std::vector<int32_t> ok;
        for (int32_t h = 0; h < n; ++h)
            if (ref.vertex_ok(v, h)) ok.push_back(row[h]);
        a.vertex_halfedges.push_back(ok.empty() ? kNone : ok[std::uniform_int_distribution<std::size_t>(0, ok.size() - 1)(rng)]);
    }
    for (int32_t f = 0; f < ref.F; ++f) {
        std::vector<int32_t> ok;
        for (int32_t h = 0; h < n; ++h)
            if (ref.face[h] == f) ok.push_back(row[h]);
        a.face_halfedges.push_back(ok[std::uniform_int_distribution<std::size_t>(0, ok.size() - 1)(rng)]);
    }
    return a;
}

HalfEdgeTableResult mark(const IndexedMesh& m, const HalfEdgeAnswer& a) {
    return mark_half_edge_answer(m.face_offsets, m.face_vertices, m.vertex_count(), a);
}

std::vector<IndexedMesh> fixtures() { return wingspline::test_exercises::exercise_fixtures(); }

// Random meshes for the property tests: grids, fans and spheres of random sizes, or a fixture.
IndexedMesh random_mesh(std::mt19937& rng) {
    const int pick = std::uniform_int_distribution<int>(0, 3)(rng);
    if (pick == 0) return grid(std::uniform_int_distribution<int>(1, 5)(rng), std::uniform_int_distribution<int>(1, 4)(rng));
    if (pick == 1) return open_fan(std::uniform_int_distribution<int>(1, 8)(rng));
    if (pick == 2) return uv_sphere(std::uniform_int_distribution<int>(3, 6)(rng), std::uniform_int_distribution<int>(2, 4)(rng));
    static const std::vector<IndexedMesh> fixed = fixtures();
    return fixed[std::uniform_int_distribution<std::size_t>(0, fixed.size() - 1)(rng)];
}

std::vector<int32_t> shuffled(int32_t n, std::mt19937& rng) {
    std::vector<int32_t> p(n);
    for (int32_t i = 0; i < n; ++i) p[i] = i;
    std::shuffle(p.begin(), p.end(), rng);
    return p;
}

const char* const kColumns[] = {"origin", "face", "next", "prev", "twin"};

// Every "h<number>" in a text.
std::set<std::string> half_edge_labels_in(const std::string& text) {
    std::set<std::string> out;
    const std::regex label("\\bh[0-9]+\\b");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), label); it != std::sregex_iterator(); ++it) out.insert(it->str());
    return out;
}

// lecture 000's mesh with the slide's numbering, its half-edge table by hand (e_k gives
// h(2k-1) = S -> E and h(2k) = E -> S; test_half_edge.cpp works the same rows out from the
// slide's winged edge):
//        v3 ------- v4
//       /  \  F2  /  \        F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4);
//     v1 F1 \    / F3 v5      the boundary loop v1 -> v3 -> v4 -> v5 -> v2 -> v1
//       \    \  /   /         is h1, h7, h13, h12, h4.
//        ---- v2 ---
// Columns origin face next prev twin, 1-based as the page writes them (0: none).
const int32_t kLectureTable[14][5] = {
    {1, 0, 7, 4, 2},    {3, 1, 3, 5, 1},    {1, 1, 5, 2, 4},    {2, 0, 1, 12, 3},   {2, 1, 2, 3, 6},
    {3, 2, 9, 8, 5},    {3, 0, 13, 1, 8},   {4, 2, 6, 9, 7},    {2, 2, 8, 6, 10},   {4, 3, 11, 14, 9},
    {2, 3, 14, 10, 12}, {5, 0, 4, 13, 11},  {4, 0, 12, 7, 14},  {5, 3, 10, 11, 13},
};

HalfEdgeAnswer lecture_answer() {
    HalfEdgeAnswer a;
    for (const auto& row : kLectureTable)
        for (int32_t x : row) a.halfedges.push_back(x - 1); // 0 (none) -> kNone
    a.vertex_halfedges = {0, 3, 6, 12, 11}; // h1 h4 h7 h13 h12: each vertex's boundary half-edge
    a.face_halfedges = {1, 5, 9};           // h2 h6 h10
    return a;
}

} // namespace

TEST_CASE("half-edge table: lecture 000's table by hand is right, renumbered too; a wrong cell is named", "[mesh][exercise][half-edge]") {
    const NamedMesh lecture = lecture_example();
    const IndexedMesh& m = lecture.mesh;
    const HalfEdgeAnswer a = lecture_answer();
    const HalfEdgeTableResult r = mark(m, a);
    INFO((r.check.findings.empty() ? std::string() : r.check.findings[0].reason));
    REQUIRE(r.check.correct());
    CHECK(r.worked.halfedges == a.halfedges);

    // The slide's numbering with the twin pairs apart: swap rows h2 and h9 (every reference too).
    HalfEdgeAnswer b = a;
    auto swap_label = [](int32_t x) { return x == 1 ? 8 : x == 8 ? 1 : x; };
    for (int k = 0; k < 5; ++k) std::swap(b.halfedges[5 * 1 + k], b.halfedges[5 * 8 + k]);
    for (std::size_t i = 0; i < b.halfedges.size(); ++i)
        if (i % 5 >= 2) b.halfedges[i] = swap_label(b.halfedges[i]);
    for (int32_t& x : b.face_halfedges) x = swap_label(x);
    CHECK(mark(m, b).check.correct());

    // Any outgoing half-edge of an interior vertex would do, but every vertex here is on the
    // boundary: v2 storing h5 (v2 -> v3 on F1) is not its boundary half-edge.
    HalfEdgeAnswer c = a;
    c.vertex_halfedges[1] = 4;
    const HalfEdgeTableResult rc = mark(m, c);
    REQUIRE(rc.check.findings.size() == 1);
    CHECK(rc.check.findings[0].code == "not-boundary");
    CHECK(rc.check.findings[0].table == MeshTable::Vertex);
    CHECK(rc.check.findings[0].row == 1);

    // Row h5 (v2 -> v3 on F1), column next: h6 (v3 -> v2) instead of h2 (v3 -> v1).
    HalfEdgeAnswer d = a;
    d.halfedges[5 * 4 + 2] = 5;
    const HalfEdgeTableResult rd = mark(m, d);
    REQUIRE(rd.check.findings.size() == 1);
    const AnswerFinding& f = rd.check.findings[0];
    CHECK(f.code == "wrong-next");
    CHECK(f.row == 4);
    CHECK(f.field == "next");
    CHECK(f.expected == 1);
    // The student's own table says where h5 ends (its twin h6 starts at v3) and its face F1.
    CHECK(f.message == "Row h5, column next: this is not next(h5). Re-read: next(h) must start where h ends (v3), and lie on the "
                       "same face (F1): the next side counter-clockwise round that face, the boundary loop counting as a face.");
    CHECK(half_edge_labels_in(f.message) == std::set<std::string>{"h5"});
    CHECK(f.reason.find("h2") != std::string::npos);

    // The slide's face table names e1 for F1, whose L is not F1: its h1 is not on F1.
    HalfEdgeAnswer e = a;
    e.face_halfedges[0] = 0;
    // With the slide's numbering, the worked answer puts in the face's own half-edge: the side
    // of e1 along F1, h2.
    const HalfEdgeTableResult re = mark_half_edge_answer(m.face_offsets, m.face_vertices, m.vertex_count(), e, lecture.options);
    REQUIRE(re.check.findings.size() == 1);
    CHECK(re.check.findings[0].code == "not-on-face");
    CHECK(re.worked.face_halfedges[0] == 1);
}

TEST_CASE("half-edge table: thousands of random renumberings are right; every one-cell change is one finding there", "[mesh][exercise][half-edge]") {
    std::mt19937 rng(20261128);
    int accepted = 0, corrupted = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const IndexedMesh m = random_mesh(rng);
        const Ref ref(m);
        const int32_t n = ref.count();
        const std::vector<int32_t> perm = shuffled(n, rng);
        std::vector<int32_t> row(n);
        for (int32_t r = 0; r < n; ++r) row[perm[r]] = r;
        const HalfEdgeAnswer a = answer_of(ref, perm, rng);
        const HalfEdgeTableResult ok = mark(m, a);
        INFO("trial " << trial << (ok.check.findings.empty() ? std::string() : ": " + ok.check.findings[0].reason));
        REQUIRE(ok.check.correct());
        REQUIRE(ok.worked.halfedges == a.halfedges);
        ++accepted;

        // One cell changed to a wrong value (another vertex, face or row, none, blank, a label
        // out of range).
        HalfEdgeAnswer b = a;
        const int32_t cells = 5 * n + ref.V + ref.F;
        const int32_t at = std::uniform_int_distribution<int32_t>(0, cells - 1)(rng);
        const int kind = std::uniform_int_distribution<int>(0, 9)(rng); // 0: blank, 1: out of range, else another value
        int32_t* cell = at < 5 * n ? &b.halfedges[at] : at < 5 * n + ref.V ? &b.vertex_halfedges[at - 5 * n] : &b.face_halfedges[at - 5 * n - ref.V];
        const int32_t column = at < 5 * n ? at % 5 : -1;
        const int32_t range = column == 0 ? ref.V : column == 1 ? ref.F : n; // a face cell also takes none
        const int32_t before = *cell;
        auto wrong = [&](int32_t x) {
            if (x == before) return false;
            if (at >= 5 * n && at < 5 * n + ref.V) return x < 0 || !ref.vertex_ok(at - 5 * n, perm[x]);
            if (at >= 5 * n + ref.V) return x < 0 || ref.face[perm[x]] != at - 5 * n - ref.V;
            return true;
        };
        if (kind == 0) *cell = kBlank;
        else if (kind == 1) *cell = range + 3;
        else {
            std::vector<int32_t> options;
            for (int32_t x = column == 1 ? kNone : 0; x < range; ++x)
                if (wrong(x)) options.push_back(x);
            if (options.empty()) continue;
            *cell = options[std::uniform_int_distribution<std::size_t>(0, options.size() - 1)(rng)];
        }
        const HalfEdgeTableResult bad = mark(m, b);
        INFO("cell " << at << ": " << before << " -> " << *cell);
        for (const AnswerFinding& f : bad.check.findings) INFO(f.reason);
        REQUIRE(bad.check.findings.size() == 1);
        const AnswerFinding& f = bad.check.findings[0];
        if (column >= 0) {
            CHECK(f.table == MeshTable::Edge);
            CHECK(f.row == at / 5);
            CHECK(f.field == kColumns[column]);
            CHECK(f.expected == before); // the right value, in the student's numbering
            // The message holds no half-edge label but the row's own, and no face label for a
            // face cell, no vertex label for an origin cell.
            CHECK(half_edge_labels_in(f.message) == std::set<std::string>{"h" + std::to_string(at / 5 + 1)});
            if (column == 0) CHECK(f.message.find(" (v") == std::string::npos);
            if (column == 1) CHECK(f.message.find("(F") == std::string::npos);
        } else {
            const bool vertex = at < 5 * n + ref.V;
            CHECK(f.table == (vertex ? MeshTable::Vertex : MeshTable::Face));
            CHECK(f.row == (vertex ? at - 5 * n : at - 5 * n - ref.V));
            CHECK(f.field == "halfedge");
            CHECK(half_edge_labels_in(f.message).empty());
        }
        CHECK_FALSE(f.hint.empty());
        // The worked answer puts the cell right and keeps the numbering.
        CHECK(bad.worked.halfedges == (column >= 0 ? a.halfedges : b.halfedges));
        ++corrupted;
    }
    CHECK(accepted == 3000);
    CHECK(corrupted > 2500);
}

TEST_CASE("half-edge table: every cell of every fixture, changed, is found on its row and column", "[mesh][exercise][half-edge]") {
    std::mt19937 rng(31);
    for (const IndexedMesh& m : fixtures()) {
        const Ref ref(m);
        const int32_t n = ref.count();
        const HalfEdgeAnswer a = answer_of(ref, shuffled(n, rng), rng);
        REQUIRE(mark(m, a).check.correct());
        for (int32_t i = 0; i < 5 * n; ++i) {
            HalfEdgeAnswer b = a;
            const int32_t column = i % 5;
            const int32_t range = column == 0 ? ref.V : column == 1 ? ref.F : n;
            // the next value round the column's range (a face cell: none, F1, ...)
            const int32_t lo = column == 1 ? kNone : 0;
            b.halfedges[i] = lo + (b.halfedges[i] - lo + 1) % (range - lo);
            if (b.halfedges[i] == a.halfedges[i]) continue;
            const HalfEdgeTableResult r = mark(m, b);
            INFO("cell " << i << " of " << 5 * n);
            REQUIRE(r.check.findings.size() == 1);
            CHECK(r.check.findings[0].row == i / 5);
            CHECK(r.check.findings[0].field == kColumns[column]);
        }
    }
}

TEST_CASE("half-edge table: the table's shape is checked; blank tables are findings, not errors", "[mesh][exercise][half-edge]") {
    const IndexedMesh m = lecture_example().mesh;
    HalfEdgeAnswer a = lecture_answer();
    a.halfedges.pop_back();
    CHECK_THROWS_WITH(mark(m, a), Catch::Contains("the mesh has 14 half-edges"));
    HalfEdgeAnswer b = lecture_answer();
    b.halfedges[3] = -3;
    CHECK_THROWS_WITH(mark(m, b), Catch::Contains("row h1, prev holds -3"));
    HalfEdgeAnswer blank;
    blank.halfedges.assign(70, kBlank);
    blank.vertex_halfedges.assign(5, kBlank);
    blank.face_halfedges.assign(3, kBlank);
    const HalfEdgeTableResult r = mark(m, blank);
    CHECK(r.check.findings.size() == 70 + 5 + 3);
    for (const AnswerFinding& f : r.check.findings) CHECK(f.code == "blank");
    // The worked answer of a blank table is a right table.
    CHECK(mark(m, r.worked).check.correct());
}

TEST_CASE("half-edge walk: every step of every walk, against the rules applied to the faces", "[mesh][exercise][half-edge]") {
    for (const IndexedMesh& m : fixtures()) {
        const WingedEdgeMesh w = exercise_mesh(m.face_offsets, m.face_vertices, m.vertex_count());
        const Ref ref(m);
        // The core's half-edge h is 2e = S -> E or 2e + 1 = E -> S of winged edge e (half_edge.h's numbering).
        auto ref_of = [&](int32_t h) {
            const EdgeRecord& e = w.edge(h / 2);
            return h % 2 == 0 ? ref.of.at({e.start, e.end}) : ref.of.at({e.end, e.start});
        };
        std::vector<int32_t> core_of(ref.count());
        for (int32_t h = 0; h < 2 * w.edge_count(); ++h) core_of[ref_of(h)] = h;
        for (bool around_face : {false, true}) {
            const int32_t count = around_face ? ref.F : ref.V;
            for (int32_t element = 0; element < count; ++element) {
                const WalkStepCheck first = check_half_edge_walk_step(w, around_face, element, 1, kBlank);
                const int32_t start = ref_of(first.from);
                // The walk starts at the element's own half-edge: on the face; leaving the
                // vertex, its boundary one on the boundary.
                if (around_face) CHECK(ref.face[start] == element);
                else CHECK(ref.vertex_ok(element, start));
                int32_t h = start;
                for (int32_t step = 1;; ++step) {
                    const int32_t want = around_face ? ref.next[h] : ref.twin[ref.prev[h]];
                    const WalkStepCheck right = check_half_edge_walk_step(w, around_face, element, step, core_of[want]);
                    CHECK(right.correct);
                    CHECK(ref_of(right.from) == h);
                    CHECK(right.done == (want == start));
                    for (int32_t g : {kBlank, core_of[h], core_of[ref.twin[want]], 2 * w.edge_count()}) {
                        if (g == core_of[want]) continue;
                        const WalkStepCheck wrong = check_half_edge_walk_step(w, around_face, element, step, g);
                        CHECK_FALSE(wrong.correct);
                        CHECK(half_edge_labels_in(wrong.message) == std::set<std::string>{half_edge_label(core_of[h])});
                        CHECK(wrong.message.find("Step " + std::to_string(step) + ",") == 0);
                    }
                    h = want;
                    if (want == start) {
                        CHECK_THROWS_WITH(check_half_edge_walk_step(w, around_face, element, step + 1, 0), Catch::Contains("a step is 1 to"));
                        break;
                    }
                    REQUIRE(step < 100);
                }
            }
        }
    }
}

TEST_CASE("half-edge walk: lecture 000 around v2 from h4 is h11, h9, h5, back to h4; along F1 from h2 h3, h5, h2", "[mesh][exercise][half-edge]") {
    const NamedMesh lecture = lecture_example();
    const WingedEdgeMesh w = WingedEdgeMesh::build(lecture.mesh, lecture.options);
    const int32_t around_v2[] = {10, 8, 4, 3}; // h11 h9 h5 h4, by hand: twin(prev(h4)) = twin(h12) = h11, ...
    for (int32_t step = 1; step <= 4; ++step) {
        const WalkStepCheck c = check_half_edge_walk_step(w, false, 1, step, around_v2[step - 1]);
        CHECK(c.correct);
        CHECK(c.done == (step == 4));
    }
    CHECK(check_half_edge_walk_step(w, false, 1, 1, 10).from == 3);
    CHECK(check_half_edge_walk_step(w, false, 1, 1, 10).reason ==
          "h11: the CCW walk around v2 goes from h4 to twin(prev(h4)): prev(h4) is h12, and its twin is h11");
    const WalkStepCheck wrong = check_half_edge_walk_step(w, false, 1, 2, 9); // h10, the twin of the right one
    CHECK_FALSE(wrong.correct);
    CHECK(wrong.expected == 8);
    CHECK(wrong.reason.find("not h10") == 0);
    const int32_t along_f1[] = {2, 4, 1}; // h3 h5 h2
    for (int32_t step = 1; step <= 3; ++step) CHECK(check_half_edge_walk_step(w, true, 0, step, along_f1[step - 1]).correct);
    CHECK_THROWS_WITH(check_half_edge_walk_step(w, false, 7, 1, 0), Catch::Contains("v8"));
}
