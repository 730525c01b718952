// Checking a student's half-edge table and their predictions of a half-edge walk
// (exercise_half_edge.h). The expected structure is the core's half-edge view of the winged edge
// built from the faces (half_edge.h); only the row numbering is the student's.
#include "wingspline/mesh/exercise_half_edge.h"

#include "wingspline/error.h"
#include "wingspline/mesh/half_edge.h"

#include <algorithm>
#include <array>
#include <map>
#include <tuple>
#include <utility>

namespace wingspline::mesh {
namespace {

constexpr std::array<const char*, kHalfEdgeCellsPerRow> kColumns = {"origin", "face", "next", "prev", "twin"};
enum Column { kOrigin = 0, kFace = 1, kNext = 2, kPrev = 3, kTwin = 4 };

std::string face_or_boundary(int32_t f) { return f == kNone ? std::string("none (the boundary)") : face_label(f); }

// The mesh half-edge h written with its ends and face: "v2 -> v4 on F1".
std::string described(const HalfEdgeMesh& H, int32_t h) {
    return vertex_label(H.origin(h)) + " -> " + vertex_label(H.target(h)) + (H.is_boundary(h) ? " on the boundary" : " on " + face_label(H.face(h)));
}

struct Checker {
    const HalfEdgeMesh& H;
    const HalfEdgeAnswer& a;
    int32_t rows, V, F;
    std::vector<int32_t> id0;   // per row: the half-edge its own origin and face name (kNone: none, or not readable)
    std::vector<int32_t> match; // per row: the mesh half-edge it describes
    std::vector<int32_t> row_of; // per mesh half-edge: the row describing it

    int32_t cell(int32_t r, int k) const { return a.halfedges[static_cast<std::size_t>(kHalfEdgeCellsPerRow) * r + k]; }
    bool is_row(int32_t x) const { return x >= 0 && x < rows; }

    // Which row is which half-edge. A half-edge is its origin and its face (a vertex is a
    // corner of a face once, and has one outgoing boundary half-edge: the winged edge refuses
    // the rest), so a row's own two cells name it; every other cell that points at a row, or
    // from it, is a vote too: row r's next names the row of next(r), so that row's half-edge
    // says r is its prev, and so on. The rows take the half-edges by the most votes first, so
    // one wrong cell (an origin, a face, a pointer) is outvoted by the row's other cells and
    // the rows pointing at it, and is then judged as the one mistake it is.
    void match_rows() {
        std::map<std::pair<int32_t, int32_t>, int32_t> by_origin_face;
        for (int32_t h = 0; h < H.halfedge_count(); ++h) by_origin_face[{H.origin(h), H.face(h)}] = h;
        id0.assign(rows, kNone);
        for (int32_t r = 0; r < rows; ++r) {
            const auto it = by_origin_face.find({cell(r, kOrigin), cell(r, kFace)});
            if (it != by_origin_face.end()) id0[r] = it->second;
        }
        // votes[r][h]: how many pointers say row r is half-edge h.
        std::vector<std::map<int32_t, int32_t>> votes(rows);
        for (int32_t r = 0; r < rows; ++r) {
            if (id0[r] != kNone) votes[r].emplace(id0[r], 0); // its own cells are counted below
            for (int k : {kNext, kPrev, kTwin}) {
                const int32_t x = cell(r, k);
                if (!is_row(x)) continue;
                // r -> x: what r says of x, and what x (through its own cells) says of r.
                if (id0[r] != kNone) votes[x][k == kNext ? H.next(id0[r]) : k == kPrev ? H.prev(id0[r]) : twin(id0[r])] += 1;
                if (id0[x] != kNone) votes[r][k == kNext ? H.prev(id0[x]) : k == kPrev ? H.next(id0[x]) : twin(id0[x])] += 1;
            }
        }
        std::vector<std::tuple<int32_t, int32_t, int32_t>> ranked; // (-score, row, half-edge)
        for (int32_t r = 0; r < rows; ++r)
            for (const auto& [h, n] : votes[r]) {
                const int32_t score = n + (H.origin(h) == cell(r, kOrigin)) + (H.face(h) == cell(r, kFace));
                ranked.emplace_back(-score, r, h);
            }
        std::sort(ranked.begin(), ranked.end());
        match.assign(rows, kNone);
        row_of.assign(H.halfedge_count(), kNone);
        for (const auto& [score, r, h] : ranked)
            if (match[r] == kNone && row_of[h] == kNone) match[r] = h, row_of[h] = r;
        // Rows nothing names (everything blank) take the half-edges left, in order.
        int32_t free_h = 0;
        for (int32_t r = 0; r < rows; ++r) {
            if (match[r] != kNone) continue;
            while (row_of[free_h] != kNone) ++free_h;
            match[r] = free_h, row_of[free_h] = r;
        }
    }

