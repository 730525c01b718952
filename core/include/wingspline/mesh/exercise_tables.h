#pragma once
// Exercise kind 1 for the tables other than the winged edge: a student fills in, by
// hand, a table the lessons show for a given mesh, and the check says what is wrong, against
// the table's definition (never against a copy of one numbering):
//
//  * "faces", lecture 000's "Vertex and Face Tables" (each face lists vertex references): per
//    face its corners. Right: the face's cycle from any corner (a rotation). The lecture lists
//    corners counter-clockwise, seen from the front (F2 = v2 v4 v3): the cycle read the other
//    way round is one finding, "clockwise".
//  * "edge-list", lecture 001's pointers to an edge list: E_i = (V1, V2, P1, P2), lambda (none)
//    where no polygon lies on that side, and the polygons P_i = (E ...). The student numbers the
//    edges (rows are matched by their vertex pair, as in the winged-edge check) and may run a
//    row either way. Foley's example does not tie P1 or P2 to a side (E1 = (V1, V2, P1, lambda)
//    has P1 on its left, E4 = (V4, V2, P1, P2) has P1 on its right), so {P1, P2} is checked as
//    the pair of faces on the edge, in either order. A polygon's edges are checked as a set:
//    the slide's P1 = (E1, E4, E5) is both its cycle and ascending, so it fixes no order.
//  * "adjacency", lecture 000's adjacency lists, the "vertices" column of the per-vertex table:
//    per vertex its neighbours. The slide shows no order and the core lists them by edge
//    number (representations.h), which depends on the numbering, so the list is checked as a
//    set: every neighbour once, nothing else.
//
// Vertex and face numbers are fixed by the exercise (they come with the faces); only the edge
// list's edge numbers are the student's. Cells: 0-based numbers, kNone (-1) = none / lambda,
// kBlank (-2) = left blank. Findings are AnswerFinding (exercise_check.h) with table = the kind
// of row (faces: Face; edge list: Edge rows, then Face for the polygons; adjacency: Vertex),
// field = the column as tables.cpp names it ("vertices"; "v1", "v2", "p1", "p2"; "edges") and,
// in a list column, index = the position in the student's list.
#include "wingspline/mesh/exercise_check.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

// A table whose rows are lists, CSR: row r is cells[offsets[r] .. offsets[r+1]).
struct ListAnswer {
    std::vector<int32_t> offsets; // rows + 1 entries, from 0, never decreasing
    std::vector<int32_t> cells;
};

struct EdgeListAnswer {
    std::vector<int32_t> edges; // edges[4*r + k], k: 0 V1, 1 V2, 2 P1, 3 P2 of the student's row r
    ListAnswer polygons;        // per face: the student's edge (row) numbers
};

struct TableAnswerCheck {
    std::vector<AnswerFinding> findings;
    bool correct() const { return findings.empty(); }
};

// Faces (CSR face_offsets/face_vertices on vertex_count vertices) as exercise_check.h takes
// them. Each check throws Error "invalid-answer" for input that is not a table of the shape
// (a row count other than the mesh's, a cell below -2, offsets that do not fit), or what
// exercise_mesh() throws for the faces.

// Codes: blank, unknown-label (no such vertex), clockwise (the whole cycle the other way round;
// one finding, index kNone), wrong-vertex (same length, the corner at this position is another
// vertex), wrong-order (the right corners, not in cycle order), missing-vertex (the list is
// short of this corner; index kNone), extra-vertex (not a corner of the face, or listed twice).
TableAnswerCheck check_faces_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                    int32_t vertex_count, const ListAnswer& answer);
// The worked table: each face's counter-clockwise cycle, from the corner the student started at
// where the row could be aligned with the cycle.
ListAnswer worked_faces_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                               int32_t vertex_count, const ListAnswer& answer);

// Codes, edge rows: blank, unknown-label, not-an-edge, duplicate-edge (V1 or V2: the row names
// no edge, or an edge another row has; expected = the vertex that makes it the edge the row
// describes), missing-edge (row kNone: an edge of the mesh no row describes), wrong-face (P1
// or P2: not a face on that edge, lambda where a face lies, or a face where there is none).
// Polygons (table Face, field "edges"): blank, unknown-label (no such row), not-on-face (the
// row's edge is not a side of the polygon, or is listed twice; expected = a side still
// missing, if any), missing-edge (a side not listed; index kNone).
TableAnswerCheck check_edge_list_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                        int32_t vertex_count, const EdgeListAnswer& answer);
// The worked table in the student's numbering and orientation where rows match (the mesh's
// edges no row describes take the unmatched rows' numbers, then new ones); a matched row keeps
// its P1, P2 with a wrong one replaced by the face its finding expects, a new row gets (the face
// on the left, the face on the right) with lambda written second as on the slide; a polygon
// keeps its right entries in place, each wrong one replaced by the side its finding expects,
// the sides still missing after them.
EdgeListAnswer worked_edge_list_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                       int32_t vertex_count, const EdgeListAnswer& answer);

// Codes: blank, unknown-label, not-adjacent (not a neighbour, or listed twice; expected = a
// neighbour still missing, if any), missing-vertex (a neighbour not listed; index kNone).
TableAnswerCheck check_adjacency_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                        int32_t vertex_count, const ListAnswer& answer);
// The worked table: the student's right entries in their order, each wrong one replaced by the
// neighbour its finding expects, the neighbours still missing after them (counter-clockwise).
ListAnswer worked_adjacency_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                   int32_t vertex_count, const ListAnswer& answer);

// The check and the worked table of one answer from one pass (what a page shows together;
// check_* and worked_* above each run the whole check).
struct ListTableResult {
    TableAnswerCheck check;
    ListAnswer worked;
};
struct EdgeListTableResult {
    TableAnswerCheck check;
    EdgeListAnswer worked;
};
ListTableResult mark_faces_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                  int32_t vertex_count, const ListAnswer& answer);
EdgeListTableResult mark_edge_list_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                          int32_t vertex_count, const EdgeListAnswer& answer);
ListTableResult mark_adjacency_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                      int32_t vertex_count, const ListAnswer& answer);

} // namespace wingspline::mesh
