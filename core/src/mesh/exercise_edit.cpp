// The edit exercise (exercise_edit.h): the question and the check, both read off the
// operation's change record on a copy of the mesh before.
#include "wingspline/mesh/exercise_edit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <cstdio>

namespace wingspline::mesh {
namespace {

constexpr int kTables = 3;
constexpr int kV = static_cast<int>(MeshTable::Vertex), kE = static_cast<int>(MeshTable::Edge), kF = static_cast<int>(MeshTable::Face);
constexpr int kEdgeCells = 8;
// As the table exercise bounds its mesh (exercise_check.cpp); the edits replayed before the
// question are the lesson state's, at most this many.
constexpr int32_t kMaxFaces = 10000;
constexpr std::size_t kMaxEdits = 4096;
// A cell that names a new element whose row has no usable label: the check cannot say what
// the student should have written there (the label's own finding says what to fix).
constexpr int32_t kUnlabelled = -3;
// A cell naming no row of its table after the operation.
constexpr int32_t kNoRow = -4;

const char* const kEdgeField[kEdgeCells] = {"start", "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"};
const char* const kEdgeColumn[kEdgeCells] = {"S", "E", "L", "R", "S:L", "S:R", "E:L", "E:R"};
// The table each edge cell names: S, E vertices; L, R faces; the wings edges.
const int kEdgeCellTable[kEdgeCells] = {kV, kV, kF, kF, kE, kE, kE, kE};

int width(int t) { return t == kE ? kEdgeCells : 1; }
int32_t count(const WingedEdgeMesh& m, int t) { return t == kV ? m.vertex_count() : t == kE ? m.edge_count() : m.face_count(); }
bool deleted(const WingedEdgeMesh& m, int t, int32_t i) {
    return t == kV ? m.is_deleted(Vertex(i)) : t == kE ? m.is_deleted(Edge(i)) : m.is_deleted(Face(i));
}
std::string label_of(int t, int32_t i) { return t == kV ? vertex_label(i) : t == kE ? edge_label(i) : face_label(i); }
const char* table_words(int t) { return t == kV ? "vertex" : t == kE ? "edge" : "face"; }

std::array<int32_t, kEdgeCells> cells_of(const EdgeRecord& r) {
    return {r.start, r.end, r.left, r.right, r.start_left, r.start_right, r.end_left, r.end_right};
}
// The row walked from E to S (exercise_check.cpp, reversed()): S <-> E, L <-> R, S:L <-> E:R, S:R <-> E:L.
std::array<int32_t, kEdgeCells> reversed_cells(const std::array<int32_t, kEdgeCells>& c) {
    return {c[1], c[0], c[3], c[2], c[7], c[6], c[5], c[4]};
}

// "flip e3", "split e3 at t = 0.5": the entry's describe line with the arguments as the slides label them.
std::string describe(const Operation& op) {
    std::string text = op.entry->describe;
    for (std::size_t k = 0; k < op.entry->arguments.size(); ++k) {
        const OperationArgument& a = op.entry->arguments[k];
        std::string value;
        const auto i = static_cast<int32_t>(op.args[k]);
        if (a.kind == ElementKind::Vertex) value = vertex_label(i);
        else if (a.kind == ElementKind::Edge) value = edge_label(i);
        else if (a.kind == ElementKind::Face) value = face_label(i);
        else {
            // As an ostream prints it (%g), without <sstream>'s iostream and locale code.
            char number[32];
            std::snprintf(number, sizeof number, "%g", op.args[k]);
            value = number;
        }
        const std::string key = std::string("{") + a.name + "}";
        const auto at = text.find(key);
        if (at != std::string::npos) text.replace(at, key.size(), value);
    }
    return text;
}

EditQuestion question_of(const WingedEdgeMesh& before, const Operation& op, const ChangeRecord& rec) {
    EditQuestion q;
    std::array<std::set<int32_t>, kTables> rows;
    for (const RowChange& r : rec.rows) {
        const int t = static_cast<int>(r.table);
        if (r.row >= count(before, t)) continue; // a new element: one of the new rows
        // firstCorner is where face_set() lists a face from, not a column of the slide's tables
        if (std::any_of(r.fields.begin(), r.fields.end(), [](const FieldChange& f) { return f.field != "firstCorner"; }))
            rows[t].insert(r.row);
    }
    for (const Vertex v : rec.removed_vertices) rows[kV].insert(v.idx);
    for (const Edge e : rec.removed_edges) rows[kE].insert(e.idx);
    for (const Face f : rec.removed_faces) rows[kF].insert(f.idx);
    for (int t = 0; t < kTables; ++t) q.rows[t].assign(rows[t].begin(), rows[t].end());
    q.added = {static_cast<int32_t>(rec.added_vertices.size()), static_cast<int32_t>(rec.added_edges.size()),
               static_cast<int32_t>(rec.added_faces.size())};
    q.operation = describe(op);
    return q;
}

// Greedy assignment of student rows to core elements by votes (largest first, ties to the
// earlier row and element); rows and elements left over are paired in order. Returns per
// row the element, kNone for a row that takes no part (participates[r] == 0).
std::vector<int32_t> assign(const std::vector<std::vector<int>>& votes, const std::vector<int32_t>& elements,
                            const std::vector<char>& participates) {
    const std::size_t R = votes.size(), C = elements.size();
    std::vector<int32_t> out(R, kNone);
    std::vector<char> taken(C, 0);
    struct Pair {
        int score;
        std::size_t r, c;
    };
    std::vector<Pair> pairs;
    for (std::size_t r = 0; r < R; ++r)
        if (participates[r])
            for (std::size_t c = 0; c < C; ++c)
                if (votes[r][c] > 0) pairs.push_back({votes[r][c], r, c});
    std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.score > b.score; });
    for (const Pair& p : pairs)
        if (out[p.r] == kNone && !taken[p.c]) {
            out[p.r] = elements[p.c];
            taken[p.c] = 1;
        }
    std::size_t c = 0;
    for (std::size_t r = 0; r < R; ++r) {
        if (!participates[r] || out[r] != kNone) continue;
        while (c < C && taken[c]) ++c;
        if (c == C) break;
        out[r] = elements[c];
        taken[c] = 1;
    }
    return out;
}

