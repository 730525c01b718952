#pragma once
// The edit exercise: a mesh before, one operation of the registry (operations.h: flip e3,
// split e5, collapse e6, ...), and the student writes the rows of the winged-edge tables
// that the operation rewrites, as they read after it (lecture 000's tables: per edge S, E,
// L, R and the wings S:L, S:R, E:L, E:R; per vertex and per face one edge).
//
// The question is read off the operation's change record on a copy of the mesh:
//  * the existing rows it rewrites (a field of the vertex, edge or face table changed) or
//    removes, in table order; they keep their labels;
//  * as many new rows per table as the operation adds elements, which the student labels
//    as they choose: any label no row of that table had before, each once.
// The check compares the answer with the change record's after-state, never with one
// numbering: new elements are matched to the student's labels by a bijection read from the
// answer (a new vertex by the edges that name it, a new edge by its two ends, a new face by
// the L and R cells that name it), so every numbering of the new elements is right. A new
// edge, and an existing edge whose two ends the operation replaces (a flipped edge), may be
// written in either direction: S-E read the other way swaps L with R, S:L with E:R and S:R
// with E:L. The vertex table's edge is right when it is one of the vertex's edges after the
// operation and the face table's when it is a side of the face (the definition, as the
// table exercise checks it). A removed element's row is marked removed.
//
// Each mistake is an AnswerFinding (exercise_check.h) whose reason names the row and the
// column and the rule to re-read, never the right value (that is `expected`, for the worked
// answer only). Rows: table = the row's table, row = its label (0-based; kNone for a new row
// without a usable label), index = the row's position in the answer's list of that table,
// field = "start".."endRight" (edge rows), "edge" (vertex, face rows), "removed", "label".
#include "wingspline/mesh/exercise_check.h"
#include "wingspline/mesh/operations.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

// What the student is asked: per table, the labels of the existing rows to write (0-based,
// ascending) and how many new rows to add.
struct EditQuestion {
    std::array<std::vector<int32_t>, 3> rows; // indexed by MeshTable: Vertex, Edge, Face
    std::array<int32_t, 3> added{0, 0, 0};
    std::string operation; // the operation as the edit panel writes it: "flip e3"
};

// One table of the answer: the listed rows first (question order), then the new rows.
// cells: 8 per edge row (S E L R S:L S:R E:L E:R), 1 per vertex or face row (its edge);
// 0-based labels, kNone = none, kBlank = left blank. removed[i]: the row is marked removed
// (its cells are then not read). labels: the new rows' labels (kBlank: not given yet).
struct EditTableAnswer {
    std::vector<int32_t> cells;
    std::vector<char> removed;
    std::vector<int32_t> labels;
};
struct EditAnswer {
    std::array<EditTableAnswer, 3> tables; // indexed by MeshTable
};

struct EditCheck {
    std::vector<AnswerFinding> findings; // vertex rows, edge rows, face rows, each in answer order
    bool correct() const { return findings.empty(); }
};

// The mesh before an edit exercise's question: the faces built with `options` (the slide's
// numbering, if any), then `edits` replayed in order (the lesson state's earlier edits), each
// by the registry as the page applied it; an edit without an entry (Operation{}) is the
// lesson's Compact step (WingedEdgeMesh::compact()). Throws "invalid-faces" for a mesh larger than an
// exercise's, the mesh's validation code, or an edit's refusal (its own code and message).
WingedEdgeMesh edited_exercise_mesh(const IndexedMesh& mesh, const BuildOptions& options, const std::vector<Operation>& edits);

// The question for `op` on `before`. Throws the operation's refusal (its code and message).
EditQuestion edit_question(const WingedEdgeMesh& before, const Operation& op);

// Checks the answer. Throws Error("invalid-answer") for input that is not an answer to this
// question (a table with the wrong number of rows or cells, a cell below -2), and the
// operation's refusal.
EditCheck check_edit_answer(const WingedEdgeMesh& before, const Operation& op, const EditAnswer& answer);

// The worked answer in the student's labels: every row's right cells (a vertex or face edge
// the student got right is kept), the removed rows marked, the new rows' labels kept where
// they were usable and otherwise the next free labels.
EditAnswer worked_edit_answer(const WingedEdgeMesh& before, const Operation& op, const EditAnswer& answer);

} // namespace wingspline::mesh
