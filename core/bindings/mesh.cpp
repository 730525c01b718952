// Mesh bindings (issue 3). Meshes live in a C++ registry and JS holds only an integer
// handle: no embind class handle can leak, and mesh.dispose() frees the entry at once.
// Everything else crosses as plain values: typed arrays with documented strides, or small
// objects. Faces cross as CSR: faceOffsets (F + 1 entries) and faceVertices.
#include "boundary.h"
#include "mesh_access.h"
#include "tables.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/mesh_io.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/tables.h"
#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <map>
#include <memory>
#include <unordered_map>

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// The winged edge is built with the mesh; the other representations are its cache
// (RepresentationCache): derived from the winged edge's current face set on first use and
// again whenever the mesh's version moved on, so a mesh's wasm memory is the winged edge's
// own until a lesson asks for the others, and no operation leaves a stale copy.
struct MeshEntry {
    WingedEdgeMesh winged;
    RepresentationCache representations;
};

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

// Building in steps (issue 17, winged_edge.h WingedEdgeBuild): meshBuildStart reads the
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

// ------------------------------------------------------------------ the winged edge

// A missing element or a gap left by an edit (join-faces, collapse-edge), refused as the
// mesh's own operations refuse them (WingedEdgeMesh::check_element).
void require_vertex(const WingedEdgeMesh& w, int32_t v) { require_ok(w.check_element(Vertex(v))); }
void require_face(const WingedEdgeMesh& w, int32_t f) { require_ok(w.check_element(Face(f))); }
void require_edge(const WingedEdgeMesh& w, int32_t e) { require_ok(w.check_element(Edge(e))); }

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
        // The faces as given: face_set() lists each face from its first corner (issue 14).
        const auto planes = face_planes(entry(handle).winged);
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

// {face, near: Int32Array, distance: Float64Array}: the faces seen along `towards` through
// `point` (issue 17, view_geometry.h pick_faces): the nearest hit face (-1: none) and the
// faces within `radius` of the line of sight, the hit face first.
val mesh_pick(int32_t handle, double px, double py, double pz, double tx, double ty, double tz, double radius, int32_t max_near) {
    return guarded([&] {
        const PickResult p = pick_faces(entry(handle).winged, {px, py, pz}, {tx, ty, tz}, radius, max_near);
        std::vector<int32_t> faces;
        std::vector<double> distances;
        for (const PickNear& n : p.near) faces.push_back(n.face), distances.push_back(n.distance);
        val r = val::object();
        r.set("face", p.face);
        r.set("near", to_typed_array(faces));
        r.set("distance", to_typed_array(distances));
        return r;
    });
}

// {positions: Float64Array, triangles: Int32Array, cell}: the lighter picture drawn while
// the view moves (view_geometry.h display_proxy).
val mesh_display_proxy(int32_t handle, int32_t target) {
    return guarded([&] {
        const DisplayProxy p = display_proxy(entry(handle).winged, target);
        val r = val::object();
        r.set("positions", to_typed_array(p.positions));
        r.set("triangles", to_typed_array(p.triangles));
        r.set("cell", p.cell);
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

// Moves one vertex in every representation; reports how many xyz copies each rewrote.
val mesh_set_vertex_position(int32_t handle, int32_t v, double x, double y, double z) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        require_vertex(m.winged, v);
        m.winged.set_position(v, {x, y, z});
        const auto copies = m.representations.follow_position(m.winged, v, {x, y, z});
        val changed = val::object();
        for (int r = 0; r + 1 < kRepresentationCount; ++r) changed.set(representation_key(static_cast<Representation>(r)), copies[r]);
        changed.set(representation_key(Representation::WingedEdge), 1);
        val r = val::object();
        r.set("changedEntries", changed);
        r.set("version", version_value(m.winged.version()));
        return r;
    });
}

// ------------------------------------------------------------------ the change model

// {topology, geometry}: which state of the mesh this is (winged_edge.h, MeshVersion).
val mesh_version(int32_t handle) {
    return guarded([&] { return version_value(entry(handle).winged.version()); });
}

