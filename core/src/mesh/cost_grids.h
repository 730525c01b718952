#pragma once
// Costs against mesh size (edit_costs.h, queries.h): the same element asked on
// docs/benchmarks.md grids of n x n quads (F = 2 n^2 triangles, n even), and the count at
// any size from three small grids. Internal to the core's mesh sources.
#include "wingspline/error.h"
#include "wingspline/mesh/tables.h"
#include "wingspline/mesh/winged_edge.h"

#include <array>
#include <cstdint>
#include <string>

namespace wingspline::mesh::cost_grids {

// The sizes the counts are fitted through, and the fourth that checks the fit.
constexpr std::array<int32_t, 3> kFit{8, 16, 24};
constexpr int32_t kCheck = 32;

inline void require_even(int32_t n) {
    if (n < 2 || n % 2 != 0 || n > 4000)
        throw Error("invalid-argument", "a cost grid has an even number of quads across, 2 to 4000, not " + std::to_string(n));
}

// The grid's middle element of a kind: the vertex at row n/2, column n/2 (interior, valence
// 6), the edge from it to its right-hand neighbour, the face F/2 + n: the same neighbourhood
// at every even n.
inline int32_t middle(ElementKind kind, const WingedEdgeMesh& grid, int32_t n) {
    const int32_t vertex = (n / 2) * (n + 1) + n / 2;
    if (kind == ElementKind::Vertex) return vertex;
    if (kind == ElementKind::Face) return grid.face_count() / 2 + n;
    for (const int32_t e : grid.edges_around_vertex(vertex))
        if (grid.edge(e).start + grid.edge(e).end == 2 * vertex + 1) return e;
    return kNone;
}

// A count that is a whole-number quadratic in n (a scan over the vertex, edge or face table
// reads a fixed number of entries per element; V, E and F are quadratics in n), from its
// values y at kFit: Newton's divided differences in steps of h = 8, exact in integers,
// y(n) = y0 + d1 (n - 8)/h + d2 (n - 8)(n - 16)/(2 h^2). Throws Error("internal-error") when
// the values are not such a quadratic's.
inline int64_t quadratic_at(const std::array<int64_t, 3>& y, int64_t n) {
    const int64_t h = 8, d1 = y[1] - y[0], d2 = y[2] - 2 * y[1] + y[0];
    const int64_t twice = 2 * h * h * y[0] + 2 * h * d1 * (n - 8) + d2 * (n - 8) * (n - 16);
    if (twice % (2 * h * h) != 0) throw Error("internal-error", "the measured costs are not a whole-number quadratic in n");
    return twice / (2 * h * h);
}

} // namespace wingspline::mesh::cost_grids
