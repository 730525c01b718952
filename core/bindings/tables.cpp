// The generic table binding (tables.h) and meshTableDescriptors(): every descriptor as a
// plain value, read once by web/js/core/tables.js.
#include "tables.h"

#include <algorithm>

namespace wingspline::bindings {

using namespace wingspline::mesh;

namespace {

const char* role_name(ArrayRole r) { return r == ArrayRole::Rows ? "rows" : r == ArrayRole::Offsets ? "offsets" : "list"; }
const char* type_name(ScalarType t) { return t == ScalarType::Float64 ? "float64" : "int32"; }

val descriptor_value(const TableDescriptor& d) {
    val arrays = val::array();
    for (std::size_t i = 0; i < d.arrays.size(); ++i) {
        const ArrayDescriptor& a = d.arrays[i];
        val one = val::object();
        one.set("name", std::string(a.name));
        one.set("type", std::string(type_name(a.type)));
        one.set("role", std::string(role_name(a.role)));
        one.set("stride", a.stride);
        if (a.role == ArrayRole::List) one.set("offsets", std::string(a.offsets));
        arrays.set(i, one);
    }
    val columns = val::array();
    for (std::size_t i = 0; i < d.columns.size(); ++i) {
        const ColumnDescriptor& c = d.columns[i];
        const ArrayDescriptor& a = d.array(c.array);
        val one = val::object();
        one.set("name", std::string(c.name));
        one.set("label", std::string(c.label));
        one.set("group", std::string(c.group));
        one.set("refers", c.refers == ElementKind::None ? val::null() : val(std::string(element_kind_name(c.refers))));
        one.set("type", std::string(type_name(a.type)));
        one.set("layout", std::string(a.role == ArrayRole::List ? "csr" : "fixed"));
        one.set("array", std::string(c.array));
        if (a.role == ArrayRole::List) one.set("offsets", std::string(a.offsets));
        one.set("stride", a.stride);
        one.set("first", c.first);
        one.set("width", c.width);
        columns.set(i, one);
    }
    val r = val::object();
    r.set("representation", std::string(representation_key(d.representation)));
    r.set("name", std::string(d.name));
    r.set("title", std::string(d.title));
    r.set("rows", std::string(element_kind_name(d.rows)));
    r.set("arrays", arrays);
    r.set("columns", columns);
    return r;
}

template <class T> val slice(const T* data, std::size_t begin, std::size_t end) { return to_typed_array(data + begin, end - begin); }
val slice(const ArrayData& a, std::size_t begin, std::size_t end) {
    return a.f64 != nullptr ? slice(a.f64, begin, end) : slice(a.i32, begin, end);
}

val mesh_table_descriptors() {
    return guarded([] {
        val all = val::array();
        const auto& ds = table_descriptors();
        for (std::size_t i = 0; i < ds.size(); ++i) all.set(i, descriptor_value(ds[i]));
        val r = val::object();
        r.set("tables", all);
        return r;
    });
}

} // namespace

Representation representation_named(const std::string& key) {
    for (int r = 0; r < kRepresentationCount; ++r)
        if (key == representation_key(static_cast<Representation>(r))) return static_cast<Representation>(r);
    throw Error("unknown-representation", "unknown representation '" + key.substr(0, 40) + "'");
}

val tables_value(const std::vector<TableData>& tables, int32_t first, int32_t rows) {
    require(first >= 0 && rows >= 0, "invalid-argument", "offset and limit must not be negative");
    val out = val::array();
    for (std::size_t t = 0; t < tables.size(); ++t) {
        const TableData& table = tables[t];
        const TableDescriptor& d = *table.descriptor;
        const std::size_t total = static_cast<std::size_t>(table.rows);
        const std::size_t begin = std::min(total, static_cast<std::size_t>(first));
        const std::size_t end = std::min(total, begin + static_cast<std::size_t>(rows));
        val arrays = val::object();
        for (std::size_t i = 0; i < d.arrays.size(); ++i) {
            const ArrayDescriptor& a = d.arrays[i];
            const ArrayData& data = table.arrays[i];
            if (a.role == ArrayRole::Rows) {
                arrays.set(a.name, slice(data, a.stride * begin, a.stride * end));
            } else if (a.role == ArrayRole::Offsets) {
                arrays.set(a.name, slice(data, begin, end + 1));
            } else {
                const ArrayData& off = table.arrays[&d.array(a.offsets) - d.arrays.data()];
                arrays.set(a.name, slice(data, a.stride * static_cast<std::size_t>(off.at(begin)), a.stride * static_cast<std::size_t>(off.at(end))));
            }
        }
        val one = val::object();
        one.set("representation", std::string(representation_key(d.representation)));
        one.set("name", std::string(d.name));
        one.set("rows", static_cast<double>(total));
        one.set("first", static_cast<double>(begin));
        one.set("arrays", arrays);
        out.set(t, one);
    }
    return out;
}

} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_tables) {
    emscripten::function("meshTableDescriptors", &wingspline::bindings::mesh_table_descriptors);
}
