// Loop and Catmull-Clark subdivision on the winged edge, and curve subdivision.
// Expected values come from the formulas worked by hand (tetrahedron, cube: fractions
// below), from an independent recomputation on the indexed face set (neighbours and faces
// found by plain loops over the faces, not by the winged edge's walks), and from
// invariants (counts, Euler characteristic, validate(), symmetry, similarity transforms,
// masks summing to 1, knot insertion).
//
// Tolerance: positions are compared with |a - b| <= 1e-12 * s, s = the largest coordinate
// magnitude of the input (unit: the mesh's own length unit), so every verdict is the same at
// every scale; a handful of floating-point operations per point cannot come near it.
#include <catch2/catch.hpp>

#include "wingspline/curves/bspline_ops.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/subdivision.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/subdivision.h"
#include "wingspline/mesh/winged_edge.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

using namespace wingspline::mesh;
using glm::dvec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

dvec3 pos(const std::vector<double>& p, int32_t v) { return {p[3 * v], p[3 * v + 1], p[3 * v + 2]}; }

double scale_of(const std::vector<double>& p) {
    double s = 0;
    for (double x : p) s = std::max(s, std::abs(x));
    return std::max(s, 1e-300);
}

bool near(const dvec3& a, const dvec3& b, double s, double rel = 1e-12) {
    return std::abs(a.x - b.x) <= rel * s && std::abs(a.y - b.y) <= rel * s && std::abs(a.z - b.z) <= rel * s;
}

// ------------------------------------------------------------ independent recomputation
// Everything below reads only the indexed face set: faces as corner lists.
struct FaceSetFacts {
    std::vector<std::vector<int32_t>> faces;
    std::map<std::pair<int32_t, int32_t>, std::vector<int32_t>> edge_faces; // (min, max) -> faces on it
    std::vector<std::set<int32_t>> neighbours, boundary_neighbours, faces_at;
};

FaceSetFacts facts_of(const IndexedMesh& m) {
    FaceSetFacts f;
    const int32_t V = m.vertex_count();
    f.neighbours.resize(V), f.boundary_neighbours.resize(V), f.faces_at.resize(V);
    for (int32_t i = 0; i < m.face_count(); ++i) {
        std::vector<int32_t> c(m.face_vertices.begin() + m.face_offsets[i], m.face_vertices.begin() + m.face_offsets[i + 1]);
        for (std::size_t k = 0; k < c.size(); ++k) {
            const int32_t a = c[k], b = c[(k + 1) % c.size()];
            f.edge_faces[{std::min(a, b), std::max(a, b)}].push_back(i);
            f.neighbours[a].insert(b), f.neighbours[b].insert(a), f.faces_at[a].insert(i);
        }
        f.faces.push_back(c);
    }
    for (const auto& [e, fs] : f.edge_faces)
        if (fs.size() == 1) f.boundary_neighbours[e.first].insert(e.second), f.boundary_neighbours[e.second].insert(e.first);
    return f;
}

dvec3 centroid(const std::vector<double>& p, const std::vector<int32_t>& corners) {
    dvec3 c(0.0);
    for (int32_t v : corners) c += pos(p, v);
    return c / static_cast<double>(corners.size());
}

double beta_by_hand(int n) {
    const double c = 3.0 / 8.0 + std::cos(2.0 * kPi / n) / 4.0;
    return (5.0 / 8.0 - c * c) / n;
}

// The rules, applied to the facts (not to the winged edge).
dvec3 expected_vertex(const FaceSetFacts& f, const std::vector<double>& p, int32_t v, Scheme s) {
    const auto& nb = f.neighbours[v];
    const auto& bn = f.boundary_neighbours[v];
    const dvec3 pv = pos(p, v);
    if (nb.empty()) return pv;
    if (!bn.empty()) {
        dvec3 sum(0.0);
        for (int32_t u : bn) sum += pos(p, u);
        return 0.75 * pv + 0.125 * sum;
    }
    const double n = static_cast<double>(nb.size());
    dvec3 sum(0.0);
    for (int32_t u : nb) sum += pos(p, u);
    if (s == Scheme::Loop) {
        const double b = beta_by_hand(static_cast<int>(n));
        return (1 - n * b) * pv + b * sum;
    }
    dvec3 fs(0.0);
    for (int32_t g : f.faces_at[v]) fs += centroid(p, f.faces[g]);
    return (n - 2) / n * pv + sum / (n * n) + fs / (n * n);
}

