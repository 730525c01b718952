// Loop and Catmull-Clark subdivision on the winged edge; header: subdivision.h.
//
// Two paths, as the rest of the mesh core (docs/architecture.md, "Teaching path and fast
// kernels"):
//  * the fast step (SubdivisionAccess::step) writes the result's tables directly. Every new
//    element's number is arithmetic on old numbers (V + e, 2e, 2e + 1, 2E + 3f + k, ...), so
//    each field of each new edge record is written exactly once, from one walk of each old
//    face and one pass over the old edges: no search, no hash map, no rebuild;
//  * the teaching path (step_masks) reads like the lecture: for every new point, its mask
//    (the old vertices and weights it averages) from the ring and face walks of
//    winged_edge.h. The tests check the fast positions against the masks applied.
//
// The rules (Loop 1987; Catmull and Clark 1978; boundaries: the cubic B-spline curve rules,
// as Hoppe et al. 1994 and Biermann et al. 2000 without creases):
//   Loop         edge point   3/8 (S + E) + 1/8 (the two opposite corners)
//                vertex point (1 - n beta) v + beta sum(neighbours),
//                             beta = (1/n)(5/8 - (3/8 + cos(2 pi / n)/4)^2)
//   Catmull-Clark face point  the centroid of the face's corners
//                edge point   (S + E + the two face points) / 4
//                vertex point ((n - 2)/n) v + (1/n^2) sum(neighbours) + (1/n^2) sum(face points)
//   boundary     edge point   the midpoint; vertex point 1/8 a + 6/8 v + 1/8 b (a, b its
//                boundary neighbours)
#include "wingspline/mesh/subdivision.h"

#include "wingspline/error.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace wingspline::mesh {

namespace {

constexpr int32_t kMaxSteps = 16;
constexpr double kPi = 3.14159265358979323846;

std::string with_commas(int64_t n) {
    std::string s = std::to_string(n);
    for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(static_cast<std::size_t>(i), ",");
    return s;
}

const char* scheme_title(Scheme s) { return s == Scheme::Loop ? "Loop" : "Catmull-Clark"; }

} // namespace

const char* scheme_name(Scheme s) { return s == Scheme::Loop ? "loop" : "catmull-clark"; }

Scheme scheme_from_name(const std::string& name) {
    if (name == "loop") return Scheme::Loop;
    if (name == "catmull-clark") return Scheme::CatmullClark;
    throw Error("unknown-scheme", "unknown subdivision scheme '" + name.substr(0, 40) +
                                      "': use 'loop' (triangle meshes) or 'catmull-clark' (any polygons)");
}

const char* point_rule_name(int32_t rule) {
    static const char* const names[kPointRuleCount] = {"face-point",      "edge-interior",   "edge-boundary",
                                                       "vertex-interior", "vertex-boundary", "vertex-isolated"};
    return rule >= 0 && rule < kPointRuleCount ? names[rule] : "";
}

double loop_beta(int32_t n) {
    const double c = 3.0 / 8.0 + std::cos(2.0 * kPi / n) / 4.0;
    return (5.0 / 8.0 - c * c) / n;
}

// ------------------------------------------------------------------ the fast step

