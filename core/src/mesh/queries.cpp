// Each query written once per representation, reading that representation's arrays only
// through a Reader that counts every entry it hands out.
#include "wingspline/mesh/queries.h"

#include "cost_grids.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/half_edge.h"

#include <algorithm>

namespace wingspline::mesh {

namespace {

struct Reader {
    std::size_t count = 0;
    template <class T> T operator()(const std::vector<T>& table, std::size_t i) {
        ++count;
        return table[i];
    }
};

// Sorted, without -1 and repeats: the answer of a scan, whose order is the table's.
std::vector<int32_t> as_set(std::vector<int32_t> v) {
    v.erase(std::remove(v.begin(), v.end(), kNone), v.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

// Appends x unless it is -1 or already there (first-appearance order of a short list).
void add_once(std::vector<int32_t>& out, int32_t x) {
    if (x != kNone && std::find(out.begin(), out.end(), x) == out.end()) out.push_back(x);
}

// The answer a face-table scan gives when corner c (of the face's corners begin..end-1) is
// the vertex asked about: the face itself, or the two sides that meet at c (the side that
// leaves c and the side that arrives at it; names[c] is the side c -> c+1).
void answer_at_corner(QueryKind kind, QueryAnswer& a, const std::vector<int32_t>& names, int32_t f, int32_t c,
                      int32_t begin, int32_t end) {
    if (kind == QueryKind::FacesAroundVertex) {
        a.answer.push_back(f);
    } else {
        a.answer.push_back(names[c]);
        a.answer.push_back(names[c == begin ? end - 1 : c - 1]);
    }
}

// ---------------------------------------------------------------- independent faces

// Compares corner c with p coordinate by coordinate, stopping at the first difference.
bool same_point(Reader& rd, const std::vector<double>& xyz, int32_t c, const glm::dvec3& p) {
    return rd(xyz, 3 * c) == p.x && rd(xyz, 3 * c + 1) == p.y && rd(xyz, 3 * c + 2) == p.z;
}

QueryAnswer independent_faces_query(QueryKind kind, int32_t element, const IndependentFaces& t,
                                    const std::vector<int32_t>& names, const WingedEdgeMesh& w) {
    QueryAnswer a;
    Reader rd;
    const auto& off = t.face_offsets;
    const auto& xyz = t.corner_positions;
    const int32_t F = static_cast<int32_t>(off.size()) - 1;
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex: {
        // No vertex identity: find the point in every face (a scan of the whole table).
        const glm::dvec3 p = w.position(element);
        int32_t end = rd(off, 0);
        for (int32_t f = 0; f < F; ++f) {
            const int32_t begin = end;
            end = rd(off, f + 1);
            for (int32_t c = begin; c < end; ++c)
                if (same_point(rd, xyz, c, p)) {
                    answer_at_corner(kind, a, names, f, c, begin, end);
                    break;
                }
        }
        break;
    }
    case QueryKind::EdgesOfFace: {
        // The sides are the consecutive coordinate pairs of the row.
        const int32_t begin = rd(off, element), end = rd(off, element + 1);
        for (int32_t c = begin; c < end; ++c) {
            for (int k = 0; k < 3; ++k) rd(xyz, 3 * c + k);
            a.answer.push_back(names[c]);
        }
        break;
    }
    case QueryKind::FacesOfEdge: {
        // A face has the edge when two consecutive corners are its two end points.
        const glm::dvec3 s = w.position(w.edge(element).start), e = w.position(w.edge(element).end);
        int32_t end = rd(off, 0);
        for (int32_t f = 0; f < F; ++f) {
            const int32_t begin = end;
            end = rd(off, f + 1);
            int first = 0, previous = 0;
            for (int32_t c = begin; c < end; ++c) {
                const int code = same_point(rd, xyz, c, s) ? 1 : same_point(rd, xyz, c, e) ? 2 : 0;
                if (c == begin) first = code;
                if (c > begin && code && previous && code != previous) {
                    a.answer.push_back(f);
                    break;
                }
                if (c == end - 1 && code && first && code != first) a.answer.push_back(f);
                previous = code;
            }
        }
        break;
    }
    case QueryKind::NeighboursOfFace: {
        // Read the face's points, then look for two of them, consecutive, in every other face.
        const int32_t fb = rd(off, element), fe = rd(off, element + 1), n = fe - fb;
        std::vector<glm::dvec3> points;
        for (int32_t c = fb; c < fe; ++c) points.push_back({rd(xyz, 3 * c), rd(xyz, 3 * c + 1), rd(xyz, 3 * c + 2)});
        int32_t end = rd(off, 0);
        for (int32_t g = 0; g < F; ++g) {
            const int32_t begin = end;
            end = rd(off, g + 1);
            if (g == element) continue;
            std::vector<int32_t> at; // index in `points` of each corner of g, or -1
            for (int32_t c = begin; c < end; ++c) {
                int32_t hit = kNone;
                for (int32_t i = 0; i < n && hit == kNone; ++i)
                    if (same_point(rd, xyz, c, points[i])) hit = i;
                at.push_back(hit);
            }
            for (std::size_t i = 0; i < at.size(); ++i) {
                const int32_t x = at[i], y = at[(i + 1) % at.size()];
                if (x != kNone && y != kNone && ((x + 1) % n == y || (y + 1) % n == x)) {
                    a.answer.push_back(g);
                    break;
                }
            }
        }
        break;
    }
    }
    if (kind != QueryKind::EdgesOfFace) a.answer = as_set(a.answer);
    a.entries_read = rd.count;
    return a;
}

// ---------------------------------------------------------------- vertex and face tables

QueryAnswer vertex_face_tables_query(QueryKind kind, int32_t element, const VertexFaceTables& t,
                                     const std::vector<int32_t>& names, const WingedEdgeMesh& w) {
    QueryAnswer a;
    Reader rd;
    const auto& off = t.face_offsets;
    const auto& fv = t.face_vertices;
    const int32_t F = static_cast<int32_t>(off.size()) - 1;
    // Visits every face's corners in order; visit(f, begin, end) reads what it needs.
    auto scan_faces = [&](auto&& visit) {
        int32_t end = rd(off, 0);
        for (int32_t f = 0; f < F; ++f) {
            const int32_t begin = end;
            end = rd(off, f + 1);
            // A gap left by an edit has no corners: nothing more to read (its first corner
            // would be the next face's, or past the table's end for the last face).
            if (begin != end) visit(f, begin, end);
        }
    };
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex:
        // The face table points at vertices, never back: scan it.
        scan_faces([&](int32_t f, int32_t begin, int32_t end) {
            for (int32_t c = begin; c < end; ++c)
                if (rd(fv, c) == element) {
                    answer_at_corner(kind, a, names, f, c, begin, end);
                    break;
                }
        });
        break;
    case QueryKind::EdgesOfFace: {
        const int32_t begin = rd(off, element), end = rd(off, element + 1);
        for (int32_t c = begin; c < end; ++c) {
            rd(fv, c);
            a.answer.push_back(names[c]);
        }
        break;
    }
    case QueryKind::FacesOfEdge: {
        const int32_t s = w.edge(element).start, e = w.edge(element).end;
        auto is_edge = [&](int32_t x, int32_t y) { return (x == s && y == e) || (x == e && y == s); };
        scan_faces([&](int32_t f, int32_t begin, int32_t end) {
            const int32_t first = rd(fv, begin);
            int32_t previous = first;
            for (int32_t c = begin + 1; c <= end; ++c) {
                const int32_t x = c == end ? first : rd(fv, c);
                if (is_edge(previous, x)) {
                    a.answer.push_back(f);
                    return;
                }
                previous = x;
            }
        });
        break;
    }
    case QueryKind::NeighboursOfFace: {
        const int32_t fb = rd(off, element), fe = rd(off, element + 1);
        std::vector<int32_t> ring;
        for (int32_t c = fb; c < fe; ++c) ring.push_back(rd(fv, c));
        auto is_side = [&](int32_t x, int32_t y) {
            for (std::size_t i = 0; i < ring.size(); ++i)
                if (ring[i] == y && ring[(i + 1) % ring.size()] == x) return true; // a neighbour runs it backwards
            return false;
        };
        scan_faces([&](int32_t g, int32_t begin, int32_t end) {
            if (g == element) return;
            const int32_t first = rd(fv, begin);
            int32_t previous = first;
            for (int32_t c = begin + 1; c <= end; ++c) {
                const int32_t x = c == end ? first : rd(fv, c);
                if (is_side(previous, x)) {
                    a.answer.push_back(g);
                    return;
                }
                previous = x;
            }
        });
        break;
    }
    }
    if (kind != QueryKind::EdgesOfFace) a.answer = as_set(a.answer);
    a.entries_read = rd.count;
    return a;
}

// ---------------------------------------------------------------- adjacency lists

QueryAnswer adjacency_lists_query(QueryKind kind, int32_t element, const AdjacencyLists& t) {
    QueryAnswer a;
    Reader rd;
    auto read_list = [&](const std::vector<int32_t>& offsets, const std::vector<int32_t>& list) {
        const int32_t begin = rd(offsets, element), end = rd(offsets, element + 1);
        for (int32_t i = begin; i < end; ++i) {
            const int32_t x = rd(list, i);
            if (x != kNone) a.answer.push_back(x);
        }
    };
    switch (kind) {
    case QueryKind::FacesAroundVertex: read_list(t.vertex_face_offsets, t.vertex_faces); break;
    case QueryKind::EdgesAroundVertex: read_list(t.vertex_offsets, t.vertex_edges); break;
    case QueryKind::EdgesOfFace: read_list(t.face_offsets, t.face_edges); break;
    case QueryKind::NeighboursOfFace:
        // FF lists the face across each side: a face sharing two sides appears twice.
        read_list(t.face_offsets, t.face_faces);
        keep_first_appearance(a.answer);
        break;
    case QueryKind::FacesOfEdge:
        for (int side = 0; side < 2; ++side) add_once(a.answer, rd(t.edge_faces, 2 * element + side));
        break;
    }
    a.entries_read = rd.count;
    return a;
}

QueryAnswer partial_adjacency_lists_query(QueryKind kind, int32_t element, const PartialAdjacencyLists& t) {
    QueryAnswer a;
    Reader rd;
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex: {
        const int32_t begin = rd(t.vertex_offsets, element), end = rd(t.vertex_offsets, element + 1);
        for (int32_t i = begin; i < end; ++i) {
            const int32_t e = rd(t.vertex_edges, i);
            if (kind == QueryKind::EdgesAroundVertex) {
                a.answer.push_back(e);
            } else {
                // Derived: the faces around v are the faces of v's edges.
                add_once(a.answer, rd(t.edge_faces, 2 * e));
                add_once(a.answer, rd(t.edge_faces, 2 * e + 1));
            }
        }
        break;
    }
    case QueryKind::EdgesOfFace:
    case QueryKind::NeighboursOfFace: {
        const int32_t begin = rd(t.face_offsets, element), end = rd(t.face_offsets, element + 1);
        for (int32_t i = begin; i < end; ++i) {
            const int32_t e = rd(t.face_edges, i);
            if (kind == QueryKind::EdgesOfFace) {
                a.answer.push_back(e);
            } else {
                // Derived: across each edge, whichever of L and R is not this face.
                const int32_t left = rd(t.edge_faces, 2 * e);
                add_once(a.answer, left == element ? rd(t.edge_faces, 2 * e + 1) : left);
            }
        }
        break;
    }
    case QueryKind::FacesOfEdge:
        for (int side = 0; side < 2; ++side) add_once(a.answer, rd(t.edge_faces, 2 * element + side));
        break;
    }
    a.entries_read = rd.count;
    return a;
}

// ---------------------------------------------------------------- Foley's edge list

QueryAnswer edge_list_query(QueryKind kind, int32_t element, const EdgeList& t) {
    QueryAnswer a;
    Reader rd;
    const int32_t E = static_cast<int32_t>(t.edges.size() / 4);
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex:
        // Lecture 001: "the determining of which edges are incident to a vertex is not easy.
        // All edges must be inspected."
        for (int32_t e = 0; e < E; ++e) {
            if (rd(t.edges, 4 * e) != element && rd(t.edges, 4 * e + 1) != element) continue;
            if (kind == QueryKind::EdgesAroundVertex) {
                a.answer.push_back(e);
            } else {
                a.answer.push_back(rd(t.edges, 4 * e + 2));
                a.answer.push_back(rd(t.edges, 4 * e + 3));
            }
        }
        a.answer = as_set(a.answer);
        break;
    case QueryKind::EdgesOfFace:
    case QueryKind::NeighboursOfFace: {
        const int32_t begin = rd(t.polygon_offsets, element), end = rd(t.polygon_offsets, element + 1);
        for (int32_t i = begin; i < end; ++i) {
            const int32_t e = rd(t.polygon_edges, i);
            if (kind == QueryKind::EdgesOfFace) {
                a.answer.push_back(e);
            } else {
                const int32_t p1 = rd(t.edges, 4 * e + 2);
                add_once(a.answer, p1 == element ? rd(t.edges, 4 * e + 3) : p1);
            }
        }
        break;
    }
    case QueryKind::FacesOfEdge:
        add_once(a.answer, rd(t.edges, 4 * element + 2));
        add_once(a.answer, rd(t.edges, 4 * element + 3));
        break;
    }
    a.entries_read = rd.count;
    return a;
}