dvec3 expected_edge(const FaceSetFacts& f, const std::vector<double>& p, int32_t a, int32_t b, Scheme s) {
    const auto& fs = f.edge_faces.at({std::min(a, b), std::max(a, b)});
    if (fs.size() == 1) return 0.5 * (pos(p, a) + pos(p, b));
    if (s == Scheme::CatmullClark)
        return 0.25 * (pos(p, a) + pos(p, b) + centroid(p, f.faces[fs[0]]) + centroid(p, f.faces[fs[1]]));
    dvec3 opp(0.0);
    for (int32_t g : fs)
        for (int32_t c : f.faces[g])
            if (c != a && c != b) opp += pos(p, c);
    return 0.375 * (pos(p, a) + pos(p, b)) + 0.125 * opp;
}

// Checks every position and every face of one step against the facts and the numbering
// of subdivision.h, plus counts, validate() and Euler's characteristic.
void check_one_step(const WingedEdgeMesh& in, Scheme s) {
    const WingedEdgeMesh out = subdivide(in, s, 1);
    const IndexedMesh fs = in.face_set();
    const FaceSetFacts f = facts_of(fs);
    const std::vector<double>& p = in.positions();
    const double sc = scale_of(p);
    const int32_t V = in.vertex_count(), E = in.edge_count(), F = in.face_count();
    int32_t corners = 0;
    for (const auto& face : f.faces) corners += static_cast<int32_t>(face.size());
    // Counts: Loop V+E, 2E+3F, 4F; Catmull-Clark V+E+F, 2E+sum(n_f), sum(n_f).
    if (s == Scheme::Loop) {
        CHECK(out.vertex_count() == V + E);
        CHECK(out.edge_count() == 2 * E + 3 * F);
        CHECK(out.face_count() == 4 * F);
    } else {
        CHECK(out.vertex_count() == V + E + F);
        CHECK(out.edge_count() == 2 * E + corners);
        CHECK(out.face_count() == corners);
    }
    const ValidationReport report = out.validate();
    INFO((report.problems.empty() ? std::string() : report.problems.front().message));
    REQUIRE(report.ok());
    CHECK(out.counts().euler() == in.counts().euler());
    CHECK(out.counts().boundary_loops == in.counts().boundary_loops);
    // Positions: old vertices, edge points V + e, face points V + E + f.
    const std::vector<double>& q = out.positions();
    for (int32_t v = 0; v < V; ++v) {
        INFO("vertex " << v);
        CHECK(near(pos(q, v), expected_vertex(f, p, v, s), sc));
    }
    for (int32_t e = 0; e < E; ++e) {
        INFO("edge " << e);
        CHECK(near(pos(q, V + e), expected_edge(f, p, in.edge(e).start, in.edge(e).end, s), sc));
    }
    if (s == Scheme::CatmullClark)
        for (int32_t g = 0; g < F; ++g) CHECK(near(pos(q, V + E + g), centroid(p, f.faces[g]), sc));
    // Faces: the numbering of subdivision.h, from the input's face set and edge table.
    std::map<std::pair<int32_t, int32_t>, int32_t> edge_of;
    for (int32_t e = 0; e < E; ++e) edge_of[{std::min(in.edge(e).start, in.edge(e).end), std::max(in.edge(e).start, in.edge(e).end)}] = e;
    const auto mid = [&](int32_t a, int32_t b) { return V + edge_of.at({std::min(a, b), std::max(a, b)}); };
    const IndexedMesh ofs = out.face_set();
    const auto corners_of = [&](int32_t g) {
        return std::vector<int32_t>(ofs.face_vertices.begin() + ofs.face_offsets[g], ofs.face_vertices.begin() + ofs.face_offsets[g + 1]);
    };
    int32_t o = 0;
    for (int32_t g = 0; g < F; ++g) {
        const auto& c = f.faces[g];
        const int32_t n = static_cast<int32_t>(c.size());
        for (int32_t k = 0; k < n; ++k) {
            const int32_t ck = c[k], next = c[(k + 1) % n], prev = c[(k + n - 1) % n];
            if (s == Scheme::Loop)
                CHECK(corners_of(4 * g + k) == std::vector<int32_t>{ck, mid(ck, next), mid(prev, ck)});
            else
                CHECK(corners_of(o + k) == std::vector<int32_t>{ck, mid(ck, next), V + E + g, mid(prev, ck)});
        }
        if (s == Scheme::Loop) CHECK(corners_of(4 * g + 3) == std::vector<int32_t>{mid(c[0], c[1]), mid(c[1], c[2]), mid(c[2], c[0])});
        o += n;
    }
}

