#pragma once
// Subdivision surfaces on the winged edge: Loop's scheme (triangle meshes) and
// Catmull-Clark's (any polygons), one step built directly as a new winged edge by index
// arithmetic (no search, no hash map): the point of lecture 000's "aim for efficiency in
// implementing subdivision rules". Boundaries follow the cubic B-spline curve rules.
//
// Numbering of one step's result (docs/api-mesh.md, "Subdivision"):
//  * vertices: old vertex v keeps v (moved), the point on edge e is V + e, Catmull-Clark's
//    point of face f is V + E + f;
//  * edges: old edge e becomes 2e (S -> edge point) and 2e + 1 (edge point -> E), same
//    direction; then the inner edges of each face in face order: Loop 2E + 3f + k (from the
//    point of side k to the point of side k-1), Catmull-Clark 2E + o_f + k (from the point
//    of side k to the face point), o_f = the corners of the faces before f;
//  * faces: Loop 4f + k is the triangle at corner k of face f, 4f + 3 the middle one;
//    Catmull-Clark o_f + k is the quad at corner k. Corner k and side k (corner k ->
//    corner k+1) are as face_set() lists face f.
// The input must have no gaps (compact() it first): "old vertex v keeps v" has no meaning
// for a numbering with holes.
#include "wingspline/mesh/limits.h"
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

enum class Scheme { Loop, CatmullClark };
const char* scheme_name(Scheme s); // "loop", "catmull-clark"
// Throws Error("unknown-scheme") for anything else.
Scheme scheme_from_name(const std::string& name);

// Loop's original vertex weight for valence n: (1/n)(5/8 - (3/8 + cos(2 pi / n)/4)^2).
double loop_beta(int32_t n);

// V, E, F of the mesh after `steps` steps (int64: a refusal must be able to say the number).
struct SubdivisionCounts {
    int64_t vertices = 0, edges = 0, faces = 0;
};
// Refuses (nothing is built): "unknown-scheme", "mesh-has-gaps", "not-a-triangle-mesh"
// (Loop; the message names the first face that is not a triangle), "invalid-argument"
// (steps outside 0..16), "too-large" (the result would exceed `limits`: the message says
// how many faces it would have).
CheckResult check_subdivide(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps,
                            const MeshLimits& limits = kUnlimitedCounts);
SubdivisionCounts subdivision_counts(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps);

// A new mesh, `steps` steps finer; the input is untouched. Throws Error(code, message) for
// what check_subdivide refuses. validate() is clean on the result.
WingedEdgeMesh subdivide(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps = 1,
                         const MeshLimits& limits = kUnlimitedCounts);

// A mask: the old vertices a new position averages and their weights (sum 1), CSR over
// the new positions (offsets has one entry more than there are positions).
struct Masks {
    std::vector<int32_t> offsets{0};
    std::vector<int32_t> vertices;
    std::vector<double> weights;
    int32_t count() const { return static_cast<int32_t>(offsets.size()) - 1; }
    // Appends one mask (repeated vertices merged, kept in first-appearance order).
    void add(const std::vector<std::pair<int32_t, double>>& terms);
    glm::dvec3 apply(int32_t i, const std::vector<double>& positions) const;
};

// What each new position is, by the rule that made it (the lesson labels the stencil).
enum class PointRule : int32_t {
    FacePoint = 0,      // Catmull-Clark: the centroid of the face
    EdgeInterior = 1,   // Loop 3/8, 3/8, 1/8, 1/8; Catmull-Clark (S + E + two face points)/4
    EdgeBoundary = 2,   // the midpoint (cubic B-spline edge rule)
    VertexInterior = 3, // Loop (1 - n beta, beta ...); Catmull-Clark ((n-2)/n, 1/n^2 ...)
    VertexBoundary = 4, // 1/8, 6/8, 1/8 along the boundary (cubic B-spline vertex rule)
    VertexIsolated = 5, // a vertex on no edge stays
};
inline constexpr int32_t kPointRuleCount = 6;
// "face-point", "edge-interior", "edge-boundary", "vertex-interior", "vertex-boundary",
// "vertex-isolated" (the names the JS API gives the rules).
const char* point_rule_name(int32_t rule);

// One step as the lecture reads it, by the reference path (ring and face walks of
// winged_edge.h): the phases in order (face points, edge points, vertex points,
// reconnection), the mask of every new position (indexed as the result's vertices), the
// rule and, for vertex points, the valence. `result` is subdivide(mesh, scheme, 1).
struct SubdivisionSteps {
    Scheme scheme = Scheme::Loop;
    struct Phase {
        std::string name; // "face-points", "edge-points", "vertex-points", "reconnection"
        int32_t first = 0, count = 0; // the new vertices it makes (reconnection: the faces)
    };
    std::vector<Phase> phases;
    Masks masks;                     // one per vertex of the result
    std::vector<int32_t> rules;      // PointRule per vertex of the result
    std::vector<int32_t> valences;   // per old vertex: edges at it
    std::vector<double> positions;   // the masks applied to the old positions
    WingedEdgeMesh result;
};
SubdivisionSteps subdivision_steps(const WingedEdgeMesh& mesh, Scheme scheme);

// The reconnection phase as pointer assignments, for step-by-step playback as the edit
// panel plays an operation: every entry of the next level's three tables written once, in
// the order a person can follow the lecture's "connect the new points":
//   line 0: each old edge e split in two: 2e from S to the edge point, 2e + 1 from the edge
//           point to E (their S and E);
//   line 1: each old face f, in face order: its new faces take an edge (face table);
//   line 2: ... its inner edges: S, E, L, R and the four wings;
//   line 3: ... the halves of its sides: on the side that faces f, the face and two wings;
//   line 4: the halves on the boundary: the two wings on the side with no face;
//   line 5: every vertex of the next level takes an edge (vertex table).
// Each step's `phase` indexes `lines`; `source[i]` is the old element step i belongs to (an
// old edge for lines 0 and 4, an old face for lines 1-3, -1 for line 5). `before` is -1 for
// every step (the next level's tables start empty); entries that stay -1 (no face on a
// boundary side) are not assigned. `result` is subdivide(mesh, scheme, 1).
struct ReconnectionPlayback {
    std::vector<std::string> lines;
    std::vector<AssignmentStep> steps;
    std::vector<int32_t> source;
};
ReconnectionPlayback reconnection_playback(const WingedEdgeMesh& mesh, Scheme scheme, const WingedEdgeMesh& result);

// Where each vertex goes in the limit (3 per vertex), and the limit masks.
//  * Loop, interior vertex of valence n: (1 - n chi) v + chi sum(neighbours),
//    chi = 1 / (3 / (8 beta) + n) (Loop 1987; Hoppe et al. 1994);
//  * Catmull-Clark, interior: (n^2 v1 + 4 sum e1_j + sum f1_j) / (n (n + 5)) on the points
//    of one step (v1 the vertex point, e1_j its edge points, f1_j its face points: after one
//    step every face is a quad, where the formula holds; Halstead et al. 1993);
//  * boundary vertex (both): (1/6, 4/6, 1/6) along the boundary (the cubic B-spline's limit);
//  * isolated vertex: stays.
Masks limit_masks(const WingedEdgeMesh& mesh, Scheme scheme);
std::vector<double> limit_positions(const WingedEdgeMesh& mesh, Scheme scheme);

} // namespace wingspline::mesh
