// Mesh bindings (issue 3). Meshes live in a C++ registry and JS holds only an integer
// handle: no embind class handle can leak, and mesh.dispose() frees the entry at once.
// Everything else crosses as plain values: typed arrays with documented strides, or small
// objects. Faces cross as CSR: faceOffsets (F + 1 entries) and faceVertices.
#include "boundary.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/mesh_io.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/winged_edge.h"

#include <malloc.h>
#include <memory>
#include <unordered_map>

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// Only the winged edge is kept: the other representations are derived from it on demand.
struct MeshEntry {
    WingedEdgeMesh winged;
};

struct Registry {
    std::unordered_map<int32_t, std::unique_ptr<MeshEntry>> meshes;
    int32_t next_handle = 1;
};

Registry& registry() {
    static Registry r;
    return r;
}

MeshEntry& entry(int32_t handle) {
    auto it = registry().meshes.find(handle);
    if (it == registry().meshes.end())
        throw Error("disposed", "this mesh has been disposed (or was never built); build it again with buildMesh()");
    return *it->second;
}

val int_array(const std::vector<int32_t>& v) {
    val a = val::array();
    for (std::size_t i = 0; i < v.size(); ++i) a.set(i, v[i]);
    return a;
}

val problem_value(const Problem& p) {
    val r = val::object();
    r.set("code", p.code);
    r.set("severity", std::string(p.severity == Severity::Error ? "error" : "warning"));
    r.set("message", p.message);
    val elements = val::object();
    elements.set("vertices", int_array(p.vertices));
    elements.set("edges", int_array(p.edges));
    elements.set("faces", int_array(p.faces));
    r.set("elements", elements);
    return r;
}

val report_value(const ValidationReport& report) {
    val r = val::object();
    r.set("valid", report.ok());
    val problems = val::array();
    for (std::size_t i = 0; i < report.problems.size(); ++i) problems.set(i, problem_value(report.problems[i]));
    r.set("problems", problems);
    return r;
}

// guarded() rethrows nothing, so InvalidMesh must be caught before it: run body here.
template <class Body> val guarded_build(Body&& body) {
    try {
        val r = body();
        r.set("ok", true);
        return r;
    } catch (const InvalidMesh& e) {
        val r = error_object(e.code(), e.what());
        r.set("details", report_value(e.report())["problems"]);
        return r;
    } catch (...) {
        return guarded([&]() -> val { throw; });
    }
}

IndexedMesh indexed_from(const val& positions, const val& face_offsets, const val& face_vertices) {
    IndexedMesh m;
    m.positions = to_doubles(positions);
    m.face_offsets = to_ints(face_offsets);
    m.face_vertices = to_ints(face_vertices);
    require(m.positions.size() % 3 == 0, "invalid-argument", "positions must hold x, y, z for each vertex (a multiple of 3 numbers)");
    require(!m.face_offsets.empty() && m.face_offsets.front() == 0 &&
                m.face_offsets.back() == static_cast<int32_t>(m.face_vertices.size()),
            "invalid-argument", "face offsets do not match the face vertex list");
    for (std::size_t i = 1; i < m.face_offsets.size(); ++i)
        require(m.face_offsets[i] >= m.face_offsets[i - 1], "invalid-argument", "face offsets must not decrease");
    return m;
}

val indexed_value(const IndexedMesh& m) {
    val r = val::object();
    r.set("positions", to_typed_array(m.positions));
    r.set("faceOffsets", to_typed_array(m.face_offsets));
    r.set("faceVertices", to_typed_array(m.face_vertices));
    return r;
}

val named_value(const NamedMesh& n) {
    val r = indexed_value(n.mesh);
    std::vector<int32_t> flat;
    for (const auto& e : n.options.edges) flat.insert(flat.end(), {e[0], e[1]});
    r.set("edges", to_typed_array(flat));
    r.set("vertexEdges", to_typed_array(n.options.vertex_edges));
    r.set("faceEdges", to_typed_array(n.options.face_edges));
    return r;
}

// ------------------------------------------------------------------ building and freeing

