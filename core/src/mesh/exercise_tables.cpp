// Checking a student's face table, edge list and adjacency lists (exercise kind 1;
// exercise_tables.h for what is right). The expected values come from the core's winged edge of
// the faces: a face's corners as given (counter-clockwise), an edge's two faces (L, R), a
// vertex's neighbours (the other ends of its edges).
#include "wingspline/mesh/exercise_tables.h"

#include "wingspline/mesh/exercise_feedback.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <utility>

namespace wingspline::mesh {
namespace {

std::vector<int32_t> row_of(const ListAnswer& a, int32_t r) {
    return {a.cells.begin() + a.offsets[r], a.cells.begin() + a.offsets[r + 1]};
}

// A list as a reason writes it: "v2 v4 v3"; a long one (a fan's hub) is cut after
// kListShown items, so a reason stays a sentence however large the exercise.
constexpr std::size_t kListShown = 12;
std::string list_text(const std::vector<int32_t>& items, std::string (*label)(int32_t), const char* separator = " ") {
    std::string s;
    for (std::size_t i = 0; i < items.size() && i < kListShown; ++i) s += (i == 0 ? "" : separator) + label(items[i]);
    if (items.size() > kListShown) s += std::string(separator) + "... (" + std::to_string(items.size()) + " in all)";
    return s;
}

// A list table of `rows` rows (one per vertex or face; the label names the row).
void require_list(const ListAnswer& a, int32_t rows, const std::string& what, std::string (*row_label)(int32_t)) {
    require(a.offsets.size() == static_cast<std::size_t>(rows) + 1, "invalid-answer",
            what + " has " + std::to_string(a.offsets.empty() ? 0 : a.offsets.size() - 1) + " rows; the mesh has " +
                std::to_string(rows));
    require(a.offsets.front() == 0 && a.offsets.back() == static_cast<int32_t>(a.cells.size()) &&
                std::is_sorted(a.offsets.begin(), a.offsets.end()),
            "invalid-answer", what + ": the row offsets must start at 0, never decrease, and end at the number of cells");
    for (int32_t r = 0; r < rows; ++r) {
        require(a.offsets[r + 1] - a.offsets[r] <= 4 * 10000, "invalid-answer", what + ", " + row_label(r) + " lists far too many items");
        for (int32_t i = a.offsets[r]; i < a.offsets[r + 1]; ++i)
            require(a.cells[i] >= kBlank, "invalid-answer",
                    what + ", " + row_label(r) + ", item " + std::to_string(i - a.offsets[r] + 1) + " holds " +
                        std::to_string(a.cells[i]) + "; a cell holds an index (0 names v1, e1 or F1), -1 (none) or -2 (blank)");
    }
}

AnswerFinding finding(MeshTable table, int32_t row, const char* field, int32_t index, int32_t given, int32_t expected,
                      const char* code, std::string reason) {
    AnswerFinding f;
    f.table = table;
    f.row = row;
    f.field = field;
    f.index = index;
    f.given = given;
    f.expected = expected;
    f.code = code;
    f.reason = std::move(reason);
    return f;
}

// One row of a list checked as a set (a polygon's edges, a vertex's neighbours): each right
// item once, nothing else. Wrong entries are paired, in order, with the items still missing.
struct SetRow {
    MeshTable table;
    int32_t row;
    const char* field;
    std::string name;                // "polygon F2"
    std::string rule;                // "P2's sides are e2 e3 e4"
    std::string (*label)(int32_t);   // how an item is written
    int32_t range;                   // items are 0 .. range-1
    const char* wrong_code;          // an item that does not belong
    const char* missing_code;
    std::string wrong_words;         // "is not a side of P2"
    std::string missing_words;       // "a side of P2 is missing"
    std::function<bool(int32_t)> judged = [](int32_t) { return true; }; // false: not judged here
};

struct SetResult {
    std::vector<AnswerFinding> findings;
    std::vector<int32_t> worked;
};

SetResult check_set_row(const SetRow& s, const std::vector<int32_t>& given, const std::vector<int32_t>& expected) {
    std::vector<char> seen(expected.size(), 0);
    std::map<int32_t, std::size_t> slot; // item -> its place in `expected` (items are distinct)
    for (std::size_t k = 0; k < expected.size(); ++k) slot[expected[k]] = k;
    std::vector<int32_t> bad; // positions
    std::vector<char> ok(given.size(), 0), skipped(given.size(), 0);
    for (std::size_t i = 0; i < given.size(); ++i) {
        const int32_t g = given[i];
        const auto it = slot.find(g);
        if (g >= 0 && g < s.range && !s.judged(g) && it == slot.end()) {
            skipped[i] = 1;
            continue;
        }
        if (it != slot.end() && !seen[it->second]) seen[it->second] = 1, ok[i] = 1;
        else bad.push_back(static_cast<int32_t>(i));
    }
    std::vector<int32_t> missing;
    for (std::size_t k = 0; k < expected.size(); ++k)
        if (!seen[k]) missing.push_back(expected[k]);
    SetResult out;
    std::size_t next = 0;
    for (int32_t i : bad) {
        const int32_t g = given[i];
        const int32_t want = next < missing.size() ? missing[next++] : kNone;
        const std::string instead = want == kNone ? "" : "; " + s.label(want) + " is missing there";
        const std::string at = s.name + ", item " + std::to_string(i + 1) + ": ";
        if (g == kBlank) out.findings.push_back(finding(s.table, s.row, s.field, i, g, want, "blank", at + "blank" + instead + "; " + s.rule));
        else if (g < 0 || g >= s.range)
            out.findings.push_back(finding(s.table, s.row, s.field, i, g, want, "unknown-label",
                                           at + (g < 0 ? std::string("none is not ") + (s.table == MeshTable::Vertex ? "a vertex" : "an edge")
                                                       : s.label(g) + " does not exist") + instead + "; " + s.rule));
        else {
            const bool twice = slot.count(g) > 0; // a right item on a wrong entry: its first copy was taken
            out.findings.push_back(finding(s.table, s.row, s.field, i, g, want, s.wrong_code,
                                           at + s.label(g) + (twice ? " is listed twice" : " " + s.wrong_words) + instead + "; " + s.rule));
        }
    }
    for (; next < missing.size(); ++next)
        out.findings.push_back(finding(s.table, s.row, s.field, kNone, kNone, missing[next], s.missing_code,
                                       s.name + ": " + s.label(missing[next]) + " " + s.missing_words + "; " + s.rule));
    // Worked: the right entries in place, each wrong one replaced by the item paired with it,
    // the rest of the missing items after them.
    std::size_t paired = 0;
    for (std::size_t i = 0; i < given.size(); ++i) {
        if (ok[i]) out.worked.push_back(given[i]);
        else if (!skipped[i] && paired < missing.size()) out.worked.push_back(missing[paired++]);
    }
    for (; paired < missing.size(); ++paired) out.worked.push_back(missing[paired]);
    return out;
}

// ------------------------------------------------------------------ faces
// The student's list laid against the cycle: direction (counter-clockwise first) and start.
struct Alignment {
    bool clockwise = false;
    std::vector<int32_t> cycle; // the cycle read from the aligned start in the aligned direction
    int matches = -1;
};

// A face's corners are distinct, so a corner the student wrote at position i sits in place for
// exactly one start per direction: the matches of every (direction, start) counted in one pass.
Alignment align(const std::vector<int32_t>& given, const std::vector<int32_t>& c) {
    const int32_t n = static_cast<int32_t>(c.size());
    std::map<int32_t, int32_t> position;
    for (int32_t p = 0; p < n; ++p) position[c[p]] = p;
    std::vector<int> ccw(n, 0), cw(n, 0);
    for (int32_t i = 0; i < n; ++i) {
        const auto it = position.find(given[i]);
        if (it == position.end()) continue;
        ++ccw[((it->second - i) % n + n) % n]; // a[i] = c[(rot + i) mod n]
        ++cw[(it->second + i) % n];            // a[i] = c[(rot - i) mod n]
    }
    Alignment best;
    int32_t rot = 0;
    for (bool clockwise : {false, true})
        for (int32_t r = 0; r < n; ++r) {
            const int m = clockwise ? cw[r] : ccw[r];
            if (m > best.matches) best.matches = m, best.clockwise = clockwise, rot = r;
        }
    best.cycle.resize(n);
    for (int32_t i = 0; i < n; ++i) best.cycle[i] = best.clockwise ? c[((rot - i) % n + n) % n] : c[(rot + i) % n];
    return best;
}

std::vector<int32_t> ccw_from(const std::vector<int32_t>& c, int32_t first) {
    const auto it = std::find(c.begin(), c.end(), first);
    if (it == c.end()) return c;
    std::vector<int32_t> out(it, c.end());
    out.insert(out.end(), c.begin(), it);
    return out;
}

ListTableResult run_faces(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices, int32_t vertex_count,
                      const ListAnswer& answer) {
    const WingedEdgeMesh mesh = exercise_mesh(face_offsets, face_vertices, vertex_count);
    const int32_t F = static_cast<int32_t>(face_offsets.size()) - 1;
    require_list(answer, F, "the face table", face_label);
    ListTableResult out;
    out.worked.offsets.push_back(0);
    for (int32_t f = 0; f < F; ++f) {
        const std::vector<int32_t> c(face_vertices.begin() + face_offsets[f], face_vertices.begin() + face_offsets[f + 1]);
        const std::vector<int32_t> g = row_of(answer, f);
        const std::string head = "face " + face_label(f) + ": ";
        const std::string rule = face_label(f) + "'s corners counter-clockwise are " + list_text(c, vertex_label) +
                                 " (any corner may come first)";
        std::vector<int32_t> worked = c;
        if (g.size() == c.size()) {
            const Alignment a = align(g, c);
            const std::vector<int32_t> g_sorted = [&] { auto x = g; std::sort(x.begin(), x.end()); return x; }();
            const std::vector<int32_t> c_sorted = [&] { auto x = c; std::sort(x.begin(), x.end()); return x; }();
            if (a.clockwise)
                out.check.findings.push_back(finding(
                    MeshTable::Face, f, "vertices", kNone, kNone, kNone, "clockwise",
                    head + "the corners run clockwise; the lecture lists a face's corners counter-clockwise (seen from the front): " +
                        list_text(ccw_from(c, a.cycle[0]), vertex_label)));
            for (std::size_t i = 0; i < g.size(); ++i) {
                if (g[i] == a.cycle[i]) continue;
                const int32_t want = a.cycle[i];
                const std::string at = "face " + face_label(f) + ", corner " + std::to_string(i + 1) + ": ";
                const std::string read = a.clockwise ? " (reading your clockwise order)" : "";
                if (g[i] == kBlank) out.check.findings.push_back(finding(MeshTable::Face, f, "vertices", i, g[i], want, "blank", at + "blank; it is " + vertex_label(want) + read + "; " + rule));
                else if (g[i] < 0 || g[i] >= vertex_count)
                    out.check.findings.push_back(finding(MeshTable::Face, f, "vertices", i, g[i], want, "unknown-label",
                                                         at + (g[i] < 0 ? std::string("none is not a vertex") : "the mesh has no vertex " + vertex_label(g[i])) +
                                                             "; it is " + vertex_label(want) + read + "; " + rule));
                else if (g_sorted == c_sorted)
                    out.check.findings.push_back(finding(MeshTable::Face, f, "vertices", i, g[i], want, "wrong-order",
                                                         at + "the corners are the right ones in the wrong order: here comes " + vertex_label(want) +
                                                             ", not " + vertex_label(g[i]) + read + "; " + rule));
                else
                    out.check.findings.push_back(finding(MeshTable::Face, f, "vertices", i, g[i], want, "wrong-vertex",
                                                         at + vertex_label(want) + ", not " + vertex_label(g[i]) + read + "; " + rule));
            }
            worked = ccw_from(c, a.cycle[0]);
        } else {
            SetRow s{MeshTable::Face, f, "vertices", "face " + face_label(f), rule, vertex_label, vertex_count, "extra-vertex", "missing-vertex",
                     "is not a corner of " + face_label(f), "is missing (a corner of " + face_label(f) + ")"};
            SetResult r = check_set_row(s, g, c);
            for (AnswerFinding& x : r.findings) out.check.findings.push_back(std::move(x));
            for (int32_t x : g)
                if (std::find(c.begin(), c.end(), x) != c.end()) {
                    worked = ccw_from(c, x);
                    break;
                }
        }
        out.worked.cells.insert(out.worked.cells.end(), worked.begin(), worked.end());
        out.worked.offsets.push_back(static_cast<int32_t>(out.worked.cells.size()));
    }
    return out;
}

// ------------------------------------------------------------------ edge list
enum EdgeColumn { kV1, kV2, kP1, kP2 };
const char* const kEdgeListField[4] = {"v1", "v2", "p1", "p2"};

std::pair<int32_t, int32_t> key(int32_t a, int32_t b) { return {std::min(a, b), std::max(a, b)}; }
std::string polygon_text(int32_t p) { return p == kNone ? "\u03bb" : face_label(p); }

struct EdgeListChecker {
    const WingedEdgeMesh& mesh;
    const EdgeListAnswer& answer;
    int32_t rows = 0;
    std::map<std::pair<int32_t, int32_t>, int32_t> edge_of_pair;
    std::vector<int32_t> row_edge, edge_row, worked_label;
    std::vector<char> row_reversed;
    std::vector<std::array<int32_t, 2>> row_faces; // the worked P1, P2 of a matched row
    std::vector<AnswerFinding> row_findings, missing_findings, polygon_findings;
    ListAnswer worked_polygons;

