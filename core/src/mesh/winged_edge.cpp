// Building Baumgart's winged edge (lecture 000) from an indexed face set without any map
// per edge: half-edges are bucketed by their lower vertex (a counting sort, CSR layout),
// twins are matched inside each small bucket, and the wings are read off each face's
// previous and next corner. Anything the structure cannot hold is handed to
// validate_indexed(), which explains every problem; the build only has to notice that
// something is wrong.
//
// This file is the reference path: each phase of build() below is one named function that
// fills or checks one part of the lecture's tables, written the way the lecture reads.
// The fixed-degree kernels that the benchmarks need (triangles unrolled, the ring walk
// inlined) live beside it in fast_kernels.cpp and are tested to give identical tables
// (tests/native/test_mesh_kernels.cpp; docs/architecture.md, "Teaching path and fast kernels").
#include "wingspline/mesh/winged_edge.h"

#include "fast_kernels.h"

#include <cstdio>
#include <string>

#include <algorithm>
#include <cmath>
#include <memory>

namespace wingspline::mesh {

using detail::BucketSlot;

namespace {

[[noreturn]] void refuse(const IndexedMesh& mesh) { throw InvalidMesh(validate_indexed(mesh)); }

void sort_bucket(BucketSlot* first, BucketSlot* last) {
    if (last - first <= 12) {
        for (BucketSlot* i = first + 1; i < last; ++i) {
            const BucketSlot x = *i;
            BucketSlot* j = i;
            while (j > first && (j - 1)->other > x.other) {
                *j = *(j - 1);
                --j;
            }
            *j = x;
        }
    } else {
        std::sort(first, last, [](const BucketSlot& a, const BucketSlot& b) { return a.other < b.other; });
    }
}

bool corners_distinct(const int32_t* c, int32_t n) {
    if (n == 3) return c[0] != c[1] && c[1] != c[2] && c[0] != c[2];
    if (n <= 16) {
        for (int32_t i = 1; i < n; ++i)
            for (int32_t j = 0; j < i; ++j)
                if (c[i] == c[j]) return false;
        return true;
    }
    std::vector<int32_t> s(c, c + n);
    std::sort(s.begin(), s.end());
    return std::adjacent_find(s.begin(), s.end()) == s.end();
}

// Phase 0, the vertex table's positions: at least one face, three finite coordinates per
// vertex, none beyond kMaxCoordinate (limits.h).
void check_positions(const IndexedMesh& mesh) {
    if (mesh.face_count() <= 0 || mesh.positions.size() != 3 * static_cast<std::size_t>(mesh.vertex_count())) refuse(mesh);
    for (double c : mesh.positions)
        if (!std::isfinite(c) || std::abs(c) > kMaxCoordinate) refuse(mesh);
}

// Phase 1, count: every face of the face set is checked (at least three distinct corners,
// each an existing vertex) and each of its sides, corner i -> corner i + 1, is counted into
// the bucket of its lower vertex. false if some face cannot be used.
bool count_sides(const IndexedMesh& mesh, int32_t* count) {
    const std::vector<int32_t>& fo = mesh.face_offsets;
    const std::vector<int32_t>& fv = mesh.face_vertices;
    for (int32_t f = 0; f < mesh.face_count(); ++f) {
        const int32_t o = fo[f], n = fo[f + 1] - o;
        if (n < 3 || !detail::face_corners_ok(fv.data() + o, n, mesh.vertex_count())) return false;
        for (int32_t i = 0; i < n; ++i) ++count[std::min(fv[o + i], fv[o + (i + 1) % n])];
    }
    return true;
}

// Phase 2, bucket the sides by vertex pair: side h (corner h -> corner h + 1 of its face)
// goes into the bucket of its lower vertex, naming the higher one (a counting sort). On
// entry bucket_end[v] is where bucket v starts; on return, where it ends.
void bucket_sides(const IndexedMesh& mesh, int32_t* bucket_end, BucketSlot* slots) {
    const std::vector<int32_t>& fo = mesh.face_offsets;
    const std::vector<int32_t>& fv = mesh.face_vertices;
    for (int32_t f = 0; f < mesh.face_count(); ++f) {
        const int32_t o = fo[f], n = fo[f + 1] - o;
        for (int32_t i = 0; i < n; ++i) detail::put_side(slots, bucket_end, o + i, fv[o + i], fv[o + (i + 1) % n]);
    }
}

// Phase 3, twins: inside a bucket, equal `other` means the same undirected edge, met by
// two faces that must walk it in opposite directions (the mesh is oriented). edge_of[h]
// becomes h's twin (kNone on a boundary); returns the number of pairs.
int32_t pair_twins(const IndexedMesh& mesh, const std::vector<int32_t>& bucket_end, BucketSlot* slots,
                   std::vector<int32_t>& edge_of) {
    int32_t pairs = 0;
    for (int32_t v = 0; v < mesh.vertex_count(); ++v) {
        BucketSlot* first = slots + (v == 0 ? 0 : bucket_end[v - 1]);
        BucketSlot* last = slots + bucket_end[v];
        if (last - first > 1) sort_bucket(first, last);
        for (BucketSlot* s = first; s < last;) {
            BucketSlot* t = s + 1;
            while (t < last && t->other == s->other) ++t;
            if (t - s == 2) {
                if ((s->code & 1) == (s[1].code & 1)) refuse(mesh); // same direction twice
                edge_of[s->code >> 1] = s[1].code >> 1;
                edge_of[s[1].code >> 1] = s->code >> 1;
                ++pairs;
            } else if (t - s > 2) {
                refuse(mesh); // more than two faces on one edge
            }
            s = t;
        }
    }
    return pairs;
}

// Phase 4, number the edges (the edge table's rows and its S and E columns): order of
// first appearance walking the faces, oriented as first walked. In place: a half-edge
// whose twin comes earlier takes the twin's (already final) number.
void number_edges(const IndexedMesh& mesh, std::vector<int32_t>& edge_of, std::vector<EdgeRecord>& edges) {
    const std::vector<int32_t>& fo = mesh.face_offsets;
    const std::vector<int32_t>& fv = mesh.face_vertices;
    for (int32_t f = 0, e = 0; f < mesh.face_count(); ++f) {
        const int32_t o = fo[f], last = fo[f + 1] - 1;
        for (int32_t h = o; h <= last; ++h) {
            const int32_t t = edge_of[h];
            if (t == kNone || t > h) {
                edges[e].start = fv[h];
                edges[e].end = fv[h == last ? o : h + 1];
                edge_of[h] = e++;
            } else {
                edge_of[h] = edge_of[t];
            }
        }
    }
}

// An edge the caller gave, as a message names it: its label, or the number itself when it
// is negative (-1 = none).
std::string edge_or_none(int32_t e) { return e >= 0 ? edge_label(e) : std::to_string(e); }

// Phase 4b, the caller's numbering (BuildOptions::edges, e.g. the slide's e1..e7): find
// each [s, t] in its bucket and renumber and reorient the edge table to match.
void apply_edge_list(const BuildOptions& options, int32_t V, const std::vector<int32_t>& bucket_end,
                     const BucketSlot* slots, std::vector<int32_t>& edge_of, std::vector<EdgeRecord>& edges) {
    const int32_t E = static_cast<int32_t>(edges.size());
    if (static_cast<int32_t>(options.edges.size()) != E)
        throw Error("invalid-edge-list", "the edge list has " + std::to_string(options.edges.size()) +
                    " edges but the faces have " + std::to_string(E));
    std::vector<int32_t> renumber(E, kNone);
    for (int32_t i = 0; i < E; ++i) {
        const int32_t s = options.edges[i][0], t = options.edges[i][1];
        const std::string label = edge_label(i) + " = [" + std::to_string(s) + ", " + std::to_string(t) + "]";
        for (const int32_t v : {s, t})
            if (v < 0 || v >= V) throw Error("invalid-edge-list", label + ": " + missing_element_message(MeshTable::Vertex, v, V));
        if (s == t) throw Error("invalid-edge-list", label + " joins " + vertex_label(s) + " to itself; an edge needs two different vertices");
        const int32_t lo = std::min(s, t), hi = std::max(s, t);
        const BucketSlot* first = slots + (lo == 0 ? 0 : bucket_end[lo - 1]);
        const BucketSlot* last = slots + bucket_end[lo];
        const BucketSlot* hit = std::lower_bound(first, last, hi,
                                                 [](const BucketSlot& a, int32_t x) { return a.other < x; });
        if (hit == last || hit->other != hi)
            throw Error("invalid-edge-list", label + ": " + vertex_label(s) + "-" + vertex_label(t) +
                        " is not an edge of any face");
        int32_t& slot = renumber[edge_of[hit->code >> 1]];
        if (slot != kNone)
            throw Error("invalid-edge-list", label + " repeats " + edge_label(slot) + " (" + vertex_label(s) + "-" +
                        vertex_label(t) + ")");
        slot = i;
        edges[i].start = s;
        edges[i].end = t;
    }
    for (int32_t& e : edge_of) e = renumber[e];
}

// Phase 5, the edge table's L and R columns and the four wings from each face's previous
// and next corner: L traverses S->E, R traverses E->S. Also the face table (each face's
// first side).
void fill_face_wings(const IndexedMesh& mesh, const std::vector<int32_t>& edge_of, std::vector<EdgeRecord>& edges,
                     std::vector<int32_t>& face_edge) {
    const std::vector<int32_t>& fo = mesh.face_offsets;
    const std::vector<int32_t>& fv = mesh.face_vertices;
    for (int32_t f = 0; f < mesh.face_count(); ++f) {
        const int32_t o = fo[f], last = fo[f + 1] - 1;
        const int32_t first = edge_of[o];
        face_edge[f] = first; // default face edge: the face's first side (corner 1 -> 2)
        int32_t prev = edge_of[last], e = first;
        for (int32_t h = o; h <= last; ++h) {
            const int32_t next = h == last ? first : edge_of[h + 1];
            EdgeRecord& r = edges[e];
            if (r.start == fv[h]) {
                r.left = f;
                r.start_left = prev;
                r.end_left = next;
            } else {
                r.right = f;
                r.start_right = next;
                r.end_right = prev;
            }
            prev = e;
            e = next;
        }
    }
}

// Phase 6, the boundary wings: a side that no face claims is a boundary, and the lecture
// defines its wings "as though the boundary was also a face". boundary_in[v] (the vertex
// table's default edge) and boundary_out[v] are the boundary edges arriving at and leaving
// v; a second one at the same vertex is a bow-tie.
void fill_boundary_wings(const IndexedMesh& mesh, std::vector<EdgeRecord>& edges, std::vector<int32_t>& boundary_in,
                         std::vector<int32_t>& boundary_out) {
    const int32_t E = static_cast<int32_t>(edges.size());
    for (int32_t e = 0; e < E; ++e) {
        const EdgeRecord& r = edges[e];
        if (r.left != kNone && r.right != kNone) continue;
        // The boundary half-edge runs opposite to the face's: S->E when L is missing.
        const int32_t from = r.left == kNone ? r.start : r.end;
        const int32_t to = r.left == kNone ? r.end : r.start;
        if (boundary_out[from] != kNone || boundary_in[to] != kNone) refuse(mesh); // two boundary gaps: bow-tie
        boundary_out[from] = e;
        boundary_in[to] = e;
    }
    for (int32_t e = 0; e < E; ++e) {
        EdgeRecord& r = edges[e];
        if (r.left == kNone) {
            r.start_left = boundary_in[r.start];
            r.end_left = boundary_out[r.end];
        } else if (r.right == kNone) {
            r.start_right = boundary_out[r.start];
            r.end_right = boundary_in[r.end];
        }
    }
}

// Phase 7, the vertex table's edge column: after the boundary gap (already in place),
// else the lowest-numbered incident edge. Also counts each vertex's degree.
void choose_vertex_edges(const std::vector<EdgeRecord>& edges, std::vector<int32_t>& vertex_edge,
                         std::vector<int32_t>& degree) {
    std::fill(degree.begin(), degree.end(), 0);
    for (int32_t e = 0; e < static_cast<int32_t>(edges.size()); ++e) {
        const EdgeRecord& r = edges[e];
        ++degree[r.start];
        ++degree[r.end];
        if (vertex_edge[r.start] == kNone) vertex_edge[r.start] = e;
        if (vertex_edge[r.end] == kNone) vertex_edge[r.end] = e;
    }
}

// Phase 8, manifoldness at the vertices: one fan per vertex, so the lecture's CCW walk
// must meet every incident edge (else a bow-tie).
void check_one_fan_per_vertex(const IndexedMesh& mesh, const WingedEdgeMesh& m, const std::vector<int32_t>& degree) {
    for (int32_t v = 0; v < m.vertex_count(); ++v) {
        const int32_t first = m.vertex_edge(v);
        if (first == kNone) continue;
        int32_t e = first, steps = 0;
        do {
            e = m.next_ccw(e, v);
            ++steps;
        } while (e != first && steps <= degree[v]);
        if (steps != degree[v]) refuse(mesh);
    }
}

// Phase 9, no two faces on exactly the same edges (a pillow of duplicates), by the
// lecture's walk along each face.
void check_no_duplicate_faces(const IndexedMesh& mesh, const WingedEdgeMesh& m) {
    const std::vector<int32_t>& fo = mesh.face_offsets;
    for (int32_t f = 0; f < m.face_count(); ++f) {
        const EdgeRecord& r0 = m.edge(m.face_edge(f));
        const int32_t g = r0.left == f ? r0.right : r0.left;
        if (g == kNone || fo[g + 1] - fo[g] != fo[f + 1] - fo[f]) continue;
        bool all_shared = true;
        int32_t e = m.face_edge(f);
        do {
            const EdgeRecord& r = m.edge(e);
            if ((r.left == f ? r.right : r.left) != g) all_shared = false;
            e = m.next_in_face(e, f);
        } while (all_shared && e != m.face_edge(f));
        if (all_shared) refuse(mesh);
    }
}

// Phase 10, the caller's vertex edges (BuildOptions::vertex_edges, e.g. the slide's
// vertex table): each must touch its vertex; an isolated vertex keeps kNone.
void apply_vertex_edges(const BuildOptions& options, const std::vector<EdgeRecord>& edges,
                        const std::vector<int32_t>& degree, std::vector<int32_t>& vertex_edge) {
    const int32_t V = static_cast<int32_t>(vertex_edge.size()), E = static_cast<int32_t>(edges.size());
    if (static_cast<int32_t>(options.vertex_edges.size()) != V)
        throw Error("invalid-vertex-edge", "vertexEdges has " + std::to_string(options.vertex_edges.size()) +
                    " entries but the mesh has " + std::to_string(V) + " vertices");
    for (int32_t v = 0; v < V; ++v) {
        const int32_t e = options.vertex_edges[v];
        const bool isolated = degree[v] == 0;
        const bool ok = isolated ? e == kNone
                                 : (e >= 0 && e < E && (edges[e].start == v || edges[e].end == v));
        if (!ok)
            throw Error("invalid-vertex-edge", "vertexEdges gives " + edge_or_none(e) + " for " + vertex_label(v) + ", but " +
                        (isolated    ? vertex_label(v) + " belongs to no face, so it has no edge (-1)"
                         : e < 0     ? vertex_label(v) + " is a corner of a face, so it stores one of its edges"
                         : e < E     ? "that edge does not touch " + vertex_label(v)
                                     : missing_element_message(MeshTable::Edge, e, E)));
        vertex_edge[v] = e;
    }
}

// Phase 11, the caller's face edges (BuildOptions::face_edges, e.g. the slide's face
// table): each must be a side of its face.
void apply_face_edges(const BuildOptions& options, const std::vector<EdgeRecord>& edges, std::vector<int32_t>& face_edge) {
    const int32_t F = static_cast<int32_t>(face_edge.size()), E = static_cast<int32_t>(edges.size());
    if (static_cast<int32_t>(options.face_edges.size()) != F)
        throw Error("invalid-face-edge", "faceEdges has " + std::to_string(options.face_edges.size()) +
                    " entries but the mesh has " + std::to_string(F) + " faces");
    for (int32_t f = 0; f < F; ++f) {
        const int32_t e = options.face_edges[f];
        if (e < 0 || e >= E || (edges[e].left != f && edges[e].right != f))
            throw Error("invalid-face-edge", "faceEdges gives " + edge_or_none(e) + " for " + face_label(f) + ", but " +
                        (e >= 0 && e < E ? "that edge is not a side of " + face_label(f) : missing_element_message(MeshTable::Edge, e, E)));
        face_edge[f] = e;
    }
}

} // namespace

namespace detail {

bool face_corners_ok(const int32_t* corners, int32_t n, int32_t V) {
    if (n < 3 || n > kMaxFaceCorners) return false;
    for (int32_t i = 0; i < n; ++i)
        if (corners[i] < 0 || corners[i] >= V) return false;
    return corners_distinct(corners, n);
}

} // namespace detail

WingedEdgeMesh WingedEdgeMesh::build(const IndexedMesh& mesh, const BuildOptions& options) {
    return build_impl(mesh, options, nullptr, true);
}

WingedEdgeMesh WingedEdgeMesh::build(IndexedMesh&& mesh, const BuildOptions& options) {
    return build_impl(mesh, options, &mesh.positions, true);
}

WingedEdgeMesh WingedEdgeMesh::build_reference(const IndexedMesh& mesh, const BuildOptions& options) {
    return build_impl(mesh, options, nullptr, false);
}

WingedEdgeMesh WingedEdgeMesh::build_impl(const IndexedMesh& mesh, const BuildOptions& options,
                                          std::vector<double>* positions_to_take, bool fast_kernels) {
    WingedEdgeBuild build(&mesh, &options, positions_to_take, fast_kernels);
    while (!build.step()) {
    }
    return build.take();
}

// ------------------------------------------------------------------ the build, phase by phase

struct WingedEdgeBuild::State {
    IndexedMesh owned;                 // the face set, when the build owns it (WingedEdgeBuild(mesh))
    BuildOptions owned_options;
    const IndexedMesh* mesh = nullptr; // what is built from
    const BuildOptions* options = nullptr;
    std::vector<double>* positions_to_take = nullptr;
    bool fast = true;
    int phase = 0;
    int32_t V = 0, F = 0, H = 0, pairs = 0;
    std::vector<int32_t> bucket_end;
    std::unique_ptr<BucketSlot[]> slots;
    std::vector<int32_t> edge_of;
    std::vector<int32_t> scratch;
    WingedEdgeMesh m;
};

namespace {
const char* const kBuildPhases[] = {"counting sides",  "bucketing sides", "pairing twins", "numbering edges",
                                    "face wings",      "boundary wings",  "checks",        "stored edges",
                                    "done"};
} // namespace

WingedEdgeBuild::WingedEdgeBuild(IndexedMesh mesh, BuildOptions options) : s_(std::make_unique<State>()) {
    s_->owned = std::move(mesh);
    s_->owned_options = std::move(options);
    s_->mesh = &s_->owned;
    s_->options = &s_->owned_options;
    s_->positions_to_take = &s_->owned.positions;
}

WingedEdgeBuild::WingedEdgeBuild(const IndexedMesh* mesh, const BuildOptions* options, std::vector<double>* positions_to_take,
                                 bool fast)
    : s_(std::make_unique<State>()) {
    s_->mesh = mesh;
    s_->options = options;
    s_->positions_to_take = positions_to_take;
    s_->fast = fast;
}

WingedEdgeBuild::~WingedEdgeBuild() = default;
WingedEdgeBuild::WingedEdgeBuild(WingedEdgeBuild&&) noexcept = default;
WingedEdgeBuild& WingedEdgeBuild::operator=(WingedEdgeBuild&&) noexcept = default;

const char* WingedEdgeBuild::phase() const { return kBuildPhases[s_ ? std::min(s_->phase, 8) : 8]; }

bool WingedEdgeBuild::step() {
    if (!s_) throw Error("invalid-argument", "this build is over (its mesh was taken, or it was refused)");
    State& st = *s_;
    const IndexedMesh& mesh = *st.mesh;
    const BuildOptions& options = *st.options;
    WingedEdgeMesh& m = st.m;
    try {
        switch (st.phase) {
        case 0: {
            // Phase 1: count the sides per lower vertex (CSR offsets).
            st.V = mesh.vertex_count();
            st.F = mesh.face_count();
            check_positions(mesh);
            st.H = mesh.face_offsets[st.F];
            st.bucket_end.assign(static_cast<std::size_t>(st.V) + 1, 0);
            if (!(st.fast ? detail::count_sides_fast(mesh, st.bucket_end.data() + 1) : count_sides(mesh, st.bucket_end.data() + 1)))
                refuse(mesh);
            for (int32_t v = 0; v < st.V; ++v) st.bucket_end[v + 1] += st.bucket_end[v];
            break;
        }
        case 1:
            // Phase 2: bucket them. Now bucket v is [bucket_end[v-1], bucket_end[v]) (bucket_end[-1] = 0).
            st.slots.reset(new BucketSlot[st.H]); // every slot is written below
            if (st.fast)
                detail::bucket_sides_fast(mesh, st.bucket_end.data(), st.slots.get());
            else
                bucket_sides(mesh, st.bucket_end.data(), st.slots.get());
            break;
        case 2:
            st.edge_of.assign(st.H, kNone); // first each half-edge's twin, then its edge
            st.pairs = pair_twins(mesh, st.bucket_end, st.slots.get(), st.edge_of);
            break;
        case 3:
            m.edges_.resize(st.H - st.pairs);
            m.vertex_edge_.assign(st.V, kNone);
            m.face_edge_.assign(st.F, kNone);
            number_edges(mesh, st.edge_of, m.edges_);
            if (!options.edges.empty()) apply_edge_list(options, st.V, st.bucket_end, st.slots.get(), st.edge_of, m.edges_);
            st.slots.reset();
            st.bucket_end = std::vector<int32_t>();
            break;
        case 4:
            fill_face_wings(mesh, st.edge_of, m.edges_, m.face_edge_);
            st.edge_of = std::vector<int32_t>();
            break;
        case 5:
            st.scratch.assign(st.V, kNone); // the boundary edge leaving each vertex, then its degree
            fill_boundary_wings(mesh, m.edges_, m.vertex_edge_, st.scratch);
            choose_vertex_edges(m.edges_, m.vertex_edge_, st.scratch);
            break;
        case 6:
            check_one_fan_per_vertex(mesh, m, st.scratch);
            check_no_duplicate_faces(mesh, m);
            break;
        case 7: {
            if (!options.vertex_edges.empty()) apply_vertex_edges(options, m.edges_, st.scratch, m.vertex_edge_);
            if (!options.face_edges.empty()) {
                apply_face_edges(options, m.edges_, m.face_edge_);
                // face_set() lists each face from its first corner as given, wherever its walk now starts.
                const int32_t* fo = mesh.face_offsets.data();
                const int32_t* fv = mesh.face_vertices.data();
                for (int32_t f = 0; f < st.F; ++f)
                    if (m.walk_start_corner(f) != fv[fo[f]]) {
                        m.face_first_corner_.resize(st.F);
                        for (int32_t g = 0; g < st.F; ++g) m.face_first_corner_[g] = fv[fo[g]];
                        break;
                    }
            }
            st.scratch = std::vector<int32_t>();
            // Last, so that every refusal above still sees the caller's positions.
            if (st.positions_to_take)
                m.positions_ = std::move(*st.positions_to_take);
            else
                m.positions_ = mesh.positions;
            break;
        }
        default:
            return true;
        }
    } catch (...) {
        s_.reset(); // a refused build is over
        throw;
    }
    ++st.phase;
    return st.phase == 8;
}

WingedEdgeMesh WingedEdgeBuild::take() {
    if (!s_ || s_->phase < 8) throw Error("invalid-argument", "the mesh is not built yet: call step() until it returns true");
    WingedEdgeMesh m = std::move(s_->m);
    s_.reset();
    return m;
}

void WingedEdgeMesh::set_position(int32_t v, const glm::dvec3& p) {
    // The same bound as building (limits.h): a vertex moved to 1e300 would give NaN normals
    // and a state the page cannot reload. Refused before anything changes.
    for (int k = 0; k < 3; ++k) {
        const double c = p[k];
        const std::string where = vertex_label(v) + " cannot move to " + "xyz"[k] + " = ";
        if (!std::isfinite(c))
            throw Error("non-finite-coordinate", where + std::to_string(c) + ": a coordinate must be a finite number");
        if (std::abs(c) > kMaxCoordinate) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%g", c);
            throw Error("coordinate-out-of-range", where + buf + ": coordinates are limited to 1e9 in size");
        }
    }
    if (positions_[3 * v] == p.x && positions_[3 * v + 1] == p.y && positions_[3 * v + 2] == p.z) return;
    positions_[3 * v] = p.x;
    positions_[3 * v + 1] = p.y;
    positions_[3 * v + 2] = p.z;
    version_.geometry = ++used_.geometry;
}

