// The Euler operations on Baumgart's winged edge (lecture 000): split an edge,
// split a face, join two faces, flip an edge, collapse an edge, poke a face.
//
// Each operation is written once, as the lecture reads: every pointer of the slide's
// tables (the vertex table's edge, the edge table's S, E, L, R and four wings, the face
// table's edge) is set by one named assignment, in the order the algorithm makes it. The
// assignments go through a recorder, a template parameter: Recording writes each one into
// the ChangeRecord (steps, for step-by-step playback), NoRecorder compiles to the bare
// store, so the benchmarks run this same code with no strings and no allocations.
//
// A side of an edge is a half: (e, left) runs S -> E with face L, (e, right) E -> S with
// face R. Along a half's face, next() is the edge after it (L: end_left, R: start_right)
// and prev() the edge before it (L: start_left, R: end_right), exactly the wing rule of
// next_in_face(); a boundary side (face kNone) is walked as though the boundary were a
// face, as the slide defines the wings. Which side of the next edge belongs to the same
// face is read from its faces (an edge never has one face on both sides).
#include "unrecorded.h"

#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>

namespace wingspline::mesh {

struct Half {
    int32_t e = kNone;
    bool left = true;
};

// The sides of a face at its corners a and b (the split-face check finds them walking the
// face once, and the operation uses them: one walk, not two).
struct FaceSides {
    int32_t a = kNone, b = kNone;
    Half into_a, out_of_a, into_b, out_of_b;
};

// What the split-vertex check finds walking around v once, for the change: the edges to
// a and b, their sides leaving v, the edges strictly between them (counter-clockwise) that
// move to the new vertex, and the centre of the neighbours the new vertex takes.
struct VertexFan {
    int32_t v = kNone, a = kNone, b = kNone, ea = kNone, eb = kNone;
    Half out_a, out_b;
    std::vector<int32_t> moved;
    std::vector<int32_t> faces; // the faces (kNone: the boundary) between v-a and v-b, which get w for v
    glm::dvec3 centre{0.0};
};

namespace {

// Records nothing: every call is empty and inlined away (the benchmark path).
struct NoRecorder {
    bool moved = false; // a position was set (the geometry version moves on)
    void step(MeshTable, int32_t, const char*, int32_t, int32_t) {}
    void phase(const char*) {}
    void position(int32_t, const glm::dvec3&, const glm::dvec3&) { moved = true; }
    void began_first_corners() {}
    void added(Vertex) {}
    void added(Edge) {}
    void added(Face) {}
    void removed(Vertex) {}
    void removed(Edge) {}
    void removed(Face) {}
};

// Writes every assignment, position and element into a ChangeRecord.
struct Recording {
    ChangeRecord& c;
    void step(MeshTable t, int32_t row, const char* field, int32_t before, int32_t after) {
        c.steps.push_back({t, row, field, before, after, static_cast<int32_t>(c.phases.size()) - 1});
    }
    // The algorithm's next line (its comment in the source): the steps after it are its.
    void phase(const char* line) {
        if (c.phases.empty() || c.phases.back() != line) c.phases.emplace_back(line);
    }
    void position(int32_t v, const glm::dvec3& before, const glm::dvec3& after) {
        c.positions.push_back({v, before, after, c.steps.size()});
    }
    void began_first_corners() { c.began_first_corners = true; }
    void added(Vertex v) { c.added_vertices.push_back(v); }
    void added(Edge e) { c.added_edges.push_back(e); }
    void added(Face f) { c.added_faces.push_back(f); }
    void removed(Vertex v) { c.removed_vertices.push_back(v); }
    void removed(Edge e) { c.removed_edges.push_back(e); }
    void removed(Face f) { c.removed_faces.push_back(f); }
};

// Per row, each field's first before and last after; fields that came back to where they
// were are left out, and so are rows with nothing left.
void aggregate_rows(ChangeRecord& c) {
    for (const AssignmentStep& s : c.steps) {
        auto row = std::find_if(c.rows.begin(), c.rows.end(), [&](const RowChange& r) { return r.table == s.table && r.row == s.row; });
        if (row == c.rows.end()) {
            c.rows.push_back({s.table, s.row, {}});
            row = c.rows.end() - 1;
        }
        auto field = std::find_if(row->fields.begin(), row->fields.end(), [&](const FieldChange& f) { return f.field == s.field; });
        if (field == row->fields.end())
            row->fields.push_back({s.field, s.before, s.after});
        else
            field->after = s.after;
    }
    for (RowChange& r : c.rows)
        r.fields.erase(std::remove_if(r.fields.begin(), r.fields.end(), [](const FieldChange& f) { return f.before == f.after; }),
                       r.fields.end());
    c.rows.erase(std::remove_if(c.rows.begin(), c.rows.end(), [](const RowChange& r) { return r.fields.empty(); }), c.rows.end());
}

// Why a check refused, without any text (the fast path); explain() turns it into words.
struct Verdict {
    const char* code = nullptr; // nullptr = accepted
    int32_t x[4] = {kNone, kNone, kNone, kNone};
    bool ok() const { return code == nullptr; }
};
Verdict refuse(const char* code, int32_t a = kNone, int32_t b = kNone, int32_t c = kNone, int32_t d = kNone) {
    Verdict v;
    v.code = code;
    v.x[0] = a, v.x[1] = b, v.x[2] = c, v.x[3] = d;
    return v;
}

std::string number(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", t);
    return buf;
}

} // namespace

// The tables' private parts for the operations below (a friend of WingedEdgeMesh).
struct EulerAccess {
    // ------------------------------------------------------------ reading sides
    static int32_t face(const WingedEdgeMesh& m, Half h) { return h.left ? m.edges_[h.e].left : m.edges_[h.e].right; }
    static int32_t tail(const WingedEdgeMesh& m, Half h) { return h.left ? m.edges_[h.e].start : m.edges_[h.e].end; }
    static int32_t head(const WingedEdgeMesh& m, Half h) { return h.left ? m.edges_[h.e].end : m.edges_[h.e].start; }
    static Half side_of(const WingedEdgeMesh& m, int32_t e, int32_t f) { return {e, m.edges_[e].left == f}; }
    // (A kept branch rather than a select, as next_ccw: the next load need not wait.)
    static Half next(const WingedEdgeMesh& m, Half h) {
        const EdgeRecord& r = m.edges_[h.e];
        if (h.left) return side_of(m, r.end_left, r.left);
        WINGSPLINE_KEEP_BRANCH();
        return side_of(m, r.start_right, r.right);
    }
    static Half prev(const WingedEdgeMesh& m, Half h) {
        const EdgeRecord& r = m.edges_[h.e];
        if (h.left) return side_of(m, r.start_left, r.left);
        WINGSPLINE_KEEP_BRANCH();
        return side_of(m, r.end_right, r.right);
    }
    static Half twin(Half h) { return {h.e, !h.left}; }
    static int32_t face_size(const WingedEdgeMesh& m, int32_t f) {
        int32_t n = 0;
        const int32_t first = m.face_edge_[f];
        int32_t e = first;
        do {
            e = m.next_in_face(e, f);
            ++n;
        } while (e != first && n <= m.edge_count());
        return n;
    }
    // Corners of a side's face (or boundary loop), at most `limit` counted.
    static int32_t loop_size(const WingedEdgeMesh& m, Half h, int32_t limit) {
        Half x = h;
        int32_t n = 0;
        do {
            x = next(m, x);
            ++n;
        } while ((x.e != h.e || x.left != h.left) && n < limit);
        return n;
    }
    static int32_t valence(const WingedEdgeMesh& m, int32_t v) {
        int32_t n = 0;
        const int32_t first = m.vertex_edge_[v];
        int32_t e = first;
        do {
            e = m.next_ccw(e, v);
            ++n;
        } while (e != first && n <= m.edge_count());
        return n;
    }
    static bool on_boundary(const WingedEdgeMesh& m, int32_t v) {
        const int32_t first = m.vertex_edge_[v];
        int32_t e = first, n = 0;
        do {
            if (m.edges_[e].left == kNone || m.edges_[e].right == kNone) return true;
            e = m.next_ccw(e, v);
        } while (e != first && ++n <= m.edge_count());
        return false;
    }
    // The edge joining a and b, or kNone (a walk around a).
    static int32_t edge_between(const WingedEdgeMesh& m, int32_t a, int32_t b) {
        const int32_t first = m.vertex_edge_[a];
        if (first == kNone) return kNone;
        int32_t e = first, n = 0;
        do {
            const EdgeRecord& r = m.edges_[e];
            if (r.start == a) {
                if (r.end == b) return e;
                e = r.start_left;
            } else {
                WINGSPLINE_KEEP_BRANCH();
                if (r.start == b) return e;
                e = r.end_right;
            }
        } while (e != first && ++n <= m.edge_count());
        return kNone;
    }
    static bool face_has_corner(const WingedEdgeMesh& m, int32_t f, int32_t v) {
        const int32_t first = m.face_edge_[f];
        int32_t e = first, n = 0;
        do {
            if (m.edges_[e].start == v || m.edges_[e].end == v) return true;
            e = m.next_in_face(e, f);
        } while (e != first && ++n <= m.edge_count());
        return false;
    }
    // Every corner of p but a and b is a corner of q.
    static bool corners_within(const WingedEdgeMesh& m, int32_t p, int32_t q, int32_t a, int32_t b) {
        const int32_t first = m.face_edge_[p];
        int32_t x = first, n = 0;
        do {
            const EdgeRecord& r = m.edges_[x];
            const int32_t v = r.left == p ? r.start : r.end; // the corner this side leaves
            if (v != a && v != b && !face_has_corner(m, q, v)) return false;
            x = m.next_in_face(x, p);
        } while (x != first && ++n <= m.edge_count());
        return true;
    }
    template <class H> static const char* element(const WingedEdgeMesh& m, H h, int32_t count) {
        if (h.idx < 0 || h.idx >= count) return "invalid-element";
        return m.is_deleted(h) ? "deleted-element" : nullptr;
    }
    static constexpr int32_t kVertexKind = 0, kEdgeKind = 1, kFaceKind = 2; // Verdict x[1] of an element refusal

