#pragma once
// Baumgart's winged-edge structure exactly as in lecture 000: a vertex table (coordinates
// and one incident edge), an edge table (S, E, L, R and the four wings) and a face table
// (one incident edge). Nothing else is kept, so its storage is the slide's storage.
//
// Conventions (decoded from the slide's table and checked against it in the tests):
//  * L is the face that traverses the edge from S to E (faces are counter-clockwise),
//    R the face that traverses it from E to S; a boundary side is kNone.
//  * Wing "X-Y" is the other edge at vertex X of the face on side Y. On a boundary side
//    the boundary loop is treated as a face (the slide: "wing edges are defined as though
//    the boundary was also a face").
//  * CCW around v: from e, if v is e's Start the next edge is start_left, else end_right.
//  * Along face f: from e, if f is e's Left the next edge is end_left, else start_right.
#include "wingspline/mesh/indexed_mesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

// An empty asm statement on one arm of a walk's two-way choice keeps the compiler from
// turning it into a select. With a select, the address of the next edge waits for the
// load of this edge's S (the walk is serialised on memory); with a predicted branch the
// processor walks ahead. Measured on the 1M-face sphere: the ring walk in wasm 8.4 -> 3.5
// ns per edge, natively 3.0 -> 2.9 (clang makes a select for wasm, gcc a branch).
#if defined(__GNUC__) || defined(__clang__)
#define WINGSPLINE_KEEP_BRANCH() __asm__ volatile("")
#else
#define WINGSPLINE_KEEP_BRANCH() ((void)0)
#endif

namespace wingspline::mesh {

// 32 bytes, aligned to 32 so that no record straddles two cache lines: a walk reads one
// line per edge. Unaligned (malloc gives 16), every other record spans two lines, and the
// 1M-face walks measured up to 1.6x slower natively and 1.5x in wasm, depending on where
// the table happened to land.
struct alignas(32) EdgeRecord {
    int32_t start = kNone, end = kNone;  // S, E
    int32_t left = kNone, right = kNone; // L, R faces
    int32_t start_left = kNone, start_right = kNone, end_left = kNone, end_right = kNone;
};

struct BuildOptions {
    // Optional: fixes the edge numbering and orientation, one [start, end] per edge.
    std::vector<std::array<int32_t, 2>> edges;
    // Optional: the edge stored for each vertex / face (each must be incident).
    std::vector<int32_t> vertex_edges;
    std::vector<int32_t> face_edges;
};

struct MeshCounts {
    int32_t vertices = 0, edges = 0, faces = 0, boundary_edges = 0, boundary_loops = 0;
    int32_t isolated_vertices = 0;
    int32_t euler() const { return vertices - edges + faces; }
};

struct TraversalStep {
    int32_t edge = kNone;
    bool at_start = false; // v (or the face's walk) met the edge at its Start
    int32_t next = kNone;  // read from start_left (at_start) or end_right
};

// Every vertex's ring walked once (BENCH.md mesh_ring): edges visited (2E on a mesh
// without isolated vertices) and the sum of the neighbour indices met.
static_assert(sizeof(EdgeRecord) == 8 * sizeof(int32_t), "the edge table crosses the boundary as 8 int32 per edge");

struct RingWalkTotals {
    double visited = 0;
    double neighbour_sum = 0;
};

struct FaceStep {
    int32_t edge = kNone;
    bool face_is_left = false; // next read from end_left (left) or start_right (right)
    int32_t next = kNone;
};

// Removes repeats from v, keeping each element where it first appears (n log n).
void keep_first_appearance(std::vector<int32_t>& v);

class WingedEdgeMesh {
public:
    // Builds the structure. Without options.edges, edges are numbered in order of first
    // appearance walking the faces and oriented as first traversed. Default vertex edge:
    // at a boundary vertex the edge that follows the boundary gap counter-clockwise (so the
    // CCW walk meets all faces before the gap); elsewhere the lowest-numbered incident
    // edge. Default face edge: the edge along the face's first side (its first two corners),
    // so that face_set() reads the faces back with their corners in the order given.
    // Throws InvalidMesh (with the full report) when the winged edge cannot hold the mesh,
    // Error("invalid-edge-list" / "invalid-vertex-edge" / "invalid-face-edge") for bad options.
    static WingedEdgeMesh build(const IndexedMesh& mesh, const BuildOptions& options = {});
    // The same, taking the positions over instead of copying them (a caller that made the
    // face set only to build from it, as the wasm binding does). On refusal `mesh` is intact.
    static WingedEdgeMesh build(IndexedMesh&& mesh, const BuildOptions& options = {});

