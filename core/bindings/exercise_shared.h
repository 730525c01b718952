#pragma once
// What the exercise bindings share: a slide's numbering as it crosses (edges [S, E] per edge,
// flat; vertexEdges; faceEdges; each possibly empty) and a check's findings (exercise_check.h,
// AnswerFinding) as the plain objects every exercise binding returns: {table, row, field,
// index, given, expected, code, reason}.
#include "boundary.h"

#include "wingspline/mesh/exercise_check.h"

#include <vector>

namespace wingspline::bindings {

inline mesh::BuildOptions numbering_options(const val& edges, const val& vertex_edges, const val& face_edges) {
    mesh::BuildOptions options;
    const std::vector<int32_t> pairs = to_ints(edges);
    require(pairs.size() % 2 == 0, "invalid-argument", "edges must hold [S, E] for each edge");
    for (std::size_t i = 0; i + 1 < pairs.size(); i += 2) options.edges.push_back({pairs[i], pairs[i + 1]});
    options.vertex_edges = to_ints(vertex_edges);
    options.face_edges = to_ints(face_edges);
    return options;
}

inline val findings_value(const std::vector<mesh::AnswerFinding>& list) {
    val findings = val::array();
    for (std::size_t i = 0; i < list.size(); ++i) {
        const mesh::AnswerFinding& f = list[i];
        val o = val::object();
        o.set("table", std::string(mesh::table_name(f.table)));
        o.set("row", f.row);
        o.set("field", f.field);
        o.set("index", f.index);
        o.set("given", f.given);
        o.set("expected", f.expected);
        o.set("code", f.code);
        o.set("reason", f.reason);
        o.set("message", f.message);
        o.set("hint", f.hint);
        findings.set(i, o);
    }
    return findings;
}

} // namespace wingspline::bindings