    // The mesh limits (limits.h): an edit makes nothing a mesh file could not hold, so the
    // page can always read its own export back. Corners of a side's face, counted up to one
    // past the limit (a walk of at most kMaxFaceCorners + 1 steps).
    static int32_t corners(const WingedEdgeMesh& m, Half h) { return loop_size(m, h, kMaxFaceCorners + 1); }
    // Whether `added` more elements would make more live ones than `limit`: the rows less the
    // gaps, which are counted only when the rows alone would pass it (O(1) below the limit).
    static bool over_limit(const std::vector<char>& gaps, int32_t rows, int32_t added, int32_t limit) {
        if (static_cast<int64_t>(rows) + added <= limit) return false;
        return rows - std::count(gaps.begin(), gaps.end(), char(1)) + static_cast<int64_t>(added) > limit;
    }
    // too-large, before the operation: x = {its element, 0 (vertices) or 1 (faces), how many then}.
    static Verdict counts_within(const WingedEdgeMesh& m, int32_t element, int32_t new_vertices, int32_t new_faces) {
        if (over_limit(m.vertex_deleted_, m.vertex_count(), new_vertices, kFileLimits.max_vertices))
            return refuse("too-large", element, 0, m.counts().vertices + new_vertices);
        if (over_limit(m.face_deleted_, m.face_count(), new_faces, kFileLimits.max_faces))
            return refuse("too-large", element, 1, m.counts().faces + new_faces);
        return {};
    }

    // ------------------------------------------------------------ the checks, without words
    static Verdict split_edge(const WingedEdgeMesh& m, Edge e, double t) {
        if (const char* c = element(m, e, m.edge_count())) return refuse(c, e.idx, kEdgeKind);
        if (!(t > 0.0 && t < 1.0)) return refuse("invalid-parameter", e.idx);
        // Both faces gain a corner.
        for (const Half h : {Half{e.idx, true}, Half{e.idx, false}})
            if (face(m, h) != kNone && corners(m, h) + 1 > kMaxFaceCorners) return refuse("face-too-large", e.idx, face(m, h), kNone, corners(m, h) + 1);
        return counts_within(m, e.idx, 1, 0);
    }
    static Verdict split_face(const WingedEdgeMesh& m, Face f, Vertex a, Vertex b, FaceSides* sides = nullptr) {
        if (const char* c = element(m, f, m.face_count())) return refuse(c, f.idx, kFaceKind);
        if (const char* c = element(m, a, m.vertex_count())) return refuse(c, a.idx, kVertexKind);
        if (const char* c = element(m, b, m.vertex_count())) return refuse(c, b.idx, kVertexKind);
        // One walk along f (the lecture's rule, next_in_face) finds the sides at a and b.
        // The side leaving a corner follows the one arriving there.
        FaceSides found;
        Half before;
        const int32_t first = m.face_edge_[f.idx];
        int32_t x = first, n = 0;
        do {
            const EdgeRecord& r = m.edges_[x];
            const bool left = r.left == f.idx;
            const int32_t tail = left ? r.start : r.end;
            if (tail == a.idx) found.out_of_a = {x, left}, found.into_a = before;
            if (tail == b.idx) found.out_of_b = {x, left}, found.into_b = before;
            before = {x, left};
            x = m.next_in_face(x, f.idx);
        } while (x != first && ++n <= m.edge_count());
        if (found.out_of_a.e == kNone) return refuse("not-a-corner", a.idx, f.idx);
        if (found.out_of_b.e == kNone) return refuse("not-a-corner", b.idx, f.idx);
        // A triangle's corners are all neighbours: whichever two are chosen, that is the reason.
        if (corners(m, side_of(m, first, f.idx)) == 3) return refuse("adjacent-corners", a.idx, b.idx, kNone, f.idx);
        if (a == b) return refuse("same-vertex", a.idx);
        if (found.into_a.e == kNone) found.into_a = before; // a starts the walk: the last side arrives there
        if (found.into_b.e == kNone) found.into_b = before;
        const int32_t existing = edge_between(m, a.idx, b.idx);
        if (existing != kNone) {
            const EdgeRecord& r = m.edges_[existing];
            return refuse(r.left == f.idx || r.right == f.idx ? "adjacent-corners" : "edge-exists", a.idx, b.idx, existing, f.idx);
        }
        if (const Verdict v = counts_within(m, f.idx, 0, 1); !v.ok()) return v;
        if (sides) {
            *sides = found;
            sides->a = a.idx, sides->b = b.idx;
        }
        return {};
    }
    static Verdict join_faces(const WingedEdgeMesh& m, Edge e) {
        if (const char* c = element(m, e, m.edge_count())) return refuse(c, e.idx, kEdgeKind);
        const EdgeRecord& r = m.edges_[e.idx];
        if (r.left == kNone || r.right == kNone) return refuse("boundary-edge", e.idx);
        if (r.left == r.right) return refuse("same-face", e.idx, r.left);
        // Every corner of R other than S and E must not be a corner of L: else the joined
        // face would pass that corner twice (and a second shared edge leaves a dangling edge).
        const int32_t first = m.face_edge_[r.right];
        int32_t x = first, n = 0;
        do {
            for (int32_t v : {m.edges_[x].start, m.edges_[x].end})
                if (v != r.start && v != r.end && face_has_corner(m, r.left, v)) return refuse("faces-touch-elsewhere", e.idx, v, r.left, r.right);
            x = m.next_in_face(x, r.right);
        } while (x != first && ++n <= m.edge_count());
        // The joined face must not lie on one other face along all its sides: the two would
        // be the same polygon twice (a pillow), which no face set can hold.
        int32_t across = -2;
        bool one_face = true;
        for (const int32_t f : {r.left, r.right}) {
            x = m.face_edge_[f], n = 0;
            const int32_t start = x;
            do {
                if (x != e.idx) {
                    const int32_t g = m.edges_[x].left == f ? m.edges_[x].right : m.edges_[x].left;
                    if (across == -2) across = g;
                    one_face = one_face && g == across && g != kNone;
                }
                x = m.next_in_face(x, f);
            } while (x != start && ++n <= m.edge_count());
        }
        if (one_face) return refuse("would-duplicate-face", e.idx, across, r.left, r.right);
        // The joined face has the corners of both but the two of e counted twice.
        const int32_t joined = corners(m, {e.idx, true}) + corners(m, {e.idx, false}) - 2;
        if (joined > kMaxFaceCorners) return refuse("face-too-large", e.idx, r.left, r.right, joined);
        return {};
    }
    static Verdict flip_edge(const WingedEdgeMesh& m, Edge e) {
        if (const char* c = element(m, e, m.edge_count())) return refuse(c, e.idx, kEdgeKind);
        const EdgeRecord& r = m.edges_[e.idx];
        if (r.left == kNone || r.right == kNone) return refuse("boundary-edge", e.idx);
        if (face_size(m, r.left) != 3) return refuse("not-triangles", e.idx, r.left);
        if (face_size(m, r.right) != 3) return refuse("not-triangles", e.idx, r.right);
        const int32_t c = head(m, next(m, {e.idx, true})), d = head(m, next(m, {e.idx, false}));
        const int32_t existing = edge_between(m, c, d);
        if (c == d || existing != kNone) return refuse("edge-exists", e.idx, d, c, existing);
        return {};
    }
    static Verdict collapse_edge(const WingedEdgeMesh& m, Edge e, double t) {
        if (const char* c = element(m, e, m.edge_count())) return refuse(c, e.idx, kEdgeKind);
        if (!(t >= 0.0 && t <= 1.0)) return refuse("invalid-parameter", e.idx);
        const EdgeRecord& r = m.edges_[e.idx];
        const bool interior = r.left != kNone && r.right != kNone;
        if (interior && on_boundary(m, r.start) && on_boundary(m, r.end)) return refuse("would-pinch", e.idx, r.start, r.end);
        int32_t opposite[2] = {kNone, kNone};
        for (int s = 0; s < 2; ++s) {
            const Half h{e.idx, s == 0};
            const int32_t n = loop_size(m, h, 4);
            if (face(m, h) == kNone) {
                if (n <= 3) return refuse("hole-too-small", e.idx);
                continue;
            }
            if (n > 3) continue;
            // The triangle (S, E, c) goes and its two edges at c become one, between the faces
            // beyond them: A across c-S, B across E-c. c keeps one edge fewer. With three, all
            // inside, it keeps two, both between A and B: polygons may (join-faces makes such a
            // vertex), two triangles would be one triangle twice. (With two, what lies beyond
            // them is a face holding both S and E, refused by the link condition below, or
            // the boundary, where S and E are both boundary vertices: refused above.)
            const Half into_c = next(m, h), out_of_c = next(m, into_c);
            const int32_t c = head(m, into_c);
            opposite[s] = c;
            const Half to_a = twin(out_of_c), to_b = twin(into_c);
            if (valence(m, c) == 3 && !on_boundary(m, c) && loop_size(m, to_a, 4) == 3 && loop_size(m, to_b, 4) == 3)
                return refuse("degenerate-vertex", e.idx, c, face(m, to_a), face(m, to_b));
        }
        // The link condition: the vertices joined to both S and E are exactly the opposite
        // corners of the triangles on e.
        const int32_t first = m.vertex_edge_[r.start];
        int32_t x = first, n = 0;
        do {
            const int32_t v = m.other_vertex(x, r.start);
            if (v != r.end && v != opposite[0] && v != opposite[1] && edge_between(m, r.end, v) != kNone)
                return refuse("link-condition", e.idx, v, r.start, r.end);
            x = m.next_ccw(x, r.start);
        } while (x != first && ++n <= m.edge_count());
        // No other face may hold both S and E (it would pass the merged vertex twice).
        x = m.vertex_edge_[r.end], n = 0;
        const int32_t first_e = x;
        do {
            const int32_t f = m.edges_[x].start == r.end ? m.edges_[x].left : m.edges_[x].right;
            if (f != kNone && f != r.left && f != r.right && face_has_corner(m, f, r.start))
                return refuse("link-condition-face", e.idx, f, r.start, r.end);
            x = m.next_ccw(x, r.end);
        } while (x != first_e && ++n <= m.edge_count());
        // No two faces may become the same polygon (validate_indexed's duplicate-face): with
        // E renamed S, a face at E must not have the corners of another face at S. A face
        // that goes with its triangle takes no part; L and R keep all their corners but E.
        const auto goes = [&](int32_t f) { return f == kNone || (f == r.left && opposite[0] != kNone) || (f == r.right && opposite[1] != kNone); };
        const auto corners_after = [&](int32_t f) { return face_size(m, f) - (f == r.left || f == r.right ? 1 : 0); };
        for (int32_t p_edge = first_e, i = 0;;) {
            const int32_t p = m.edges_[p_edge].start == r.end ? m.edges_[p_edge].left : m.edges_[p_edge].right;
            if (!goes(p)) {
                const int32_t size = corners_after(p);
                for (int32_t q_edge = first, j = 0;;) {
                    const int32_t q = m.edges_[q_edge].start == r.start ? m.edges_[q_edge].left : m.edges_[q_edge].right;
                    if (q != p && !goes(q) && corners_after(q) == size && corners_within(m, p, q, r.start, r.end))
                        return refuse("would-duplicate-face", e.idx, p, q);
                    q_edge = m.next_ccw(q_edge, r.start);
                    if (q_edge == first || ++j > m.edge_count()) break;
                }
            }
            p_edge = m.next_ccw(p_edge, r.end);
            if (p_edge == first_e || ++i > m.edge_count()) break;
        }
        return {};
    }
    // The side of e that leaves v (e touches v).
    static Half leaving(const WingedEdgeMesh& m, int32_t e, int32_t v) { return {e, m.edges_[e].start == v}; }
    static Verdict split_vertex(const WingedEdgeMesh& m, Vertex v, Vertex a, Vertex b, double t, VertexFan* fan) {
        if (const char* c = element(m, v, m.vertex_count())) return refuse(c, v.idx, kVertexKind);
        if (const char* c = element(m, a, m.vertex_count())) return refuse(c, a.idx, kVertexKind);
        if (const char* c = element(m, b, m.vertex_count())) return refuse(c, b.idx, kVertexKind);
        if (!(t > 0.0 && t < 1.0)) return refuse("invalid-parameter", v.idx);
        if (a == b) return refuse("same-vertex", v.idx, a.idx);
        // One walk around v (the lecture's rule, next_ccw) finds v-a and v-b.
        int32_t ea = kNone, eb = kNone;
        const int32_t first = m.vertex_edge_[v.idx];
        if (first != kNone) {
            int32_t x = first, n = 0;
            do {
                const int32_t other = m.other_vertex(x, v.idx);
                if (other == a.idx) ea = x;
                if (other == b.idx) eb = x;
                x = m.next_ccw(x, v.idx);
            } while (x != first && ++n <= m.edge_count());
        }
        if (ea == kNone) return refuse("not-a-neighbour", v.idx, a.idx);
        if (eb == kNone) return refuse("not-a-neighbour", v.idx, b.idx);
        if (const Verdict c = counts_within(m, v.idx, 1, 2); !c.ok()) return c;
        if (fan) {
            fan->v = v.idx, fan->a = a.idx, fan->b = b.idx, fan->ea = ea, fan->eb = eb;
            fan->out_a = leaving(m, ea, v.idx), fan->out_b = leaving(m, eb, v.idx);
            fan->moved.clear();
            fan->faces.assign(1, face(m, fan->out_a));
            glm::dvec3 sum = m.position(a.idx) + m.position(b.idx);
            for (int32_t x = m.next_ccw(ea, v.idx); x != eb; x = m.next_ccw(x, v.idx)) {
                fan->moved.push_back(x);
                fan->faces.push_back(face(m, leaving(m, x, v.idx)));
                sum += m.position(m.other_vertex(x, v.idx));
            }
            fan->centre = sum / static_cast<double>(fan->moved.size() + 2);
        }
        return {};
    }
    // "v1, v4, v7": v's neighbours counter-clockwise, for a refusal.
    static std::string neighbour_list(const WingedEdgeMesh& m, int32_t v) {
        std::string out;
        for (const int32_t u : m.vertices_around_vertex(v)) out += (out.empty() ? "" : ", ") + vertex_label(u);
        return out.empty() ? "it has none" : out;
    }
    static Verdict set_vertex_edge(const WingedEdgeMesh& m, Vertex v, Edge e) {
        if (const char* c = element(m, v, m.vertex_count())) return refuse(c, v.idx, kVertexKind);
        if (const char* c = element(m, e, m.edge_count())) return refuse(c, e.idx, kEdgeKind);
        const EdgeRecord& r = m.edges_[e.idx];
        if (r.start == v.idx || r.end == v.idx) return {};
        return refuse("edge-not-incident", e.idx, v.idx);
    }
    static Verdict set_face_edge(const WingedEdgeMesh& m, Face f, Edge e) {
        if (const char* c = element(m, f, m.face_count())) return refuse(c, f.idx, kFaceKind);
        if (const char* c = element(m, e, m.edge_count())) return refuse(c, e.idx, kEdgeKind);
        const EdgeRecord& r = m.edges_[e.idx];
        if (r.left == f.idx || r.right == f.idx) return {};
        return refuse("edge-not-on-face", e.idx, f.idx);
    }
    static std::string edge_list(const std::vector<int32_t>& edges) {
        std::string out;
        for (const int32_t e : edges) out += (out.empty() ? "" : ", ") + edge_label(e);
        return out;
    }
    static Verdict poke_face(const WingedEdgeMesh& m, Face f) {
        if (const char* c = element(m, f, m.face_count())) return refuse(c, f.idx, kFaceKind);
        // A new vertex, and an n-gon becomes n triangles (n - 1 new faces).
        return counts_within(m, f.idx, 1, corners(m, side_of(m, m.face_edge_[f.idx], f.idx)) - 1);
    }