WingedEdgeMesh built(const IndexedMesh& m) { return WingedEdgeMesh::build(m); }

// Random meshes: a sphere or grid, edited by random Euler operations (joins make polygons
// of every size, flips and collapses change valences), compacted, positions jittered.
WingedEdgeMesh random_mesh(std::mt19937& rng, bool triangles) {
    std::uniform_int_distribution<int> pick(0, 3);
    const int kind = pick(rng);
    WingedEdgeMesh m = kind == 0 ? built(uv_sphere(5 + pick(rng), 4 + pick(rng)))
                       : kind == 1 ? built(grid(3 + pick(rng), 2 + pick(rng)))
                       : kind == 2 ? built(open_fan(3 + pick(rng)))
                                   : built(tetrahedron());
    for (int i = 0; i < 12; ++i) {
        const int32_t e = std::uniform_int_distribution<int32_t>(0, m.edge_count() - 1)(rng);
        if (m.is_deleted(Edge(e))) continue;
        const int op = pick(rng);
        if (!triangles && op == 0 && m.check(operation("join-faces", Edge(e))).ok) m.apply(operation("join-faces", Edge(e)));
        else if (op == 1 && m.check(operation("flip-edge", Edge(e))).ok) m.apply(operation("flip-edge", Edge(e)));
        else if (op == 2 && m.check(operation("collapse-edge", Edge(e))).ok) m.apply(operation("collapse-edge", Edge(e)));
        else if (!triangles && op == 3 && m.check(operation("split-edge", Edge(e))).ok) m.apply(operation("split-edge", Edge(e)));
    }
    m.compact();
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    for (int32_t v = 0; v < m.vertex_count(); ++v) m.set_position(v, m.position(v) + dvec3(jitter(rng), jitter(rng), jitter(rng)));
    return m;
}

} // namespace

TEST_CASE("Loop on the tetrahedron: one step worked by hand", "[subdivision]") {
    // beta(3) = (1/3)(5/8 - (3/8 - 1/8)^2) = 3/16. The four corners sum to 0, so a vertex
    // point is (1 - 9/16) v + 3/16 (-v) = v/4 and an edge point 3/8 (a + b) + 1/8 (c + d)
    // = 3/8 (a + b) - 1/8 (a + b) = (a + b)/4.
    CHECK(loop_beta(3) == Approx(3.0 / 16.0).epsilon(1e-15));
    const WingedEdgeMesh in = built(tetrahedron());
    const WingedEdgeMesh out = subdivide(in, Scheme::Loop, 1);
    const std::vector<double>& p = in.positions();
    for (int32_t v = 0; v < 4; ++v) CHECK(near(out.position(v), pos(p, v) / 4.0, 1.0, 1e-15));
    for (int32_t e = 0; e < 6; ++e)
        CHECK(near(out.position(4 + e), (pos(p, in.edge(e).start) + pos(p, in.edge(e).end)) / 4.0, 1.0, 1e-15));
    // Counts: V' = 4 + 6, E' = 12 + 12, F' = 16; chi = 2.
    CHECK(out.vertex_count() == 10);
    CHECK(out.edge_count() == 24);
    CHECK(out.face_count() == 16);
    CHECK(out.counts().euler() == 2);
    check_one_step(in, Scheme::Loop);
}