struct SubdivisionAccess {
    // The sides of face f in the order face_set() lists its corners: side k is edge
    // edges[k], run from corner k to corner k+1, forward (S -> E, f on the left) or not.
    // Writes at most `room` sides into the arrays; returns the side count (more than `room`:
    // the caller asks again with more room).
    // (Kept small so that it inlines into the step's face loop; the rotation is separate.)
    static int32_t walk_face(const WingedEdgeMesh& m, int32_t f, int32_t* edges, char* forward, int32_t room) {
        const EdgeRecord* E = m.edges_.data();
        const int32_t e0 = m.face_edge_[f];
        const bool left0 = E[e0].left == f;
        const int32_t most = static_cast<int32_t>(m.edges_.size());
        int32_t e = e0, n = 0;
        bool left = left0;
        do {
            if (n < room) edges[n] = e, forward[n] = left;
            ++n;
            e = left ? E[e].end_left : E[e].start_right;
            left = E[e].left == f;
        } while ((e != e0 || left != left0) && n <= most);
        return n;
    }
    // Once face edges were chosen, face_set() lists f from its first corner, not from where
    // its walk starts: turn the n sides so that side 0 starts there.
    static void rotate_to_first_corner(const WingedEdgeMesh& m, int32_t f, int32_t* edges, char* forward, int32_t n) {
        const int32_t first = m.face_first_corner_[f];
        for (int32_t k = 0; k < n; ++k) {
            const EdgeRecord& r = m.edges_[edges[k]];
            if ((forward[k] ? r.start : r.end) == first) {
                std::rotate(edges, edges + k, edges + n);
                std::rotate(forward, forward + k, forward + n);
                return;
            }
        }
    }
    static int32_t face_sides(const WingedEdgeMesh& m, int32_t f, int32_t* edges, char* forward, int32_t room) {
        const int32_t n = walk_face(m, f, edges, forward, room);
        if (n <= room && !m.face_first_corner_.empty()) rotate_to_first_corner(m, f, edges, forward, n);
        return n;
    }
    static void face_sides(const WingedEdgeMesh& m, int32_t f, std::vector<int32_t>& edges, std::vector<char>& forward) {
        int32_t n = face_sides(m, f, edges.data(), forward.data(), static_cast<int32_t>(edges.size()));
        if (n > static_cast<int32_t>(edges.size())) {
            edges.resize(static_cast<std::size_t>(n)), forward.resize(static_cast<std::size_t>(n));
            n = face_sides(m, f, edges.data(), forward.data(), n);
        }
        edges.resize(static_cast<std::size_t>(n)), forward.resize(static_cast<std::size_t>(n));
    }

    static const std::vector<int32_t>& first_corners(const WingedEdgeMesh& m) { return m.face_first_corner_; }

    // The half of old edge x at its end v: 2x (S -> edge point) or 2x + 1 (edge point -> E).
    static int32_t half(const EdgeRecord* E, int32_t x, int32_t v) { return 2 * x + (E[x].start == v ? 0 : 1); }

    // Side of a new edge in a new face: L with its wings (prev at S, next at E) when the face
    // runs it S -> E, else R (prev at E, next at S): the slide's wing rule.
    static void side(EdgeRecord& r, bool forward, int32_t face, int32_t prev, int32_t next) {
        if (forward) {
            r.left = face, r.start_left = prev, r.end_left = next;
        } else {
            r.right = face, r.end_right = prev, r.start_right = next;
        }
    }

