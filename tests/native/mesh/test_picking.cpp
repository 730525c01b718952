// Picking and the display proxy of a big mesh, against analytic answers: the face
// of a unit-square grid under a point is floor(x) + nx floor(y); the nearest face of a sphere
// seen along n is the one around the direction n; and both answers stay the same when the
// mesh, the point and the radius are moved, turned and scaled together.
#include <catch2/catch.hpp>

#include "wingspline/error.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/view_geometry.h"
#include "wingspline/mesh/winged_edge.h"
#include "random_edits.h"

#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

using namespace wingspline::mesh;

namespace {
// nx x ny unit squares in z = 0, face j nx + i = [i, i+1] x [j, j+1], CCW seen from +z.
IndexedMesh square_grid(int32_t nx, int32_t ny) {
    IndexedMesh m;
    for (int32_t j = 0; j <= ny; ++j)
        for (int32_t i = 0; i <= nx; ++i) m.positions.insert(m.positions.end(), {double(i), double(j), 0.0});
    const auto id = [&](int32_t i, int32_t j) { return j * (nx + 1) + i; };
    for (int32_t j = 0; j < ny; ++j)
        for (int32_t i = 0; i < nx; ++i) m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    return m;
}

// A random rotation (from a random unit quaternion), scale and move.
struct Similarity {
    glm::dmat3 R{1.0};
    double s = 1;
    glm::dvec3 t{0.0};
    glm::dvec3 point(const glm::dvec3& p) const { return s * (R * p) + t; }
    glm::dvec3 direction(const glm::dvec3& d) const { return R * d; }
};
Similarity random_similarity(std::mt19937& rng) {
    std::normal_distribution<double> g;
    double q[4];
    double len = 0;
    for (double& x : q) x = g(rng), len += x * x;
    len = std::sqrt(len);
    const double w = q[0] / len, x = q[1] / len, y = q[2] / len, z = q[3] / len;
    Similarity S;
    // Columns of the rotation matrix of the unit quaternion (w, x, y, z).
    S.R = glm::dmat3(glm::dvec3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)),
                     glm::dvec3(2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)),
                     glm::dvec3(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)));
    S.s = std::pow(10.0, std::uniform_real_distribution<double>(-6, 6)(rng));
    S.t = glm::dvec3(g(rng), g(rng), g(rng)) * std::pow(10.0, std::uniform_real_distribution<double>(-3, 3)(rng));
    return S;
}
IndexedMesh mapped(IndexedMesh m, const Similarity& S) {
    for (std::size_t v = 0; 3 * v < m.positions.size(); ++v) {
        const glm::dvec3 p = S.point({m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]});
        m.positions[3 * v] = p.x, m.positions[3 * v + 1] = p.y, m.positions[3 * v + 2] = p.z;
    }
    return m;
}
} // namespace

TEST_CASE("the face under a point of a square grid is floor(x) + nx floor(y), moved, turned and scaled", "[mesh][pick]") {
    constexpr int32_t nx = 7, ny = 5;
    std::mt19937 rng(17017);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        const Similarity S = trial == 0 ? Similarity{} : random_similarity(rng);
        const WingedEdgeMesh mesh = WingedEdgeMesh::build(mapped(square_grid(nx, ny), S));
        // A point at least 1e-3 of a square away from every side (so floor() is the answer),
        // seen from the front (+z) or from behind (-z), at any height on the line of sight.
        const int32_t i = static_cast<int32_t>(u(rng) * nx), j = static_cast<int32_t>(u(rng) * ny);
        const glm::dvec3 p(i + 0.001 + 0.998 * u(rng), j + 0.001 + 0.998 * u(rng), 10 * (u(rng) - 0.5));
        const double side = trial % 2 ? -1.0 : 1.0;
        const PickResult r = pick_faces(mesh, S.point(p), S.direction({0, 0, side}), 0, 8);
        REQUIRE(r.face == j * nx + i);
        REQUIRE(r.near.size() == 1);
        CHECK(r.near[0].face == r.face);
        CHECK(r.near[0].distance == 0);
    }
}

