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

#include <array>
#include <cstddef>
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

} // namespace wingspline::mesh