// ---------------------------------------------------------------- winged edge

// The lecture's walks, counting each field of a table row as it is read.
QueryAnswer winged_edge_query(QueryKind kind, int32_t element, const WingedEdgeMesh& w) {
    QueryAnswer a;
    std::size_t reads = 0;
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex: {
        const int32_t v = element;
        const int32_t first = w.vertex_edge(v);
        ++reads;
        if (first == kNone) break;
        int32_t e = first;
        do {
            const EdgeRecord& r = w.edge(e);
            const bool at_start = r.start == v;
            ++reads;
            if (kind == QueryKind::EdgesAroundVertex) {
                a.answer.push_back(e);
            } else {
                // Turning CCW from e at its Start sweeps L; at its End it sweeps R.
                const int32_t f = at_start ? r.left : r.right;
                ++reads;
                if (f != kNone) a.answer.push_back(f);
            }
            e = at_start ? r.start_left : r.end_right;
            ++reads;
        } while (e != first && a.answer.size() <= static_cast<std::size_t>(w.edge_count()));
        break;
    }
    case QueryKind::EdgesOfFace:
    case QueryKind::NeighboursOfFace: {
        const int32_t f = element;
        const int32_t first = w.face_edge(f);
        ++reads;
        int32_t e = first;
        std::size_t steps = 0;
        do {
            const EdgeRecord& r = w.edge(e);
            const bool is_left = r.left == f;
            ++reads;
            if (kind == QueryKind::EdgesOfFace) {
                a.answer.push_back(e);
            } else {
                const int32_t g = is_left ? r.right : r.left;
                ++reads;
                if (g != kNone) a.answer.push_back(g);
            }
            e = is_left ? r.end_left : r.start_right;
            ++reads;
        } while (e != first && ++steps <= static_cast<std::size_t>(w.edge_count()));
        // A face met across two of f's edges is one neighbour (a set, docs/api-mesh.md).
        if (kind == QueryKind::NeighboursOfFace) keep_first_appearance(a.answer);
        break;
    }
    case QueryKind::FacesOfEdge: {
        const EdgeRecord& r = w.edge(element);
        reads += 2;
        add_once(a.answer, r.left);
        add_once(a.answer, r.right);
        break;
    }
    }
    a.entries_read = reads;
    return a;
}

} // namespace