struct Run {
    const WingedEdgeMesh& before;
    const EditAnswer& answer;
    WingedEdgeMesh after;
    ChangeRecord rec;
    EditQuestion q;
    std::array<int32_t, kTables> before_count{};
    std::array<std::vector<int32_t>, kTables> added;       // the core's new elements, in order
    std::array<std::vector<char>, kTables> label_ok;       // per new row
    std::array<std::map<int32_t, std::size_t>, kTables> new_label_row; // usable label -> new row
    std::array<std::vector<int32_t>, kTables> new_row_core; // per new row: the element it was matched to
    std::array<std::vector<int32_t>, kTables> core_label;   // after-index -> the student's label (kUnlabelled)
    std::vector<char> edge_row_reversed;                    // per answer edge row
    std::vector<AnswerFinding> findings;

    Run(const WingedEdgeMesh& b, const Operation& op, const EditAnswer& a) : before(b), answer(a), after(b) {
        rec = after.apply(op);
        q = question_of(before, op, rec);
        for (int t = 0; t < kTables; ++t) before_count[t] = count(before, t);
        for (const Vertex v : rec.added_vertices) added[kV].push_back(v.idx);
        for (const Edge e : rec.added_edges) added[kE].push_back(e.idx);
        for (const Face f : rec.added_faces) added[kF].push_back(f.idx);
        require_shape();
    }

    std::size_t listed(int t) const { return q.rows[t].size(); }
    std::size_t rows(int t) const { return listed(t) + added[t].size(); }