TEST_CASE("a point beside the grid finds the boundary face within the radius, at the right distance", "[mesh][pick]") {
    std::mt19937 rng(4242);
    for (int trial = 0; trial < 500; ++trial) {
        const Similarity S = random_similarity(rng);
        const WingedEdgeMesh mesh = WingedEdgeMesh::build(mapped(square_grid(4, 3), S));
        // 0.25 to the right of square (3, 1): outside, the nearest side is x = 4 of face 7.
        const glm::dvec3 p(4.25, 1.5, 0);
        const PickResult wide = pick_faces(mesh, S.point(p), S.direction({0, 0, 1}), 0.3 * S.s, 4);
        CHECK(wide.face == -1);
        REQUIRE(wide.near.size() == 1);
        CHECK(wide.near[0].face == 7);
        // Relative to the size of the coordinates compared: the move t can be 1e9 times the
        // square's side, and the distance comes from coordinates of size |t| + s.
        CHECK(std::abs(wide.near[0].distance - 0.25 * S.s) <= 1e-9 * S.s + 1e-12 * (glm::length(S.t) + S.s));
        const PickResult narrow = pick_faces(mesh, S.point(p), S.direction({0, 0, 1}), 0.2 * S.s, 4);
        CHECK(narrow.face == -1);
        CHECK(narrow.near.empty());
    }
}

TEST_CASE("the nearest face of a sphere seen along n is the one around n, not the one behind it", "[mesh][pick]") {
    const IndexedMesh sphere = uv_sphere(24, 13);
    const WingedEdgeMesh mesh = WingedEdgeMesh::build(sphere);
    std::mt19937 rng(99);
    std::normal_distribution<double> g;
    for (int trial = 0; trial < 1000; ++trial) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        // The line through the centre along n meets the sphere twice; the viewer at +n sees
        // the face around n. Its centroid is within one face of n: 360/24 = 15 degrees
        // across, so the angle is below 15 degrees (cos > 0.96).
        const PickResult r = pick_faces(mesh, {0, 0, 0}, n, 0, 1);
        REQUIRE(r.face >= 0);
        glm::dvec3 c(0.0);
        const std::vector<int32_t> corners = mesh.vertices_of_face(r.face);
        for (int32_t v : corners) c += mesh.position(v);
        c /= double(corners.size());
        CHECK(glm::dot(glm::normalize(c), n) > 0.96);
    }
}

TEST_CASE("picking refuses a zero direction, a negative radius and a non-finite point", "[mesh][pick]") {
    const WingedEdgeMesh mesh = WingedEdgeMesh::build(cube());
    const auto code = [&](auto&& call) {
        try {
            call();
        } catch (const wingspline::Error& e) {
            return std::string(e.code());
        }
        return std::string("none");
    };
    CHECK(code([&] { pick_faces(mesh, {0, 0, 0}, {0, 0, 0}, 0, 1); }) == "invalid-argument");
    CHECK(code([&] { pick_faces(mesh, {0, 0, 0}, {0, 0, 1}, -1, 1); }) == "invalid-argument");
    CHECK(code([&] { pick_faces(mesh, {NAN, 0, 0}, {0, 0, 1}, 0, 1); }) == "invalid-argument");
    CHECK(code([&] { display_proxy(mesh, 0); }) == "invalid-argument");
}

TEST_CASE("a mesh under the target is its own proxy: its fan triangles, its positions", "[mesh][proxy]") {
    const IndexedMesh m = cube();
    const DisplayProxy p = display_proxy(WingedEdgeMesh::build(m), 100);
    CHECK(p.cell == 0);
    CHECK(p.positions == m.positions);
    REQUIRE(p.triangles.size() == 3 * 12); // 6 quads, 2 fan triangles each
    for (std::size_t f = 0; f < 6; ++f) {
        // Each quad's triangles are its corners 0 1 2 and 0 2 3, in some rotation of the
        // face's corners (the walk starts at the face's stored edge).
        const int32_t* t = &p.triangles[6 * f];
        CHECK(t[0] == t[3]);
        CHECK(t[2] == t[4]);
    }
}