QueryKind query_kind(const std::string& name) {
    if (name == "faces-around-vertex") return QueryKind::FacesAroundVertex;
    if (name == "edges-around-vertex") return QueryKind::EdgesAroundVertex;
    if (name == "edges-of-face") return QueryKind::EdgesOfFace;
    if (name == "faces-of-edge") return QueryKind::FacesOfEdge;
    if (name == "neighbours-of-face") return QueryKind::NeighboursOfFace;
    throw Error("unknown-query", "unknown query '" + name +
                                     "'; use faces-around-vertex, edges-around-vertex, edges-of-face, faces-of-edge "
                                     "or neighbours-of-face");
}

ElementKind query_element_kind(QueryKind kind) {
    switch (kind) {
    case QueryKind::FacesAroundVertex:
    case QueryKind::EdgesAroundVertex: return ElementKind::Vertex;
    case QueryKind::FacesOfEdge: return ElementKind::Edge;
    case QueryKind::EdgesOfFace:
    case QueryKind::NeighboursOfFace: return ElementKind::Face;
    }
    return ElementKind::None;
}

namespace {
void check_query_element(QueryKind kind, int32_t element, const WingedEdgeMesh& w) {
    const ElementKind of = query_element_kind(kind);
    require_ok(of == ElementKind::Vertex ? w.check_element(Vertex(element))
               : of == ElementKind::Edge ? w.check_element(Edge(element))
                                         : w.check_element(Face(element)));
}
} // namespace