    std::vector<AnswerFinding> findings;

    void add(MeshTable t, int32_t row, const char* field, int32_t given, int32_t expected, const char* code, std::string reason) {
        findings.push_back(AnswerFinding{t, row, field, kNone, given, expected, code, std::move(reason), {}, {}});
    }

    // Does the student's own table already say where row r's half-edge ends (its twin's row,
    // and that row's origin, both right)? Then the message may name that vertex.
    bool own_end_right(int32_t r) const {
        const int32_t t = cell(r, kTwin);
        return is_row(t) && match[t] == twin(match[r]) && cell(t, kOrigin) == H.target(match[r]);
    }

    void check_row(int32_t r) {
        const int32_t h = match[r];
        const std::string row = "row " + half_edge_label(r);
        const std::string is = row + " (" + described(H, h) + ")";
        // origin and face
        for (int k : {kOrigin, kFace}) {
            const int32_t g = cell(r, k);
            const int32_t want = k == kOrigin ? H.origin(h) : H.face(h);
            const std::string col = std::string(", column ") + kColumns[k];
            const std::string right = k == kOrigin ? vertex_label(want) : face_or_boundary(want);
            if (g == kBlank) add(MeshTable::Edge, r, kColumns[k], g, want, "blank", row + col + ": blank; " + is + ", so it is " + right);
            else if (k == kOrigin ? (g < 0 || g >= V) : (g < kNone || g >= F))
                add(MeshTable::Edge, r, kColumns[k], g, want, "unknown-label",
                    row + col + ": " + (g == kNone ? std::string("none is not a vertex") : "the mesh has no " + (k == kOrigin ? vertex_label(g) : face_label(g))) +
                        "; " + is + ", so it is " + right);
            else if (g != want)
                add(MeshTable::Edge, r, kColumns[k], g, want, k == kOrigin ? "wrong-origin" : "wrong-face",
                    row + col + ": " + (k == kOrigin ? vertex_label(g) : face_or_boundary(g)) + ", not " + right + ": " + is +
                        (k == kOrigin ? ", so it leaves " + right : ", and the face on its left is " + right));
        }
        // next, prev, twin: rows
        for (int k : {kNext, kPrev, kTwin}) {
            const int32_t g = cell(r, k);
            const int32_t want_h = k == kNext ? H.next(h) : k == kPrev ? H.prev(h) : twin(h);
            const int32_t want = row_of[want_h];
            const std::string col = std::string(", column ") + kColumns[k];
            const std::string why = k == kNext  ? "next(h) starts where h ends (" + vertex_label(H.target(h)) + ") on the same face (" + face_or_boundary(H.face(h)) + ")"
                                    : k == kPrev ? "prev(h) ends where h starts (" + vertex_label(H.origin(h)) + ") on the same face (" + face_or_boundary(H.face(h)) + ")"
                                                 : "twin(h) runs the same edge the other way, " + vertex_label(H.target(h)) + " -> " + vertex_label(H.origin(h));
            const std::string right = half_edge_label(want) + " (" + described(H, want_h) + ")";
            if (g == kBlank) add(MeshTable::Edge, r, kColumns[k], g, want, "blank", row + col + ": blank; " + is + ": " + why + ", " + right);
            else if (!is_row(g))
                add(MeshTable::Edge, r, kColumns[k], g, want, "unknown-label",
                    row + col + ": " + (g == kNone ? std::string("none is not a half-edge (every half-edge has one)") : "the table has no " + half_edge_label(g)) +
                        "; " + is + ": " + why + ", " + right);
            else if (match[g] != want_h)
                add(MeshTable::Edge, r, kColumns[k], g, want, k == kNext ? "wrong-next" : k == kPrev ? "wrong-prev" : "wrong-twin",
                    row + col + ": " + half_edge_label(g) + " (" + described(H, match[g]) + "), not " + right + ": " + is + ", and " + why);
        }
    }

