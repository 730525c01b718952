#pragma once
// The benchmark's edit tasks (docs/benchmarks.md, mesh_edit_flip and mesh_edit_split), run
// through the operations' unrecorded path. Linked only into the native benchmark and the
// bench wasm module, never into the shipped module or the student API.
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>

namespace wingspline::bench {

// For every edge e with e % 3 == 0, in increasing order, flip it if the check allows.
// Returns the number of flips made.
int32_t flip_every_third_edge(mesh::WingedEdgeMesh& mesh);
// Split every edge of the mesh as built (0 .. E-1, in order) at its midpoint and split each
// triangle beside it from the new vertex to the opposite corner (as OpenMesh's TriMesh
// split). Returns the number of edges split.
int32_t split_every_edge(mesh::WingedEdgeMesh& mesh);

} // namespace wingspline::bench