    void require_shape() const {
        for (int t = 0; t < kTables; ++t) {
            const EditTableAnswer& a = answer.tables[t];
            const std::string what = std::string("the ") + table_words(t) + " rows";
            require(a.cells.size() == rows(t) * width(t), "invalid-answer",
                    what + " hold " + std::to_string(a.cells.size()) + " cells; the question has " + std::to_string(rows(t)) +
                        " rows of " + std::to_string(width(t)));
            require(a.removed.size() == rows(t), "invalid-answer",
                    what + " have " + std::to_string(a.removed.size()) + " removed marks, not one per row (" + std::to_string(rows(t)) + ")");
            require(a.labels.size() == added[t].size(), "invalid-answer",
                    what + " give " + std::to_string(a.labels.size()) + " labels for " + std::to_string(added[t].size()) + " new rows");
            for (std::size_t i = 0; i < a.cells.size(); ++i)
                require(a.cells[i] >= kBlank, "invalid-answer", what + ": a cell holds " + std::to_string(a.cells[i]) +
                                                                   "; a cell holds a label (0 names v1, e1 or F1), -1 (none) or -2 (blank)");
            for (const int32_t l : a.labels)
                require(l >= kBlank, "invalid-answer", what + ": a new row's label is " + std::to_string(l) + "; use -2 for none given");
        }
    }

    int32_t cell(int t, std::size_t row, int k) const { return answer.tables[t].cells[row * width(t) + k]; }
    // The element the answer's row describes (kNone: a new row not matched).
    int32_t core_of_row(int t, std::size_t row) const {
        return row < listed(t) ? q.rows[t][row] : new_row_core[t][row - listed(t)];
    }
    // What a student's label names after the operation: an after-index, kNone (none), kBlank,
    // kUnlabelled never (labels are the student's), kNoRow.
    int32_t resolve(int t, int32_t label) const {
        if (label == kNone || label == kBlank) return label;
        if (label >= 0 && label < before_count[t]) return label;
        const auto it = new_label_row[t].find(label);
        if (it == new_label_row[t].end()) return kNoRow;
        const int32_t c = new_row_core[t][it->second];
        return c == kNone ? kNoRow : c;
    }
    std::string row_name(int t, std::size_t row) const {
        std::string prefix = t == kE ? "row " : std::string(t == kV ? "vertex" : "face") + " table, row ";
        if (row < listed(t)) return prefix + label_of(t, q.rows[t][row]);
        const std::size_t n = row - listed(t);
        const std::string nth = "new " + std::string(table_words(t)) + " row " + std::to_string(n + 1);
        return label_ok[t][n] ? nth + " (" + label_of(t, answer.tables[t].labels[n]) + ")" : nth;
    }
    std::string row_label(int t, std::size_t row) const {
        if (row < listed(t)) return label_of(t, q.rows[t][row]);
        const std::size_t n = row - listed(t);
        return label_ok[t][n] ? label_of(t, answer.tables[t].labels[n]) : std::string("this ") + table_words(t);
    }
    int32_t finding_row(int t, std::size_t row) const {
        if (row < listed(t)) return q.rows[t][row];
        const std::size_t n = row - listed(t);
        return label_ok[t][n] ? answer.tables[t].labels[n] : kNone;
    }
    void add(int t, std::size_t row, const std::string& field, int32_t given, int32_t expected, const std::string& code,
             const std::string& reason) {
        AnswerFinding f;
        f.table = static_cast<MeshTable>(t);
        f.row = finding_row(t, row);
        f.field = field;
        f.index = static_cast<int32_t>(row);
        f.given = given;
        f.expected = expected;
        f.code = code;
        f.reason = reason;
        findings.push_back(std::move(f));
    }