val element_list(const std::vector<Vertex>& vs, const std::vector<Edge>& es, const std::vector<Face>& fs) {
    const auto ints = [](const auto& hs) {
        std::vector<int32_t> out;
        for (const auto& h : hs) out.push_back(h.idx);
        return int_array(out);
    };
    val r = val::object();
    r.set("vertices", ints(vs));
    r.set("edges", ints(es));
    r.set("faces", ints(fs));
    return r;
}

// {op, added, removed: {vertices, edges, faces}, rows: [{table, row, fields: [{field,
// before, after}]}], before, after: {topology, geometry}}
val change_value(const ChangeRecord& c) {
    val rows = val::array();
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        val fields = val::array();
        for (std::size_t k = 0; k < c.rows[i].fields.size(); ++k) {
            val field = val::object();
            field.set("field", c.rows[i].fields[k].field);
            field.set("before", c.rows[i].fields[k].before);
            field.set("after", c.rows[i].fields[k].after);
            fields.set(k, field);
        }
        val row = val::object();
        row.set("table", std::string(table_name(c.rows[i].table)));
        row.set("row", c.rows[i].row);
        row.set("fields", fields);
        rows.set(i, row);
    }
    // Euler operations: every assignment in order, six int32 per step [table, row, field,
    // before, after, phase] (indices into meshOperationDescriptors().tables / .fields, and
    // into this record's phases), and the positions set, eight numbers each [vertex, before
    // xyz, after xyz, step].
    std::vector<int32_t> steps;
    steps.reserve(6 * c.steps.size());
    for (const AssignmentStep& s : c.steps)
        steps.insert(steps.end(), {static_cast<int32_t>(s.table), s.row, change_field_index(s.field), s.before, s.after, s.phase});
    val phases = val::array();
    for (std::size_t k = 0; k < c.phases.size(); ++k) phases.set(k, c.phases[k]);
    std::vector<double> positions;
    for (const PositionChange& p : c.positions)
        positions.insert(positions.end(), {static_cast<double>(p.vertex), p.before.x, p.before.y, p.before.z, p.after.x, p.after.y,
                                           p.after.z, static_cast<double>(p.step)});
    val r = val::object();
    r.set("op", c.op);
    r.set("steps", to_typed_array(steps));
    r.set("phases", phases);
    r.set("positions", to_typed_array(positions));
    r.set("added", element_list(c.added_vertices, c.added_edges, c.added_faces));
    r.set("removed", element_list(c.removed_vertices, c.removed_edges, c.removed_faces));
    r.set("rows", rows);
    r.set("before", version_value(c.before));
    r.set("after", version_value(c.after));
    return r;
}

// Any operation of the registry (operations.h) by name, its arguments in the entry's order.
// check = true only asks the check ({allowed, code, message}, nothing changed); otherwise
// runs the operation and returns its change record, or the refusal as {ok: false, code,
// message} with the mesh unchanged. cost: also say how many stored entries each
// representation rewrote (rewritten_entries: the winged edge's from the change record, the
// others by comparing their derivations before and after, which the cache hands over
// rather than copies; the lesson asks it only for the edit a person just made).
val mesh_edit(int32_t handle, const std::string& name, const val& args, bool check, bool cost) {
    return guarded([&] {
        MeshEntry& me = entry(handle);
        WingedEdgeMesh& w = me.winged;
        const std::vector<double> a = to_doubles(args);
        const Operation op = operation_from(name, a.data(), a.size());
        if (check) {
            const CheckResult verdict = w.check(op);
            val r = val::object();
            r.set("allowed", verdict.ok);
            r.set("code", verdict.code);
            r.set("message", verdict.message);
            return r;
        }
        std::unique_ptr<Representations> before_reps;
        if (cost && w.check(op).ok) before_reps = me.representations.take(w);
        const ChangeRecord c = w.apply(op);
        val r = change_value(c);
        if (before_reps) {
            const auto n = rewritten_entries(c, *before_reps, w, me.representations.of(w));
            val rewritten = val::object();
            for (int k = 0; k < kRepresentationCount; ++k) rewritten.set(representation_key(static_cast<Representation>(k)), static_cast<double>(n[k]));
            r.set("rewritten", rewritten);
        }
        return r;
    });
}