    void check_vertex(int32_t v) {
        const int32_t g = a.vertex_halfedges[v];
        const int32_t own = H.vertex_halfedge(v);
        const bool boundary = own != kNone && H.is_boundary(own);
        const std::string at = "vertex " + vertex_label(v) + ": ";
        const std::string rule = own == kNone ? vertex_label(v) + " is on no face: none"
                                 : boundary   ? vertex_label(v) + " is on the boundary: its half-edge is the one leaving it with face none, " +
                                                  half_edge_label(row_of[own]) + " (" + described(H, own) + ")"
                                              : "any half-edge leaving " + vertex_label(v) + ", e.g. " + half_edge_label(row_of[own]) + " (" + described(H, own) + ")";
        const int32_t want = own == kNone ? kNone : row_of[own];
        if (g == kBlank) add(MeshTable::Vertex, v, "halfedge", g, want, "blank", at + "blank; " + rule);
        else if (g == kNone && own == kNone) return;
        else if (g == kNone) add(MeshTable::Vertex, v, "halfedge", g, want, "not-outgoing", at + "none, but half-edges leave it; " + rule);
        else if (!is_row(g)) add(MeshTable::Vertex, v, "halfedge", g, want, "unknown-label", at + "the table has no " + half_edge_label(g) + "; " + rule);
        else if (H.origin(match[g]) != v)
            add(MeshTable::Vertex, v, "halfedge", g, want, "not-outgoing", at + half_edge_label(g) + " (" + described(H, match[g]) + ") does not leave it; " + rule);
        else if (boundary && !H.is_boundary(match[g]))
            add(MeshTable::Vertex, v, "halfedge", g, want, "not-boundary", at + half_edge_label(g) + " (" + described(H, match[g]) + ") is not on the boundary; " + rule);
    }

    void check_face(int32_t f) {
        const int32_t g = a.face_halfedges[f];
        const int32_t own = H.face_halfedge(f);
        const int32_t want = row_of[own];
        const std::string at = "face " + face_label(f) + ": ";
        const std::string rule = "any half-edge whose face is " + face_label(f) + ", e.g. " + half_edge_label(want) + " (" + described(H, own) + ")";
        if (g == kBlank) add(MeshTable::Face, f, "halfedge", g, want, "blank", at + "blank; " + rule);
        else if (!is_row(g))
            add(MeshTable::Face, f, "halfedge", g, want, "unknown-label",
                at + (g == kNone ? std::string("none, but every face has half-edges") : "the table has no " + half_edge_label(g)) + "; " + rule);
        else if (H.face(match[g]) != f)
            add(MeshTable::Face, f, "halfedge", g, want, "not-on-face", at + half_edge_label(g) + " (" + described(H, match[g]) + ") is not on it; " + rule);
    }

