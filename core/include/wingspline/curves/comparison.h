#pragma once
// The measurements of the comparison lesson (lectures 001, 003: the representations' table,
// basis conversion, affine and perspective invariance) and the convex hull of a control
// polygon. Lessons used to compute these in JavaScript; they ask the core now and keep only
// the wording (docs/api-curves.md, "Comparison measurements").
//
// Every tolerance is relative to the size of what is compared, so a verdict does not change
// when the points are scaled, translated or rotated:
//   kHullTolerance           orientation test of the hull, relative to extent^2
//   kInterpolationTolerance  "the curve passes through P_i", relative to the extent
//   kWeightTolerance         blending weights (unitless already)
// where extent = the larger side of the axis-aligned bounding box of the points compared.
#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/curve.h"

#include <array>

#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::curves {

// ---- convex hull of plane points (Andrew's monotone chain)
// Three points count as collinear when |cross(b - a, c - a)| <= kHullTolerance * extent^2
// (cross has units of area); a point within that of an edge is not a hull vertex.
constexpr double kHullTolerance = 1e-12; // unitless, relative to extent^2

struct ConvexHull {
    std::vector<int32_t> indices; // hull vertices as indices into the input, counter-clockwise,
                                  // starting at the lowest-x (then lowest-y) point; no repeats.
                                  // 1 distinct point: 1 index; all collinear: the 2 ends
    double tolerance = 0;         // the collinearity threshold used (world units^2)
};
// points[2*i + k] (dim 2). Throws 'invalid-points' (odd length), 'non-finite-input' (names
// the point).
ConvexHull convex_hull(const std::vector<double>& points);

// ---- maps of the plane (lecture 001 "Invariance", lecture 002 perspective and NURBS)
// x' = (a x + b y + tx) / w, y' = (c x + d y + ty) / w, w = px x + py y + 1. The linear part
// [a b; c d] = scale * rotation(angle) * shear, shear = [1 shear; 0 1]. px = py = 0: affine.
struct PlaneMap {
    double a = 1, b = 0, c = 0, d = 1, tx = 0, ty = 0, px = 0, py = 0;
};
// angle in degrees. Throws 'non-finite-input' naming the parameter.
PlaneMap plane_map(bool perspective, double angle_degrees, double scale, double shear, double tx, double ty,
                   double px, double py);

struct MappedPoints {
    std::vector<double> points; // points'[2*i + k]
    std::vector<double> w;      // w(P_i), the homogeneous coordinate: the weight a rational
                                // curve needs to follow the map exactly (lecture 002)
};
// dim must be 2. A point with w <= 0 lies behind the eye: Error('perspective-behind-eye')
// naming it as `what` + index (e.g. "P3"), its coordinates and w. A mapped point that
// overflows (w tiny) is Error('non-finite-result'), named the same way.
MappedPoints map_points(const std::vector<double>& points, int dim, const PlaneMap& map,
                        const std::string& what = "point ");

// ---- distances
struct MaxDistance {
    double distance = 0; // max_j |a_j - b_j| (world units); 0 for no points
    int32_t index = -1;  // the j where it is reached (-1: no points)
};
// a, b: the same number of points of dimension dim (1..3), e.g. two curves sampled at the
// same parameters. Throws 'invalid-argument' (sizes), 'non-finite-input' (names the entry).
MaxDistance max_distance(const std::vector<double>& a, const std::vector<double>& b, int dim);

// n evenly spaced parameters over the curve's domain, the first and last exactly the ends
// (the lessons' sampling).
std::vector<double> domain_params(const Curve& curve, int n);

// ---- the comparison table's measurements (segments: the family's pieces, joints between
// consecutive entries; each sampled at `samples` parameters over its own domain)
constexpr double kWeightTolerance = 1e-12;       // unitless
constexpr double kInterpolationTolerance = 1e-9; // relative to the extent of points and curve

// Convex hull row: the blending weights of the control POINTS (lecture 003: >= 0, sum 1).
struct BlendingWeightCheck {
    double tangent_weight = 0;  // largest |weight| of a tangent vector (Hermite), else 0
    bool weights_points = true; // false: tangent weights exceed kWeightTolerance -> "N/A"
    double min_weight = 0;      // smallest weight of a point at any sample
    double min_weight_at = 0;   // the parameter of its first occurrence (the segment's own parameter)
    double sum_error = 0;       // largest |sum of the points' weights - 1|
    bool convex_hull = false;   // weights_points, min_weight >= -tol and sum_error <= tol
    double tolerance = kWeightTolerance;
};
BlendingWeightCheck blending_weight_check(const std::vector<Curve>& segments, int samples);

