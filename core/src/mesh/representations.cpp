// Building lecture 000's and 001's other representations from one indexed face set.
// Everything is counted from the face set's corners; the winged edge contributes only the
// edge numbering (which edge is e1, e2, ...) and the current vertex positions.
#include "wingspline/mesh/representations.h"

#include <algorithm>

namespace wingspline::mesh {

namespace {

template <class T> ArrayStorage array_storage(const char* name, const std::vector<T>& v) {
    return {name, v.size(), sizeof(T)};
}

// CSR offsets from per-element counts: offsets[i+1] - offsets[i] = counts[i].
std::vector<int32_t> offsets_from_counts(const std::vector<int32_t>& counts) {
    std::vector<int32_t> offsets(counts.size() + 1, 0);
    for (std::size_t i = 0; i < counts.size(); ++i) offsets[i + 1] = offsets[i] + counts[i];
    return offsets;
}

// The shared edge number of every corner's outgoing side, matched against the winged
// edge's face loops; anything that does not match means `faces` is another face set.
std::vector<int32_t> name_corner_edges(const IndexedMesh& faces, const WingedEdgeMesh& w) {
    auto mismatch = [](int32_t f) {
        throw Error("mismatched-face-set", face_label(f) + " of the face set is not a face of the winged-edge mesh "
                                           "(the representations must be built from the faces the mesh was built from)");
    };
    if (faces.face_count() != w.face_count() || faces.vertex_count() != w.vertex_count()) mismatch(0);
    std::vector<int32_t> names(faces.face_vertices.size(), kNone);
    for (int32_t f = 0; f < faces.face_count(); ++f) {
        if (w.is_deleted(Face(f))) { // a gap left by an edit: listed with no corners
            if (faces.face_size(f) != 0) mismatch(f);
            continue;
        }
        const std::vector<int32_t> loop = w.edges_of_face(f);
        const std::vector<int32_t> ring = w.vertices_of_face(f); // ring[i] starts loop[i]
        const int32_t n = faces.face_size(f);
        if (static_cast<int32_t>(ring.size()) != n) mismatch(f);
        const int32_t r = static_cast<int32_t>(std::find(ring.begin(), ring.end(), faces.corner(f, 0)) - ring.begin());
        if (r == n) mismatch(f);
        for (int32_t i = 0; i < n; ++i) {
            if (ring[(r + i) % n] != faces.corner(f, i)) mismatch(f);
            names[faces.face_offsets[f] + i] = loop[(r + i) % n];
        }
    }
    return names;
}

} // namespace

std::size_t Storage::entries() const {
    std::size_t n = 0;
    for (const ArrayStorage& a : arrays) n += a.entries;
    return n;
}

std::size_t Storage::bytes() const {
    std::size_t n = 0;
    for (const ArrayStorage& a : arrays) n += a.entries * a.bytes_per_entry;
    return n;
}

Storage IndependentFaces::storage() const {
    return {{array_storage("face offsets", face_offsets), array_storage("corner coordinates", corner_positions)}};
}

Storage VertexFaceTables::storage() const {
    return {{array_storage("vertex coordinates", positions), array_storage("face offsets", face_offsets),
             array_storage("face vertices", face_vertices)}};
}

Storage AdjacencyLists::storage() const {
    return {{array_storage("vertex coordinates", positions), array_storage("vertex offsets", vertex_offsets),
             array_storage("vertex-vertex", vertex_vertices), array_storage("vertex-edge", vertex_edges),
             array_storage("vertex-face offsets", vertex_face_offsets), array_storage("vertex-face", vertex_faces),
             array_storage("edge-vertex", edge_vertices), array_storage("edge-edge offsets", edge_edge_offsets),
             array_storage("edge-edge", edge_edges), array_storage("edge-face", edge_faces),
             array_storage("face offsets", face_offsets), array_storage("face-vertex", face_vertices),
             array_storage("face-edge", face_edges), array_storage("face-face", face_faces)}};
}

Storage PartialAdjacencyLists::storage() const {
    return {{array_storage("vertex coordinates", positions), array_storage("vertex offsets", vertex_offsets),
             array_storage("vertex-edge", vertex_edges), array_storage("edge-vertex", edge_vertices),
             array_storage("edge-face", edge_faces), array_storage("face offsets", face_offsets),
             array_storage("face-edge", face_edges)}};
}

Storage EdgeList::storage() const {
    return {{array_storage("vertex list", positions), array_storage("edge list (V1 V2 P1 P2)", edges),
             array_storage("polygon offsets", polygon_offsets), array_storage("polygon edges", polygon_edges)}};
}

Storage winged_edge_storage(const WingedEdgeMesh& w) {
    const std::size_t V = w.vertex_count(), E = w.edge_count(), F = w.face_count();
    return {{{"vertex coordinates", 3 * V, sizeof(double)},
             {"vertex edge", V, sizeof(int32_t)},
             {"edge table (S E L R SL SR EL ER)", 8 * E, sizeof(int32_t)},
             {"face edge", F, sizeof(int32_t)}}};
}

const char* representation_key(Representation r) {
    switch (r) {
    case Representation::IndependentFaces: return "independent-faces";
    case Representation::VertexFaceTables: return "vertex-face-tables";
    case Representation::AdjacencyLists: return "adjacency-lists";
    case Representation::PartialAdjacencyLists: return "partial-adjacency-lists";
    case Representation::EdgeList: return "edge-list";
    case Representation::WingedEdge: return "winged-edge";
    }
    return "unknown";
}

Representations build_representations(const IndexedMesh& faces, const WingedEdgeMesh& w) {
    Representations reps;
    reps.corner_edge_names = name_corner_edges(faces, w);
    const std::vector<int32_t>& names = reps.corner_edge_names;
    const std::vector<double>& positions = w.positions();
    const std::vector<int32_t>& fo = faces.face_offsets;
    const std::vector<int32_t>& fv = faces.face_vertices;
    const int32_t V = w.vertex_count(), E = w.edge_count(), F = w.face_count();
    const int32_t C = static_cast<int32_t>(fv.size());

    IndependentFaces& ind = reps.independent_faces;
    ind.face_offsets = fo;
    ind.corner_positions.resize(3 * static_cast<std::size_t>(C));
    for (int32_t c = 0; c < C; ++c)
        for (int k = 0; k < 3; ++k) ind.corner_positions[3 * c + k] = positions[3 * fv[c] + k];

    reps.vertex_face_tables = {positions, fo, fv};

    // Edges from the face set: S, E of the numbering; L = the face that runs S->E.
    std::vector<int32_t> edge_vertices(2 * static_cast<std::size_t>(E), kNone), edge_faces(2 * static_cast<std::size_t>(E), kNone);
    // A gap left by an edit (a removed edge) keeps its row with kNone everywhere and is in
    // no vertex's list (docs/api-mesh.md, "Gaps").
    for (int32_t e = 0; e < E; ++e) {
        if (w.is_deleted(Edge(e))) continue;
        edge_vertices[2 * e] = w.edge(e).start;
        edge_vertices[2 * e + 1] = w.edge(e).end;
    }
    for (int32_t f = 0; f < F; ++f)
        for (int32_t c = fo[f]; c < fo[f + 1]; ++c) {
            const int32_t e = names[c];
            edge_faces[2 * e + (fv[c] == edge_vertices[2 * e] ? 0 : 1)] = f;
        }

    // VE / VV: each edge listed at both its ends, ascending edge number.
    std::vector<int32_t> degree(V, 0);
    for (int32_t e = 0; e < 2 * E; ++e)
        if (edge_vertices[e] != kNone) ++degree[edge_vertices[e]];
    std::vector<int32_t> vertex_offsets = offsets_from_counts(degree);
    const std::size_t listed = static_cast<std::size_t>(vertex_offsets.back());
    std::vector<int32_t> vertex_edges(listed), vertex_vertices(listed);
    {
        std::vector<int32_t> fill(vertex_offsets.begin(), vertex_offsets.end() - 1);
        for (int32_t e = 0; e < E; ++e)
            for (int end = 0; end < 2 && edge_vertices[2 * e] != kNone; ++end) {
                const int32_t v = edge_vertices[2 * e + end];
                vertex_edges[fill[v]] = e;
                vertex_vertices[fill[v]++] = edge_vertices[2 * e + 1 - end];
            }
    }

    AdjacencyLists& adj = reps.adjacency_lists;
    adj.positions = positions;
    adj.vertex_offsets = vertex_offsets;
    adj.vertex_vertices = std::move(vertex_vertices);
    adj.vertex_edges = vertex_edges;
    {
        std::vector<int32_t> corners_at(V, 0);
        for (int32_t v : fv) ++corners_at[v];
        adj.vertex_face_offsets = offsets_from_counts(corners_at);
        adj.vertex_faces.resize(C);
        std::vector<int32_t> fill(adj.vertex_face_offsets.begin(), adj.vertex_face_offsets.end() - 1);
        for (int32_t f = 0; f < F; ++f)
            for (int32_t c = fo[f]; c < fo[f + 1]; ++c) adj.vertex_faces[fill[fv[c]]++] = f;
    }
    adj.edge_vertices = edge_vertices;
    adj.edge_faces = edge_faces;
    adj.edge_edge_offsets.assign(1, 0);
    for (int32_t e = 0; e < E; ++e) {
        for (int end = 0; end < 2 && edge_vertices[2 * e] != kNone; ++end) {
            const int32_t v = edge_vertices[2 * e + end];
            for (int32_t i = vertex_offsets[v]; i < vertex_offsets[v + 1]; ++i)
                if (vertex_edges[i] != e) adj.edge_edges.push_back(vertex_edges[i]);
        }
        adj.edge_edge_offsets.push_back(static_cast<int32_t>(adj.edge_edges.size()));
    }
    adj.face_offsets = fo;
    adj.face_vertices = fv;
    adj.face_edges = names;
    adj.face_faces.resize(C);
    for (int32_t f = 0; f < F; ++f)
        for (int32_t c = fo[f]; c < fo[f + 1]; ++c) {
            const int32_t e = names[c];
            adj.face_faces[c] = edge_faces[2 * e] == f ? edge_faces[2 * e + 1] : edge_faces[2 * e];
        }

    PartialAdjacencyLists& part = reps.partial_adjacency_lists;
    part.positions = positions;
    part.vertex_offsets = std::move(vertex_offsets);
    part.vertex_edges = std::move(vertex_edges);
    part.edge_vertices = edge_vertices;
    part.edge_faces = edge_faces;
    part.face_offsets = fo;
    part.face_edges = names;

    EdgeList& list = reps.edge_list;
    list.positions = positions;
    list.edges.resize(4 * static_cast<std::size_t>(E));
    for (int32_t e = 0; e < E; ++e) {
        const int32_t a = edge_faces[2 * e], b = edge_faces[2 * e + 1];
        const int32_t p1 = a == kNone ? b : (b == kNone ? a : std::min(a, b));
        const int32_t p2 = (a == kNone || b == kNone) ? kNone : std::max(a, b);
        list.edges[4 * e] = edge_vertices[2 * e];
        list.edges[4 * e + 1] = edge_vertices[2 * e + 1];
        list.edges[4 * e + 2] = p1;
        list.edges[4 * e + 3] = p2;
    }
    list.polygon_offsets = fo;
    list.polygon_edges.resize(C);
    for (int32_t f = 0; f < F; ++f) {
        if (fo[f] == fo[f + 1]) continue; // a removed face
        const auto first = names.begin() + fo[f], last = names.begin() + fo[f + 1];
        std::rotate_copy(first, std::min_element(first, last), last, list.polygon_edges.begin() + fo[f]);
    }
    return reps;
}

std::array<Storage, kRepresentationCount> representation_storage(const Representations& reps,
                                                                  const WingedEdgeMesh& winged) {
    return {reps.independent_faces.storage(), reps.vertex_face_tables.storage(), reps.adjacency_lists.storage(),
            reps.partial_adjacency_lists.storage(), reps.edge_list.storage(), winged_edge_storage(winged)};
}

std::array<int32_t, kRepresentationCount - 1> set_vertex_position(Representations& reps, int32_t v,
                                                                  const glm::dvec3& p) {
    auto write = [&](double* xyz) {
        xyz[0] = p.x;
        xyz[1] = p.y;
        xyz[2] = p.z;
    };
    // Lecture 000: "changing a vertex requires changing the coordinates of each instance".
    int32_t copies = 0;
    const AdjacencyLists& adj = reps.adjacency_lists;
    const std::vector<int32_t>& fo = reps.vertex_face_tables.face_offsets;
    const std::vector<int32_t>& fv = reps.vertex_face_tables.face_vertices;
    for (int32_t i = adj.vertex_face_offsets[v]; i < adj.vertex_face_offsets[v + 1]; ++i) {
        const int32_t f = adj.vertex_faces[i];
        for (int32_t c = fo[f]; c < fo[f + 1]; ++c)
            if (fv[c] == v) {
                write(&reps.independent_faces.corner_positions[3 * c]);
                ++copies;
            }
    }
    // "...changing the coordinates of a single point" in every indexed representation.
    write(&reps.vertex_face_tables.positions[3 * v]);
    write(&reps.adjacency_lists.positions[3 * v]);
    write(&reps.partial_adjacency_lists.positions[3 * v]);
    write(&reps.edge_list.positions[3 * v]);
    return {copies, 1, 1, 1, 1};
}

const Representations& RepresentationCache::of(const WingedEdgeMesh& winged) {
    if (!reps_ || version_ != winged.version()) {
        reps_ = std::make_unique<Representations>(build_representations(winged.face_set(), winged));
        version_ = winged.version();
        ++derivations_;
    }
    return *reps_;
}

std::unique_ptr<Representations> RepresentationCache::take(const WingedEdgeMesh& winged) {
    of(winged);
    return std::move(reps_);
}

std::array<int32_t, kRepresentationCount - 1> RepresentationCache::follow_position(const WingedEdgeMesh& winged, int32_t v,
                                                                                   const glm::dvec3& p) {
    // Current in everything but this vertex's position: follow it in place. Otherwise (first
    // use, or the topology moved on) derive from the winged edge, which already holds p.
    // (Only this vertex: the geometry moved on by at most this one move.)
    const MeshVersion now = winged.version();
    const bool one_move = reps_ && version_.topology == now.topology && now.geometry - version_.geometry <= 1;
    if (!one_move) of(winged);
    const auto copies = set_vertex_position(*reps_, v, p);
    version_ = now;
    return copies;
}

} // namespace wingspline::mesh
