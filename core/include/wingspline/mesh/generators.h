#pragma once
// Named meshes: the lecture's example (000), Foley's two polygons (001), and generated
// solids, grids and spheres of any size (docs/benchmarks.md defines the grid and the sphere).
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/winged_edge.h"

namespace wingspline::mesh {

// A mesh plus the numbering that makes it match a slide.
struct NamedMesh {
    IndexedMesh mesh;
    BuildOptions options;
};

// Lecture 000: v1..v5 at (0,1) (1,0) (1,2) (2,1) (2,-1), z = 0; F1 = (v1 v2 v3),
// F2 = (v2 v4 v3), F3 = (v2 v5 v4), CCW; edges e1..e7, vertex and face edges as on the slide.
NamedMesh lecture_example();
// Lecture 001: V1..V4, P1 = (1, 2, 4), P2 = (4, 2, 3); edges E1..E5 in Foley's order.
NamedMesh foley_example();

IndexedMesh tetrahedron();                // 4 triangles, CCW seen from outside
IndexedMesh cube();                       // 6 quads on [0,1]^3, CCW seen from outside
IndexedMesh open_fan(int32_t n);          // n triangles around vertex 0, spanning 270 degrees
// docs/benchmarks.md grid: height field z = 0.1 sin(7x/nx) cos(5y/ny) on [0,2] x [0,1], nx x ny quads,
// each split (v00, v10, v11), (v00, v11, v01); coordinates rounded to 6 decimals.
IndexedMesh grid(int32_t nx, int32_t ny);
// docs/benchmarks.md sphere: radius 1, vertex 0 the north pole, the last vertex the south pole,
// slices x stacks, F = 2 slices (stacks - 1), triangles CCW from outside; 6 decimals.
IndexedMesh uv_sphere(int32_t slices, int32_t stacks);

} // namespace wingspline::mesh
