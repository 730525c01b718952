// The half-edge view of a mesh (half_edge.h) through one binding: its arrays (a window of
// rows at a time), its walks, its query answers with their reads and its storage. The
// binding group `edit` (the mesh lesson's module and the whole mesh API, not the subdivision
// lesson's), which keeps the view in step with every edit (mesh_edit.cpp). Its validate() is
// the native tests', run after every edit there; it is not bound, to keep the mesh lesson's
// module small.
#include "boundary.h"
#include "mesh_entry.h"

#include "wingspline/mesh/half_edge.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <memory>

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// The view of the mesh as it is now: made on first use, and again when the topology moved on
// by something that did not update it (compact).
const HalfEdgeMesh& half_edge_of(MeshEntry& me) {
    const uint32_t topology = me.winged.version().topology;
    if (!me.half_edge || me.half_edge_topology != topology) {
        me.half_edge = std::make_unique<HalfEdgeMesh>(HalfEdgeMesh::build(me.winged));
        me.half_edge_topology = topology;
    }
    return *me.half_edge;
}

// Rows [first, first + rows) of `column` (fewer at its end), as an Int32Array.
val window(const std::vector<int32_t>& column, int32_t first, int32_t rows) {
    const std::size_t n = column.size();
    const std::size_t begin = std::min(n, static_cast<std::size_t>(first));
    const std::size_t end = rows < 0 ? n : std::min(n, begin + static_cast<std::size_t>(rows));
    return to_typed_array(column.data() + begin, end - begin);
}

// One entry point for the whole view, by `kind` (one embind function rather than four keeps
// the mesh lesson's module within its budget, docs/architecture.md "Module size"):
//  * "arrays": {halfedges, vertices, faces: the full row counts; origin, face, next, prev:
//    Int32Array, one entry per half-edge of rows [a, a + b); vertexHalfedge, faceHalfedge:
//    the same rows of the vertex and face tables}; b < 0: every row.
//  * "vertex-walk" (around vertex `element`, from half-edge a, -1 = its own) and "face-walk"
//    (along face `element`): {steps: Int32Array, 3 per step: steps[3*i + {0, 1, 2}] = the
//    half-edge, the value read there (prev or next), the half-edge the step goes to}.
//  * "storage": {entries, bytes, arrays: [{name, entries, bytesPerEntry}]} (half_edge_storage).
//  * "change": what the newest edit or undo changed in the view (mesh_entry.h,
//    HalfEdgeChange): {followed (false: the view was not current then, nothing known),
//    entries: Int32Array, 6 per entry: entries[6*i + {0..5}] = table (HalfEdgeTable), row,
//    field (HalfEdgeField), before, after, the winged-edge step it follows (-1: none),
//    wingedAssignments: the winged edge's pointer assignments in the same edit}.
//  * a query of queries.h ("faces-around-vertex", ...) about `element`: {answer: Int32Array,
//    entriesRead} on the half-edge arrays.
val mesh_half_edge(int32_t handle, const std::string& kind, int32_t element, int32_t a, int32_t b) {
    return guarded([&] {
        MeshEntry& me = entry(handle);
        if (kind == "storage") return storage_value(half_edge_storage(half_edge_of(me), me.winged));
        val r = val::object();
        if (kind == "arrays") {
            require(a >= 0, "invalid-argument", "offset must be >= 0");
            const HalfEdgeMesh& h = half_edge_of(me);
            r.set("halfedges", h.halfedge_count());
            r.set("vertices", h.vertex_count());
            r.set("faces", h.face_count());
            r.set("origin", window(h.origins(), a, b));
            r.set("face", window(h.faces(), a, b));
            r.set("next", window(h.nexts(), a, b));
            r.set("prev", window(h.prevs(), a, b));
            r.set("vertexHalfedge", window(h.vertex_halfedges(), a, b));
            r.set("faceHalfedge", window(h.face_halfedges(), a, b));
        } else if (kind == "change") {
            const HalfEdgeChange& c = me.half_edge_change;
            r.set("followed", c.followed);
            r.set("entries", to_typed_array(reinterpret_cast<const int32_t*>(c.entries.data()), 6 * c.entries.size()));
            r.set("wingedAssignments", static_cast<double>(c.winged_assignments));
        } else if (kind == "vertex-walk" || kind == "face-walk") {
            const bool around_vertex = kind == "vertex-walk";
            if (around_vertex) require_vertex(me.winged, element);
            else require_face(me.winged, element);
            const HalfEdgeMesh& h = half_edge_of(me);
            if (around_vertex && a != kNone)
                require(a >= 0 && a < h.halfedge_count() && h.origin(a) == element, "invalid-argument",
                        "the walk around " + vertex_label(element) + " starts at a half-edge leaving it");
            const std::vector<HalfEdgeStep> steps = around_vertex ? h.vertex_walk(element, a) : h.face_walk(element);
            r.set("steps", to_typed_array(reinterpret_cast<const int32_t*>(steps.data()), 3 * steps.size()));
        } else {
            const QueryAnswer q = half_edge_answer(query_kind(kind), element, half_edge_of(me), me.winged);
            r.set("answer", to_typed_array(q.answer));
            r.set("entriesRead", static_cast<double>(q.entries_read));
        }
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh_half_edge) {
    using namespace wingspline::bindings;
    emscripten::function("meshHalfEdge", &mesh_half_edge);
}
