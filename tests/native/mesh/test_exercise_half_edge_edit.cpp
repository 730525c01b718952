// The edit exercise in half-edge terms (exercise_half_edge_edit.h): flip e3 on the lecture mesh
// worked by hand, and on random edits of every fixture the worked answer accepted and every
// one-cell corruption named at its cell.
#include <catch2/catch.hpp>

#include "random_edits.h"

#include "wingspline/mesh/exercise_half_edge_edit.h"
#include "wingspline/mesh/half_edge.h"

#include <random>
#include <set>

using namespace wingspline::mesh;
using namespace wingspline::test_edits;

namespace {
constexpr int kV = static_cast<int>(MeshTable::Vertex);
constexpr int kH = static_cast<int>(MeshTable::Edge);
constexpr int kF = static_cast<int>(MeshTable::Face);

int32_t h(int k) { return k - 1; } // the page's h1 is row 0
int32_t v(int k) { return k - 1; }
int32_t f(int k) { return k - 1; }
} // namespace

// Flip e3 by hand (tests/helpers/lecture-slide.mjs FLIP_E3: e3 becomes v4 -> v1 with L = F1,
// R = F2; F1 = v1 v2 v4, F2 = v3 v1 v4, F3 and the boundary loop untouched). Half-edges after,
// eₖ giving h₂ₖ₋₁ = S -> E (on L) and h₂ₖ = E -> S (on R):
//   F1: h3 (v1 -> v2), h9 (v2 -> v4), h5 (v4 -> v1);   F2: h2 (v3 -> v1), h6 (v1 -> v4), h8 (v4 -> v3).
// Before (test_half_edge.cpp's slide rows): h2 v3 v1 F1 next h3 prev h5; h3 v1 v2 F1 h5 h2;
// h5 v2 v3 F1 h2 h3; h6 v3 v2 F2 h9 h8; h8 v4 v3 F2 h6 h9; h9 v2 v4 F2 h8 h6. All six change;
// h1 h4 h7 h10..h14 do not. Every vertex is on the boundary and keeps its boundary half-edge;
// F1's half-edge was h2 (e1's, now on F2): it becomes e3's on F1, h5; F2 keeps h6.
TEST_CASE("half-edge edit exercise: flip e3 on the lecture mesh, worked by hand", "[mesh][exercise][half-edge]") {
    const WingedEdgeMesh before = lecture();
    const Operation op = operation("flip-edge", Edge(2));
    const HalfEdgeEditQuestion q = half_edge_edit_question(before, op);
    CHECK(q.operation == "flip e3");
    CHECK(q.rows[kH] == std::vector<int32_t>{h(2), h(3), h(5), h(6), h(8), h(9)});
    CHECK(q.rows[kV].empty());
    CHECK(q.rows[kF] == std::vector<int32_t>{f(1)});
    CHECK(q.before_count == std::array<int32_t, 3>{5, 14, 3});

    // origin face next prev, per asked row, by hand above.
    EditAnswer a;
    a.tables[kH].cells = {v(3), f(2), h(6), h(8),   // h2
                          v(1), f(1), h(9), h(5),   // h3
                          v(4), f(1), h(3), h(9),   // h5
                          v(1), f(2), h(8), h(2),   // h6
                          v(4), f(2), h(2), h(6),   // h8
                          v(2), f(1), h(5), h(3)};  // h9
    a.tables[kH].removed.assign(6, 0);
    a.tables[kF].cells = {h(9)}; // any half-edge of F1 after: h9 as well as h5
    a.tables[kF].removed.assign(1, 0);
    CHECK(check_half_edge_edit_answer(before, op, a).correct());
    const EditAnswer worked = worked_half_edge_edit_answer(before, op);
    std::vector<int32_t> expected = a.tables[kH].cells;
    CHECK(worked.tables[kH].cells == expected);

    // h8's next written as h6 (its before value): one finding at row h8, column next, without the value.
    a.tables[kH].cells[4 * 4 + 2] = h(6);
    const EditCheck wrong = check_half_edge_edit_answer(before, op, a);
    REQUIRE(wrong.findings.size() == 1);
    CHECK(wrong.findings[0].table == MeshTable::Edge);
    CHECK(wrong.findings[0].row == h(8));
    CHECK(wrong.findings[0].field == "next");
    CHECK(wrong.findings[0].code == "wrong-next");
    CHECK(wrong.findings[0].reason.find("Row h8, column next") == 0);
    CHECK(wrong.findings[0].reason.find("h2") == std::string::npos);
    // F1 given h2, a half-edge of F2 now: not on the face.
    a.tables[kH].cells[4 * 4 + 2] = h(2);
    a.tables[kF].cells = {h(2)};
    const EditCheck face = check_half_edge_edit_answer(before, op, a);
    REQUIRE(face.findings.size() == 1);
    CHECK(face.findings[0].code == "not-on-face");
    // h5 marked removed: e3 stays.
    a.tables[kF].cells = {h(5)};
    a.tables[kH].removed[2] = 1;
    const EditCheck kept = check_half_edge_edit_answer(before, op, a);
    REQUIRE(kept.findings.size() == 1);
    CHECK(kept.findings[0].code == "kept");
    // An answer of the wrong shape is refused.
    a.tables[kH].cells.pop_back();
    CHECK_THROWS_AS(check_half_edge_edit_answer(before, op, a), wingspline::Error);
}