    // ------------------------------------------------------------ the checks in words
    static CheckResult words(const WingedEdgeMesh& m, const char* op, const Verdict& v, double t = 0.0) {
        if (v.ok()) return CheckResult::accept();
        const std::string code = v.code;
        if (code == "invalid-element" || code == "deleted-element")
            return v.x[1] == kVertexKind ? m.check_element(Vertex(v.x[0]))
                   : v.x[1] == kEdgeKind ? m.check_element(Edge(v.x[0]))
                                         : m.check_element(Face(v.x[0]));
        const auto V = [](int32_t i) { return vertex_label(i); };
        const auto E = [](int32_t i) { return edge_label(i); };
        const auto F = [](int32_t i) { return face_label(i); };
        const int32_t* x = v.x;
        std::string msg;
        const std::string opname = op;
        if (code == "invalid-parameter")
            msg = opname == "split" ? "t = " + number(t) + " is not strictly between 0 and 1: the new vertex must lie inside " + E(x[0])
                                    : "t = " + number(t) + " is not between 0 and 1: the merged vertex must lie on " + E(x[0]);
        else if (code == "same-vertex")
            msg = "a new edge needs two different corners, but both are " + V(x[0]);
        else if (code == "not-a-corner")
            msg = V(x[0]) + " is not a corner of " + F(x[1]);
        else if (code == "adjacent-corners")
            // A triangle has no two corners that are not neighbours: say that, not "choose others".
            msg = x[2] == kNone
                      ? F(x[3]) + " is a triangle: every two of its corners are joined by a side, so no new edge can split it;"
                                  " split a face with four or more corners"
                      : V(x[0]) + " and " + V(x[1]) + " are already joined by " + E(x[2]) + ", a side of " + F(x[3]) +
                            ": choose two corners that are not neighbours";
        else if (code == "edge-exists" && opname == "flip")
            msg = "flipping " + E(x[0]) + " would create an edge " + V(x[1]) + "-" + V(x[2]) + " that already exists (" + E(x[3]) + ")";
        else if (code == "edge-exists")
            msg = "splitting " + F(x[3]) + " would create an edge " + V(x[0]) + "-" + V(x[1]) + " that already exists (" + E(x[2]) + ")";
        else if (code == "boundary-edge")
            msg = E(x[0]) + " is on the boundary: it has only one face, so there is nothing on the other side to " +
                  (opname == "flip" ? "turn it into" : "join with");
        else if (code == "same-face")
            msg = E(x[0]) + " has " + F(x[1]) + " on both sides";
        else if (code == "faces-touch-elsewhere")
            msg = F(x[2]) + " and " + F(x[3]) + " also meet at " + V(x[1]) + ": joining them across " + E(x[0]) +
                  " would make a face that passes " + V(x[1]) + " twice";
        else if (code == "would-duplicate-face" && opname == "collapse")
            msg = "collapsing " + E(x[0]) + " would give " + F(x[1]) + " the corners of " + F(x[2]) + ": the same polygon twice";
        else if (code == "would-duplicate-face")
            msg = "joining " + F(x[2]) + " and " + F(x[3]) + " across " + E(x[0]) + " would give a face with the same sides as " + F(x[1]) +
                  ": the same polygon twice";
        else if (code == "face-too-large" && opname == "join")
            msg = "joining " + F(x[1]) + " and " + F(x[2]) + " would make a face of " + std::to_string(x[3]) +
                  " corners; a face may have at most " + std::to_string(kMaxFaceCorners);
        else if (code == "face-too-large")
            msg = "splitting " + E(x[0]) + " would give " + F(x[1]) + " " + std::to_string(x[3]) + " corners; a face may have at most " +
                  std::to_string(kMaxFaceCorners);
        else if (code == "too-large")
            msg = (opname == "poke" ? "poking " + F(x[0]) : opname == "split-face" ? "splitting " + F(x[0]) : "splitting " + E(x[0])) +
                  " would make " + std::to_string(x[2]) + (x[1] == 0 ? " vertices" : " faces") + "; a mesh may have at most " +
                  std::to_string(x[1] == 0 ? kFileLimits.max_vertices : kFileLimits.max_faces) + ", as many as a mesh file may hold";
        else if (code == "not-triangles")
            msg = "only an edge between two triangles can be flipped, but " + F(x[1]) + " beside " + E(x[0]) + " is not a triangle";
        else if (code == "would-pinch")
            msg = V(x[1]) + " and " + V(x[2]) + " are both on the boundary but " + E(x[0]) +
                  " is not: collapsing it would pinch the surface at one vertex";
        else if (code == "hole-too-small")
            msg = "the boundary hole beside " + E(x[0]) + " has only three corners: collapsing " + E(x[0]) + " would close it into two edges with no face between";
        else if (code == "degenerate-vertex")
            msg = "collapsing " + E(x[0]) + " would leave " + V(x[1]) + " with two edges, both between the triangles " + F(x[2]) + " and " +
                  F(x[3]) + ": the same triangle twice";
        else if (code == "link-condition")
            msg = V(x[1]) + " is joined to both " + V(x[2]) + " and " + V(x[3]) + " but not across a triangle on " + E(x[0]) +
                  ": collapsing " + E(x[0]) + " would make two edges between the same vertices (the link condition)";
        else if (code == "edge-not-incident" && m.vertex_edge_[x[1]] == kNone)
            msg = V(x[1]) + " belongs to no face, so it has no edge to store (" + E(x[0]) + " does not touch it)";
        else if (code == "edge-not-incident")
            msg = E(x[0]) + " does not touch " + V(x[1]) + ": the vertex table stores one of " + V(x[1]) + "'s own edges (" +
                  edge_list(m.edges_around_vertex(x[1])) + ")";
        else if (code == "edge-not-on-face")
            msg = E(x[0]) + " is not a side of " + F(x[1]) + ": the face table stores one of " + F(x[1]) + "'s own edges (" +
                  edge_list(m.edges_of_face(x[1])) + ")";
        else if (code == "link-condition-face")
            msg = F(x[1]) + " has both " + V(x[2]) + " and " + V(x[3]) + " as corners: collapsing " + E(x[0]) +
                  " would make it pass the merged vertex twice (the link condition)";
        else
            msg = code;
        return CheckResult::refuse(code, msg);
    }
};

namespace {
using A = EulerAccess;

// Every assignment of one operation, through its recorder.
template <class Recorder> struct Editor {
    WingedEdgeMesh& m;
    std::vector<EdgeRecord>& edges;
    std::vector<int32_t>& vertex_edge;
    std::vector<int32_t>& face_edge;
    Recorder& rec;

    void set(int32_t e, int32_t EdgeRecord::*field, const char* name, int32_t value) {
        int32_t& slot = edges[e].*field;
        if (slot == value) return;
        rec.step(MeshTable::Edge, e, name, slot, value);
        slot = value;
    }
    void start(int32_t e, int32_t v) { set(e, &EdgeRecord::start, "start", v); }
    void end(int32_t e, int32_t v) { set(e, &EdgeRecord::end, "end", v); }
    void left(int32_t e, int32_t f) { set(e, &EdgeRecord::left, "left", f); }
    void right(int32_t e, int32_t f) { set(e, &EdgeRecord::right, "right", f); }
    void start_left(int32_t e, int32_t w) { set(e, &EdgeRecord::start_left, "startLeft", w); }
    void start_right(int32_t e, int32_t w) { set(e, &EdgeRecord::start_right, "startRight", w); }
    void end_left(int32_t e, int32_t w) { set(e, &EdgeRecord::end_left, "endLeft", w); }
    void end_right(int32_t e, int32_t w) { set(e, &EdgeRecord::end_right, "endRight", w); }
    // Along h's face: the edge after h (L: end_left, R: start_right) and before it
    // (L: start_left, R: end_right); h's face (L or R).
    void set_next(Half h, int32_t w) { h.left ? end_left(h.e, w) : start_right(h.e, w); }
    void set_prev(Half h, int32_t w) { h.left ? start_left(h.e, w) : end_right(h.e, w); }
    void set_face(Half h, int32_t f) { h.left ? left(h.e, f) : right(h.e, f); }
    void set_vertex_edge(int32_t v, int32_t e) {
        if (vertex_edge[v] == e) return;
        rec.step(MeshTable::Vertex, v, "edge", vertex_edge[v], e);
        vertex_edge[v] = e;
    }
    void set_face_edge(int32_t f, int32_t e) {
        if (face_edge[f] == e) return;
        rec.step(MeshTable::Face, f, "edge", face_edge[f], e);
        face_edge[f] = e;
    }
};
} // namespace

// Undo is rare and not hot: kept out of line, so the page's module carries one copy.
#if defined(__GNUC__) || defined(__clang__)
#define WINGSPLINE_NOINLINE __attribute__((noinline))
#else
#define WINGSPLINE_NOINLINE
#endif

// The row bookkeeping shared by the operations (new rows at the end, gaps marked), as
// member functions of the friend so they can reach the private tables.
struct EulerRows {
    template <class R> static int32_t new_vertex(WingedEdgeMesh& m, const glm::dvec3& p, R& rec) {
        const int32_t v = m.vertex_count();
        m.positions_.push_back(p.x);
        m.positions_.push_back(p.y);
        m.positions_.push_back(p.z);
        m.vertex_edge_.push_back(kNone);
        if (!m.vertex_deleted_.empty()) m.vertex_deleted_.push_back(0);
        rec.added(Vertex(v));
        rec.position(v, p, p);
        return v;
    }
    template <class R> static int32_t new_edge(WingedEdgeMesh& m, R& rec) {
        const int32_t e = m.edge_count();
        m.edges_.emplace_back();
        if (!m.edge_deleted_.empty()) m.edge_deleted_.push_back(0);
        rec.added(Edge(e));
        return e;
    }
    template <class R> static int32_t new_face(WingedEdgeMesh& m, R& rec) {
        const int32_t f = m.face_count();
        m.face_edge_.push_back(kNone);
        if (!m.face_first_corner_.empty()) m.face_first_corner_.push_back(kNone);
        if (!m.face_deleted_.empty()) m.face_deleted_.push_back(0);
        rec.added(Face(f));
        return f;
    }
    static void mark(std::vector<char>& marks, int32_t& marked, std::size_t count, int32_t i) {
        if (marks.empty()) marks.assign(count, 0);
        marks[i] = 1;
        ++marked;
    }
    template <class R> static void remove(WingedEdgeMesh& m, Vertex v, R& rec) {
        mark(m.vertex_deleted_, m.deleted_count_[0], m.vertex_edge_.size(), v.idx);
        rec.removed(v);
    }
    template <class R> static void remove(WingedEdgeMesh& m, Edge e, R& rec) {
        mark(m.edge_deleted_, m.deleted_count_[1], m.edges_.size(), e.idx);
        rec.removed(e);
    }
    template <class R> static void remove(WingedEdgeMesh& m, Face f, R& rec) {
        mark(m.face_deleted_, m.deleted_count_[2], m.face_edge_.size(), f.idx);
        rec.removed(f);
    }
    // ------------------------------------------------------------ undo
    // The cell a change record's field names (nullptr: none), for undo.
    WINGSPLINE_NOINLINE static int32_t* cell(WingedEdgeMesh& m, MeshTable t, int32_t row, const std::string& field) {
        if (t == MeshTable::Vertex) return field == "edge" && row < m.vertex_count() ? &m.vertex_edge_[row] : nullptr;
        if (t == MeshTable::Face) {
            if (row >= m.face_count()) return nullptr;
            if (field == "edge") return &m.face_edge_[row];
            return field == "firstCorner" && !m.face_first_corner_.empty() ? &m.face_first_corner_[row] : nullptr;
        }
        if (row >= m.edge_count()) return nullptr;
        EdgeRecord& r = m.edges_[row];
        int32_t* const cells[] = {&r.start, &r.end, &r.left, &r.right, &r.start_left, &r.start_right, &r.end_left, &r.end_right};
        const int k = change_field_index(field) - 1; // change_fields(): "edge", then the edge table's eight
        return k >= 0 && k < 8 ? cells[k] : nullptr;
    }
    // How many rows a table had before the change: its new rows, the last ones, go. kNone
    // when the elements it added are not the table's last rows.
    // (An operation adds each element once, so k of them in the last k rows are those rows.)
    template <class H> static int32_t rows_before(const std::vector<H>& added, int32_t count) {
        const int32_t before = count - static_cast<int32_t>(added.size());
        for (const H& h : added)
            if (h.idx < before || h.idx >= count) return kNone;
        return before;
    }
    template <class H> static bool all_marked(const std::vector<char>& marks, const std::vector<H>& removed, int32_t before) {
        return std::all_of(removed.begin(), removed.end(), [&](H h) { return h.idx < before && !marks.empty() && marks[h.idx]; });
    }
    template <class H> static void unmark(std::vector<char>& marks, int32_t& marked, const std::vector<H>& removed) {
        for (const H& h : removed) marks[h.idx] = 0;
        marked -= static_cast<int32_t>(removed.size());
        if (marked == 0) marks.clear(); // no gap left: no marks, as before the first removal
    }
    // Why `c` cannot be taken back (empty: it can).
    WINGSPLINE_NOINLINE static std::string undo_refusal(const WingedEdgeMesh& m, const ChangeRecord& c) {
        if (!c.changed()) return "it changed nothing";
        if (c.after.topology != m.version_.topology) return "another change came after it";
        const int32_t n[3] = {rows_before(c.added_vertices, m.vertex_count()), rows_before(c.added_edges, m.edge_count()),
                              rows_before(c.added_faces, m.face_count())};
        if (n[0] == kNone || n[1] == kNone || n[2] == kNone) return "its new elements are not the last rows";
        if (!all_marked(m.vertex_deleted_, c.removed_vertices, n[0]) || !all_marked(m.edge_deleted_, c.removed_edges, n[1]) ||
            !all_marked(m.face_deleted_, c.removed_faces, n[2]))
            return "an element it removed is not a gap";
        WingedEdgeMesh& w = const_cast<WingedEdgeMesh&>(m); // cell() only reads here
        for (const RowChange& r : c.rows)
            for (const FieldChange& f : r.fields) {
                const int32_t* x = cell(w, r.table, r.row, f.field);
                if (x == nullptr ? r.row < n[static_cast<int>(r.table)] : *x != f.after) return element_label(r.table, r.row) + "'s " + f.field + " changed after it";
            }
        for (const PositionChange& p : c.positions)
            if (p.vertex < n[0] && m.position(p.vertex) != last_position(c, p.vertex)) return element_label(MeshTable::Vertex, p.vertex) + " moved after it";
        return {};
    }
    static CheckResult check_undo(const WingedEdgeMesh& m, const ChangeRecord& c) {
        const std::string why = undo_refusal(m, c);
        if (why.empty()) return CheckResult::accept();
        return CheckResult::refuse("cannot-undo", "cannot take back " + c.op + ": " + why + " (only the mesh's newest change can be taken back)");
    }
    // Where the change left v (its last position change), and where v was before it (its first).
    static glm::dvec3 last_position(const ChangeRecord& c, int32_t v) {
        glm::dvec3 p{0.0};
        for (const PositionChange& x : c.positions)
            if (x.vertex == v) p = x.after;
        return p;
    }
    static ChangeRecord undo(WingedEdgeMesh& m, const ChangeRecord& c) {
        require_ok(check_undo(m, c));
        ChangeRecord u;
        u.op = "undo";
        u.before = m.version_;
        const int32_t V = rows_before(c.added_vertices, m.vertex_count()), E = rows_before(c.added_edges, m.edge_count()),
                      F = rows_before(c.added_faces, m.face_count());
        const int32_t n[3] = {V, E, F};
        for (const RowChange& r : c.rows) {
            RowChange back{r.table, r.row, {}};
            for (const FieldChange& f : r.fields) {
                int32_t* x = cell(m, r.table, r.row, f.field);
                if (x == nullptr || r.row >= n[static_cast<int>(r.table)]) continue;
                *x = f.before;
                back.fields.push_back({f.field, f.after, f.before});
            }
            if (!back.fields.empty()) u.rows.push_back(std::move(back));
        }
        // The vertices it moved, each to where it was before its first move.
        for (const PositionChange& p : c.positions) {
            if (p.vertex >= V || std::any_of(u.positions.begin(), u.positions.end(), [&](const PositionChange& q) { return q.vertex == p.vertex; })) continue;
            const glm::dvec3 now = m.position(p.vertex);
            if (now == p.before) continue;
            m.positions_[3 * p.vertex] = p.before.x, m.positions_[3 * p.vertex + 1] = p.before.y, m.positions_[3 * p.vertex + 2] = p.before.z;
            u.positions.push_back({p.vertex, now, p.before, 0});
        }
        if (!c.removed_vertices.empty()) unmark(m.vertex_deleted_, m.deleted_count_[0], c.removed_vertices);
        if (!c.removed_edges.empty()) unmark(m.edge_deleted_, m.deleted_count_[1], c.removed_edges);
        if (!c.removed_faces.empty()) unmark(m.face_deleted_, m.deleted_count_[2], c.removed_faces);
        if (c.began_first_corners) m.face_first_corner_.clear(); // every face listed from its walk's start again
        // The tables end where they ended before (erase from the end: nothing moves).
        const auto cut = [](auto& v, std::size_t n) { if (n < v.size()) v.erase(v.begin() + static_cast<std::ptrdiff_t>(n), v.end()); };
        cut(m.positions_, 3 * static_cast<std::size_t>(V));
        cut(m.vertex_edge_, V), cut(m.edges_, E), cut(m.face_edge_, F), cut(m.face_first_corner_, F);
        cut(m.vertex_deleted_, V), cut(m.edge_deleted_, E), cut(m.face_deleted_, F);
        u.added_vertices = c.removed_vertices, u.added_edges = c.removed_edges, u.added_faces = c.removed_faces;
        u.removed_vertices = c.added_vertices, u.removed_edges = c.added_edges, u.removed_faces = c.added_faces;
        // The state before the change, by its own version; the geometry by a new number when
        // a position moved since the change (the positions are not that state's exactly).
        m.version_.topology = c.before.topology;
        m.version_.geometry = m.version_.geometry == c.after.geometry ? c.before.geometry : ++m.used_.geometry;
        u.after = m.version_;
        return u;
    }
    // face_set() lists a face from its first corner once face edges were chosen; a face
    // that lost that corner (or is new) is listed from where its walk starts.
    template <class R> static void keep_first_corner(WingedEdgeMesh& m, int32_t f, R& rec) {
        if (m.face_first_corner_.empty() || f == kNone) return;
        int32_t& slot = m.face_first_corner_[f];
        if (slot != kNone && A::face_has_corner(m, f, slot)) return;
        const int32_t corner = m.walk_start_corner(f);
        rec.step(MeshTable::Face, f, "firstCorner", slot, corner);
        slot = corner;
    }
    // Every assignment of one operation goes through this editor and its recorder.
    template <class R> static Editor<R> editor(WingedEdgeMesh& m, R& rec) { return Editor<R>{m, m.edges_, m.vertex_edge_, m.face_edge_, rec}; }
    // Runs an accepted operation's change through a recorder and moves the versions on
    // (topology when anything changed, geometry when a position was set).
    template <class Change> static ChangeRecord run_recorded(WingedEdgeMesh& m, const char* name, Change change_of) {
        ChangeRecord c;
        c.op = name;
        c.before = m.version_;
        Recording rec{c};
        change_of(rec);
        const bool changed = !c.steps.empty() || !c.positions.empty() || !c.added_vertices.empty() || !c.added_edges.empty() ||
                             !c.added_faces.empty() || !c.removed_vertices.empty() || !c.removed_edges.empty() || !c.removed_faces.empty();
        if (changed) m.version_.topology = ++m.used_.topology;
        if (!c.positions.empty()) m.version_.geometry = ++m.used_.geometry;
        c.after = m.version_;
        aggregate_rows(c);
        return c;
    }
    template <class Change> static void run_unrecorded(WingedEdgeMesh& m, Change change_of) {
        NoRecorder rec;
        change_of(rec);
        m.version_.topology = ++m.used_.topology;
        if (rec.moved) m.version_.geometry = ++m.used_.geometry;
    }
    template <class R> static void set_position(WingedEdgeMesh& m, int32_t v, const glm::dvec3& p, R& rec) {
        const glm::dvec3 before = m.position(v);
        if (before == p) return;
        m.positions_[3 * v] = p.x, m.positions_[3 * v + 1] = p.y, m.positions_[3 * v + 2] = p.z;
        rec.position(v, before, p);
    }
};

namespace {
using Rows = EulerRows;
} // namespace
// The changes, each written as the lecture reads (a friend of WingedEdgeMesh).
struct EulerChanges {
// ------------------------------------------------------------------ split edge
// e = S -> E with faces L, R. A new vertex m on e; e now ends at m; a new edge n runs
// m -> E with the same faces. Only the wings at E change hands: the edge after e in L and
// the edge before e in R now meet n instead.
template <class R> static void change_split_edge(WingedEdgeMesh& mesh, Edge e_, double t, R& rec) {
    auto w = Rows::editor(mesh, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half after_in_L = A::next(mesh, a);  // leaves E along L
    const Half before_in_R = A::prev(mesh, b); // arrives at E along R
    const int32_t S = mesh.edges_[e].start, E = mesh.edges_[e].end, L = mesh.edges_[e].left, Rf = mesh.edges_[e].right;
    rec.phase("a new vertex m at (1 - t) S + t E and a new edge n; m stores n");
    const int32_t m = Rows::new_vertex(mesh, (1.0 - t) * mesh.position(S) + t * mesh.position(E), rec);
    const int32_t n = Rows::new_edge(mesh, rec);
    w.set_vertex_edge(m, n);
    rec.phase("the new edge's row: m -> E, the faces L and R of e, its four wings");
    w.start(n, m);
    w.end(n, E);
    w.left(n, L);
    w.right(n, Rf);
    w.start_left(n, e);
    w.start_right(n, e);
    w.end_left(n, after_in_L.e);
    w.end_right(n, before_in_R.e);
    rec.phase("e now ends at m, and its wings at its end are n on both sides");
    w.end(e, m);
    w.end_left(e, n);
    w.end_right(e, n);
    rec.phase("the neighbours at E that pointed at e now point at n (and E's stored edge)");
    w.set_prev(after_in_L, n);
    w.set_next(before_in_R, n);
    if (mesh.vertex_edge_[E] == e) w.set_vertex_edge(E, n);
}

// ------------------------------------------------------------------ split face
// A new edge n = a -> b inside f. Its left side closes f's corners b ... a, its right side
// the new face g's corners a ... b.
template <class R> static void change_split_face(WingedEdgeMesh& m, Face f_, const FaceSides& sides, R& rec) {
    auto w = Rows::editor(m, rec);
    const int32_t f = f_.idx, a = sides.a, b = sides.b;
    // the sides of f at a and b, as the check found them
    const Half into_a = sides.into_a, out_of_a = sides.out_of_a, into_b = sides.into_b, out_of_b = sides.out_of_b;
    rec.phase("a new edge n = a -> b with f on its left and a new face g on its right; its wings");
    const int32_t n = Rows::new_edge(m, rec);
    const int32_t g = Rows::new_face(m, rec);
    w.start(n, a);
    w.end(n, b);
    w.left(n, f);
    w.right(n, g);
    w.start_left(n, into_a.e);
    w.end_left(n, out_of_b.e);
    w.start_right(n, out_of_a.e);
    w.end_right(n, into_b.e);
    rec.phase("the sides of f at a and b now meet n in their wings");
    w.set_next(into_a, n);
    w.set_prev(out_of_b, n);
    w.set_prev(out_of_a, n);
    w.set_next(into_b, n);
    rec.phase("the sides from a round to b now belong to g; g (and f, if its edge moved) store n");
    bool face_edge_moved = false;
    for (Half h = out_of_a;;) {
        const bool last = h.e == into_b.e && h.left == into_b.left;
        const Half following = last ? h : A::next(m, h);
        w.set_face(h, g);
        face_edge_moved |= m.face_edge_[f] == h.e;
        if (last) break;
        h = following;
    }
    w.set_face_edge(g, n);
    if (face_edge_moved) w.set_face_edge(f, n);
    Rows::keep_first_corner(m, f, rec);
    Rows::keep_first_corner(m, g, rec);
}

// ------------------------------------------------------------------ join faces
// Removes e = S -> E; the higher-numbered of its faces is merged into the lower one. The
// edges before and after e on each side now meet each other.
template <class R> static void change_join_faces(WingedEdgeMesh& m, Edge e_, R& rec) {
    auto w = Rows::editor(m, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half pa = A::prev(m, a), na = A::next(m, a), pb = A::prev(m, b), nb = A::next(m, b);
    const int32_t S = m.edges_[e].start, E = m.edges_[e].end, L = m.edges_[e].left, Rf = m.edges_[e].right;
    const int32_t keep = std::min(L, Rf), gone = std::max(L, Rf);
    rec.phase("every side of the face that goes now belongs to the one kept");
    const Half along_gone = gone == L ? a : b;
    for (Half x = A::next(m, along_gone); x.e != e;) {
        const Half following = A::next(m, x);
        w.set_face(x, keep);
        x = following;
    }
    rec.phase("close the gap e leaves: on each side the edge before e meets the edge after it");
    w.set_next(pa, nb.e);
    w.set_prev(nb, pa.e);
    w.set_next(pb, na.e);
    w.set_prev(na, pb.e);
    rec.phase("S, E and the face kept stop storing e; e and the face that went are removed");
    if (m.vertex_edge_[S] == e) w.set_vertex_edge(S, nb.e);
    if (m.vertex_edge_[E] == e) w.set_vertex_edge(E, na.e);
    if (m.face_edge_[keep] == e) w.set_face_edge(keep, na.e);
    Rows::remove(m, Edge(e), rec);
    Rows::remove(m, Face(gone), rec);
    Rows::keep_first_corner(m, keep, rec);
}

// ------------------------------------------------------------------ flip edge
// e = S -> E between triangles L = (S, E, c) and R = (E, S, d) becomes e = d -> c between
// L = (c, S, d) and R = (d, E, c): the side S -> d moves into L, E -> c into R.
template <class R> static void change_flip_edge(WingedEdgeMesh& m, Edge e_, R& rec) {
    auto w = Rows::editor(m, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half a1 = A::next(m, a), a2 = A::next(m, a1); // E -> c, c -> S
    const Half b1 = A::next(m, b), b2 = A::next(m, b1); // S -> d, d -> E
    const int32_t S = m.edges_[e].start, E = m.edges_[e].end, L = m.edges_[e].left, Rf = m.edges_[e].right;
    const int32_t c = A::head(m, a1), d = A::head(m, b1);
    rec.phase("e's row: d -> c; its wings are the two sides at d and the two at c");
    w.start(e, d);
    w.end(e, c);
    w.start_left(e, b1.e);
    w.end_left(e, a2.e);
    w.start_right(e, b2.e);
    w.end_right(e, a1.e);
    rec.phase("L becomes (c, S, d): the side S -> d moves into L");
    w.set_prev(a2, e);
    w.set_next(a2, b1.e);
    w.set_face(b1, L);
    w.set_prev(b1, a2.e);
    w.set_next(b1, e);
    rec.phase("R becomes (d, E, c): the side E -> c moves into R");
    w.set_prev(b2, e);
    w.set_next(b2, a1.e);
    w.set_face(a1, Rf);
    w.set_prev(a1, b2.e);
    w.set_next(a1, e);
    rec.phase("S and E stop storing e; L and R store an edge of their own");
    if (m.vertex_edge_[S] == e) w.set_vertex_edge(S, b1.e);
    if (m.vertex_edge_[E] == e) w.set_vertex_edge(E, a1.e);
    if (m.face_edge_[L] == a1.e) w.set_face_edge(L, e);
    if (m.face_edge_[Rf] == b1.e) w.set_face_edge(Rf, e);
    Rows::keep_first_corner(m, L, rec);
    Rows::keep_first_corner(m, Rf, rec);
}

// ------------------------------------------------------------------ collapse edge
// e = S -> E: E is merged into S (S keeps its number and moves to (1-t) S + t E). Every
// edge at E now ends at S. On a triangle side (S, E, c) the triangle goes and its two
// edges at c become one: the edge c-S stays and takes over the other side of E-c, which
// goes. On a longer side (or the boundary) the edges before and after e meet.
template <class R> static void change_collapse_edge(WingedEdgeMesh& m, Edge e_, double t, R& rec) {
    auto w = Rows::editor(m, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half pa = A::prev(m, a), na = A::next(m, a), pb = A::prev(m, b), nb = A::next(m, b);
    const int32_t S = m.edges_[e].start, E = m.edges_[e].end, L = m.edges_[e].left, Rf = m.edges_[e].right;
    const bool tri_L = L != kNone && A::loop_size(m, a, 4) == 3;
    const bool tri_R = Rf != kNone && A::loop_size(m, b, 4) == 3;
    rec.phase("S moves to (1 - t) S + t E");
    Rows::set_position(m, S, (1.0 - t) * m.position(S) + t * m.position(E), rec);
    rec.phase("every edge at E (but e and the edges E-c that go) now ends at S");
    for (int32_t x = m.next_ccw(e, E); x != e;) {
        const int32_t following = m.next_ccw(x, E);
        if (!(tri_L && x == na.e) && !(tri_R && x == pb.e)) {
            if (m.edges_[x].start == E)
                w.start(x, S);
            else
                w.end(x, S);
        }
        x = following;
    }
    // A triangle side reads its outer neighbours when it is closed, so a side that only
    // splices goes first: at a boundary corner of valence 2 the neighbour of one side's
    // edge is the other side's (an ear of the boundary).
    const auto side_L = [&] {
        rec.phase(tri_L ? "the triangle L goes: its edge c-S takes over the other side of E-c" : "in L the edge before e meets the edge after it");
        if (tri_L) {
            const Half gone = A::twin(na), kept = pa; // gone: c -> E outside L; kept: c -> S in L
            const Half before = A::prev(m, gone), after = A::next(m, gone);
            const int32_t outside = A::face(m, gone), c = A::tail(m, gone);
            w.set_face(kept, outside);
            w.set_prev(kept, before.e);
            w.set_next(kept, after.e);
            w.set_next(before, kept.e);
            w.set_prev(after, kept.e);
            if (outside != kNone && m.face_edge_[outside] == na.e) w.set_face_edge(outside, kept.e);
            if (m.vertex_edge_[c] == na.e) w.set_vertex_edge(c, kept.e);
        } else {
            w.set_next(pa, na.e);
            w.set_prev(na, pa.e);
            if (L != kNone && m.face_edge_[L] == e) w.set_face_edge(L, na.e);
        }
    };
    const auto side_R = [&] {
        rec.phase(tri_R ? "the triangle R goes: its edge S-d takes over the other side of E-d" : "in R the edge before e meets the edge after it");
        if (tri_R) {
            const Half gone = A::twin(pb), kept = nb; // gone: E -> d outside R; kept: S -> d in R
            const Half before = A::prev(m, gone), after = A::next(m, gone);
            const int32_t outside = A::face(m, gone), d = A::head(m, gone);
            w.set_face(kept, outside);
            w.set_prev(kept, before.e);
            w.set_next(kept, after.e);
            w.set_next(before, kept.e);
            w.set_prev(after, kept.e);
            if (outside != kNone && m.face_edge_[outside] == pb.e) w.set_face_edge(outside, kept.e);
            if (m.vertex_edge_[d] == pb.e) w.set_vertex_edge(d, kept.e);
        } else {
            w.set_next(pb, nb.e);
            w.set_prev(nb, pb.e);
            if (Rf != kNone && m.face_edge_[Rf] == e) w.set_face_edge(Rf, nb.e);
        }
    };
    if (tri_L && !tri_R) {
        side_R();
        side_L();
    } else {
        side_L();
        side_R();
    }
    rec.phase("S stops storing e; e, E and the triangles' edges and faces are removed");
    if (m.vertex_edge_[S] == e) w.set_vertex_edge(S, pa.e);
    Rows::remove(m, Edge(e), rec);
    Rows::remove(m, Vertex(E), rec);
    if (tri_L) Rows::remove(m, Edge(na.e), rec), Rows::remove(m, Face(L), rec);
    if (tri_R) Rows::remove(m, Edge(pb.e), rec), Rows::remove(m, Face(Rf), rec);
    if (!m.face_first_corner_.empty()) {
        const int32_t first = m.vertex_edge_[S];
        int32_t x = first;
        do {
            Rows::keep_first_corner(m, m.edges_[x].start == S ? m.edges_[x].left : m.edges_[x].right, rec);
            x = m.next_ccw(x, S);
        } while (x != first);
    }
}

// ------------------------------------------------------------------ poke face
// f with sides h0 (its stored edge) ... h(n-1), corners c_i = start of h_i. A new vertex v
// and edges s_i = v -> c_i; triangle T_i = (c_i, c_(i+1), v) on h_i, T_0 = f (so f keeps
// its stored edge), T_1 ... T_(n-1) new faces. s_i has T_i on its left, T_(i-1) on its right.
template <class R> static void change_poke_face(WingedEdgeMesh& m, Face f_, R& rec) {
    auto w = Rows::editor(m, rec);
    const int32_t f = f_.idx;
    std::vector<Half> sides;
    glm::dvec3 centroid(0.0);
    const Half first = A::side_of(m, m.face_edge_[f], f);
    for (Half h = first;;) {
        sides.push_back(h);
        centroid += m.position(A::tail(m, h));
        h = A::next(m, h);
        if (h.e == first.e && h.left == first.left) break;
    }
    const int32_t n = static_cast<int32_t>(sides.size());
    centroid /= static_cast<double>(n);
    rec.phase("a new vertex v at the centroid, n new edges v -> corner, n - 1 new faces");
    const int32_t v = Rows::new_vertex(m, centroid, rec);
    std::vector<int32_t> spoke(n), tri(n);
    for (int32_t i = 0; i < n; ++i) spoke[i] = Rows::new_edge(m, rec);
    tri[0] = f;
    for (int32_t i = 1; i < n; ++i) tri[i] = Rows::new_face(m, rec);
    w.set_vertex_edge(v, spoke[0]);
    rec.phase("each spoke's row: v -> its corner, the triangles on its two sides, its wings");
    for (int32_t i = 0; i < n; ++i) {
        const int32_t s = spoke[i], next_i = (i + 1) % n, prev_i = (i + n - 1) % n;
        w.start(s, v);
        w.end(s, A::tail(m, sides[i]));
        w.left(s, tri[i]);
        w.right(s, tri[prev_i]);
        w.start_left(s, spoke[next_i]);
        w.start_right(s, spoke[prev_i]);
        w.end_left(s, sides[i].e);
        w.end_right(s, sides[prev_i].e);
    }
    rec.phase("each side of f now borders its own triangle and meets the two spokes at its ends");
    for (int32_t i = 0; i < n; ++i) {
        w.set_face(sides[i], tri[i]);
        w.set_prev(sides[i], spoke[i]);
        w.set_next(sides[i], spoke[(i + 1) % n]);
        if (i > 0) w.set_face_edge(tri[i], sides[i].e);
    }
    for (int32_t i = 0; i < n; ++i) Rows::keep_first_corner(m, tri[i], rec);
}

    // ------------------------------------------------------------------ split vertex
    // Hoppe's vertex split, the inverse of collapse-edge: v's edges strictly between v-a and
    // v-b (counter-clockwise around v) move to a new vertex w, joined to v by a new edge
    // e = v -> w, and two new triangles fill the gap: Ta = (v, a, w) and Tb = (v, w, b). The
    // face Fa between v-a and the first edge that moves now meets w through a new edge
    // p = w -> a, the face Fb before v-b through q = w -> b (Fa = Fb when nothing moves).
    // v stays where it is; w lies at (1 - t) v + t c, c the centre of a, b and the
    // neighbours whose edges move. collapse-edge on e with t = 0 undoes it. V+1, E+3, F+2.
    template <class R> static void change_split_vertex(WingedEdgeMesh& m, const VertexFan& fan, double t, R& rec) {
        auto w = Rows::editor(m, rec);
        const int32_t v = fan.v, a = fan.a, b = fan.b, ea = fan.ea, eb = fan.eb;
        const Half out_a = fan.out_a, in_b = A::twin(fan.out_b); // v -> a along Fa; b -> v along Fb
        const int32_t Fa = A::face(m, out_a), Fb = A::face(m, in_b);
        const Half after_a = A::next(m, out_a); // leaves a along Fa
        const Half before_b = A::prev(m, in_b); // arrives at b along Fb
        // The sides of the first and last edge that move, at v: into v along Fa, out of v along Fb.
        const Half into_first = fan.moved.empty() ? Half{} : A::twin(A::leaving(m, fan.moved.front(), v));
        const Half out_of_last = fan.moved.empty() ? Half{} : A::leaving(m, fan.moved.back(), v);
        rec.phase("a new vertex w between v and the centre of the edges it takes; new edges e = v -> w, p = w -> a, q = w -> b; "
                  "new triangles Ta = (v, a, w) and Tb = (v, w, b)");
        const int32_t wv = Rows::new_vertex(m, (1.0 - t) * m.position(v) + t * fan.centre, rec);
        const int32_t e = Rows::new_edge(m, rec), p = Rows::new_edge(m, rec), q = Rows::new_edge(m, rec);
        const int32_t Ta = Rows::new_face(m, rec), Tb = Rows::new_face(m, rec);
        w.set_vertex_edge(wv, e);
        rec.phase("the edges between v-a and v-b around v now end at w");
        for (const int32_t x : fan.moved) {
            if (m.edges_[x].start == v)
                w.start(x, wv);
            else
                w.end(x, wv);
        }
        rec.phase("e's row: v -> w with Tb on its left and Ta on its right; its wings v-b and q, v-a and p");
        w.start(e, v);
        w.end(e, wv);
        w.left(e, Tb);
        w.right(e, Ta);
        w.start_left(e, eb);
        w.end_left(e, q);
        w.start_right(e, ea);
        w.end_right(e, p);
        rec.phase("p's row: w -> a with Fa on its left and Ta on its right");
        w.start(p, wv);
        w.end(p, a);
        w.left(p, Fa);
        w.right(p, Ta);
        w.start_left(p, fan.moved.empty() ? q : fan.moved.front());
        w.end_left(p, after_a.e);
        w.start_right(p, e);
        w.end_right(p, ea);
        rec.phase("q's row: w -> b with Tb on its left and Fb on its right");
        w.start(q, wv);
        w.end(q, b);
        w.left(q, Tb);
        w.right(q, Fb);
        w.start_left(q, e);
        w.end_left(q, eb);
        w.start_right(q, fan.moved.empty() ? p : fan.moved.back());
        w.end_right(q, before_b.e);
        rec.phase("v-a's side that faced Fa now borders Ta, v-b's side that faced Fb borders Tb");
        w.set_face(out_a, Ta);
        w.set_prev(out_a, e);
        w.set_next(out_a, p);
        w.set_face(in_b, Tb);
        w.set_next(in_b, e);
        w.set_prev(in_b, q);
        rec.phase("in Fa and Fb the neighbours that met v-a and v-b now meet p and q");
        w.set_prev(after_a, p);
        w.set_next(before_b, q);
        if (!fan.moved.empty()) {
            w.set_next(into_first, p);
            w.set_prev(out_of_last, q);
        }
        rec.phase("the stored edges: v stores e if its edge moved to w; Fa and Fb store p and q if they stored v-a and v-b; "
                  "Ta and Tb store e");
        if (std::find(fan.moved.begin(), fan.moved.end(), m.vertex_edge_[v]) != fan.moved.end()) w.set_vertex_edge(v, e);
        if (Fa != kNone && m.face_edge_[Fa] == ea) w.set_face_edge(Fa, p);
        if (Fb != kNone && m.face_edge_[Fb] == eb) w.set_face_edge(Fb, q);
        w.set_face_edge(Ta, e);
        w.set_face_edge(Tb, e);
        for (const int32_t f : fan.faces) Rows::keep_first_corner(m, f, rec);
        for (const int32_t f : {Ta, Tb}) Rows::keep_first_corner(m, f, rec);
    }

    // ------------------------------------------------------------------ the stored edges
    // set-vertex-edge / set-face-edge: the vertex table (the face table) stores one incident
    // edge per vertex (per face); choose another one. The walk around v (along f) then
    // starts at e. Nothing is created; choosing the edge already stored changes nothing.
    template <class R> static void change_set_vertex_edge(WingedEdgeMesh& m, Vertex v, Edge e, R& rec) {
        auto w = Rows::editor(m, rec);
        rec.phase("v's row in the vertex table stores e");
        w.set_vertex_edge(v.idx, e.idx);
    }
    template <class R> static void change_set_face_edge(WingedEdgeMesh& m, Face f, Edge e, R& rec) {
        auto w = Rows::editor(m, rec);
        if (m.face_edge_[f.idx] == e.idx) return;
        // The face set keeps its listing (face_set() lists a face from its first corner):
        // until now every face was listed from where its walk starts.
        if (m.face_first_corner_.empty()) {
            m.face_first_corner_.resize(m.face_edge_.size());
            // (A gap has no corners: none, until an undo makes it a face again.)
            for (int32_t g = 0; g < m.face_count(); ++g) m.face_first_corner_[g] = m.is_deleted(Face(g)) ? kNone : m.walk_start_corner(g);
            rec.began_first_corners();
        }
        rec.phase("f's row in the face table stores e");
        w.set_face_edge(f.idx, e.idx);
    }
};

// ------------------------------------------------------------------ the registry
// Each operation as one value: its check (without words: a Verdict), the words of its
// refusals, its change (through any recorder), and a plan the check hands the change (the
// sides a walk found), so nothing is looked up twice.
namespace {
using C = EulerChanges;

struct Args {
    const std::array<double, 4>& a;
    int32_t i(int k) const { return static_cast<int32_t>(a[k]); }
    double x(int k) const { return a[k]; }
};

struct NoPlan {};

// Whether an accepted operation changes nothing (only storing the edge already stored can):
// the unrecorded path then leaves the version alone, as the recorded one does.
struct ChangesSomething {
    static bool noop(const WingedEdgeMesh&, Args) { return false; }
};

struct SplitEdge : ChangesSomething {
    using Plan = NoPlan;
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan&) { return A::split_edge(m, Edge(a.i(0)), a.x(1)); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args a) { return A::words(m, "split", v, a.x(1)); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan&, R& rec) { C::change_split_edge(m, Edge(a.i(0)), a.x(1), rec); }
};
struct SplitFace : ChangesSomething {
    using Plan = FaceSides;
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan& sides) { return A::split_face(m, Face(a.i(0)), Vertex(a.i(1)), Vertex(a.i(2)), &sides); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args) { return A::words(m, "split-face", v); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan& sides, R& rec) { C::change_split_face(m, Face(a.i(0)), sides, rec); }
};
struct JoinFaces : ChangesSomething {
    using Plan = NoPlan;
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan&) { return A::join_faces(m, Edge(a.i(0))); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args) { return A::words(m, "join", v); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan&, R& rec) { C::change_join_faces(m, Edge(a.i(0)), rec); }
};
struct FlipEdge : ChangesSomething {
    using Plan = NoPlan;
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan&) { return A::flip_edge(m, Edge(a.i(0))); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args) { return A::words(m, "flip", v); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan&, R& rec) { C::change_flip_edge(m, Edge(a.i(0)), rec); }
};
struct CollapseEdge : ChangesSomething {
    using Plan = NoPlan;
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan&) { return A::collapse_edge(m, Edge(a.i(0)), a.x(1)); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args a) { return A::words(m, "collapse", v, a.x(1)); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan&, R& rec) { C::change_collapse_edge(m, Edge(a.i(0)), a.x(1), rec); }
};
struct PokeFace : ChangesSomething {
    using Plan = NoPlan;
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan&) { return A::poke_face(m, Face(a.i(0))); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args) { return A::words(m, "poke", v); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan&, R& rec) { C::change_poke_face(m, Face(a.i(0)), rec); }
};
struct SplitVertex : ChangesSomething {
    using Plan = VertexFan;
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan& fan) { return A::split_vertex(m, Vertex(a.i(0)), Vertex(a.i(1)), Vertex(a.i(2)), a.x(3), &fan); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args a) {
        if (v.ok()) return CheckResult::accept();
        const std::string code = v.code;
        const auto V = [](int32_t i) { return vertex_label(i); };
        if (code == "invalid-parameter")
            return CheckResult::refuse(code, "t = " + number(a.x(3)) + " is not strictly between 0 and 1: the new vertex must lie between " + V(v.x[0]) +
                                                 " and the centre of the edges it takes");
        if (code == "same-vertex")
            return CheckResult::refuse(code, "the new vertex takes the edges between two different neighbours of " + V(v.x[0]) + ", but both are " + V(v.x[1]));
        if (code == "not-a-neighbour")
            return CheckResult::refuse(code, V(v.x[1]) + " is not joined to " + V(v.x[0]) + ": choose two of " + V(v.x[0]) + "'s neighbours (" +
                                                 A::neighbour_list(m, v.x[0]) + ")");
        if (code == "too-large")
            return CheckResult::refuse(code, "splitting " + V(v.x[0]) + " would make " + std::to_string(v.x[2]) + (v.x[1] == 0 ? " vertices" : " faces") +
                                                 "; a mesh may have at most " + std::to_string(v.x[1] == 0 ? kFileLimits.max_vertices : kFileLimits.max_faces) +
                                                 ", as many as a mesh file may hold");
        return A::words(m, "split-vertex", v);
    }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan& fan, R& rec) { C::change_split_vertex(m, fan, a.x(3), rec); }
};
struct SetVertexEdge {
    using Plan = NoPlan;
    static bool noop(const WingedEdgeMesh& m, Args a) { return m.vertex_edge(a.i(0)) == a.i(1); }
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan&) { return A::set_vertex_edge(m, Vertex(a.i(0)), Edge(a.i(1))); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args) { return A::words(m, "set-vertex-edge", v); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan&, R& rec) { C::change_set_vertex_edge(m, Vertex(a.i(0)), Edge(a.i(1)), rec); }
};
struct SetFaceEdge {
    using Plan = NoPlan;
    static bool noop(const WingedEdgeMesh& m, Args a) { return m.face_edge(a.i(0)) == a.i(1); }
    static Verdict check(const WingedEdgeMesh& m, Args a, Plan&) { return A::set_face_edge(m, Face(a.i(0)), Edge(a.i(1))); }
    static CheckResult words(const WingedEdgeMesh& m, const Verdict& v, Args) { return A::words(m, "set-face-edge", v); }
    template <class R> static void change(WingedEdgeMesh& m, Args a, const Plan&, R& rec) { C::change_set_face_edge(m, Face(a.i(0)), Edge(a.i(1)), rec); }
};

} // namespace