    // ---------------------------------------------------------------- labels of the new rows
    void read_labels() {
        for (int t = 0; t < kTables; ++t) {
            const std::vector<int32_t>& labels = answer.tables[t].labels;
            label_ok[t].assign(labels.size(), 0);
            for (std::size_t n = 0; n < labels.size(); ++n) {
                const int32_t l = labels[n];
                const std::size_t row = listed(t) + n;
                const std::string name = "new " + std::string(table_words(t)) + " row " + std::to_string(n + 1);
                if (l == kBlank) {
                    add(t, row, "label", l, kNone, "blank-label",
                        name + " has no label: a new " + table_words(t) + " takes a label no " + table_words(t) + " had before " + q.operation +
                            ", your choice");
                } else if (l < before_count[t]) {
                    add(t, row, "label", l, kNone, "used-label",
                        name + " is labelled " + (l == kNone ? std::string("none") : label_of(t, l)) + ", which the mesh already has: a new " +
                            table_words(t) + " takes a label no " + table_words(t) + " had before " + q.operation);
                } else if (new_label_row[t].count(l)) {
                    add(t, row, "label", l, kNone, "duplicate-label",
                        name + " has the label " + label_of(t, l) + " of another new row: each new " + table_words(t) + " has its own label");
                } else {
                    new_label_row[t][l] = n;
                    label_ok[t][n] = 1;
                }
            }
        }
    }

