#pragma once
// Exercise kind 1: checking a winged-edge table a student filled in by hand for a
// given mesh (lecture 000: per edge S, E, L, R and the wings S:L, S:R, E:L, E:R; per vertex one
// incident edge; per face one edge).
//
// The exercise fixes the vertex and face numbers (they come with the faces); the edge numbers
// are the student's own: row r of their edge table is their edge e(r+1), and their wings and
// vertex/face tables name edges by those row numbers. Any correct table is accepted: the rows
// are matched to the mesh's edges by their S-E vertex pairs (a bijection found from the
// answer, never a fixed numbering), and either orientation of each edge is right (walking an
// edge the other way swaps L and R, S:L with E:R and S:R with E:L). What is checked is the
// structure the table describes, against the definition:
//  * S-E must be an edge of the mesh, one row per edge;
//  * L is the face whose corners run from S to E (faces are counter-clockwise), R the face
//    that runs from E to S; none on a boundary side;
//  * wing X:Y is the other edge at vertex X of the face on side Y, the boundary counting as
//    a face on a boundary side (the slide: "wing edges are defined as though the boundary was
//    also a face"). So S:L and E:R are the next edges counter-clockwise around S and E;
//  * the vertex table's edge touches the vertex (none for a vertex with no edge), the face
//    table's edge is a side of the face.
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

// A cell the student left blank (kNone, -1, is the table's "none": a boundary side).
inline constexpr int32_t kBlank = -2;

// The student's tables. Cells hold a vertex, face or edge number, 0-based; an edge number is
// the student's row number. kNone = "none", kBlank = left blank.
struct WingedEdgeAnswer {
    std::vector<int32_t> edges;        // edges[8*r + k], k: 0 S, 1 E, 2 L, 3 R, 4 S:L, 5 S:R, 6 E:L, 7 E:R
    std::vector<int32_t> vertex_edges; // vertex_edges[v]: the edge the vertex table stores for v
    std::vector<int32_t> face_edges;   // face_edges[f]: the edge the face table stores for f
};

// One thing wrong with the answer. `field` is the column as wingedEdge() names it ("start",
// "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"; "edge" in the
// vertex and face tables; "" for an edge of the mesh that has no row). given/expected are
// cell values as in WingedEdgeAnswer; expected edges use the worked answer's numbering (the
// student's where a row matches, see worked_winged_edge_answer).
// Codes: blank, unknown-label, not-an-edge, duplicate-edge, missing-edge, swapped-ends (S and
// E the other way round, all else right: one finding), wrong-face, wrong-wing, not-incident
// (vertex table), not-on-face (face table).
struct AnswerFinding {
    MeshTable table = MeshTable::Edge;
    int32_t row = kNone; // the student's row (vertex/face tables: the vertex/face); kNone for missing-edge
    std::string field;
    // In a column that holds a list (exercise_tables.h: a face's corners, a polygon's edges, a
    // vertex's neighbours): the position in the student's list, 0-based; kNone for a cell of
    // a fixed column and for an item missing from the list.
    int32_t index = kNone;
    int32_t given = kNone;
    int32_t expected = kNone;
    std::string code;
    std::string reason; // names the row and the column, and why, from the definition (with the values: the worked answer's)
    // What a student reads at feedback level "check" and "hint" (exercise_feedback.h): where,
    // as the question's grid counts (row e3, column S:L), and the rule to re-read; never the
    // right value nor anything it is copied from. hint: a value-free nudge.
    std::string message;
    std::string hint;
};

struct AnswerCheck {
    std::vector<AnswerFinding> findings; // edge table rows in order, then missing edges, vertices, faces
    std::vector<int32_t> row_edge;       // per student row: the mesh edge it was matched to (kNone: none)
    std::vector<char> row_reversed;      // 1 where the row runs the mesh edge from its End to its Start
    bool correct() const { return findings.empty(); }
};

// Checks `answer` for the mesh with these faces (CSR: face f's corners are
// face_vertices[face_offsets[f] .. face_offsets[f+1])) on vertex_count vertices. A student's
// mistake is a finding; input that is not a table of this shape throws Error:
// "invalid-answer" (a row not of 8 cells, a vertex/face table of the wrong length, a cell
// below -2), "invalid-faces" (the CSR arrays do not fit together), or the mesh's own
// validation code (e.g. "index-out-of-range", "non-manifold-edge") for faces the winged edge
// cannot hold.
AnswerCheck check_winged_edge_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                     int32_t vertex_count, const WingedEdgeAnswer& answer);

// The exercise's mesh from its faces (CSR, as above) on vertex_count vertices, built with
// `options` (a slide's numbering; empty: the default build). Throws "invalid-faces" when the
// arrays do not fit together or the mesh is larger than an exercise's, or the mesh's own
// validation code. Every exercise check builds its mesh here.
WingedEdgeMesh exercise_mesh(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                             int32_t vertex_count, const BuildOptions& options = {});

// The worked answer, as close to the student's table as it can be: every row the check could
// match keeps its number and orientation; the mesh's edges no row describes take the
// unmatched rows' numbers in order, then new numbers after the last row. Every cell is the
// right value (blanks filled from the mesh); a correct vertex or face table entry is kept, a
// wrong or blank one becomes the core's choice (docs/api-mesh.md, "Building"). Throws as
// check_winged_edge_answer.
WingedEdgeAnswer worked_winged_edge_answer(const std::vector<int32_t>& face_offsets,
                                           const std::vector<int32_t>& face_vertices, int32_t vertex_count,
                                           const WingedEdgeAnswer& answer);

} // namespace wingspline::mesh
