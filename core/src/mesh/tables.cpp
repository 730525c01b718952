// The table descriptors (tables.h) and the one place that ties each described array to the
// C++ vector holding it.
#include "wingspline/mesh/tables.h"

#include <algorithm>
#include <stdexcept>

namespace wingspline::mesh {

namespace {

using R = Representation;
using K = ElementKind;
constexpr ScalarType F64 = ScalarType::Float64;
constexpr ScalarType I32 = ScalarType::Int32;

ArrayDescriptor rows(const char* name, ScalarType type, int stride) { return {name, type, ArrayRole::Rows, stride, ""}; }
ArrayDescriptor offsets(const char* name) { return {name, I32, ArrayRole::Offsets, 1, ""}; }
ArrayDescriptor list(const char* name, const char* offsets_name, ScalarType type = I32, int width = 1) {
    return {name, type, ArrayRole::List, width, offsets_name};
}
// Columns x, y, z of a positions array (3 per row).
std::vector<ColumnDescriptor> xyz(const char* x, const char* y, const char* z) {
    return {{"x", x, "", K::None, "positions", 0, 1}, {"y", y, "", K::None, "positions", 1, 1}, {"z", z, "", K::None, "positions", 2, 1}};
}
ColumnDescriptor position(const char* label = "position") { return {"position", label, "", K::None, "positions", 0, 3}; }
ColumnDescriptor csr(const char* name, K refers, const char* array) { return {name, name, "", refers, array, 0, 1}; }

std::vector<TableDescriptor> describe() {
    std::vector<TableDescriptor> t;
    // Lecture 000, "Winged Edge": the slide's three tables, columns as its headers.
    auto vertex_columns = xyz("x", "y", "z");
    vertex_columns.push_back({"edge", "edge", "", K::Edge, "vertexEdge", 0, 1});
    t.push_back({R::WingedEdge, "vertices", "VERTEX TABLE", K::Vertex,
                 {rows("positions", F64, 3), rows("vertexEdge", I32, 1)}, vertex_columns});
    t.push_back({R::WingedEdge, "edges", "EDGE TABLE", K::Edge, {rows("edges", I32, 8)},
                 {{"start", "S", "", K::Vertex, "edges", 0, 1},
                  {"end", "E", "", K::Vertex, "edges", 1, 1},
                  {"left", "L", "", K::Face, "edges", 2, 1},
                  {"right", "R", "", K::Face, "edges", 3, 1},
                  {"startLeft", "L", "S", K::Edge, "edges", 4, 1},
                  {"startRight", "R", "S", K::Edge, "edges", 5, 1},
                  {"endLeft", "L", "E", K::Edge, "edges", 6, 1},
                  {"endRight", "R", "E", K::Edge, "edges", 7, 1}}});
    t.push_back({R::WingedEdge, "faces", "FACE TABLE", K::Face, {rows("faceEdge", I32, 1)},
                 {{"edge", "edge", "", K::Edge, "faceEdge", 0, 1}}});
    // Lecture 000, "Independent Faces": each face lists vertex coordinates.
    t.push_back({R::IndependentFaces, "faces", "FACE TABLE (each face lists vertex coordinates)", K::Face,
                 {offsets("faceOffsets"), list("cornerPositions", "faceOffsets", F64, 3)},
                 {{"corners", "corners (x, y, z)", "", K::None, "cornerPositions", 0, 3}}});
    // Lecture 000, "Vertex and Face Tables": each face lists vertex references.
    t.push_back({R::VertexFaceTables, "vertices", "VERTEX TABLE", K::Vertex, {rows("positions", F64, 3)}, xyz("X", "Y", "Z")});
    t.push_back({R::VertexFaceTables, "faces", "FACE TABLE (each face lists vertex references)", K::Face,
                 {offsets("faceOffsets"), list("faceVertices", "faceOffsets")}, {csr("vertices", K::Vertex, "faceVertices")}});
    // Lecture 000, "Adjacency Lists": all nine relations (representations.h for the orders).
    t.push_back({R::AdjacencyLists, "vertices", "Adjacency lists: per vertex", K::Vertex,
                 {rows("positions", F64, 3), offsets("vertexOffsets"), list("vertexVertices", "vertexOffsets"),
                  list("vertexEdges", "vertexOffsets"), offsets("vertexFaceOffsets"), list("vertexFaces", "vertexFaceOffsets")},
                 {position(), csr("vertices", K::Vertex, "vertexVertices"), csr("edges", K::Edge, "vertexEdges"),
                  csr("faces", K::Face, "vertexFaces")}});
    t.push_back({R::AdjacencyLists, "edges", "Adjacency lists: per edge", K::Edge,
                 {rows("edgeVertices", I32, 2), offsets("edgeEdgeOffsets"), list("edgeEdges", "edgeEdgeOffsets"), rows("edgeFaces", I32, 2)},
                 {{"vertices", "vertices", "", K::Vertex, "edgeVertices", 0, 2}, csr("edges", K::Edge, "edgeEdges"),
                  {"faces", "faces", "", K::Face, "edgeFaces", 0, 2}}});
    t.push_back({R::AdjacencyLists, "faces", "Adjacency lists: per face", K::Face,
                 {offsets("faceOffsets"), list("faceVertices", "faceOffsets"), list("faceEdges", "faceOffsets"), list("faceFaces", "faceOffsets")},
                 {csr("vertices", K::Vertex, "faceVertices"), csr("edges", K::Edge, "faceEdges"), csr("faces", K::Face, "faceFaces")}});
    // Partial adjacency lists: VE, EV, EF, FE only.
    t.push_back({R::PartialAdjacencyLists, "vertices", "Partial adjacency lists: per vertex", K::Vertex,
                 {rows("positions", F64, 3), offsets("vertexOffsets"), list("vertexEdges", "vertexOffsets")},
                 {position(), csr("edges", K::Edge, "vertexEdges")}});
    t.push_back({R::PartialAdjacencyLists, "edges", "Partial adjacency lists: per edge", K::Edge,
                 {rows("edgeVertices", I32, 2), rows("edgeFaces", I32, 2)},
                 {{"vertices", "vertices", "", K::Vertex, "edgeVertices", 0, 2}, {"faces", "faces", "", K::Face, "edgeFaces", 0, 2}}});
    t.push_back({R::PartialAdjacencyLists, "faces", "Partial adjacency lists: per face", K::Face,
                 {offsets("faceOffsets"), list("faceEdges", "faceOffsets")}, {csr("edges", K::Edge, "faceEdges")}});
    // Lecture 001, Foley & van Dam's pointers to an edge list.
    t.push_back({R::EdgeList, "vertices", "V = (V\u2081, V\u2082, \u2026)", K::Vertex, {rows("positions", F64, 3)}, {position("(x, y, z)")}});
    t.push_back({R::EdgeList, "edges", "E\u1d62 = (V\u2081, V\u2082, P\u2081, P\u2082)   (\u03bb: no polygon on that side)", K::Edge,
                 {rows("edges", I32, 4)},
                 {{"v1", "V\u2081", "", K::Vertex, "edges", 0, 1},
                  {"v2", "V\u2082", "", K::Vertex, "edges", 1, 1},
                  {"p1", "P\u2081", "", K::Face, "edges", 2, 1},
                  {"p2", "P\u2082", "", K::Face, "edges", 3, 1}}});
    t.push_back({R::EdgeList, "polygons", "P\u1d62 = (E\u2026)", K::Face, {offsets("polygonOffsets"), list("polygonEdges", "polygonOffsets")},
                 {csr("edges", K::Edge, "polygonEdges")}});
    return t;
}

ArrayData view(const std::vector<double>& v) { return {v.data(), nullptr, v.size()}; }
ArrayData view(const std::vector<int32_t>& v) { return {nullptr, v.data(), v.size()}; }

// The named arrays of one table, in its descriptor's order; a described array with no
// vector (or a vector of the wrong type) is a programming error caught by the native tests.
TableData bind(const TableDescriptor& d, std::initializer_list<std::pair<const char*, ArrayData>> named) {
    TableData t;
    t.descriptor = &d;
    for (const ArrayDescriptor& a : d.arrays) {
        const ArrayData* found = nullptr;
        for (const auto& [name, data] : named)
            if (std::string(name) == a.name) found = &data;
        if (found == nullptr || (a.type == F64) != (found->f64 != nullptr))
            throw std::logic_error(std::string("table ") + d.name + ": no " + (a.type == F64 ? "double" : "int32") + " array '" + a.name + "'");
        t.arrays.push_back(*found);
    }
    const ArrayDescriptor& a0 = d.arrays.front();
    const std::size_t n = t.arrays.front().size;
    t.rows = static_cast<int32_t>(a0.role == ArrayRole::Offsets ? (n == 0 ? 0 : n - 1) : n / a0.stride);
    return t;
}

} // namespace

const char* element_kind_name(ElementKind k) {
    switch (k) {
    case ElementKind::Vertex: return "vertex";
    case ElementKind::Edge: return "edge";
    case ElementKind::Face: return "face";
    case ElementKind::None: break;
    }
    return "";
}

const ArrayDescriptor& TableDescriptor::array(const std::string& wanted) const {
    for (const ArrayDescriptor& a : arrays)
        if (wanted == a.name) return a;
    throw std::out_of_range(std::string("table ") + name + " has no array " + wanted);
}

const std::vector<TableDescriptor>& table_descriptors() {
    static const std::vector<TableDescriptor> all = describe();
    return all;
}

std::vector<TableData> representation_tables(Representation r, const Representations* reps, const WingedEdgeMesh& w) {
    if (r != R::WingedEdge && reps == nullptr)
        throw Error("representations-not-built", "the other representations of this mesh have not been built yet");
    std::vector<TableData> out;
    for (const TableDescriptor& d : table_descriptors()) {
        if (d.representation != r) continue;
        const std::string table = d.name;
        switch (r) {
        case R::WingedEdge: {
            const ArrayData edges{nullptr, reinterpret_cast<const int32_t*>(w.edges().data()), 8 * w.edges().size()};
            out.push_back(bind(d, {{"positions", view(w.positions())}, {"vertexEdge", view(w.vertex_edges())},
                                   {"edges", edges}, {"faceEdge", view(w.face_edges())}}));
            break;
        }
        case R::IndependentFaces: {
            const IndependentFaces& i = reps->independent_faces;
            out.push_back(bind(d, {{"faceOffsets", view(i.face_offsets)}, {"cornerPositions", view(i.corner_positions)}}));
            break;
        }
        case R::VertexFaceTables: {
            const VertexFaceTables& v = reps->vertex_face_tables;
            out.push_back(bind(d, {{"positions", view(v.positions)}, {"faceOffsets", view(v.face_offsets)}, {"faceVertices", view(v.face_vertices)}}));
            break;
        }
        case R::AdjacencyLists: {
            const AdjacencyLists& a = reps->adjacency_lists;
            out.push_back(bind(d, {{"positions", view(a.positions)}, {"vertexOffsets", view(a.vertex_offsets)},
                                   {"vertexVertices", view(a.vertex_vertices)}, {"vertexEdges", view(a.vertex_edges)},
                                   {"vertexFaceOffsets", view(a.vertex_face_offsets)}, {"vertexFaces", view(a.vertex_faces)},
                                   {"edgeVertices", view(a.edge_vertices)}, {"edgeEdgeOffsets", view(a.edge_edge_offsets)},
                                   {"edgeEdges", view(a.edge_edges)}, {"edgeFaces", view(a.edge_faces)},
                                   {"faceOffsets", view(a.face_offsets)}, {"faceVertices", view(a.face_vertices)},
                                   {"faceEdges", view(a.face_edges)}, {"faceFaces", view(a.face_faces)}}));
            break;
        }
        case R::PartialAdjacencyLists: {
            const PartialAdjacencyLists& p = reps->partial_adjacency_lists;
            out.push_back(bind(d, {{"positions", view(p.positions)}, {"vertexOffsets", view(p.vertex_offsets)},
                                   {"vertexEdges", view(p.vertex_edges)}, {"edgeVertices", view(p.edge_vertices)},
                                   {"edgeFaces", view(p.edge_faces)}, {"faceOffsets", view(p.face_offsets)},
                                   {"faceEdges", view(p.face_edges)}}));
            break;
        }
        case R::EdgeList: {
            const EdgeList& l = reps->edge_list;
            out.push_back(bind(d, {{"positions", view(l.positions)}, {"edges", view(l.edges)},
                                   {"polygonOffsets", view(l.polygon_offsets)}, {"polygonEdges", view(l.polygon_edges)}}));
            break;
        }
        }
    }
    return out;
}

std::vector<std::string> table_layout_problems(const TableData& t, int32_t vertices, int32_t edges, int32_t faces) {
    std::vector<std::string> problems;
    const TableDescriptor& d = *t.descriptor;
    const std::string where = std::string(representation_key(d.representation)) + "/" + d.name;
    const auto say = [&](const std::string& s) { problems.push_back(where + ": " + s); };
    const std::size_t n = static_cast<std::size_t>(t.rows);
    for (std::size_t i = 0; i < d.arrays.size(); ++i) {
        const ArrayDescriptor& a = d.arrays[i];
        const ArrayData& data = t.arrays[i];
        if (a.role == ArrayRole::Rows && data.size != n * a.stride)
            say(std::string(a.name) + " holds " + std::to_string(data.size) + " numbers, not stride " + std::to_string(a.stride) + " x " + std::to_string(n) + " rows");
        if (a.role == ArrayRole::Offsets) {
            if (data.size != n + 1) say(std::string(a.name) + " has " + std::to_string(data.size) + " offsets for " + std::to_string(n) + " rows");
            else if (data.at(0) != 0) say(std::string(a.name) + " does not start at 0");
            for (std::size_t k = 1; k < data.size; ++k)
                if (data.at(k) < data.at(k - 1)) { say(std::string(a.name) + " decreases at row " + std::to_string(k - 1)); break; }
        }
        if (a.role == ArrayRole::List) {
            std::size_t k = 0;
            while (k < d.arrays.size() && std::string(d.arrays[k].name) != a.offsets) ++k;
            if (k == d.arrays.size() || d.arrays[k].role != ArrayRole::Offsets) { say(std::string(a.name) + " names no offsets array"); continue; }
            const ArrayData& off = t.arrays[k];
            const std::size_t items = off.size == 0 ? 0 : static_cast<std::size_t>(off.at(off.size - 1));
            if (data.size != items * a.stride)
                say(std::string(a.name) + " holds " + std::to_string(data.size) + " numbers, not " + std::to_string(a.stride) + " x " + std::to_string(items) + " items");
        }
    }
    const auto limit = [&](ElementKind k) { return k == ElementKind::Vertex ? vertices : k == ElementKind::Edge ? edges : faces; };
    const std::size_t own = static_cast<std::size_t>(limit(d.rows));
    if (n != own) say(std::to_string(n) + " rows, but the mesh has " + std::to_string(own) + " " + element_kind_name(d.rows) + "s");
    for (const ColumnDescriptor& c : d.columns) {
        std::size_t i = 0;
        while (i < d.arrays.size() && std::string(d.arrays[i].name) != c.array) ++i;
        if (i == d.arrays.size() || d.arrays[i].role == ArrayRole::Offsets) { say(std::string("column ") + c.name + " names no data array"); continue; }
        const ArrayDescriptor& a = d.arrays[i];
        if (a.role == ArrayRole::Rows ? c.first + c.width > a.stride : (c.first != 0 || c.width != a.stride))
            say(std::string("column ") + c.name + " lies outside its array's stride");
        if (c.refers == ElementKind::None) continue;
        if (a.type != ScalarType::Int32) { say(std::string("column ") + c.name + " refers to elements but holds doubles"); continue; }
        const int32_t top = limit(c.refers);
        for (std::size_t k = 0; k < t.arrays[i].size; ++k) {
            if (a.role == ArrayRole::Rows && static_cast<int>(k % a.stride) - c.first >= c.width) continue;
            if (a.role == ArrayRole::Rows && static_cast<int>(k % a.stride) < c.first) continue;
            const int32_t x = t.arrays[i].at(k);
            if (x < -1 || x >= top) { say(std::string("column ") + c.name + " names " + std::to_string(x) + ", outside -1.." + std::to_string(top - 1)); break; }
        }
    }
    return problems;
}

} // namespace wingspline::mesh

