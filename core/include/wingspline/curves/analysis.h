#pragma once
// Differential geometry of a curve (lecture 004: tangent vector; lectures 001/004:
// parametric and geometric continuity): tangent, curvature, arc length by Gauss-Legendre
// quadrature, arc-length reparameterisation, and the continuity at a joint.
#include "wingspline/curves/curve.h"

#include <string>
#include <vector>

namespace wingspline::curves {

struct CurvatureValues {
    std::vector<double> curvature;  // kappa = |P' x P''| / |P'|^3 (>= 0)
    std::vector<double> signed_curvature; // dim 2 only: (x'y'' - y'x'') / |P'|^3
    std::vector<double> speed;      // |P'|
    std::vector<double> tangent;    // unit tangent, dim per param (0 where the speed is 0)
    std::vector<unsigned char> singular; // 1 where |P'| = 0: tangent and curvature undefined (reported as 0)
};
CurvatureValues curvature(const Curve& curve, const std::vector<double>& params);

// The length of the curve between parameters a <= b (both in the domain): adaptive
// 10-point Gauss-Legendre on every polynomial piece, to a relative accuracy of about 1e-13.
double arc_length(const Curve& curve, double a, double b);

struct ArcLengthParams {
    std::vector<double> params;   // n parameters with equal arc length between neighbours
    std::vector<double> lengths;  // the arc length from the domain start to each of them
    double total = 0;
};
ArcLengthParams arc_length_params(const Curve& curve, int n);

// Continuity where curve a ends (its domain end) and curve b starts (its domain start).
struct JointEvidence {
    double tolerance = 0;
    std::vector<double> a_derivatives; // orders 0..2 of a at its end: [P, P', P''] (dim each)
    std::vector<double> b_derivatives; // orders 0..2 of b at its start
    double position_gap = 0;           // |a(end) - b(start)|
    double size = 0;                   // the size of the pair: 2 max |Q - c| over the control points Q of
                                       // both curves, c their centroid (caller's units; rotation-invariant)
    double relative_gap = 0;           // position_gap / size (0 where they meet): C^-1 when above the tolerance
    double d1_gap = 0, d2_gap = 0;     // |a' - b'|, |a'' - b''|
    double ratio = 0;                  // |b'| / |a'| (the alpha of G^1: b' = alpha a')
    double tangent_angle = 0;          // angle between a' and b' (radians)
    double curvature_a = 0, curvature_b = 0;
    double curvature_vector_gap = 0;   // |kappa_a N_a - kappa_b N_b|
    bool zero_tangent = false;         // a' or b' is the zero vector: G^1 is undefined
    bool zero_tangent_a = false, zero_tangent_b = false; // per side: that side's curvature is undefined
    std::vector<std::string> notes;
    // The statements that decide the verdict (exercise kind 3), each judged on its
    // own (a pair that does not meet can still have equal derivatives):
    //   C^0 = meet, C^1 = C^0 and equal_first, C^2 = C^1 and equal_second;
    //   G^1 = meet and same_direction, G^2 = G^1 and equal_curvature.
    bool meet = false;            // P(1) = Q(0)
    bool equal_first = false;     // P'(1) = Q'(0)
    bool same_direction = false;  // both non-zero, same unit tangent
    bool equal_second = false;    // P''(1) = Q''(0)
    bool equal_curvature = false; // both tangents non-zero, same curvature vector kappa N
};
// What one reading of "G^n" says for this joint. The lectures word it in
// two ways; the core's verdict is the third (reparametrisation-invariant) one.
struct LectureWording {
    std::string id;      // 'curvature-vector' | 'proportional' | 'direction'
    std::string source;  // where the wording is: 'lectures 001, 004', 'lecture 003', ...
    std::string wording; // the words, quoted
    int geometric = -1;  // the highest k in -1..2 this reading gives
    std::string reason;  // why it says so, and why it differs from the core's verdict if it does
};
struct JointContinuity {
    int parametric = -1; // highest k in -1..2 with C^k
    int geometric = -1;  // highest k in -1..2 with G^k
    JointEvidence evidence;
    std::vector<LectureWording> wordings; // curvature-vector (= geometric), proportional, direction
};
// Values are "equal" when |x - y| <= tolerance * max(1, |x|, |y|) (vectors: Euclidean norms).
// G^1: same unit tangent (both non-zero); G^2: G^1 and the same curvature vector.
JointContinuity joint_continuity(const Curve& a, const Curve& b, double tolerance);

} // namespace wingspline::curves
