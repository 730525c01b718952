// What an edit costs each representation (edit_costs.h): reads counted by hand on the
// slide's mesh, writes against the slide's tables, invariants over random edits, and the
// cost against mesh size checked against real counted grids.
#include <catch2/catch.hpp>

#include "mesh/random_edits.h"
#include "wingspline/mesh/edit_costs.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/tables.h"

#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>

using namespace wingspline::mesh;
using wingspline::test_edits::lecture;

namespace {

constexpr int kIF = static_cast<int>(Representation::IndependentFaces);
constexpr int kVF = static_cast<int>(Representation::VertexFaceTables);
constexpr int kAL = static_cast<int>(Representation::AdjacencyLists);
constexpr int kPAL = static_cast<int>(Representation::PartialAdjacencyLists);
constexpr int kEL = static_cast<int>(Representation::EdgeList);
constexpr int kWE = static_cast<int>(Representation::WingedEdge);

// The slide's mesh (lecture 000), as the reasoning below reads it:
//
//            v3 (1,2)
//           /  |  \         e1 = v1 v3, e2 = v1 v2, e3 = v2 v3 (L F1, R F2),
//       e1 / F1|F2 \ e4     e4 = v3 v4, e5 = v2 v4, e6 = v2 v5, e7 = v4 v5
//  (0,1) v1    |e3  v4 (2,1)
//       e2 \   |  / |       F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4)
//           \  | /e5|e7
//            v2 (1,0)
//               \ F3|
//             e6 \  |
//                 v5 (2,-1)

} // namespace

TEST_CASE("flip e3 on the slide's mesh: each representation's reads counted by hand", "[mesh][edit-costs]") {
    WingedEdgeMesh w = lecture();
    const EditCosts c = measure_edit(w, operation("flip-edge", Edge(2)));
    // A flip finds the faces on both sides of e3, then the sides of each (Locate::EdgeSides).
    // Winged edge: e3's L and R (2); per face its edge (1) and per side the edge's L, to know
    // which way it runs, and the next wing (2 x 3): 2 + 7 + 7.
    CHECK(c[kWE].reads == 16);
    // Vertex and face tables: no way back from an edge to its faces, so all F = 3 faces are
    // scanned: F + 1 = 4 offsets, per face the first corner and the next ones until the pair
    // v2 v3 appears (F1 = v1 v2 v3: 3 reads; F2 = v2 v4 v3, found at the wrap v3 -> v2 which
    // reads nothing new: 3; F3: 3) = 13. Then the sides of F1 and F2: 2 offsets + 3 corners: 10.
    CHECK(c[kVF].reads == 23);
    // Independent faces: the same scan, comparing each corner with v2 = (1,0,0) and then with
    // v3 = (1,2,0) coordinate by coordinate until one differs: a corner at v1, v4 or v5 costs
    // 1 + 1, at v2 3 (a match), at v3 2 + 3. F1: 2 + 3 + 5, F2: 3 + 2 + 5, F3: 3 + 2 + 2, and
    // the 4 offsets: 31. Sides of F1 and F2: 2 offsets + 3 corners x 3 coordinates: 2 x 11.
    CHECK(c[kIF].reads == 53);
    // The three that store an edge's faces with the edge: 2, then 2 x (2 offsets + 3 sides).
    CHECK(c[kAL].reads == 12);
    CHECK(c[kPAL].reads == 12);
    CHECK(c[kEL].reads == 12);
}

