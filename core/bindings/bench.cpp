// Benchmark and leak-test bindings (docs/architecture.md, "Teaching path and fast kernels"):
// the native benchmark times the core's work on data already in memory; these time the same
// work inside the module (emscripten_get_now, ms) so the wasm and native figures compare
// like for like. Reached only through web/js/core/bench-hooks.js, never from the student
// API (tests/wasm/module/bench-hooks.test.mjs).
#include "boundary.h"
#include "mesh_access.h"

#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/winged_edge.h"

#include <emscripten/emscripten.h>

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

val bench_build_in_core(val positions, val face_offsets, val face_vertices, int32_t repetitions) {
    return guarded([&] {
        const IndexedMesh m = indexed_from_arrays(positions, face_offsets, face_vertices);
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
        const WingedEdgeMesh& w = winged_of_handle(handle);
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

// Walks every vertex ring (BENCH.md mesh_ring): {visited, checksum}.
val bench_ring_walk(int32_t handle) {
    return guarded([&] {
        const RingWalkTotals totals = winged_of_handle(handle).walk_every_ring();
        val r = val::object();
        r.set("visited", totals.visited);
        r.set("checksum", totals.neighbour_sum);
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_bench) {
    using namespace wingspline::bindings;
    emscripten::function("benchBuildInCore", &bench_build_in_core);
    emscripten::function("benchNormalsInCore", &bench_normals_in_core);
    emscripten::function("benchRingWalk", &bench_ring_walk);
}
