// The edit exercise (exercise_edit.h). The lecture's flip of e3 worked by hand from lecture
// 000's conventions; then thousands of random edits on random meshes (closed, open, polygons,
// after earlier edits that left gaps): the rows that change found independently by comparing
// the tables before and after, the right answer read from the after-mesh's tables under a
// random numbering of the new elements (and either direction of a new or flipped edge, any
// edge of a vertex, any side of a face) is accepted, and every one-cell corruption is named
// on its row and column with a message that never holds the right value.
#include <catch2/catch.hpp>

#include "mesh/random_edits.h"
#include "wingspline/mesh/exercise_edit.h"

#include <map>
#include <set>
#include <sstream>

using namespace wingspline::mesh;
using namespace wingspline::test_edits;

namespace {

constexpr int kV = 0, kE = 1, kF = 2;
const char* const kFields[8] = {"start", "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"};
const int kCellTable[8] = {kV, kV, kF, kF, kE, kE, kE, kE};

int32_t count(const WingedEdgeMesh& m, int t) { return t == kV ? m.vertex_count() : t == kE ? m.edge_count() : m.face_count(); }
bool gone(const WingedEdgeMesh& m, int t, int32_t i) {
    return t == kV ? m.is_deleted(Vertex(i)) : t == kE ? m.is_deleted(Edge(i)) : m.is_deleted(Face(i));
}
std::array<int32_t, 8> row_cells(const EdgeRecord& r) {
    return {r.start, r.end, r.left, r.right, r.start_left, r.start_right, r.end_left, r.end_right};
}
std::string label(int t, int32_t i) { return (t == kV ? "v" : t == kE ? "e" : "F") + std::to_string(i + 1); }

// The rows an edit rewrites, found by comparing the two meshes' tables (not the change record).
std::array<std::vector<int32_t>, 3> changed_rows(const WingedEdgeMesh& before, const WingedEdgeMesh& after) {
    std::array<std::vector<int32_t>, 3> rows;
    for (int t = 0; t < 3; ++t)
        for (int32_t i = 0; i < count(before, t); ++i) {
            if (gone(before, t, i)) continue;
            bool differs = gone(after, t, i);
            if (!differs && t == kV) differs = before.vertex_edge(i) != after.vertex_edge(i);
            if (!differs && t == kF) differs = before.face_edge(i) != after.face_edge(i);
            if (!differs && t == kE) differs = row_cells(before.edge(i)) != row_cells(after.edge(i));
            if (differs) rows[t].push_back(i);
        }
    return rows;
}

struct Built {
    EditAnswer answer;
    std::array<std::vector<int32_t>, 3> core; // per answer row: the after-mesh element it describes
};

// The right answer read from the after-mesh: new elements labelled at random (distinct, above
// every existing label), a new or flipped edge in a random direction, a random edge of each
// vertex and a random side of each face.
Built right_answer(const WingedEdgeMesh& before, const WingedEdgeMesh& after, const std::array<std::vector<int32_t>, 3>& rows,
                   std::mt19937& rng) {
    Built b;
    std::array<std::map<int32_t, int32_t>, 3> label_of; // after-index -> label
    for (int t = 0; t < 3; ++t) {
        for (int32_t i = 0; i < count(before, t); ++i) label_of[t][i] = i;
        std::vector<int32_t> fresh;
        for (int32_t i = count(before, t); i < count(after, t); ++i) fresh.push_back(i);
        std::shuffle(fresh.begin(), fresh.end(), rng);
        std::set<int32_t> used;
        b.core[t] = rows[t];
        for (const int32_t i : fresh) {
            int32_t l;
            do l = count(before, t) + static_cast<int32_t>(rng() % 40); while (used.count(l));
            used.insert(l);
            label_of[t][i] = l;
            b.core[t].push_back(i);
            b.answer.tables[t].labels.push_back(l);
        }
    }
    const auto L = [&](int t, int32_t i) { return i == kNone ? kNone : label_of[t].at(i); };
    for (int t = 0; t < 3; ++t) {
        EditTableAnswer& a = b.answer.tables[t];
        for (std::size_t row = 0; row < b.core[t].size(); ++row) {
            const int32_t x = b.core[t][row];
            const bool removed = gone(after, t, x);
            a.removed.push_back(removed);
            if (t == kE) {
                std::array<int32_t, 8> c = row_cells(after.edge(x));
                const bool is_new = x >= count(before, kE);
                const EdgeRecord& was = before.edge(std::min(x, count(before, kE) - 1));
                const bool flipped = !is_new && !removed && c[0] != was.start && c[0] != was.end && c[1] != was.start && c[1] != was.end;
                if (!removed && (is_new || flipped) && rng() % 2) c = {c[1], c[0], c[3], c[2], c[7], c[6], c[5], c[4]};
                for (int k = 0; k < 8; ++k) a.cells.push_back(removed ? kBlank : L(kCellTable[k], c[k]));
                continue;
            }
            if (removed) {
                a.cells.push_back(kBlank);
                continue;
            }
            std::vector<int32_t> options = t == kV ? after.edges_around_vertex(x) : after.edges_of_face(x);
            a.cells.push_back(options.empty() ? kNone : L(kE, options[rng() % options.size()]));
        }
    }
    return b;
}

// Whether `text` holds `word` as a whole label (e7 in "e7," but not in "e71").
bool holds_label(const std::string& text, const std::string& word) {
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        const std::size_t end = at + word.size();
        const bool starts = at == 0 || !std::isalnum(static_cast<unsigned char>(text[at - 1]));
        const bool ends = end == text.size() || !std::isdigit(static_cast<unsigned char>(text[end]));
        if (starts && ends) return true;
    }
    return false;
}