TEST_CASE("Catmull-Clark on the cube: one step worked by hand", "[subdivision]") {
    // The cube [0,1]^3, centre c = (1/2, 1/2, 1/2). Vertex (0,0,0), n = 3: 1/3 v + 1/9 (three
    // neighbours: (1,1,1)) + 1/9 (three face centres: (1,1,1)) = (2/9, 2/9, 2/9), i.e.
    // c + 5/9 (v - c). Edge (0,0,0)-(1,0,0), faces z = 0 and y = 0:
    // ((0,0,0) + (1,0,0) + (1/2,1/2,0) + (1/2,0,1/2))/4 = (1/2, 1/8, 1/8) = c + 3/4 (m - c),
    // m the edge's midpoint. Face points: the face centres.
    const WingedEdgeMesh in = built(cube());
    const WingedEdgeMesh out = subdivide(in, Scheme::CatmullClark, 1);
    const dvec3 c(0.5);
    CHECK(near(out.position(0), dvec3(2.0 / 9.0), 1.0, 1e-15));
    for (int32_t v = 0; v < 8; ++v) CHECK(near(out.position(v), c + 5.0 / 9.0 * (in.position(v) - c), 1.0, 1e-15));
    for (int32_t e = 0; e < 12; ++e) {
        const dvec3 m = 0.5 * (in.position(in.edge(e).start) + in.position(in.edge(e).end));
        CHECK(near(out.position(8 + e), c + 0.75 * (m - c), 1.0, 1e-15));
    }
    const IndexedMesh fs = in.face_set();
    for (int32_t f = 0; f < 6; ++f) {
        dvec3 sum(0.0);
        for (int32_t k = fs.face_offsets[f]; k < fs.face_offsets[f + 1]; ++k) sum += in.position(fs.face_vertices[k]);
        CHECK(near(out.position(20 + f), sum / 4.0, 1.0, 1e-15));
    }
    // Which edge point is which: edge (0,0,0)-(1,0,0) lands on (1/2, 1/8, 1/8).
    for (int32_t e = 0; e < 12; ++e)
        if (std::min(in.edge(e).start, in.edge(e).end) == 0 && std::max(in.edge(e).start, in.edge(e).end) == 1)
            CHECK(near(out.position(8 + e), dvec3(0.5, 0.125, 0.125), 1.0, 1e-15));
    CHECK(out.vertex_count() == 26);
    CHECK(out.edge_count() == 48);
    CHECK(out.face_count() == 24);
    check_one_step(in, Scheme::CatmullClark);
}

