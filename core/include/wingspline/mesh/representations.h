#pragma once
// The four other ways lectures 000 and 001 store a polygon mesh, as real arrays built from
// the same indexed face set as the winged edge, with the winged edge's edge numbering (so
// every representation names edges e1..eE alike and their answers can be compared).
//
// Every array is a flat std::vector; per-element records of variable size use CSR: an
// offsets array (one entry per element + 1) and one list. storage() counts the entries of
// every array (an entry = one element of the vector: a double coordinate or an int32 index)
// and their bytes, from the vectors' sizes. None of this is part of the winged edge's
// bytes: a WingedEdgeMesh holds only its own three tables (lecture 000).
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/winged_edge.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace wingspline::mesh {

// One array of a representation: its name as the docs and lessons show it, how many
// entries it holds and how many bytes one entry takes.
struct ArrayStorage {
    std::string name;
    std::size_t entries = 0;
    std::size_t bytes_per_entry = 0;
};

struct Storage {
    std::vector<ArrayStorage> arrays;
    std::size_t entries() const;
    std::size_t bytes() const;
};

// Lecture 000 "independent faces" / lecture 001 "explicit polygons": each face lists its
// vertex coordinates, so a vertex shared by k faces is stored k times.
struct IndependentFaces {
    std::vector<int32_t> face_offsets;    // face f's corners are [face_offsets[f], face_offsets[f+1])
    std::vector<double> corner_positions; // corner_positions[3*c + k]: one xyz copy per face corner c
    Storage storage() const;
};

// Lecture 000 "vertex and face tables" / lecture 001 "pointers to a vertex list".
struct VertexFaceTables {
    std::vector<double> positions;     // positions[3*v + k]
    std::vector<int32_t> face_offsets; // CSR over face_vertices
    std::vector<int32_t> face_vertices;
    Storage storage() const;
};

// Lecture 000 "adjacency lists: store all vertex, edge, and face adjacencies": every one of
// the nine relations between vertices, edges and faces is a stored list.
//  * VV and VE share vertex_offsets (the i-th neighbour lies across the i-th edge);
//    edges in ascending edge number.
//  * VF has its own offsets (a boundary vertex has one face fewer than edges); ascending.
//  * EV = (S, E); EF = (L, R), -1 on the boundary side; EE = the other edges at S, then
//    the other edges at E (each in VE's order).
//  * FV, FE and FF share face_offsets: corner i, the edge from corner i to corner i + 1,
//    and the face across that edge (-1 on the boundary).
struct AdjacencyLists {
    std::vector<double> positions; // positions[3*v + k]
    std::vector<int32_t> vertex_offsets, vertex_vertices, vertex_edges;
    std::vector<int32_t> vertex_face_offsets, vertex_faces;
    std::vector<int32_t> edge_vertices; // edge_vertices[2*e + {0,1}] = S, E
    std::vector<int32_t> edge_edge_offsets, edge_edges;
    std::vector<int32_t> edge_faces; // edge_faces[2*e + {0,1}] = L, R
    std::vector<int32_t> face_offsets, face_vertices, face_edges, face_faces;
    Storage storage() const;
};

// Partial adjacency lists (lecture 000 names the variant; its slide repeats the full list's
// bullets, "store all ... adjacencies", so the choice of relations is ours): only the
// incidences between neighbouring dimensions, V->E, E->V, E->F and F->E, are stored; the
// others (VV, VF, EE, FV, FF) are derived with one extra lookup each (e.g. the faces
// around v are the faces of v's edges). Same array conventions as AdjacencyLists.
struct PartialAdjacencyLists {
    std::vector<double> positions;
    std::vector<int32_t> vertex_offsets, vertex_edges;
    std::vector<int32_t> edge_vertices; // S, E
    std::vector<int32_t> edge_faces;    // L, R (-1 = boundary)
    std::vector<int32_t> face_offsets, face_edges;
    Storage storage() const;
};

// Lecture 001 "pointers to an edge list" (Foley & van Dam): a vertex list, an edge list
// E = (V1, V2, P1, P2) and polygons as lists of edge indices. P1 is the lower-numbered
// polygon on the edge, P2 the other one or -1 (lambda) on the boundary; a polygon lists its
// edges in its own (counter-clockwise) order starting at its lowest-numbered edge, which
// reproduces Foley's P1 = (E1, E4, E5), P2 = (E2, E3, E4).
struct EdgeList {
    std::vector<double> positions;        // positions[3*v + k]
    std::vector<int32_t> edges;           // edges[4*e + {0,1,2,3}] = V1, V2, P1, P2
    std::vector<int32_t> polygon_offsets; // CSR over polygon_edges
    std::vector<int32_t> polygon_edges;
    Storage storage() const;
};

// The winged edge's own storage: vertex table (xyz + edge), edge table (8 per edge), face table.
Storage winged_edge_storage(const WingedEdgeMesh& winged);

// The order every list of six below uses; names are the JS keys.
enum class Representation : int {
    IndependentFaces,
    VertexFaceTables,
    AdjacencyLists,
    PartialAdjacencyLists,
    EdgeList,
    WingedEdge,
};
constexpr int kRepresentationCount = 6;
const char* representation_key(Representation r); // "independent-faces", ...

struct Representations {
    IndependentFaces independent_faces;
    VertexFaceTables vertex_face_tables;
    AdjacencyLists adjacency_lists;
    PartialAdjacencyLists partial_adjacency_lists;
    EdgeList edge_list;
    // Naming only, part of no representation: the shared number of the edge from corner c
    // to the next corner of its face. Representations without an edge table (independent
    // faces, vertex and face tables) know an edge only as two consecutive corners; this
    // translates their answers into e1..eE so they can be compared. Never counted as read.
    std::vector<int32_t> corner_edge_names;
};

// Builds all four from the indexed face set `faces` (corner order kept as given) and the
// winged edge built from it (for the edge numbering and the current positions). Throws
// Error("mismatched-face-set") when `faces` is not the face set `winged` was built from.
Representations build_representations(const IndexedMesh& faces, const WingedEdgeMesh& winged);

// The other representations as a cache of the winged edge (docs/architecture.md, "The
// mesh's change model"): derived from the winged edge's current face set (face_set()) on
// first use, and derived again whenever the mesh's version is not the one they were derived
// for, so an operation on the winged edge never leaves a stale copy behind. Moving a vertex
// is the one change followed in place (follow_position), because lecture 000 counts the
// copies each representation rewrites.
class RepresentationCache {
public:
    // The representations of `winged` as it is now.
    const Representations& of(const WingedEdgeMesh& winged);
    // After winged.set_position(v, p): writes p into every stored copy (building first if
    // needed) and returns set_vertex_position's counts. The cache is then current again.
    std::array<int32_t, kRepresentationCount - 1> follow_position(const WingedEdgeMesh& winged, int32_t v, const glm::dvec3& p);
    // The representations of `winged` as it is now, handed over: the cache is empty after it
    // (an edit's cost compares them with the ones derived after the edit, without a copy).
    std::unique_ptr<Representations> take(const WingedEdgeMesh& winged);
    bool built() const { return reps_ != nullptr; }
    // The version they were derived for (meaningful only when built()).
    MeshVersion version() const { return version_; }
    // How many times they were derived (tests: a cache hit derives nothing).
    int32_t derivations() const { return derivations_; }

private:
    std::unique_ptr<Representations> reps_;
    MeshVersion version_;
    int32_t derivations_ = 0;
};

// Storage of all six, in Representation order.
std::array<Storage, kRepresentationCount> representation_storage(const Representations& reps,
                                                                  const WingedEdgeMesh& winged);

// Moves vertex v in every stored copy (the winged edge's own positions are set by
// WingedEdgeMesh::set_position). Returns, in Representation order without the winged
// edge, how many xyz copies each one rewrote: independent faces one per face corner at v
// (found through its faces in the adjacency list's VF, so coincident points stay apart),
// every indexed representation exactly one.
std::array<int32_t, kRepresentationCount - 1> set_vertex_position(Representations& reps, int32_t v,
                                                                  const glm::dvec3& p);

} // namespace wingspline::mesh
