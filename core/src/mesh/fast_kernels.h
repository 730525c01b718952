#pragma once
// Private to the core (not installed with the public headers): the fixed-degree kernels
// that sit beside the lecture's reference path. Each one computes exactly what a reference
// function computes, only faster (triangles unrolled, walks inlined);
// tests/native/test_mesh_kernels.cpp checks them against the reference on thousands of
// random meshes. docs/architecture.md, "Teaching path and fast kernels".
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>

namespace wingspline::mesh::detail {

// One half-edge in the bucket of its lower vertex: the other vertex, and the half-edge
// index times two plus 1 when it runs from the higher vertex to the lower one.
struct BucketSlot {
    int32_t other;
    int32_t code;
};

// Puts side h, a -> b, into the bucket of its lower vertex (bucket_end[v] = next free slot).
inline void put_side(BucketSlot* slots, int32_t* bucket_end, int32_t h, int32_t a, int32_t b) {
    slots[bucket_end[a < b ? a : b]++] = {a < b ? b : a, 2 * h + (a > b ? 1 : 0)};
}

// A face of n corners the winged edge can hold: 3 <= n <= kMaxFaceCorners (limits.h), each
// an existing vertex, all distinct (winged_edge.cpp).
bool face_corners_ok(const int32_t* corners, int32_t n, int32_t V);

// Build phase 1 (winged_edge.cpp count_sides) with triangles unrolled.
bool count_sides_fast(const IndexedMesh& mesh, int32_t* count);
// Build phase 2 (winged_edge.cpp bucket_sides) with triangles unrolled.
void bucket_sides_fast(const IndexedMesh& mesh, int32_t* bucket_end, BucketSlot* slots);

// The lecture's CCW walk around every vertex in index order (as edges_around_vertex and
// other_vertex give it), with next_ccw inlined: visit(v, e, neighbour) for each edge e met.
template <class Visit>
inline void walk_every_ring_fast(const WingedEdgeMesh& mesh, Visit&& visit) {
    const EdgeRecord* edges = mesh.edges().data();
    // The gap marks read once (null: no gaps), not through is_deleted() per vertex: the
    // vector's bounds reloaded in the loop cost the wasm walk about 10% on sphere_1000000.
    const char* deleted = mesh.deleted_vertices().empty() ? nullptr : mesh.deleted_vertices().data();
    const int32_t* vertex_edges = mesh.vertex_edges().data();
    const int32_t V = mesh.vertex_count();
    for (int32_t v = 0; v < V; ++v) {
        const int32_t first = vertex_edges[v];
        if (first == kNone || (deleted != nullptr && deleted[v])) continue;
        int32_t e = first;
        do {
            const EdgeRecord& r = edges[e];
            const int32_t here = e;
            int32_t neighbour;
            if (r.start == v) {
                neighbour = r.end;
                e = r.start_left;
            } else {
                WINGSPLINE_KEEP_BRANCH();
                neighbour = r.start;
                e = r.end_right;
            }
            visit(v, here, neighbour); // once, after the branch: one copy of the visit's code
        } while (e != first);
    }
}

// The lecture's walk along face f from its stored edge (as edges_of_face gives it), with
// next_in_face inlined: visit(a, b) for each side a -> b in the face's CCW order.
template <class Visit>
inline void walk_face_sides_fast(const EdgeRecord* edges, int32_t first, int32_t f, Visit&& visit) {
    int32_t e = first;
    do {
        const EdgeRecord& r = edges[e];
        if (r.left == f) {
            visit(r.start, r.end);
            e = r.end_left;
        } else {
            WINGSPLINE_KEEP_BRANCH();
            visit(r.end, r.start);
            e = r.start_right;
        }
    } while (e != first);
}

} // namespace wingspline::mesh::detail
