#pragma once
// The edit exercise in half-edge terms: a mesh before, one operation of the registry (flip e3,
// split e5, ...), and the student writes the rows of the half-edge view (half_edge.h) that the
// operation rewrites, as they read after it: per half-edge its origin, face, next and prev
// (its target and twin follow from the numbering: twin(h) is its pair, target(h) its twin's
// origin), per vertex and per face its half-edge.
//
// The rows asked are the view's before and after the operation compared: a half-edge row
// whose origin, face, next or prev changed, a vertex or face row whose half-edge changed, and
// the rows of the elements the operation adds or removes. New elements are numbered as the
// core numbers them, the next free numbers (edge e gives half-edges 2e and 2e + 1), and the
// question says so, so the exercise asks the pointers, not a numbering (the winged-edge edit
// kind, exercise_edit.h, asks that). A vertex's half-edge is right when it leaves the vertex
// after the operation, and on the boundary when the vertex is; a face's when it lies on the
// face. A removed element's rows are marked removed.
//
// The answer and the findings are exercise_edit.h's, with the Edge table's slot holding the
// half-edges: cells 4 per half-edge row (origin, face, next, prev), 1 per vertex or face row;
// fields "origin", "face", "next", "prev", "halfedge", "removed"; reasons name the row and the
// column and the rule to re-read, never the right value (that is `expected`).
#include "wingspline/mesh/exercise_edit.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

struct HalfEdgeEditQuestion {
    // The rows to write per table (MeshTable: Vertex, Edge = half-edges, Face), 0-based,
    // ascending: existing rows first, then the new ones.
    std::array<std::vector<int32_t>, 3> rows;
    // The row counts before the operation: a row at or past its table's count is new.
    std::array<int32_t, 3> before_count{0, 0, 0};
    std::string operation; // "flip e3"
};

// The question for `op` on `before`. Throws the operation's refusal (its code and message).
HalfEdgeEditQuestion half_edge_edit_question(const WingedEdgeMesh& before, const Operation& op);

// Checks the answer. Throws Error("invalid-answer") for input that is not an answer to this
// question (a table with the wrong number of rows or cells, a cell below -2).
EditCheck check_half_edge_edit_answer(const WingedEdgeMesh& before, const Operation& op, const EditAnswer& answer);

// The worked answer: every asked row as the view reads after the operation (the view's own
// vertex and face half-edges), removed rows marked.
EditAnswer worked_half_edge_edit_answer(const WingedEdgeMesh& before, const Operation& op);

} // namespace wingspline::mesh