QueryAnswer winged_edge_answer(QueryKind kind, int32_t element, const WingedEdgeMesh& w) {
    check_query_element(kind, element, w);
    return winged_edge_query(kind, element, w);
}

std::array<QueryAnswer, kRepresentationCount> answer_query(QueryKind kind, int32_t element,
                                                           const Representations& reps,
                                                           const WingedEdgeMesh& w) {
    check_query_element(kind, element, w);
    return {independent_faces_query(kind, element, reps.independent_faces, reps.corner_edge_names, w),
            vertex_face_tables_query(kind, element, reps.vertex_face_tables, reps.corner_edge_names, w),
            adjacency_lists_query(kind, element, reps.adjacency_lists),
            partial_adjacency_lists_query(kind, element, reps.partial_adjacency_lists),
            edge_list_query(kind, element, reps.edge_list),
            winged_edge_query(kind, element, w)};
}

// ---------------------------------------------------------------- cost against mesh size

std::array<int64_t, kRepresentationCount> query_reads_on_grid(QueryKind kind, int32_t n) {
    cost_grids::require_even(n);
    const IndexedMesh faces = grid(n, n);
    const WingedEdgeMesh w = WingedEdgeMesh::build(faces);
    const Representations reps = build_representations(faces, w);
    const auto answers = answer_query(kind, cost_grids::middle(query_element_kind(kind), w, n), reps, w);
    std::array<int64_t, kRepresentationCount> reads{};
    for (int r = 0; r < kRepresentationCount; ++r) reads[r] = static_cast<int64_t>(answers[r].entries_read);
    return reads;
}

