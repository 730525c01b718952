#include "edit_tasks.h"

#include "mesh/unrecorded.h"

#include "wingspline/mesh/operations.h"

namespace wingspline::bench {

using namespace wingspline::mesh;

int32_t flip_every_third_edge(WingedEdgeMesh& mesh) {
    Operation flip = operation("flip-edge");
    const UnrecordedRun run = unrecorded_run(*flip.entry);
    int32_t flips = 0;
    for (int32_t e = 0; e < mesh.edge_count(); e += 3) {
        flip.args[0] = e;
        flips += run(mesh, flip);
    }
    return flips;
}

int32_t split_every_edge(WingedEdgeMesh& mesh) {
    const int32_t E = mesh.edge_count();
    mesh.reserve(mesh.vertex_count() + E, 4 * E, mesh.face_count() + 2 * E);
    Operation split = operation("split-edge"), cut = operation("split-face");
    const UnrecordedRun run_split = unrecorded_run(*split.entry), run_cut = unrecorded_run(*cut.entry);
    int32_t splits = 0;
    for (int32_t e = 0; e < E; ++e) {
        const EdgeRecord& r = mesh.edge(e);
        // the corners opposite e in its two faces, if they are triangles (read before the split)
        const int32_t E_ = r.end, L = r.left, R = r.right;
        const int32_t c = L != kNone && mesh.next_in_face(r.end_left, L) == r.start_left ? mesh.other_vertex(r.end_left, E_) : kNone;
        const int32_t d = R != kNone && mesh.next_in_face(r.start_right, R) == r.end_right ? mesh.other_vertex(r.end_right, E_) : kNone;
        split.args[0] = e;
        if (!run_split(mesh, split)) continue;
        ++splits;
        const int32_t m = mesh.vertex_count() - 1;
        if (c != kNone) cut.args = {static_cast<double>(L), static_cast<double>(m), static_cast<double>(c), 0}, run_cut(mesh, cut);
        if (d != kNone) cut.args = {static_cast<double>(R), static_cast<double>(m), static_cast<double>(d), 0}, run_cut(mesh, cut);
    }
    return splits;
}

} // namespace wingspline::bench
