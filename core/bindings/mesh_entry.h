#pragma once
// What the mesh bindings share (mesh.cpp defines it): the registry entry of a live mesh (its
// winged edge and the cache of the other representations), the handle lookup, and the small
// value builders every mesh binding uses.
#include "boundary.h"

#include "wingspline/mesh/half_edge.h"
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace wingspline::bindings {

// The winged edge is built with the mesh; the other representations are its cache
// (RepresentationCache): derived from the winged edge's current face set on first use and
// again whenever the mesh's version moved on, so a mesh's wasm memory is the winged edge's
// own until a lesson asks for the others, and no operation leaves a stale copy.
// A big mesh also keeps its pick grid (view_geometry.h), made on the first pick at a view and
// again when the mesh or the view direction changed: a pointer moving over a still view asks
// it many times.
// The records of its newest edits (meshEdit), newest last, are what meshUndo takes back
// (WingedEdgeMesh::undo): at most kUndoRecords, the oldest dropped first.
// The half-edge view (half_edge.h) is made on first use for the topology version it shows
// (half_edge_topology); an edit or an undo made while it is current updates it from the
// change record, O(the edit) (mesh_edit.cpp); any other topology change (compact) leaves
// it stale, and it is made again on the next use (mesh_half_edge.cpp). What the newest edit
// or undo changed in it is kept (half_edge_change, with the winged edge's pointer
// assignments counted beside it) until the next one; followed = false when the view was not
// current then, so nothing is known.
struct HalfEdgeChange {
    bool followed = false;
    std::vector<mesh::HalfEdgeAssignment> entries;
    int64_t winged_assignments = 0;
};
struct MeshEntry {
    mesh::WingedEdgeMesh winged;
    mesh::RepresentationCache representations;
    mesh::PickGrid pick_grid;
    std::vector<std::unique_ptr<mesh::ChangeRecord>> undoable;
    std::unique_ptr<mesh::HalfEdgeMesh> half_edge;
    uint32_t half_edge_topology = 0;
    HalfEdgeChange half_edge_change;
};
inline constexpr std::size_t kUndoRecords = 1000;

// The entry of a live handle; throws Error("disposed") for a disposed or unknown one.
MeshEntry& entry(int32_t handle);
const mesh::Representations& representations_of(MeshEntry& m);
val version_value(const mesh::MeshVersion& v);
val int_array(const std::vector<int32_t>& v);
val report_value(const mesh::ValidationReport& report);
// {entries, bytes, arrays: [{name, entries, bytesPerEntry}]}: one representation's storage
// (mesh_representations.cpp), as meshStorage gives each.
val storage_value(const mesh::Storage& s);
// {face, near: Int32Array, distance: Float64Array}: a pick's answer (mesh_geometry.cpp).
val pick_value(const mesh::PickResult& p);
// A missing element or a gap left by an edit, refused as the mesh's own operations refuse
// them (WingedEdgeMesh::check_element).
void require_vertex(const mesh::WingedEdgeMesh& w, int32_t v);
void require_face(const mesh::WingedEdgeMesh& w, int32_t f);
void require_edge(const mesh::WingedEdgeMesh& w, int32_t e);

} // namespace wingspline::bindings