    static WingedEdgeMesh step(const WingedEdgeMesh& m, Scheme scheme) {
        const int32_t V = m.vertex_count(), E = m.edge_count(), F = m.face_count();
        const EdgeRecord* in = m.edges_.data();
        const double* P = m.positions_.data();
        const bool loop = scheme == Scheme::Loop;
        int64_t corners = 0; // sum of the faces' sides
        for (int32_t e = 0; e < E; ++e) corners += (in[e].left != kNone) + (in[e].right != kNone);
        const int32_t V2 = loop ? V + E : V + E + F;
        const int32_t E2 = static_cast<int32_t>(2 * static_cast<int64_t>(E) + corners);
        const int32_t F2 = static_cast<int32_t>(loop ? 4 * static_cast<int64_t>(F) : corners);

        WingedEdgeMesh out;
        out.positions_.resize(3 * static_cast<std::size_t>(V2));
        out.vertex_edge_.resize(static_cast<std::size_t>(V2));
        out.edges_.resize(static_cast<std::size_t>(E2));
        out.face_edge_.resize(static_cast<std::size_t>(F2));
        double* Q = out.positions_.data();
        EdgeRecord* R = out.edges_.data();
        int32_t* VE = out.vertex_edge_.data();
        int32_t* FE = out.face_edge_.data();

        // Phase 1 (faces): the face points (Catmull-Clark) and, for every face, the new
        // faces and inner edges with every wing, by the numbering of subdivision.h.
        // The sides of one face: on the stack, or (a face of more than kRoom sides) in big.
        constexpr int32_t kRoom = 64;
        int32_t a_room[kRoom];
        char fw_room[kRoom];
        std::vector<int32_t> a_big;
        std::vector<char> fw_big;
        int32_t o = 0; // Catmull-Clark: corners of the faces before f
        for (int32_t f = 0; f < F; ++f) {
            int32_t* a = a_room;
            char* fw = fw_room;
            int32_t n;
            if (loop && m.face_first_corner_.empty()) { // a triangle listed from its walk's start: three reads
                const int32_t e0 = m.face_edge_[f];
                const bool l0 = in[e0].left == f;
                const int32_t e1 = l0 ? in[e0].end_left : in[e0].start_right;
                const bool l1 = in[e1].left == f;
                const int32_t e2 = l1 ? in[e1].end_left : in[e1].start_right;
                a[0] = e0, a[1] = e1, a[2] = e2, fw[0] = l0, fw[1] = l1, fw[2] = in[e2].left == f;
                n = 3;
            } else {
                n = face_sides(m, f, a, fw, kRoom);
            }
            if (n > kRoom) {
                face_sides(m, f, a_big, fw_big);
                a = a_big.data(), fw = fw_big.data();
            }
            if (loop) {
                const int32_t T = 2 * E + 3 * f;
                for (int32_t k = 0; k < 3; ++k) {
                    const int32_t km = k == 0 ? 2 : k - 1, kp = k == 2 ? 0 : k + 1;
                    const int32_t hA = 2 * a[k] + (fw[k] ? 0 : 1), hC = 2 * a[km] + (fw[km] ? 1 : 0);
                    const int32_t face = 4 * f + k, t = T + k;
                    side(R[hA], fw[k], face, hC, t);
                    side(R[hC], fw[km], face, t, hA);
                    EdgeRecord& r = R[t];
                    r.start = V + a[k], r.end = V + a[km];
                    r.left = face, r.start_left = hA, r.end_left = hC;
                    r.right = 4 * f + 3, r.end_right = T + km, r.start_right = T + kp;
                    FE[face] = hA;
                    // Loop's edge point of side k gets 1/8 of the corner opposite it (k+2);
                    // the edge pass adds 3/8 (S + E) (the positions start at zero).
                    const EdgeRecord& opp = in[a[km]];
                    const double* pc = P + 3 * (fw[km] ? opp.start : opp.end);
                    double* q = Q + 3 * (V + a[k]);
                    q[0] += 0.125 * pc[0], q[1] += 0.125 * pc[1], q[2] += 0.125 * pc[2];
                }
                FE[4 * f + 3] = T + 1;
            } else {
                const int32_t p = V + E + f, T = 2 * E + o;
                double c[3] = {0, 0, 0};
                for (int32_t k = 0; k < n; ++k) {
                    const int32_t km = k == 0 ? n - 1 : k - 1;
                    const EdgeRecord& ak = in[a[k]];
                    const int32_t corner = fw[k] ? ak.start : ak.end;
                    c[0] += P[3 * corner], c[1] += P[3 * corner + 1], c[2] += P[3 * corner + 2];
                    const int32_t hA = 2 * a[k] + (fw[k] ? 0 : 1), hC = 2 * a[km] + (fw[km] ? 1 : 0);
                    const int32_t face = o + k, t = T + k, tm = T + km;
                    side(R[hA], fw[k], face, hC, t);
                    side(R[hC], fw[km], face, tm, hA);
                    EdgeRecord& r = R[t];
                    r.start = V + a[k], r.end = p;
                    r.left = face, r.start_left = hA, r.end_left = tm;
                    EdgeRecord& rm = R[tm];
                    rm.right = face, rm.end_right = t, rm.start_right = hC;
                    FE[face] = hA;
                }
                Q[3 * p] = c[0] / n, Q[3 * p + 1] = c[1] / n, Q[3 * p + 2] = c[2] / n;
                VE[p] = T;
                o += n;
            }
        }

        // Phase 2 (edges): each old edge's two halves, their boundary wings (the boundary
        // walked as a face), and the edge point.
        for (int32_t e = 0; e < E; ++e) {
            const EdgeRecord& r = in[e];
            const int32_t mid = V + e, h0 = 2 * e, h1 = 2 * e + 1;
            R[h0].start = r.start, R[h0].end = mid;
            R[h1].start = mid, R[h1].end = r.end;
            const double* s = P + 3 * r.start;
            const double* t = P + 3 * r.end;
            double* q = Q + 3 * mid;
            if (r.right == kNone) {
                R[h0].start_right = half(in, r.start_right, r.start), R[h0].end_right = h1;
                R[h1].start_right = h0, R[h1].end_right = half(in, r.end_right, r.end);
            }
            if (r.left == kNone) {
                R[h0].start_left = half(in, r.start_left, r.start), R[h0].end_left = h1;
                R[h1].start_left = h0, R[h1].end_left = half(in, r.end_left, r.end);
            }
            if (r.left == kNone || r.right == kNone) {
                for (int k = 0; k < 3; ++k) q[k] = 0.5 * (s[k] + t[k]);
                VE[mid] = r.left == kNone ? h0 : h1; // the edge after the boundary gap (CCW)
                continue;
            }
            VE[mid] = h0;
            if (loop) {
                for (int k = 0; k < 3; ++k) q[k] += 0.375 * (s[k] + t[k]); // + 1/8 of each opposite corner (phase 1)
            } else {
                const double* fl = Q + 3 * (V + E + r.left);
                const double* fr = Q + 3 * (V + E + r.right);
                for (int k = 0; k < 3; ++k) q[k] = 0.25 * (s[k] + t[k] + fl[k] + fr[k]);
            }
        }

        // Phase 3 (vertices): each old vertex's ring walked once by the lecture's rule.
        double beta_of[16];
        for (int32_t n = 3; n < 16; ++n) beta_of[n] = loop_beta(n);
        for (int32_t v = 0; v < V; ++v) {
            const int32_t e0 = m.vertex_edge_[v];
            double* q = Q + 3 * v;
            const double* pv = P + 3 * v;
            if (e0 == kNone) {
                VE[v] = kNone;
                q[0] = pv[0], q[1] = pv[1], q[2] = pv[2];
                continue;
            }
            VE[v] = half(in, e0, v);
            double sum[3] = {0, 0, 0}, fsum[3] = {0, 0, 0}, bsum[3] = {0, 0, 0};
            int32_t n = 0, nb = 0;
            int32_t e = e0;
            do {
                const EdgeRecord& r = in[e];
                int32_t other, face, next;
                if (r.start == v) {
                    other = r.end, face = r.left, next = r.start_left;
                } else {
                    WINGSPLINE_KEEP_BRANCH();
                    other = r.start, face = r.right, next = r.end_right;
                }
                const double* po = P + 3 * other;
                sum[0] += po[0], sum[1] += po[1], sum[2] += po[2];
                if (r.left == kNone || r.right == kNone) {
                    bsum[0] += po[0], bsum[1] += po[1], bsum[2] += po[2];
                    ++nb;
                }
                if (!loop && face != kNone) {
                    const double* pf = Q + 3 * (V + E + face);
                    fsum[0] += pf[0], fsum[1] += pf[1], fsum[2] += pf[2];
                }
                ++n;
                e = next;
            } while (e != e0 && n <= E);
            if (nb > 0) {
                for (int k = 0; k < 3; ++k) q[k] = 0.75 * pv[k] + 0.125 * bsum[k];
            } else if (loop) {
                const double beta = n < 16 ? beta_of[n] : loop_beta(n);
                for (int k = 0; k < 3; ++k) q[k] = (1.0 - n * beta) * pv[k] + beta * sum[k];
            } else {
                const double nn = static_cast<double>(n) * n;
                for (int k = 0; k < 3; ++k) q[k] = (n - 2.0) / n * pv[k] + (sum[k] + fsum[k]) / nn;
            }
        }
        return out;
    }
};

