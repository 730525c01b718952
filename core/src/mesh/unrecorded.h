#pragma once
// Not part of the core's surface: an operation run without its change record (no strings,
// no allocations beyond the tables' own growth), for the benchmarks and the tests that
// compare it with apply(). Returns false, changing nothing, where apply() would refuse.
#include "wingspline/mesh/operations.h"

namespace wingspline::mesh {
bool apply_unrecorded(WingedEdgeMesh& mesh, const Operation& op);
} // namespace wingspline::mesh
