// Exercise bindings (issue 19): checking a student's winged-edge table. The mesh crosses as
// CSR (faceOffsets: F + 1 entries, faceVertices) with its vertex count; the answer as flat
// Int32 arrays: edges[8*r + k] (k: S E L R S:L S:R E:L E:R of the student's row r),
// vertexEdges[v], faceEdges[f]; -1 = none, -2 = blank. Findings leave as plain objects.
#include "boundary.h"

#include "wingspline/mesh/exercise_check.h"

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
        val findings = val::array();
        for (std::size_t i = 0; i < c.findings.size(); ++i) {
            const AnswerFinding& f = c.findings[i];
            val o = val::object();
            o.set("table", std::string(table_name(f.table)));
            o.set("row", f.row);
            o.set("field", f.field);
            o.set("given", f.given);
            o.set("expected", f.expected);
            o.set("code", f.code);
            o.set("reason", f.reason);
            findings.set(i, o);
        }
        val r = val::object();
        r.set("findings", findings);
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

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_exercise) {
    emscripten::function("exerciseCheckWingedEdge", &wingspline::bindings::check_answer);
    emscripten::function("exerciseWorkedWingedEdge", &wingspline::bindings::worked_answer);
}