// ------------------------------------------------------------------ checks and counts

namespace {

SubdivisionCounts one_step(const SubdivisionCounts& c, int64_t corners, Scheme s) {
    if (s == Scheme::Loop) return {c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces};
    return {c.vertices + c.edges + c.faces, 2 * c.edges + corners, corners};
}

int64_t corner_count(const WingedEdgeMesh& m) {
    int64_t corners = 0;
    for (const EdgeRecord& r : m.edges()) corners += (r.left != kNone) + (r.right != kNone);
    return corners;
}

} // namespace

SubdivisionCounts subdivision_counts(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps) {
    SubdivisionCounts c{mesh.vertex_count(), mesh.edge_count(), mesh.face_count()};
    int64_t corners = corner_count(mesh);
    for (int32_t i = 0; i < steps; ++i) {
        c = one_step(c, corners, scheme);
        corners = scheme == Scheme::Loop ? 3 * c.faces : 4 * c.faces; // every new face is a triangle / quad
    }
    return c;
}

CheckResult check_subdivide(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps, const MeshLimits& limits) {
    if (steps < 0 || steps > kMaxSteps)
        return CheckResult::refuse("invalid-argument", "steps must be a whole number from 0 to " + std::to_string(kMaxSteps) +
                                                           ", not " + std::to_string(steps));
    if (mesh.has_garbage()) {
        std::string first;
        const auto find = [&](const std::vector<char>& marks, std::string (*label)(int32_t)) {
            for (std::size_t i = 0; first.empty() && i < marks.size(); ++i)
                if (marks[i]) first = label(static_cast<int32_t>(i));
        };
        find(mesh.deleted_vertices(), &vertex_label);
        find(mesh.deleted_edges(), &edge_label);
        find(mesh.deleted_faces(), &face_label);
        return CheckResult::refuse("mesh-has-gaps", "the mesh has elements removed by an edit (" + first +
                                                        " is a gap); compact it first, so that its vertices are numbered "
                                                        "v1, v2, ... without gaps and the result's numbering is defined");
    }
    if (scheme == Scheme::Loop) {
        for (int32_t f = 0; f < mesh.face_count(); ++f) {
            const int32_t e0 = mesh.face_edge(f);
            int32_t e = e0, n = 0;
            do {
                e = mesh.next_in_face(e, f);
                ++n;
            } while (e != e0 && n <= 3);
            if (n != 3)
                return CheckResult::refuse("not-a-triangle-mesh", "Loop subdivision needs a triangle mesh, but " + face_label(f) +
                                                                      " has " + (n > 3 ? "more than 3" : std::to_string(n)) +
                                                                      " corners; use Catmull-Clark for polygons");
        }
    }
    const SubdivisionCounts c = subdivision_counts(mesh, scheme, steps);
    const int64_t max_faces = std::min<int64_t>(limits.max_faces, INT32_MAX);
    const int64_t max_vertices = std::min<int64_t>(limits.max_vertices, INT32_MAX);
    if (c.faces > max_faces || c.vertices > max_vertices || c.edges > INT32_MAX)
        return CheckResult::refuse("too-large", std::to_string(steps) + " " + scheme_title(scheme) + " step" + (steps == 1 ? "" : "s") +
                                                    " of this mesh would make " + with_commas(c.faces) + " faces and " +
                                                    with_commas(c.vertices) + " vertices; the limit is " +
                                                    with_commas(max_faces) + " faces and " + with_commas(max_vertices) +
                                                    " vertices. Choose fewer steps.");
    return CheckResult::accept();
}

