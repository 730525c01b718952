// Benchmark and leak-test bindings (docs/architecture.md, "Teaching path and fast kernels"):
// the native benchmark times the core's work on data already in memory; these time the same
// work inside the module (emscripten_get_now, ms) so the wasm and native figures compare
// like for like. Reached only through web/js/core/bench-hooks.js, never from the student
// API (tests/wasm/module/bench-hooks.test.mjs).
#include "boundary.h"
#include "edit_tasks.h"
#include "mesh_access.h"

#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/subdivision.h"
#include "wingspline/mesh/winged_edge.h"

#include <emscripten/emscripten.h>
#include <malloc.h>

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

// Walks every vertex ring (docs/benchmarks.md mesh_ring): {visited, checksum}.
val bench_ring_walk(int32_t handle) {
    return guarded([&] {
        const RingWalkTotals totals = winged_of_handle(handle).walk_every_ring();
        val r = val::object();
        r.set("visited", totals.visited);
        r.set("checksum", totals.neighbour_sum);
        return r;
    });
}

// docs/benchmarks.md mesh_edit_flip / mesh_edit_split inside the module: each repetition edits a fresh
// copy of the built mesh (the copy is not timed), as the native benchmark does.
val bench_edit_in_core(int32_t handle, const std::string& task, int32_t repetitions) {
    return guarded([&] {
        const WingedEdgeMesh& built = winged_of_handle(handle);
        if (task != "mesh_edit_flip" && task != "mesh_edit_split")
            throw Error("unknown-task", "benchEditInCore times mesh_edit_flip or mesh_edit_split");
        int32_t (*edit)(WingedEdgeMesh&) = task == "mesh_edit_flip" ? &bench::flip_every_third_edge : &bench::split_every_edge;
        std::vector<double> seconds;
        double checksum = 0;
        for (int32_t i = 0; i < repetitions; ++i) {
            WingedEdgeMesh m = built;
            const double t0 = emscripten_get_now();
            checksum = edit(m);
            seconds.push_back((emscripten_get_now() - t0) / 1000.0);
            checksum += m.edge_count() + m.edge(m.edge_count() - 1).start;
        }
        val r = val::object();
        r.set("seconds", to_typed_array(seconds));
        r.set("checksum", checksum);
        r.set("n", task == "mesh_edit_flip" ? (built.edge_count() + 2) / 3 : built.edge_count());
        return r;
    });
}

// docs/benchmarks.md mesh_subdivide_loop / mesh_subdivide_cc inside the module: one step
// from the built mesh to the new winged edge with positions, R times; the bench limits
// (kUnlimitedCounts), not the page's. Also the result's own bytes and the heap growth while
// one result is held (malloc's count, as api.memoryUsage().heapInUse).
val bench_subdivide_in_core(int32_t handle, const std::string& task, int32_t repetitions) {
    return guarded([&] {
        const WingedEdgeMesh& built = winged_of_handle(handle);
        if (task != "mesh_subdivide_loop" && task != "mesh_subdivide_cc")
            throw Error("unknown-task", "benchSubdivideInCore times mesh_subdivide_loop or mesh_subdivide_cc");
        const Scheme scheme = task == "mesh_subdivide_loop" ? Scheme::Loop : Scheme::CatmullClark;
        std::vector<double> seconds;
        double checksum = 0;
        for (int32_t i = 0; i < repetitions; ++i) {
            const double t0 = emscripten_get_now();
            const WingedEdgeMesh out = subdivide(built, scheme, 1);
            seconds.push_back((emscripten_get_now() - t0) / 1000.0);
            checksum += out.vertex_count() + out.edge_count() + out.face_count() + out.edge(out.edge_count() - 1).end_right +
                        out.positions()[out.positions().size() - 1];
        }
        const double before = static_cast<double>(mallinfo().uordblks);
        const WingedEdgeMesh held = subdivide(built, scheme, 1);
        val r = val::object();
        r.set("heapGrowth", static_cast<double>(mallinfo().uordblks) - before);
        r.set("resultBytes", static_cast<double>(held.bytes()));
        r.set("seconds", to_typed_array(seconds));
        r.set("checksum", checksum);
        r.set("n", built.face_count());
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
    emscripten::function("benchEditInCore", &bench_edit_in_core);
    emscripten::function("benchSubdivideInCore", &bench_subdivide_in_core);
}
