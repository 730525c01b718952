// The Euler operations of issue 15 on Baumgart's winged edge (lecture 000): split an edge,
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
#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

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

namespace {

// Records nothing: every call is empty and inlined away (the benchmark path).
struct NoRecorder {
    bool moved = false; // a position was set (the geometry version moves on)
    void step(MeshTable, int32_t, const char*, int32_t, int32_t) {}
    void phase(const char*) {}
    void position(int32_t, const glm::dvec3&, const glm::dvec3&) { moved = true; }
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
        if (a == b) return refuse("same-vertex", a.idx);
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
            msg = V(x[0]) + " and " + V(x[1]) + " are already joined by " + E(x[2]) + ", a side of " + F(x[3]) +
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
    static void mark(std::vector<char>& marks, std::size_t count, int32_t i) {
        if (marks.empty()) marks.assign(count, 0);
        marks[i] = 1;
    }
    template <class R> static void remove(WingedEdgeMesh& m, Vertex v, R& rec) {
        mark(m.vertex_deleted_, m.vertex_edge_.size(), v.idx);
        rec.removed(v);
    }
    template <class R> static void remove(WingedEdgeMesh& m, Edge e, R& rec) {
        mark(m.edge_deleted_, m.edges_.size(), e.idx);
        rec.removed(e);
    }
    template <class R> static void remove(WingedEdgeMesh& m, Face f, R& rec) {
        mark(m.face_deleted_, m.face_edge_.size(), f.idx);
        rec.removed(f);
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
    template <class R> static void set_position(WingedEdgeMesh& m, int32_t v, const glm::dvec3& p, R& rec) {
        const glm::dvec3 before = m.position(v);
        if (before == p) return;
        m.positions_[3 * v] = p.x, m.positions_[3 * v + 1] = p.y, m.positions_[3 * v + 2] = p.z;
        rec.position(v, before, p);
    }
};

namespace {
using Rows = EulerRows;
template <class R> Editor<R> editor_of(WingedEdgeMesh& m, std::vector<EdgeRecord>& e, std::vector<int32_t>& ve,
                                       std::vector<int32_t>& fe, R& rec) {
    return Editor<R>{m, e, ve, fe, rec};
}
} // namespace

// ------------------------------------------------------------------ split edge
// e = S -> E with faces L, R. A new vertex m on e; e now ends at m; a new edge n runs
// m -> E with the same faces. Only the wings at E change hands: the edge after e in L and
// the edge before e in R now meet n instead.
template <class R> void WingedEdgeMesh::split_edge_impl(Edge e_, double t, R& rec) {
    auto w = editor_of(*this, edges_, vertex_edge_, face_edge_, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half after_in_L = A::next(*this, a);  // leaves E along L
    const Half before_in_R = A::prev(*this, b); // arrives at E along R
    const int32_t S = edges_[e].start, E = edges_[e].end, L = edges_[e].left, Rf = edges_[e].right;
    rec.phase("a new vertex m at (1 - t) S + t E and a new edge n; m stores n");
    const int32_t m = Rows::new_vertex(*this, (1.0 - t) * position(S) + t * position(E), rec);
    const int32_t n = Rows::new_edge(*this, rec);
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
    if (vertex_edge_[E] == e) w.set_vertex_edge(E, n);
}

// ------------------------------------------------------------------ split face
// A new edge n = a -> b inside f. Its left side closes f's corners b ... a, its right side
// the new face g's corners a ... b.
template <class R> void WingedEdgeMesh::split_face_impl(Face f_, const FaceSides& sides, R& rec) {
    auto w = editor_of(*this, edges_, vertex_edge_, face_edge_, rec);
    const int32_t f = f_.idx, a = sides.a, b = sides.b;
    // the sides of f at a and b, as the check found them
    const Half into_a = sides.into_a, out_of_a = sides.out_of_a, into_b = sides.into_b, out_of_b = sides.out_of_b;
    rec.phase("a new edge n = a -> b with f on its left and a new face g on its right; its wings");
    const int32_t n = Rows::new_edge(*this, rec);
    const int32_t g = Rows::new_face(*this, rec);
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
        const Half following = last ? h : A::next(*this, h);
        w.set_face(h, g);
        face_edge_moved |= face_edge_[f] == h.e;
        if (last) break;
        h = following;
    }
    w.set_face_edge(g, n);
    if (face_edge_moved) w.set_face_edge(f, n);
    Rows::keep_first_corner(*this, f, rec);
    Rows::keep_first_corner(*this, g, rec);
}

// ------------------------------------------------------------------ join faces
// Removes e = S -> E; the higher-numbered of its faces is merged into the lower one. The
// edges before and after e on each side now meet each other.
template <class R> void WingedEdgeMesh::join_faces_impl(Edge e_, R& rec) {
    auto w = editor_of(*this, edges_, vertex_edge_, face_edge_, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half pa = A::prev(*this, a), na = A::next(*this, a), pb = A::prev(*this, b), nb = A::next(*this, b);
    const int32_t S = edges_[e].start, E = edges_[e].end, L = edges_[e].left, Rf = edges_[e].right;
    const int32_t keep = std::min(L, Rf), gone = std::max(L, Rf);
    rec.phase("every side of the face that goes now belongs to the one kept");
    const Half along_gone = gone == L ? a : b;
    for (Half x = A::next(*this, along_gone); x.e != e;) {
        const Half following = A::next(*this, x);
        w.set_face(x, keep);
        x = following;
    }
    rec.phase("close the gap e leaves: on each side the edge before e meets the edge after it");
    w.set_next(pa, nb.e);
    w.set_prev(nb, pa.e);
    w.set_next(pb, na.e);
    w.set_prev(na, pb.e);
    rec.phase("S, E and the face kept stop storing e; e and the face that went are removed");
    if (vertex_edge_[S] == e) w.set_vertex_edge(S, nb.e);
    if (vertex_edge_[E] == e) w.set_vertex_edge(E, na.e);
    if (face_edge_[keep] == e) w.set_face_edge(keep, na.e);
    Rows::remove(*this, Edge(e), rec);
    Rows::remove(*this, Face(gone), rec);
    Rows::keep_first_corner(*this, keep, rec);
}

// ------------------------------------------------------------------ flip edge
// e = S -> E between triangles L = (S, E, c) and R = (E, S, d) becomes e = d -> c between
// L = (c, S, d) and R = (d, E, c): the side S -> d moves into L, E -> c into R.
template <class R> void WingedEdgeMesh::flip_edge_impl(Edge e_, R& rec) {
    auto w = editor_of(*this, edges_, vertex_edge_, face_edge_, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half a1 = A::next(*this, a), a2 = A::next(*this, a1); // E -> c, c -> S
    const Half b1 = A::next(*this, b), b2 = A::next(*this, b1); // S -> d, d -> E
    const int32_t S = edges_[e].start, E = edges_[e].end, L = edges_[e].left, Rf = edges_[e].right;
    const int32_t c = A::head(*this, a1), d = A::head(*this, b1);
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
    if (vertex_edge_[S] == e) w.set_vertex_edge(S, b1.e);
    if (vertex_edge_[E] == e) w.set_vertex_edge(E, a1.e);
    if (face_edge_[L] == a1.e) w.set_face_edge(L, e);
    if (face_edge_[Rf] == b1.e) w.set_face_edge(Rf, e);
    Rows::keep_first_corner(*this, L, rec);
    Rows::keep_first_corner(*this, Rf, rec);
}

// ------------------------------------------------------------------ collapse edge
// e = S -> E: E is merged into S (S keeps its number and moves to (1-t) S + t E). Every
// edge at E now ends at S. On a triangle side (S, E, c) the triangle goes and its two
// edges at c become one: the edge c-S stays and takes over the other side of E-c, which
// goes. On a longer side (or the boundary) the edges before and after e meet.
template <class R> void WingedEdgeMesh::collapse_edge_impl(Edge e_, double t, R& rec) {
    auto w = editor_of(*this, edges_, vertex_edge_, face_edge_, rec);
    const int32_t e = e_.idx;
    const Half a{e, true}, b{e, false};
    const Half pa = A::prev(*this, a), na = A::next(*this, a), pb = A::prev(*this, b), nb = A::next(*this, b);
    const int32_t S = edges_[e].start, E = edges_[e].end, L = edges_[e].left, Rf = edges_[e].right;
    const bool tri_L = L != kNone && A::loop_size(*this, a, 4) == 3;
    const bool tri_R = Rf != kNone && A::loop_size(*this, b, 4) == 3;
    rec.phase("S moves to (1 - t) S + t E");
    Rows::set_position(*this, S, (1.0 - t) * position(S) + t * position(E), rec);
    rec.phase("every edge at E (but e and the edges E-c that go) now ends at S");
    for (int32_t x = next_ccw(e, E); x != e;) {
        const int32_t following = next_ccw(x, E);
        if (!(tri_L && x == na.e) && !(tri_R && x == pb.e)) {
            if (edges_[x].start == E)
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
            const Half before = A::prev(*this, gone), after = A::next(*this, gone);
            const int32_t outside = A::face(*this, gone), c = A::tail(*this, gone);
            w.set_face(kept, outside);
            w.set_prev(kept, before.e);
            w.set_next(kept, after.e);
            w.set_next(before, kept.e);
            w.set_prev(after, kept.e);
            if (outside != kNone && face_edge_[outside] == na.e) w.set_face_edge(outside, kept.e);
            if (vertex_edge_[c] == na.e) w.set_vertex_edge(c, kept.e);
        } else {
            w.set_next(pa, na.e);
            w.set_prev(na, pa.e);
            if (L != kNone && face_edge_[L] == e) w.set_face_edge(L, na.e);
        }
    };
    const auto side_R = [&] {
        rec.phase(tri_R ? "the triangle R goes: its edge S-d takes over the other side of E-d" : "in R the edge before e meets the edge after it");
        if (tri_R) {
            const Half gone = A::twin(pb), kept = nb; // gone: E -> d outside R; kept: S -> d in R
            const Half before = A::prev(*this, gone), after = A::next(*this, gone);
            const int32_t outside = A::face(*this, gone), d = A::head(*this, gone);
            w.set_face(kept, outside);
            w.set_prev(kept, before.e);
            w.set_next(kept, after.e);
            w.set_next(before, kept.e);
            w.set_prev(after, kept.e);
            if (outside != kNone && face_edge_[outside] == pb.e) w.set_face_edge(outside, kept.e);
            if (vertex_edge_[d] == pb.e) w.set_vertex_edge(d, kept.e);
        } else {
            w.set_next(pb, nb.e);
            w.set_prev(nb, pb.e);
            if (Rf != kNone && face_edge_[Rf] == e) w.set_face_edge(Rf, nb.e);
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
    if (vertex_edge_[S] == e) w.set_vertex_edge(S, pa.e);
    Rows::remove(*this, Edge(e), rec);
    Rows::remove(*this, Vertex(E), rec);
    if (tri_L) Rows::remove(*this, Edge(na.e), rec), Rows::remove(*this, Face(L), rec);
    if (tri_R) Rows::remove(*this, Edge(pb.e), rec), Rows::remove(*this, Face(Rf), rec);
    if (!face_first_corner_.empty()) {
        const int32_t first = vertex_edge_[S];
        int32_t x = first;
        do {
            Rows::keep_first_corner(*this, edges_[x].start == S ? edges_[x].left : edges_[x].right, rec);
            x = next_ccw(x, S);
        } while (x != first);
    }
}

// ------------------------------------------------------------------ poke face
// f with sides h0 (its stored edge) ... h(n-1), corners c_i = start of h_i. A new vertex v
// and edges s_i = v -> c_i; triangle T_i = (c_i, c_(i+1), v) on h_i, T_0 = f (so f keeps
// its stored edge), T_1 ... T_(n-1) new faces. s_i has T_i on its left, T_(i-1) on its right.
template <class R> void WingedEdgeMesh::poke_face_impl(Face f_, R& rec) {
    auto w = editor_of(*this, edges_, vertex_edge_, face_edge_, rec);
    const int32_t f = f_.idx;
    std::vector<Half> sides;
    glm::dvec3 centroid(0.0);
    const Half first = A::side_of(*this, face_edge_[f], f);
    for (Half h = first;;) {
        sides.push_back(h);
        centroid += position(A::tail(*this, h));
        h = A::next(*this, h);
        if (h.e == first.e && h.left == first.left) break;
    }
    const int32_t n = static_cast<int32_t>(sides.size());
    centroid /= static_cast<double>(n);
    rec.phase("a new vertex v at the centroid, n new edges v -> corner, n - 1 new faces");
    const int32_t v = Rows::new_vertex(*this, centroid, rec);
    std::vector<int32_t> spoke(n), tri(n);
    for (int32_t i = 0; i < n; ++i) spoke[i] = Rows::new_edge(*this, rec);
    tri[0] = f;
    for (int32_t i = 1; i < n; ++i) tri[i] = Rows::new_face(*this, rec);
    w.set_vertex_edge(v, spoke[0]);
    rec.phase("each spoke's row: v -> its corner, the triangles on its two sides, its wings");
    for (int32_t i = 0; i < n; ++i) {
        const int32_t s = spoke[i], next_i = (i + 1) % n, prev_i = (i + n - 1) % n;
        w.start(s, v);
        w.end(s, A::tail(*this, sides[i]));
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
    for (int32_t i = 0; i < n; ++i) Rows::keep_first_corner(*this, tri[i], rec);
}

// ------------------------------------------------------------------ the public pairs
namespace {
template <class Op> ChangeRecord run_recorded(const char* name, MeshVersion& version, Op op) {
    ChangeRecord change;
    change.op = name;
    change.before = version;
    Recording rec{change};
    op(rec);
    ++version.topology;
    if (!change.positions.empty()) ++version.geometry;
    change.after = version;
    aggregate_rows(change);
    return change;
}
template <class Op> bool run_unrecorded(const Verdict& verdict, MeshVersion& version, Op op) {
    if (!verdict.ok()) return false;
    NoRecorder rec;
    op(rec);
    ++version.topology;
    if (rec.moved) ++version.geometry;
    return true;
}
} // namespace

CheckResult WingedEdgeMesh::check_split_edge(Edge e, double t) const { return A::words(*this, "split", A::split_edge(*this, e, t), t); }
ChangeRecord WingedEdgeMesh::split_edge(Edge e, double t) {
    require_ok(check_split_edge(e, t));
    return run_recorded("split-edge", version_, [&](Recording& r) { split_edge_impl(e, t, r); });
}
bool WingedEdgeMesh::split_edge_unrecorded(Edge e, double t) {
    return run_unrecorded(A::split_edge(*this, e, t), version_, [&](NoRecorder& r) { split_edge_impl(e, t, r); });
}

CheckResult WingedEdgeMesh::check_split_face(Face f, Vertex a, Vertex b) const {
    return A::words(*this, "split-face", A::split_face(*this, f, a, b));
}
ChangeRecord WingedEdgeMesh::split_face(Face f, Vertex a, Vertex b) {
    FaceSides sides;
    require_ok(A::words(*this, "split-face", A::split_face(*this, f, a, b, &sides)));
    return run_recorded("split-face", version_, [&](Recording& r) { split_face_impl(f, sides, r); });
}
bool WingedEdgeMesh::split_face_unrecorded(Face f, Vertex a, Vertex b) {
    FaceSides sides;
    return run_unrecorded(A::split_face(*this, f, a, b, &sides), version_, [&](NoRecorder& r) { split_face_impl(f, sides, r); });
}

CheckResult WingedEdgeMesh::check_join_faces(Edge e) const { return A::words(*this, "join", A::join_faces(*this, e)); }
ChangeRecord WingedEdgeMesh::join_faces(Edge e) {
    require_ok(check_join_faces(e));
    return run_recorded("join-faces", version_, [&](Recording& r) { join_faces_impl(e, r); });
}
bool WingedEdgeMesh::join_faces_unrecorded(Edge e) {
    return run_unrecorded(A::join_faces(*this, e), version_, [&](NoRecorder& r) { join_faces_impl(e, r); });
}

CheckResult WingedEdgeMesh::check_flip_edge(Edge e) const { return A::words(*this, "flip", A::flip_edge(*this, e)); }
ChangeRecord WingedEdgeMesh::flip_edge(Edge e) {
    require_ok(check_flip_edge(e));
    return run_recorded("flip-edge", version_, [&](Recording& r) { flip_edge_impl(e, r); });
}
bool WingedEdgeMesh::flip_edge_unrecorded(Edge e) {
    return run_unrecorded(A::flip_edge(*this, e), version_, [&](NoRecorder& r) { flip_edge_impl(e, r); });
}

CheckResult WingedEdgeMesh::check_collapse_edge(Edge e, double t) const {
    return A::words(*this, "collapse", A::collapse_edge(*this, e, t), t);
}
ChangeRecord WingedEdgeMesh::collapse_edge(Edge e, double t) {
    require_ok(check_collapse_edge(e, t));
    return run_recorded("collapse-edge", version_, [&](Recording& r) { collapse_edge_impl(e, t, r); });
}
bool WingedEdgeMesh::collapse_edge_unrecorded(Edge e, double t) {
    return run_unrecorded(A::collapse_edge(*this, e, t), version_, [&](NoRecorder& r) { collapse_edge_impl(e, t, r); });
}

CheckResult WingedEdgeMesh::check_poke_face(Face f) const { return A::words(*this, "poke", A::poke_face(*this, f)); }
ChangeRecord WingedEdgeMesh::poke_face(Face f) {
    require_ok(check_poke_face(f));
    return run_recorded("poke-face", version_, [&](Recording& r) { poke_face_impl(f, r); });
}
bool WingedEdgeMesh::poke_face_unrecorded(Face f) {
    return run_unrecorded(A::poke_face(*this, f), version_, [&](NoRecorder& r) { poke_face_impl(f, r); });
}

void WingedEdgeMesh::reserve(int32_t vertices, int32_t edges, int32_t faces) {
    positions_.reserve(3 * static_cast<std::size_t>(vertices));
    vertex_edge_.reserve(vertices);
    edges_.reserve(edges);
    face_edge_.reserve(faces);
}

int32_t flip_every_third_edge(WingedEdgeMesh& mesh) {
    int32_t flips = 0;
    for (int32_t e = 0; e < mesh.edge_count(); e += 3) flips += mesh.flip_edge_unrecorded(Edge(e));
    return flips;
}

int32_t split_every_edge(WingedEdgeMesh& mesh) {
    const int32_t E = mesh.edge_count();
    mesh.reserve(mesh.vertex_count() + E, 4 * E, mesh.face_count() + 2 * E);
    int32_t splits = 0;
    for (int32_t e = 0; e < E; ++e) {
        const EdgeRecord& r = mesh.edge(e);
        // the corners opposite e in its two faces, if they are triangles (read before the split)
        const int32_t E_ = r.end, L = r.left, R = r.right;
        const int32_t c = L != kNone && mesh.next_in_face(r.end_left, L) == r.start_left ? mesh.other_vertex(r.end_left, E_) : kNone;
        const int32_t d = R != kNone && mesh.next_in_face(r.start_right, R) == r.end_right ? mesh.other_vertex(r.end_right, E_) : kNone;
        if (!mesh.split_edge_unrecorded(Edge(e), 0.5)) continue;
        ++splits;
        const Vertex m(mesh.vertex_count() - 1);
        if (c != kNone) mesh.split_face_unrecorded(Face(L), m, Vertex(c));
        if (d != kNone) mesh.split_face_unrecorded(Face(R), m, Vertex(d));
    }
    return splits;
}

} // namespace wingspline::mesh