// ------------------------------------------------------------------ the change model

const char* table_name(MeshTable t) {
    switch (t) {
    case MeshTable::Vertex: return "vertex";
    case MeshTable::Edge: return "edge";
    case MeshTable::Face: return "face";
    }
    return "unknown";
}

std::string element_label(MeshTable t, int32_t i) {
    return t == MeshTable::Vertex ? vertex_label(i) : t == MeshTable::Edge ? edge_label(i) : face_label(i);
}

std::string missing_element_message(MeshTable t, int32_t index, int32_t count) {
    const std::string has = t == MeshTable::Vertex ? elements_text(&vertex_label, "vertices", count)
                            : t == MeshTable::Edge ? elements_text(&edge_label, "edges", count)
                                                   : elements_text(&face_label, "faces", count);
    if (index < 0) return std::to_string(index) + " names no " + table_name(t) + (index == kNone ? " (it stands for none)" : "") + ": the mesh has " + has;
    return "there is no " + element_label(t, index) + ": the mesh has " + has;
}

std::string removed_element_message(MeshTable t, int32_t index) {
    return element_label(t, index) + " was removed by an edit (its number stays a gap until the mesh is compacted)";
}


CheckResult WingedEdgeMesh::check_element(Vertex v) const {
    if (v.idx < 0 || v.idx >= vertex_count())
        return CheckResult::refuse("invalid-element", missing_element_message(MeshTable::Vertex, v.idx, vertex_count()));
    if (is_deleted(v)) return CheckResult::refuse("deleted-element", removed_element_message(MeshTable::Vertex, v.idx));
    return CheckResult::accept();
}
CheckResult WingedEdgeMesh::check_element(Edge e) const {
    if (e.idx < 0 || e.idx >= edge_count())
        return CheckResult::refuse("invalid-element", missing_element_message(MeshTable::Edge, e.idx, edge_count()));
    if (is_deleted(e)) return CheckResult::refuse("deleted-element", removed_element_message(MeshTable::Edge, e.idx));
    return CheckResult::accept();
}
CheckResult WingedEdgeMesh::check_element(Face f) const {
    if (f.idx < 0 || f.idx >= face_count())
        return CheckResult::refuse("invalid-element", missing_element_message(MeshTable::Face, f.idx, face_count()));
    if (is_deleted(f)) return CheckResult::refuse("deleted-element", removed_element_message(MeshTable::Face, f.idx));
    return CheckResult::accept();
}