    int32_t vertex_count() const { return static_cast<int32_t>(vertex_edge_.size()); }
    int32_t edge_count() const { return static_cast<int32_t>(edges_.size()); }
    int32_t face_count() const { return static_cast<int32_t>(face_edge_.size()); }

    const EdgeRecord& edge(int32_t e) const { return edges_[e]; }
    int32_t vertex_edge(int32_t v) const { return vertex_edge_[v]; }
    int32_t face_edge(int32_t f) const { return face_edge_[f]; }
    glm::dvec3 position(int32_t v) const {
        return {positions_[3 * v], positions_[3 * v + 1], positions_[3 * v + 2]};
    }
    const std::vector<double>& positions() const { return positions_; }
    const std::vector<EdgeRecord>& edges() const { return edges_; }
    const std::vector<int32_t>& vertex_edges() const { return vertex_edge_; } // the vertex table's edge column
    const std::vector<int32_t>& face_edges() const { return face_edge_; }     // the face table
    // Throws Error("non-finite-coordinate" / "coordinate-out-of-range") beyond kMaxCoordinate
    // (limits.h) and then changes nothing.
    void set_position(int32_t v, const glm::dvec3& p);

    // The lecture's rule, one step: the edge after e counter-clockwise around v.
    int32_t next_ccw(int32_t e, int32_t v) const {
        const EdgeRecord& r = edges_[e];
        if (r.start == v) return r.start_left;
        WINGSPLINE_KEEP_BRANCH();
        return r.end_right;
    }
    // The edge after e along face f (counter-clockwise).
    int32_t next_in_face(int32_t e, int32_t f) const {
        const EdgeRecord& r = edges_[e];
        if (r.left == f) return r.end_left;
        WINGSPLINE_KEEP_BRANCH();
        return r.start_right;
    }
    int32_t other_vertex(int32_t e, int32_t v) const {
        return edges_[e].start == v ? edges_[e].end : edges_[e].start;
    }

    std::vector<int32_t> edges_around_vertex(int32_t v) const;
    // For every vertex in index order, the CCW walk by the lecture's rule (no lists built).
    RingWalkTotals walk_every_ring() const;
    std::vector<TraversalStep> traversal_steps(int32_t v) const;
    std::vector<int32_t> faces_around_vertex(int32_t v) const;    // CCW, boundary gaps skipped
    std::vector<int32_t> vertices_around_vertex(int32_t v) const; // CCW
    std::vector<int32_t> edges_of_face(int32_t f) const;          // CCW from the face's edge
    std::vector<FaceStep> face_edge_steps(int32_t f) const;
    std::vector<int32_t> vertices_of_face(int32_t f) const;       // CCW, first = S-side of face edge walk
    std::array<int32_t, 2> faces_of_edge(int32_t e) const { return {edges_[e].left, edges_[e].right}; }
    std::vector<int32_t> face_neighbours(int32_t f) const;        // distinct faces across f's edges, first met first

    // The indexed face set read back from the structure: each face walked from its face
    // edge. With the default face edges this is the face set the mesh was built from.
    IndexedMesh face_set() const;

    MeshCounts counts() const;
    // Bytes of the vertex, edge and face tables (capacity actually held).
    std::size_t bytes() const;
    // Every broken connectivity invariant (wings, rings, face loops, table references).
    ValidationReport validate() const;

private:
    static WingedEdgeMesh build_impl(const IndexedMesh& mesh, const BuildOptions& options,
                                     std::vector<double>* positions_to_take);

    std::vector<double> positions_;    // positions_[3*v + k]
    std::vector<int32_t> vertex_edge_; // one incident edge per vertex (kNone if isolated)
    std::vector<EdgeRecord> edges_;
    std::vector<int32_t> face_edge_;   // one edge per face
};

} // namespace wingspline::mesh
