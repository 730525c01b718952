// Checking a student's winged-edge table (exercise kind 1). The expected table is
// the core's own winged edge of the faces (whose every entry the tests hold against lecture
// 000's slide); the student's rows are matched to its edges by their S-E vertex pairs, and
// each cell is then compared with the definition's value in the student's orientation.
#include "wingspline/mesh/exercise_check.h"

#include "wingspline/mesh/exercise_feedback.h"

#include "wingspline/mesh/limits.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

namespace wingspline::mesh {
namespace {

enum Column { kS, kE, kL, kR, kSL, kSR, kEL, kER };
constexpr int kCellsPerRow = 8;
const char* const kFieldName[kCellsPerRow] = {"start", "end", "left", "right", "startLeft", "startRight", "endLeft", "endRight"};
// How the slide heads each column, and what it holds, in words.
const char* const kFieldWords[kCellsPerRow] = {
    "S (the Start vertex)", "E (the End vertex)", "L (the face on the Left)", "R (the face on the Right)",
    "the left wing at the Start (S:L)", "the right wing at the Start (S:R)", "the left wing at the End (E:L)",
    "the right wing at the End (E:R)"};

// A mesh edge's row as seen walking it from End to Start: the new Start is the old End and
// the new Left the old Right, so wing X:Y (the other edge at X of the face on side Y) moves
// S:L <-> E:R and S:R <-> E:L.
EdgeRecord reversed(const EdgeRecord& r) {
    EdgeRecord o;
    o.start = r.end;
    o.end = r.start;
    o.left = r.right;
    o.right = r.left;
    o.start_left = r.end_right;
    o.start_right = r.end_left;
    o.end_left = r.start_right;
    o.end_right = r.start_left;
    return o;
}

int32_t cell_of(const EdgeRecord& r, int k) {
    const int32_t cells[kCellsPerRow] = {r.start, r.end, r.left, r.right, r.start_left, r.start_right, r.end_left, r.end_right};
    return cells[k];
}

std::pair<int32_t, int32_t> key(int32_t a, int32_t b) { return {std::min(a, b), std::max(a, b)}; }

// A cell as the table shows it.
std::string face_text(int32_t f) { return f == kNone ? "none" : f == kBlank ? "blank" : face_label(f); }
std::string edge_text(int32_t e) { return e == kNone ? "none" : e == kBlank ? "blank" : edge_label(e); }

// Everything the checker knows, and the match it builds.
struct Checker {
    const WingedEdgeMesh& mesh;
    const WingedEdgeAnswer& answer;
    int32_t rows = 0;
    std::map<std::pair<int32_t, int32_t>, int32_t> edge_of_pair; // (min, max) -> mesh edge
    std::vector<int32_t> row_edge;                              // student row -> mesh edge
    std::vector<char> row_reversed;
    std::vector<int32_t> edge_row;   // mesh edge -> the student's row (kNone: no row describes it)
    std::vector<int32_t> worked_label; // mesh edge -> its number in the worked answer
    std::vector<AnswerFinding> row_findings, missing_findings;

    int32_t label_of(int32_t e) const { return e == kNone ? kNone : worked_label[e]; }

    Checker(const WingedEdgeMesh& m, const WingedEdgeAnswer& a)
        : mesh(m), answer(a), rows(static_cast<int32_t>(a.edges.size() / kCellsPerRow)) {
        for (int32_t e = 0; e < m.edge_count(); ++e) edge_of_pair[key(m.edge(e).start, m.edge(e).end)] = e;
        row_edge.assign(rows, kNone);
        row_reversed.assign(rows, 0);
        edge_row.assign(m.edge_count(), kNone);
    }

    int32_t given(int32_t r, int k) const { return answer.edges[kCellsPerRow * static_cast<std::size_t>(r) + k]; }
    bool is_vertex(int32_t v) const { return v >= 0 && v < mesh.vertex_count(); }
    bool is_row(int32_t e) const { return e >= 0 && e < rows; }

    // The mesh edge's row in the orientation the student chose.
    EdgeRecord expected_row(int32_t e, bool reverse) const { return reverse ? reversed(mesh.edge(e)) : mesh.edge(e); }