WingedEdgeMesh subdivide(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps, const MeshLimits& limits) {
    const CheckResult check = check_subdivide(mesh, scheme, steps, limits);
    if (!check.ok) throw Error(check.code, check.message);
    if (steps == 0) return mesh;
    WingedEdgeMesh result = SubdivisionAccess::step(mesh, scheme);
    for (int32_t i = 1; i < steps; ++i) result = SubdivisionAccess::step(result, scheme);
    return result;
}

// ------------------------------------------------------------------ masks: the teaching path

void Masks::add(const std::vector<std::pair<int32_t, double>>& terms) {
    const std::size_t first = vertices.size();
    for (const auto& [v, w] : terms) {
        auto at = std::find(vertices.begin() + static_cast<std::ptrdiff_t>(first), vertices.end(), v);
        if (at == vertices.end()) {
            vertices.push_back(v);
            weights.push_back(w);
        } else {
            weights[static_cast<std::size_t>(at - vertices.begin())] += w;
        }
    }
    offsets.push_back(static_cast<int32_t>(vertices.size()));
}

glm::dvec3 Masks::apply(int32_t i, const std::vector<double>& positions) const {
    glm::dvec3 p(0.0);
    for (int32_t k = offsets[i]; k < offsets[i + 1]; ++k) {
        const int32_t v = vertices[k];
        p += weights[k] * glm::dvec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    }
    return p;
}

