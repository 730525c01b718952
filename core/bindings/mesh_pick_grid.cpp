// Picking on a big mesh through its pick grid (view_geometry.h PickGrid), kept in the mesh's
// entry: made on the first pick at a view and again after the mesh changed or the view
// turned, so a pointer moving over a still view reads a few cells per move instead of the
// whole mesh. Same arguments and answer as meshPick. In the `edit` group: the mesh lesson's
// modules carry it; the subdivision lesson's picks by the whole pass (its page's budget).
#include "boundary.h"
#include "mesh_entry.h"

#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/winged_edge.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// From this many edges a pick goes through the grid (one pass over the mesh per view, then
// a few cells per pick); below it the pass itself is quicker than making a grid.
constexpr std::size_t kPickGridFromEdges = 30000;

val mesh_pick_grid(int32_t handle, double px, double py, double pz, double tx, double ty, double tz, double radius, int32_t max_near) {
    return guarded([&] {
        MeshEntry& m = entry(handle);
        const glm::dvec3 towards{tx, ty, tz};
        PickResult p;
        if (m.winged.edges().size() < kPickGridFromEdges) {
            p = pick_faces(m.winged, {px, py, pz}, towards, radius, max_near);
        } else {
            if (!m.pick_grid.fits(m.winged, towards)) m.pick_grid.build(m.winged, towards);
            p = m.pick_grid.pick(m.winged, {px, py, pz}, radius, max_near);
        }
        return pick_value(p);
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh_pick_grid) {
    using namespace wingspline::bindings;
    emscripten::function("meshPickGrid", &mesh_pick_grid);
}
