// Validation of an indexed face set: every problem, not only the first.
#include "wingspline/mesh/indexed_mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <cstdio>

namespace wingspline::mesh {

int32_t IndexedMesh::add_vertex(double x, double y, double z) {
    positions.insert(positions.end(), {x, y, z});
    return vertex_count() - 1;
}

void IndexedMesh::add_face(std::initializer_list<int32_t> vertices) {
    add_face(vertices.begin(), static_cast<int32_t>(vertices.size()));
}

void IndexedMesh::add_face(const int32_t* vertices, int32_t count) {
    face_vertices.insert(face_vertices.end(), vertices, vertices + count);
    face_offsets.push_back(static_cast<int32_t>(face_vertices.size()));
}

bool ValidationReport::ok() const { return first_error() == nullptr; }

const Problem* ValidationReport::first_error() const {
    for (const auto& p : problems)
        if (p.severity == Severity::Error) return &p;
    return nullptr;
}

bool ValidationReport::has(const std::string& code) const {
    return std::any_of(problems.begin(), problems.end(), [&](const Problem& p) { return p.code == code; });
}

namespace {
// A number as an ostream prints it by default (%g: 6 significant digits, inf, nan), without
// <sstream>: one ostringstream pulled 58 KB of iostream and locale code into the wasm module.
std::string number_text(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

std::string first_error_code(const ValidationReport& r) {
    const Problem* p = r.first_error();
    return p ? p->code : "invalid-mesh";
}
std::string first_error_message(const ValidationReport& r) {
    const Problem* p = r.first_error();
    if (!p) return "the mesh is not valid";
    const auto errors = std::count_if(r.problems.begin(), r.problems.end(),
                                      [](const Problem& q) { return q.severity == Severity::Error; });
    if (errors == 1) return p->message;
    return p->message + " (and " + std::to_string(errors - 1) + " more problem" + (errors > 2 ? "s" : "") + ")";
}
} // namespace

InvalidMesh::InvalidMesh(ValidationReport report)
    : Error(first_error_code(report), first_error_message(report)), report_(std::move(report)) {}

// (int64_t: the largest index a caller may pass, 2^31 - 1, has a label too.)
std::string vertex_label(int32_t v) { return "v" + std::to_string(int64_t{v} + 1); }
std::string face_label(int32_t f) { return "F" + std::to_string(int64_t{f} + 1); }
std::string edge_label(int32_t e) { return "e" + std::to_string(int64_t{e} + 1); }

std::string elements_text(std::string (*label)(int32_t), const char* plural, int32_t count) {
    if (count <= 0) return std::string("no ") + plural;
    if (count == 1) return "only " + label(0);
    return plural + (" " + label(0)) + " to " + label(count - 1);
}

std::string face_too_large_message(int32_t f, int64_t corners) {
    return face_label(f) + " has " + std::to_string(corners) + " corners; a face may have at most " + std::to_string(kMaxFaceCorners);
}

namespace {

std::string join_faces(const std::vector<int32_t>& faces) {
    std::string s;
    for (std::size_t i = 0; i < faces.size(); ++i) s += (i ? ", " : "") + face_label(faces[i]);
    return s;
}

struct HalfEdgeKey {
    int32_t lo, hi;  // the undirected edge
    int32_t from;    // direction: from == lo or hi
    int32_t face;
    int32_t corner;  // global corner index of `from` in face_vertices
};

class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int32_t find(int32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(int32_t a, int32_t b) { parent_[find(a)] = find(b); }

private:
    std::vector<int32_t> parent_;
};

Problem make(const char* code, std::string message, std::vector<int32_t> vertices = {},
             std::vector<int32_t> faces = {}, Severity severity = Severity::Error) {
    Problem p;
    p.code = code;
    p.severity = severity;
    p.message = std::move(message);
    p.vertices = std::move(vertices);
    p.faces = std::move(faces);
    return p;
}

} // namespace

ValidationReport validate_indexed(const IndexedMesh& mesh) {
    ValidationReport report;
    auto& out = report.problems;
    const int32_t V = mesh.vertex_count();
    const int32_t F = mesh.face_count();

    if (F <= 0) out.push_back(make("empty-mesh", "the mesh has no faces; a winged-edge mesh needs at least one polygon"));

    for (int32_t v = 0; v < V; ++v) {
        for (int k = 0; k < 3; ++k) {
            const double c = mesh.positions[3 * v + k];
            if (!std::isfinite(c)) {
                out.push_back(make("non-finite-coordinate", vertex_label(v) + " has a coordinate that is not a finite number (" +
                                   "xyz"[k] + " = " + number_text(c) + ")", {v}));
                break;
            }
            if (std::abs(c) > kMaxCoordinate) {
                // The one coordinate bound (limits.h): the state format's, and far inside
                // what Newell's sums of pair products can hold without overflow.
                out.push_back(make("coordinate-out-of-range", vertex_label(v) + " has a coordinate beyond the limit of " +
                                   number_text(kMaxCoordinate) + " in size (" + "xyz"[k] + " = " + number_text(c) + ")", {v}));
                break;
            }
        }
    }

    std::vector<char> face_ok(std::max(F, 0), 1);
    std::vector<char> used(V, 0);
    for (int32_t f = 0; f < F; ++f) {
        const int32_t n = mesh.face_size(f);
        if (n < 3) {
            face_ok[f] = 0;
            out.push_back(make("too-few-vertices", face_label(f) + " has " + std::to_string(n) +
                               " vertices; a polygon needs at least 3", {}, {f}));
        }
        if (n > kMaxFaceCorners) out.push_back(make("face-too-large", face_too_large_message(f, n), {}, {f}));
        std::vector<int32_t> bad;
        for (int32_t i = 0; i < n; ++i) {
            const int32_t v = mesh.corner(f, i);
            if (v < 0 || v >= V) bad.push_back(v);
            else used[v] = 1;
        }
        if (!bad.empty()) {
            // Named as the slides name vertices, with the index as the face list gives it.
            face_ok[f] = 0;
            std::string m = face_label(f) + " refers to ";
            for (std::size_t i = 0; i < bad.size(); ++i)
                m += (i ? ", " : "") + (bad[i] >= 0 ? vertex_label(bad[i]) + " (index " + std::to_string(bad[i]) + ")" : std::to_string(bad[i]) + ", no vertex");
            m += ", but the mesh has " + elements_text(&vertex_label, "vertices", V);
            out.push_back(make("index-out-of-range", m, {}, {f}));
            continue;
        }
        std::vector<int32_t> sorted(mesh.face_vertices.begin() + mesh.face_offsets[f],
                                    mesh.face_vertices.begin() + mesh.face_offsets[f + 1]);
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i = 1; i < sorted.size(); ++i) {
            if (sorted[i] == sorted[i - 1]) {
                face_ok[f] = 0;
                out.push_back(make("repeated-vertex", face_label(f) + " visits " + vertex_label(sorted[i]) +
                                   " more than once; a polygon's corners must be distinct vertices", {sorted[i]}, {f}));
                break;
            }
        }
    }