namespace {

using Terms = std::vector<std::pair<int32_t, double>>;

bool is_boundary_edge(const WingedEdgeMesh& m, int32_t e) { return m.edge(e).left == kNone || m.edge(e).right == kNone; }

// The corners of face f as face_set() lists them.
std::vector<int32_t> corners_of(const WingedEdgeMesh& m, int32_t f) {
    std::vector<int32_t> edges;
    std::vector<char> forward;
    SubdivisionAccess::face_sides(m, f, edges, forward);
    std::vector<int32_t> corners;
    for (std::size_t k = 0; k < edges.size(); ++k) corners.push_back(forward[k] ? m.edge(edges[k]).start : m.edge(edges[k]).end);
    return corners;
}

Terms face_point_terms(const WingedEdgeMesh& m, int32_t f) {
    const std::vector<int32_t> corners = m.vertices_of_face(f);
    Terms t;
    for (int32_t c : corners) t.emplace_back(c, 1.0 / static_cast<double>(corners.size()));
    return t;
}

// The vertex opposite edge e in triangle f.
int32_t opposite(const WingedEdgeMesh& m, int32_t e, int32_t f) {
    for (int32_t c : m.vertices_of_face(f))
        if (c != m.edge(e).start && c != m.edge(e).end) return c;
    return kNone;
}

// The boundary neighbours of v (the other ends of its boundary edges).
std::vector<int32_t> boundary_neighbours(const WingedEdgeMesh& m, int32_t v) {
    std::vector<int32_t> out;
    for (int32_t e : m.edges_around_vertex(v))
        if (is_boundary_edge(m, e)) out.push_back(m.other_vertex(e, v));
    return out;
}

// The step's masks, rules and valences (everything subdivision_steps reports but the result).
void step_masks(const WingedEdgeMesh& m, Scheme scheme, Masks& masks, std::vector<int32_t>& rules, std::vector<int32_t>& valences) {
    const int32_t V = m.vertex_count(), E = m.edge_count(), F = m.face_count();
    const bool loop = scheme == Scheme::Loop;
    // Vertex points (the result's vertices 0..V-1).
    for (int32_t v = 0; v < V; ++v) {
        const std::vector<int32_t> ring = m.vertex_edge(v) == kNone ? std::vector<int32_t>{} : m.vertices_around_vertex(v);
        const int32_t n = static_cast<int32_t>(ring.size());
        valences.push_back(n);
        const std::vector<int32_t> b = n == 0 ? std::vector<int32_t>{} : boundary_neighbours(m, v);
        if (n == 0) {
            masks.add({{v, 1.0}});
            rules.push_back(static_cast<int32_t>(PointRule::VertexIsolated));
        } else if (!b.empty()) {
            Terms t{{v, 0.75}};
            for (int32_t u : b) t.emplace_back(u, 0.25 / static_cast<double>(b.size()));
            masks.add(t);
            rules.push_back(static_cast<int32_t>(PointRule::VertexBoundary));
        } else if (loop) {
            const double beta = loop_beta(n);
            Terms t{{v, 1.0 - n * beta}};
            for (int32_t u : ring) t.emplace_back(u, beta);
            masks.add(t);
            rules.push_back(static_cast<int32_t>(PointRule::VertexInterior));
        } else {
            const double nn = static_cast<double>(n) * n;
            Terms t{{v, (n - 2.0) / n}};
            for (int32_t u : ring) t.emplace_back(u, 1.0 / nn);
            for (int32_t f : m.faces_around_vertex(v))
                for (const auto& [c, w] : face_point_terms(m, f)) t.emplace_back(c, w / nn);
            masks.add(t);
            rules.push_back(static_cast<int32_t>(PointRule::VertexInterior));
        }
    }
    // Edge points (V + e).
    for (int32_t e = 0; e < E; ++e) {
        const EdgeRecord& r = m.edge(e);
        if (is_boundary_edge(m, e)) {
            masks.add({{r.start, 0.5}, {r.end, 0.5}});
            rules.push_back(static_cast<int32_t>(PointRule::EdgeBoundary));
            continue;
        }
        if (loop) {
            masks.add({{r.start, 0.375}, {r.end, 0.375}, {opposite(m, e, r.left), 0.125}, {opposite(m, e, r.right), 0.125}});
        } else {
            Terms t{{r.start, 0.25}, {r.end, 0.25}};
            for (int32_t f : {r.left, r.right})
                for (const auto& [c, w] : face_point_terms(m, f)) t.emplace_back(c, 0.25 * w);
            masks.add(t);
        }
        rules.push_back(static_cast<int32_t>(PointRule::EdgeInterior));
    }
    // Face points (V + E + f), Catmull-Clark only.
    if (!loop)
        for (int32_t f = 0; f < F; ++f) {
            Terms t;
            for (int32_t c : corners_of(m, f)) t.emplace_back(c, 1.0);
            for (auto& term : t) term.second /= static_cast<double>(t.size());
            masks.add(t);
            rules.push_back(static_cast<int32_t>(PointRule::FacePoint));
        }
}

} // namespace