Renumbering WingedEdgeMesh::compact() {
    Renumbering map;
    const auto number = [](const std::vector<char>& marks, int32_t n, std::vector<int32_t>& to) {
        to.assign(n, kNone);
        int32_t next = 0;
        for (int32_t i = 0; i < n; ++i)
            if (marks.empty() || !marks[i]) to[i] = next++;
        return next;
    };
    const int32_t V = number(vertex_deleted_, vertex_count(), map.vertices);
    const int32_t E = number(edge_deleted_, edge_count(), map.edges);
    const int32_t F = number(face_deleted_, face_count(), map.faces);
    if (!has_garbage()) return map;
    const auto at = [](const std::vector<int32_t>& to, int32_t i) { return i == kNone ? kNone : to[i]; };
    for (int32_t v = 0; v < vertex_count(); ++v) {
        const int32_t to = map.vertices[v];
        if (to == kNone) continue;
        for (int k = 0; k < 3; ++k) positions_[3 * to + k] = positions_[3 * v + k];
        vertex_edge_[to] = at(map.edges, vertex_edge_[v]);
    }
    for (int32_t e = 0; e < edge_count(); ++e) {
        const int32_t to = map.edges[e];
        if (to == kNone) continue;
        EdgeRecord r = edges_[e];
        r.start = map.vertices[r.start], r.end = map.vertices[r.end];
        r.left = at(map.faces, r.left), r.right = at(map.faces, r.right);
        r.start_left = map.edges[r.start_left], r.start_right = map.edges[r.start_right];
        r.end_left = map.edges[r.end_left], r.end_right = map.edges[r.end_right];
        edges_[to] = r;
    }
    for (int32_t f = 0; f < face_count(); ++f) {
        const int32_t to = map.faces[f];
        if (to == kNone) continue;
        face_edge_[to] = map.edges[face_edge_[f]];
        if (!face_first_corner_.empty()) face_first_corner_[to] = map.vertices[face_first_corner_[f]];
    }
    positions_.resize(3 * static_cast<std::size_t>(V));
    vertex_edge_.resize(V);
    edges_.resize(E);
    face_edge_.resize(F);
    if (!face_first_corner_.empty()) face_first_corner_.resize(F);
    if (!vertex_deleted_.empty()) version_.geometry = ++used_.geometry; // the positions moved up
    vertex_deleted_.clear(), edge_deleted_.clear(), face_deleted_.clear();
    deleted_count_ = {};
    version_.topology = ++used_.topology;
    return map;
}