    HalfEdgeAnswer worked() const {
        HalfEdgeAnswer w;
        w.halfedges.resize(a.halfedges.size());
        for (int32_t r = 0; r < rows; ++r) {
            const int32_t h = match[r];
            const std::array<int32_t, kHalfEdgeCellsPerRow> cells = {H.origin(h), H.face(h), row_of[H.next(h)], row_of[H.prev(h)], row_of[twin(h)]};
            std::copy(cells.begin(), cells.end(), w.halfedges.begin() + static_cast<std::ptrdiff_t>(kHalfEdgeCellsPerRow) * r);
        }
        w.vertex_halfedges.resize(V);
        for (int32_t v = 0; v < V; ++v) {
            const int32_t own = H.vertex_halfedge(v);
            const int32_t g = a.vertex_halfedges[v];
            const bool kept = is_row(g) && H.origin(match[g]) == v && (own == kNone || !H.is_boundary(own) || H.is_boundary(match[g]));
            w.vertex_halfedges[v] = kept ? g : own == kNone ? kNone : row_of[own];
        }
        w.face_halfedges.resize(F);
        for (int32_t f = 0; f < F; ++f) {
            const int32_t g = a.face_halfedges[f];
            w.face_halfedges[f] = is_row(g) && H.face(match[g]) == f ? g : row_of[H.face_halfedge(f)];
        }
        return w;
    }
};

// Value-free words (docs/exercises.md, "Feedback levels"): where, the definition to re-read,
// a nudge. A vertex or face is named only where the student's own table already says it
// right (their face cell of the row; their twin's origin for where the row ends).
void word_findings(const Checker& c, std::vector<AnswerFinding>& findings) {
    for (AnswerFinding& f : findings) {
        if (f.table == MeshTable::Vertex) {
            const std::string v = vertex_label(f.row);
            f.message = "The vertex table, row " + v + ": " +
                        (f.code == "blank"          ? std::string("it is blank")
                         : f.code == "not-boundary" ? "this half-edge leaves " + v + " but is not on the boundary"
                         : f.code == "unknown-label" ? std::string("it names a row the table does not have")
                         : f.given == kNone          ? "none, but half-edges leave " + v
                                                      : "this half-edge does not leave " + v) +
                        ". Re-read: a vertex stores one half-edge whose origin is the vertex; on the boundary, the one whose face is "
                        "none, so that a walk around the vertex from it meets every edge there.";
            f.hint = "Any row whose origin is " + v + " will do, unless " + v + " is on the boundary: then the one of them whose face is none.";
            continue;
        }
        if (f.table == MeshTable::Face) {
            const std::string face = face_label(f.row);
            f.message = "The face table, row " + face + ": " +
                        (f.code == "blank" ? std::string("it is blank") : f.code == "unknown-label" ? std::string("it names no half-edge of the table")
                                                                                                   : "this half-edge is not on " + face) +
                        ". Re-read: a face stores one of its half-edges (one whose face is " + face + ").";
            f.hint = "Any row whose face is " + face + " will do.";
            continue;
        }
        const int32_t r = f.row;
        const int32_t h = c.match[r];
        const bool face_right = c.cell(r, kFace) == c.H.face(h);
        const bool origin_right = c.cell(r, kOrigin) == c.H.origin(h);
        const bool end_right = c.own_end_right(r);
        const std::string same_face = face_right ? (c.H.is_boundary(h) ? std::string(" (the boundary)") : " (" + face_label(c.H.face(h)) + ")") : "";
        const std::string where = "Row " + half_edge_label(r) + ", column " + f.field + ": ";
        const std::string wrong = f.code == "blank" ? "it is blank" : f.code == "unknown-label" ? "it names something the mesh (or the table) does not have"
                                                                                                : "this is not " + f.field + "(" + half_edge_label(r) + ")";
        std::string rule, hint;
        if (f.field == "origin") {
            rule = "origin(h) is the vertex h leaves; h and twin(h) lie on one edge, each leaving one of its ends";
            hint = "Find the edge h runs along and the face on its left (or the boundary): walking along h with that face on your left, you start at origin(h).";
        } else if (f.field == "face") {
            rule = "face(h) is the face on the left of h as it runs from its origin (faces go counter-clockwise); none where that side is the boundary";
            hint = "Walk along h from its origin: the face on your left is face(h), none if your left is outside the mesh.";
        } else if (f.field == "next") {
            rule = "next(h) must start where h ends" + std::string(end_right ? " (" + vertex_label(c.H.target(h)) + ")" : "") +
                   ", and lie on the same face" + same_face + ": the next side counter-clockwise round that face, the boundary loop counting as a face";
            hint = "Stand where h ends, inside the same face, and follow the face's next side.";
        } else if (f.field == "prev") {
            rule = "prev(h) must end where h starts" + std::string(origin_right ? " (" + vertex_label(c.H.origin(h)) + ")" : "") +
                   ", and lie on the same face" + same_face + ": next(prev(h)) = h";
            hint = "Stand where h starts, inside the same face: the side of that face that arrives there is prev(h).";
        } else {
            rule = "twin(h) is the other half of h's edge: it runs the same edge the other way, so twin(twin(h)) = h";
            hint = "Find the row that runs along the same edge the other way round.";
        }
        f.message = where + wrong + ". Re-read: " + rule + ".";
        f.hint = hint;
    }
}

} // namespace

std::string half_edge_label(int32_t h) { return "h" + std::to_string(h + 1); }

HalfEdgeTableResult mark_half_edge_answer(const std::vector<int32_t>& face_offsets, const std::vector<int32_t>& face_vertices,
                                          int32_t vertex_count, const HalfEdgeAnswer& answer, const BuildOptions& options) {
    const WingedEdgeMesh mesh = exercise_mesh(face_offsets, face_vertices, vertex_count, options);
    const HalfEdgeMesh H = HalfEdgeMesh::build(mesh);
    const int32_t rows = H.halfedge_count();
    require(answer.halfedges.size() == static_cast<std::size_t>(kHalfEdgeCellsPerRow) * rows, "invalid-answer",
            "the half-edge table has " + std::to_string(answer.halfedges.size()) + " cells; the mesh has " + std::to_string(rows) +
                " half-edges (two per edge) of 5 cells each (origin face next prev twin)");
    require(answer.vertex_halfedges.size() == static_cast<std::size_t>(mesh.vertex_count()), "invalid-answer",
            "the vertex table has " + std::to_string(answer.vertex_halfedges.size()) + " rows; the mesh has " + std::to_string(mesh.vertex_count()) + " vertices");
    require(answer.face_halfedges.size() == static_cast<std::size_t>(mesh.face_count()), "invalid-answer",
            "the face table has " + std::to_string(answer.face_halfedges.size()) + " rows; the mesh has " + std::to_string(mesh.face_count()) + " faces");
    for (const auto* table : {&answer.halfedges, &answer.vertex_halfedges, &answer.face_halfedges})
        for (std::size_t i = 0; i < table->size(); ++i)
            require((*table)[i] >= kBlank, "invalid-answer",
                    std::string(table == &answer.halfedges ? "row " + half_edge_label(static_cast<int32_t>(i / kHalfEdgeCellsPerRow)) + ", " + kColumns[i % kHalfEdgeCellsPerRow]
                                : table == &answer.vertex_halfedges ? "vertex " + vertex_label(static_cast<int32_t>(i))
                                                                    : "face " + face_label(static_cast<int32_t>(i))) +
                        " holds " + std::to_string((*table)[i]) + "; a cell holds an index (0 names v1, F1 or h1), -1 (none) or -2 (blank)");
    Checker c{H, answer, rows, mesh.vertex_count(), mesh.face_count(), {}, {}, {}, {}};
    c.match_rows();
    for (int32_t r = 0; r < rows; ++r) c.check_row(r);
    for (int32_t v = 0; v < c.V; ++v) c.check_vertex(v);
    for (int32_t f = 0; f < c.F; ++f) c.check_face(f);
    word_findings(c, c.findings);
    HalfEdgeTableResult out;
    out.worked = c.worked();
    out.check.findings = std::move(c.findings);
    out.row_halfedge = c.match;
    return out;
}

WalkStepCheck check_half_edge_walk_step(const WingedEdgeMesh& mesh, bool around_face, int32_t element, int32_t step, int32_t given) {
    const int32_t count = around_face ? mesh.face_count() : mesh.vertex_count();
    require(element >= 0 && element < count, "index-out-of-range",
            missing_element_message(around_face ? MeshTable::Face : MeshTable::Vertex, element, count));
    const std::string name = around_face ? face_label(element) : vertex_label(element);
    require(around_face || mesh.vertex_edge(element) != kNone, "no-walk", name + " belongs to no face: it has no half-edge to walk around");
    const HalfEdgeMesh H = HalfEdgeMesh::build(mesh);
    const std::vector<HalfEdgeStep> steps = around_face ? H.face_walk(element) : H.vertex_walk(element);
    const int32_t n = static_cast<int32_t>(steps.size());
    require(step >= 1 && step <= n, "invalid-step",
            "the walk " + std::string(around_face ? "along " : "around ") + name + " has " + std::to_string(n) +
                " half-edges, so a step is 1 to " + std::to_string(n) + " (step " + std::to_string(n) + " closes it), not " + std::to_string(step));
    const HalfEdgeStep& s = steps[step - 1];
    const std::string from = half_edge_label(s.halfedge);
    WalkStepCheck out;
    out.from = s.halfedge;
    out.expected = s.next;
    out.done = s.next == steps[0].halfedge;
    out.correct = given == s.next;
    const std::string why = around_face ? "the walk along " + name + " goes from " + from + " to next(" + from + "), " + half_edge_label(s.next)
                                        : "the CCW walk around " + name + " goes from " + from + " to twin(prev(" + from + ")): prev(" + from +
                                              ") is " + half_edge_label(s.read) + ", and its twin is " + half_edge_label(s.next);
    const std::string closed = out.done ? "; that is the first half-edge again, so the walk is closed" : "";
    const int32_t total = 2 * mesh.edge_count();
    if (out.correct) {
        out.reason = half_edge_label(s.next) + ": " + why + closed;
        return out;
    }
    const std::string wrong = given == kBlank                    ? std::string("no half-edge given")
                              : given >= 0 && given < total      ? "not " + half_edge_label(given)
                              : given >= 0                       ? "not " + half_edge_label(given) + " (the mesh has no such half-edge)"
                                                                 : "not " + std::to_string(given) + " (that names no half-edge)";
    out.reason = wrong + ": " + why + closed;
    const std::string rule = around_face ? "along a face, h -> next(h): the half-edge that starts where h ends, on the same face"
                                         : "around a vertex counter-clockwise, h -> twin(prev(h)): prev(h) arrives at the vertex along h's "
                                           "face, and its twin leaves the vertex again, on the next face counter-clockwise (the boundary "
                                           "counting as a face)";
    out.message = "Step " + std::to_string(step) + ", from " + from +
                  (given == kBlank ? std::string(": no half-edge is picked") : ": that is not the half-edge the walk reaches next") +
                  ". Re-read the rule: " + rule + "; the walk ends when it comes back to the half-edge it started from.";
    out.hint = around_face ? "Stand where " + from + " ends, inside " + name + ": the side of " + name + " that leaves there is next(" + from + ")."
                           : "First find prev(" + from + "): the half-edge of the same face as " + from + " (or of the boundary loop) that ends at " +
                                 name + "; then take the other half of its edge.";
    return out;
}

} // namespace wingspline::mesh
