// Mesh bindings (issue 3). Meshes live in a C++ registry and JS holds only an integer
// handle: no embind class handle can leak, and mesh.dispose() frees the entry at once.
// Everything else crosses as plain values: typed arrays with documented strides, or small
// objects. Faces cross as CSR: faceOffsets (F + 1 entries) and faceVertices.
#include "boundary.h"
#include "tables.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/mesh_io.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/winged_edge.h"

#include <emscripten/emscripten.h>

#include <algorithm>
#include <memory>
#include <unordered_map>

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// The winged edge is built with the mesh; the other representations only on first use
// (meshBuildRepresentations, from the face set read back from the winged edge, or the one
// the JS Mesh keeps when the caller chose the face edges), so a mesh's
// wasm memory is the winged edge's own until a lesson asks for the others.
struct MeshEntry {
    WingedEdgeMesh winged;
    std::unique_ptr<Representations> representations;
};

Representations& representations_of(MeshEntry& m) {
    if (!m.representations)
        throw Error("representations-not-built", "the other representations of this mesh have not been built yet");
    return *m.representations;
}

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
    // A plain loop with the throw on the cold branch: a call in this loop (even an inline
    // require()) goes through a JS trampoline per iteration under Emscripten's exception
    // handling, which made copying a 100k-face mesh in cost a third of building it.
    const int32_t* fo = m.face_offsets.data();
    for (std::size_t i = 1; i < m.face_offsets.size(); ++i)
        if (fo[i] < fo[i - 1]) throw Error("invalid-argument", "face offsets must not decrease");
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
        IndexedMesh m = indexed_from(positions, face_offsets, face_vertices);
        BuildOptions options;
        const std::vector<int32_t> flat = to_ints(edges);
        for (std::size_t i = 0; i + 1 < flat.size(); i += 2) options.edges.push_back({flat[i], flat[i + 1]});
        options.vertex_edges = to_ints(vertex_edges);
        options.face_edges = to_ints(face_edges);
        auto e = std::make_unique<MeshEntry>();
        e->winged = WingedEdgeMesh::build(std::move(m), options); // positions taken, not copied
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
// crossCorners: Int32Array (3 per face), the vertices used as P1, P2, P3. The faces as
// given: the other representations' vertex and face tables when built (the JS Mesh builds
// them first when faceEdges were chosen), otherwise read back from the winged edge, which
// with the default face edges is the same face set.
val mesh_planes(int32_t handle) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        const auto planes = m.representations
                                ? face_planes(m.winged, m.representations->vertex_face_tables.face_offsets,
                                              m.representations->vertex_face_tables.face_vertices)
                                : face_planes(m.winged);
        std::vector<double> cross, newell, residual;
        std::vector<int32_t> corners;
        for (const auto& p : planes) {
            corners.insert(corners.end(), p.cross_corners.begin(), p.cross_corners.end());
            cross.insert(cross.end(), {p.cross.x, p.cross.y, p.cross.z, p.cross.w});
            newell.insert(newell.end(), {p.newell.x, p.newell.y, p.newell.z, p.newell.w});
            residual.push_back(p.residual);
        }
        val r = val::object();
        r.set("cross", to_typed_array(cross));
        r.set("crossCorners", to_typed_array(corners));
        r.set("newell", to_typed_array(newell));
        r.set("residual", to_typed_array(residual));
        return r;
    });
}

// {normals: Float64Array (3 per face)}, Newell unit normals. With `into` (a Float64Array
// of 3F numbers the JS layer checked) the result is copied into it instead of a new array:
// a caller that recomputes often (a drag, the benchmark) allocates nothing per call, as the
// native code reusing its vector. The scratch buffer is not zero-filled (all written).
val mesh_normals(int32_t handle, val into) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        const std::size_t n = 3 * static_cast<std::size_t>(w.face_count());
        std::unique_ptr<double[]> scratch(new double[n]);
        newell_normals(w, scratch.get());
        const double* data = scratch.get();
        val r = val::object();
        if (into.isNull()) {
            r.set("normals", to_typed_array(data, n));
        } else {
            // The view lives only for this call; nothing allocates between making and using it.
            into.call<void>("set", val(emscripten::typed_memory_view(n, data)));
            r.set("normals", into);
        }
        return r;
    });
}