    // ---------------------------------------------------------------- the bijection
    // New vertices by the edges that name them: an edge row whose S or E holds the label, and
    // the vertex row's own edge; then new edges by their two ends; then new faces by the L
    // and R cells that name them and the face row's own edge.
    void match() {
        for (int t = 0; t < kTables; ++t) new_row_core[t].assign(added[t].size(), kNone);
        const auto row_of_label = [&](int t, int32_t label) -> int {
            const auto it = new_label_row[t].find(label);
            return it == new_label_row[t].end() ? -1 : static_cast<int>(it->second);
        };
        const auto index_of = [&](int t, int32_t element) -> int {
            const auto it = std::find(added[t].begin(), added[t].end(), element);
            return it == added[t].end() ? -1 : static_cast<int>(it - added[t].begin());
        };
        // vertices
        {
            std::vector<std::vector<int>> votes(added[kV].size(), std::vector<int>(added[kV].size(), 0));
            for (std::size_t row = 0; row < listed(kE); ++row) {
                if (answer.tables[kE].removed[row]) continue;
                const EdgeRecord& r = after.edge(q.rows[kE][row]);
                for (int k = 0; k < 2; ++k) {
                    const int s = row_of_label(kV, cell(kE, row, k));
                    if (s < 0) continue;
                    for (const int32_t end : {r.start, r.end}) {
                        const int c = index_of(kV, end);
                        if (c >= 0) votes[s][c] += 1;
                    }
                }
            }
            for (std::size_t n = 0; n < added[kV].size(); ++n) {
                const int32_t e = cell(kV, listed(kV) + n, 0);
                if (e < 0 || e >= before_count[kE] || deleted(after, kE, e)) continue;
                for (const int32_t end : {after.edge(e).start, after.edge(e).end}) {
                    const int c = index_of(kV, end);
                    if (c >= 0) votes[n][c] += 1;
                }
            }
            new_row_core[kV] = assign(votes, added[kV], label_ok[kV]);
        }
        // edges: both ends right weighs more than any number of other cells
        {
            const std::size_t n_new = added[kE].size();
            std::vector<std::vector<int>> votes(n_new, std::vector<int>(n_new, 0));
            for (std::size_t n = 0; n < n_new; ++n) {
                const std::size_t row = listed(kE) + n;
                const int32_t s = resolve(kV, cell(kE, row, 0)), e = resolve(kV, cell(kE, row, 1));
                for (std::size_t c = 0; c < n_new; ++c) {
                    const EdgeRecord& r = after.edge(added[kE][c]);
                    int score = 0;
                    if ((s == r.start && e == r.end) || (s == r.end && e == r.start)) score += 100;
                    else if (s == r.start || s == r.end || e == r.start || e == r.end) score += 10;
                    // the wings that name existing edges
                    const auto mine = cells_of(r);
                    int same = 0, other = 0;
                    const auto rev = reversed_cells(mine);
                    for (int k = 4; k < kEdgeCells; ++k) {
                        const int32_t given = cell(kE, row, k);
                        if (given < 0 || given >= before_count[kE]) continue;
                        same += given == mine[k];
                        other += given == rev[k];
                    }
                    votes[n][c] = score + std::max(same, other) + 1; // + 1: every pair may be taken
                }
            }
            new_row_core[kE] = assign(votes, added[kE], label_ok[kE]);
        }
        // orientation of every edge row, now that the edges are matched
        edge_row_reversed.assign(rows(kE), 0);
        for (std::size_t row = 0; row < rows(kE); ++row) {
            const int32_t e = core_of_row(kE, row);
            if (e == kNone || deleted(after, kE, e) || !free_direction(row, e)) continue;
            const auto mine = cells_of(after.edge(e));
            const auto rev = reversed_cells(mine);
            int same = 0, other = 0;
            for (int k = 0; k < kEdgeCells; ++k) {
                const int t = kEdgeCellTable[k];
                const int32_t given = resolve(t, cell(kE, row, k));
                // faces are not matched yet: compare the vertices and the wings that decide
                if (t == kF) continue;
                same += given == mine[k];
                other += given == rev[k];
            }
            edge_row_reversed[row] = other > same;
        }
        // faces
        {
            const std::size_t n_new = added[kF].size();
            std::vector<std::vector<int>> votes(n_new, std::vector<int>(n_new, 0));
            for (std::size_t row = 0; row < rows(kE); ++row) {
                const int32_t e = core_of_row(kE, row);
                if (e == kNone || deleted(after, kE, e) || answer.tables[kE].removed[row]) continue;
                auto mine = cells_of(after.edge(e));
                if (edge_row_reversed[row]) mine = reversed_cells(mine);
                for (int k = 2; k < 4; ++k) {
                    const int s = row_of_label(kF, cell(kE, row, k));
                    const int c = index_of(kF, mine[k]);
                    if (s >= 0 && c >= 0) votes[s][c] += 2;
                }
            }
            for (std::size_t n = 0; n < n_new; ++n) {
                const int32_t e = resolve(kE, cell(kF, listed(kF) + n, 0));
                if (e < 0 || deleted(after, kE, e)) continue;
                for (const int32_t f : {after.edge(e).left, after.edge(e).right}) {
                    const int c = index_of(kF, f);
                    if (c >= 0) votes[n][c] += 1;
                }
            }
            new_row_core[kF] = assign(votes, added[kF], label_ok[kF]);
        }
        for (int t = 0; t < kTables; ++t) {
            core_label[t].assign(count(after, t), kUnlabelled);
            for (int32_t i = 0; i < before_count[t]; ++i) core_label[t][i] = i;
            for (std::size_t n = 0; n < added[t].size(); ++n)
                if (new_row_core[t][n] != kNone) core_label[t][new_row_core[t][n]] = answer.tables[t].labels[n];
        }
    }

    // A new edge, or one whose two ends the operation replaced (a flip), may be written
    // either way round; any other edge keeps the direction its row had.
    bool free_direction(std::size_t row, int32_t e) const {
        if (row >= listed(kE)) return true;
        const EdgeRecord& b = before.edge(e);
        const EdgeRecord& a = after.edge(e);
        return b.start != a.start && b.start != a.end && b.end != a.start && b.end != a.end;
    }

    int32_t label_in_answer(int t, int32_t element) const { return element == kNone ? kNone : core_label[t][element]; }