SubdivisionSteps subdivision_steps(const WingedEdgeMesh& mesh, Scheme scheme) {
    SubdivisionSteps s;
    s.scheme = scheme;
    s.result = subdivide(mesh, scheme, 1); // refuses what subdivide refuses, before any work
    const int32_t V = mesh.vertex_count(), E = mesh.edge_count(), F = mesh.face_count();
    step_masks(mesh, scheme, s.masks, s.rules, s.valences);
    const int32_t face_points = scheme == Scheme::Loop ? 0 : F;
    s.phases = {{"face-points", V + E, face_points}, {"edge-points", V, E}, {"vertex-points", 0, V},
                {"reconnection", 0, s.result.face_count()}};
    s.positions.resize(3 * static_cast<std::size_t>(s.masks.count()));
    for (int32_t i = 0; i < s.masks.count(); ++i) {
        const glm::dvec3 p = s.masks.apply(i, mesh.positions());
        s.positions[3 * i] = p.x, s.positions[3 * i + 1] = p.y, s.positions[3 * i + 2] = p.z;
    }
    return s;
}

ReconnectionPlayback reconnection_playback(const WingedEdgeMesh& mesh, Scheme scheme, const WingedEdgeMesh& result) {
    const int32_t E = mesh.edge_count(), F = mesh.face_count();
    const bool loop = scheme == Scheme::Loop;
    ReconnectionPlayback p;
    p.lines = {
        "Split each old edge in two: its first half runs from S to the edge point, its second from the edge point to E",
        "Old face F: each new face inside it stores one of its edges (face table)",
        "Old face F: each new inner edge gets S, E, L, R and its four wings",
        "Old face F: the halves of its sides get, on the side facing F, the new face and two wings",
        "A half on the boundary gets its two wings on the side with no face (the boundary walked as a face)",
        "Every vertex of the next level stores one edge at it (vertex table)",
    };
    auto assign = [&](MeshTable table, int32_t row, const char* field, int32_t after, int32_t line, int32_t source) {
        if (after == kNone) return;
        AssignmentStep s;
        s.table = table, s.row = row, s.field = field, s.before = kNone, s.after = after, s.phase = line;
        p.steps.push_back(s);
        p.source.push_back(source);
    };
    // line 0: the halves' ends
    for (int32_t e = 0; e < E; ++e) {
        for (int32_t h : {2 * e, 2 * e + 1}) {
            assign(MeshTable::Edge, h, "start", result.edge(h).start, 0, e);
            assign(MeshTable::Edge, h, "end", result.edge(h).end, 0, e);
        }
    }
    // lines 1-3: face by face (the numbering of subdivision.h: the new faces and inner edges
    // of face f are a block that starts at o_f, the corners of the faces before f)
    int32_t o = 0;
    for (int32_t f = 0; f < F; ++f) {
        const std::vector<int32_t> sides = mesh.edges_of_face(f);
        const int32_t n = static_cast<int32_t>(sides.size());
        const int32_t first_face = loop ? 4 * f : o, face_count = loop ? 4 : n;
        const int32_t first_inner = loop ? 2 * E + 3 * f : 2 * E + o, inner_count = loop ? 3 : n;
        const auto inside = [&](int32_t face) { return face != kNone && face >= first_face && face < first_face + face_count; };
        for (int32_t g = first_face; g < first_face + face_count; ++g) assign(MeshTable::Face, g, "edge", result.face_edge(g), 1, f);
        for (int32_t t = first_inner; t < first_inner + inner_count; ++t) {
            const EdgeRecord& r = result.edge(t);
            assign(MeshTable::Edge, t, "start", r.start, 2, f);
            assign(MeshTable::Edge, t, "end", r.end, 2, f);
            assign(MeshTable::Edge, t, "left", r.left, 2, f);
            assign(MeshTable::Edge, t, "right", r.right, 2, f);
            assign(MeshTable::Edge, t, "startLeft", r.start_left, 2, f);
            assign(MeshTable::Edge, t, "startRight", r.start_right, 2, f);
            assign(MeshTable::Edge, t, "endLeft", r.end_left, 2, f);
            assign(MeshTable::Edge, t, "endRight", r.end_right, 2, f);
        }
        for (int32_t e : sides) {
            for (int32_t h : {2 * e, 2 * e + 1}) {
                const EdgeRecord& r = result.edge(h);
                if (inside(r.left)) {
                    assign(MeshTable::Edge, h, "left", r.left, 3, f);
                    assign(MeshTable::Edge, h, "startLeft", r.start_left, 3, f);
                    assign(MeshTable::Edge, h, "endLeft", r.end_left, 3, f);
                }
                if (inside(r.right)) {
                    assign(MeshTable::Edge, h, "right", r.right, 3, f);
                    assign(MeshTable::Edge, h, "startRight", r.start_right, 3, f);
                    assign(MeshTable::Edge, h, "endRight", r.end_right, 3, f);
                }
            }
        }
        o += n;
    }
    // line 4: the boundary halves' wings on their open side
    for (int32_t e = 0; e < E; ++e) {
        for (int32_t h : {2 * e, 2 * e + 1}) {
            const EdgeRecord& r = result.edge(h);
            if (r.left == kNone) {
                assign(MeshTable::Edge, h, "startLeft", r.start_left, 4, e);
                assign(MeshTable::Edge, h, "endLeft", r.end_left, 4, e);
            }
            if (r.right == kNone) {
                assign(MeshTable::Edge, h, "startRight", r.start_right, 4, e);
                assign(MeshTable::Edge, h, "endRight", r.end_right, 4, e);
            }
        }
    }
    // line 5: the vertex table
    for (int32_t v = 0; v < result.vertex_count(); ++v) assign(MeshTable::Vertex, v, "edge", result.vertex_edge(v), 5, kNone);
    return p;
}