    // Undirected edges of the good faces, grouped by their two vertices.
    std::vector<HalfEdgeKey> keys;
    for (int32_t f = 0; f < F; ++f) {
        if (!face_ok[f]) continue;
        const int32_t o = mesh.face_offsets[f], n = mesh.face_size(f);
        for (int32_t i = 0; i < n; ++i) {
            const int32_t a = mesh.face_vertices[o + i], b = mesh.face_vertices[o + (i + 1) % n];
            keys.push_back({std::min(a, b), std::max(a, b), a, f, o + i});
        }
    }
    std::sort(keys.begin(), keys.end(), [](const HalfEdgeKey& x, const HalfEdgeKey& y) {
        return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.face < y.face;
    });
    auto next_corner = [&](int32_t f, int32_t c) {
        const int32_t o = mesh.face_offsets[f], n = mesh.face_size(f);
        return o + (c - o + 1) % n;
    };
    DisjointSets fans(mesh.face_vertices.size());
    std::vector<char> vertex_on_bad_edge(V, 0);
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i;
        while (j < keys.size() && keys[j].lo == keys[i].lo && keys[j].hi == keys[i].hi) ++j;
        const int32_t a = keys[i].lo, b = keys[i].hi;
        const std::string name = "edge " + vertex_label(a) + "-" + vertex_label(b);
        std::vector<int32_t> faces;
        for (std::size_t k = i; k < j; ++k) faces.push_back(keys[k].face);
        if (j - i > 2) {
            out.push_back(make("non-manifold-edge", name + " is shared by " + std::to_string(j - i) + " faces (" +
                               join_faces(faces) + "); a winged-edge mesh allows at most 2", {a, b}, faces));
            vertex_on_bad_edge[a] = vertex_on_bad_edge[b] = 1;
        } else if (j - i == 2) {
            const HalfEdgeKey& x = keys[i];
            const HalfEdgeKey& y = keys[i + 1];
            if (x.from == y.from) {
                out.push_back(make("inconsistent-orientation",
                                   face_label(x.face) + " and " + face_label(y.face) + " both run along " + name +
                                   " from " + vertex_label(x.from) + " to " + vertex_label(x.from == a ? b : a) +
                                   "; neighbouring faces must traverse their shared edge in opposite directions "
                                   "(all counter-clockwise seen from the same side)", {a, b}, faces));
                vertex_on_bad_edge[a] = vertex_on_bad_edge[b] = 1;
            } else {
                // The two faces are consecutive in the fan of both endpoints.
                fans.unite(x.corner, next_corner(y.face, y.corner));
                fans.unite(next_corner(x.face, x.corner), y.corner);
            }
        }
        i = j;
    }

