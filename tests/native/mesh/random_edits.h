#pragma once
// Random edits for the native tests: the meshes they start from (closed, open, polygons)
// and one random call of an operation of the registry (operations.h), its arguments drawn
// by kind (an element argument after the first mostly among its `choices`). The Euler tests
// (test_mesh_euler.cpp), the edit exercise's tests (test_exercise_edit.cpp) and the undo tests
// (test_undo.cpp) share them, and a snapshot of everything a mesh holds.
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace wingspline::test_edits {

using namespace wingspline::mesh;

inline WingedEdgeMesh lecture() {
    const NamedMesh ex = lecture_example();
    return WingedEdgeMesh::build(ex.mesh, ex.options);
}

// ---------------------------------------------------------------- random operations
// Drawn from the registry (operations.h), so every operation with an entry is exercised
// here: each argument by its kind, an element argument after the first mostly among its
// `choices` (the corners of the face, the neighbours of the vertex), sometimes any element.
inline const int kOps = static_cast<int>(operations().size());

struct Call {
    int op;
    int32_t a, b, c; // the element arguments in order
    double t;        // the number argument, if any
};
inline const char* op_name(int op) { return operations()[op].name; }

inline Operation operation_of(const Call& c) {
    const OperationEntry& entry = operations()[c.op];
    Operation op{&entry, {}};
    const int32_t elements[3] = {c.a, c.b, c.c};
    int next = 0;
    for (std::size_t k = 0; k < entry.arguments.size(); ++k)
        op.args[k] = entry.arguments[k].kind == ElementKind::None ? c.t : elements[next++];
    return op;
}

inline std::vector<int32_t> choices_of(const WingedEdgeMesh& w, const char* query, int32_t first) {
    const std::string q = query;
    if (q == "vertices-of-face") return w.vertices_of_face(first);
    if (q == "vertices-around-vertex") return w.vertices_around_vertex(first);
    if (q == "edges-around-vertex") return w.edges_around_vertex(first);
    if (q == "edges-of-face") return w.edges_of_face(first);
    return {};
}

inline int32_t count_of(const WingedEdgeMesh& w, ElementKind k) {
    return k == ElementKind::Vertex ? w.vertex_count() : k == ElementKind::Edge ? w.edge_count() : w.face_count();
}

inline bool is_live(const WingedEdgeMesh& w, ElementKind k, int32_t i) {
    if (i < 0 || i >= count_of(w, k)) return false;
    return k == ElementKind::Vertex ? !w.is_deleted(Vertex(i)) : k == ElementKind::Edge ? !w.is_deleted(Edge(i)) : !w.is_deleted(Face(i));
}

inline Call random_call(const WingedEdgeMesh& w, std::mt19937& rng) {
    const auto pick = [&](int32_t n) { return static_cast<int32_t>(rng() % static_cast<uint32_t>(std::max(n, 1))); };
    Call c{static_cast<int>(rng() % static_cast<uint32_t>(kOps)), 0, 0, 0, 0.5};
    const double ts[] = {0.5, 0.25, 0.0, 1.0, 0.9, -0.5, 1.5};
    c.t = ts[rng() % 7];
    const OperationEntry& entry = operations()[c.op];
    int32_t* slots[3] = {&c.a, &c.b, &c.c};
    int next = 0;
    for (const OperationArgument& arg : entry.arguments) {
        if (arg.kind == ElementKind::None) continue;
        int32_t& slot = *slots[next++];
        const int32_t n = count_of(w, arg.kind);
        if (arg.choices == nullptr) {
            // now and then one past the end or -1 (refused as invalid-element)
            slot = pick(n) - (rng() % 50 == 0 ? n + 1 : 0);
        } else if (is_live(w, entry.arguments[0].kind, c.a) && rng() % 5 != 0) {
            const std::vector<int32_t> options = choices_of(w, arg.choices, c.a);
            slot = options.empty() ? pick(n) : options[pick(static_cast<int32_t>(options.size()))];
        } else {
            slot = pick(n);
        }
    }
    return c;
}

// ---------------------------------------------------------------- snapshots
// Everything a WingedEdgeMesh holds, read through its public interface: the tables, the face
// set, the gap marks and the version.
struct Snapshot {
    std::vector<double> positions;
    std::vector<int32_t> vertex_edge, edges, face_edge, face_set_offsets, face_set_vertices;
    std::vector<char> dv, de, df;
    MeshVersion version;
    // The same tables, face set and gaps, whatever the version.
    bool same_tables(const Snapshot& o) const {
        return positions == o.positions && vertex_edge == o.vertex_edge && edges == o.edges && face_edge == o.face_edge &&
               face_set_offsets == o.face_set_offsets && face_set_vertices == o.face_set_vertices && dv == o.dv && de == o.de &&
               df == o.df;
    }
    bool operator==(const Snapshot& o) const { return same_tables(o) && version == o.version; }
};

inline Snapshot snapshot(const WingedEdgeMesh& w) {
    Snapshot s;
    s.positions = w.positions();
    s.vertex_edge = w.vertex_edges();
    for (const EdgeRecord& r : w.edges())
        s.edges.insert(s.edges.end(), {r.start, r.end, r.left, r.right, r.start_left, r.start_right, r.end_left, r.end_right});
    s.face_edge = w.face_edges();
    const IndexedMesh fs = w.face_set();
    s.face_set_offsets = fs.face_offsets;
    s.face_set_vertices = fs.face_vertices;
    s.dv = w.deleted_vertices(), s.de = w.deleted_edges(), s.df = w.deleted_faces();
    s.version = w.version();
    return s;
}

struct Fixture {
    std::string name;
    WingedEdgeMesh mesh;
};
inline std::vector<Fixture> fixtures() {
    IndexedMesh hexagons; // a polygon mesh: two hexagons and a quad
    for (int i = 0; i < 10; ++i) hexagons.add_vertex(i % 5, i / 5, 0);
    hexagons.add_face({0, 1, 2, 7, 6, 5});
    hexagons.add_face({2, 3, 4, 9, 8, 7});
    const NamedMesh foley = foley_example();
    return {{"tetrahedron", WingedEdgeMesh::build(tetrahedron())}, {"cube", WingedEdgeMesh::build(cube())},
            {"lecture", lecture()}, {"foley", WingedEdgeMesh::build(foley.mesh, foley.options)},
            {"sphere", WingedEdgeMesh::build(uv_sphere(8, 6))}, {"grid", WingedEdgeMesh::build(grid(4, 3))},
            {"fan", WingedEdgeMesh::build(open_fan(5))}, {"hexagons", WingedEdgeMesh::build(hexagons)}};
}

} // namespace wingspline::test_edits