std::vector<int32_t> WingedEdgeMesh::edges_around_vertex(int32_t v) const {
    std::vector<int32_t> out;
    const int32_t first = vertex_edge_[v];
    if (first == kNone) return out;
    int32_t e = first;
    do {
        out.push_back(e);
        e = next_ccw(e, v);
    } while (e != first && out.size() <= edges_.size());
    return out;
}

std::vector<TraversalStep> WingedEdgeMesh::traversal_steps(int32_t v) const {
    std::vector<TraversalStep> out;
    for (int32_t e : edges_around_vertex(v)) out.push_back({e, edges_[e].start == v, next_ccw(e, v)});
    return out;
}

std::vector<int32_t> WingedEdgeMesh::faces_around_vertex(int32_t v) const {
    std::vector<int32_t> out;
    for (int32_t e : edges_around_vertex(v)) {
        // Turning CCW from e at its Start sweeps L; at its End it sweeps R.
        const int32_t f = edges_[e].start == v ? edges_[e].left : edges_[e].right;
        if (f != kNone) out.push_back(f);
    }
    return out;
}

std::vector<int32_t> WingedEdgeMesh::vertices_around_vertex(int32_t v) const {
    std::vector<int32_t> out;
    for (int32_t e : edges_around_vertex(v)) out.push_back(other_vertex(e, v));
    return out;
}