    // Duplicate faces: the same set of vertices (in either orientation).
    std::vector<std::pair<std::vector<int32_t>, int32_t>> face_keys;
    for (int32_t f = 0; f < F; ++f) {
        if (!face_ok[f]) continue;
        std::vector<int32_t> k(mesh.face_vertices.begin() + mesh.face_offsets[f],
                               mesh.face_vertices.begin() + mesh.face_offsets[f + 1]);
        std::sort(k.begin(), k.end());
        face_keys.emplace_back(std::move(k), f);
    }
    std::sort(face_keys.begin(), face_keys.end());
    for (std::size_t i = 0; i < face_keys.size();) {
        std::size_t j = i;
        std::vector<int32_t> faces;
        while (j < face_keys.size() && face_keys[j].first == face_keys[i].first) faces.push_back(face_keys[j++].second);
        if (faces.size() > 1) {
            std::string verts;
            for (std::size_t k = 0; k < face_keys[i].first.size(); ++k) verts += (k ? " " : "") + vertex_label(face_keys[i].first[k]);
            out.push_back(make("duplicate-face", join_faces(faces) + " use the same vertices (" + verts +
                               "); each polygon may appear only once", face_keys[i].first, faces));
        }
        i = j;
    }

    // Bow-tie vertices: the faces around a manifold vertex form one fan.
    std::vector<std::vector<int32_t>> roots(V);
    std::vector<std::vector<int32_t>> root_faces(V);
    for (int32_t f = 0; f < F; ++f) {
        if (!face_ok[f]) continue;
        for (int32_t c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
            const int32_t v = mesh.face_vertices[c];
            if (vertex_on_bad_edge[v]) continue;
            const int32_t r = fans.find(c);
            if (std::find(roots[v].begin(), roots[v].end(), r) == roots[v].end()) roots[v].push_back(r);
            root_faces[v].push_back(f);
        }
    }
    for (int32_t v = 0; v < V; ++v) {
        if (roots[v].size() > 1) {
            out.push_back(make("non-manifold-vertex", vertex_label(v) + " joins " + std::to_string(roots[v].size()) +
                               " separate fans of faces (" + join_faces(root_faces[v]) +
                               ") like a bow-tie; the faces around a winged-edge vertex must form one fan",
                               {v}, root_faces[v]));
        }
    }

    for (int32_t v = 0; v < V; ++v) {
        if (!used[v]) {
            out.push_back(make("isolated-vertex", vertex_label(v) + " belongs to no face; it is kept with no edge (edge = -1)",
                               {v}, {}, Severity::Warning));
        }
    }
    return report;
}

} // namespace wingspline::mesh