// The message, less what the question itself says (the operation, the row's label and the
// value the student wrote), must not hold the right value.
void require_value_free(const AnswerFinding& f, const std::string& operation, int cell_table) {
    if (f.expected < 0 || f.field == "removed" || f.field == "label") return;
    std::string text = f.reason;
    for (const std::string& said : {operation, label(static_cast<int>(f.table), f.row)}) {
        for (std::size_t at = text.find(said); at != std::string::npos; at = text.find(said)) text.erase(at, said.size());
    }
    if (f.given >= 0) {
        const std::string given = label(cell_table, f.given);
        for (std::size_t at = text.find(given); at != std::string::npos; at = text.find(given)) text.erase(at, given.size());
    }
    INFO(f.reason);
    CHECK_FALSE(holds_label(text, label(cell_table, f.expected)));
}

int table_of_cell(const AnswerFinding& f) {
    if (f.table != MeshTable::Edge) return kE;
    for (int k = 0; k < 8; ++k)
        if (f.field == kFields[k]) return kCellTable[k];
    return kE;
}

} // namespace

TEST_CASE("flip e3 of the lecture mesh: the question, the slide's rows after it, a wrong wing named without its value",
          "[exercise-edit]") {
    const WingedEdgeMesh w = lecture();
    const Operation op = operation("flip-edge", Edge(2));
    const EditQuestion q = edit_question(w, op);
    // By hand (lecture 000's conventions): the flip turns e3 = v2-v3 into v4 -> v1 inside the
    // quad v1 v2 v4 v3; the wings of e1, e2, e4, e5 that named e3 or each other change; v3
    // stored e3 and now stores e1; F1 stored e1, which left F1, and now stores e3.
    CHECK(q.operation == "flip e3");
    CHECK(q.rows[kV] == std::vector<int32_t>{2});
    CHECK(q.rows[kE] == std::vector<int32_t>{0, 1, 2, 3, 4});
    CHECK(q.rows[kF] == std::vector<int32_t>{0});
    CHECK(q.added == std::array<int32_t, 3>{0, 0, 0});

    // The rows after the flip, as the Euler test works them out by hand.
    const auto e = [](int n) { return n - 1; };
    EditAnswer a;
    a.tables[kV] = {{e(1)}, {0}, {}}; // v3: e1
    a.tables[kE] = {{e(1), e(3), kNone, e(2), e(2), e(3), e(4), e(4),   // e1: v1 v3 - F2 e2 e3 e4 e4
                     e(1), e(2), e(1), kNone, e(3), e(1), e(5), e(6),    // e2: v1 v2 F1 - e3 e1 e5 e6
                     e(4), e(1), e(1), e(2), e(5), e(4), e(2), e(1),     // e3: v4 v1 F1 F2 e5 e4 e2 e1
                     e(3), e(4), kNone, e(2), e(1), e(1), e(7), e(3),    // e4: v3 v4 - F2 e1 e1 e7 e3
                     e(2), e(4), e(1), e(3), e(2), e(6), e(3), e(7)},    // e5: v2 v4 F1 F3 e2 e6 e3 e7
                    std::vector<char>(5, 0), {}};
    a.tables[kF] = {{e(3)}, {0}, {}};
    const EditCheck right = check_edit_answer(w, op, a);
    for (const AnswerFinding& f : right.findings) INFO(f.reason);
    CHECK(right.correct());
    // and written the other way round, e3 = v1 -> v4, it is right too
    EditAnswer reversed = a;
    const int32_t rev[8] = {e(1), e(4), e(2), e(1), e(1), e(2), e(4), e(5)};
    std::copy(rev, rev + 8, reversed.tables[kE].cells.begin() + 16);
    CHECK(check_edit_answer(w, op, reversed).correct());

    // e3's S:L written as e2 (its E:L): one finding on row e3, column S:L, naming the rule
    EditAnswer wrong = a;
    wrong.tables[kE].cells[16 + 4] = e(2);
    const EditCheck c = check_edit_answer(w, op, wrong);
    REQUIRE(c.findings.size() == 1);
    CHECK(c.findings[0].row == 2);
    CHECK(c.findings[0].field == "startLeft");
    CHECK(c.findings[0].code == "wrong-wing");
    CHECK(c.findings[0].expected == e(5));
    CHECK(c.findings[0].reason.find("row e3, column S:L") == 0);
    CHECK(c.findings[0].reason.find("counter-clockwise around its start (v4)") != std::string::npos);
    CHECK_FALSE(holds_label(c.findings[0].reason, "e5"));

    // the worked answer restores it
    const EditAnswer worked = worked_edit_answer(w, op, wrong);
    CHECK(worked.tables[kE].cells == a.tables[kE].cells);
}

