#pragma once
// One description for every curve family of the course (lectures 000-004), and one batch
// evaluator for all of them.
//
// Conventions:
//  * Points are flat arrays with a stated dimension: points[dim*i + k], dim 2 or 3.
//  * Knot vectors have K + p + 1 entries for K control points of degree p; the domain is
//    [t_p, t_K]; a parameter u lies in the span t_l <= u < t_{l+1}, and u = t_K belongs to
//    the last (non-empty) span, so derivatives at the end are the left-sided ones.
//  * Parameters outside the domain are refused (code 'parameter-out-of-range'), never
//    clamped silently; an overshoot of kParameterSlack (relative to the domain) is rounding
//    and is moved onto the domain end.
//  * Domains per family:
//      bezier         [0, 1]
//      hermite        [0, K-1]  segment k = [k, k+1] between p_k and p_k+1
//      catmull-rom    [0, K-3]  segment i = [i, i+1] uses P_i..P_i+3, runs from P_i+1 to P_i+2
//      cardinal       [0, K-3]  as catmull-rom, tangents (1-tension)(P_i+1 - P_i-1)/2
//      bspline/nurbs  [t_p, t_K] with knots; without knots the uniform knots t_j = j - p,
//                     so the domain is [0, K-p] and segment i = [i, i+1] uses P_i..P_i+p
//      interpolation  [u_0, u_n], the interpolation nodes (default u_i = i/n)
#include <cstddef>
#include <string>
#include <vector>

namespace wingspline::curves {

enum class CurveKind { Bezier, BSpline, Nurbs, Hermite, CatmullRom, Cardinal, Interpolation };

// Parses 'bezier' | 'bspline' | 'nurbs' | 'hermite' | 'catmull-rom' | 'cardinal' |
// 'interpolation'; throws Error("unknown-curve-kind") naming the word.
CurveKind parse_curve_kind(const std::string& name);
const char* curve_kind_name(CurveKind kind);

// Degrees accepted for Bezier curves and B-splines/NURBS: 1..kMaxDegree. The limit keeps
// the per-parameter work arrays on the stack and the basis numerically meaningful.
constexpr int kMaxDegree = 20;
// Polynomial interpolation through at most this many points (degree 31). The curve is
// evaluated in the Lagrange product form on nodes scaled by a power of two (exact at the
// nodes at any offset and scale); what limits the count is the problem itself: at the
// default equispaced nodes the Lebesgue constant (the factor by which the curve between
// the nodes magnifies a change of the data) is 1.2e7 at 32 points and doubles with every
// further point, so beyond 32 the drawn curve would be dominated by the rounding of the
// data (docs/api-curves.md, "Interpolation").
constexpr int kMaxInterpolationPoints = 32;
// Two interpolation nodes closer than this fraction of the nodes' spread are refused
// ('nodes-too-close'): between them the interpolant grows like spread / gap, so rounding of
// the data would be magnified by more than 1e9.
constexpr double kMinNodeSeparation = 1e-9;
// A parameter this far (relative to max(1, |domain ends|)) outside the domain is rounding.
constexpr double kParameterSlack = 1e-12;

struct Curve {
    CurveKind kind = CurveKind::Bezier;
    int dim = 2;                  // 2 or 3 (1 is used internally for blending functions)
    std::vector<double> points;   // points[dim*i + k]
    int degree = 0;               // 0: the family's default (bezier: K-1, bspline/nurbs: 3)
    std::vector<double> knots;    // bspline/nurbs: K+p+1 non-decreasing values; empty: uniform
    std::vector<double> weights;  // nurbs (and rational bezier): weights[i] > 0; empty: all 1
    std::vector<double> tangents; // hermite: tangents[dim*i + k], one per point
    std::vector<double> nodes;    // interpolation: strictly increasing u_i; empty: i/n
    double tension = 0;           // cardinal: 0 gives catmull-rom, 1 gives straight lines
};

struct Domain {
    double start = 0;
    double end = 1;
};

// Throws Error with one of the codes of docs/api-curves.md when the curve is not valid.
void validate(const Curve& curve);
int control_point_count(const Curve& curve);
// The degree actually used (defaults resolved); 3 for the cubic families.
int curve_degree(const Curve& curve);
// True for the families whose points enter linearly in a polynomial (no weights).
bool is_rational(const Curve& curve);

// A validated curve, ready for batch evaluation. Cheap to build; holds a copy of the data
// in the form the evaluation needs (knots with defaults, homogeneous points, or the power
// coefficients C = M G of every cubic segment).
class CurveEvaluator {
public:
    explicit CurveEvaluator(const Curve& curve);