    EdgeListChecker(const WingedEdgeMesh& m, const EdgeListAnswer& a) : mesh(m), answer(a), rows(static_cast<int32_t>(a.edges.size() / 4)) {
        for (int32_t e = 0; e < m.edge_count(); ++e) edge_of_pair[key(m.edge(e).start, m.edge(e).end)] = e;
        row_edge.assign(rows, kNone);
        row_reversed.assign(rows, 0);
        row_faces.assign(rows, {kNone, kNone});
        edge_row.assign(m.edge_count(), kNone);
    }
    int32_t given(int32_t r, int k) const { return answer.edges[4 * static_cast<std::size_t>(r) + k]; }
    bool is_vertex(int32_t v) const { return v >= 0 && v < mesh.vertex_count(); }
    // (left, right) of edge e run from `from`.
    std::pair<int32_t, int32_t> sides(int32_t e, bool reverse) const {
        const EdgeRecord& x = mesh.edge(e);
        return reverse ? std::make_pair(x.right, x.left) : std::make_pair(x.left, x.right);
    }
    bool polygon_lists(int32_t f, int32_t r) const {
        if (f < 0) return false;
        const auto b = answer.polygons.cells.begin();
        return std::find(b + answer.polygons.offsets[f], b + answer.polygons.offsets[f + 1], r) != b + answer.polygons.offsets[f + 1];
    }
    // How well row r fits edge e: its P1, P2 against e's faces, and the polygons listing it.
    int agreement(int32_t r, int32_t e) const {
        const EdgeRecord& x = mesh.edge(e);
        std::vector<int32_t> want = {x.left, x.right};
        int n = 0;
        for (int k : {kP1, kP2}) {
            const auto it = std::find(want.begin(), want.end(), given(r, k));
            if (it != want.end()) ++n, want.erase(it);
        }
        return n + polygon_lists(x.left, r) + polygon_lists(x.right, r);
    }
    void match(int32_t r, int32_t e, bool reverse) {
        row_edge[r] = e;
        row_reversed[r] = reverse;
        edge_row[e] = r;
    }
    void match_rows();
    void number_edges();
    void check_faces(int32_t r);
    void check_polygons();
};

void EdgeListChecker::match_rows() {
    std::vector<std::vector<int32_t>> claims(mesh.edge_count());
    std::vector<int32_t> bad;
    for (int32_t r = 0; r < rows; ++r) {
        const int32_t s = given(r, kV1), t = given(r, kV2);
        const auto it = is_vertex(s) && is_vertex(t) && s != t ? edge_of_pair.find(key(s, t)) : edge_of_pair.end();
        if (it == edge_of_pair.end()) bad.push_back(r);
        else claims[it->second].push_back(r);
    }
    for (int32_t e = 0; e < mesh.edge_count(); ++e) {
        int32_t best = kNone, best_score = -1;
        for (int32_t r : claims[e])
            if (agreement(r, e) > best_score) best = r, best_score = agreement(r, e);
        for (int32_t r : claims[e])
            if (r == best) match(r, e, given(r, kV1) != mesh.edge(e).start);
            else bad.push_back(r);
    }
    std::sort(bad.begin(), bad.end());
    for (int32_t r : bad) {
        const int32_t s = given(r, kV1), t = given(r, kV2);
        // The edge the row describes: an edge no row has yet at the end it keeps, the one its
        // P1, P2 (and the polygons listing it) agree with best.
        int32_t best = kNone, best_score = -1, kept_column = kV1;
        for (int kept : {kV1, kV2}) {
            const int32_t v = kept == kV1 ? s : t;
            if (!is_vertex(v) || mesh.vertex_edge(v) == kNone) continue;
            for (int32_t e : mesh.edges_around_vertex(v)) {
                if (edge_row[e] != kNone) continue;
                const int score = agreement(r, e);
                if (score > best_score) best = e, best_score = score, kept_column = kept;
            }
        }
        const int32_t wrong_column = best == kNone ? (is_vertex(s) ? kV2 : kV1) : kept_column == kV1 ? kV2 : kV1;
        const int32_t g = given(r, wrong_column);
        int32_t want = kNone;
        if (best != kNone) {
            const int32_t kept_vertex = kept_column == kV1 ? s : t;
            want = mesh.other_vertex(best, kept_vertex);
            const int32_t v1 = kept_column == kV1 ? kept_vertex : want;
            match(r, best, v1 != mesh.edge(best).start);
        }
        const bool pair_given = is_vertex(s) && is_vertex(t);
        const bool duplicate = pair_given && s != t && edge_of_pair.count(key(s, t));
        const char* code = g == kBlank ? "blank" : !is_vertex(g) ? "unknown-label" : duplicate ? "duplicate-edge" : "not-an-edge";
        std::string what = g == kBlank ? std::string("blank")
                           : !is_vertex(g) ? (g == kNone ? std::string("\u03bb is not a vertex") : "the mesh has no vertex " + vertex_label(g))
                           : duplicate ? vertex_label(s) + "-" + vertex_label(t) + " is already the edge of row " +
                                             edge_label(edge_row[edge_of_pair.at(key(s, t))]) + "; each edge has one row"
                           : s == t ? "V\u2081 and V\u2082 are both " + vertex_label(s) + "; an edge joins two different vertices"
                                    : vertex_label(s) + "-" + vertex_label(t) + " is not an edge of the mesh: no face has them as neighbouring corners";
        const std::string fix = want == kNone ? "; every edge at its other vertex already has its row, so this row is none of them"
                                              : "; the row describes the edge " + (kept_column == kV1 ? vertex_label(s) + "-" + vertex_label(want)
                                                                                                   : vertex_label(want) + "-" + vertex_label(t)) +
                                                    " (its polygons fit), so " + (wrong_column == kV1 ? "V\u2081" : "V\u2082") + " is " + vertex_label(want);
        row_findings.push_back(finding(MeshTable::Edge, r, kEdgeListField[wrong_column], kNone, g, want, code, "row " + edge_label(r) + ": " + what + fix));
    }
}

void EdgeListChecker::number_edges() {
    worked_label.assign(mesh.edge_count(), kNone);
    std::vector<int32_t> free_rows;
    for (int32_t r = 0; r < rows; ++r)
        if (row_edge[r] == kNone) free_rows.push_back(r);
    std::size_t next = 0;
    int32_t fresh = rows;
    for (int32_t e = 0; e < mesh.edge_count(); ++e) {
        if (edge_row[e] != kNone) worked_label[e] = edge_row[e];
        else {
            worked_label[e] = next < free_rows.size() ? free_rows[next++] : fresh++;
            const auto p = key(mesh.edge(e).start, mesh.edge(e).end);
            missing_findings.push_back(finding(MeshTable::Edge, kNone, "", kNone, kNone, worked_label[e], "missing-edge",
                                               "the edge " + vertex_label(p.first) + "-" + vertex_label(p.second) +
                                                   " has no row; the edge list has one row per edge of the mesh"));
        }
    }
}

void EdgeListChecker::check_faces(int32_t r) {
    const int32_t e = row_edge[r];
    if (e == kNone) return;
    const auto [left, right] = sides(e, row_reversed[r]);
    std::vector<int32_t> want = {left, right};
    const int32_t p[2] = {given(r, kP1), given(r, kP2)};
    bool ok[2] = {false, false};
    for (int k = 0; k < 2; ++k) {
        const auto it = std::find(want.begin(), want.end(), p[k]);
        if (it != want.end()) ok[k] = true, want.erase(it);
    }
    row_faces[r] = {p[0], p[1]};
    if (ok[0] && ok[1]) return;
    // The faces still to place, in slide order: the one on the left first, lambda last.
    if (want.size() == 2 && want[0] == kNone) std::swap(want[0], want[1]);
    const std::string pair = vertex_label(mesh.edge(e).start) + "-" + vertex_label(mesh.edge(e).end);
    const std::string rule = left == kNone || right == kNone
                                 ? "the edge " + pair + " has one polygon, " + polygon_text(left == kNone ? right : left) +
                                       ", and \u03bb (no polygon) on its other side; either may be P\u2081"
                                 : "the polygons on the edge " + pair + " are " + face_label(left) + " and " + face_label(right) +
                                       "; either may be P\u2081";
    std::size_t next = 0;
    for (int k = 0; k < 2; ++k) {
        if (ok[k]) continue;
        const int32_t w = want[next++];
        const int32_t g = p[k];
        row_faces[r][k] = w;
        const std::string name = k == 0 ? "P\u2081" : "P\u2082";
        const std::string head = "row " + edge_label(r) + ": ";
        if (g == kBlank) row_findings.push_back(finding(MeshTable::Edge, r, kEdgeListField[kP1 + k], kNone, g, w, "blank", head + name + " is blank; it is " + polygon_text(w) + ": " + rule));
        else if (g >= mesh.face_count())
            row_findings.push_back(finding(MeshTable::Edge, r, kEdgeListField[kP1 + k], kNone, g, w, "unknown-label",
                                           head + name + " names " + face_label(g) + ", but the mesh has no polygon " + face_label(g) + "; " + rule));
        else
            row_findings.push_back(finding(MeshTable::Edge, r, kEdgeListField[kP1 + k], kNone, g, w, "wrong-face",
                                           head + name + " is " + polygon_text(w) + ", not " + polygon_text(g) + ": " + rule));
    }
}

void EdgeListChecker::check_polygons() {
    worked_polygons.offsets.push_back(0);
    for (int32_t f = 0; f < mesh.face_count(); ++f) {
        std::vector<int32_t> expected;
        for (int32_t e : mesh.edges_of_face(f)) expected.push_back(worked_label[e]);
        const std::string sides_text = list_text(expected, edge_label, ", ");
        SetRow s{MeshTable::Face, f, "edges", "polygon " + face_label(f), face_label(f) + "'s sides are " + sides_text + " (in any order)", edge_label, rows,
                 "not-on-face", "missing-edge", "is not a side of " + face_label(f), "is missing (a side of " + face_label(f) + ")"};
        s.judged = [this](int32_t g) { return row_edge[g] != kNone; };
        SetResult res = check_set_row(s, row_of(answer.polygons, f), expected);
        for (AnswerFinding& x : res.findings) polygon_findings.push_back(std::move(x));
        worked_polygons.cells.insert(worked_polygons.cells.end(), res.worked.begin(), res.worked.end());
        worked_polygons.offsets.push_back(static_cast<int32_t>(worked_polygons.cells.size()));
    }
}

EdgeListTableResult run_edge_list(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices, int32_t vertex_count,
                             const EdgeListAnswer& answer) {
    const WingedEdgeMesh mesh = exercise_mesh(face_offsets, face_vertices, vertex_count);
    require(answer.edges.size() % 4 == 0, "invalid-answer",
            "the edge list has " + std::to_string(answer.edges.size()) + " cells; each row holds 4 (V\u2081 V\u2082 P\u2081 P\u2082)");
    require(answer.edges.size() / 4 <= 2 * face_vertices.size() + 16, "invalid-answer",
            "the edge list has " + std::to_string(answer.edges.size() / 4) + " rows, far more than the mesh has edges");
    for (std::size_t i = 0; i < answer.edges.size(); ++i)
        require(answer.edges[i] >= kBlank, "invalid-answer",
                "row " + edge_label(static_cast<int32_t>(i / 4)) + ", " + kEdgeListField[i % 4] + " holds " + std::to_string(answer.edges[i]) +
                    "; a cell holds an index (0 names V1 or P1), -1 (\u03bb) or -2 (blank)");
    require_list(answer.polygons, mesh.face_count(), "the polygon table", face_label);
    EdgeListChecker c(mesh, answer);
    c.match_rows();
    c.number_edges();
    for (int32_t r = 0; r < c.rows; ++r) c.check_faces(r);
    c.check_polygons();
    EdgeListTableResult out;
    std::stable_sort(c.row_findings.begin(), c.row_findings.end(), [](const AnswerFinding& a, const AnswerFinding& b) { return a.row < b.row; });
    for (auto* list : {&c.row_findings, &c.missing_findings, &c.polygon_findings})
        for (AnswerFinding& x : *list) out.check.findings.push_back(std::move(x));
    int32_t rows = c.rows;
    for (int32_t label : c.worked_label) rows = std::max(rows, label + 1);
    out.worked.edges.assign(4 * static_cast<std::size_t>(rows), kBlank);
    for (int32_t e = 0; e < mesh.edge_count(); ++e) {
        const int32_t r = c.worked_label[e];
        const bool reverse = c.edge_row[e] != kNone && c.row_reversed[c.edge_row[e]];
        const EdgeRecord& x = mesh.edge(e);
        int32_t* cell = &out.worked.edges[4 * static_cast<std::size_t>(r)];
        cell[kV1] = reverse ? x.end : x.start;
        cell[kV2] = reverse ? x.start : x.end;
        const auto [left, right] = c.sides(e, reverse);
        // A matched row keeps its P1, P2 with the wrong one(s) replaced; a new row reads them
        // from its direction, lambda second as on the slide.
        if (c.edge_row[e] != kNone) cell[kP1] = c.row_faces[r][0], cell[kP2] = c.row_faces[r][1];
        else if (left == kNone) cell[kP1] = right, cell[kP2] = left;
        else cell[kP1] = left, cell[kP2] = right;
    }
    out.worked.polygons = std::move(c.worked_polygons);
    return out;
}

// ------------------------------------------------------------------ adjacency
ListTableResult run_adjacency(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices, int32_t vertex_count,
                              const ListAnswer& answer) {
    const WingedEdgeMesh mesh = exercise_mesh(face_offsets, face_vertices, vertex_count);
    require_list(answer, vertex_count, "the adjacency list", vertex_label);
    // Neighbours: the other end of each edge at v, by edge number (as the core's adjacency lists).
    std::vector<std::vector<int32_t>> around(vertex_count);
    for (int32_t e = 0; e < mesh.edge_count(); ++e) {
        around[mesh.edge(e).start].push_back(mesh.edge(e).end);
        around[mesh.edge(e).end].push_back(mesh.edge(e).start);
    }
    ListTableResult out;
    out.worked.offsets.push_back(0);
    for (int32_t v = 0; v < vertex_count; ++v) {
        const std::string rule = around[v].empty() ? vertex_label(v) + " belongs to no face, so it has no neighbours"
                                                   : vertex_label(v) + "'s neighbours (the other ends of its edges) are " +
                                                         list_text(around[v], vertex_label) + " (in any order)";
        SetRow s{MeshTable::Vertex, v, "vertices", "vertex " + vertex_label(v), rule, vertex_label, vertex_count,
                 "not-adjacent", "missing-vertex", "is not a neighbour of " + vertex_label(v) + " (no edge joins them)",
                 "is missing (an edge joins it to " + vertex_label(v) + ")"};
        SetResult r = check_set_row(s, row_of(answer, v), around[v]);
        for (AnswerFinding& x : r.findings) out.check.findings.push_back(std::move(x));
        out.worked.cells.insert(out.worked.cells.end(), r.worked.begin(), r.worked.end());
        out.worked.offsets.push_back(static_cast<int32_t>(out.worked.cells.size()));
    }
    return out;
}

// A table's result with the value-free words of its findings (exercise_feedback.h).
template <class Result>
Result worded(const char* table, Result r) {
    word_table_findings(table, r.check.findings);
    return r;
}

} // namespace

ListTableResult mark_faces_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                  int32_t vertex_count, const ListAnswer& answer) {
    return worded("faces", run_faces(face_offsets, face_vertices, vertex_count, answer));
}
EdgeListTableResult mark_edge_list_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                          int32_t vertex_count, const EdgeListAnswer& answer) {
    return worded("edge-list", run_edge_list(face_offsets, face_vertices, vertex_count, answer));
}
ListTableResult mark_adjacency_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                      int32_t vertex_count, const ListAnswer& answer) {
    return worded("adjacency", run_adjacency(face_offsets, face_vertices, vertex_count, answer));
}
TableAnswerCheck check_faces_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                    int32_t vertex_count, const ListAnswer& answer) {
    return worded("faces", run_faces(face_offsets, face_vertices, vertex_count, answer)).check;
}
ListAnswer worked_faces_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                               int32_t vertex_count, const ListAnswer& answer) {
    return run_faces(face_offsets, face_vertices, vertex_count, answer).worked;
}
TableAnswerCheck check_edge_list_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                        int32_t vertex_count, const EdgeListAnswer& answer) {
    return worded("edge-list", run_edge_list(face_offsets, face_vertices, vertex_count, answer)).check;
}
EdgeListAnswer worked_edge_list_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                       int32_t vertex_count, const EdgeListAnswer& answer) {
    return run_edge_list(face_offsets, face_vertices, vertex_count, answer).worked;
}
TableAnswerCheck check_adjacency_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                        int32_t vertex_count, const ListAnswer& answer) {
    return worded("adjacency", run_adjacency(face_offsets, face_vertices, vertex_count, answer)).check;
}
ListAnswer worked_adjacency_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                   int32_t vertex_count, const ListAnswer& answer) {
    return run_adjacency(face_offsets, face_vertices, vertex_count, answer).worked;
}

} // namespace wingspline::mesh