// {min, max, centre: Float64Array(3) each}: the bounding box a 3D view turns about (issue 13).
val mesh_bounding_box(int32_t handle) {
    return guarded([&] {
        const BoundingBox b = bounding_box(entry(handle).winged);
        const glm::dvec3 c = b.centre();
        val r = val::object();
        r.set("min", to_typed_array(std::vector<double>{b.min.x, b.min.y, b.min.z}));
        r.set("max", to_typed_array(std::vector<double>{b.max.x, b.max.y, b.max.z}));
        r.set("centre", to_typed_array(std::vector<double>{c.x, c.y, c.z}));
        return r;
    });
}

// {normal: Float64Array(3)}: the area-weighted unit normal at vertex v (0 0 0 if none).
val mesh_vertex_normal(int32_t handle, int32_t v) {
    return guarded([&] {
        const glm::dvec3 n = vertex_normal(entry(handle).winged, v);
        val r = val::object();
        r.set("normal", to_typed_array(std::vector<double>{n.x, n.y, n.z}));
        return r;
    });
}

// ------------------------------------------------------------------ benchmark only

// The native benchmark times the core's work on data already in memory; these time the
// same work inside the module (emscripten_get_now, ms) so the wasm and native figures
// compare like for like. The JS API figures add the boundary: copies in and out.
val bench_build_in_core(val positions, val face_offsets, val face_vertices, int32_t repetitions) {
    return guarded([&] {
        const IndexedMesh m = indexed_from(positions, face_offsets, face_vertices);
        std::vector<double> seconds;
        double checksum = 0;
        for (int32_t i = 0; i < repetitions; ++i) {
            const double t0 = emscripten_get_now();
            const WingedEdgeMesh w = WingedEdgeMesh::build(m);
            seconds.push_back((emscripten_get_now() - t0) / 1000.0);
            checksum += w.edge(w.edge_count() - 1).end_right + w.edge_count();
        }
        val r = val::object();
        r.set("seconds", to_typed_array(seconds));
        r.set("checksum", checksum);
        return r;
    });
}

val bench_normals_in_core(int32_t handle, int32_t repetitions) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        std::vector<double> normals, seconds;
        double checksum = 0;
        for (int32_t i = 0; i < repetitions; ++i) {
            const double t0 = emscripten_get_now();
            newell_normals(w, normals);
            seconds.push_back((emscripten_get_now() - t0) / 1000.0);
            checksum += normals[0] + normals[normals.size() - 1];
        }
        val r = val::object();
        r.set("seconds", to_typed_array(seconds));
        r.set("checksum", checksum);
        return r;
    });
}

// Moves one vertex in every representation; reports how many xyz copies each rewrote.
val mesh_set_vertex_position(int32_t handle, int32_t v, double x, double y, double z) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        require_vertex(m.winged, v);
        Representations& reps = representations_of(m);
        m.winged.set_position(v, {x, y, z});
        const auto copies = set_vertex_position(reps, v, {x, y, z});
        val changed = val::object();
        for (int r = 0; r + 1 < kRepresentationCount; ++r) changed.set(representation_key(static_cast<Representation>(r)), copies[r]);
        changed.set(representation_key(Representation::WingedEdge), 1);
        val r = val::object();
        r.set("changedEntries", changed);
        return r;
    });
}

// ------------------------------------------------------------------ the other representations

// Builds the four other representations from the face set the mesh was built from (once).
val mesh_build_representations(int32_t handle, val face_offsets, val face_vertices) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        if (!m.representations) {
            // Without a face set from JS, the faces are read back from the winged edge (the
            // default face edges keep each face's corner order as given).
            IndexedMesh faces;
            if (face_offsets.isNull() || face_offsets.isUndefined()) {
                faces = m.winged.face_set();
            } else {
                faces.positions = m.winged.positions();
                faces.face_offsets = to_ints(face_offsets);
                faces.face_vertices = to_ints(face_vertices);
            }
            m.representations = std::make_unique<Representations>(build_representations(faces, m.winged));
        }
        return val::object();
    });
}

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
        r.set("tables", tables_value(representation_tables(which, m.representations.get(), m.winged), first, rows));
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