    // ---------------------------------------------------------------- the cells
    std::string column_reason(std::size_t row, int k, const std::array<int32_t, kEdgeCells>& expected_core) const {
        const std::string e = row_label(kE, row);
        // name S or E only when the student's own S or E is right (it is then no news)
        const auto end_name = [&](int which) {
            const int32_t given = cell(kE, row, which);
            const int32_t want = label_in_answer(kV, expected_core[which]);
            return given >= 0 && given == want ? " (" + vertex_label(given) + ")" : std::string();
        };
        switch (k) {
        case 0:
        case 1:
            return std::string("after ") + q.operation + ", S and E are the two vertices " + e +
                   " joins, S where it starts (its wings and faces must be read the same way round): re-read what the operation does to " + e + "'s ends";
        case 2:
            return std::string("L is the face that runs along ") + e + " from S to E (faces run counter-clockwise), none on a boundary side: re-read which faces lie beside " + e + " after " + q.operation;
        case 3:
            return std::string("R is the face that runs along ") + e + " from E to S (faces run counter-clockwise), none on a boundary side: re-read which faces lie beside " + e + " after " + q.operation;
        case 4:
            return std::string("after ") + q.operation + ", S:L is the edge after " + e + " counter-clockwise around its start" + end_name(0) +
                   ", the other edge at S of the face on the left (a boundary counts as a face): re-read the wing rule";
        case 5:
            return std::string("after ") + q.operation + ", S:R is the edge before " + e + " counter-clockwise around its start" + end_name(0) +
                   ", the other edge at S of the face on the right (a boundary counts as a face): re-read the wing rule";
        case 6:
            return std::string("after ") + q.operation + ", E:L is the edge before " + e + " counter-clockwise around its end" + end_name(1) +
                   ", the other edge at E of the face on the left (a boundary counts as a face): re-read the wing rule";
        default:
            return std::string("after ") + q.operation + ", E:R is the edge after " + e + " counter-clockwise around its end" + end_name(1) +
                   ", the other edge at E of the face on the right (a boundary counts as a face): re-read the wing rule";
        }
    }

    void check_removed(int t, std::size_t row, bool& skip) {
        const bool marked = answer.tables[t].removed[row] != 0;
        skip = false;
        if (row >= listed(t)) {
            if (marked) add(t, row, "removed", 1, 0, "new-removed", row_name(t, row) + " is marked removed: a new row is an element the operation adds");
            return;
        }
        const bool gone = deleted(after, t, q.rows[t][row]);
        if (gone) skip = true;
        if (marked && !gone) {
            add(t, row, "removed", 1, 0, "kept",
                row_name(t, row) + " is marked removed: re-read which elements " + q.operation + " removes and which it only rewires");
            skip = true;
        } else if (!marked && gone) {
            add(t, row, "removed", 0, 1, "removed",
                row_name(t, row) + " is written as a row of the mesh after " + q.operation + ": re-read which elements the operation removes");
        }
    }

    void check_edges() {
        for (std::size_t row = 0; row < rows(kE); ++row) {
            bool skip = false;
            check_removed(kE, row, skip);
            const int32_t e = core_of_row(kE, row);
            if (skip || e == kNone || (row >= listed(kE) && !label_ok[kE][row - listed(kE)])) continue;
            auto expected_core = cells_of(after.edge(e));
            if (edge_row_reversed[row]) expected_core = reversed_cells(expected_core);
            for (int k = 0; k < kEdgeCells; ++k) {
                const int t = kEdgeCellTable[k];
                const int32_t want = label_in_answer(t, expected_core[k]);
                if (want == kUnlabelled) continue;
                const int32_t given = cell(kE, row, k);
                if (given == want) continue;
                const std::string where = row_name(kE, row) + ", column " + kEdgeColumn[k];
                if (given == kBlank) {
                    add(kE, row, kEdgeField[k], given, want, "blank",
                        where + " is blank: every cell of a row the operation rewrites is written (none where there is no face)");
                } else if (given != kNone && resolve(t, given) == kNoRow) {
                    add(kE, row, kEdgeField[k], given, want, "unknown-label",
                        where + " names " + label_of(t, given) + ", which no " + table_words(t) + " has after " + q.operation +
                            " (new rows take the labels you gave them)");
                } else if (given != kNone && deleted(after, t, resolve(t, given))) {
                    const bool earlier = resolve(t, given) < before_count[t] && deleted(before, t, resolve(t, given));
                    add(kE, row, kEdgeField[k], given, want, "removed-element",
                        where + " names " + label_of(t, given) + ", which " + (earlier ? std::string("an earlier edit removed") : q.operation + " removes") +
                            ": " + column_reason(row, k, expected_core));
                } else {
                    const char* code = t == kV ? "wrong-vertex" : t == kF ? "wrong-face" : "wrong-wing";
                    add(kE, row, kEdgeField[k], given, want, code, where + ": " + column_reason(row, k, expected_core));
                }
            }
        }
    }