std::vector<int32_t> WingedEdgeMesh::edges_of_face(int32_t f) const {
    std::vector<int32_t> out;
    const int32_t first = face_edge_[f];
    int32_t e = first;
    do {
        out.push_back(e);
        e = next_in_face(e, f);
    } while (e != first && out.size() <= edges_.size());
    return out;
}

std::vector<FaceStep> WingedEdgeMesh::face_edge_steps(int32_t f) const {
    std::vector<FaceStep> out;
    for (int32_t e : edges_of_face(f)) out.push_back({e, edges_[e].left == f, next_in_face(e, f)});
    return out;
}

std::vector<int32_t> WingedEdgeMesh::vertices_of_face(int32_t f) const {
    std::vector<int32_t> out;
    for (int32_t e : edges_of_face(f)) out.push_back(edges_[e].left == f ? edges_[e].start : edges_[e].end);
    return out;
}

void keep_first_appearance(std::vector<int32_t>& v) {
    std::vector<int32_t> seen(v);
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    std::vector<char> taken(seen.size(), 0);
    std::size_t out = 0;
    for (int32_t x : v) {
        const auto i = static_cast<std::size_t>(std::lower_bound(seen.begin(), seen.end(), x) - seen.begin());
        if (!taken[i]) taken[i] = 1, v[out++] = x;
    }
    v.resize(out);
}

