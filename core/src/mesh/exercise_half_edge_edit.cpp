// The edit exercise in half-edge terms (exercise_half_edge_edit.h): the half-edge view built
// before and after the operation on a copy (an exercise's mesh is small), compared row by row.
#include "wingspline/mesh/exercise_half_edge_edit.h"

#include "wingspline/error.h"
#include "wingspline/mesh/half_edge.h"

namespace wingspline::mesh {
namespace {

constexpr int kVertex = static_cast<int>(MeshTable::Vertex);
constexpr int kHalf = static_cast<int>(MeshTable::Edge);
constexpr int kFace = static_cast<int>(MeshTable::Face);
constexpr int kHalfWidth = 4; // origin, face, next, prev
const char* const kHalfFields[kHalfWidth] = {"origin", "face", "next", "prev"};

int width(int t) { return t == kHalf ? kHalfWidth : 1; }

std::string half_label(int32_t h) { return "h" + std::to_string(h + 1); }
std::string row_label(int t, int32_t row) {
    return t == kHalf ? half_label(row) : t == kVertex ? vertex_label(row) : face_label(row);
}

struct Views {
    WingedEdgeMesh after;
    HalfEdgeMesh before_view;
    HalfEdgeMesh after_view;
    std::string operation;
};

Views views_of(const WingedEdgeMesh& before, const Operation& op) {
    if (op.entry == nullptr) throw Error("unknown-operation", "an operation needs a name (operations.h)");
    std::string text = edit_question(before, op).operation; // refuses as the edit would
    WingedEdgeMesh after = before;
    after.apply(op);
    HalfEdgeMesh b = HalfEdgeMesh::build(before);
    HalfEdgeMesh a = HalfEdgeMesh::build(after);
    return {std::move(after), std::move(b), std::move(a), std::move(text)};
}

// A half-edge row as the view holds it: origin, face, next, prev (all kNone for a gap).
std::array<int32_t, kHalfWidth> half_row(const HalfEdgeMesh& m, int32_t h) {
    if (h >= m.halfedge_count()) return {kNone, kNone, kNone, kNone};
    return {m.origin(h), m.face(h), m.next(h), m.prev(h)};
}
int32_t single(const HalfEdgeMesh& m, int t, int32_t i) {
    if (t == kVertex) return i < m.vertex_count() ? m.vertex_halfedge(i) : kNone;
    return i < m.face_count() ? m.face_halfedge(i) : kNone;
}
int32_t count_of(const HalfEdgeMesh& m, int t) {
    return t == kHalf ? m.halfedge_count() : t == kVertex ? m.vertex_count() : m.face_count();
}
// Removed by the operation: its row is a gap after and was not before.
bool removed_after(const Views& v, int t, int32_t i) {
    if (t == kHalf) return v.after.is_deleted(Edge(i >> 1));
    if (t == kVertex) return v.after.is_deleted(Vertex(i));
    return v.after.is_deleted(Face(i));
}

HalfEdgeEditQuestion question_of(const Views& v) {
    HalfEdgeEditQuestion q;
    q.operation = v.operation;
    for (int t = 0; t < 3; ++t) {
        const int32_t before_n = count_of(v.before_view, t);
        const int32_t after_n = count_of(v.after_view, t);
        q.before_count[t] = before_n;
        for (int32_t i = 0; i < after_n; ++i) {
            const bool changed = i >= before_n ||
                                 (t == kHalf ? half_row(v.before_view, i) != half_row(v.after_view, i)
                                             : single(v.before_view, t, i) != single(v.after_view, t, i));
            if (changed) q.rows[t].push_back(i);
        }
    }
    return q;
}

// Whether `cell` is a right half-edge for vertex v (t == kVertex) or face f after the edit.
bool fits_single(const Views& v, int t, int32_t element, int32_t cell) {
    const HalfEdgeMesh& m = v.after_view;
    if (cell < 0 || cell >= m.halfedge_count() || m.origin(cell) == kNone) return false;
    if (t == kFace) return m.face(cell) == element;
    if (m.origin(cell) != element) return false;
    // On the boundary the vertex stores a boundary half-edge, so its walk meets the whole fan.
    return m.is_boundary(m.vertex_halfedge(element)) ? m.is_boundary(cell) : true;
}

std::string rule(int t, int field, const std::string& row, const std::string& op) {
    const std::string at = "Row " + row + ", column ";
    if (t == kVertex)
        return at + "half-edge: after " + op + " a vertex stores one half-edge that leaves it (on the boundary, its boundary half-edge, so a walk meets the whole fan): re-read the edges at the vertex";
    if (t == kFace) return at + "half-edge: after " + op + " a face stores one of its own half-edges: re-read the face's sides";
    switch (field) {
    case 0: return at + "origin: " + row + " is one half of its edge (odd labels S -> E, even E -> S); after " + op + " its origin is that end of the edge: re-read the edge's S and E";
    case 1: return at + "face: the face on the left of " + row + " after " + op + " (none on the boundary): walk along it from its origin";
    case 2: return at + "next: after " + op + " next(" + row + ") starts where " + row + " ends and follows it around the same face (or the same boundary loop)";
    default: return at + "prev: after " + op + " prev(" + row + ") ends where " + row + " starts and comes before it around the same face (or boundary loop)";
    }
}

void require_shape(const HalfEdgeEditQuestion& q, const EditAnswer& answer) {
    for (int t = 0; t < 3; ++t) {
        const EditTableAnswer& a = answer.tables[t];
        const std::size_t rows = q.rows[t].size();
        if (a.cells.size() != rows * width(t) || a.removed.size() != rows)
            throw Error("invalid-answer", std::string("the ") + (t == kHalf ? "half-edge" : table_name(static_cast<MeshTable>(t))) +
                                              " table of the answer does not have the question's rows");
        for (const int32_t c : a.cells)
            if (c < kBlank) throw Error("invalid-answer", "a cell of the answer is below -2");
    }
}

} // namespace

HalfEdgeEditQuestion half_edge_edit_question(const WingedEdgeMesh& before, const Operation& op) {
    return question_of(views_of(before, op));
}

EditCheck check_half_edge_edit_answer(const WingedEdgeMesh& before, const Operation& op, const EditAnswer& answer) {
    const Views v = views_of(before, op);
    const HalfEdgeEditQuestion q = question_of(v);
    require_shape(q, answer);
    EditCheck out;
    // Half-edges first, then vertices, then faces: the order the page lists them.
    for (const int t : {kHalf, kVertex, kFace}) {
        for (std::size_t r = 0; r < q.rows[t].size(); ++r) {
            const int32_t row = q.rows[t][r];
            const std::string name = row_label(t, row);
            const bool gone = removed_after(v, t, row);
            const bool marked = answer.tables[t].removed[r] != 0;
            AnswerFinding f;
            f.table = static_cast<MeshTable>(t);
            f.row = row;
            f.index = static_cast<int32_t>(r);
            if (gone != marked) {
                f.field = "removed";
                f.code = gone ? "removed" : "kept";
                f.reason = gone ? "Row " + name + ": " + q.operation + " removes this element, so its row is marked removed"
                                : "Row " + name + ": " + q.operation + " keeps this element, so its row is not removed";
                out.findings.push_back(f);
                continue;
            }
            if (gone) continue;
            for (int k = 0; k < width(t); ++k) {
                const int32_t given = answer.tables[t].cells[r * width(t) + k];
                f.field = t == kHalf ? kHalfFields[k] : "halfedge";
                f.given = given;
                f.expected = t == kHalf ? half_row(v.after_view, row)[k] : single(v.after_view, t, row);
                const bool right = t == kHalf ? given == f.expected : fits_single(v, t, row, given);
                if (right) continue;
                f.code = given == kBlank ? "blank" : t == kHalf ? std::string("wrong-") + kHalfFields[k]
                                                    : t == kVertex ? "not-leaving" : "not-on-face";
                f.reason = given == kBlank ? "Row " + name + ", column " + f.field + ": it is blank; every cell of a row the operation rewrites is written (none where there is no face)"
                                           : rule(t, k, name, q.operation);
                out.findings.push_back(f);
            }
        }
    }
    return out;
}

EditAnswer worked_half_edge_edit_answer(const WingedEdgeMesh& before, const Operation& op) {
    const Views v = views_of(before, op);
    const HalfEdgeEditQuestion q = question_of(v);
    EditAnswer w;
    for (int t = 0; t < 3; ++t) {
        EditTableAnswer& a = w.tables[t];
        for (const int32_t row : q.rows[t]) {
            const bool gone = removed_after(v, t, row);
            a.removed.push_back(gone ? 1 : 0);
            if (t == kHalf) {
                const auto cells = half_row(v.after_view, row);
                for (const int32_t c : cells) a.cells.push_back(gone ? kBlank : c);
            } else {
                a.cells.push_back(gone ? kBlank : single(v.after_view, t, row));
            }
        }
    }
    return w;
}

} // namespace wingspline::mesh
