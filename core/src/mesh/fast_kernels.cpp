// The fixed-degree kernels beside the lecture's reference path (fast_kernels.h): the two
// counting-sort phases of the winged-edge build with triangles unrolled, the ring walk of
// every vertex and Newell's normals with the lecture's walks inlined. The reference path
// they must agree with: winged_edge.cpp (count_sides, bucket_sides, edges_around_vertex,
// edges_of_face) and planes.cpp (newell_vector, newell_normals_reference).
#include "fast_kernels.h"

#include "wingspline/mesh/planes.h"

#include <cmath>

namespace wingspline::mesh {
namespace detail {

bool count_sides_fast(const IndexedMesh& mesh, int32_t* count) {
    const int32_t V = mesh.vertex_count();
    const int32_t F = mesh.face_count();
    const std::vector<int32_t>& fo = mesh.face_offsets;
    const std::vector<int32_t>& fv = mesh.face_vertices;
    // Per face: check the corners, then count its sides into the bucket of their lower
    // vertex (a counting sort). Sides are visited last to first, so each side's end corner
    // is the one visited just before: one load per side, no wrap-around test.
    for (int32_t f = 0; f < F; ++f) {
        const int32_t o = fo[f], n = fo[f + 1] - o;
        if (n == 3) {
            // Triangles (most meshes): unrolled, unsigned compare for 0 <= index < V.
            const int32_t a = fv[o], b = fv[o + 1], c = fv[o + 2];
            if (static_cast<uint32_t>(a) >= static_cast<uint32_t>(V) || static_cast<uint32_t>(b) >= static_cast<uint32_t>(V) ||
                static_cast<uint32_t>(c) >= static_cast<uint32_t>(V) || a == b || b == c || a == c)
                return false;
            ++count[a < b ? a : b];
            ++count[b < c ? b : c];
            ++count[c < a ? c : a];
            continue;
        }
        // n < 3 first: a face without corners has no fv[o] to point at.
        if (n < 3 || !face_corners_ok(fv.data() + o, n, V)) return false;
        for (int32_t h = o + n - 1, b = fv[o]; h >= o; --h) {
            const int32_t a = fv[h];
            ++count[a < b ? a : b];
            b = a;
        }
    }
    return true;
}

void bucket_sides_fast(const IndexedMesh& mesh, int32_t* bucket_end, BucketSlot* slots) {
    const int32_t F = mesh.face_count();
    const std::vector<int32_t>& fo = mesh.face_offsets;
    const std::vector<int32_t>& fv = mesh.face_vertices;
    for (int32_t f = 0; f < F; ++f) {
        const int32_t o = fo[f], n = fo[f + 1] - o;
        if (n == 3) {
            const int32_t a = fv[o], b = fv[o + 1], c = fv[o + 2];
            put_side(slots, bucket_end, o, a, b);
            put_side(slots, bucket_end, o + 1, b, c);
            put_side(slots, bucket_end, o + 2, c, a);
            continue;
        }
        for (int32_t h = o + n - 1, b = fv[o]; h >= o; --h) {
            const int32_t a = fv[h];
            put_side(slots, bucket_end, h, a, b);
            b = a;
        }
    }
}

} // namespace detail

RingWalkTotals WingedEdgeMesh::walk_every_ring() const {
    RingWalkTotals totals;
    detail::walk_every_ring_fast(*this, [&](int32_t, int32_t, int32_t neighbour) {
        totals.visited += 1;
        totals.neighbour_sum += neighbour;
    });
    return totals;
}

void newell_normals(const WingedEdgeMesh& mesh, double* normals) {
    // Walk each face's edges by the lecture's rule (L: the next edge is the end-left wing,
    // R: the start-right wing) and sum Newell's term of each side a -> b the face walks.
    // Measured alternatives (docs/benchmarks.md mesh_normals, three runs each, wasm / native):
    //  * one pass over the edge table, adding each edge's term to L and subtracting it
    //    from R: fastest natively, but up to 2.0x in wasm at 1M faces;
    //  * loading only b and carrying it over as the next side's a: up to 1.9x at 1M;
    //  * selects instead of the kept branch: 1.6-2.0x at every size;
    //  * this walk: at most 1.6x at every size.
    const int32_t F = mesh.face_count();
    const double* p = mesh.positions().data();
    const EdgeRecord* edges = mesh.edges().data();
    for (int32_t f = 0; f < F; ++f) {
        if (mesh.is_deleted(Face(f))) { // a gap left by an edit: no face, no normal
            normals[3 * f] = normals[3 * f + 1] = normals[3 * f + 2] = 0.0;
            continue;
        }
        double sx = 0, sy = 0, sz = 0;
        detail::walk_face_sides_fast(edges, mesh.face_edge(f), f, [&](int32_t a, int32_t b) {
            const double* pa = p + 3 * a;
            const double* pb = p + 3 * b;
            sx += (pa[2] + pb[2]) * (pa[1] - pb[1]);
            sy += (pa[0] + pb[0]) * (pa[2] - pb[2]);
            sz += (pa[1] + pb[1]) * (pa[0] - pb[0]);
        });
        const double len = std::sqrt(sx * sx + sy * sy + sz * sz);
        const double inv = len > 0 ? 1.0 / len : 0.0;
        normals[3 * f] = sx * inv;
        normals[3 * f + 1] = sy * inv;
        normals[3 * f + 2] = sz * inv;
    }
}

} // namespace wingspline::mesh