    // The vertex and face tables: any edge of the vertex (side of the face) after the operation.
    void check_stored_edges(int t) {
        for (std::size_t row = 0; row < rows(t); ++row) {
            bool skip = false;
            check_removed(t, row, skip);
            const int32_t x = core_of_row(t, row);
            if (skip || x == kNone || (row >= listed(t) && !label_ok[t][row - listed(t)])) continue;
            const int32_t given = cell(t, row, 0);
            const int32_t stored = t == kV ? after.vertex_edge(x) : after.face_edge(x);
            const int32_t want = label_in_answer(kE, stored);
            const int32_t e = resolve(kE, given);
            bool right;
            if (given == kNone) right = stored == kNone;
            else if (e < 0 || deleted(after, kE, e)) right = false;
            else {
                const EdgeRecord& r = after.edge(e);
                right = t == kV ? (r.start == x || r.end == x) : (r.left == x || r.right == x);
            }
            if (right) continue;
            const std::string where = row_name(t, row);
            if (given == kBlank) {
                add(t, row, "edge", given, want, "blank", where + " is blank: every row the operation rewrites is written");
            } else if (given != kNone && e == kNoRow) {
                add(t, row, "edge", given, want, "unknown-label",
                    where + " names " + edge_label(given) + ", which no edge has after " + q.operation + " (new rows take the labels you gave them)");
            } else if (t == kV) {
                add(t, row, "edge", given, want, "not-incident",
                    where + ": the vertex table stores one of the vertex's own edges as they are after " + q.operation +
                        ": re-read which edges meet " + row_label(kV, row) + " after the operation");
            } else {
                add(t, row, "edge", given, want, "not-on-face",
                    where + ": the face table stores one of the face's sides as they are after " + q.operation + ": re-read which edges bound " +
                        row_label(kF, row) + " after the operation");
            }
        }
    }

    void run() {
        read_labels();
        match();
        check_stored_edges(kV);
        check_edges();
        check_stored_edges(kF);
        // vertex rows, edge rows, face rows, each in answer order (labels first within a row)
        std::stable_sort(findings.begin(), findings.end(), [](const AnswerFinding& a, const AnswerFinding& b) {
            const int ta = a.table == MeshTable::Vertex ? 0 : a.table == MeshTable::Edge ? 1 : 2;
            const int tb = b.table == MeshTable::Vertex ? 0 : b.table == MeshTable::Edge ? 1 : 2;
            if (ta != tb) return ta < tb;
            return a.index < b.index;
        });
    }
};

} // namespace

WingedEdgeMesh edited_exercise_mesh(const IndexedMesh& mesh, const BuildOptions& options, const std::vector<Operation>& edits) {
    require(mesh.face_count() <= kMaxFaces, "invalid-faces",
            "an exercise's mesh has at most " + std::to_string(kMaxFaces) + " faces, not " + std::to_string(mesh.face_count()));
    require(edits.size() <= kMaxEdits, "invalid-argument",
            "an exercise replays at most " + std::to_string(kMaxEdits) + " edits, not " + std::to_string(edits.size()));
    WingedEdgeMesh w = WingedEdgeMesh::build(mesh, options);
    for (const Operation& op : edits) {
        if (op.entry == nullptr) w.compact();
        else w.apply(op);
    }
    return w;
}

