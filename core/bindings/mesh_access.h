#pragma once
// What bench.cpp needs from mesh.cpp: the winged edge of a live handle (throws
// Error("disposed") for a disposed or unknown one) and the checked face-set reader.
#include "boundary.h"

#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>
#include <vector>

namespace wingspline::bindings {

const mesh::WingedEdgeMesh& winged_of_handle(int32_t handle);
mesh::IndexedMesh indexed_from_arrays(const val& positions, const val& face_offsets, const val& face_vertices);
// A new live mesh (subdivision.cpp's results): its handle, as buildMesh returns one.
int32_t register_mesh(mesh::WingedEdgeMesh&& winged);
// Pointer assignments as they cross (a change record's, a reconnection's): an Int32Array of
// six per step [table, row, field, before, after, phase], table and field as indices into
// meshOperationDescriptors().tables / .fields (defined in mesh_representations.cpp, which
// every module with meshes links).
val assignment_steps_array(const std::vector<mesh::AssignmentStep>& steps);

} // namespace wingspline::bindings