std::vector<int32_t> WingedEdgeMesh::face_neighbours(int32_t f) const {
    // Distinct faces in the order the walk first meets them: a face across two of f's
    // edges is one neighbour (a set, docs/api-mesh.md).
    std::vector<int32_t> out;
    for (int32_t e : edges_of_face(f)) {
        const int32_t g = edges_[e].left == f ? edges_[e].right : edges_[e].left;
        if (g != kNone) out.push_back(g);
    }
    keep_first_appearance(out);
    return out;
}

IndexedMesh WingedEdgeMesh::face_set() const {
    IndexedMesh out;
    out.positions = positions_;
    out.face_offsets.reserve(face_edge_.size() + 1);
    out.face_vertices.reserve(2 * edges_.size()); // sides of all faces <= 2E
    for (int32_t f = 0; f < face_count(); ++f) {
        const std::vector<int32_t> corners = face_corners(f);
        out.face_vertices.insert(out.face_vertices.end(), corners.begin(), corners.end());
        out.face_offsets.push_back(static_cast<int32_t>(out.face_vertices.size()));
    }
    return out;
}

std::vector<int32_t> WingedEdgeMesh::face_corners(int32_t f) const {
    if (is_deleted(Face(f))) return {}; // a gap left by an edit: a face with no corners, so numbers stay
    std::vector<int32_t> corners = vertices_of_face(f);
    if (!face_first_corner_.empty())
        std::rotate(corners.begin(), std::find(corners.begin(), corners.end(), face_first_corner_[f]), corners.end());
    return corners;
}

