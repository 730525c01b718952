// Geometry of a built mesh: plane equations, normals, the bounding box, picking, the display
// proxy of a big mesh, and moving a vertex (followed by every representation).
#include "boundary.h"
#include "mesh_entry.h"

#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/winged_edge.h"

namespace wingspline::bindings {

val pick_value(const mesh::PickResult& p) {
    std::vector<int32_t> faces;
    std::vector<double> distances;
    for (const mesh::PickNear& n : p.near) faces.push_back(n.face), distances.push_back(n.distance);
    val r = val::object();
    r.set("face", p.face);
    r.set("near", to_typed_array(faces));
    r.set("distance", to_typed_array(distances));
    return r;
}
namespace {

using namespace wingspline::mesh;

// {cross: Float64Array (4 per face: A B C D), newell: Float64Array (4 per face), residual: Float64Array (1 per face)}
// crossCorners: Int32Array (3 per face), the vertices used as P1, P2, P3. The faces as
// given: the other representations' vertex and face tables when built (the JS Mesh builds
// them first when faceEdges were chosen), otherwise read back from the winged edge, which
// with the default face edges is the same face set.
// limit < 0: every face (through the face set); otherwise faces offset .. offset + limit - 1.
val mesh_planes(int32_t handle, int32_t offset, int32_t limit) {
    return guarded([&] {
        // The faces as given: face_set() lists each face from its first corner.
        const WingedEdgeMesh& w = entry(handle).winged;
        const auto planes = limit < 0 ? face_planes(w) : face_planes(w, offset, limit);
        std::vector<double> cross, newell, residual, normals;
        std::vector<int32_t> corners;
        for (const auto& p : planes) {
            corners.insert(corners.end(), p.cross_corners.begin(), p.cross_corners.end());
            cross.insert(cross.end(), {p.cross.x, p.cross.y, p.cross.z, p.cross.w});
            newell.insert(newell.end(), {p.newell.x, p.newell.y, p.newell.z, p.newell.w});
            residual.push_back(p.residual);
            const glm::dvec3 n = p.unit_normal();
            normals.insert(normals.end(), {n.x, n.y, n.z});
        }
        val r = val::object();
        r.set("cross", to_typed_array(cross));
        r.set("crossCorners", to_typed_array(corners));
        r.set("newell", to_typed_array(newell));
        r.set("residual", to_typed_array(residual));
        r.set("normals", to_typed_array(normals));
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

// {min, max, centre: Float64Array(3) each}: the bounding box a 3D view turns about.
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
// `point` (view_geometry.h pick_faces): the nearest hit face (-1: none) and the
// faces within `radius` of the line of sight, the hit face first.
val mesh_pick(int32_t handle, double px, double py, double pz, double tx, double ty, double tz, double radius, int32_t max_near) {
    return guarded([&] {
        return pick_value(pick_faces(entry(handle).winged, {px, py, pz}, {tx, ty, tz}, radius, max_near));
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

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh_geometry) {
    using namespace wingspline::bindings;
    emscripten::function("meshPlanes", &mesh_planes);
    emscripten::function("meshNormals", &mesh_normals);
    emscripten::function("meshBoundingBox", &mesh_bounding_box);
    emscripten::function("meshPick", &mesh_pick);
    emscripten::function("meshDisplayProxy", &mesh_display_proxy);
    emscripten::function("meshVertexNormal", &mesh_vertex_normal);
    emscripten::function("meshSetVertexPosition", &mesh_set_vertex_position);
}