TEST_CASE("Limit positions: the tetrahedron (Loop) and the cube (Catmull-Clark) by hand, and convergence", "[subdivision]") {
    // Loop, n = 3: chi = 1/(3/(8 * 3/16) + 3) = 1/5; limit = (1 - 3/5) v + 1/5 (-v) = v/5.
    const WingedEdgeMesh tet = built(tetrahedron());
    const std::vector<double> lt = limit_positions(tet, Scheme::Loop);
    for (int32_t v = 0; v < 4; ++v) CHECK(near(pos(lt, v), tet.position(v) / 5.0, 1.0, 1e-14));
    // Catmull-Clark, cube corner (0,0,0), n = 3, on the points of one step: v1 = (2/9)(1,1,1),
    // edge points (1/2,1/8,1/8) and permutations (sum (3/4)(1,1,1)), face points (1/2,1/2,0)
    // and permutations (sum (1,1,1)): (9 v1 + 4 sum e + sum f)/24 = (2 + 3 + 1)/24 = 1/4.
    const WingedEdgeMesh cb = built(cube());
    const std::vector<double> lc = limit_positions(cb, Scheme::CatmullClark);
    CHECK(near(pos(lc, 0), dvec3(0.25), 1.0, 1e-14));
    for (int32_t v = 0; v < 8; ++v) CHECK(near(pos(lc, v), dvec3(0.5) + 0.5 * (cb.position(v) - dvec3(0.5)), 1.0, 1e-14));
    // Subdividing again and again, every old vertex approaches its limit position: the
    // distance after 7 steps is a small fraction of the distance after 1.
    std::mt19937 rng(16);
    for (int trial = 0; trial < 6; ++trial) {
        const Scheme s = trial % 2 ? Scheme::CatmullClark : Scheme::Loop;
        const WingedEdgeMesh m = random_mesh(rng, s == Scheme::Loop);
        const std::vector<double> lim = limit_positions(m, s);
        const WingedEdgeMesh one = subdivide(m, s, 1), many = subdivide(m, s, 6);
        for (int32_t v = 0; v < m.vertex_count(); ++v) {
            const double d1 = glm::length(one.position(v) - pos(lim, v)), d6 = glm::length(many.position(v) - pos(lim, v));
            INFO("trial " << trial << " vertex " << v << " d1 " << d1 << " d6 " << d6);
            CHECK(d6 <= 0.1 * d1 + 1e-12);
        }
    }
}

TEST_CASE("Random meshes: positions by the formulas, numbering, counts, validate, chi", "[subdivision]") {
    std::mt19937 rng(2016);
    for (int trial = 0; trial < 300; ++trial) {
        const bool tri = trial % 2 == 0;
        const WingedEdgeMesh m = random_mesh(rng, tri);
        INFO("trial " << trial);
        if (tri) check_one_step(m, Scheme::Loop);
        check_one_step(m, Scheme::CatmullClark);
    }
}

TEST_CASE("The input is untouched and several steps chain; a mesh with chosen face edges keeps its corner order", "[subdivision]") {
    const NamedMesh lecture = lecture_example();
    const WingedEdgeMesh in = WingedEdgeMesh::build(lecture.mesh, lecture.options);
    const WingedEdgeMesh copy = in;
    const WingedEdgeMesh two = subdivide(in, Scheme::CatmullClark, 2);
    CHECK(in.positions() == copy.positions());
    CHECK(in.version() == copy.version());
    const WingedEdgeMesh again = subdivide(subdivide(in, Scheme::CatmullClark, 1), Scheme::CatmullClark, 1);
    CHECK(two.positions() == again.positions());
    CHECK(two.validate().ok());
    check_one_step(in, Scheme::CatmullClark);
    // An isolated vertex (a build warning, not an error) stays where it is, in both schemes.
    IndexedMesh lonely = tetrahedron();
    lonely.add_vertex(5, 6, 7);
    const WingedEdgeMesh with_isolated = built(lonely);
    check_one_step(with_isolated, Scheme::Loop);
    check_one_step(with_isolated, Scheme::CatmullClark);
    CHECK(subdivide(with_isolated, Scheme::Loop, 2).position(4) == dvec3(5, 6, 7));
    const NamedMesh foley = foley_example(); // P2's walk starts at E2, not at its first corner
    check_one_step(WingedEdgeMesh::build(foley.mesh, foley.options), Scheme::CatmullClark);
}

