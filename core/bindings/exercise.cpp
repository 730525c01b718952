// Exercise bindings: checking a student's winged-edge table (and the other tables, the
// half-edge table, the walks). The mesh crosses as
// CSR (faceOffsets: F + 1 entries, faceVertices) with its vertex count; the answer as flat
// Int32 arrays: edges[8*r + k] (k: S E L R S:L S:R E:L E:R of the student's row r),
// vertexEdges[v], faceEdges[f]; -1 = none, -2 = blank. Findings leave as plain objects.
#include "boundary.h"
#include "exercise_shared.h"

#include "wingspline/mesh/exercise_check.h"
#include "wingspline/mesh/exercise_half_edge.h"
#include "wingspline/mesh/exercise_tables.h"
#include "wingspline/mesh/exercise_walk.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// The exercise's mesh and the student's answer, as the core's check reads them.
struct ExerciseInput {
    std::vector<int32_t> face_offsets, face_vertices;
    int32_t vertex_count;
    WingedEdgeAnswer answer;
};

ExerciseInput exercise_input(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const val& edges,
                             const val& vertex_edges, const val& face_edges) {
    return {to_ints(face_offsets), to_ints(face_vertices), vertex_count, {to_ints(edges), to_ints(vertex_edges), to_ints(face_edges)}};
}

val check_answer(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const val& edges,
                 const val& vertex_edges, const val& face_edges) {
    return guarded([&] {
        const ExerciseInput in = exercise_input(face_offsets, face_vertices, vertex_count, edges, vertex_edges, face_edges);
        const AnswerCheck c = check_winged_edge_answer(in.face_offsets, in.face_vertices, in.vertex_count, in.answer);
        val r = val::object();
        r.set("findings", findings_value(c.findings));
        r.set("rowEdges", to_typed_array(c.row_edge));
        r.set("rowReversed", to_typed_array(c.row_reversed));
        return r;
    });
}

val worked_answer(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const val& edges,
                  const val& vertex_edges, const val& face_edges) {
    return guarded([&] {
        const ExerciseInput in = exercise_input(face_offsets, face_vertices, vertex_count, edges, vertex_edges, face_edges);
        const WingedEdgeAnswer w = worked_winged_edge_answer(in.face_offsets, in.face_vertices, in.vertex_count, in.answer);
        val r = val::object();
        r.set("edges", to_typed_array(w.edges));
        r.set("vertexEdges", to_typed_array(w.vertex_edges));
        r.set("faceEdges", to_typed_array(w.face_edges));
        return r;
    });
}

// The other tables (exercise_tables.h): `flat` holds the edge list's rows (4 per row), the list
// (offsets + cells) the face table's, the polygon table's or the adjacency list's rows. Returns
// {findings, worked: {flat, offsets, cells}} (flat empty but for the edge list).
val check_table(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const std::string& table,
                const val& flat, const val& list_offsets, const val& list_cells) {
    return guarded([&] {
        const std::vector<int32_t> fo = to_ints(face_offsets), fv = to_ints(face_vertices);
        const ListAnswer list{to_ints(list_offsets), to_ints(list_cells)};
        std::vector<AnswerFinding> findings;
        std::vector<int32_t> worked_flat;
        ListAnswer worked;
        // (one pass each: the findings and the worked table together)
        if (table == "faces" || table == "adjacency") {
            ListTableResult m = table == "faces" ? mark_faces_answer(fo, fv, vertex_count, list) : mark_adjacency_answer(fo, fv, vertex_count, list);
            findings = std::move(m.check.findings);
            worked = std::move(m.worked);
        } else if (table == "edge-list") {
            EdgeListTableResult m = mark_edge_list_answer(fo, fv, vertex_count, EdgeListAnswer{to_ints(flat), list});
            findings = std::move(m.check.findings);
            worked_flat = std::move(m.worked.edges);
            worked = std::move(m.worked.polygons);
        } else {
            throw Error("unknown-table", "no exercise table '" + table.substr(0, 40) + "'; use faces, edge-list or adjacency");
        }
        val w = val::object();
        w.set("flat", to_typed_array(worked_flat));
        w.set("offsets", to_typed_array(worked.offsets));
        w.set("cells", to_typed_array(worked.cells));
        val r = val::object();
        r.set("findings", findings_value(findings));
        r.set("worked", w);
        return r;
    });
}

// A walk step (exercise_walk.h; the half-edge walk's, exercise_half_edge.h, when half_edge) on
// the mesh built from the faces with the slide's numbering when given: edges = [S, E] per edge
// (flat), vertexEdges, faceEdges (each may be empty).
val check_walk(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const val& edges, const val& vertex_edges,
               const val& face_edges, bool around_face, int32_t element, int32_t step, int32_t given, bool half_edge) {
    return guarded([&] {
        const BuildOptions options = numbering_options(edges, vertex_edges, face_edges);
        const WingedEdgeMesh mesh = exercise_mesh(to_ints(face_offsets), to_ints(face_vertices), vertex_count, options);
        const WalkStepCheck c = half_edge ? check_half_edge_walk_step(mesh, around_face, element, step, given)
                                          : check_walk_step(mesh, around_face, element, step, given);
        val r = val::object();
        r.set("correct", c.correct);
        r.set("from", c.from);
        r.set("expected", c.expected);
        r.set("done", c.done);
        r.set("reason", c.reason);
        r.set("message", c.message);
        r.set("hint", c.hint);
        return r;
    });
}

// The half-edge table (exercise_half_edge.h): halfEdges[5*r + k] (k: origin face next prev twin
// of the student's row r), vertexHalfedges[v], faceHalfedges[f]. Returns {findings, worked:
// {halfedges, vertexHalfedges, faceHalfedges}, rowHalfedges}.
// The slide's numbering (edges, vertexEdges, faceEdges as check_walk takes them) only orders
// the worked answer's rows where the answer identifies none.
val check_half_edge(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const val& edges, const val& vertex_edges,
                    const val& face_edges, const val& halfedges, const val& vertex_halfedges, const val& face_halfedges) {
    return guarded([&] {
        const HalfEdgeTableResult m = mark_half_edge_answer(to_ints(face_offsets), to_ints(face_vertices), vertex_count,
                                                            {to_ints(halfedges), to_ints(vertex_halfedges), to_ints(face_halfedges)},
                                                            numbering_options(edges, vertex_edges, face_edges));
        val w = val::object();
        w.set("halfedges", to_typed_array(m.worked.halfedges));
        w.set("vertexHalfedges", to_typed_array(m.worked.vertex_halfedges));
        w.set("faceHalfedges", to_typed_array(m.worked.face_halfedges));
        val r = val::object();
        r.set("findings", findings_value(m.check.findings));
        r.set("worked", w);
        r.set("rowHalfedges", to_typed_array(m.row_halfedge));
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_exercise) {
    emscripten::function("exerciseCheckWingedEdge", &wingspline::bindings::check_answer);
    emscripten::function("exerciseWorkedWingedEdge", &wingspline::bindings::worked_answer);
    emscripten::function("exerciseCheckTable", &wingspline::bindings::check_table);
    emscripten::function("exerciseCheckWalkStep", &wingspline::bindings::check_walk);
    emscripten::function("exerciseCheckHalfEdge", &wingspline::bindings::check_half_edge);
}