TEST_CASE("the proxy of a 100k-face sphere: about the target, valid, and on the sphere within a cell", "[mesh][proxy]") {
    for (const double s : {1e-6, 1.0, 1e6}) {
        IndexedMesh m = uv_sphere(250, 201);
        for (double& x : m.positions) x *= s;
        const DisplayProxy p = display_proxy(WingedEdgeMesh::build(m), 20000);
        const std::size_t T = p.triangles.size() / 3;
        CHECK(T >= 20000 / 4);
        CHECK(T <= 20000 * 3 / 2);
        REQUIRE(p.cell > 0);
        const std::size_t V = p.positions.size() / 3;
        for (std::size_t t = 0; t < T; ++t) {
            const int32_t a = p.triangles[3 * t], b = p.triangles[3 * t + 1], c = p.triangles[3 * t + 2];
            REQUIRE((a >= 0 && b >= 0 && c >= 0));
            REQUIRE((std::size_t(a) < V && std::size_t(b) < V && std::size_t(c) < V));
            REQUIRE((a != b && b != c && c != a));
        }
        // A mean of points of the sphere of radius s in one cell lies inside the sphere and
        // within a cell diagonal of its surface.
        for (std::size_t v = 0; v < V; ++v) {
            const double r = glm::length(glm::dvec3(p.positions[3 * v], p.positions[3 * v + 1], p.positions[3 * v + 2]));
            CHECK(r <= s * (1 + 1e-6)); // coordinates rounded to 6 decimals: |p| within sqrt(3) 5e-7 of 1
            CHECK(r >= s * (1 - 1e-6) - std::sqrt(3.0) * p.cell);
        }
    }
}

TEST_CASE("a point on a side or a corner shared by faces of the grid is inside exactly one of them", "[mesh][pick]") {
    // Exact arithmetic (integer and half-integer coordinates, the identity view): the
    // crossing-number test is half-open, so every point inside the grid's outline finds a
    // face, and it is one of the faces that touch the point.
    constexpr int32_t nx = 5, ny = 4;
    const WingedEdgeMesh mesh = WingedEdgeMesh::build(square_grid(nx, ny));
    const auto touching = [&](double x, double y, int32_t f) {
        const int32_t i = f % nx, j = f / nx;
        return x >= i && x <= i + 1 && y >= j && y <= j + 1;
    };
    int checked = 0;
    for (int32_t a = 1; a < 2 * nx; ++a) {
        for (int32_t b = 1; b < 2 * ny; ++b) {
            const double x = a / 2.0, y = b / 2.0; // corners, side midpoints and centres
            for (const double side : {1.0, -1.0}) {
                const PickResult r = pick_faces(mesh, {x, y, 0}, {0, 0, side}, 0, 4);
                REQUIRE(r.face >= 0);
                CHECK(touching(x, y, r.face));
                ++checked;
            }
        }
    }
    CHECK(checked == 2 * (2 * nx - 1) * (2 * ny - 1));
}

TEST_CASE("a strip thinner than a cell is its own proxy rather than an empty one", "[mesh][proxy]") {
    // 300 x 1 unit squares: clustering for 50 triangles would use cells wider than the strip
    // and keep almost no triangle; the mesh itself comes back (cell 0, 600 fan triangles).
    const DisplayProxy p = display_proxy(WingedEdgeMesh::build(square_grid(300, 1)), 50);
    CHECK(p.cell == 0);
    CHECK(p.triangles.size() == 3 * 600);
}

namespace {
bool same_pick(const PickResult& a, const PickResult& b) {
    if (a.face != b.face || a.near.size() != b.near.size()) return false;
    for (std::size_t i = 0; i < a.near.size(); ++i)
        if (a.near[i].face != b.near[i].face || a.near[i].distance != b.near[i].distance) return false;
    return true;
}
} // namespace

