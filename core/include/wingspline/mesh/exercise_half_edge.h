#pragma once
// The half-edge exercises (half_edge.h's structure, taught from the winged edge):
//
//  * the half-edge table filled in by hand: per half-edge row origin, face, next, prev, twin;
//    per vertex one outgoing half-edge; per face one of its half-edges. Vertex and face
//    numbers are the exercise's; the half-edge numbering is the student's: row r is their
//    h(r+1), and next, prev, twin, the vertex and the face columns name rows. Any numbering
//    is right as long as it describes the mesh's half-edges: the rows are matched to the
//    mesh's half-edges by a bijection read from the answer (never a fixed numbering, so twin
//    pairs need not be h1/h2), and every cell is checked against the definition:
//      origin(h)  the vertex h leaves;
//      face(h)    the face on h's left (faces counter-clockwise), none on the boundary;
//      next(h)    starts where h ends, on the same face (the boundary loop counting as a face);
//      prev(h)    ends where h starts, on the same face; next(prev(h)) = h;
//      twin(h)    the other half of h's edge, running the other way;
//      vertex v   a half-edge leaving v, the boundary one (face none) when v is on the
//                 boundary, so that a walk from it meets the whole fan (pmp, OpenMesh);
//      face f     a half-edge whose face is f.
//  * the next half-edge of a walk, step after step: around a vertex counter-clockwise
//    h -> twin(prev(h)) from the vertex's half-edge, along a face h -> next(h) from the
//    face's half-edge (HalfEdgeMesh::vertex_walk / face_walk, on the view of the mesh built
//    with the exercise's numbering: edge e gives h(2e+1) = S -> E and h(2e+2) = E -> S on screen).
#include "wingspline/mesh/exercise_tables.h"
#include "wingspline/mesh/exercise_walk.h"
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

inline constexpr int32_t kHalfEdgeCellsPerRow = 5;

// The student's tables. Cells: 0-based vertex, face or row numbers; kNone = none, kBlank = blank.
struct HalfEdgeAnswer {
    std::vector<int32_t> halfedges;        // halfedges[5*r + k], k: 0 origin, 1 face, 2 next, 3 prev, 4 twin of row r
    std::vector<int32_t> vertex_halfedges; // vertex_halfedges[v]: the row the vertex table stores for v
    std::vector<int32_t> face_halfedges;   // face_halfedges[f]: the row the face table stores for f
};

// Findings are AnswerFinding (exercise_check.h): table Edge for a half-edge row (the grid's
// "halfedge" rows), Vertex and Face for the two small tables; field "origin", "face", "next",
// "prev", "twin", or "halfedge" in the vertex and face tables; row the student's row; given and
// expected cell values, expected in the student's numbering (the worked answer's).
// Codes: blank, unknown-label (no such vertex, face or row; none where a half-edge must be
// named), wrong-origin, wrong-face, wrong-next, wrong-prev, wrong-twin, not-outgoing (vertex
// table: the half-edge does not leave v, or none for a vertex that has half-edges),
// not-boundary (vertex table: v is on the boundary and the half-edge is not its boundary one),
// not-on-face (face table). One wrong cell is one finding, on its own row and column.
struct HalfEdgeTableResult {
    TableAnswerCheck check;
    HalfEdgeAnswer worked;              // every cell right, in the student's numbering
    std::vector<int32_t> row_halfedge;  // per row: the mesh half-edge it was matched to (half_edge.h's numbering)
};

// `options`: a slide's numbering (as exercise_mesh takes it); it changes no verdict, only the
// worked answer's choices for rows nothing in the answer identifies (an all-blank answer's
// worked table is the lesson's own numbering). Throws Error "invalid-answer" (a table of
// another size than the mesh's: 2 rows per edge, one per vertex and face; a cell below -2), or
// what exercise_mesh() throws for the faces.
HalfEdgeTableResult mark_half_edge_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                          int32_t vertex_count, const HalfEdgeAnswer& answer, const BuildOptions& options = {});

// "h5": a half-edge (0-based) as the page writes it, from 1.
std::string half_edge_label(int32_t h);

// Step k (k >= 1) of the half-edge walk around vertex `element` (along face `element` when
// around_face), half-edges 0 .. k-1 shown; the last step (k = n) closes the walk. `given` is
// the student's half-edge in the mesh's numbering (any number: one that names none is wrong).
// expected is a half-edge; reason, message and hint as check_walk_step's (exercise_walk.h).
// Throws Error "index-out-of-range", "no-walk" (a vertex on no face), "invalid-step".
WalkStepCheck check_half_edge_walk_step(const WingedEdgeMesh& mesh, bool around_face, int32_t element, int32_t step, int32_t given);

} // namespace wingspline::mesh