    // How many of a row's faces and wings agree with mesh edge e in that orientation: the wings
    // judged by the S-E pair of the row they name (which does not depend on the match). Used
    // to choose between rows that claim the same edge, and an orientation for a row whose
    // S-E cannot be read.
    int agreement(int32_t r, int32_t e, bool reverse) const {
        const EdgeRecord x = expected_row(e, reverse);
        int n = (given(r, kL) == x.left) + (given(r, kR) == x.right);
        for (int k = kSL; k <= kER; ++k) {
            const int32_t g = given(r, k), want = cell_of(x, k);
            if (!is_row(g) || want == kNone) continue;
            const int32_t a = given(g, kS), b = given(g, kE);
            n += key(a, b) == key(mesh.edge(want).start, mesh.edge(want).end);
        }
        return n;
    }

    // The edges at v that no row describes yet (a walk around v: a vertex has few edges, so
    // matching a wrong row costs its degree, not the mesh's size).
    std::vector<int32_t> unmatched_at(int32_t v) const {
        std::vector<int32_t> out;
        for (int32_t e : mesh.edges_around_vertex(v))
            if (edge_row[e] == kNone) out.push_back(e);
        return out;
    }

    void match(int32_t r, int32_t e, bool reverse) {
        row_edge[r] = e;
        row_reversed[r] = reverse;
        edge_row[e] = r;
    }

    // An edge as a pair of vertices, lower number first (the pair, not an orientation).
    std::string pair_words(int32_t e) const {
        const auto p = key(mesh.edge(e).start, mesh.edge(e).end);
        return vertex_label(p.first) + "-" + vertex_label(p.second);
    }

    void add_row_finding(int32_t r, int k, int32_t expected, const char* code, std::string reason) {
        AnswerFinding f;
        f.table = MeshTable::Edge;
        f.row = r;
        f.field = kFieldName[k];
        f.given = given(r, k);
        f.expected = expected;
        f.code = code;
        f.reason = "row " + edge_label(r) + ": " + std::move(reason);
        row_findings.push_back(std::move(f));
    }

