// Subdivision bindings: Loop and Catmull-Clark steps, their masks and limit
// positions, and curve subdivision. Kept in their own file (the registry is reached through
// mesh_access.h). Results cross as flat typed arrays; a mask table is CSR: maskOffsets
// (one more entry than there are new points), maskVertices, maskWeights.
#include "boundary.h"
#include "mesh_access.h"

#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/subdivision.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// The subdivision limits (limits.h, kSubdivisionLimits, the former import limit of 200,000
// faces): a bigger result is refused with the number of faces it would have.
val mesh_subdivide(int32_t handle, const std::string& scheme, int32_t steps) {
    return guarded([&] {
        WingedEdgeMesh result = subdivide(winged_of_handle(handle), scheme_from_name(scheme), steps, kSubdivisionLimits);
        val r = val::object();
        r.set("handle", register_mesh(std::move(result)));
        return r;
    });
}

val mesh_subdivision_steps(int32_t handle, const std::string& scheme) {
    return guarded([&] {
        const WingedEdgeMesh& w = winged_of_handle(handle);
        const Scheme s = scheme_from_name(scheme);
        const CheckResult check = check_subdivide(w, s, 1, kSubdivisionLimits);
        if (!check.ok) throw Error(check.code, check.message);
        const SubdivisionSteps st = subdivision_steps(w, s);
        val phases = val::array();
        for (std::size_t i = 0; i < st.phases.size(); ++i) {
            val p = val::object();
            p.set("name", st.phases[i].name);
            p.set("first", st.phases[i].first);
            p.set("count", st.phases[i].count);
            phases.set(i, p);
        }
        const IndexedMesh faces = st.result.face_set();
        val r = val::object();
        r.set("phases", phases);
        r.set("maskOffsets", to_typed_array(st.masks.offsets));
        r.set("maskVertices", to_typed_array(st.masks.vertices));
        r.set("maskWeights", to_typed_array(st.masks.weights));
        r.set("rules", to_typed_array(st.rules));
        val names = val::array();
        for (int32_t i = 0; i < kPointRuleCount; ++i) names.set(i, std::string(point_rule_name(i)));
        r.set("ruleNames", names);
        r.set("valences", to_typed_array(st.valences));
        r.set("positions", to_typed_array(st.positions));
        r.set("faceOffsets", to_typed_array(faces.face_offsets));
        r.set("faceVertices", to_typed_array(faces.face_vertices));
        r.set("edges", st.result.edge_count());
        return r;
    });
}

// The reconnection phase as pointer assignments (reconnection_playback): steps as int32,
// 6 each [table, row, field, before, after, line] in the change records' layout
// (meshOperations' tables and fields), the old element of each step, and the lines.
val mesh_reconnection_playback(int32_t handle, const std::string& scheme) {
    return guarded([&] {
        const WingedEdgeMesh& w = winged_of_handle(handle);
        const Scheme s = scheme_from_name(scheme);
        const CheckResult check = check_subdivide(w, s, 1, kSubdivisionLimits);
        if (!check.ok) throw Error(check.code, check.message);
        const ReconnectionPlayback p = reconnection_playback(w, s, subdivide(w, s, 1));
        val lines = val::array();
        for (std::size_t k = 0; k < p.lines.size(); ++k) lines.set(k, p.lines[k]);
        val r = val::object();
        r.set("steps", assignment_steps_array(p.steps));
        r.set("sources", to_typed_array(p.source));
        r.set("lines", lines);
        return r;
    });
}

val mesh_limit_positions(int32_t handle, const std::string& scheme) {
    return guarded([&] {
        val r = val::object();
        r.set("positions", to_typed_array(limit_positions(winged_of_handle(handle), scheme_from_name(scheme))));
        return r;
    });
}


} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_subdivision) {
    using namespace wingspline::bindings;
    emscripten::function("meshSubdivide", &mesh_subdivide);
    emscripten::function("meshSubdivisionSteps", &mesh_subdivision_steps);
    emscripten::function("meshLimitPositions", &mesh_limit_positions);
    emscripten::function("meshReconnectionPlayback", &mesh_reconnection_playback);
}