TEST_CASE("flip e3: the winged edge's writes are the entries that differ between the slide's tables and the flipped ones", "[mesh][edit-costs]") {
    // The slide's edge table and, by hand, the one after flip e3 (e3 becomes v4 -> v1 between
    // F1 = (v1 v2 v4) and F2 = (v4 v3 v1)); S E L R S:L S:R E:L E:R, 0 = none, 1-based.
    const std::map<int, std::array<int, 8>> before = {
        {1, {1, 3, 0, 1, 2, 2, 4, 3}}, {2, {1, 2, 1, 0, 1, 1, 3, 6}}, {3, {2, 3, 1, 2, 2, 5, 1, 4}},
        {4, {3, 4, 0, 2, 1, 3, 7, 5}}, {5, {2, 4, 2, 3, 3, 6, 4, 7}}};
    const std::map<int, std::array<int, 8>> after = {
        {1, {1, 3, 0, 2, 2, 3, 4, 4}}, {2, {1, 2, 1, 0, 3, 1, 5, 6}}, {3, {4, 1, 1, 2, 5, 4, 2, 1}},
        {4, {3, 4, 0, 2, 1, 1, 7, 3}}, {5, {2, 4, 1, 3, 2, 6, 3, 7}}};
    int differing = 0;
    for (const auto& [e, row] : before)
        for (int k = 0; k < 8; ++k) differing += row[k] != after.at(e)[k];
    differing += 1; // v3 stored e3, now e1 (e3 no longer ends at v3)
    differing += 1; // F1 stored e1, now e3 (e1 left F1)
    REQUIRE(differing == 18);
    WingedEdgeMesh w = lecture();
    const EditCosts c = measure_edit(w, operation("flip-edge", Edge(2)));
    // No entry written twice and no coordinate: the assignments are the differing entries.
    CHECK(c[kWE].writes == differing);
    for (int e = 1; e <= 5; ++e) {
        const EdgeRecord& r = w.edge(e - 1);
        const std::array<int, 8> got = {r.start + 1, r.end + 1, r.left + 1, r.right + 1, r.start_left + 1, r.start_right + 1, r.end_left + 1, r.end_right + 1};
        CHECK(got == after.at(e));
    }
}

TEST_CASE("split e3 and collapse e6: coordinates written and an entry written twice are lines of the playback, and writes", "[mesh][edit-costs]") {
    {
        WingedEdgeMesh w = lecture();
        const ChangeRecord change = w.apply(operation("split-edge", Edge(2), 0.5));
        int assignments = 0;
        for (const AssignmentStep& s : change.steps) assignments += s.field != "firstCorner";
        // The new vertex v6's x, y and z are written too: 3 lines more than the assignments.
        CHECK(playback_writes(change) == assignments + 3);
    }
    {
        WingedEdgeMesh w = lecture();
        const ChangeRecord change = w.apply(operation("collapse-edge", Edge(5), 0.5));
        std::set<std::tuple<int, int32_t, std::string>> entries;
        int assignments = 0;
        for (const AssignmentStep& s : change.steps) {
            if (s.field == "firstCorner") continue;
            ++assignments;
            entries.insert({static_cast<int>(s.table), s.row, s.field});
        }
        // e2's E:R is written twice (e6, then e7, then e5 as the triangles go).
        CHECK(entries.size() + 1 == static_cast<std::size_t>(assignments));
        // v2 moves from (1, 0, 0) to the middle of e6, (1.5, -0.5, 0): x and y, not z.
        CHECK(playback_writes(change) == assignments + 2);
    }
}

TEST_CASE("random edits: the winged edge's lines cover what differs (new rows' none fields aside), exactly when no entry is written twice; reads never change the mesh", "[mesh][edit-costs]") {
    std::mt19937 rng(20261128);
    for (auto& [name, start] : wingspline::test_edits::fixtures()) {
        WingedEdgeMesh w = start;
        for (int i = 0; i < 40; ++i) {
            const Operation op = wingspline::test_edits::operation_of(wingspline::test_edits::random_call(w, rng));
            if (!w.check(op).ok) continue;
            const WingedEdgeMesh before = w;
            RepresentationCache cache;
            const Representations reps_before = cache.of(w);
            const auto reads = edit_reads(op, w, reps_before);
            CHECK(w.version() == before.version());
            const ChangeRecord change = w.apply(op);
            const Representations& reps_after = cache.of(w);
            const auto differing = rewritten_entries(before, reps_before, w, reps_after);
            const EditCosts c = edit_costs(reads, change, reps_before, w, reps_after);
            std::set<std::tuple<int, int32_t, std::string>> entries;
            int assignments = 0;
            for (const AssignmentStep& s : change.steps)
                if (s.field != "firstCorner") {
                    ++assignments;
                    entries.insert({static_cast<int>(s.table), s.row, s.field});
                }
            // A row an edit adds is born with every pointer "none": a field it leaves none (a
            // boundary edge's missing face) is never assigned, so no line, while comparing the
            // two states counts the new row whole (rewritten_entries).
            int64_t born_none = 0;
            const auto unassigned = [&](MeshTable t, int32_t row, std::initializer_list<const char*> fields) {
                for (const char* f : fields) born_none += entries.count({static_cast<int>(t), row, f}) == 0;
            };
            for (const Edge e : change.added_edges)
                unassigned(MeshTable::Edge, e.idx, {"start", "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"});
            for (const Vertex v : change.added_vertices) unassigned(MeshTable::Vertex, v.idx, {"edge"});
            for (const Face f : change.added_faces) unassigned(MeshTable::Face, f.idx, {"edge"});
            INFO(name << ": " << op.entry->name);
            CHECK(c[kWE].writes + born_none >= differing[kWE]);
            if (entries.size() == static_cast<std::size_t>(assignments)) CHECK(c[kWE].writes + born_none == differing[kWE]);
            for (int r = 0; r < kRepresentationCount; ++r) {
                if (r != kWE) CHECK(c[r].writes == differing[r]);
                CHECK(c[r].reads > 0);
            }
            REQUIRE(w.validate().ok());
        }
    }
}