namespace {
template <class Op> CheckResult check_op(const WingedEdgeMesh& m, const Operation& op) {
    typename Op::Plan plan;
    return Op::words(m, Op::check(m, Args{op.args}, plan), Args{op.args});
}
template <class Op> ChangeRecord apply_op(WingedEdgeMesh& m, const Operation& op) {
    typename Op::Plan plan;
    const Args args{op.args};
    const Verdict v = Op::check(m, args, plan);
    if (!v.ok()) require_ok(Op::words(m, v, args));
    return Rows::run_recorded(m, op.entry->name, [&](Recording& r) { Op::change(m, args, plan, r); });
}
// The unrecorded path is the benchmarks' hot loop: its check and change are inlined into it
// whole (flatten), as they were when each operation had its own unrecorded twin; without
// it the check's walks stayed calls and a flip took 1.4x as long (mesh_edit_flip).
#if defined(__GNUC__) || defined(__clang__)
#define WINGSPLINE_FLATTEN __attribute__((flatten))
#else
#define WINGSPLINE_FLATTEN
#endif
template <class Op> WINGSPLINE_FLATTEN bool apply_op_unrecorded(WingedEdgeMesh& m, const Operation& op) {
    typename Op::Plan plan;
    const Args args{op.args};
    if (!Op::check(m, args, plan).ok()) return false;
    if (Op::noop(m, args)) return true;
    Rows::run_unrecorded(m, [&](NoRecorder& r) { Op::change(m, args, plan, r); });
    return true;
}
template <class Op> const OperationImpl* impl_of() {
    static const OperationImpl impl{&check_op<Op>, &apply_op<Op>};
    return &impl;
}
} // namespace

