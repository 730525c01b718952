// Exercise kind "subdivide": the exact stencils and the checks of a student's mask and counts.
// Expected values: the lecture's masks worked by hand in this file (Loop 3/8, 3/8, 1/8, 1/8;
// beta(n) from its formula with the exact cosines; the boundary's 1/2, 1/2 and 1/8, 6/8, 1/8;
// Catmull-Clark's face, edge and vertex points expanded onto the corners by plain loops over
// the face set), invariants (the weights sum to exactly 1) and the subdivided mesh itself
// (each stencil applied to the old positions is the new position subdivide() computes).
//
// Tolerance: kPositionTolerance * s, s the largest coordinate magnitude of the input (the
// mesh's length unit): a stencil applied in doubles and the fast step differ by a few
// roundings of numbers below s.
#include <catch2/catch.hpp>

#include "wingspline/error.h"
#include "wingspline/mesh/exercise_subdivide.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/subdivision.h"
#include "wingspline/mesh/winged_edge.h"

#include <map>
#include <random>
#include <set>

using namespace wingspline::mesh;

namespace {

constexpr double kPositionTolerance = 1e-12;

WingedEdgeMesh mesh_of(const IndexedMesh& m) { return WingedEdgeMesh::build(m); }

// The lecture's example as the subdivision lesson builds it (its own numbering, not the
// slide's): v1..v5, F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4).
//
//        v3 ---- v4
//       /  \ F2 / \
//      / F1 \  / F3\
//    v1 ---- v2 ---- v5    (v5 below: the fan opens around v2)
WingedEdgeMesh lecture_mesh() { return mesh_of(lecture_example().mesh); }

int32_t edge_between(const WingedEdgeMesh& m, int32_t a, int32_t b) {
    for (int32_t e = 0; e < m.edge_count(); ++e)
        if ((m.edge(e).start == a && m.edge(e).end == b) || (m.edge(e).start == b && m.edge(e).end == a)) return e;
    FAIL("no edge between the two vertices");
    return kNone;
}

// A stencil as a map vertex -> weight, for comparison with one worked by hand.
std::map<int32_t, Fraction> as_map(const SubdivideStencil& s) {
    std::map<int32_t, Fraction> out;
    for (std::size_t i = 0; i < s.vertices.size(); ++i) out[s.vertices[i]] = s.weights[i];
    return out;
}

bool same(const std::map<int32_t, Fraction>& a, const std::map<int32_t, Fraction>& b) { return a == b; }

Fraction sum_of(const SubdivideStencil& s) {
    Fraction t;
    for (const Fraction& w : s.weights) t = t + w;
    return t;
}

SubdivideMaskAnswer right_answer(const SubdivideStencil& s) {
    return {static_cast<int32_t>(s.rule), s.vertices, s.weights};
}

// Catmull-Clark's rules expanded by plain loops over the face set (not the winged edge's walks).
std::map<int32_t, Fraction> cc_by_faces(const IndexedMesh& m, NewPoint point, int32_t element, int32_t a = kNone, int32_t b = kNone) {
    std::map<int32_t, Fraction> out;
    auto face_point = [&](int32_t f, const Fraction& scale) {
        const int32_t n = m.face_offsets[f + 1] - m.face_offsets[f];
        for (int32_t k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) out[m.face_vertices[k]] = out[m.face_vertices[k]] + scale / Fraction(n);
    };
    // Face f has the side a-b (a and b next to each other around it, either way).
    auto has_side = [&](int32_t f, int32_t p, int32_t q) {
        const int32_t n = m.face_offsets[f + 1] - m.face_offsets[f];
        for (int32_t k = 0; k < n; ++k) {
            const int32_t x = m.face_vertices[m.face_offsets[f] + k], y = m.face_vertices[m.face_offsets[f] + (k + 1) % n];
            if ((x == p && y == q) || (x == q && y == p)) return true;
        }
        return false;
    };
    if (point == NewPoint::Face) {
        face_point(element, Fraction(1));
    } else if (point == NewPoint::Edge) { // the interior edge a-b: (a + b + two face points) / 4
        out[a] = out[a] + Fraction(1, 4);
        out[b] = out[b] + Fraction(1, 4);
        for (int32_t f = 0; f < m.face_count(); ++f)
            if (has_side(f, a, b)) face_point(f, Fraction(1, 4));
    } else { // interior vertex v of valence n: (n-2)/n v + 1/n^2 (neighbours + face points)
        const int32_t v = element;
        std::set<int32_t> neighbours;
        std::vector<int32_t> faces;
        for (int32_t f = 0; f < m.face_count(); ++f) {
            const int32_t n = m.face_offsets[f + 1] - m.face_offsets[f];
            for (int32_t k = 0; k < n; ++k)
                if (m.face_vertices[m.face_offsets[f] + k] == v) {
                    faces.push_back(f);
                    neighbours.insert(m.face_vertices[m.face_offsets[f] + (k + 1) % n]);
                    neighbours.insert(m.face_vertices[m.face_offsets[f] + (k + n - 1) % n]);
                }
        }
        const int64_t n = static_cast<int64_t>(neighbours.size());
        out[v] = out[v] + Fraction(n - 2, n);
        for (int32_t u : neighbours) out[u] = out[u] + Fraction(1, n * n);
        for (int32_t f : faces) face_point(f, Fraction(1, n * n));
    }
    return out;
}

// A random mesh to subdivide: a sphere, a grid, a fan or a cube, with random flips
// (valences change) and, for Catmull-Clark, joined faces (polygons of any size).
WingedEdgeMesh random_exercise_mesh(std::mt19937& rng, bool triangles) {
    std::uniform_int_distribution<int> small(0, 3);
    const int kind = small(rng);
    WingedEdgeMesh m = mesh_of(kind == 0 ? uv_sphere(4 + small(rng), 3 + small(rng))
                               : kind == 1 ? grid(2 + small(rng), 2 + small(rng))
                               : kind == 2 || triangles ? open_fan(3 + small(rng))
                                                        : cube());
    const int32_t tries = 6 + small(rng);
    for (int32_t i = 0; i < tries; ++i) {
        const Edge e(std::uniform_int_distribution<int32_t>(0, m.edge_count() - 1)(rng));
        if (m.is_deleted(e)) continue;
        const auto op = operation(triangles || small(rng) < 2 ? "flip-edge" : "join-faces", e);
        if (m.check(op).ok) m.apply(op);
    }
    m.compact();
    std::uniform_real_distribution<double> move(-0.1, 0.1);
    for (int32_t v = 0; v < m.vertex_count(); ++v) m.set_position(v, m.position(v) + glm::dvec3(move(rng), move(rng), move(rng)));
    return m;
}

// Every text a check gave, and whether one holds `value` (a weight "3/8", a count "26").
bool any_finding_says(const std::vector<SubdivideFinding>& findings, const std::string& value) {
    for (const auto& f : findings)
        if (f.text.find(value) != std::string::npos || f.hint.find(value) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_CASE("Fractions stay exact and in lowest terms", "[exercise][subdivide]") {
    CHECK(Fraction(6, 16) == Fraction(3, 8));
    CHECK(Fraction(3, -8) == Fraction(-3, 8));
    CHECK((Fraction(3, 8) + Fraction(3, 8) + Fraction(1, 8) + Fraction(1, 8)) == Fraction(1));
    CHECK(Fraction(1, 3).text() == "1/3");
    CHECK(Fraction(4, 2).text() == "2");
    CHECK_THROWS_AS(Fraction(1, 0), wingspline::Error);
}

TEST_CASE("Loop's beta exactly: the formula with cos(2 pi / n) for n = 3, 4, 6", "[exercise][subdivide]") {
    // beta(n) = (1/n)(5/8 - (3/8 + cos(2 pi/n)/4)^2), worked by hand:
    //  n = 3: cos = -1/2, 3/8 - 1/8 = 1/4, 5/8 - 1/16 = 9/16, / 3 = 3/16
    //  n = 4: cos = 0, (3/8)^2 = 9/64, 5/8 - 9/64 = 31/64, / 4 = 31/256
    //  n = 6: cos = 1/2, 3/8 + 1/8 = 1/2, 5/8 - 1/4 = 3/8, / 6 = 1/16 (the regular valence)
    CHECK(loop_beta_exact(3) == Fraction(3, 16));
    CHECK(loop_beta_exact(4) == Fraction(31, 256));
    CHECK(loop_beta_exact(6) == Fraction(1, 16));
    for (int32_t n : {3, 4, 6}) CHECK(loop_beta_exact(n).value() == Approx(loop_beta(n)).epsilon(1e-15));
    for (int32_t n : {5, 7, 8, 12}) {
        CHECK_THROWS_WITH(loop_beta_exact(n), Catch::Contains("valence " + std::to_string(n)));
    }
}

TEST_CASE("Stencils on the lecture's mesh: Loop's interior and boundary masks by hand", "[exercise][subdivide]") {
    const WingedEdgeMesh m = lecture_mesh();
    const int32_t v1 = 0, v2 = 1, v3 = 2, v4 = 3, v5 = 4;
    // v2-v3 lies between F1 and F2: 3/8 of each end, 1/8 of v1 (opposite in F1) and v4 (in F2).
    const SubdivideStencil inner = exact_stencil(m, Scheme::Loop, NewPoint::Edge, edge_between(m, v2, v3));
    CHECK(inner.rule == PointRule::EdgeInterior);
    CHECK(same(as_map(inner), {{v2, Fraction(3, 8)}, {v3, Fraction(3, 8)}, {v1, Fraction(1, 8)}, {v4, Fraction(1, 8)}}));
    // v1-v2 is on the boundary: its midpoint.
    const SubdivideStencil rim = exact_stencil(m, Scheme::Loop, NewPoint::Edge, edge_between(m, v1, v2));
    CHECK(rim.rule == PointRule::EdgeBoundary);
    CHECK(same(as_map(rim), {{v1, Fraction(1, 2)}, {v2, Fraction(1, 2)}}));
    // v2 is on the boundary between v1 and v5: 1/8, 6/8, 1/8 (v3 and v4 are not used).
    const SubdivideStencil corner = exact_stencil(m, Scheme::Loop, NewPoint::Vertex, v2);
    CHECK(corner.rule == PointRule::VertexBoundary);
    CHECK(same(as_map(corner), {{v1, Fraction(1, 8)}, {v2, Fraction(6, 8)}, {v5, Fraction(1, 8)}}));
    // Loop has no face points.
    CHECK_THROWS_WITH(exact_stencil(m, Scheme::Loop, NewPoint::Face, 0), Catch::Contains("no face points"));
    // No such elements.
    CHECK_THROWS_WITH(exact_stencil(m, Scheme::Loop, NewPoint::Edge, 7), Catch::Contains("e8"));
    CHECK_THROWS_WITH(exact_stencil(m, Scheme::Loop, NewPoint::Vertex, -1), Catch::Contains("vertex"));
}

TEST_CASE("Stencils on the tetrahedron (Loop, valence 3) and the cube (Catmull-Clark) by hand", "[exercise][subdivide]") {
    const WingedEdgeMesh t = mesh_of(tetrahedron());
    for (int32_t v = 0; v < 4; ++v) { // 1 - 3 beta(3) = 7/16 and 3/16 for each neighbour
        const SubdivideStencil s = exact_stencil(t, Scheme::Loop, NewPoint::Vertex, v);
        CHECK(s.rule == PointRule::VertexInterior);
        std::map<int32_t, Fraction> want{{v, Fraction(7, 16)}};
        for (int32_t u = 0; u < 4; ++u)
            if (u != v) want[u] = Fraction(3, 16);
        CHECK(same(as_map(s), want));
    }
    const IndexedMesh cube_faces = cube();
    const WingedEdgeMesh c = mesh_of(cube_faces);
    for (int32_t f = 0; f < 6; ++f) { // a face point: 1/4 of each corner
        const SubdivideStencil s = exact_stencil(c, Scheme::CatmullClark, NewPoint::Face, f);
        CHECK(s.rule == PointRule::FacePoint);
        std::map<int32_t, Fraction> want;
        for (int32_t k = cube_faces.face_offsets[f]; k < cube_faces.face_offsets[f + 1]; ++k) want[cube_faces.face_vertices[k]] = Fraction(1, 4);
        CHECK(same(as_map(s), want));
    }
    for (int32_t v = 0; v < 8; ++v) {
        // n = 3: v gets 1/3 + 3 (1/9)(1/4) = 5/12; an edge neighbour 1/9 + 2 (1/9)(1/4) = 1/6;
        // the far corner of each face around v (1/9)(1/4) = 1/36 ... and the cube's opposite
        // corner nothing.
        const SubdivideStencil s = exact_stencil(c, Scheme::CatmullClark, NewPoint::Vertex, v);
        CHECK(s.rule == PointRule::VertexInterior);
        const auto got = as_map(s);
        CHECK(got.at(v) == Fraction(5, 12));
        int sixths = 0, thirty_sixths = 0;
        for (const auto& [u, w] : got) sixths += w == Fraction(1, 6), thirty_sixths += w == Fraction(1, 36);
        CHECK(sixths == 3);
        CHECK(thirty_sixths == 3);
        CHECK(got.size() == 7);
        CHECK(same(got, cc_by_faces(cube_faces, NewPoint::Vertex, v)));
    }
    for (int32_t e = 0; e < 12; ++e) {
        // (S + E + two face points)/4: each end 1/4 + 2 (1/4)(1/4) = 3/8, the two far
        // corners of each face (1/4)(1/4) = 1/16.
        const SubdivideStencil s = exact_stencil(c, Scheme::CatmullClark, NewPoint::Edge, e);
        CHECK(s.rule == PointRule::EdgeInterior);
        const auto got = as_map(s);
        CHECK(got.at(c.edge(e).start) == Fraction(3, 8));
        CHECK(got.at(c.edge(e).end) == Fraction(3, 8));
        CHECK(got.size() == 6);
        CHECK(same(got, cc_by_faces(cube_faces, NewPoint::Edge, e, c.edge(e).start, c.edge(e).end)));
    }
}

TEST_CASE("Random meshes: every stencil sums to exactly 1 and gives subdivide()'s position", "[exercise][subdivide]") {
    std::mt19937 rng(2026);
    int64_t points = 0, irrational = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const bool loop = trial % 2 == 0;
        const Scheme scheme = loop ? Scheme::Loop : Scheme::CatmullClark;
        const WingedEdgeMesh m = random_exercise_mesh(rng, loop);
        const WingedEdgeMesh next = subdivide(m, scheme, 1);
        const IndexedMesh faces = m.face_set();
        double s = 0;
        for (double x : m.positions()) s = std::max(s, std::abs(x));
        const int32_t V = m.vertex_count(), E = m.edge_count();
        auto check_point = [&](NewPoint p, int32_t element, int32_t new_vertex) {
            SubdivideStencil st;
            try {
                st = exact_stencil(m, scheme, p, element);
            } catch (const wingspline::Error& err) {
                REQUIRE(err.code() == "no-exact-mask"); // Loop's beta at valence 5, 7, ... or an isolated vertex
                ++irrational;
                return;
            }
            ++points;
            REQUIRE(sum_of(st) == Fraction(1));
            glm::dvec3 at(0.0);
            for (std::size_t i = 0; i < st.vertices.size(); ++i) at += st.weights[i].value() * m.position(st.vertices[i]);
            const glm::dvec3 want = next.position(new_vertex);
            REQUIRE(std::abs(at.x - want.x) <= kPositionTolerance * s);
            REQUIRE(std::abs(at.y - want.y) <= kPositionTolerance * s);
            REQUIRE(std::abs(at.z - want.z) <= kPositionTolerance * s);
            // An interior Catmull-Clark point is also what the face set's loops give.
            if (!loop && st.rule != PointRule::VertexBoundary && st.rule != PointRule::EdgeBoundary)
                REQUIRE(same(as_map(st), p == NewPoint::Edge ? cc_by_faces(faces, p, element, m.edge(element).start, m.edge(element).end)
                                                             : cc_by_faces(faces, p, element)));
        };
        for (int32_t v = 0; v < V; ++v) check_point(NewPoint::Vertex, v, v);
        for (int32_t e = 0; e < E; ++e) check_point(NewPoint::Edge, e, V + e);
        if (!loop)
            for (int32_t f = 0; f < m.face_count(); ++f) check_point(NewPoint::Face, f, V + E + f);
    }
    CAPTURE(points, irrational);
    CHECK(points > 2000);
    CHECK(irrational > 0); // the random Loop meshes do have vertices of valence 5 or 7
}

TEST_CASE("The mask check: the right answer passes; every wrong weight, missing point, stray point and wrong mask is named without its value",
          "[exercise][subdivide]") {
    std::mt19937 rng(11);
    int64_t corruptions = 0;
    for (int trial = 0; trial < 30; ++trial) {
        const bool loop = trial % 2 == 0;
        const Scheme scheme = loop ? Scheme::Loop : Scheme::CatmullClark;
        const WingedEdgeMesh m = trial < 2 ? lecture_mesh() : random_exercise_mesh(rng, loop);
        const int32_t V = m.vertex_count();
        std::vector<std::pair<NewPoint, int32_t>> asked;
        for (int32_t v = 0; v < V; ++v) asked.emplace_back(NewPoint::Vertex, v);
        for (int32_t e = 0; e < m.edge_count(); ++e) asked.emplace_back(NewPoint::Edge, e);
        if (!loop)
            for (int32_t f = 0; f < m.face_count(); ++f) asked.emplace_back(NewPoint::Face, f);
        for (const auto& [p, element] : asked) {
            SubdivideStencil st;
            try {
                st = exact_stencil(m, scheme, p, element);
            } catch (const wingspline::Error&) {
                continue;
            }
            const SubdivideMaskAnswer right = right_answer(st);
            REQUIRE(check_subdivide_mask(m, scheme, p, element, right).empty());
            const auto no_value = [&](const std::vector<SubdivideFinding>& fs) {
                for (const Fraction& w : st.weights) REQUIRE_FALSE(any_finding_says(fs, w.text()));
            };
            // The rows in another order, and a stray point given weight 0, are right too.
            SubdivideMaskAnswer turned = right;
            std::reverse(turned.vertices.begin(), turned.vertices.end());
            std::reverse(turned.weights.begin(), turned.weights.end());
            REQUIRE(check_subdivide_mask(m, scheme, p, element, turned).empty());
            for (int32_t u = 0; u < V; ++u) {
                if (std::find(st.vertices.begin(), st.vertices.end(), u) != st.vertices.end()) continue;
                SubdivideMaskAnswer zero = right;
                zero.vertices.push_back(u);
                zero.weights.push_back(Fraction(0));
                REQUIRE(check_subdivide_mask(m, scheme, p, element, zero).empty());
                SubdivideMaskAnswer stray = right;
                stray.vertices.push_back(u);
                stray.weights.push_back(Fraction(1, 8));
                const auto fs = check_subdivide_mask(m, scheme, p, element, stray);
                REQUIRE(fs.size() == 1);
                REQUIRE(fs[0].code == "not-in-stencil");
                REQUIRE(fs[0].row == static_cast<int32_t>(right.vertices.size()));
                REQUIRE(fs[0].text.find(vertex_label(u)) != std::string::npos);
                no_value(fs);
                ++corruptions;
                break; // one stray point per question is enough
            }
            for (std::size_t i = 0; i < st.vertices.size(); ++i) {
                const std::string name = vertex_label(st.vertices[i]);
                SubdivideMaskAnswer wrong = right;
                wrong.weights[i] = wrong.weights[i] + Fraction(1, 16);
                auto fs = check_subdivide_mask(m, scheme, p, element, wrong);
                REQUIRE(fs.size() == 1);
                REQUIRE(fs[0].code == "wrong-weight");
                REQUIRE(fs[0].row == static_cast<int32_t>(i));
                REQUIRE(fs[0].vertex == st.vertices[i]);
                REQUIRE(fs[0].text.find(name) != std::string::npos);
                REQUIRE(fs[0].text.find("row " + std::to_string(i + 1)) != std::string::npos);
                no_value(fs);
                SubdivideMaskAnswer missing = right;
                missing.vertices.erase(missing.vertices.begin() + static_cast<std::ptrdiff_t>(i));
                missing.weights.erase(missing.weights.begin() + static_cast<std::ptrdiff_t>(i));
                fs = check_subdivide_mask(m, scheme, p, element, missing);
                REQUIRE(fs.size() == 1);
                REQUIRE(fs[0].code == "missing-point");
                REQUIRE(fs[0].vertex == st.vertices[i]);
                REQUIRE(fs[0].text.find(name + " is missing") != std::string::npos);
                no_value(fs);
                corruptions += 2;
            }
            for (int32_t rule = 0; rule < kPointRuleCount; ++rule) {
                if (rule == static_cast<int32_t>(st.rule)) continue;
                SubdivideMaskAnswer other = right;
                other.rule = rule;
                const auto fs = check_subdivide_mask(m, scheme, p, element, other);
                REQUIRE(fs.size() == 1);
                REQUIRE(fs[0].code == "wrong-mask");
                no_value(fs);
                // The mask's name is not given away either: the text names no mask.
                REQUIRE(fs[0].text.find("interior edge mask") == std::string::npos);
                REQUIRE(fs[0].text.find("boundary vertex mask") == std::string::npos);
                ++corruptions;
            }
            SubdivideMaskAnswer none = right;
            none.rule = kNone;
            const auto fs = check_subdivide_mask(m, scheme, p, element, none);
            REQUIRE(fs.size() == 1);
            REQUIRE(fs[0].code == "no-mask");
        }
    }
    CAPTURE(corruptions);
    CHECK(corruptions > 3000);
}

TEST_CASE("The mask check names rows that name no vertex or repeat one, and refuses a malformed answer", "[exercise][subdivide]") {
    const WingedEdgeMesh m = lecture_mesh();
    const int32_t e = edge_between(m, 1, 2);
    const SubdivideStencil st = exact_stencil(m, Scheme::Loop, NewPoint::Edge, e);
    SubdivideMaskAnswer a = right_answer(st);
    a.vertices.push_back(8);
    a.weights.push_back(Fraction(0));
    auto fs = check_subdivide_mask(m, Scheme::Loop, NewPoint::Edge, e, a);
    REQUIRE(fs.size() == 1);
    CHECK(fs[0].code == "not-a-vertex");
    CHECK(fs[0].text == "Row 5 names v9, but the old mesh has vertices v1 to v5.");
    a = right_answer(st);
    a.vertices.push_back(a.vertices[0]);
    a.weights.push_back(Fraction(0));
    fs = check_subdivide_mask(m, Scheme::Loop, NewPoint::Edge, e, a);
    REQUIRE(fs.size() == 1);
    CHECK(fs[0].code == "repeated-point");
    CHECK(fs[0].text.find("Row 1 and row 5 both name " + vertex_label(a.vertices[0])) == 0);
    a = right_answer(st);
    a.weights.pop_back();
    CHECK_THROWS_WITH(check_subdivide_mask(m, Scheme::Loop, NewPoint::Edge, e, a), Catch::Contains("one weight per point"));
    // The wrong-weight sentence with the mask right: where, the role, the rule, no value.
    a = right_answer(st);
    const std::size_t opposite = static_cast<std::size_t>(std::find(a.vertices.begin(), a.vertices.end(), 0) - a.vertices.begin());
    a.weights[opposite] = Fraction(3, 8);
    fs = check_subdivide_mask(m, Scheme::Loop, NewPoint::Edge, e, a);
    REQUIRE(fs.size() == 1);
    CHECK(fs[0].text == "The weight of v1 (row " + std::to_string(opposite + 1) + ") in the edge point of " + edge_label(e) +
                            " is not right: v1 is the corner of F1 opposite " + edge_label(e) +
                            ", and an interior Loop edge point weighs the edge's two ends alike, and more than the two corners opposite "
                            "the edge. Re-read the interior edge mask of Loop's scheme.");
    CHECK_FALSE(fs[0].hint.empty());
}

TEST_CASE("The counts check: V, E, F after one step, each wrong count named without its value", "[exercise][subdivide]") {
    // Loop on the tetrahedron: V' = V + E = 10, E' = 2E + 3F = 24, F' = 4F = 16.
    const WingedEdgeMesh t = mesh_of(tetrahedron());
    CHECK(check_subdivide_counts(t, Scheme::Loop, 1, 10, 24, 16).empty());
    // Catmull-Clark on the cube: V' = V + E + F = 26, E' = 2E + (corners) = 48, F' = corners = 24.
    const WingedEdgeMesh c = mesh_of(cube());
    CHECK(check_subdivide_counts(c, Scheme::CatmullClark, 1, 26, 48, 24).empty());
    // Two steps on the cube: 26 + 48 + 24 = 98, 2 * 48 + 4 * 24 = 192, 4 * 24 = 96.
    CHECK(check_subdivide_counts(c, Scheme::CatmullClark, 2, 98, 192, 96).empty());
    const char* names[3] = {"vertices", "edges", "faces"};
    const int64_t right[3] = {26, 48, 24};
    for (int k = 0; k < 3; ++k) {
        int64_t given[3] = {26, 48, 24};
        given[k] += 1;
        const auto fs = check_subdivide_counts(c, Scheme::CatmullClark, 1, given[0], given[1], given[2]);
        REQUIRE(fs.size() == 1);
        CHECK(fs[0].code == "wrong-count");
        CHECK(fs[0].count == k);
        CHECK(fs[0].text.find(std::string("number of ") + names[k]) != std::string::npos);
        CHECK_FALSE(any_finding_says(fs, std::to_string(right[k])));
    }
    const auto blank = check_subdivide_counts(c, Scheme::CatmullClark, 1, kNone, 48, 24);
    REQUIRE(blank.size() == 1);
    CHECK(blank[0].text.find("missing") != std::string::npos);
    CHECK_THROWS_WITH(check_subdivide_counts(c, Scheme::Loop, 1, 1, 1, 1), Catch::Contains("triangle"));
    CHECK_THROWS_WITH(check_subdivide_counts(c, Scheme::CatmullClark, 5, 1, 1, 1), Catch::Contains("1 to 4 steps"));
}