EditQuestion edit_question(const WingedEdgeMesh& before, const Operation& op) {
    require(op.entry != nullptr, "unknown-operation", "an operation needs a name (operations.h)");
    WingedEdgeMesh after = before;
    const ChangeRecord rec = after.apply(op);
    return question_of(before, op, rec);
}

EditCheck check_edit_answer(const WingedEdgeMesh& before, const Operation& op, const EditAnswer& answer) {
    require(op.entry != nullptr, "unknown-operation", "an operation needs a name (operations.h)");
    Run r(before, op, answer);
    r.run();
    EditCheck out;
    out.findings = std::move(r.findings);
    return out;
}

EditAnswer worked_edit_answer(const WingedEdgeMesh& before, const Operation& op, const EditAnswer& answer) {
    require(op.entry != nullptr, "unknown-operation", "an operation needs a name (operations.h)");
    Run r(before, op, answer);
    r.read_labels();
    r.match();
    // new elements without a usable row take the next free labels, after every label in use
    EditAnswer w;
    for (int t = 0; t < kTables; ++t) {
        const std::size_t n_new = r.added[t].size();
        EditTableAnswer& out = w.tables[t];
        out.removed.assign(r.rows(t), 0);
        out.cells.assign(r.rows(t) * width(t), kBlank);
        out.labels.assign(n_new, kBlank);
        int32_t next = r.before_count[t];
        for (const auto& entry : r.new_label_row[t]) next = std::max(next, entry.first + 1);
        std::vector<char> taken(n_new, 0);
        for (std::size_t n = 0; n < n_new; ++n)
            for (std::size_t c = 0; c < n_new; ++c)
                if (r.new_row_core[t][n] == r.added[t][c]) taken[c] = 1;
        std::size_t c = 0;
        for (std::size_t n = 0; n < n_new; ++n) {
            if (r.new_row_core[t][n] != kNone) {
                out.labels[n] = r.answer.tables[t].labels[n];
                continue;
            }
            while (taken[c]) ++c;
            taken[c] = 1;
            r.new_row_core[t][n] = r.added[t][c];
            r.core_label[t][r.added[t][c]] = next;
            out.labels[n] = next++;
        }
    }
    for (int t = 0; t < kTables; ++t) {
        EditTableAnswer& out = w.tables[t];
        for (std::size_t row = 0; row < r.rows(t); ++row) {
            const int32_t x = r.core_of_row(t, row);
            if (row < r.listed(t) && deleted(r.after, t, x)) {
                out.removed[row] = 1;
                continue;
            }
            if (t == kE) {
                auto cells = cells_of(r.after.edge(x));
                if (r.edge_row_reversed[row]) cells = reversed_cells(cells);
                for (int k = 0; k < kEdgeCells; ++k) out.cells[row * kEdgeCells + k] = r.label_in_answer(kEdgeCellTable[k], cells[k]);
                continue;
            }
            // a stored edge the student got right is kept
            const int32_t given = r.cell(t, row, 0);
            const int32_t e = given >= 0 ? r.resolve(kE, given) : kNoRow;
            bool keep = false;
            if (e >= 0 && !deleted(r.after, kE, e)) {
                const EdgeRecord& er = r.after.edge(e);
                keep = t == kV ? (er.start == x || er.end == x) : (er.left == x || er.right == x);
            }
            out.cells[row] = keep ? given : r.label_in_answer(kE, t == kV ? r.after.vertex_edge(x) : r.after.face_edge(x));
        }
    }
    return w;
}

} // namespace wingspline::mesh