// Interpolation rows: distance from every control point to the sampled curve (segment ends
// included exactly); a point is interpolated when its distance <= tolerance.
struct PointCurveDistances {
    std::vector<double> distances;
    std::vector<int32_t> interpolated; // ascending
    int32_t farthest = -1;             // the control point farthest from the curve
    int32_t nearest_missed = -1;       // the nearest one that is not interpolated (-1: none)
    double tolerance = 0;              // kInterpolationTolerance * extent (world units)
};
PointCurveDistances point_curve_distances(const std::vector<double>& points, int dim,
                                          const std::vector<Curve>& segments, int samples);

// Subdivision row: every cubic segment (bezier of any degree; hermite, uniform bspline and
// catmull-rom segments of one window, converted to Bezier with q = M_B^-1 M G) split at
// u = 1/2 by de Casteljau; both halves evaluated at v = 0, 1/4, 1/2, 3/4, 1 against the
// original at the matching parameters. error: the largest distance (world units).
struct SplitCheck {
    double error = 0;
    int segments = 0;
};
SplitCheck split_check(const std::vector<Curve>& segments);

// The non-uniform B-spline's refinement (Boehm): one knot in the middle of every non-empty
// span; the refined curve evaluated at `samples` parameters against the original.
struct KnotRefinementCheck {
    double error = 0;
    int inserted = 0;
    int points_before = 0;
    int points_after = 0;
};
KnotRefinementCheck knot_refinement_check(const Curve& curve, int samples);

// ---- the Hermite family of the comparison table, "with tangents from the points": the
// Catmull-Rom conditions of lecture 002, t_i = (P_i+1 - P_i-1) / 2 inside, and the one-sided
// chords P_1 - P_0, P_K-1 - P_K-2 at the ends. points[dim*i + k]; at least 2 points
// ('too-few-points'), finite ('non-finite-input' naming the point).
std::vector<double> catmull_rom_tangents(const std::vector<double>& points, int dim);

// ---- bicubic patches (lecture 002, the surfaces lesson): corners and joins.
// tolerance = k * extent + kPatchRounding * (largest |coordinate|) of the sampled surface
// points: relative to the surface's size, plus the evaluation's rounding, which grows with
// the coordinates (16 terms of 1 ulp each, with margin), so a corner or a shared boundary
// 1e9 patch sizes from the origin is still recognised and a gap of 1e-6 sizes still seen.
constexpr double kCornerTolerance = 1e-12;            // unitless, times the extent
constexpr double kJoinTolerance = 1e-9;               // unitless, times the extent (positions and p_u, both lengths)
constexpr double kPatchRounding = 64 * 2.220446049250313e-16; // 64 ulp, times the largest |coordinate|

// The corners p(0,0), p(0,1), p(1,0), p(1,1) against the net entries holding them (Bezier:
// p00 p03 p30 p33, entries 0 3 12 15; Hermite: the top-left block, entries 0 1 4 5).
struct PatchCornerCheck {
    std::array<int32_t, 4> entry{};
    std::array<double, 4> distance{};
    std::array<bool, 4> interpolated{};
    double tolerance = 0; // world units
};
PatchCornerCheck patch_corner_check(BasisKind kind, const std::vector<double>& net);

// Patch A's u = 1 edge against patch B's u = 0 edge, sampled at `samples` values of v:
// the largest position gap and p_u gap; C0 / C1 when they are within tolerance.
struct PatchJoinCheck {
    double position_gap = 0;
    double du_gap = 0;
    bool c0 = false;
    bool c1 = false;
    double tolerance = 0; // world units
};
PatchJoinCheck patch_join_check(BasisKind kind, const std::vector<double>& a, const std::vector<double>& b, int samples);

// The same bicubic patch in another basis (hermite <-> bezier; lecture 002's q = M^-1 M_B P
// applied down every column, then along every row: Q = C P C^T, C = M_to^-1 M_from). Entries
// within kNetSnap times the largest |entry| of the input of zero are stored as 0 (rounding of
// an entry that is 0 exactly; the net shows and shares "0", not "1e-17").
constexpr double kNetSnap = 1e-14; // unitless, times the largest |entry|
std::vector<double> convert_patch_basis(const std::vector<double>& net, BasisKind from, BasisKind to);

} // namespace wingspline::curves
