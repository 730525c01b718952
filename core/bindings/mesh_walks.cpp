// The winged edge read as the lecture walks it: adjacency around a vertex and along a face,
// the walks step by step, counts and validation.
#include "boundary.h"
#include "mesh_entry.h"

#include "wingspline/mesh/winged_edge.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// kind: edges-around-vertex, faces-around-vertex, vertices-around-vertex (v);
// edges-of-face, vertices-of-face, face-neighbours (f); faces-of-edge (e).
val mesh_adjacency(int32_t handle, const std::string& kind, int32_t element) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        std::vector<int32_t> out;
        if (kind == "edges-around-vertex" || kind == "faces-around-vertex" || kind == "vertices-around-vertex") {
            require_vertex(w, element);
            out = kind == "edges-around-vertex"   ? w.edges_around_vertex(element)
                  : kind == "faces-around-vertex" ? w.faces_around_vertex(element)
                                                  : w.vertices_around_vertex(element);
        } else if (kind == "edges-of-face" || kind == "vertices-of-face" || kind == "face-neighbours") {
            require_face(w, element);
            out = kind == "edges-of-face"      ? w.edges_of_face(element)
                  : kind == "vertices-of-face" ? w.vertices_of_face(element)
                                               : w.face_neighbours(element);
        } else if (kind == "faces-of-edge") {
            require_edge(w, element);
            const auto lr = w.faces_of_edge(element);
            out.assign(lr.begin(), lr.end());
        } else {
            throw Error("unknown-query", "unknown adjacency query '" + kind + "'");
        }
        val r = val::object();
        r.set("indices", to_typed_array(out));
        return r;
    });
}

// One walk as three parallel arrays, one entry per step: the edge, which way the lecture's
// rule met it (1/0, named `flag`), and the edge it read next.
template <class Steps, class Way> val walk_value(const Steps& steps, const char* flag, Way way) {
    std::vector<int32_t> edges, ways, next;
    for (const auto& s : steps) {
        edges.push_back(s.edge);
        ways.push_back(way(s));
        next.push_back(s.next);
    }
    val r = val::object();
    r.set("edges", to_typed_array(edges));
    r.set(flag, to_typed_array(ways));
    r.set("next", to_typed_array(next));
    return r;
}

// {edges, atStart (1/0), next}: the lecture's CCW walk around v.
val mesh_traversal_steps(int32_t handle, int32_t v) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        require_vertex(w, v);
        return walk_value(w.traversal_steps(v), "atStart", [](const TraversalStep& s) { return s.at_start; });
    });
}

// {edges, faceIsLeft (1/0), next}: the walk along face f.
val mesh_face_edge_steps(int32_t handle, int32_t f) {
    return guarded([&] {
        const WingedEdgeMesh& w = entry(handle).winged;
        require_face(w, f);
        return walk_value(w.face_edge_steps(f), "faceIsLeft", [](const FaceStep& s) { return s.face_is_left; });
    });
}

val mesh_counts(int32_t handle) {
    return guarded([&] {
        const MeshCounts c = entry(handle).winged.counts();
        val r = val::object();
        r.set("vertices", c.vertices);
        r.set("edges", c.edges);
        r.set("faces", c.faces);
        r.set("boundaryEdges", c.boundary_edges);
        r.set("boundaryLoops", c.boundary_loops);
        r.set("isolatedVertices", c.isolated_vertices);
        r.set("euler", c.euler());
        return r;
    });
}

val mesh_validate(int32_t handle) {
    return guarded([&] { return report_value(entry(handle).winged.validate()); });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh_walks) {
    using namespace wingspline::bindings;
    emscripten::function("meshAdjacency", &mesh_adjacency);
    emscripten::function("meshTraversalSteps", &mesh_traversal_steps);
    emscripten::function("meshFaceEdgeSteps", &mesh_face_edge_steps);
    emscripten::function("meshCounts", &mesh_counts);
    emscripten::function("meshValidate", &mesh_validate);
}