    void match_rows();
    void number_edges();
    void check_row(int32_t r);
    std::string wing_reason(int32_t r, int k, const EdgeRecord& x) const;
    std::string face_reason(int k, const EdgeRecord& x) const;
};

// 1. Rows whose S-E is an edge of the mesh; where several rows claim one edge, the row that
//    agrees with it best keeps it. 2. A row whose pair is wrong (no edge, or another row's
//    edge) keeps the end it shares with an edge no row describes, and is read as that edge.
//    3. Rows with S or E blank (or naming no vertex) take the remaining edges that fit the end
//    they do give.
void Checker::match_rows() {
    std::vector<std::vector<int32_t>> claims(mesh.edge_count());
    std::vector<int32_t> bad_pair, unread;
    for (int32_t r = 0; r < rows; ++r) {
        const int32_t s = given(r, kS), t = given(r, kE);
        if (!is_vertex(s) || !is_vertex(t)) {
            unread.push_back(r);
            continue;
        }
        auto it = edge_of_pair.find(key(s, t));
        if (s == t || it == edge_of_pair.end()) bad_pair.push_back(r);
        else claims[it->second].push_back(r);
    }
    std::vector<int32_t> duplicates;
    for (int32_t e = 0; e < mesh.edge_count(); ++e) {
        int32_t best = kNone, best_score = -1;
        for (int32_t r : claims[e]) {
            const int score = agreement(r, e, given(r, kS) != mesh.edge(e).start);
            if (score > best_score) best = r, best_score = score;
        }
        for (int32_t r : claims[e])
            if (r == best) match(r, e, given(r, kS) != mesh.edge(e).start);
            else duplicates.push_back(r);
    }
    std::sort(duplicates.begin(), duplicates.end());
    bad_pair.insert(bad_pair.end(), duplicates.begin(), duplicates.end());
    std::sort(bad_pair.begin(), bad_pair.end());
    for (int32_t r : bad_pair) {
        const int32_t s = given(r, kS), t = given(r, kE);
        const bool duplicate = s != t && edge_of_pair.count(key(s, t));
        // The edge the row describes: an unmatched edge at S or at E, in the orientation its
        // L, R and wings agree with best (the end it keeps breaks a tie). Both ends can be
        // wrong: S = w, E = z for the edge u -> w whose faces and wings the row gives.
        int32_t best = kNone, best_score = -1;
        bool best_reverse = false;
        for (int kept : {kS, kE}) {
            for (int32_t e : unmatched_at(kept == kS ? s : t)) {
                for (bool reverse : {false, true}) {
                    const EdgeRecord x = expected_row(e, reverse);
                    const int ends = (x.start == s) + (x.end == t);
                    const int score = 4 * agreement(r, e, reverse) + ends;
                    if (score > best_score) best = e, best_score = score, best_reverse = reverse;
                }
            }
        }
        std::string reason = duplicate ? vertex_label(s) + "-" + vertex_label(t) + " is already the edge of row " +
                                             edge_label(edge_row[edge_of_pair.at(key(s, t))]) + "; each edge has one row"
                                       : s == t ? "S and E are both " + vertex_label(s) + "; an edge joins two different vertices"
                                                : vertex_label(s) + "-" + vertex_label(t) +
                                                      " is not an edge of the mesh: no face has " + vertex_label(s) +
                                                      " and " + vertex_label(t) + " as neighbouring corners";
        const char* code = duplicate ? "duplicate-edge" : "not-an-edge";
        if (best == kNone) {
            // Only the edges at its two ends were looked at: say so, no more (an edge elsewhere
            // may still lack a row, and then the worked answer gives it this row's number).
            add_row_finding(r, kS, kNone, code, reason + "; every edge at " + vertex_label(s) + " and at " + vertex_label(t) +
                                                    " already has its row, so this row is none of them");
            continue;
        }
        match(r, best, best_reverse);
        const EdgeRecord x = expected_row(best, best_reverse);
        if (x.start != s && x.end != t) {
            // Neither end fits: the row's faces and wings are those of the edge x.
            add_row_finding(r, kS, x.start, code,
                            reason + ". The edge " + pair_words(best) + " has no row, and this row's L, R and wings are those of " +
                                vertex_label(x.start) + " -> " + vertex_label(x.end) + ", so S is " + vertex_label(x.start) +
                                " and E is " + vertex_label(x.end));
            add_row_finding(r, kE, x.end, code, "E is " + vertex_label(x.end) + ", not " + vertex_label(t) + " (see S)");
            continue;
        }
        const int blamed = x.start == s ? kE : kS;
        const int32_t want = cell_of(x, blamed);
        add_row_finding(r, blamed, want, code,
                        reason + ". The edge " + pair_words(best) + " has no row; read with " +
                            (blamed == kS ? "E = " + vertex_label(t) : "S = " + vertex_label(s)) + ", this row is that edge, so " +
                            (blamed == kS ? "S" : "E") + " is " + vertex_label(want));
    }
    // Rows that give one end first: a row with neither takes what they leave.
    std::stable_partition(unread.begin(), unread.end(), [&](int32_t r) { return is_vertex(given(r, kS)) || is_vertex(given(r, kE)); });
    int32_t next_unmatched = 0;
    for (int32_t r : unread) {
        const int32_t s = given(r, kS), t = given(r, kE);
        int32_t best = kNone, best_score = -1;
        bool best_reverse = false;
        // The edges that fit the end the row gives; with neither end, the next edge no row describes.
        while (next_unmatched < mesh.edge_count() && edge_row[next_unmatched] != kNone) ++next_unmatched;
        const std::vector<int32_t> candidates = is_vertex(s) ? unmatched_at(s) : is_vertex(t) ? unmatched_at(t)
                                                : next_unmatched < mesh.edge_count() ? std::vector<int32_t>{next_unmatched}
                                                                                     : std::vector<int32_t>{};
        for (int32_t e : candidates) {
            const EdgeRecord& m = mesh.edge(e);
            for (bool reverse : {false, true}) {
                const EdgeRecord x = reverse ? reversed(m) : m;
                if ((is_vertex(s) && x.start != s) || (is_vertex(t) && x.end != t)) continue;
                const int score = agreement(r, e, reverse);
                if (score > best_score) best = e, best_score = score, best_reverse = reverse;
            }
        }
        if (best != kNone) match(r, best, best_reverse);
        for (int k : {kS, kE}) {
            const int32_t g = given(r, k);
            if (is_vertex(g)) continue;
            const int32_t want = best == kNone ? kNone : cell_of(expected_row(best, best_reverse), k);
            const std::string what = k == kS ? "S" : "E";
            const std::string fix = best == kNone ? (is_vertex(s) || is_vertex(t)
                                                         ? "; every edge at " + vertex_label(is_vertex(s) ? s : t) + " already has a row"
                                                         : std::string("; every edge of the mesh already has a row"))
                                                  : "; the edge " + pair_words(best) + " has no other row, so " + what + " is " +
                                                        vertex_label(want);
            if (g == kBlank) add_row_finding(r, k, want, "blank", what + " is blank" + fix);
            else add_row_finding(r, k, want, "unknown-label",
                                 what + (g == kNone ? " is none, but every edge has two ends"
                                                    : " names " + vertex_label(g) + ", but the mesh has no vertex " + vertex_label(g)) +
                                     fix);
        }
    }
}

// The worked answer's numbering: a matched edge keeps its row's number; the others take the
// unmatched rows' numbers in order, then numbers after the last row.
void Checker::number_edges() {
    worked_label.assign(mesh.edge_count(), kNone);
    int32_t free_row = 0, next_new = rows;
    for (int32_t e = 0; e < mesh.edge_count(); ++e) {
        if (edge_row[e] != kNone) {
            worked_label[e] = edge_row[e];
            continue;
        }
        while (free_row < rows && row_edge[free_row] != kNone) ++free_row;
        worked_label[e] = free_row < rows ? free_row++ : next_new++;
        const EdgeRecord& m = mesh.edge(e);
        AnswerFinding f;
        f.table = MeshTable::Edge;
        f.code = "missing-edge";
        f.reason = "the edge " + pair_words(e) + " (" + (m.left == kNone ? std::string("the boundary") : face_label(m.left)) +
                   " on one side, " + (m.right == kNone ? std::string("the boundary") : face_label(m.right)) +
                   " on the other) has no row; every edge of the mesh needs one";
        missing_findings.push_back(std::move(f));
    }
}

std::string Checker::face_reason(int k, const EdgeRecord& x) const {
    const bool left = k == kL;
    const int32_t from = left ? x.start : x.end, to = left ? x.end : x.start;
    const int32_t face = left ? x.left : x.right;
    const std::string rule = std::string("the face on the ") + (left ? "Left" : "Right") + " is the one whose corners run from " +
                             vertex_label(from) + " to " + vertex_label(to) + " (faces go counter-clockwise)";
    if (face == kNone) return rule + "; no face does, so that side is the boundary: none";
    return rule + ": " + face_label(face);
}

// Wing X:Y = the other edge at X of the face on side Y; S:L and E:R are the next edge
// counter-clockwise around S and E (lecture 000's traversal rule), S:R and E:L the next one
// clockwise.
std::string Checker::wing_reason(int32_t r, int k, const EdgeRecord& x) const {
    const bool at_start = k == kSL || k == kSR;
    const bool on_left = k == kSL || k == kEL;
    const int32_t vertex = at_start ? x.start : x.end;
    const int32_t face = on_left ? x.left : x.right;
    const std::string side = on_left ? "Left" : "Right";
    const std::string face_words = face == kNone
                                       ? "the boundary (" + edge_label(r) + " has no face on its " + side +
                                             "; the boundary counts as a face there)"
                                       : face_label(face) + " (the face on the " + side + " of " + edge_label(r) + ")";
    const bool ccw = k == kSL || k == kER;
    return "it is the other edge at " + vertex_label(vertex) + " (the " + (at_start ? "Start" : "End") + ") of " + face_words +
           "; walking " + (ccw ? "counter-clockwise" : "clockwise") + " around " + vertex_label(vertex) + ", the edge after " +
           edge_label(r) + " is " + edge_text(label_of(cell_of(x, k)));
}


void Checker::check_row(int32_t r) {
    const int32_t e = row_edge[r];
    if (e == kNone) return;
    const EdgeRecord x = expected_row(e, row_reversed[r]);
    // S and E written the other way round with everything else right is one mistake, not six:
    // the row is read in the orientation its faces and wings describe.
    const auto fits = [&](const EdgeRecord& y) {
        for (int k = kL; k < kCellsPerRow; ++k)
            if (given(r, k) != (k < kSL ? cell_of(y, k) : label_of(cell_of(y, k))) || (k >= kSL && !is_row(given(r, k)))) return false;
        return true;
    };
    // Not on a row whose S or E was already judged (read through one end while matching):
    // that finding names the end to fix, and a swap would contradict it.
    const bool ends_judged = std::any_of(row_findings.begin(), row_findings.end(), [&](const AnswerFinding& f) {
        return f.table == MeshTable::Edge && f.row == r && (f.field == kFieldName[kS] || f.field == kFieldName[kE]);
    });
    if (!ends_judged && !fits(x) && fits(reversed(x))) {
        row_reversed[r] = !row_reversed[r];
        add_row_finding(r, kS, x.end, "swapped-ends",
                        "S and E are the other way round: L, R and the wings describe the edge run from " +
                            vertex_label(x.end) + " to " + vertex_label(x.start) + ", so swap them (S = " +
                            vertex_label(x.end) + ", E = " + vertex_label(x.start) + ")");
        return;
    }
    for (int k : {kL, kR}) {
        const int32_t g = given(r, k), want = cell_of(x, k);
        if (g == want) continue;
        const std::string why = face_reason(k, x);
        const std::string name = k == kL ? "L" : "R";
        if (g == kBlank) add_row_finding(r, k, want, "blank", name + " is blank; " + why);
        else if (g >= mesh.face_count())
            add_row_finding(r, k, want, "unknown-label", name + " names " + face_label(g) + ", but the mesh has no face " + face_label(g) + "; " + why);
        else add_row_finding(r, k, want, "wrong-face", kFieldWords[k] + std::string(" is ") + face_text(want) + ", not " + face_text(g) + ": " + why);
    }
    for (int k = kSL; k <= kER; ++k) {
        const int32_t g = given(r, k), wing = cell_of(x, k), want = label_of(wing);
        if (g == want && is_row(g)) continue; // a number past the last row is unknown even where the worked answer adds it
        // A wing naming a row that describes no edge, where the wing's edge has no row either:
        // that row's own finding says what is wrong; judging the wing would repeat it.
        if (is_row(g) && row_edge[g] == kNone && wing != kNone && edge_row[wing] == kNone) continue;
        const std::string why = wing_reason(r, k, x);
        if (g == kBlank) add_row_finding(r, k, want, "blank", kFieldWords[k] + std::string(" is blank; ") + why);
        else if (g >= rows)
            add_row_finding(r, k, want, "unknown-label",
                            kFieldWords[k] + std::string(" names ") + edge_label(g) + ", but the table has no row " + edge_label(g) + "; " + why);
        else add_row_finding(r, k, want, "wrong-wing", kFieldWords[k] + std::string(" is ") + edge_text(want) + ", not " + edge_text(g) + ": " + why);
    }
}

// The vertex and face tables: any incident edge (any side) is right. A cell naming a row
// that describes no edge is not judged (that row has its finding).
struct TableCheck {
    bool ok = true;
    bool judged = true; // false: the cell names a row that describes no edge
    int32_t expected = kNone;
    const char* code = "";
    std::string reason;
};

TableCheck check_vertex_cell(const Checker& c, int32_t v, int32_t g) {
    TableCheck t;
    const int32_t stored = c.mesh.vertex_edge(v);
    t.expected = stored == kNone ? kNone : c.worked_label[stored];
    const std::string head = "vertex " + vertex_label(v) + ": ";
    if (stored == kNone) {
        t.ok = g == kNone;
        t.code = g == kBlank ? "blank" : "not-incident";
        t.reason = head + vertex_label(v) + " belongs to no face, so it has no edge: none";
        return t;
    }
    const std::string rule = "the vertex table stores one edge that touches " + vertex_label(v) + ", e.g. " + edge_label(t.expected);
    if (g == kBlank) t.ok = false, t.code = "blank", t.reason = head + "the edge is blank; " + rule;
    else if (g == kNone) t.ok = false, t.code = "not-incident", t.reason = head + vertex_label(v) + " has edges, so not none; " + rule;
    else if (g >= c.rows) t.ok = false, t.code = "unknown-label", t.reason = head + "the table has no row " + edge_label(g) + "; " + rule;
    else if (c.row_edge[g] == kNone) t.judged = false;
    else if (c.mesh.edge(c.row_edge[g]).start != v && c.mesh.edge(c.row_edge[g]).end != v)
        t.ok = false, t.code = "not-incident",
        t.reason = head + edge_label(g) + " (" + c.pair_words(c.row_edge[g]) + ") does not touch " + vertex_label(v) + "; " + rule;
    return t;
}

TableCheck check_face_cell(const Checker& c, int32_t f, int32_t g) {
    TableCheck t;
    t.expected = c.worked_label[c.mesh.face_edge(f)];
    std::string sides;
    for (int32_t e : c.mesh.edges_of_face(f)) sides += (sides.empty() ? "" : ", ") + edge_label(c.worked_label[e]);
    const std::string head = "face " + face_label(f) + ": ";
    const std::string rule = "the face table stores one side of " + face_label(f) + " (" + sides + ")";
    if (g == kBlank) t.ok = false, t.code = "blank", t.reason = head + "the edge is blank; " + rule;
    else if (g == kNone) t.ok = false, t.code = "not-on-face", t.reason = head + "every face has sides, so not none; " + rule;
    else if (g >= c.rows) t.ok = false, t.code = "unknown-label", t.reason = head + "the table has no row " + edge_label(g) + "; " + rule;
    else if (c.row_edge[g] == kNone) t.judged = false;
    else if (c.mesh.edge(c.row_edge[g]).left != f && c.mesh.edge(c.row_edge[g]).right != f)
        t.ok = false, t.code = "not-on-face", t.reason = head + edge_label(g) + " (" + c.pair_words(c.row_edge[g]) + ") is not a side of " + face_label(f) + "; " + rule;
    return t;
}

// An exercise's mesh is worked by hand: far below this. The bound keeps the matching's
// quadratic repairs (a wrong row is compared with each unmatched edge) cheap.
constexpr int32_t kExerciseMaxFaces = 10000;

void require_exercise_faces(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                            int32_t vertex_count) {
    require(vertex_count >= 0 && vertex_count <= 4 * kExerciseMaxFaces, "invalid-faces",
            "the vertex count must be a whole number from 0 to " + std::to_string(4 * kExerciseMaxFaces) + ", not " + std::to_string(vertex_count));
    require(!face_offsets.empty() && face_offsets.front() == 0 && face_offsets.back() == static_cast<int32_t>(face_vertices.size()) &&
                std::is_sorted(face_offsets.begin(), face_offsets.end()),
            "invalid-faces", "the face offsets must start at 0, never decrease, and end at the number of corners listed");
    const int32_t F = static_cast<int32_t>(face_offsets.size()) - 1;
    require(F <= kExerciseMaxFaces, "invalid-faces",
            "an exercise's mesh has at most " + std::to_string(kExerciseMaxFaces) + " faces, not " + std::to_string(F));
}

WingedEdgeMesh winged_edge_exercise_mesh(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                         int32_t vertex_count, const WingedEdgeAnswer& answer) {
    require_exercise_faces(face_offsets, face_vertices, vertex_count);
    const int32_t F = static_cast<int32_t>(face_offsets.size()) - 1;
    require(answer.edges.size() % kCellsPerRow == 0, "invalid-answer",
            "the edge table has " + std::to_string(answer.edges.size()) + " cells; each row holds 8 (S E L R S:L S:R E:L E:R)");
    require(answer.vertex_edges.size() == static_cast<std::size_t>(vertex_count), "invalid-answer",
            "the vertex table has " + std::to_string(answer.vertex_edges.size()) + " rows; the mesh has " + std::to_string(vertex_count) + " vertices");
    require(answer.face_edges.size() == static_cast<std::size_t>(F), "invalid-answer",
            "the face table has " + std::to_string(answer.face_edges.size()) + " rows; the mesh has " + std::to_string(F) + " faces");
    require(answer.edges.size() / kCellsPerRow <= 2 * face_vertices.size() + 16, "invalid-answer",
            "the edge table has " + std::to_string(answer.edges.size() / kCellsPerRow) + " rows, far more than the mesh has edges");
    for (std::size_t i = 0; i < answer.edges.size(); ++i)
        require(answer.edges[i] >= kBlank, "invalid-answer",
                "row " + edge_label(static_cast<int32_t>(i / kCellsPerRow)) + ", " + kFieldName[i % kCellsPerRow] + " holds " +
                    std::to_string(answer.edges[i]) + "; a cell holds an index (0 names v1, e1 or F1), -1 (none) or -2 (blank)");
    for (const auto* table : {&answer.vertex_edges, &answer.face_edges})
        for (std::size_t i = 0; i < table->size(); ++i)
            require((*table)[i] >= kBlank, "invalid-answer",
                    std::string(table == &answer.vertex_edges ? "vertex " + vertex_label(static_cast<int32_t>(i)) : "face " + face_label(static_cast<int32_t>(i))) +
                        " holds " + std::to_string((*table)[i]) + "; a cell holds an index (0 names v1, e1 or F1), -1 (none) or -2 (blank)");
    return exercise_mesh(face_offsets, face_vertices, vertex_count);
}

Checker run_checker(const WingedEdgeMesh& mesh, const WingedEdgeAnswer& answer) {
    Checker c(mesh, answer);
    c.match_rows();
    c.number_edges();
    for (int32_t r = 0; r < c.rows; ++r) c.check_row(r);
    return c;
}

} // namespace

WingedEdgeMesh exercise_mesh(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                             int32_t vertex_count, const BuildOptions& options) {
    require_exercise_faces(face_offsets, face_vertices, vertex_count);
    IndexedMesh m;
    m.positions.assign(3 * static_cast<std::size_t>(vertex_count), 0.0); // the checks read connectivity only
    m.face_offsets = face_offsets;
    m.face_vertices = face_vertices;
    return WingedEdgeMesh::build(m, options);
}

AnswerCheck check_winged_edge_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                     int32_t vertex_count, const WingedEdgeAnswer& answer) {
    const WingedEdgeMesh mesh = winged_edge_exercise_mesh(face_offsets, face_vertices, vertex_count, answer);
    Checker c = run_checker(mesh, answer);
    AnswerCheck out;
    std::stable_sort(c.row_findings.begin(), c.row_findings.end(),
                     [](const AnswerFinding& a, const AnswerFinding& b) { return a.row < b.row; });
    out.findings = std::move(c.row_findings);
    for (AnswerFinding& f : c.missing_findings) out.findings.push_back(std::move(f));
    const auto add = [&](MeshTable table, int32_t row, int32_t g, const TableCheck& t) {
        if (t.ok) return;
        AnswerFinding f;
        f.table = table;
        f.row = row;
        f.field = "edge";
        f.given = g;
        f.expected = t.expected;
        f.code = t.code;
        f.reason = t.reason;
        out.findings.push_back(std::move(f));
    };
    for (int32_t v = 0; v < mesh.vertex_count(); ++v) add(MeshTable::Vertex, v, answer.vertex_edges[v], check_vertex_cell(c, v, answer.vertex_edges[v]));
    for (int32_t f = 0; f < mesh.face_count(); ++f) add(MeshTable::Face, f, answer.face_edges[f], check_face_cell(c, f, answer.face_edges[f]));
    word_table_findings("winged-edge", out.findings);
    out.row_edge = std::move(c.row_edge);
    out.row_reversed = std::move(c.row_reversed);
    return out;
}

