// The other representations of a mesh (lectures 000, 001): their storage, their tables read
// through the generic table binding, the queries whose cost they compare, and bytes.
#include "boundary.h"
#include "mesh_entry.h"

#include "tables.h"

#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/tables.h"
#include "wingspline/mesh/winged_edge.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// {[key]: {entries, bytes, arrays: [{name, entries, bytesPerEntry}]}}
val mesh_storage(int32_t handle) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        const auto all = representation_storage(representations_of(m), m.winged);
        val out = val::object();
        for (int r = 0; r < kRepresentationCount; ++r) {
            val arrays = val::array();
            for (std::size_t i = 0; i < all[r].arrays.size(); ++i) {
                const ArrayStorage& a = all[r].arrays[i];
                val item = val::object();
                item.set("name", a.name);
                item.set("entries", static_cast<double>(a.entries));
                item.set("bytesPerEntry", static_cast<double>(a.bytes_per_entry));
                arrays.set(i, item);
            }
            val one = val::object();
            one.set("entries", static_cast<double>(all[r].entries()));
            one.set("bytes", static_cast<double>(all[r].bytes()));
            one.set("arrays", arrays);
            out.set(representation_key(static_cast<Representation>(r)), one);
        }
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

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh_representations) {
    using namespace wingspline::bindings;
    emscripten::function("meshBytes", &mesh_bytes);
    emscripten::function("meshStorage", &mesh_storage);
    emscripten::function("meshTables", &mesh_tables);
    emscripten::function("meshQuery", &mesh_query);
}
