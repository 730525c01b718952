// The half-edge view of the winged edge: every row read off the winged-edge tables by the
// rules in half_edge.h, so that a build and an update write the same values.
#include "wingspline/mesh/half_edge.h"

#include <initializer_list>
#include <string>

namespace wingspline::mesh {

namespace {

// The half-edge of edge x that leaves v (x's S -> E when v is its Start).
int32_t leaving(const WingedEdgeMesh& w, int32_t x, int32_t v) {
    if (x == kNone) return kNone;
    return w.edge(x).start == v ? 2 * x : 2 * x + 1;
}
// The half-edge of edge x that arrives at v.
int32_t arriving(const WingedEdgeMesh& w, int32_t x, int32_t v) {
    if (x == kNone) return kNone;
    return w.edge(x).end == v ? 2 * x : 2 * x + 1;
}

} // namespace

void HalfEdgeMesh::resize(const WingedEdgeMesh& w) {
    const std::size_t H = 2 * static_cast<std::size_t>(w.edge_count());
    for (auto* column : {&origin_, &face_, &next_, &prev_}) column->resize(H, kNone);
    vertex_halfedge_.resize(w.vertex_count(), kNone);
    face_halfedge_.resize(w.face_count(), kNone);
}

void HalfEdgeMesh::write_edge(const WingedEdgeMesh& w, int32_t e) {
    const int32_t a = 2 * e, b = 2 * e + 1;
    if (w.is_deleted(Edge(e))) {
        for (auto* column : {&origin_, &face_, &next_, &prev_}) (*column)[a] = (*column)[b] = kNone;
        return;
    }
    const EdgeRecord& r = w.edge(e);
    origin_[a] = r.start;
    origin_[b] = r.end;
    face_[a] = r.left;
    face_[b] = r.right;
    // S -> E runs along L: after it comes L's other edge at E (end_left), before it L's
    // other edge at S (start_left); E -> S runs along R, from start_right's and end_right's.
    next_[a] = leaving(w, r.end_left, r.end);
    prev_[a] = arriving(w, r.start_left, r.start);
    next_[b] = leaving(w, r.start_right, r.start);
    prev_[b] = arriving(w, r.end_right, r.end);
}

void HalfEdgeMesh::write_vertex(const WingedEdgeMesh& w, int32_t v) {
    int32_t& out = vertex_halfedge_[v];
    out = kNone;
    if (w.is_deleted(Vertex(v))) return;
    const int32_t first = w.vertex_edge(v);
    if (first == kNone) return;
    out = leaving(w, first, v);
    // The first outgoing half-edge CCW from v's edge with no face, if any: the sector CCW
    // after the outgoing half-edge along e is e's L when v is its Start, else its R.
    int32_t e = first;
    for (int32_t guard = 0; guard <= w.edge_count(); ++guard) {
        const EdgeRecord& r = w.edge(e);
        if ((r.start == v ? r.left : r.right) == kNone) {
            out = leaving(w, e, v);
            return;
        }
        e = w.next_ccw(e, v);
        if (e == first || e == kNone) return;
    }
}

void HalfEdgeMesh::write_face(const WingedEdgeMesh& w, int32_t f) {
    int32_t& out = face_halfedge_[f];
    out = kNone;
    if (w.is_deleted(Face(f))) return;
    const int32_t e = w.face_edge(f);
    if (e != kNone) out = w.edge(e).left == f ? 2 * e : 2 * e + 1;
}

HalfEdgeMesh HalfEdgeMesh::build(const WingedEdgeMesh& w) {
    HalfEdgeMesh m;
    m.resize(w);
    for (int32_t e = 0; e < w.edge_count(); ++e) m.write_edge(w, e);
    for (int32_t v = 0; v < w.vertex_count(); ++v) m.write_vertex(w, v);
    for (int32_t f = 0; f < w.face_count(); ++f) m.write_face(w, f);
    return m;
}

void HalfEdgeMesh::update(const WingedEdgeMesh& w, const ChangeRecord& c, std::vector<HalfEdgeAssignment>* written) {
    std::vector<int32_t>* const columns[4] = {&origin_, &face_, &next_, &prev_}; // in HalfEdgeField's order
    int32_t step = kNone; // the step the rows now written are attributed to
    const auto log = [&](HalfEdgeTable t, int32_t row, HalfEdgeField f, int32_t before, int32_t after) {
        if (written && before != after) written->push_back({t, row, f, before, after, step});
    };
    // Rows an undo drops from the end leave their values for none.
    if (written) {
        for (int32_t x = 2 * w.edge_count(); x < halfedge_count(); ++x)
            for (int k = 0; k < 4; ++k) log(HalfEdgeTable::HalfEdge, x, static_cast<HalfEdgeField>(k), (*columns[k])[x], kNone);
        for (int32_t v = w.vertex_count(); v < vertex_count(); ++v) log(HalfEdgeTable::Vertex, v, HalfEdgeField::HalfEdge, vertex_halfedge_[v], kNone);
        for (int32_t f = w.face_count(); f < face_count(); ++f) log(HalfEdgeTable::Face, f, HalfEdgeField::HalfEdge, face_halfedge_[f], kNone);
    }
    resize(w);
    const int32_t V = w.vertex_count(), E = w.edge_count(), F = w.face_count();
    // Each write compared with what the row held: a row written again logs nothing more, so
    // every entry is logged once, with its first before and (the winged edge being final
    // already) its last after.
    const auto own_edge = [&](int32_t e) {
        if (e < 0 || e >= E) return; // an undo's removed rows: gone with the resize
        int32_t old[2][4];
        for (int s = 0; s < 2; ++s)
            for (int k = 0; k < 4; ++k) old[s][k] = (*columns[k])[2 * e + s];
        write_edge(w, e);
        for (int s = 0; s < 2; ++s)
            for (int k = 0; k < 4; ++k) log(HalfEdgeTable::HalfEdge, 2 * e + s, static_cast<HalfEdgeField>(k), old[s][k], (*columns[k])[2 * e + s]);
    };
    const auto vertex = [&](int32_t v) {
        if (v < 0 || v >= V) return;
        const int32_t old = vertex_halfedge_[v];
        write_vertex(w, v);
        log(HalfEdgeTable::Vertex, v, HalfEdgeField::HalfEdge, old, vertex_halfedge_[v]);
    };
    const auto face = [&](int32_t f) {
        if (f < 0 || f >= F) return;
        const int32_t old = face_halfedge_[f];
        write_face(w, f);
        log(HalfEdgeTable::Face, f, HalfEdgeField::HalfEdge, old, face_halfedge_[f]);
    };
    // First the elements the winged-edge steps name, in the order they first name them (a
    // named element's own rows; the search for repeats is the logging's: nothing changes).
    if (written) {
        for (std::size_t i = 0; i < c.steps.size(); ++i) {
            const AssignmentStep& a = c.steps[i];
            step = static_cast<int32_t>(i);
            if (a.table == MeshTable::Edge) own_edge(a.row);
            else if (a.table == MeshTable::Vertex) vertex(a.row);
            else face(a.row);
        }
        step = kNone;
    }
    // An edge's rows depend on its own row and on its wings' S and E; the wing relation is
    // symmetric (x follows e in a face exactly when e precedes x there), so the rows that
    // can read a changed edge are those of its wings. Its ends' fans and its sides' faces
    // changed with it.
    const auto edge = [&](int32_t e) {
        if (e < 0 || e >= E) return;
        own_edge(e);
        if (w.is_deleted(Edge(e))) return;
        const EdgeRecord& r = w.edge(e);
        for (const int32_t x : {r.start_left, r.start_right, r.end_left, r.end_right}) own_edge(x);
        vertex(r.start);
        vertex(r.end);
        face(r.left);
        face(r.right);
    };
    for (const RowChange& row : c.rows) {
        // A vertex or face that lost an edge is reached without the edge's old values: the
        // edges next to it in its fan or loop changed their wings (named, and it is at their
        // end or on their side), or it was removed (named).
        if (row.table == MeshTable::Edge) {
            edge(row.row);
        } else if (row.table == MeshTable::Vertex) {
            vertex(row.row);
        } else {
            face(row.row);
        }
    }
    for (const Edge e : c.added_edges) edge(e.idx);
    for (const Edge e : c.removed_edges) edge(e.idx);
    for (const Vertex v : c.added_vertices) vertex(v.idx);
    for (const Vertex v : c.removed_vertices) vertex(v.idx);
    for (const Face f : c.added_faces) face(f.idx);
    for (const Face f : c.removed_faces) face(f.idx);
}

std::vector<HalfEdgeStep> HalfEdgeMesh::vertex_walk(int32_t v, int32_t start) const {
    std::vector<HalfEdgeStep> steps;
    const int32_t first = start == kNone ? vertex_halfedge_[v] : start;
    if (first == kNone) return steps;
    int32_t h = first;
    do {
        const int32_t p = prev_[h];
        steps.push_back({h, p, p == kNone ? kNone : twin(p)});
        h = steps.back().next;
    } while (h != first && h != kNone && steps.size() <= origin_.size());
    return steps;
}

std::vector<HalfEdgeStep> HalfEdgeMesh::face_walk(int32_t f) const {
    std::vector<HalfEdgeStep> steps;
    const int32_t first = face_halfedge_[f];
    if (first == kNone) return steps;
    int32_t h = first;
    do {
        const int32_t n = next_[h];
        steps.push_back({h, n, n});
        h = n;
    } while (h != first && h != kNone && steps.size() <= origin_.size());
    return steps;
}

namespace {

// A problem's message from a pattern whose %h, %v, %e, %f, %n take the next number as a
// half-edge, vertex, edge, face (or "the boundary" for none) label or a plain count; one
// call per message keeps the module small (docs/architecture.md, "Module size").
std::string say(const char* pattern, std::initializer_list<int32_t> numbers) {
    std::string out;
    const int32_t* x = numbers.begin();
    for (const char* c = pattern; *c; ++c) {
        if (*c != '%' || c[1] == '\0') {
            out += *c;
            continue;
        }
        const char kind = *++c;
        const int32_t i = *x++;
        if (kind == 'f' && i == kNone) {
            out += "the boundary";
            continue;
        }
        if (i == kNone && kind != 'n') {
            out += "none";
            continue;
        }
        if (kind != 'n') out += kind == 'h' ? 'h' : kind == 'v' ? 'v' : kind == 'e' ? 'e' : 'F';
        out += std::to_string(kind == 'n' ? int64_t{i} : int64_t{i} + 1);
    }
    return out;
}

} // namespace

ValidationReport HalfEdgeMesh::validate(const WingedEdgeMesh& w) const {
    ValidationReport report;
    // At most this many problems: past the first few a student learns nothing more.
    constexpr std::size_t kMaxProblems = 20;
    // The element a problem is about: a vertex, the edge of a half-edge, or a face.
    const auto problem = [&](std::string message, MeshTable table, int32_t element) {
        if (report.problems.size() >= kMaxProblems) return;
        Problem p{"half-edge-broken", Severity::Error, std::move(message), {}, {}, {}};
        if (element != kNone) (table == MeshTable::Vertex ? p.vertices : table == MeshTable::Edge ? p.edges : p.faces).push_back(element);
        report.problems.push_back(std::move(p));
    };
    const int32_t H = halfedge_count(), V = vertex_count(), F = face_count();
    if (H != 2 * w.edge_count() || V != w.vertex_count() || F != w.face_count()) {
        problem(say("the half-edge tables hold %n half-edges, %n vertices and %n faces; the mesh has %n, %n and %n",
                    {H, V, F, 2 * w.edge_count(), w.vertex_count(), w.face_count()}),
                MeshTable::Edge, kNone);
        return report;
    }
    const auto in = [](int32_t x, int32_t n) { return x >= 0 && x < n; };
    for (int32_t h = 0; h < H; ++h) {
        const int32_t e = edge_of_half_edge(h);
        if (w.is_deleted(Edge(e))) {
            if (origin_[h] != kNone || face_[h] != kNone || next_[h] != kNone || prev_[h] != kNone)
                problem(say("%h belongs to %e, which an edit removed, but its row is not empty", {h, e}), MeshTable::Edge, e);
            continue;
        }
        // twin(twin(h)) = h and twin(h) != h hold by the numbering; the pair must join two vertices.
        if (twin(twin(h)) != h || twin(h) == h || !in(origin_[h], V) || origin_[h] == origin_[twin(h)]) {
            problem(say("%h and its twin %h do not run between two different vertices", {h, twin(h)}), MeshTable::Edge, e);
            continue;
        }
        const int32_t n = next_[h], p = prev_[h];
        if (!in(n, H) || !in(p, H)) {
            problem(say("%h has no next or no prev half-edge", {h}), MeshTable::Edge, e);
            continue;
        }
        if (prev_[n] != h || next_[p] != h)
            problem(say("next and prev are not inverse at %h: next is %h, whose prev is %h; prev is %h, whose next is %h",
                        {h, n, prev_[n], p, next_[p]}),
                    MeshTable::Edge, e);
        if (origin_[n] != target(h))
            problem(say("%h ends at %v but its next, %h, starts at %v", {h, target(h), n, origin_[n]}), MeshTable::Edge, e);
        if (face_[n] != face_[h])
            problem(say("%h and its next, %h, lie on different faces (%f and %f)", {h, n, face_[h], face_[n]}), MeshTable::Edge, e);
    }
    for (int32_t v = 0; v < V; ++v) {
        const int32_t h = vertex_halfedge_[v];
        if (w.is_deleted(Vertex(v)) || w.vertex_edge(v) == kNone) {
            if (h != kNone) problem(say("%v has no edges, but its half-edge is %h", {v, h}), MeshTable::Vertex, v);
            continue;
        }
        if (!in(h, H) || origin_[h] != v) {
            problem(say("%v's half-edge %h does not start at it", {v, in(h, H) ? h : kNone}), MeshTable::Vertex, v);
            continue;
        }
        bool on_boundary = false;
        for (const int32_t e : w.edges_around_vertex(v)) {
            const EdgeRecord& r = w.edge(e);
            on_boundary = on_boundary || r.left == kNone || r.right == kNone;
        }
        if (on_boundary && face_[h] != kNone)
            problem(say("%v is on the boundary, but its half-edge %h is not a boundary half-edge (a walk from it would not "
                        "meet the whole fan)",
                        {v, h}),
                    MeshTable::Vertex, v);
    }
    for (int32_t f = 0; f < F; ++f) {
        const int32_t h = face_halfedge_[f];
        if (w.is_deleted(Face(f))) {
            if (h != kNone) problem(say("%f was removed by an edit, but its half-edge is %h", {f, h}), MeshTable::Face, f);
            continue;
        }
        if (!in(h, H) || face_[h] != f) {
            problem(say("%f's half-edge does not lie on it", {f}), MeshTable::Face, f);
            continue;
        }
        const int32_t corners = static_cast<int32_t>(w.face_corners(f).size());
        int32_t sides = 0;
        int32_t x = h;
        do {
            ++sides;
            x = next_[x];
        } while (in(x, H) && x != h && sides <= H);
        if (x != h)
            problem(say("%f has %n corners, but the next-loop from %h does not close", {f, corners, h}), MeshTable::Face, f);
        else if (sides != corners)
            problem(say("%f has %n corners, but the next-loop from %h has %n sides", {f, corners, h, sides}), MeshTable::Face, f);
    }
    return report;
}

Storage HalfEdgeMesh::storage() const {
    // The names and the arrays in one order; each array's entries are its real size.
    const char* names[] = {"half-edge origin", "half-edge face", "half-edge next", "half-edge prev", "vertex half-edge", "face half-edge"};
    const std::vector<int32_t>* arrays[] = {&origin_, &face_, &next_, &prev_, &vertex_halfedge_, &face_halfedge_};
    Storage s;
    for (int i = 0; i < 6; ++i) s.arrays.push_back({names[i], arrays[i]->size(), sizeof(int32_t)});
    return s;
}

Storage half_edge_storage(const HalfEdgeMesh& h, const WingedEdgeMesh& w) {
    Storage own = h.storage();
    Storage s;
    s.arrays.push_back({"vertex coordinates", w.positions().size(), sizeof(double)});
    for (ArrayStorage& a : own.arrays) s.arrays.push_back(std::move(a));
    return s;
}

QueryAnswer half_edge_answer(QueryKind kind, int32_t element, const HalfEdgeMesh& m, const WingedEdgeMesh& w) {
    const ElementKind of = query_element_kind(kind);
    require_ok(of == ElementKind::Vertex ? w.check_element(Vertex(element))
               : of == ElementKind::Edge ? w.check_element(Edge(element))
                                         : w.check_element(Face(element)));
    QueryAnswer a;
    std::size_t reads = 0;
    const std::size_t guard = m.origins().size();
    const auto add_once = [&](int32_t x) {
        if (x == kNone) return;
        for (const int32_t y : a.answer)
            if (y == x) return;
        a.answer.push_back(x);
    };
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex: {
        const int32_t first = m.vertex_halfedge(element);
        ++reads;
        if (first == kNone) break;
        int32_t h = first;
        std::size_t steps = 0;
        do {
            if (kind == QueryKind::EdgesAroundVertex) {
                a.answer.push_back(edge_of_half_edge(h));
            } else {
                const int32_t f = m.face(h);
                ++reads;
                if (f != kNone) a.answer.push_back(f);
            }
            h = twin(m.prev(h)); // CCW around the vertex
            ++reads;
        } while (h != first && ++steps <= guard);
        break;
    }
    case QueryKind::EdgesOfFace:
    case QueryKind::NeighboursOfFace: {
        const int32_t first = m.face_halfedge(element);
        ++reads;
        int32_t h = first;
        std::size_t steps = 0;
        do {
            if (kind == QueryKind::EdgesOfFace) {
                a.answer.push_back(edge_of_half_edge(h));
            } else {
                ++reads;
                add_once(m.face(twin(h))); // a face met across two sides is one neighbour
            }
            h = m.next(h);
            ++reads;
        } while (h != first && ++steps <= guard);
        break;
    }
    case QueryKind::FacesOfEdge:
        reads += 2;
        add_once(m.face(2 * element));
        add_once(m.face(2 * element + 1));
        break;
    }
    a.entries_read = reads;
    return a;
}

} // namespace wingspline::mesh