TEST_CASE("split e3 of the lecture mesh: new rows under any labels, a used label named", "[exercise-edit]") {
    const WingedEdgeMesh w = lecture();
    const Operation op = operation("split-edge", Edge(2), 0.5);
    const EditQuestion q = edit_question(w, op);
    CHECK(q.added == std::array<int32_t, 3>{1, 1, 0});
    WingedEdgeMesh after = w;
    after.apply(op);
    std::mt19937 rng(7);
    Built b = right_answer(w, after, changed_rows(w, after), rng);
    CHECK(check_edit_answer(w, op, b.answer).correct());
    b.answer.tables[kE].labels[0] = 4; // e5 is taken
    const EditCheck c = check_edit_answer(w, op, b.answer);
    REQUIRE_FALSE(c.correct());
    const auto label_finding = std::find_if(c.findings.begin(), c.findings.end(), [](const AnswerFinding& f) { return f.field == "label"; });
    REQUIRE(label_finding != c.findings.end());
    CHECK(label_finding->code == "used-label");
    CHECK(label_finding->index == 3); // after the three listed rows e1, e3, e4
}

TEST_CASE("random edits on random meshes: any numbering accepted, every one-cell corruption named, no value told",
          "[exercise-edit]") {
    int questions = 0, corruptions = 0;
    std::map<std::string, int> per_op;
#ifdef WINGSPLINE_SANITIZED
    constexpr uint32_t kSeeds = 600;
#else
    constexpr uint32_t kSeeds = 3000;
#endif
    for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
        std::vector<Fixture> all = fixtures();
        WingedEdgeMesh w = std::move(all[seed % all.size()].mesh);
        std::mt19937 rng(seed);
        // earlier edits (they may leave gaps), then the question's edit
        const int earlier = static_cast<int>(rng() % 4);
        for (int k = 0, tries = 0; k < earlier && tries < 50; ++tries) {
            const Call c = random_call(w, rng);
            if (!w.check(operation_of(c)).ok) continue;
            w.apply(operation_of(c));
            ++k;
        }
        Operation op;
        bool found = false;
        for (int tries = 0; tries < 200 && !found; ++tries) {
            op = operation_of(random_call(w, rng));
            found = w.check(op).ok;
        }
        if (!found) continue;
        INFO("seed " << seed << ": " << op.entry->name << " " << op.args[0] << " " << op.args[1] << " " << op.args[2]);
        WingedEdgeMesh after = w;
        after.apply(op);
        const EditQuestion q = edit_question(w, op);
        const auto rows = changed_rows(w, after);
        for (int t = 0; t < 3; ++t) REQUIRE(q.rows[t] == rows[t]);
        REQUIRE(q.added == std::array<int32_t, 3>{after.vertex_count() - w.vertex_count(), after.edge_count() - w.edge_count(),
                                                  after.face_count() - w.face_count()});
        const Built b = right_answer(w, after, rows, rng);
        const EditCheck right = check_edit_answer(w, op, b.answer);
        for (const AnswerFinding& f : right.findings) INFO(f.reason);
        REQUIRE(right.correct());
        ++questions;
        ++per_op[op.entry->name];

        // every cell, one at a time, set to a wrong value
        for (int t = 0; t < 3; ++t) {
            const EditTableAnswer& tab = b.answer.tables[t];
            const int width = t == kE ? 8 : 1;
            for (std::size_t row = 0; row < tab.removed.size(); ++row) {
                const int32_t x = b.core[t][row];
                if (tab.removed[row]) continue;
                for (int k = 0; k < width; ++k) {
                    const int ct = t == kE ? kCellTable[k] : kE;
                    EditAnswer bad = b.answer;
                    int32_t& cell = bad.tables[t].cells[row * width + k];
                    const int32_t was = cell;
                    // a wrong value: another label of that table (a vertex's edge not at it, a
                    // face's edge not on it), none, or blank
                    const int32_t n = count(after, ct);
                    const uint32_t pick = rng() % 8;
                    cell = pick == 0 ? kBlank : pick == 1 ? kNone : static_cast<int32_t>(rng() % static_cast<uint32_t>(n));
                    if (t != kE && cell >= 0) {
                        const int32_t id = cell < count(w, kE) ? cell : kNone;
                        if (id == kNone || gone(after, kE, id)) cell = kBlank;
                        else {
                            const EdgeRecord& r = after.edge(id);
                            if (t == kV ? (r.start == x || r.end == x) : (r.left == x || r.right == x)) cell = kBlank;
                        }
                    }
                    if (t != kE && cell == kNone && was == kNone) cell = kBlank;
                    if (cell == was) continue;
                    // a new element's label is the student's: write a label of one that exists before
                    if (cell >= count(w, ct)) cell = static_cast<int32_t>(rng() % static_cast<uint32_t>(count(w, ct)));
                    if (cell == was) continue;
                    ++corruptions;
                    const EditCheck c = check_edit_answer(w, op, bad);
                    INFO("table " << t << " row " << row << " cell " << k << ": " << was << " -> " << cell);
                    for (const AnswerFinding& f : c.findings) INFO(f.reason);
                    REQUIRE(c.findings.size() == 1);
                    const AnswerFinding& f = c.findings[0];
                    CHECK(static_cast<int>(f.table) == t);
                    CHECK(f.index == static_cast<int32_t>(row));
                    CHECK(f.field == (t == kE ? kFields[k] : "edge"));
                    require_value_free(f, q.operation, table_of_cell(f));
                }
            }
            // the removed mark, flipped on every listed row
            for (std::size_t row = 0; row < b.core[t].size() && row < q.rows[t].size(); ++row) {
                EditAnswer bad = b.answer;
                bad.tables[t].removed[row] = !bad.tables[t].removed[row];
                ++corruptions;
                const EditCheck c = check_edit_answer(w, op, bad);
                for (const AnswerFinding& f : c.findings) INFO(f.reason);
                REQUIRE(c.findings.size() == 1);
                CHECK(c.findings[0].index == static_cast<int32_t>(row));
                CHECK(c.findings[0].field == "removed");
            }
            // a new row's label: blank, or one the mesh has
            for (std::size_t n = 0; n < tab.labels.size(); ++n) {
                EditAnswer bad = b.answer;
                bad.tables[t].labels[n] = rng() % 2 ? kBlank : static_cast<int32_t>(rng() % static_cast<uint32_t>(count(w, t)));
                ++corruptions;
                const EditCheck c = check_edit_answer(w, op, bad);
                const auto named = std::find_if(c.findings.begin(), c.findings.end(), [&](const AnswerFinding& f) {
                    return f.field == "label" && f.index == static_cast<int32_t>(q.rows[t].size() + n);
                });
                CHECK(named != c.findings.end());
            }
        }
        // the worked answer of a blank answer is accepted
        EditAnswer blank = b.answer;
        for (int t = 0; t < 3; ++t) {
            std::fill(blank.tables[t].cells.begin(), blank.tables[t].cells.end(), kBlank);
            std::fill(blank.tables[t].removed.begin(), blank.tables[t].removed.end(), 0);
            std::fill(blank.tables[t].labels.begin(), blank.tables[t].labels.end(), kBlank);
        }
        const EditAnswer worked = worked_edit_answer(w, op, blank);
        const EditCheck again = check_edit_answer(w, op, worked);
        for (const AnswerFinding& f : again.findings) INFO(f.reason);
        REQUIRE(again.correct());
    }
    std::ostringstream figures;
    figures << questions << " questions, " << corruptions << " corruptions;";
    for (const auto& [name, n] : per_op) figures << " " << name << " " << n;
    WARN(figures.str());
    CHECK(questions > static_cast<int>(kSeeds) * 2 / 3); // most seeds find an operation the mesh allows
    CHECK(corruptions > static_cast<int>(kSeeds) * 15);
    CHECK(per_op.size() == operations().size());
}

TEST_CASE("an answer of the wrong shape is refused by name, an edit replayed before the question", "[exercise-edit]") {
    const WingedEdgeMesh w = lecture();
    const Operation op = operation("flip-edge", Edge(2));
    EditAnswer a;
    CHECK_THROWS_WITH(check_edit_answer(w, op, a), Catch::Contains("the vertex rows hold 0 cells"));
    const NamedMesh ex = lecture_example();
    const WingedEdgeMesh edited = edited_exercise_mesh(ex.mesh, ex.options, {operation("split-edge", Edge(2), 0.5)});
    CHECK(edited.vertex_count() == 6);
    CHECK_THROWS_AS(edited_exercise_mesh(ex.mesh, ex.options, {operation("flip-edge", Edge(0))}), wingspline::Error); // a boundary edge
}