    Domain domain() const { return domain_; }
    int dim() const { return dim_; }
    int degree() const { return degree_; }
    const Curve& curve() const { return curve_; }

    // Checks params (finite, inside the domain up to kParameterSlack) and returns them with
    // rounding overshoots moved onto the domain ends. Throws 'non-finite-input' or
    // 'parameter-out-of-range' naming the index, the value and the domain.
    std::vector<double> checked_params(const double* params, std::size_t n) const;
    // The same check in place (no copy): the batch path of the bindings, which works in
    // chunks; index_offset is added to the parameter index named in a message.
    void check_params(double* params, std::size_t n, std::size_t index_offset = 0) const;

    // out[dim*j + c]: the derivative of order `order` (0 = the point) at params[j].
    // params must come from checked_params.
    void evaluate(const double* params, std::size_t n, int order, double* out) const;
    // out[(max_order+1)*dim*j + dim*k + c]: orders k = 0..max_order at params[j].
    void evaluate_all(const double* params, std::size_t n, int max_order, double* out) const;


private:
    void evaluate_polynomial(const double* params, std::size_t n, int max_order, bool all, double* out) const;
    void evaluate_spline(const double* params, std::size_t n, int max_order, bool all, double* out) const;

    Curve curve_;
    int dim_ = 2;
    int degree_ = 3;
    Domain domain_;
    // spline form (bezier, bspline, nurbs)
    bool spline_ = false;
    bool rational_ = false;
    std::vector<double> knots_;
    std::vector<double> homogeneous_; // stride dim+1 when rational (w x, w y, w z, w), else dim
    int first_span_ = 0;
    int last_span_ = 0;
    // Cubic fast path: per span l, the reciprocals of the knot differences the Cox-de Boor
    // triangle divides by (they depend on the span only, not on u), so evaluation needs no
    // division: inverse_differences_[kCubicStride*l + ...], see curve.cpp.
    static constexpr int kCubicStride = 9;
    std::vector<double> inverse_differences_;
    // polynomial form (hermite, catmull-rom, cardinal)
    std::vector<std::vector<double>> segment_coefficients_;
    // interpolation: the Lagrange product form P(u) = sum_j y_j w_j prod_(m != j) d_m with
    // d_m = (u - u_m) 2^s (s: a power of two that brings the nodes' spread into [2, 4), so
    // the products neither overflow nor underflow) and w_j = 1 / prod_(m != j) (u_j - u_m) 2^s.
    void evaluate_interpolation(const double* params, std::size_t n, int max_order, bool all, double* out) const;
    std::vector<double> nodes_;
    std::vector<double> node_weights_;
    int node_shift_ = 0;
};

// Convenience wrappers (validate + evaluate). Output layout as CurveEvaluator::evaluate.
std::vector<double> evaluate_curve(const Curve& curve, const std::vector<double>& params, int order = 0);
std::vector<double> evaluate_curve_all(const Curve& curve, const std::vector<double>& params, int max_order);

// Weights at any scale: a uniform factor cancels in a rational curve, so every
// rational computation first multiplies the weights by 2^weight_shift(weights), which puts
// the largest in [0.5, 1) exactly (a power of two), and reports weights scaled back.
// validate() refuses weights whose ratio exceeds kMaxWeightRatio, so the smallest scaled
// weight stays a normal number.
constexpr double kMaxWeightRatio = 1e300;
int weight_shift(const std::vector<double>& weights);
// (w x, w y, [w z,] w) with the scaled weights, stride dim + 1; the points when no weights.
std::vector<double> to_homogeneous(const std::vector<double>& points, int dim, const std::vector<double>& weights);
// Back from homogeneous coordinates: points = h / w, weights (if asked) = w 2^-shift.
void from_homogeneous(const std::vector<double>& h, int dim, int shift, std::vector<double>& points,
                      std::vector<double>* weights);

// The nodes u_i of an interpolation curve (its own, or the default u_i = i/n).
std::vector<double> interpolation_nodes(const Curve& curve);

// The default knots of a B-spline without knots: t_j = j - p, j = 0..K+p.
std::vector<double> uniform_knots(int count, int degree);
// The knots of a Bezier curve of degree n as a B-spline: n+1 zeros, n+1 ones.
std::vector<double> bezier_knots(int degree);

// Blending functions of every control item at every parameter (lectures 000, 001: B = M T;
// Cox-de Boor N_i,p for B-splines; rational R_i,p for NURBS):
// values[count*j + i], count = control_point_count (hermite: 2K, points then tangents).
struct BlendingValues {
    int count = 0;
    std::vector<double> values;
};
BlendingValues blending_functions(const Curve& curve, const std::vector<double>& params, int order = 0);

} // namespace wingspline::curves
