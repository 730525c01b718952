#pragma once
// A check's findings (exercise_check.h, AnswerFinding) as the plain objects every exercise
// binding returns: {table, row, field, index, given, expected, code, reason}.
#include "boundary.h"

#include "wingspline/mesh/exercise_check.h"

#include <vector>

namespace wingspline::bindings {

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
        findings.set(i, o);
    }
    return findings;
}

} // namespace wingspline::bindings