// ------------------------------------------------------------------ what an edit rewrote
namespace wingspline::mesh {
namespace {

// The numbers of one array as doubles (coordinates stay exact; int32 indices are exact too).
double number_at(const ArrayData& a, std::size_t i) { return a.f64 != nullptr ? a.f64[i] : static_cast<double>(a.i32[i]); }

// Entries of one column rewritten between two states of a table, row by row by element
// number: a fixed cell that differs in any of its `width` numbers counts `width` (a
// position is written as three numbers); in a list everything from the first item that
// differs to its end counts (a list stored packed shifts its tail when an item is
// inserted or removed); a row only one state has counts whole.
int64_t column_differences(const TableDescriptor& d, const ColumnDescriptor& c, const TableData& a, const TableData& b) {
    std::size_t array = 0;
    while (std::string(d.arrays[array].name) != c.array) ++array;
    const ArrayDescriptor& ad = d.arrays[array];
    const ArrayData& xa = a.arrays[array];
    const ArrayData& xb = b.arrays[array];
    int64_t count = 0;
    const int32_t rows = std::max(a.rows, b.rows);
    const auto same_item = [&](std::size_t at_a, std::size_t at_b) {
        for (int k = 0; k < c.width; ++k)
            if (number_at(xa, at_a + k) != number_at(xb, at_b + k)) return false;
        return true;
    };
    if (ad.role == ArrayRole::Rows) {
        for (int32_t i = 0; i < rows; ++i) {
            const std::size_t at = static_cast<std::size_t>(i) * ad.stride + c.first;
            if (i >= a.rows || i >= b.rows || !same_item(at, at)) count += c.width;
        }
        return count;
    }
    std::size_t offsets = 0;
    while (std::string(d.arrays[offsets].name) != ad.offsets) ++offsets;
    const ArrayData& oa = a.arrays[offsets];
    const ArrayData& ob = b.arrays[offsets];
    const auto list = [&](const ArrayData& o, const TableData& t, int32_t i) -> std::pair<std::size_t, std::size_t> {
        if (i >= t.rows) return {0, 0};
        const std::size_t base = static_cast<std::size_t>(o.at(0));
        return {static_cast<std::size_t>(o.at(i)) - base, static_cast<std::size_t>(o.at(i + 1)) - base};
    };
    for (int32_t i = 0; i < rows; ++i) {
        const auto [a0, a1] = list(oa, a, i);
        const auto [b0, b1] = list(ob, b, i);
        const std::size_t na = a1 - a0, nb = b1 - b0, common = std::min(na, nb);
        std::size_t k = 0;
        while (k < common && same_item((a0 + k) * c.width, (b0 + k) * c.width)) ++k;
        count += static_cast<int64_t>((std::max(na, nb) - k) * c.width);
    }
    return count;
}

} // namespace

std::array<int64_t, kRepresentationCount> rewritten_entries(const WingedEdgeMesh& before, const Representations& before_reps,
                                                            const WingedEdgeMesh& after, const Representations& after_reps) {
    std::array<int64_t, kRepresentationCount> out{};
    for (int r = 0; r < kRepresentationCount; ++r) {
        const auto rep = static_cast<Representation>(r);
        const std::vector<TableData> a = representation_tables(rep, &before_reps, before);
        const std::vector<TableData> b = representation_tables(rep, &after_reps, after);
        for (std::size_t t = 0; t < a.size(); ++t)
            for (const ColumnDescriptor& c : a[t].descriptor->columns) out[r] += column_differences(*a[t].descriptor, c, a[t], b[t]);
    }
    return out;
}

std::array<int64_t, kRepresentationCount> rewritten_entries(const ChangeRecord& change, const Representations& before_reps,
                                                            const WingedEdgeMesh& after, const Representations& after_reps) {
    std::array<int64_t, kRepresentationCount> out{};
    for (int r = 0; r < kRepresentationCount; ++r) {
        const auto rep = static_cast<Representation>(r);
        if (rep == R::WingedEdge) continue;
        const std::vector<TableData> a = representation_tables(rep, &before_reps, after);
        const std::vector<TableData> b = representation_tables(rep, &after_reps, after);
        for (std::size_t t = 0; t < a.size(); ++t)
            for (const ColumnDescriptor& c : a[t].descriptor->columns) out[r] += column_differences(*a[t].descriptor, c, a[t], b[t]);
    }
    // The winged edge: a row added holds all its entries (a vertex: x, y, z and its edge; an
    // edge: S, E, L, R and four wings; a face: its edge); an existing row the fields its
    // assignments left different (the face table's first corner is not one of the slide's
    // entries) and the coordinates a move changed.
    int64_t& winged = out[static_cast<int>(R::WingedEdge)];
    winged += 4 * static_cast<int64_t>(change.added_vertices.size()) + 8 * static_cast<int64_t>(change.added_edges.size()) +
              static_cast<int64_t>(change.added_faces.size());
    const auto added = [&](MeshTable t, int32_t row) {
        const auto has = [row](const auto& list) { return std::any_of(list.begin(), list.end(), [row](auto h) { return h.idx == row; }); };
        return t == MeshTable::Vertex ? has(change.added_vertices) : t == MeshTable::Edge ? has(change.added_edges) : has(change.added_faces);
    };
    for (const RowChange& row : change.rows) {
        if (added(row.table, row.row)) continue;
        for (const FieldChange& f : row.fields) winged += f.field != "firstCorner" && f.before != f.after;
    }
    for (const PositionChange& p : change.positions) {
        if (added(MeshTable::Vertex, p.vertex)) continue;
        for (int k = 0; k < 3; ++k) winged += p.before[k] != p.after[k];
    }
    return out;
}

} // namespace wingspline::mesh
