#pragma once
// The named corpus the table exercises' tests check against (test_exercise_tables.cpp,
// test_exercise_half_edge.cpp): the lecture's and Foley's meshes, a cube (quads), a
// tetrahedron, a 5x4 sphere, open fans of 1..6 triangles and grids of 1..4 by 1..3 quads split
// into triangles.
#include "wingspline/mesh/generators.h"

#include <vector>

namespace wingspline::test_exercises {

inline std::vector<mesh::IndexedMesh> exercise_fixtures() {
    using namespace wingspline::mesh;
    std::vector<IndexedMesh> m = {lecture_example().mesh, foley_example().mesh, cube(), tetrahedron(), uv_sphere(5, 4)};
    for (int n = 1; n <= 6; ++n) m.push_back(open_fan(n));
    for (int nx = 1; nx <= 4; ++nx)
        for (int ny = 1; ny <= 3; ++ny) m.push_back(grid(nx, ny));
    return m;
}

} // namespace wingspline::test_exercises