val mesh_build(val positions, val face_offsets, val face_vertices, val edges, val vertex_edges, val face_edges) {
    return guarded_build([&] {
        const IndexedMesh m = indexed_from(positions, face_offsets, face_vertices);
        BuildOptions options;
        const std::vector<int32_t> flat = to_ints(edges);
        for (std::size_t i = 0; i + 1 < flat.size(); i += 2) options.edges.push_back({flat[i], flat[i + 1]});
        options.vertex_edges = to_ints(vertex_edges);
        options.face_edges = to_ints(face_edges);
        auto e = std::make_unique<MeshEntry>();
        e->winged = WingedEdgeMesh::build(m, options);
        const int32_t handle = registry().next_handle++;
        registry().meshes.emplace(handle, std::move(e));
        val r = val::object();
        r.set("handle", handle);
        return r;
    });
}

val mesh_dispose(int32_t handle) {
    return guarded([&] {
        registry().meshes.erase(handle);
        return val::object();
    });
}

val mesh_live_count() {
    return guarded([] {
        val r = val::object();
        r.set("count", static_cast<int32_t>(registry().meshes.size()));
        return r;
    });
}

val validate_indexed_mesh(val positions, val face_offsets, val face_vertices) {
    return guarded([&] { return report_value(validate_indexed(indexed_from(positions, face_offsets, face_vertices))); });
}

// ------------------------------------------------------------------ the winged edge

// {positions: Float64Array (3 per vertex), vertexEdge: Int32Array (1 per vertex),
//  edges: Int32Array (8 per edge: start, end, left, right, startLeft, startRight,
//  endLeft, endRight), faceEdge: Int32Array (1 per face)}
val mesh_winged_edge(int32_t handle) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        std::vector<int32_t> vertex_edge(w.vertex_count()), face_edge(w.face_count());
        for (int32_t v = 0; v < w.vertex_count(); ++v) vertex_edge[v] = w.vertex_edge(v);
        for (int32_t f = 0; f < w.face_count(); ++f) face_edge[f] = w.face_edge(f);
        val r = val::object();
        r.set("positions", to_typed_array(w.positions()));
        r.set("vertexEdge", to_typed_array(vertex_edge));
        r.set("edges", to_typed_array(reinterpret_cast<const int32_t*>(w.edges().data()), 8 * w.edges().size()));
        r.set("faceEdge", to_typed_array(face_edge));
        return r;
    });
}

void require_vertex(const WingedEdgeMesh& w, int32_t v) {
    require(v >= 0 && v < w.vertex_count(), "invalid-element",
            "vertex index " + std::to_string(v) + " is out of range: the mesh has vertices 0 to " + std::to_string(w.vertex_count() - 1));
}
void require_face(const WingedEdgeMesh& w, int32_t f) {
    require(f >= 0 && f < w.face_count(), "invalid-element",
            "face index " + std::to_string(f) + " is out of range: the mesh has faces 0 to " + std::to_string(w.face_count() - 1));
}
void require_edge(const WingedEdgeMesh& w, int32_t e) {
    require(e >= 0 && e < w.edge_count(), "invalid-element",
            "edge index " + std::to_string(e) + " is out of range: the mesh has edges 0 to " + std::to_string(w.edge_count() - 1));
}

// kind: edges-around-vertex, faces-around-vertex, vertices-around-vertex (v);
// edges-of-face, vertices-of-face, face-neighbours (f); faces-of-edge (e).
val mesh_adjacency(int32_t handle, const std::string& kind, int32_t element) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        std::vector<int32_t> out;
        if (kind == "edges-around-vertex" || kind == "faces-around-vertex" || kind == "vertices-around-vertex") {
            require_vertex(w, element);
            out = kind == "edges-around-vertex"   ? w.edges_around_vertex(element)
                  : kind == "faces-around-vertex" ? w.faces_around_vertex(element)
                                                  : w.vertices_around_vertex(element);
        } else if (kind == "edges-of-face" || kind == "vertices-of-face" || kind == "face-neighbours") {
            require_face(w, element);
            out = kind == "edges-of-face"      ? w.edges_of_face(element)
                  : kind == "vertices-of-face" ? w.vertices_of_face(element)
                                               : w.face_neighbours(element);
        } else if (kind == "faces-of-edge") {
            require_edge(w, element);
            const auto lr = w.faces_of_edge(element);
            out.assign(lr.begin(), lr.end());
        } else {
            throw Error("unknown-query", "unknown adjacency query '" + kind + "'");
        }
        val r = val::object();
        r.set("indices", to_typed_array(out));
        return r;
    });
}

