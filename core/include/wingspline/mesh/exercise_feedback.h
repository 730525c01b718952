#pragma once
// The words of an exercise's feedback that give nothing away (the feedback levels "check" and
// "hint" of docs/exercises.md): a finding says WHERE the answer is wrong, in the question's own
// terms (the grid's row and column as the page heads them, the position in a list from
// "first"), and the RULE to re-read (lecture 000's definitions, lecture 001's edge list); a hint
// nudges without a value. The right value, and anything a student could copy it from (another
// vertex, face or edge label, a distance), appears only in `reason`, the worked answer's words.
#include "wingspline/mesh/exercise_check.h"

#include <string>
#include <vector>

namespace wingspline::mesh {

// Fills `message` and `hint` of every finding of a table check. table: "winged-edge", "faces",
// "edge-list" or "adjacency" (how the grid names its rows: e3 / v2 / F1, or the edge list's E3
// and P1). Only the finding's table, row, field, index and code are read.
void word_table_findings(const std::string& table, std::vector<AnswerFinding>& findings);

// "first", "second", ... "twelfth", then "item 13": a position as the question counts it.
std::string ordinal_words(int32_t index0);

} // namespace wingspline::mesh
