// The edit exercise's bindings (exercise_edit.h). The mesh crosses as in exercise.cpp
// (positions[3*v + k], faceOffsets, faceVertices, and the slide's numbering: edges [S, E] per
// edge flat, vertexEdges, faceEdges, each possibly empty); the earlier edits and the question's
// operation as {name, args} (the registry's arguments in order, elements 0-based); the answer
// as {vertices, edges, faces}, each {cells, removed, labels} of whole numbers (-1 none, -2 blank).
#include "boundary.h"
#include "exercise_shared.h"

#include "wingspline/mesh/exercise_edit.h"
#include "wingspline/mesh/exercise_half_edge_edit.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

const char* const kTableKeys[3] = {"vertices", "edges", "faces"};
// The half-edge edit exercise's tables (exercise_half_edge_edit.h): the Edge slot holds half-edges.
const char* const kHalfEdgeTableKeys[3] = {"vertices", "halfedges", "faces"};

// {name: 'compact'} is the lesson's Compact step among the edits (Operation{}, exercise_edit.h).
Operation operation_value(const val& op) {
    const std::string name = op["name"].as<std::string>();
    if (name == "compact") return Operation{};
    const std::vector<double> args = to_doubles(op["args"]);
    return operation_from(name, args.data(), args.size());
}

// The question's operation: one of the registry (compact is no question).
Operation question_operation(const val& op) {
    const Operation o = operation_value(op);
    require(o.entry != nullptr, "unknown-operation", "an edit exercise asks an operation of the registry, not compact");
    return o;
}

WingedEdgeMesh before_mesh(const val& positions, const val& face_offsets, const val& face_vertices, const val& edges,
                           const val& vertex_edges, const val& face_edges, const val& edits) {
    IndexedMesh m;
    m.positions = to_doubles(positions);
    m.face_offsets = to_ints(face_offsets);
    m.face_vertices = to_ints(face_vertices);
    require(m.positions.size() % 3 == 0, "invalid-argument", "positions must hold x, y, z for each vertex");
    const BuildOptions options = numbering_options(edges, vertex_edges, face_edges);
    std::vector<Operation> list;
    const auto n = edits["length"].as<unsigned>();
    for (unsigned i = 0; i < n; ++i) list.push_back(operation_value(edits[i]));
    return edited_exercise_mesh(m, options, list);
}

EditAnswer answer_value(const val& answer, const char* const* keys = kTableKeys) {
    EditAnswer a;
    for (int t = 0; t < 3; ++t) {
        const val table = answer[keys[t]];
        a.tables[t].cells = to_ints(table["cells"]);
        const std::vector<int32_t> removed = to_ints(table["removed"]);
        a.tables[t].removed.assign(removed.begin(), removed.end());
        a.tables[t].labels = to_ints(table["labels"]);
    }
    return a;
}

val answer_object(const EditAnswer& a, const char* const* keys = kTableKeys) {
    val r = val::object();
    for (int t = 0; t < 3; ++t) {
        val table = val::object();
        table.set("cells", to_typed_array(a.tables[t].cells));
        std::vector<int32_t> removed(a.tables[t].removed.begin(), a.tables[t].removed.end());
        table.set("removed", to_typed_array(removed));
        table.set("labels", to_typed_array(a.tables[t].labels));
        r.set(keys[t], table);
    }
    return r;
}

// {rows: {vertices, edges, faces} (labels 0-based), added: {vertices, edges, faces}, operation}
val edit_question_value(const val& positions, const val& face_offsets, const val& face_vertices, const val& edges,
                        const val& vertex_edges, const val& face_edges, const val& edits, const val& op) {
    return guarded([&] {
        const WingedEdgeMesh before = before_mesh(positions, face_offsets, face_vertices, edges, vertex_edges, face_edges, edits);
        const EditQuestion q = edit_question(before, question_operation(op));
        val rows = val::object(), added = val::object();
        for (int t = 0; t < 3; ++t) {
            rows.set(kTableKeys[t], to_typed_array(q.rows[t]));
            added.set(kTableKeys[t], q.added[t]);
        }
        val r = val::object();
        r.set("rows", rows);
        r.set("added", added);
        r.set("operation", q.operation);
        return r;
    });
}

// {findings: [{table, row, field, index, given, expected, code, reason}], worked: answer}
val check_edit_value(const val& positions, const val& face_offsets, const val& face_vertices, const val& edges,
                     const val& vertex_edges, const val& face_edges, const val& edits, const val& op, const val& answer) {
    return guarded([&] {
        const WingedEdgeMesh before = before_mesh(positions, face_offsets, face_vertices, edges, vertex_edges, face_edges, edits);
        const Operation operation = question_operation(op);
        const EditAnswer a = answer_value(answer);
        const EditCheck c = check_edit_answer(before, operation, a);
        val r = val::object();
        r.set("findings", findings_value(c.findings));
        r.set("worked", answer_object(worked_edit_answer(before, operation, a)));
        return r;
    });
}

// The same in half-edge terms: {rows: {vertices, halfedges, faces}, beforeCount: {...}, operation}
val half_edge_edit_question_value(const val& positions, const val& face_offsets, const val& face_vertices, const val& edges,
                                  const val& vertex_edges, const val& face_edges, const val& edits, const val& op) {
    return guarded([&] {
        const WingedEdgeMesh before = before_mesh(positions, face_offsets, face_vertices, edges, vertex_edges, face_edges, edits);
        const HalfEdgeEditQuestion q = half_edge_edit_question(before, question_operation(op));
        val rows = val::object(), counts = val::object();
        for (int t = 0; t < 3; ++t) {
            rows.set(kHalfEdgeTableKeys[t], to_typed_array(q.rows[t]));
            counts.set(kHalfEdgeTableKeys[t], q.before_count[t]);
        }
        val r = val::object();
        r.set("rows", rows);
        r.set("beforeCount", counts);
        r.set("operation", q.operation);
        return r;
    });
}

// {findings, worked}: the answer's tables {vertices, halfedges, faces}, cells 4 per half-edge row.
val check_half_edge_edit_value(const val& positions, const val& face_offsets, const val& face_vertices, const val& edges,
                               const val& vertex_edges, const val& face_edges, const val& edits, const val& op, const val& answer) {
    return guarded([&] {
        const WingedEdgeMesh before = before_mesh(positions, face_offsets, face_vertices, edges, vertex_edges, face_edges, edits);
        const Operation operation = question_operation(op);
        const EditCheck c = check_half_edge_edit_answer(before, operation, answer_value(answer, kHalfEdgeTableKeys));
        val r = val::object();
        r.set("findings", findings_value(c.findings));
        r.set("worked", answer_object(worked_half_edge_edit_answer(before, operation), kHalfEdgeTableKeys));
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_exercise_edit) {
    emscripten::function("exerciseHalfEdgeEditQuestion", &wingspline::bindings::half_edge_edit_question_value);
    emscripten::function("exerciseCheckHalfEdgeEdit", &wingspline::bindings::check_half_edge_edit_value);
    emscripten::function("exerciseEditQuestion", &wingspline::bindings::edit_question_value);
    emscripten::function("exerciseCheckEdit", &wingspline::bindings::check_edit_value);
}