TEST_CASE("Refusals: gaps, polygons for Loop, steps, limits", "[subdivision]") {
    const WingedEdgeMesh cb = built(cube());
    const CheckResult quads = check_subdivide(cb, Scheme::Loop, 1);
    CHECK(quads.code == "not-a-triangle-mesh");
    CHECK(quads.message.find("F1") != std::string::npos);
    CHECK_THROWS_AS(subdivide(cb, Scheme::Loop, 1), wingspline::Error);
    WingedEdgeMesh gaps = built(uv_sphere(6, 4));
    gaps.apply(operation("collapse-edge", Edge(3)));
    CHECK(check_subdivide(gaps, Scheme::Loop, 1).code == "mesh-has-gaps");
    CHECK(check_subdivide(cb, Scheme::CatmullClark, -1).code == "invalid-argument");
    CHECK(check_subdivide(cb, Scheme::CatmullClark, 17).code == "invalid-argument");
    // 24 * 4^7 = 393,216 faces > 200,000: refused, saying how many.
    const CheckResult big = check_subdivide(cb, Scheme::CatmullClark, 8, kSubdivisionLimits);
    CHECK(big.code == "too-large");
    CHECK(big.message.find("393,216 faces") != std::string::npos);
    CHECK(check_subdivide(cb, Scheme::CatmullClark, 7, kSubdivisionLimits).ok); // 98,304 faces
    CHECK_THROWS_AS(scheme_from_name("butterfly"), wingspline::Error);
}

TEST_CASE("Masks: weights sum to 1, applied they give the fast step's positions", "[subdivision]") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 100; ++trial) {
        const Scheme s = trial % 2 ? Scheme::CatmullClark : Scheme::Loop;
        const WingedEdgeMesh m = random_mesh(rng, s == Scheme::Loop);
        const SubdivisionSteps st = subdivision_steps(m, s);
        const WingedEdgeMesh out = subdivide(m, s, 1);
        REQUIRE(st.masks.count() == out.vertex_count());
        const double sc = scale_of(m.positions());
        for (int32_t i = 0; i < st.masks.count(); ++i) {
            double sum = 0;
            for (int32_t k = st.masks.offsets[i]; k < st.masks.offsets[i + 1]; ++k) sum += st.masks.weights[k];
            CHECK(sum == Approx(1.0).margin(1e-14));
            CHECK(near(pos(st.positions, i), out.position(i), sc));
        }
        const Masks lm = limit_masks(m, s);
        for (int32_t i = 0; i < lm.count(); ++i) {
            double sum = 0;
            for (int32_t k = lm.offsets[i]; k < lm.offsets[i + 1]; ++k) sum += lm.weights[k];
            CHECK(sum == Approx(1.0).margin(1e-14));
        }
        CHECK(st.phases.size() == 4);
        CHECK(st.phases[3].count == out.face_count());
    }
}

TEST_CASE("Symmetric inputs stay symmetric; similarity transforms commute with a step", "[subdivision]") {
    // Every old vertex of the cube (and the tetrahedron) stays equidistant from the centre,
    // and so do all edge points and all face points, after each of three steps.
    for (const Scheme s : {Scheme::CatmullClark, Scheme::Loop}) {
        const WingedEdgeMesh in = built(s == Scheme::Loop ? tetrahedron() : cube());
        const dvec3 c = s == Scheme::Loop ? dvec3(0.0) : dvec3(0.5);
        const WingedEdgeMesh out = subdivide(in, s, 3);
        const double r0 = glm::length(out.position(0) - c);
        for (int32_t v = 0; v < in.vertex_count(); ++v) CHECK(glm::length(out.position(v) - c) == Approx(r0).epsilon(1e-13));
        const WingedEdgeMesh one = subdivide(in, s, 1);
        const double re = glm::length(one.position(in.vertex_count()) - c);
        for (int32_t e = 0; e < in.edge_count(); ++e)
            CHECK(glm::length(one.position(in.vertex_count() + e) - c) == Approx(re).epsilon(1e-13));
    }
    // subdivide(T(M)) = T(subdivide(M)) for T = scale * rotation + translation, at scales
    // from 1e-6 to 1e6, tolerance relative to the transformed mesh's size.
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 40; ++trial) {
        const Scheme s = trial % 2 ? Scheme::CatmullClark : Scheme::Loop;
        const WingedEdgeMesh m = random_mesh(rng, s == Scheme::Loop);
        const double scale = std::pow(10.0, (trial % 5) * 3 - 6);
        const dvec3 axis = glm::normalize(dvec3(u(rng), u(rng), u(rng)) + dvec3(0, 0, 2));
        const double angle = 3 * u(rng);
        const dvec3 shift = scale * dvec3(u(rng), u(rng), u(rng)) * 10.0;
        const auto T = [&](dvec3 p) {
            // Rodrigues' rotation, then scale and shift.
            const dvec3 r = p * std::cos(angle) + glm::cross(axis, p) * std::sin(angle) + axis * glm::dot(axis, p) * (1 - std::cos(angle));
            return scale * r + shift;
        };
        WingedEdgeMesh moved = m;
        for (int32_t v = 0; v < m.vertex_count(); ++v) moved.set_position(v, T(m.position(v)));
        const WingedEdgeMesh a = subdivide(moved, s, 1), b = subdivide(m, s, 1);
        const double sc = scale_of(moved.positions());
        for (int32_t v = 0; v < a.vertex_count(); ++v) CHECK(near(a.position(v), T(b.position(v)), sc, 1e-13));
    }
}