// {edges, atStart (1/0), next}: one entry per step of the lecture's CCW walk around v.
val mesh_traversal_steps(int32_t handle, int32_t v) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        require_vertex(w, v);
        std::vector<int32_t> edges, at_start, next;
        for (const auto& s : w.traversal_steps(v)) {
            edges.push_back(s.edge);
            at_start.push_back(s.at_start);
            next.push_back(s.next);
        }
        val r = val::object();
        r.set("edges", to_typed_array(edges));
        r.set("atStart", to_typed_array(at_start));
        r.set("next", to_typed_array(next));
        return r;
    });
}

// {edges, faceIsLeft (1/0), next}: one entry per step along face f.
val mesh_face_edge_steps(int32_t handle, int32_t f) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        require_face(w, f);
        std::vector<int32_t> edges, left, next;
        for (const auto& s : w.face_edge_steps(f)) {
            edges.push_back(s.edge);
            left.push_back(s.face_is_left);
            next.push_back(s.next);
        }
        val r = val::object();
        r.set("edges", to_typed_array(edges));
        r.set("faceIsLeft", to_typed_array(left));
        r.set("next", to_typed_array(next));
        return r;
    });
}

val mesh_counts(int32_t handle) {
    return guarded([&] {
        const MeshCounts c = entry(handle).winged.counts();
        val r = val::object();
        r.set("vertices", c.vertices);
        r.set("edges", c.edges);
        r.set("faces", c.faces);
        r.set("boundaryEdges", c.boundary_edges);
        r.set("boundaryLoops", c.boundary_loops);
        r.set("isolatedVertices", c.isolated_vertices);
        r.set("euler", c.euler());
        return r;
    });
}

val mesh_validate(int32_t handle) {
    return guarded([&] { return report_value(entry(handle).winged.validate()); });
}


// ------------------------------------------------------------------ geometry

// {cross: Float64Array (4 per face: A B C D), newell: Float64Array (4 per face), residual: Float64Array (1 per face)}
val mesh_planes(int32_t handle) {
    return guarded([&] {
        const auto planes = face_planes(entry(handle).winged);
        std::vector<double> cross, newell, residual;
        for (const auto& p : planes) {
            cross.insert(cross.end(), {p.cross.x, p.cross.y, p.cross.z, p.cross.w});
            newell.insert(newell.end(), {p.newell.x, p.newell.y, p.newell.z, p.newell.w});
            residual.push_back(p.residual);
        }
        val r = val::object();
        r.set("cross", to_typed_array(cross));
        r.set("newell", to_typed_array(newell));
        r.set("residual", to_typed_array(residual));
        return r;
    });
}

// {normals: Float64Array (3 per face)}, Newell unit normals.
val mesh_normals(int32_t handle) {
    return guarded([&] {
        std::vector<double> n;
        newell_normals(entry(handle).winged, n);
        val r = val::object();
        r.set("normals", to_typed_array(n));
        return r;
    });
}

// Moves one vertex; reports how many stored entries each representation had to rewrite.
val mesh_set_vertex_position(int32_t handle, int32_t v, double x, double y, double z) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        require_vertex(m.winged, v);
        m.winged.set_position(v, {x, y, z});
        // Independent faces hold one coordinate copy per face corner at v.
        const int32_t copies = static_cast<int32_t>(m.winged.faces_around_vertex(v).size());
        val changed = val::object();
        changed.set("independent-faces", copies);
        changed.set("vertex-face-tables", 1);
        changed.set("adjacency-lists", 1);
        changed.set("edge-list", 1);
        changed.set("winged-edge", 1);
        val r = val::object();
        r.set("changedEntries", changed);
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