const std::vector<OperationEntry>& operations() {
    using K = ElementKind;
    static const std::vector<OperationEntry> all = {
        {"split-edge", "Split edge", "V+1, E+1", "s", "split {e} at t = {t}",
         {{"e", K::Edge}, {"t", K::None, 0.5, true, nullptr, "where the new vertex lies along the edge"}}, impl_of<SplitEdge>(), Locate::EdgeSides},
        {"flip-edge", "Flip edge", "V, E, F unchanged", "f", "flip {e}", {{"e", K::Edge}}, impl_of<FlipEdge>(), Locate::EdgeSides},
        {"collapse-edge", "Collapse edge", "V−1, E−1 (−1 more per triangle side)", "c", "collapse {e} at t = {t}",
         {{"e", K::Edge}, {"t", K::None, 0.5, true, nullptr, "where the merged vertex lies along the edge"}}, impl_of<CollapseEdge>(), Locate::EdgeSidesAndEnds},
        {"join-faces", "Join faces", "E−1, F−1", "j", "join the faces of {e}", {{"e", K::Edge}}, impl_of<JoinFaces>(), Locate::EdgeSides},
        {"split-face", "Split face", "E+1, F+1", "d", "split {f} by {a}–{b}",
         {{"f", K::Face}, {"a", K::Vertex, 0, false, "vertices-of-face", "first corner of the new edge"},
          {"b", K::Vertex, 0, false, "vertices-of-face", "second corner of the new edge"}}, impl_of<SplitFace>(), Locate::FaceSides},
        {"poke-face", "Poke face", "V+1, E+n, F+n−1", "k", "poke {f}", {{"f", K::Face}}, impl_of<PokeFace>(), Locate::FaceSides},
        {"split-vertex", "Split vertex", "V+1, E+3, F+2", "v", "split {v} between {a} and {b}",
         {{"v", K::Vertex}, {"a", K::Vertex, 0, false, "vertices-around-vertex", "neighbour where the moved edges begin"},
          {"b", K::Vertex, 0, false, "vertices-around-vertex", "neighbour where they end"},
          {"t", K::None, 0.5, true, nullptr, "where the new vertex lies, from v towards the edges it takes"}}, impl_of<SplitVertex>(), Locate::VertexStar},
        {"set-vertex-edge", "Store another edge for a vertex", "V, E, F unchanged", "", "store {e} for {v}",
         {{"v", K::Vertex}, {"e", K::Edge, 0, false, "edges-around-vertex", "the edge to store"}}, impl_of<SetVertexEdge>(), Locate::VertexStar},
        {"set-face-edge", "Store another edge for a face", "V, E, F unchanged", "", "store {e} for {f}",
         {{"f", K::Face}, {"e", K::Edge, 0, false, "edges-of-face", "the edge to store"}}, impl_of<SetFaceEdge>(), Locate::FaceSides},
    };
    return all;
}