// {renumbering: {vertices, edges, faces} (old -> new, -1 = removed), version}
val mesh_compact(int32_t handle) {
    return guarded([&] {
        WingedEdgeMesh& w = entry(handle).winged;
        const Renumbering map = w.compact();
        val renumbering = val::object();
        renumbering.set("vertices", int_array(map.vertices));
        renumbering.set("edges", int_array(map.edges));
        renumbering.set("faces", int_array(map.faces));
        val r = val::object();
        r.set("renumbering", renumbering);
        r.set("version", version_value(w.version()));
        return r;
    });
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

// Read once by mesh-api.js: {operations: [{name, title, counts, shortcut, describe,
// arguments: [{name, kind (null for a number), optional, default, choices, label}]}],
// tables, fields, stepStride, positionStride}: the registry (operations.h) as data.
val mesh_operation_descriptors() {
    return guarded([] {
        val ops = val::array();
        const auto& all = operations();
        for (std::size_t k = 0; k < all.size(); ++k) {
            val args = val::array();
            for (std::size_t j = 0; j < all[k].arguments.size(); ++j) {
                const OperationArgument& a = all[k].arguments[j];
                val one = val::object();
                one.set("name", std::string(a.name));
                one.set("kind", a.kind == ElementKind::None ? val::null() : val(std::string(element_kind_name(a.kind))));
                one.set("optional", a.optional);
                one.set("default", a.default_value);
                one.set("choices", a.choices == nullptr ? val::null() : val(std::string(a.choices)));
                one.set("label", std::string(a.label));
                args.set(j, one);
            }
            val op = val::object();
            op.set("name", std::string(all[k].name));
            op.set("title", std::string(all[k].title));
            op.set("counts", std::string(all[k].counts));
            op.set("shortcut", std::string(all[k].shortcut));
            op.set("describe", std::string(all[k].describe));
            op.set("arguments", args);
            ops.set(k, op);
        }
        const auto names = [](const std::vector<const char*>& v) {
            val out = val::array();
            for (std::size_t k = 0; k < v.size(); ++k) out.set(k, std::string(v[k]));
            return out;
        };
        val r = val::object();
        r.set("operations", ops);
        r.set("tables", names(change_tables()));
        r.set("fields", names(change_fields()));
        r.set("stepStride", 6);
        r.set("positionStride", 8);
        return r;
    });
}

// ------------------------------------------------------------------ the other representations

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
    emscripten::function("meshAdjacency", &mesh_adjacency);
    emscripten::function("meshTraversalSteps", &mesh_traversal_steps);
    emscripten::function("meshFaceEdgeSteps", &mesh_face_edge_steps);
    emscripten::function("meshCounts", &mesh_counts);
    emscripten::function("meshValidate", &mesh_validate);
    emscripten::function("meshNamed", &named_mesh);
    emscripten::function("meshPlanes", &mesh_planes);
    emscripten::function("meshNormals", &mesh_normals);
    emscripten::function("meshBoundingBox", &mesh_bounding_box);
    emscripten::function("meshPick", &mesh_pick);
    emscripten::function("meshDisplayProxy", &mesh_display_proxy);
    emscripten::function("meshVertexNormal", &mesh_vertex_normal);
    emscripten::function("meshSetVertexPosition", &mesh_set_vertex_position);
    emscripten::function("meshBytes", &mesh_bytes);
    emscripten::function("meshVersion", &mesh_version);
    emscripten::function("meshEdit", &mesh_edit);
    emscripten::function("meshCompact", &mesh_compact);
    emscripten::function("meshExport", &mesh_export);
    emscripten::function("meshGaps", &mesh_gaps);
    emscripten::function("meshOperationDescriptors", &mesh_operation_descriptors);
    emscripten::function("meshStorage", &mesh_storage);
    emscripten::function("meshTables", &mesh_tables);
    emscripten::function("meshQuery", &mesh_query);
    emscripten::function("meshParse", &mesh_parse);
    emscripten::function("meshLimits", &mesh_limits);
    emscripten::function("meshFormat", &mesh_format);
}