TEST_CASE("the pick grid answers exactly as pick_faces: 12,000 random picks on spheres, grids and edited meshes, moved, turned and scaled", "[mesh][pick]") {
    std::mt19937 rng(2026);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int compared = 0, hits = 0, nears = 0;
    for (int trial = 0; trial < 24; ++trial) {
        const Similarity S = trial < 2 ? Similarity{} : random_similarity(rng);
        const IndexedMesh base = trial % 3 == 0 ? uv_sphere(24, 13) : trial % 3 == 1 ? grid(17, 11) : square_grid(9, 7);
        WingedEdgeMesh w = WingedEdgeMesh::build(mapped(base, S));
        // Edits leave gaps, new elements and moved vertices (split edge, poke), as on the page.
        for (int k = 0; k < 40 && trial % 2 == 1; ++k) {
            const auto call = wingspline::test_edits::random_call(w, rng);
            const Operation op = wingspline::test_edits::operation_of(call);
            if (w.check(op).ok) w.apply(op);
        }
        const BoundingBox box = bounding_box(w);
        const glm::dvec3 centre = box.centre();
        const double size = glm::length(box.max - box.min);
        PickGrid picker;
        for (int view = 0; view < 5; ++view) {
            // The slide's view along +z, then random directions (a view exactly along an axis too).
            const glm::dvec3 towards = view == 0 ? S.direction({0, 0, 1}) : view == 1 ? glm::dvec3(1, 0, 0) : glm::dvec3(unit(rng), unit(rng), unit(rng));
            REQUIRE_FALSE(picker.fits(w, towards));
            picker.build(w, towards);
            REQUIRE(picker.fits(w, towards));
            for (int p = 0; p < 100; ++p) {
                // Points over the mesh and around it (some far outside), radii from 0 to a tenth of its size.
                const glm::dvec3 point = centre + (p % 5 == 0 ? 0.8 : 0.3) * size * glm::dvec3(unit(rng), unit(rng), unit(rng));
                const double radius = p % 4 == 0 ? 0.0 : 0.1 * size * std::abs(unit(rng));
                const PickResult brute = pick_faces(w, point, towards, radius, 12);
                const PickResult fast = picker.pick(w, point, radius, 12);
                INFO("trial " << trial << " view " << view << " pick " << p);
                REQUIRE(same_pick(brute, fast));
                ++compared, hits += brute.face >= 0, nears += brute.near.size() > 1;
            }
        }
    }
    CHECK(compared == 12000);
    // The cases are not all misses: most hit a face, many find several near.
    INFO("hits " << hits << " nears " << nears);
    CHECK(hits > 3000);
    CHECK(nears > 1500);
}

TEST_CASE("the pick grid must be built again after an edit or for another view, and refuses what pick_faces refuses", "[mesh][pick]") {
    WingedEdgeMesh w = WingedEdgeMesh::build(uv_sphere(16, 9));
    PickGrid picker;
    const glm::dvec3 towards{0.3, 0.2, 1.0};
    picker.build(w, towards);
    CHECK(picker.fits(w, towards));
    CHECK_FALSE(picker.fits(w, {0.3, 0.2, 1.1}));
    REQUIRE(w.check(Operation{find_operation("flip-edge"), {5}}).ok);
    w.apply(Operation{find_operation("flip-edge"), {5}});
    CHECK_FALSE(picker.fits(w, towards));
    CHECK_THROWS_AS(picker.build(w, {0, 0, 0}), wingspline::Error);
    picker.build(w, towards);
    CHECK_THROWS_AS(picker.pick(w, {0, 0, 0}, -1, 4), wingspline::Error);
    CHECK_THROWS_AS(picker.pick(w, {std::nan(""), 0, 0}, 0.1, 4), wingspline::Error);
    CHECK(picker.bytes() > 0);
}