// For the benchmark and leak tests: walks every vertex ring (BENCH.md mesh_ring).
val mesh_ring_walk(int32_t handle) {
    return guarded([&] {
        const RingWalkTotals totals = entry(handle).winged.walk_every_ring();
        val r = val::object();
        r.set("visited", totals.visited);
        r.set("checksum", totals.neighbour_sum);
        return r;
    });
}

// ------------------------------------------------------------------ files

// The text arrives as UTF-8 bytes (a Uint8Array the JS layer encoded) and is pulled into
// the module in 64 KB pieces as the reader asks for them (TextSource): a file over the
// limits is refused from its first pieces, never copied whole into the wasm memory, which
// could then never shrink again (issue 13: a refused 55 MB file used to keep it grown).
// check_counts = false lifts the vertex and face counts (benchmarks, large-file tests).
val mesh_parse(val utf8, const std::string& format, bool check_counts) {
    try {
        if (format != "off" && format != "obj")
            throw Error("unknown-format", "unknown mesh format '" + format + "'; use 'off' or 'obj'");
        const std::size_t n = utf8["length"].as<std::size_t>();
        const TextSource source = [&](char* out, std::size_t capacity, std::size_t offset) -> std::size_t {
            const std::size_t k = offset < n ? std::min(capacity, n - offset) : 0;
            if (k == 0) return 0;
            val(emscripten::typed_memory_view(k, reinterpret_cast<unsigned char*>(out)))
                .call<void>("set", utf8.call<val>("subarray", offset, offset + k));
            return k;
        };
        const MeshLimits& limits = check_counts ? kFileLimits : kUnlimitedCounts;
        val r = indexed_value(format == "off" ? parse_off(source, limits) : parse_obj(source, limits));
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

// {maxCoordinate, maxFaceCorners, maxVertices, maxFaces}: limits.h, the one set of mesh limits.
val mesh_limits() {
    return guarded([] {
        val r = val::object();
        r.set("maxCoordinate", kFileLimits.max_coordinate);
        r.set("maxFaceCorners", kFileLimits.max_face_corners);
        r.set("maxVertices", kFileLimits.max_vertices);
        r.set("maxFaces", kFileLimits.max_faces);
        return r;
    });
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
    emscripten::function("meshAdjacency", &mesh_adjacency);
    emscripten::function("meshTraversalSteps", &mesh_traversal_steps);
    emscripten::function("meshFaceEdgeSteps", &mesh_face_edge_steps);
    emscripten::function("meshCounts", &mesh_counts);
    emscripten::function("meshValidate", &mesh_validate);
    emscripten::function("meshNamed", &named_mesh);
    emscripten::function("meshPlanes", &mesh_planes);
    emscripten::function("meshNormals", &mesh_normals);
    emscripten::function("meshBoundingBox", &mesh_bounding_box);
    emscripten::function("meshVertexNormal", &mesh_vertex_normal);
    emscripten::function("meshSetVertexPosition", &mesh_set_vertex_position);
    emscripten::function("meshBytes", &mesh_bytes);
    emscripten::function("meshBuildRepresentations", &mesh_build_representations);
    emscripten::function("meshStorage", &mesh_storage);
    emscripten::function("meshTables", &mesh_tables);
    emscripten::function("meshQuery", &mesh_query);
    emscripten::function("benchBuildInCore", &bench_build_in_core);
    emscripten::function("benchNormalsInCore", &bench_normals_in_core);
    emscripten::function("meshParse", &mesh_parse);
    emscripten::function("meshLimits", &mesh_limits);
    emscripten::function("meshFormat", &mesh_format);
    emscripten::function("meshRingWalk", &mesh_ring_walk);
}