// For the benchmark and leak tests: walks every vertex ring (BENCH.md mesh_ring).
val mesh_ring_walk(int32_t handle) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        double checksum = 0, visited = 0;
        for (int32_t v = 0; v < w.vertex_count(); ++v) {
            const int32_t first = w.vertex_edge(v);
            if (first == kNone) continue;
            int32_t e = first;
            do {
                const EdgeRecord& r = w.edge(e);
                checksum += r.start == v ? r.end : r.start;
                visited += 1;
                e = r.start == v ? r.start_left : r.end_right;
            } while (e != first);
        }
        val r = val::object();
        r.set("visited", visited);
        r.set("checksum", checksum);
        return r;
    });
}

// {linearBytes: size of the wasm memory, heapInUse: bytes malloc has handed out}
val memory_usage() {
    return guarded([] {
        val r = val::object();
        r.set("linearBytes", static_cast<double>(__builtin_wasm_memory_size(0)) * 65536.0);
        r.set("heapInUse", static_cast<double>(mallinfo().uordblks));
        return r;
    });
}

// ------------------------------------------------------------------ files

val mesh_parse(const std::string& text, const std::string& format) {
    try {
        if (format != "off" && format != "obj")
            throw Error("unknown-format", "unknown mesh format '" + format + "'; use 'off' or 'obj'");
        val r = indexed_value(format == "off" ? parse_off(text) : parse_obj(text));
        r.set("ok", true);
        return r;
    } catch (const ParseError& e) {
        val r = error_object(e.code(), e.what());
        r.set("line", e.line());
        return r;
    } catch (...) {
        return guarded([&]() -> val { throw; });
    }
}

val mesh_format(val positions, val face_offsets, val face_vertices, const std::string& format) {
    return guarded([&] {
        const IndexedMesh m = indexed_from(positions, face_offsets, face_vertices);
        if (format != "off" && format != "obj")
            throw Error("unknown-format", "unknown mesh format '" + format + "'; use 'off' or 'obj'");
        val r = val::object();
        r.set("text", format == "off" ? format_off(m) : format_obj(m));
        return r;
    });
}

// ------------------------------------------------------------------ named meshes

val named_mesh(const std::string& name, int32_t a, int32_t b) {
    return guarded([&] {
        if (name == "lecture") return named_value(lecture_example());
        if (name == "foley") return named_value(foley_example());
        if (name == "tetrahedron") return indexed_value(tetrahedron());
        if (name == "cube") return indexed_value(cube());
        if (name == "fan") return indexed_value(open_fan(a));
        if (name == "grid") return indexed_value(grid(a, b));
        if (name == "sphere") return indexed_value(uv_sphere(a, b));
        throw Error("unknown-mesh", "unknown mesh '" + name + "'; choose tetrahedron, cube, fan, grid or sphere");
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh) {
    using namespace wingspline::bindings;
    emscripten::function("meshBuild", &mesh_build);
    emscripten::function("meshDispose", &mesh_dispose);
    emscripten::function("meshLiveCount", &mesh_live_count);
    emscripten::function("meshValidateIndexed", &validate_indexed_mesh);
    emscripten::function("meshWingedEdge", &mesh_winged_edge);
    emscripten::function("meshAdjacency", &mesh_adjacency);
    emscripten::function("meshTraversalSteps", &mesh_traversal_steps);
    emscripten::function("meshFaceEdgeSteps", &mesh_face_edge_steps);
    emscripten::function("meshCounts", &mesh_counts);
    emscripten::function("meshValidate", &mesh_validate);
    emscripten::function("meshNamed", &named_mesh);
    emscripten::function("meshPlanes", &mesh_planes);
    emscripten::function("meshNormals", &mesh_normals);
    emscripten::function("meshSetVertexPosition", &mesh_set_vertex_position);
    emscripten::function("meshBytes", &mesh_bytes);
    emscripten::function("meshParse", &mesh_parse);
    emscripten::function("meshFormat", &mesh_format);
    emscripten::function("meshRingWalk", &mesh_ring_walk);
    emscripten::function("memoryUsage", &memory_usage);
}