Masks limit_masks(const WingedEdgeMesh& mesh, Scheme scheme) {
    const CheckResult check = check_subdivide(mesh, scheme, 0);
    if (!check.ok) throw Error(check.code, check.message);
    const int32_t V = mesh.vertex_count(), E = mesh.edge_count();
    Masks step, out;
    std::vector<int32_t> rules, valences;
    if (scheme == Scheme::CatmullClark) step_masks(mesh, scheme, step, rules, valences);
    const auto step_terms = [&](int32_t i, double scale, Terms& t) {
        for (int32_t k = step.offsets[i]; k < step.offsets[i + 1]; ++k) t.emplace_back(step.vertices[k], scale * step.weights[k]);
    };
    for (int32_t v = 0; v < V; ++v) {
        const std::vector<int32_t> ring = mesh.vertex_edge(v) == kNone ? std::vector<int32_t>{} : mesh.vertices_around_vertex(v);
        const int32_t n = static_cast<int32_t>(ring.size());
        const std::vector<int32_t> b = n == 0 ? std::vector<int32_t>{} : boundary_neighbours(mesh, v);
        Terms t;
        if (n == 0) {
            t = {{v, 1.0}};
        } else if (!b.empty()) {
            t = {{v, 4.0 / 6.0}};
            for (int32_t u : b) t.emplace_back(u, (2.0 / 6.0) / static_cast<double>(b.size()));
        } else if (scheme == Scheme::Loop) {
            const double chi = 1.0 / (3.0 / (8.0 * loop_beta(n)) + n);
            t = {{v, 1.0 - n * chi}};
            for (int32_t u : ring) t.emplace_back(u, chi);
        } else {
            const double d = static_cast<double>(n) * (n + 5);
            step_terms(v, static_cast<double>(n) * n / d, t);
            for (int32_t e : mesh.edges_around_vertex(v)) step_terms(V + e, 4.0 / d, t);
            for (int32_t f : mesh.faces_around_vertex(v)) step_terms(V + E + f, 1.0 / d, t);
        }
        out.add(t);
    }
    return out;
}

std::vector<double> limit_positions(const WingedEdgeMesh& mesh, Scheme scheme) {
    const Masks masks = limit_masks(mesh, scheme);
    std::vector<double> out(3 * static_cast<std::size_t>(masks.count()));
    for (int32_t i = 0; i < masks.count(); ++i) {
        const glm::dvec3 p = masks.apply(i, mesh.positions());
        out[3 * i] = p.x, out[3 * i + 1] = p.y, out[3 * i + 2] = p.z;
    }
    return out;
}

} // namespace wingspline::mesh
