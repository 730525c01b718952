#pragma once
// What an edit costs each of the six representations (lecture 000's argument for the winged
// edge): the stored entries it had to READ to find what to change, and the entries it
// WROTE, counted separately.
//
// Reads: an edit first finds the elements it rewrites, and each representation finds them
// with the queries of queries.h, read through their counting reader (one entry = one number
// of one array). Which queries an operation needs is its registry entry's `locate`
// (operations.h): the faces on both sides of an edge and their sides (flip, split, join),
// those plus the edges at both ends (collapse: every edge at the removed end is re-pointed),
// the sides of a face (split face, poke), the edges around a vertex (split vertex). A table
// that points only one way (the face table, independent faces) must scan every face for
// them: O(F) reads; the winged edge reads only the records around the element.
//
// Writes: for the winged edge, the assignments its algorithm made, one per line of the
// edit's playback: every recorded assignment of a column the slides show (an entry written
// twice counts twice) and every coordinate set (a new vertex's x, y and z; a moved vertex's
// coordinates that changed; a field of a new row left "none", as a new boundary edge's
// missing face, is born so and never assigned). The other five keep no record of an algorithm: their writes are
// the entries that differ between their tables before and after (rewritten_entries), the
// fewest any algorithm could write.
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/winged_edge.h"

#include <array>
#include <cstdint>
#include <vector>

namespace wingspline::mesh {

struct EditCost {
    int64_t reads = 0;
    int64_t writes = 0;
    bool operator==(const EditCost& o) const { return reads == o.reads && writes == o.writes; }
};
using EditCosts = std::array<EditCost, kRepresentationCount>; // in Representation order

// What an operation must find, {name} standing for its first argument as in `describe`:
// "the faces on both sides of {e} and their sides".
const char* locate_description(Locate locate);

// The reads each representation makes to find what `op` rewrites, on the mesh before the
// edit (`winged` and its representations `reps`). `op` must pass winged.check(op).
std::array<int64_t, kRepresentationCount> edit_reads(const Operation& op, const WingedEdgeMesh& winged, const Representations& reps);

// The winged edge's reads alone (edit_reads' winged-edge entry), without the other
// representations: O(what it finds), for a mesh too big to derive them after every edit.
int64_t winged_edit_reads(const Operation& op, const WingedEdgeMesh& winged);

// The winged edge's writes: the lines of the edit's playback (see above).
int64_t playback_writes(const ChangeRecord& change);

// Reads and writes together: `reads` from edit_reads before the edit, the winged edge's
// writes from the change record, the others' by comparing their tables before and after.
EditCosts edit_costs(const std::array<int64_t, kRepresentationCount>& reads, const ChangeRecord& change,
                     const Representations& before_reps, const WingedEdgeMesh& after, const Representations& after_reps);

// Runs `op` on `winged` (which it changes) and counts it: reads before, writes after.
// Throws the check's refusal as Error(code, message), leaving the mesh unchanged.
EditCosts measure_edit(WingedEdgeMesh& winged, const Operation& op);

// ---------------------------------------------------------------- cost against mesh size

// The same operation on docs/benchmarks.md grids of n x n quads (F = 2 n^2 triangles), at
// the grid's middle element of the operation's first argument (vertex (n/2)(n+1) + n/2, the
// edge from it to the next vertex of its row, face F/2 + n; n even), its element choices the
// first and third the registry's query offers, t = 0.5.
Operation grid_operation(const OperationEntry& entry, const WingedEdgeMesh& grid, int32_t n);

// Reads and writes of that operation measured on a real grid of n x n quads (n even).
EditCosts measure_on_grid(const OperationEntry& entry, int32_t n);

// Reads and writes at each grid size in `sizes` (even n, any size up to the grid's limit):
// measured on real grids at three small sizes (n = 8, 16, 24), each count fitted exactly by
// a + b n + c n^2 (a scan over the vertex, edge or face table reads a fixed number of
// entries per element, and V, E, F are quadratics in n), the fit checked against a fourth
// real grid (n = 32), then evaluated at each size. Building a million-face grid and all six
// representations for every edit would take seconds and hundreds of megabytes in the page;
// tests/native/mesh/test_edit_costs.cpp checks the values against real counted grids up to
// a million faces. Throws Error("internal-error") when the fourth grid disagrees and
// the operation's check refusals (a triangle grid has no face to split).
struct EditCostGrowth {
    std::vector<int32_t> n;     // quads across, per size
    std::vector<int64_t> faces; // F = 2 n^2
    std::vector<EditCosts> costs;
};
EditCostGrowth edit_cost_growth(const OperationEntry& entry, const std::vector<int32_t>& sizes);

} // namespace wingspline::mesh