int64_t half_edge_query_reads_on_grid(QueryKind kind, int32_t n) {
    cost_grids::require_even(n);
    const WingedEdgeMesh w = WingedEdgeMesh::build(grid(n, n));
    const HalfEdgeMesh h = HalfEdgeMesh::build(w);
    return static_cast<int64_t>(half_edge_answer(kind, cost_grids::middle(query_element_kind(kind), w, n), h, w).entries_read);
}

QueryCostGrowth query_cost_growth(QueryKind kind, const std::vector<int32_t>& sizes) {
    for (const int32_t n : sizes) cost_grids::require_even(n);
    std::array<std::array<int64_t, kRepresentationCount>, 3> measured;
    std::array<int64_t, 3> measured_half_edge{};
    for (std::size_t i = 0; i < cost_grids::kFit.size(); ++i) {
        measured[i] = query_reads_on_grid(kind, cost_grids::kFit[i]);
        measured_half_edge[i] = half_edge_query_reads_on_grid(kind, cost_grids::kFit[i]);
    }
    const auto evaluate = [&](int32_t n) {
        std::array<int64_t, kRepresentationCount> reads{};
        for (int r = 0; r < kRepresentationCount; ++r) reads[r] = cost_grids::quadratic_at({measured[0][r], measured[1][r], measured[2][r]}, n);
        return reads;
    };
    const auto evaluate_half_edge = [&](int32_t n) { return cost_grids::quadratic_at(measured_half_edge, n); };
    if (evaluate(cost_grids::kCheck) != query_reads_on_grid(kind, cost_grids::kCheck) ||
        evaluate_half_edge(cost_grids::kCheck) != half_edge_query_reads_on_grid(kind, cost_grids::kCheck))
        throw Error("internal-error", "query costs: the counts on a 32 x 32 grid differ from the quadratic through 8, 16 and 24");
    QueryCostGrowth out;
    for (const int32_t n : sizes) {
        out.n.push_back(n);
        out.faces.push_back(2 * static_cast<int64_t>(n) * n);
        out.reads.push_back(evaluate(n));
        out.half_edge_reads.push_back(evaluate_half_edge(n));
    }
    return out;
}

} // namespace wingspline::mesh
