// Meshes in and out (the mesh bindings' home): meshes live in a C++ registry and JS holds
// only an integer handle, so no embind class handle can leak and mesh.dispose() frees the
// entry at once. Everything else crosses as plain values: typed arrays with documented
// strides, or small objects; faces cross as CSR (faceOffsets, F + 1 entries, and
// faceVertices). This file builds (at once or in steps), frees, validates, reads and writes
// files and names the example meshes; mesh_walks.cpp, mesh_geometry.cpp, mesh_edit.cpp and
// mesh_representations.cpp hold the rest, each over mesh_entry.h.
#include "boundary.h"
#include "mesh_access.h"
#include "mesh_entry.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/mesh_io.h"
#include "wingspline/mesh/winged_edge.h"

#include <map>
#include <memory>
#include <unordered_map>

namespace wingspline::bindings {

using namespace wingspline::mesh;

const Representations& representations_of(MeshEntry& m) { return m.representations.of(m.winged); }

val version_value(const MeshVersion& v) {
    val r = val::object();
    r.set("topology", static_cast<double>(v.topology));
    r.set("geometry", static_cast<double>(v.geometry));
    return r;
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

// A missing element or a gap left by an edit (join-faces, collapse-edge), refused as the
// mesh's own operations refuse them (WingedEdgeMesh::check_element).
void require_vertex(const WingedEdgeMesh& w, int32_t v) { require_ok(w.check_element(Vertex(v))); }
void require_face(const WingedEdgeMesh& w, int32_t f) { require_ok(w.check_element(Face(f))); }
void require_edge(const WingedEdgeMesh& w, int32_t e) { require_ok(w.check_element(Edge(e))); }

namespace {

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

// The optional numbering of a build: [start, end] per edge (flat), the vertex and face edges.
BuildOptions options_from(const val& edges, const val& vertex_edges, const val& face_edges) {
    BuildOptions options;
    const std::vector<int32_t> flat = to_ints(edges);
    for (std::size_t i = 0; i + 1 < flat.size(); i += 2) options.edges.push_back({flat[i], flat[i + 1]});
    options.vertex_edges = to_ints(vertex_edges);
    options.face_edges = to_ints(face_edges);
    return options;
}

val mesh_build(val positions, val face_offsets, val face_vertices, val edges, val vertex_edges, val face_edges) {
    return guarded_build([&] {
        IndexedMesh m = indexed_from(positions, face_offsets, face_vertices);
        const BuildOptions options = options_from(edges, vertex_edges, face_edges);
        auto e = std::make_unique<MeshEntry>();
        e->winged = WingedEdgeMesh::build(std::move(m), options); // positions taken, not copied
        const int32_t handle = registry().next_handle++;
        registry().meshes.emplace(handle, std::move(e));
        val r = val::object();
        r.set("handle", handle);
        return r;
    });
}

// Building in steps (winged_edge.h WingedEdgeBuild): meshBuildStart reads the
// face set and options as meshBuild does and returns {job}; each meshBuildStep runs one
// phase and returns {done, phase} and, once done, {handle} of the new live mesh. A refused
// step ends the job (its error is meshBuild's); meshBuildCancel ends one early.
std::map<int32_t, std::unique_ptr<WingedEdgeBuild>>& build_jobs() {
    static std::map<int32_t, std::unique_ptr<WingedEdgeBuild>> jobs;
    return jobs;
}
int32_t next_build_job = 1;

val mesh_build_start(val positions, val face_offsets, val face_vertices, val edges, val vertex_edges, val face_edges) {
    return guarded_build([&] {
        IndexedMesh m = indexed_from(positions, face_offsets, face_vertices);
        const int32_t job = next_build_job++;
        auto build = std::make_unique<WingedEdgeBuild>(std::move(m), options_from(edges, vertex_edges, face_edges));
        val r = val::object();
        r.set("job", job);
        r.set("phase", std::string(build->phase()));
        build_jobs().emplace(job, std::move(build));
        return r;
    });
}

val mesh_build_step(int32_t job) {
    return guarded_build([&] {
        const auto it = build_jobs().find(job);
        if (it == build_jobs().end())
            throw Error("invalid-argument", "build " + std::to_string(job) + " is over (done, refused or cancelled) or was never started");
        bool done = false;
        try {
            done = it->second->step();
        } catch (...) {
            build_jobs().erase(it);
            throw;
        }
        val r = val::object();
        r.set("done", done);
        r.set("phase", std::string(it->second->phase()));
        if (done) {
            r.set("handle", register_mesh(it->second->take()));
            build_jobs().erase(it);
        }
        return r;
    });
}

val mesh_build_cancel(int32_t job) {
    return guarded([&] {
        build_jobs().erase(job);
        return val::object();
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

// ------------------------------------------------------------------ files

// The text arrives as UTF-8 bytes (a Uint8Array the JS layer encoded) and is pulled into
// the module in 64 KB pieces as the reader asks for them (TextSource): a file over the
// limits is refused from its first pieces, never copied whole into the wasm memory, which
// could then never shrink again (a refused 55 MB file used to keep it grown).
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
        r.set("maxFaceCorners", kMaxFaceCorners);
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

// The faces as the winged edge holds them now, each from its first corner, a removed face
// with no corners: {faceOffsets, faceVertices}, the face set the other representations are
// derived from, read without deriving them (one walk around each face). `all`: every face;
// otherwise the faces listed (any order, each a face number of the mesh, removed or not), so
// that a page follows an edit by reading again only the faces it changed. Refuses a number
// that is no face ('invalid-element').
val mesh_face_set(int32_t handle, const val& faces, bool all) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        IndexedMesh m;
        if (all) {
            m = w.face_set();
        } else {
            const std::vector<double> list = to_doubles(faces);
            for (const double x : list) {
                if (!(x >= 0 && x < w.face_count() && x == static_cast<double>(static_cast<int32_t>(x))))
                    throw Error("invalid-element", "the face list names a face this mesh does not have");
                const std::vector<int32_t> corners = w.face_corners(static_cast<int32_t>(x));
                m.face_vertices.insert(m.face_vertices.end(), corners.begin(), corners.end());
                m.face_offsets.push_back(static_cast<int32_t>(m.face_vertices.size()));
            }
        }
        val r = val::object();
        r.set("faceOffsets", to_typed_array(m.face_offsets));
        r.set("faceVertices", to_typed_array(m.face_vertices));
        return r;
    });
}

// The edited mesh as a file: the live face set (gaps dropped, numbered as compact() would).
val mesh_export(int32_t handle, const std::string& format) {
    return guarded([&] {
        if (format != "off" && format != "obj")
            throw Error("unknown-format", "unknown mesh format '" + format + "'; use 'off' or 'obj'");
        const IndexedMesh m = entry(handle).winged.live_face_set();
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

// mesh_access.h: what the benchmark bindings (bench.cpp) read from this file.
const WingedEdgeMesh& winged_of_handle(int32_t handle) { return entry(handle).winged; }
IndexedMesh indexed_from_arrays(const val& positions, const val& face_offsets, const val& face_vertices) {
    return indexed_from(positions, face_offsets, face_vertices);
}
int32_t register_mesh(WingedEdgeMesh&& winged) {
    auto e = std::make_unique<MeshEntry>();
    e->winged = std::move(winged);
    const int32_t handle = registry().next_handle++;
    registry().meshes.emplace(handle, std::move(e));
    return handle;
}

} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh) {
    using namespace wingspline::bindings;
    emscripten::function("meshBuild", &mesh_build);
    emscripten::function("meshBuildStart", &mesh_build_start);
    emscripten::function("meshBuildStep", &mesh_build_step);
    emscripten::function("meshBuildCancel", &mesh_build_cancel);
    emscripten::function("meshDispose", &mesh_dispose);
    emscripten::function("meshLiveCount", &mesh_live_count);
    emscripten::function("meshValidateIndexed", &validate_indexed_mesh);
    emscripten::function("meshNamed", &named_mesh);
    emscripten::function("meshExport", &mesh_export);
    emscripten::function("meshFaceSet", &mesh_face_set);
    emscripten::function("meshParse", &mesh_parse);
    emscripten::function("meshLimits", &mesh_limits);
    emscripten::function("meshFormat", &mesh_format);
}
