// The other representations of a mesh (lectures 000, 001): their storage, their tables read
// through the generic table binding, the queries whose cost they compare, and bytes; the
// mesh's version and gaps; pointer assignments as they cross (a change record's, a playback's).
#include "boundary.h"
#include "mesh_access.h"
#include "mesh_entry.h"

#include "tables.h"

#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/tables.h"
#include "wingspline/mesh/winged_edge.h"

namespace wingspline::bindings {

val assignment_steps_array(const std::vector<mesh::AssignmentStep>& steps) {
    std::vector<int32_t> flat;
    flat.reserve(6 * steps.size());
    for (const mesh::AssignmentStep& s : steps)
        flat.insert(flat.end(), {static_cast<int32_t>(s.table), s.row, mesh::change_field_index(s.field), s.before, s.after, s.phase});
    return to_typed_array(flat);
}

val storage_value(const mesh::Storage& s) {
    val arrays = val::array();
    for (std::size_t i = 0; i < s.arrays.size(); ++i) {
        const mesh::ArrayStorage& a = s.arrays[i];
        val item = val::object();
        item.set("name", a.name);
        item.set("entries", static_cast<double>(a.entries));
        item.set("bytesPerEntry", static_cast<double>(a.bytes_per_entry));
        arrays.set(i, item);
    }
    val one = val::object();
    one.set("entries", static_cast<double>(s.entries()));
    one.set("bytes", static_cast<double>(s.bytes()));
    one.set("arrays", arrays);
    return one;
}

namespace {

using namespace wingspline::mesh;

// {[key]: {entries, bytes, arrays: [{name, entries, bytesPerEntry}]}}
val mesh_storage(int32_t handle) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        const auto all = representation_storage(representations_of(m), m.winged);
        val out = val::object();
        for (int r = 0; r < kRepresentationCount; ++r) out.set(representation_key(static_cast<Representation>(r)), storage_value(all[r]));
        val r = val::object();
        r.set("storage", out);
        return r;
    });
}

// Rows [first, first + rows) of every table of one representation, described once in
// core/src/mesh/tables.cpp and turned into plain values by the generic binding (tables.h).
val mesh_tables(int32_t handle, const std::string& key, int32_t first, int32_t rows) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        const Representation which = representation_named(key);
        val r = val::object();
        r.set("tables", tables_value(representation_tables(which, which == Representation::WingedEdge ? nullptr : &representations_of(m), m.winged), first, rows));
        return r;
    });
}

// {[key]: {answer: Int32Array, entriesRead}} for one query, in every representation.
val mesh_query(int32_t handle, const std::string& kind, int32_t element) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        const auto answers = answer_query(query_kind(kind), element, representations_of(m), m.winged);
        val out = val::object();
        for (int r = 0; r < kRepresentationCount; ++r) {
            val one = val::object();
            one.set("answer", to_typed_array(answers[r].answer));
            one.set("entriesRead", static_cast<double>(answers[r].entries_read));
            out.set(representation_key(static_cast<Representation>(r)), one);
        }
        val r = val::object();
        r.set("answers", out);
        return r;
    });
}

// {bytes, perFace}: the winged-edge tables' own size.
val mesh_bytes(int32_t handle) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        val r = val::object();
        r.set("bytes", static_cast<double>(w.bytes()));
        return r;
    });
}

// How pointer assignments cross (assignment_steps_array, a change record's positions):
// {tables, fields, stepStride, positionStride}, the names a step's table and field index.
val mesh_change_format() {
    return guarded([] {
        const auto names = [](const std::vector<const char*>& v) {
            val out = val::array();
            for (std::size_t k = 0; k < v.size(); ++k) out.set(k, std::string(v[k]));
            return out;
        };
        val r = val::object();
        r.set("tables", names(change_tables()));
        r.set("fields", names(change_fields()));
        r.set("stepStride", 6);
        r.set("positionStride", 8);
        return r;
    });
}

// {topology, geometry}: which state of the mesh this is (winged_edge.h, MeshVersion).
val mesh_version(int32_t handle) {
    return guarded([&] { return version_value(entry(handle).winged.version()); });
}

// The gaps: {vertices, edges, faces}, each the removed indices in increasing order.
val mesh_gaps(int32_t handle) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        const auto marked = [](const std::vector<char>& marks) {
            std::vector<int32_t> out;
            for (std::size_t i = 0; i < marks.size(); ++i)
                if (marks[i]) out.push_back(static_cast<int32_t>(i));
            return int_array(out);
        };
        val r = val::object();
        r.set("vertices", marked(w.deleted_vertices()));
        r.set("edges", marked(w.deleted_edges()));
        r.set("faces", marked(w.deleted_faces()));
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh_representations) {
    using namespace wingspline::bindings;
    emscripten::function("meshBytes", &mesh_bytes);
    emscripten::function("meshStorage", &mesh_storage);
    emscripten::function("meshTables", &mesh_tables);
    emscripten::function("meshQuery", &mesh_query);
    emscripten::function("meshVersion", &mesh_version);
    emscripten::function("meshGaps", &mesh_gaps);
    emscripten::function("meshChangeFormat", &mesh_change_format);
}