// ------------------------------------------------------------------ curves

namespace {
using namespace wingspline::curves;

// The curve's point at t (inside its domain).
std::vector<double> point_at(const CurveEvaluator& ev, double t) {
    const std::vector<double> u = ev.checked_params(&t, 1);
    std::vector<double> out(static_cast<std::size_t>(ev.dim()));
    ev.evaluate(u.data(), 1, 0, out.data());
    return out;
}

std::vector<double> polygon(std::mt19937& rng, int n, int dim) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> p(static_cast<std::size_t>(n * dim));
    for (double& x : p) x = u(rng);
    return p;
}
} // namespace

TEST_CASE("Cubic curve subdivision is knot insertion at the middle of every span", "[subdivision][curves]") {
    // A closed polygon P_0..P_(n-1) as the open uniform cubic B-spline of the wrapped points
    // W_i = P_(i mod n), i = 0..n+5, knots 0..n+9, domain [3, n+6]. Boehm's insertion of the
    // middle of every span of the domain gives 2n+9 points over knots of spacing 1/2 inside
    // the domain; the ones whose support [t_j, t_(j+4)] lies inside it are the uniform
    // refinement's points: Q_(3+k) = the closed step's point 4 + k (mod 2n), its V_2, E_2, ...
    std::mt19937 rng(3);
    for (int n : {3, 4, 5, 8, 13}) {
        const std::vector<double> P = polygon(rng, n, 2);
        Curve c;
        c.kind = CurveKind::BSpline;
        c.dim = 2;
        c.degree = 3;
        for (int i = 0; i < n + 6; ++i) c.points.insert(c.points.end(), {P[2 * (i % n)], P[2 * (i % n) + 1]});
        for (int j = 0; j <= n + 9; ++j) c.knots.push_back(j);
        for (int span = 3; span < n + 6; ++span) c = insert_knot(c, span + 0.5).curve;
        const std::vector<double> S = subdivide_curve(P, 2, CurveSubdivision::CubicBSpline, true, 1);
        REQUIRE(S.size() == static_cast<std::size_t>(4 * n));
        for (int k = 0; k <= 2 * n + 2; ++k) {
            const int j = 3 + k, i = (4 + k) % (2 * n);
            INFO("n " << n << " k " << k);
            CHECK(c.points[2 * j] == Approx(S[2 * i]).margin(1e-14));
            CHECK(c.points[2 * j + 1] == Approx(S[2 * i + 1]).margin(1e-14));
        }
    }
    // Open: the same uniform B-spline (knots 0..n+3, domain [3, n]) after inserting the middle
    // of every span is evaluated equal to the subdivided polygon's uniform B-spline with
    // knots of spacing 1/2 over the same domain (the polygon E_0, V_1, ..., E_(n-2)).
    for (int n : {4, 5, 9}) {
        const std::vector<double> P = polygon(rng, n, 3);
        Curve orig;
        orig.kind = CurveKind::BSpline, orig.dim = 3, orig.degree = 3, orig.points = P;
        for (int j = 0; j <= n + 3; ++j) orig.knots.push_back(j);
        Curve fine;
        fine.kind = CurveKind::BSpline, fine.dim = 3, fine.degree = 3;
        fine.points = subdivide_curve(P, 3, CurveSubdivision::CubicBSpline, false, 1);
        REQUIRE(fine.points.size() == static_cast<std::size_t>(3 * (2 * n - 3)));
        for (int j = 0; j < 2 * n - 3 + 4; ++j) fine.knots.push_back(3 + 0.5 * (j - 3) - 0.0);
        const CurveEvaluator a(orig), b(fine);
        for (int s = 0; s <= 50; ++s) {
            const double t = 3 + (n - 3) * s / 50.0;
            const std::vector<double> pa = point_at(a, t), pb = point_at(b, t);
            for (int k = 0; k < 3; ++k) CHECK(pa[k] == Approx(pb[k]).margin(1e-13));
        }
    }
}