WingedEdgeAnswer worked_winged_edge_answer(const std::vector<int32_t>& face_offsets,
                                           const std::vector<int32_t>& face_vertices, int32_t vertex_count,
                                           const WingedEdgeAnswer& answer) {
    const WingedEdgeMesh mesh = winged_edge_exercise_mesh(face_offsets, face_vertices, vertex_count, answer);
    const Checker c = run_checker(mesh, answer);
    int32_t rows = c.rows;
    for (int32_t label : c.worked_label) rows = std::max(rows, label + 1);
    WingedEdgeAnswer w;
    // A row that describes no edge of the mesh stays, blank, so the other numbers keep their meaning.
    w.edges.assign(kCellsPerRow * static_cast<std::size_t>(rows), kBlank);
    for (int32_t e = 0; e < mesh.edge_count(); ++e) {
        const int32_t r = c.worked_label[e];
        const EdgeRecord x = c.expected_row(e, c.edge_row[e] != kNone && c.row_reversed[c.edge_row[e]]);
        for (int k = 0; k < kCellsPerRow; ++k) {
            const int32_t v = cell_of(x, k);
            w.edges[kCellsPerRow * static_cast<std::size_t>(r) + k] = k < kSL || v == kNone ? v : c.worked_label[v];
        }
    }
    for (int32_t v = 0; v < mesh.vertex_count(); ++v) {
        const TableCheck t = check_vertex_cell(c, v, answer.vertex_edges[v]);
        w.vertex_edges.push_back(t.ok && t.judged ? answer.vertex_edges[v] : t.expected);
    }
    for (int32_t f = 0; f < mesh.face_count(); ++f) {
        const TableCheck t = check_face_cell(c, f, answer.face_edges[f]);
        w.face_edges.push_back(t.ok && t.judged ? answer.face_edges[f] : t.expected);
    }
    return w;
}

} // namespace wingspline::mesh