TEST_CASE("on grids of several sizes the face table's search reads 4F + O(1) while the winged edge's reads stay fixed", "[mesh][edit-costs]") {
    const OperationEntry& flip = *find_operation("flip-edge");
    for (const int32_t n : {4, 10, 22, 40}) {
        const EditCosts c = measure_on_grid(flip, n);
        const int64_t F = 2 * static_cast<int64_t>(n) * n;
        INFO("n = " << n);
        // F + 1 offsets and a triangle's 3 corners each (the wrap to the first corner reads
        // nothing new), at most one read fewer per face that has the edge (2), and the two
        // faces' sides (2 x 5).
        CHECK(c[kVF].reads >= 4 * F + 9);
        CHECK(c[kVF].reads <= 4 * F + 11);
        // The winged edge reads the records around the edge: 2 + 7 + 7, at any size.
        CHECK(c[kWE].reads == 16);
        CHECK(c[kEL].reads == 12);
    }
}

TEST_CASE("edit_cost_growth equals real counted grids of 968 and 9,800 faces", "[mesh][edit-costs]") {
    for (const OperationEntry& entry : operations()) {
        if (std::string(entry.name) == "split-face") {
            CHECK_THROWS_AS(edit_cost_growth(entry, {22}), wingspline::Error);
            continue;
        }
        const EditCostGrowth g = edit_cost_growth(entry, {22, 70});
        INFO(entry.name);
        CHECK(g.faces == std::vector<int64_t>{968, 9800});
        CHECK(g.costs[0] == measure_on_grid(entry, 22));
        CHECK(g.costs[1] == measure_on_grid(entry, 70));
        // The winged edge's cost does not depend on the size.
        CHECK(g.costs[0][kWE] == g.costs[1][kWE]);
    }
    CHECK_THROWS_AS(edit_cost_growth(*find_operation("flip-edge"), {21}), wingspline::Error);
}

// The chart's 100k point is the fit's value; here every operation's fit against a real counted
// grid of that size (the 1M point below is the same check at 1,002,528 faces, run by hand;
// [large]: the native layer runs it, about 4 s; the sanitizer layer leaves it out).
TEST_CASE("edit_cost_growth equals a real counted grid of 100,352 faces for every operation", "[mesh][edit-costs][large]") {
    for (const OperationEntry& entry : operations()) {
        if (std::string(entry.name) == "split-face") continue;
        INFO(entry.name);
        const EditCostGrowth g = edit_cost_growth(entry, {224});
        CHECK(g.faces == std::vector<int64_t>{100352});
        CHECK(g.costs[0] == measure_on_grid(entry, 224));
    }
}

TEST_CASE("edit_cost_growth equals real counted grids of 100,352 and 1,002,528 faces", "[.big][mesh][edit-costs]") {
    const OperationEntry& flip = *find_operation("flip-edge");
    const EditCostGrowth g = edit_cost_growth(flip, {224, 708});
    CHECK(g.costs[0] == measure_on_grid(flip, 224));
    CHECK(g.costs[1] == measure_on_grid(flip, 708));
}
