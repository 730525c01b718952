// Undo from a change record (WingedEdgeMesh::undo): the mesh before the change comes back
// row for row, gaps and marks included, on thousands of random edits taken back in random
// runs; the same change made again gives the same numbers; anything but the newest change is
// refused ("cannot-undo") and changes nothing.
#include <catch2/catch.hpp>

#include "random_edits.h"

#include "wingspline/error.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/winged_edge.h"

#include <random>
#include <string>
#include <vector>

using namespace wingspline::mesh;
using namespace wingspline::test_edits;

namespace {

void require_valid(const WingedEdgeMesh& w) {
    const ValidationReport r = w.validate();
    INFO((r.first_error() ? r.first_error()->message : std::string()));
    REQUIRE(r.ok());
}

template <class H> std::vector<int32_t> ids(const std::vector<H>& hs) {
    std::vector<int32_t> out;
    for (const H& h : hs) out.push_back(h.idx);
    return out;
}

} // namespace

TEST_CASE("undo: random edits taken back in random runs give every earlier mesh back, row for row", "[mesh][undo]") {
    std::size_t undone = 0, redone = 0, with_gaps = 0, added = 0;
    for (uint32_t seed = 1; seed <= 48; ++seed) {
        std::vector<Fixture> all = fixtures();
        Fixture& fx = all[seed % all.size()];
        WingedEdgeMesh& w = fx.mesh;
        std::mt19937 rng(seed);
        struct Done {
            ChangeRecord record;
            Snapshot before, after;
            Operation op;
        };
        std::vector<Done> history;
        for (int round = 0; round < 300; ++round) {
            INFO(fx.name << " seed " << seed << " round " << round);
            if (!history.empty() && rng() % 4 == 0) {
                // Take back a run of the newest changes, checking the mesh after each.
                const std::size_t k = 1 + rng() % history.size();
                for (std::size_t i = 0; i < k; ++i) {
                    const Done d = history.back();
                    history.pop_back();
                    INFO("undo " << d.record.op);
                    INFO(w.check_undo(d.record).message);
                    REQUIRE(w.check_undo(d.record).ok);
                    const MeshVersion v = w.version();
                    const ChangeRecord u = w.undo(d.record);
                    REQUIRE(snapshot(w) == d.before);
                    require_valid(w);
                    // The version of the state it restores (no position moved since the change).
                    REQUIRE(u.before == v);
                    REQUIRE(w.version() == d.record.before);
                    REQUIRE(u.after == w.version());
                    // The undo's record: the elements back and gone, each row's fields swapped.
                    REQUIRE(ids(u.added_edges) == ids(d.record.removed_edges));
                    REQUIRE(ids(u.removed_faces) == ids(d.record.added_faces));
                    for (const RowChange& r : u.rows)
                        for (const FieldChange& f : r.fields) REQUIRE(f.before != f.after);
                    ++undone;
                    if (!d.record.removed_edges.empty()) ++with_gaps;
                    if (!d.record.added_edges.empty()) ++added;
                    // Now and then the same change again: the same numbers, the same tables.
                    if (rng() % 3 == 0) {
                        const ChangeRecord again = w.apply(d.op);
                        REQUIRE(snapshot(w).same_tables(d.after));
                        // A number never used before: a cache of the first time is not this state's.
                        REQUIRE(again.after.topology > d.record.after.topology);
                        REQUIRE(ids(again.added_vertices) == ids(d.record.added_vertices));
                        REQUIRE(ids(again.added_edges) == ids(d.record.added_edges));
                        REQUIRE(ids(again.added_faces) == ids(d.record.added_faces));
                        history.push_back({again, d.before, d.after, d.op});
                        ++redone;
                        break;
                    }
                }
                continue;
            }
            const Operation op = operation_of(random_call(w, rng));
            if (!w.check(op).ok) continue;
            Done d{{}, snapshot(w), {}, op};
            d.record = w.apply(op);
            if (!d.record.changed()) continue;
            d.after = snapshot(w);
            require_valid(w);
            history.push_back(std::move(d));
        }
    }
    INFO("undone " << undone << ", redone " << redone << ", with gaps " << with_gaps << ", with new elements " << added);
    CHECK(undone >= 2000);
    CHECK(redone >= 300);
    CHECK(with_gaps >= 100);
    CHECK(added >= 500);
}