const OperationEntry* find_operation(std::string_view name) {
    for (const OperationEntry& e : operations())
        if (name == e.name) return &e;
    return nullptr;
}

Operation operation_from(std::string_view name, const double* args, std::size_t count) {
    const OperationEntry* entry = find_operation(name);
    if (entry == nullptr) throw Error("unknown-operation", "unknown mesh operation '" + std::string(name.substr(0, 40)) + "'");
    if (count > entry->arguments.size())
        throw Error("invalid-argument", std::string(entry->name) + " takes " + std::to_string(entry->arguments.size()) + " arguments, not " +
                                            std::to_string(count));
    Operation op{entry, {}};
    std::size_t k = 0;
    for (; k < count; ++k) op.args[k] = args[k];
    for (; k < entry->arguments.size(); ++k) op.args[k] = entry->arguments[k].kind == ElementKind::None ? entry->arguments[k].default_value : kNone;
    return op;
}

CheckResult WingedEdgeMesh::check(const Operation& op) const {
    if (op.entry == nullptr) throw Error("unknown-operation", "an operation needs a name (operations.h)");
    return op.entry->impl->check(*this, op);
}
ChangeRecord WingedEdgeMesh::apply(const Operation& op) {
    if (op.entry == nullptr) throw Error("unknown-operation", "an operation needs a name (operations.h)");
    return op.entry->impl->apply(*this, op);
}
CheckResult WingedEdgeMesh::check_undo(const ChangeRecord& change) const { return EulerRows::check_undo(*this, change); }
ChangeRecord WingedEdgeMesh::undo(const ChangeRecord& change) { return EulerRows::undo(*this, change); }
// The unrecorded runs by name, apart from the registry: only the benchmarks and the tests
// reach them, so the linker leaves them (about 20 KB of flattened code) out of the page's
// modules, which apply() alone.
UnrecordedRun unrecorded_run(const OperationEntry& entry) {
    static const std::pair<std::string_view, UnrecordedRun> runs[] = {
        {"split-edge", &apply_op_unrecorded<SplitEdge>},       {"flip-edge", &apply_op_unrecorded<FlipEdge>},
        {"collapse-edge", &apply_op_unrecorded<CollapseEdge>}, {"join-faces", &apply_op_unrecorded<JoinFaces>},
        {"split-face", &apply_op_unrecorded<SplitFace>},       {"poke-face", &apply_op_unrecorded<PokeFace>},
        {"split-vertex", &apply_op_unrecorded<SplitVertex>},   {"set-vertex-edge", &apply_op_unrecorded<SetVertexEdge>},
        {"set-face-edge", &apply_op_unrecorded<SetFaceEdge>},
    };
    for (const auto& [name, run] : runs)
        if (name == entry.name) return run;
    throw Error("unknown-operation", std::string(entry.name) + " has no unrecorded run");
}
bool apply_unrecorded(WingedEdgeMesh& mesh, const Operation& op) { return unrecorded_run(*op.entry)(mesh, op); }

void WingedEdgeMesh::reserve(int32_t vertices, int32_t edges, int32_t faces) {
    positions_.reserve(3 * static_cast<std::size_t>(vertices));
    vertex_edge_.reserve(vertices);
    edges_.reserve(edges);
    face_edge_.reserve(faces);
}

const std::vector<const char*>& change_tables() {
    static const std::vector<const char*> all = {"vertex", "edge", "face"};
    return all;
}

const std::vector<const char*>& change_fields() {
    static const std::vector<const char*> all = {"edge", "start", "end", "left", "right", "startLeft", "startRight",
                                                 "endLeft", "endRight", "firstCorner"};
    return all;
}

int change_field_index(const std::string& field) {
    const auto& all = change_fields();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (field == all[i]) return static_cast<int>(i);
    return -1;
}

} // namespace wingspline::mesh