TEST_CASE("Chaikin converges to the uniform quadratic B-spline, about 4x closer per step", "[subdivision][curves]") {
    // A closed polygon, so that no end is involved: its quadratic uniform B-spline is the
    // open one of the wrapped points P_0..P_(n-1), P_0, P_1 with knots 0..n+4, domain
    // [2, n+2]. The distance of a polygon's points to the curve is a second difference
    // (|P_(i-1) - 2 P_i + P_(i+1)|/4 at a vertex), which a step divides by about 4.
    std::mt19937 rng(5);
    for (int n : {4, 6, 10}) {
        const std::vector<double> P = polygon(rng, n, 2);
        Curve q;
        q.kind = CurveKind::BSpline, q.dim = 2, q.degree = 2, q.points = P;
        q.points.insert(q.points.end(), P.begin(), P.begin() + 4);
        for (int j = 0; j <= n + 4; ++j) q.knots.push_back(j);
        const CurveEvaluator ev(q);
        std::vector<double> curve;
        for (int s = 0; s <= 20000; ++s) {
            const std::vector<double> pt = point_at(ev, 2 + n * s / 20000.0);
            curve.insert(curve.end(), pt.begin(), pt.end());
        }
        const auto distance = [&](const std::vector<double>& poly) { // max over the polygon's points
            double worst = 0;
            for (std::size_t i = 0; i < poly.size(); i += 2) {
                double best = 1e300;
                for (std::size_t j = 0; j < curve.size(); j += 2)
                    best = std::min(best, std::hypot(poly[i] - curve[j], poly[i + 1] - curve[j + 1]));
                worst = std::max(worst, best);
            }
            return worst;
        };
        double previous = distance(P);
        for (int steps = 1; steps <= 4; ++steps) {
            const std::vector<double> S = subdivide_curve(P, 2, CurveSubdivision::Chaikin, true, steps);
            REQUIRE(S.size() == static_cast<std::size_t>(2 * n * (1 << steps)));
            const double d = distance(S);
            INFO("n " << n << " steps " << steps << " " << previous << " -> " << d);
            CHECK(d < previous / 3.0);
            if (steps >= 2) CHECK(d > previous / 5.0);
            previous = d;
        }
        // Open: n points give 2(n-1), the first 3/4 P_0 + 1/4 P_1 (no end rule).
        const std::vector<double> one = subdivide_curve(P, 2, CurveSubdivision::Chaikin, false, 1);
        CHECK(one.size() == static_cast<std::size_t>(4 * (n - 1)));
        CHECK(one[0] == Approx(0.75 * P[0] + 0.25 * P[2]).margin(1e-15));
    }
    CHECK_THROWS_AS(subdivide_curve({0, 0, 1, 1}, 2, CurveSubdivision::Chaikin, false, 1), wingspline::Error);
    CHECK_THROWS_AS(curve_subdivision_from_name("loop"), wingspline::Error);
}