IndexedMesh WingedEdgeMesh::live_face_set() const {
    IndexedMesh all = face_set();
    if (!has_garbage()) return all;
    std::vector<int32_t> to(vertex_count(), kNone);
    IndexedMesh out;
    for (int32_t v = 0; v < vertex_count(); ++v)
        if (!is_deleted(Vertex(v))) to[v] = out.add_vertex(positions_[3 * v], positions_[3 * v + 1], positions_[3 * v + 2]);
    for (int32_t f = 0; f < all.face_count(); ++f) {
        if (all.face_size(f) == 0) continue;
        for (int32_t i = 0; i < all.face_size(f); ++i) out.face_vertices.push_back(to[all.corner(f, i)]);
        out.face_offsets.push_back(static_cast<int32_t>(out.face_vertices.size()));
    }
    return out;
}

MeshCounts WingedEdgeMesh::counts() const {
    // Gaps left by edits (is_deleted) are not counted.
    MeshCounts c;
    const auto live = [](const std::vector<char>& marks, int32_t n) {
        return n - static_cast<int32_t>(std::count(marks.begin(), marks.end(), 1));
    };
    c.vertices = live(vertex_deleted_, vertex_count());
    c.edges = live(edge_deleted_, edge_count());
    c.faces = live(face_deleted_, face_count());
    for (int32_t v = 0; v < vertex_count(); ++v) c.isolated_vertices += vertex_edge_[v] == kNone && !is_deleted(Vertex(v));
    std::vector<char> seen(edges_.size(), 0);
    for (int32_t e = 0; e < edge_count(); ++e) {
        if (is_deleted(Edge(e))) continue;
        const EdgeRecord& r = edges_[e];
        if (r.left != kNone && r.right != kNone) continue;
        ++c.boundary_edges;
        if (seen[e]) continue;
        ++c.boundary_loops;
        // Walk the boundary loop as though it were a face.
        int32_t b = e;
        for (int32_t guard = 0; !seen[b] && guard <= edge_count(); ++guard) {
            seen[b] = 1;
            b = edges_[b].left == kNone ? edges_[b].end_left : edges_[b].start_right;
        }
    }
    return c;
}

std::size_t WingedEdgeMesh::bytes() const {
    return positions_.capacity() * sizeof(double) + vertex_edge_.capacity() * sizeof(int32_t) +
           edges_.capacity() * sizeof(EdgeRecord) + face_edge_.capacity() * sizeof(int32_t);
}