TEST_CASE("undo: flip e3 of the lecture mesh and take it back: the slide's tables again", "[mesh][undo]") {
    WingedEdgeMesh w = lecture();
    const Snapshot slide = snapshot(w);
    const ChangeRecord flip = w.apply(operation_from("flip-edge", std::vector<double>{2}.data(), 1));
    REQUIRE(!snapshot(w).same_tables(slide));
    const ChangeRecord u = w.undo(flip);
    REQUIRE(snapshot(w) == slide);
    REQUIRE(u.op == "undo");
    // e3's row as the flip left it, and as the slide has it: S v4 -> v2 again (0-based 3 -> 1).
    const auto e3 = std::find_if(u.rows.begin(), u.rows.end(), [](const RowChange& r) { return r.table == MeshTable::Edge && r.row == 2; });
    REQUIRE(e3 != u.rows.end());
    REQUIRE(w.edge(2).start == lecture().edge(2).start);
}

TEST_CASE("undo: the first gap taken back leaves no marks; a collapse's moved vertex goes back", "[mesh][undo]") {
    WingedEdgeMesh w = lecture();
    const Snapshot slide = snapshot(w);
    REQUIRE(!w.has_garbage());
    const double args[] = {3, 0.25}; // collapse e4 at t = 1/4: v3 moves, v4 and F2 go
    const ChangeRecord c = w.apply(operation_from("collapse-edge", args, 2));
    REQUIRE(w.has_garbage());
    REQUIRE(!c.positions.empty());
    const ChangeRecord u = w.undo(c);
    REQUIRE(!w.has_garbage());
    REQUIRE(snapshot(w) == slide);
    REQUIRE(u.positions.size() == 1);
    REQUIRE(u.positions[0].after == lecture().position(u.positions[0].vertex));
    REQUIRE(w.version() == c.before);
}

TEST_CASE("undo refuses anything but the newest change and changes nothing", "[mesh][undo]") {
    WingedEdgeMesh w = lecture();
    const double e3[] = {2, 0.5};
    const ChangeRecord split = w.apply(operation_from("split-edge", e3, 2));
    const double e1[] = {0};
    const ChangeRecord flip_or_split = w.apply(operation_from("split-edge", e1, 1));
    const Snapshot now = snapshot(w);
    const MeshVersion v = w.version();
    // An older change: another came after it.
    CheckResult c = w.check_undo(split);
    REQUIRE(!c.ok);
    REQUIRE(c.code == "cannot-undo");
    REQUIRE(c.message.find("split-edge") != std::string::npos);
    REQUIRE(c.message == "cannot take back split-edge: another change came after it (only the mesh's newest change can be taken back)");
    REQUIRE_THROWS_AS(w.undo(split), wingspline::Error);
    REQUIRE(snapshot(w) == now);
    REQUIRE(w.version() == v);
    // A vertex the change placed and that goes with it may have moved: it is taken back.
    w.set_position(flip_or_split.added_vertices.at(0).idx, {9, 9, 9});
    REQUIRE(w.check_undo(flip_or_split).ok);
    // A vertex the change moved and that stays must be where the change put it.
    WingedEdgeMesh moved = lecture();
    const double e4[] = {3, 0.25};
    const ChangeRecord collapse = moved.apply(operation_from("collapse-edge", e4, 2));
    const int32_t kept = collapse.positions.at(0).vertex;
    const glm::dvec3 put = moved.position(kept);
    moved.set_position(kept, {9, 9, 9});
    c = moved.check_undo(collapse);
    REQUIRE(c.code == "cannot-undo");
    REQUIRE(c.message.find(element_label(MeshTable::Vertex, kept) + " moved after it") != std::string::npos);
    moved.set_position(kept, put);
    REQUIRE(moved.check_undo(collapse).ok);
    // The positions moved since the change: the topology's version comes back, the geometry
    // gets a number never used.
    const MeshVersion last = moved.version();
    moved.undo(collapse);
    REQUIRE(moved.version().topology == collapse.before.topology);
    REQUIRE(moved.version().geometry == last.geometry + 1);
    // A change of another mesh at the same version: a field holds something else.
    WingedEdgeMesh other = lecture();
    other.apply(operation_from("split-edge", e1, 1));
    WingedEdgeMesh fresh = lecture();
    const ChangeRecord own = fresh.apply(operation_from("flip-edge", std::vector<double>{2}.data(), 1));
    const Snapshot before = snapshot(other);
    REQUIRE(!other.check_undo(own).ok);
    REQUIRE_THROWS_AS(other.undo(own), wingspline::Error);
    REQUIRE(snapshot(other) == before);
    // The same record twice: the second time it is no longer the newest.
    REQUIRE(fresh.check_undo(own).ok);
    fresh.undo(own);
    REQUIRE(fresh.check_undo(own).code == "cannot-undo");
}
