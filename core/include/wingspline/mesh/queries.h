#pragma once
// The same adjacency query answered by each of the six representations, with a genuine
// count of the table entries the algorithm read from that representation's arrays: the
// lesson "why the winged edge wins" (lecture 000: independent faces have "no efficient
// vertex-adjacency info"; lecture 001: with an edge list "all edges must be inspected").
//
// What a representation is asked with: a vertex by its index, or, for independent faces
// (which have no vertex identity), by its coordinates; an edge by its index, or, for the
// two representations without an edge table, by its two end vertices (their coordinates
// for independent faces). Producing that key and naming edge answers e1..eE through the
// corner numbering (Representations::corner_edge_names) are not reads of the representation
// and are not counted. One entry = one element of one array (a double or an int32).
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/tables.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

enum class QueryKind { FacesAroundVertex, EdgesAroundVertex, EdgesOfFace, FacesOfEdge, NeighboursOfFace };

// "faces-around-vertex", "edges-around-vertex", "edges-of-face", "faces-of-edge",
// "neighbours-of-face"; throws Error("unknown-query") otherwise.
QueryKind query_kind(const std::string& name);

struct QueryAnswer {
    std::vector<int32_t> answer; // element indices, no -1; order: see docs/api-mesh.md
    std::size_t entries_read = 0;
};

// The winged edge's answer alone (answer_query's winged-edge entry), needing no other
// representation. Throws as answer_query does.
QueryAnswer winged_edge_answer(QueryKind kind, int32_t element, const WingedEdgeMesh& w);

// All six answers in Representation order. Throws Error("invalid-element") when `element`
// is not a vertex / face / edge of the mesh (as the kind requires).
std::array<QueryAnswer, kRepresentationCount> answer_query(QueryKind kind, int32_t element,
                                                           const Representations& reps,
                                                           const WingedEdgeMesh& winged);

// ---------------------------------------------------------------- cost against mesh size

// The element a query asks about: a vertex, an edge or a face.
ElementKind query_element_kind(QueryKind kind);

// Entries each representation reads to answer `kind` at the middle element of a real grid of
// n x n quads (n even; the element edit_costs.h's grid_operation edits: the middle vertex,
// the edge to its right, the face F/2 + n).
std::array<int64_t, kRepresentationCount> query_reads_on_grid(QueryKind kind, int32_t n);
// The same for the half-edge view of that grid (half_edge.h, half_edge_answer): beyond the
// lectures, beside the six.
int64_t half_edge_query_reads_on_grid(QueryKind kind, int32_t n);

// The same at each grid size in `sizes` (even n up to 4000, F = 2 n^2 up to 32 million):
// measured on real grids at n = 8, 16, 24, each count fitted exactly by a + b n + c n^2
// (a table scan reads a fixed number of entries per element; V, E, F are quadratics in n;
// the walks read a constant), the fit checked against a fourth real grid (n = 32), then
// evaluated. The lesson's chart shows a million faces without building a million-face mesh
// and its six representations in the page; tests/native/mesh/test_queries.cpp checks the
// values against real counted grids up to a million faces. Throws
// Error("invalid-argument") for a size that is not such an n, Error("internal-error") when
// the fourth grid disagrees.
struct QueryCostGrowth {
    std::vector<int32_t> n;     // quads across, per size
    std::vector<int64_t> faces; // F = 2 n^2
    std::vector<std::array<int64_t, kRepresentationCount>> reads;
    std::vector<int64_t> half_edge_reads; // the half-edge view's, fitted and checked the same way
};
QueryCostGrowth query_cost_growth(QueryKind kind, const std::vector<int32_t>& sizes);

} // namespace wingspline::mesh