TEST_CASE("half-edge edit exercise: on random edits the worked answer is right and each one-cell corruption is named there", "[mesh][exercise][half-edge]") {
    std::size_t questions = 0, corruptions = 0;
    for (uint32_t seed = 1; seed <= 40; ++seed) {
        std::vector<Fixture> all = fixtures();
        WingedEdgeMesh& w = all[seed % all.size()].mesh;
        std::mt19937 rng(seed);
        for (int round = 0; round < 30; ++round) {
            const Operation op = operation_of(random_call(w, rng));
            if (!w.check(op).ok) continue;
            INFO("seed " << seed << " round " << round << " " << op.entry->name);
            const HalfEdgeEditQuestion q = half_edge_edit_question(w, op);
            const EditAnswer right = worked_half_edge_edit_answer(w, op);
            REQUIRE(check_half_edge_edit_answer(w, op, right).correct());
            ++questions;
            // The rows asked are exactly those the view changes: a fresh view after the edit
            // differs from the one before at these rows and nowhere else.
            WingedEdgeMesh after = w;
            after.apply(op);
            const HalfEdgeMesh hb = HalfEdgeMesh::build(w), ha = HalfEdgeMesh::build(after);
            std::set<int32_t> asked(q.rows[kH].begin(), q.rows[kH].end());
            for (int32_t x = 0; x < ha.halfedge_count(); ++x) {
                const bool same = x < hb.halfedge_count() && hb.origin(x) == ha.origin(x) && hb.face(x) == ha.face(x) &&
                                  hb.next(x) == ha.next(x) && hb.prev(x) == ha.prev(x);
                CHECK(asked.count(x) == (same ? 0u : 1u));
            }
            // Every half-edge cell of a kept row, one at a time, set to another value.
            for (std::size_t r = 0; r < q.rows[kH].size(); ++r) {
                if (right.tables[kH].removed[r]) continue;
                for (int k = 0; k < 4; ++k) {
                    EditAnswer bad = right;
                    int32_t& cell = bad.tables[kH].cells[4 * r + k];
                    cell = cell == kNone ? 0 : cell + 1 < (k == 0 ? ha.vertex_count() : k == 1 ? ha.face_count() : ha.halfedge_count()) ? cell + 1 : kNone;
                    const EditCheck c = check_half_edge_edit_answer(w, op, bad);
                    REQUIRE(c.findings.size() == 1);
                    CHECK(c.findings[0].row == q.rows[kH][r]);
                    CHECK(c.findings[0].index == static_cast<int32_t>(r));
                    ++corruptions;
                }
            }
            w.apply(op);
        }
    }
    INFO(questions << " questions, " << corruptions << " corruptions");
    CHECK(questions >= 500);
    CHECK(corruptions >= 5000);
}
