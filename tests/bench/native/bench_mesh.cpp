// docs/benchmarks.md mesh tasks, native: mesh_build, mesh_ring, mesh_normals, mesh_memory on
// sphere_F and grid_F for F = 10k, 100k, 1M; mesh_edit_flip and mesh_edit_split on the
// 10k and 100k inputs.
#include "bench.h"
#include "edit_tasks.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/subdivision.h"
#include "wingspline/mesh/winged_edge.h"

#include <fstream>
#include <malloc.h>
#include <unistd.h>

using namespace wingspline::mesh;
using namespace wingspline::bench;

namespace {

struct Input {
    std::string name;
    IndexedMesh mesh;
};

std::vector<Input> inputs() {
    return {{"sphere_10000", uv_sphere(100, 51)},   {"grid_10000", grid(100, 50)},
            {"sphere_100000", uv_sphere(250, 201)}, {"grid_100000", grid(250, 200)},
            {"sphere_1000000", uv_sphere(1000, 501)}, {"grid_1000000", grid(1000, 500)}};
}

double resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    double size = 0, resident = 0;
    statm >> size >> resident;
    return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

} // namespace

WINGSPLINE_BENCH(mesh) {
    if (!ctx.wants("mesh_memory") && !ctx.wants("mesh_build") && !ctx.wants("mesh_ring") && !ctx.wants("mesh_normals")) return;
    for (const Input& in : inputs()) {
        const double F = in.mesh.face_count();
        // The same rule as tests/bench/wasm/mesh.bench.mjs: a 10k-face task takes well under
        // a millisecond, so it is repeated more to keep the minimum out of the noise.
        const int kRepetitions = F <= 10000 ? 31 : 7;
        if (ctx.wants("mesh_memory")) {
            malloc_trim(0);
            const double before = resident_bytes();
            WingedEdgeMesh m = WingedEdgeMesh::build(in.mesh);
            malloc_trim(0);
            const double growth = resident_bytes() - before;
            std::vector<double> one{growth};
            report("mesh_memory", in.name, F, one, static_cast<double>(m.edge_count()),
                   ",\"unit\":\"B/face\",\"structure_bytes_per_face\":" + std::to_string(m.bytes() / F), "B");
        }
        if (ctx.wants("mesh_build")) {
            double checksum = 0;
            const auto seconds = time_runs(kRepetitions, [&] {
                WingedEdgeMesh m = WingedEdgeMesh::build(in.mesh);
                checksum += m.edge(m.edge_count() - 1).end_right + m.edge_count();
            });
            report("mesh_build", in.name, F, seconds, checksum);
        }
        const WingedEdgeMesh m = WingedEdgeMesh::build(in.mesh);
        if (ctx.wants("mesh_ring")) {
            RingWalkTotals walk;
            const auto seconds = time_runs(kRepetitions, [&] { walk = m.walk_every_ring(); });
            report("mesh_ring", in.name, walk.visited, seconds, walk.neighbour_sum);
        }
        if (ctx.wants("mesh_normals")) {
            std::vector<double> normals;
            double checksum = 0;
            const auto seconds = time_runs(kRepetitions, [&] {
                newell_normals(m, normals);
                checksum += normals[0] + normals[normals.size() - 1];
            });
            report("mesh_normals", in.name, F, seconds, checksum);
        }
    }
}

// The editing tasks change the mesh, so every run starts from a fresh copy (not timed).
WINGSPLINE_BENCH(mesh_edit) {
    if (!ctx.wants("mesh_edit_flip") && !ctx.wants("mesh_edit_split")) return;
    for (const Input& in : inputs()) {
        if (in.mesh.face_count() > 100000) continue;
        const WingedEdgeMesh built = WingedEdgeMesh::build(in.mesh);
        const int kRepetitions = in.mesh.face_count() <= 10000 ? 31 : 7;
        const auto run = [&](const char* task, int32_t (*edit)(WingedEdgeMesh&), double n) {
            std::vector<double> seconds;
            double checksum = 0;
            for (int r = 0; r < kRepetitions; ++r) {
                WingedEdgeMesh m = built;
                const double t0 = now_seconds();
                checksum = edit(m);
                seconds.push_back(now_seconds() - t0);
                checksum += m.edge_count() + m.edge(m.edge_count() - 1).start;
            }
            report(task, in.name, n, seconds, checksum);
        };
        if (ctx.wants("mesh_edit_flip")) run("mesh_edit_flip", &wingspline::bench::flip_every_third_edge, (built.edge_count() + 2) / 3);
        if (ctx.wants("mesh_edit_split")) run("mesh_edit_split", &wingspline::bench::split_every_edge, built.edge_count());
    }
}

// One subdivision step from the built mesh (not timed) to the complete new winged
// edge with positions, on the 10k and 100k inputs. Memory: the result's own bytes and the
// resident growth across one step (the step holds the result and nothing else at the end;
// the peak inside it is the result plus the face walk's few corners).
WINGSPLINE_BENCH(mesh_subdivide) {
    if (!ctx.wants("mesh_subdivide_loop") && !ctx.wants("mesh_subdivide_cc")) return;
    for (const Input& in : inputs()) {
        if (in.mesh.face_count() > 100000) continue;
        const WingedEdgeMesh built = WingedEdgeMesh::build(in.mesh);
        const double F = built.face_count();
        const int kRepetitions = F <= 10000 ? 31 : 7;
        for (const auto& [task, scheme] : {std::pair<const char*, Scheme>{"mesh_subdivide_loop", Scheme::Loop},
                                           std::pair<const char*, Scheme>{"mesh_subdivide_cc", Scheme::CatmullClark}}) {
            if (!ctx.wants(task)) continue;
            double checksum = 0;
            const auto seconds = time_runs(kRepetitions, [&] {
                const WingedEdgeMesh out = subdivide(built, scheme, 1);
                checksum += out.vertex_count() + out.edge_count() + out.face_count() + out.edge(out.edge_count() - 1).end_right +
                            out.positions()[out.positions().size() - 1];
            });
            malloc_trim(0);
            const double before = resident_bytes();
            const WingedEdgeMesh out = subdivide(built, scheme, 1);
            const double growth = resident_bytes() - before;
            report(task, in.name, F, seconds, checksum,
                   ",\"result_bytes_per_input_face\":" + std::to_string(out.bytes() / F) +
                       ",\"resident_growth_per_input_face\":" + std::to_string(growth / F));
        }
    }
}
