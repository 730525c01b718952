// Building in steps: WingedEdgeBuild runs build()'s phases one per step(); the
// mesh it gives is build()'s, table for table, and a face set build() refuses is refused by
// a step with the same report, after which the build is over.
#include <catch2/catch.hpp>

#include "wingspline/error.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/winged_edge.h"

#include <string>
#include <vector>

using namespace wingspline::mesh;

namespace {
bool same_tables(const WingedEdgeMesh& a, const WingedEdgeMesh& b) {
    if (a.positions() != b.positions() || a.vertex_edges() != b.vertex_edges() || a.face_edges() != b.face_edges()) return false;
    if (a.edges().size() != b.edges().size()) return false;
    for (std::size_t e = 0; e < a.edges().size(); ++e) {
        const EdgeRecord& x = a.edges()[e];
        const EdgeRecord& y = b.edges()[e];
        if (x.start != y.start || x.end != y.end || x.left != y.left || x.right != y.right || x.start_left != y.start_left ||
            x.start_right != y.start_right || x.end_left != y.end_left || x.end_right != y.end_right)
            return false;
    }
    return true;
}
} // namespace

TEST_CASE("a build in steps gives build()'s tables, phase by phase", "[mesh][build]") {
    const std::vector<IndexedMesh> meshes = {tetrahedron(), cube(), open_fan(5), grid(30, 20), uv_sphere(40, 21)};
    for (const IndexedMesh& m : meshes) {
        WingedEdgeBuild build(m);
        std::vector<std::string> phases;
        bool done = false;
        while (!done) {
            phases.emplace_back(build.phase());
            done = build.step();
        }
        CHECK(std::string(build.phase()) == "done");
        CHECK(phases == std::vector<std::string>{"counting sides", "bucketing sides", "pairing twins", "numbering edges",
                                                 "face wings", "boundary wings", "checks", "stored edges"});
        const WingedEdgeMesh stepped = build.take();
        CHECK(same_tables(stepped, WingedEdgeMesh::build(m)));
        CHECK(stepped.validate().ok());
    }
}

TEST_CASE("a face set build() refuses is refused by a step with the same report; the build is then over", "[mesh][build]") {
    // Three triangles on the edge v0 v1: not a 2-manifold, the winged edge cannot hold it.
    IndexedMesh m;
    for (int i = 0; i < 5; ++i) m.add_vertex(i, i * i, 0);
    m.add_face({0, 1, 2});
    m.add_face({1, 0, 3});
    m.add_face({0, 1, 4});
    std::string expected;
    try {
        WingedEdgeMesh::build(m);
    } catch (const InvalidMesh& e) {
        expected = e.what();
    }
    REQUIRE(!expected.empty());
    WingedEdgeBuild build(m);
    std::string got;
    try {
        while (!build.step()) {
        }
    } catch (const InvalidMesh& e) {
        got = e.what();
    }
    CHECK(got == expected);
    CHECK(std::string(build.phase()) == "done");
    bool over = false;
    try {
        build.step();
    } catch (const wingspline::Error& e) {
        over = std::string(e.code()) == "invalid-argument";
    }
    CHECK(over);
}
