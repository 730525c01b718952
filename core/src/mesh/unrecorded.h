#pragma once
// Not part of the core's surface: an operation run without its change record (no strings,
// no allocations beyond the tables' own growth), for the benchmarks and the tests that
// compare it with apply(). Returns false, changing nothing, where apply() would refuse.
#include "wingspline/mesh/operations.h"

namespace wingspline::mesh {

// An entry's check and its recorded change (the registry's `impl`, euler_ops.cpp). The
// unrecorded run is not in it: looked up by name (unrecorded_run), it stays out of every
// module that does not ask for it.
struct OperationImpl {
    CheckResult (*check)(const WingedEdgeMesh&, const Operation&);
    ChangeRecord (*apply)(WingedEdgeMesh&, const Operation&);
};

bool apply_unrecorded(WingedEdgeMesh& mesh, const Operation& op);
// The unrecorded run of one entry, for a loop that runs it many times (the benchmark's tasks):
// the entry's function itself, so each run is one call.
using UnrecordedRun = bool (*)(WingedEdgeMesh&, const Operation&);
UnrecordedRun unrecorded_run(const OperationEntry& entry);

} // namespace wingspline::mesh