ValidationReport WingedEdgeMesh::validate() const {
    ValidationReport report;
    auto add = [&](const char* code, std::string message, std::vector<int32_t> vs, std::vector<int32_t> es,
                   std::vector<int32_t> fs) {
        Problem p;
        p.code = code;
        p.message = std::move(message);
        p.vertices = std::move(vs);
        p.edges = std::move(es);
        p.faces = std::move(fs);
        report.problems.push_back(std::move(p));
    };
    // Gaps left by edits (is_deleted) are skipped, and a live row referring to one is an error.
    const int32_t V = vertex_count(), E = edge_count(), F = face_count();
    auto edge_ok = [&](int32_t e) { return e >= 0 && e < E && !is_deleted(Edge(e)); };
    auto face_ok = [&](int32_t f) { return f == kNone || (f >= 0 && f < F && !is_deleted(Face(f))); };
    auto vertex_ok = [&](int32_t v) { return v >= 0 && v < V && !is_deleted(Vertex(v)); };
    auto touches = [&](int32_t e, int32_t v) { return edges_[e].start == v || edges_[e].end == v; };
    bool references_ok = true;
    for (int32_t e = 0; e < E; ++e) {
        if (is_deleted(Edge(e))) continue;
        const EdgeRecord& r = edges_[e];
        const bool ok = vertex_ok(r.start) && vertex_ok(r.end) && r.start != r.end &&
                        face_ok(r.left) && face_ok(r.right) && edge_ok(r.start_left) && edge_ok(r.start_right) &&
                        edge_ok(r.end_left) && edge_ok(r.end_right);
        if (!ok) {
            references_ok = false;
            add("invalid-reference", edge_label(e) + " refers to a vertex, face or edge that does not exist", {}, {e}, {});
            continue;
        }
        if (r.left == kNone && r.right == kNone)
            add("edge-without-face", edge_label(e) + " has neither a left nor a right face", {}, {e}, {});
        const int32_t wings[4] = {r.start_left, r.start_right, r.end_left, r.end_right};
        const int32_t at[4] = {r.start, r.start, r.end, r.end};
        const char* names[4] = {"start-left", "start-right", "end-left", "end-right"};
        for (int k = 0; k < 4; ++k) {
            const int32_t w = wings[k];
            const int32_t side = k % 2 == 0 ? r.left : r.right;
            const EdgeRecord& q = edges_[w];
            const bool shares_face = side == kNone ? (q.left == kNone || q.right == kNone) : (q.left == side || q.right == side);
            if (w == e || !touches(w, at[k]) || !shares_face)
                add("wing-mismatch", edge_label(e) + "'s " + names[k] + " wing " + edge_label(w) + " is not the other edge of the " +
                    (side == kNone ? std::string("boundary") : face_label(side)) + " at " + vertex_label(at[k]), {at[k]}, {e, w},
                    side == kNone ? std::vector<int32_t>{} : std::vector<int32_t>{side});
        }
    }
    for (int32_t f = 0; f < F; ++f)
        if (!is_deleted(Face(f)) && (!edge_ok(face_edge_[f]) || (edges_[face_edge_[f]].left != f && edges_[face_edge_[f]].right != f))) {
            references_ok = false;
            add("face-edge-not-incident", face_label(f) + "'s edge is not one of its sides", {}, {}, {f});
        }
    for (int32_t v = 0; v < V; ++v) {
        const int32_t e = vertex_edge_[v];
        if (is_deleted(Vertex(v))) continue;
        if (e == kNone) {
            Problem p;
            p.code = "isolated-vertex";
            p.severity = Severity::Warning;
            p.message = vertex_label(v) + " belongs to no face; it is kept with no edge (edge = -1)";
            p.vertices = {v};
            report.problems.push_back(std::move(p));
        } else if (!edge_ok(e) || !touches(e, v)) {
            references_ok = false;
            add("vertex-edge-not-incident", vertex_label(v) + "'s edge does not touch " + vertex_label(v), {v}, {}, {});
        }
    }
    if (!references_ok) return report;

    std::vector<int32_t> degree(V, 0);
    std::size_t sides = 0;
    for (int32_t e = 0; e < E; ++e) {
        if (is_deleted(Edge(e))) continue;
        const EdgeRecord& r = edges_[e];
        ++degree[r.start];
        ++degree[r.end];
        sides += (r.left != kNone) + (r.right != kNone);
    }
    for (int32_t v = 0; v < V; ++v) {
        const int32_t first = vertex_edge_[v];
        if (first == kNone || is_deleted(Vertex(v))) continue;
        int32_t e = first, steps = 0;
        bool ok = true;
        do {
            if (!touches(e, v)) { ok = false; break; }
            e = next_ccw(e, v);
            ++steps;
        } while (e != first && steps <= degree[v]);
        if (!ok || steps != degree[v])
            add("open-vertex-ring", "walking counter-clockwise around " + vertex_label(v) + " does not meet each of its " +
                std::to_string(degree[v]) + " edges exactly once before returning to " + edge_label(first), {v}, {first}, {});
    }
    std::size_t walked = 0;
    for (int32_t f = 0; f < F; ++f) {
        if (is_deleted(Face(f))) continue;
        const int32_t first = face_edge_[f];
        int32_t e = first, steps = 0;
        bool ok = true;
        do {
            const EdgeRecord& r = edges_[e];
            if (r.left != f && r.right != f) { ok = false; break; }
            const int32_t n = next_in_face(e, f);
            // Consecutive edges of a face meet at the vertex where this one ends (for f).
            const int32_t head = r.left == f ? r.end : r.start;
            if (!touches(n, head)) { ok = false; break; }
            e = n;
            ++steps;
        } while (e != first && steps <= E);
        walked += steps;
        if (!ok || e != first)
            add("open-face-loop", "walking the edges of " + face_label(f) + " from " + edge_label(first) +
                " does not come back around the face", {}, {first}, {f});
    }
    for (int32_t f = 0; f < static_cast<int32_t>(face_first_corner_.size()) && f < F; ++f) {
        if (is_deleted(Face(f))) continue;
        const std::vector<int32_t> corners = vertices_of_face(f);
        if (std::find(corners.begin(), corners.end(), face_first_corner_[f]) == corners.end())
            add("face-first-corner-not-on-face", face_label(f) + " is listed from " + vertex_label(face_first_corner_[f]) +
                ", which is not one of its corners", {face_first_corner_[f]}, {}, {f});
    }
    if (walked != sides)
        add("open-face-loop", "the face loops cover " + std::to_string(walked) + " edge sides but the edge table names " +
            std::to_string(sides), {}, {}, {});
    return report;
}

} // namespace wingspline::mesh
