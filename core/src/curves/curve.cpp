#include "wingspline/curves/curve.h"

#include "messages.h"
#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/bspline_basis.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>

namespace wingspline::curves {

using detail::num;
using detail::range;

CurveKind parse_curve_kind(const std::string& name) {
    if (name == "bezier") return CurveKind::Bezier;
    if (name == "bspline") return CurveKind::BSpline;
    if (name == "nurbs") return CurveKind::Nurbs;
    if (name == "hermite") return CurveKind::Hermite;
    if (name == "catmull-rom") return CurveKind::CatmullRom;
    if (name == "cardinal") return CurveKind::Cardinal;
    if (name == "interpolation") return CurveKind::Interpolation;
    throw Error("unknown-curve-kind", "unknown curve kind '" + name.substr(0, 40) +
                                          "'; expected bezier, bspline, nurbs, hermite, catmull-rom, "
                                          "cardinal or interpolation");
}

const char* curve_kind_name(CurveKind kind) {
    switch (kind) {
    case CurveKind::Bezier: return "bezier";
    case CurveKind::BSpline: return "bspline";
    case CurveKind::Nurbs: return "nurbs";
    case CurveKind::Hermite: return "hermite";
    case CurveKind::CatmullRom: return "catmull-rom";
    case CurveKind::Cardinal: return "cardinal";
    case CurveKind::Interpolation: return "interpolation";
    }
    return "bezier";
}

std::vector<double> uniform_knots(int count, int degree) {
    std::vector<double> t(static_cast<std::size_t>(count + degree + 1));
    for (std::size_t j = 0; j < t.size(); ++j) t[j] = static_cast<double>(j) - degree;
    return t;
}

std::vector<double> bezier_knots(int degree) {
    std::vector<double> t(static_cast<std::size_t>(2 * degree + 2), 0.0);
    std::fill(t.begin() + degree + 1, t.end(), 1.0);
    return t;
}

int control_point_count(const Curve& c) {
    return c.dim > 0 ? static_cast<int>(c.points.size()) / c.dim : 0;
}

bool is_rational(const Curve& c) {
    return c.kind == CurveKind::Nurbs || (c.kind == CurveKind::Bezier && !c.weights.empty());
}

int curve_degree(const Curve& c) {
    switch (c.kind) {
    case CurveKind::Bezier: return control_point_count(c) - 1;
    case CurveKind::BSpline:
    case CurveKind::Nurbs: return c.degree > 0 ? c.degree : 3;
    case CurveKind::Interpolation: return control_point_count(c) - 1;
    default: return 3;
    }
}

namespace {

std::string point_name(const std::string& what, std::size_t flat_index, int dim) {
    static const char* axis[] = {"x", "y", "z"};
    return what + " " + std::to_string(flat_index / dim) + " (" +
           (dim <= 3 ? axis[flat_index % dim] : std::to_string(flat_index % dim).c_str()) + ")";
}

void require_finite(const std::vector<double>& v, const std::string& what, int dim) {
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            throw Error("non-finite-input", point_name(what, i, dim) + " is " + num(v[i]) +
                                                ", not a finite number");
}

void validate_knots(const Curve& c, int K, int p) {
    const std::size_t expected = static_cast<std::size_t>(K + p + 1);
    require(c.knots.size() == expected, "wrong-knot-count",
            "a degree-" + std::to_string(p) + " B-spline with " + std::to_string(K) +
                " control points needs K + p + 1 = " + std::to_string(expected) + " knots, not " +
                std::to_string(c.knots.size()));
    for (std::size_t i = 0; i < c.knots.size(); ++i)
        if (!std::isfinite(c.knots[i]))
            throw Error("non-finite-input", "knot t_" + std::to_string(i) + " is " + num(c.knots[i]) + ", not a finite number");
    for (std::size_t i = 1; i < c.knots.size(); ++i)
        if (!(c.knots[i] >= c.knots[i - 1]))
            throw Error("decreasing-knots", "knots must not decrease, but t_" + std::to_string(i - 1) + " = " +
                                                num(c.knots[i - 1]) + " > t_" + std::to_string(i) + " = " + num(c.knots[i]));
    for (std::size_t i = 0; i < c.knots.size();) {
        std::size_t j = i;
        while (j < c.knots.size() && c.knots[j] == c.knots[i]) ++j;
        if (static_cast<int>(j - i) > p + 1)
            throw Error("knot-multiplicity-exceeded", "knot " + num(c.knots[i]) + " appears " + std::to_string(j - i) +
                                                          " times; a degree-" + std::to_string(p) +
                                                          " B-spline allows at most p + 1 = " + std::to_string(p + 1));
        i = j;
    }
    require(c.knots[p] < c.knots[K], "empty-domain",
            "the domain [t_p, t_K] = " + range(c.knots[p], c.knots[K]) + " is empty");
}

void validate_weights(const Curve& c, int K) {
    require(c.weights.size() == static_cast<std::size_t>(K), "wrong-weight-count",
            "there are " + std::to_string(K) + " control points but " + std::to_string(c.weights.size()) +
                " weights; give one weight per point");
    for (int i = 0; i < K; ++i)
        if (!(std::isfinite(c.weights[i]) && c.weights[i] > 0))
            throw Error("invalid-weight", "weight w_" + std::to_string(i) + " of point " + std::to_string(i) + " is " +
                                              num(c.weights[i]) + "; weights must be positive finite numbers");
    const auto [low, high] = std::minmax_element(c.weights.begin(), c.weights.end());
    if (*high / kMaxWeightRatio > *low)
        throw Error("weight-ratio-out-of-range",
                    "weights w_" + std::to_string(high - c.weights.begin()) + " = " + num(*high) + " and w_" +
                        std::to_string(low - c.weights.begin()) + " = " + num(*low) + " differ by more than a factor " +
                        num(kMaxWeightRatio) + "; only their ratios matter, so bring them closer together");
}

} // namespace

void validate(const Curve& c) {
    require(c.dim >= 1 && c.dim <= 3, "invalid-dimension",
            "dim must be 2 or 3, not " + std::to_string(c.dim));
    require(c.points.size() % c.dim == 0, "invalid-points",
            "points has " + std::to_string(c.points.size()) + " numbers, which is not a multiple of dim = " +
                std::to_string(c.dim));
    require_finite(c.points, "point", c.dim);
    require(c.degree >= 0, "degree-out-of-range", "the degree must be from 1 to " + std::to_string(kMaxDegree) + ", not " + std::to_string(c.degree));
    const int K = control_point_count(c);
    const std::string kind = curve_kind_name(c.kind);
    auto need_points = [&](int n, const std::string& why) {
        require(K >= n, "too-few-points", "a " + why + " needs at least " + std::to_string(n) +
                                              " points, but has " + std::to_string(K));
    };
    switch (c.kind) {
    case CurveKind::Bezier:
        need_points(2, "Bezier curve");
        require(K - 1 <= kMaxDegree, "degree-out-of-range",
                "a Bezier curve with " + std::to_string(K) + " points has degree " + std::to_string(K - 1) +
                    "; the largest degree supported is " + std::to_string(kMaxDegree));
        require(c.degree == 0 || c.degree == K - 1, "degree-out-of-range",
                "a Bezier curve of degree " + std::to_string(c.degree) + " has " + std::to_string(c.degree + 1) +
                    " points, but " + std::to_string(K) + " were given");
        if (!c.weights.empty()) validate_weights(c, K);
        break;
    case CurveKind::BSpline:
    case CurveKind::Nurbs: {
        const int p = curve_degree(c);
        require(p >= 1 && p <= kMaxDegree, "degree-out-of-range",
                "the degree of a B-spline must be from 1 to " + std::to_string(kMaxDegree) + ", not " +
                    std::to_string(c.degree));
        need_points(p + 1, "degree-" + std::to_string(p) + " " + kind + " (p + 1 points)");
        if (!c.knots.empty()) validate_knots(c, K, p);
        if (c.kind == CurveKind::Nurbs) {
            if (!c.weights.empty()) validate_weights(c, K);
        } else {
            require(c.weights.empty(), "invalid-weight",
                    "a 'bspline' has no weights; use kind 'nurbs' for a weighted (rational) B-spline");
        }
        break;
    }
    case CurveKind::Hermite:
        need_points(2, "Hermite spline");
        require(c.tangents.size() == c.points.size(), "wrong-tangent-count",
                "a Hermite spline needs one tangent per point: " + std::to_string(K) + " points need " +
                    std::to_string(c.points.size()) + " tangent numbers, not " + std::to_string(c.tangents.size()));
        require_finite(c.tangents, "tangent", c.dim);
        break;
    case CurveKind::CatmullRom:
    case CurveKind::Cardinal:
        need_points(4, kind + " spline");
        require(std::isfinite(c.tension), "non-finite-input", "the tension is " + num(c.tension) +
                                                                  ", not a finite number");
        break;
    case CurveKind::Interpolation:
        need_points(2, "interpolating polynomial");
        require(K <= kMaxInterpolationPoints, "degree-out-of-range",
                "polynomial interpolation through " + std::to_string(K) + " points has degree " +
                    std::to_string(K - 1) + "; at most " + std::to_string(kMaxInterpolationPoints) +
                    " points are supported (with more, the curve between the points would magnify the rounding of the data by more than 1e7)");
        if (!c.nodes.empty()) {
            require(c.nodes.size() == static_cast<std::size_t>(K), "wrong-node-count",
                    std::to_string(K) + " points need " + std::to_string(K) + " parameter values u_i, not " +
                        std::to_string(c.nodes.size()));
            for (std::size_t i = 0; i < c.nodes.size(); ++i)
                if (!std::isfinite(c.nodes[i]))
                    throw Error("non-finite-input", "parameter u_" + std::to_string(i) + " is " + num(c.nodes[i]) +
                                                        ", not a finite number");
            for (std::size_t i = 1; i < c.nodes.size(); ++i)
                if (!(c.nodes[i] > c.nodes[i - 1]))
                    throw Error("nodes-not-increasing", "the parameters u_i must increase strictly, but u_" +
                                                            std::to_string(i - 1) + " = " + num(c.nodes[i - 1]) + " >= u_" +
                                                            std::to_string(i) + " = " + num(c.nodes[i]));
            // Distinct relative to their spread (any offset and scale is fine).
            const double spread = c.nodes.back() - c.nodes.front();
            require(std::isfinite(spread), "nodes-out-of-range",
                    "the parameters u_0 = " + num(c.nodes.front()) + " and u_" + std::to_string(K - 1) + " = " +
                        num(c.nodes.back()) + " are too far apart to subtract in double precision");
            for (std::size_t i = 1; i < c.nodes.size(); ++i)
                if (c.nodes[i] - c.nodes[i - 1] < kMinNodeSeparation * spread)
                    throw Error("nodes-too-close",
                                "the parameters u_" + std::to_string(i - 1) + " = " + num(c.nodes[i - 1]) + " and u_" +
                                    std::to_string(i) + " = " + num(c.nodes[i]) + " are closer than " +
                                    num(kMinNodeSeparation) + " of the whole range " + range(c.nodes.front(), c.nodes.back()) +
                                    "; between them the curve would be dominated by rounding. Move them apart");
        }
        break;
    }
}

// ------------------------------------------------------------------ evaluator

CurveEvaluator::CurveEvaluator(const Curve& curve) : curve_(curve) {
    validate(curve_);
    dim_ = curve_.dim;
    degree_ = curve_degree(curve_);
    const int K = control_point_count(curve_);
    const int d = dim_;
    switch (curve_.kind) {
    case CurveKind::Bezier:
    case CurveKind::BSpline:
    case CurveKind::Nurbs: {
        spline_ = true;
        rational_ = is_rational(curve_);
        if (curve_.kind == CurveKind::Bezier) knots_ = bezier_knots(degree_);
        else knots_ = curve_.knots.empty() ? uniform_knots(K, degree_) : curve_.knots;
        const int hd = rational_ ? d + 1 : d;
        homogeneous_.resize(static_cast<std::size_t>(K * hd));
        const int shift = weight_shift(curve_.weights); // weights at any scale
        for (int i = 0; i < K; ++i) {
            const double w = rational_ && !curve_.weights.empty() ? std::ldexp(curve_.weights[i], shift) : 1.0;
            for (int k = 0; k < d; ++k) homogeneous_[i * hd + k] = w * curve_.points[i * d + k];
            if (rational_) homogeneous_[i * hd + d] = w;
        }
        const int p = degree_;
        first_span_ = p;
        while (knots_[first_span_] == knots_[first_span_ + 1]) ++first_span_;
        last_span_ = K - 1;
        while (knots_[last_span_] == knots_[last_span_ + 1]) --last_span_;
        domain_ = {knots_[p], knots_[K]};
        if (p == 3) {
            inverse_differences_.assign(static_cast<std::size_t>(kCubicStride) * (K + 1), 0.0);
            for (int l = first_span_; l <= last_span_; ++l) {
                if (!(knots_[l] < knots_[l + 1])) continue;
                double* inv = &inverse_differences_[static_cast<std::size_t>(kCubicStride) * l];
                // Cox-de Boor step j, term r: 1 / (t_(l+r+1) - t_(l+1-j+r)), j = 1..3, r < j
                int q = 0;
                for (int j = 1; j <= 3; ++j)
                    for (int r = 0; r < j; ++r) inv[q++] = 1.0 / (knots_[l + r + 1] - knots_[l + 1 - j + r]);
                // first derivative: 1 / (t_(l+r) - t_(l-3+r)), r = 1..3
                for (int r = 1; r <= 3; ++r) inv[q++] = 1.0 / (knots_[l + r] - knots_[l - 3 + r]);
            }
        }
        break;
    }
    case CurveKind::Hermite:
    case CurveKind::CatmullRom:
    case CurveKind::Cardinal: {
        const bool hermite = curve_.kind == CurveKind::Hermite;
        const Mat4 M = hermite ? basis_matrix(BasisKind::Hermite)
                               : curve_.kind == CurveKind::CatmullRom ? basis_matrix(BasisKind::CatmullRom)
                                                                      : cardinal_matrix(curve_.tension);
        const int segments = hermite ? K - 1 : K - 3;
        for (int s = 0; s < segments; ++s) {
            // G rows: hermite [p_s, p_s+1, t_s, t_s+1] (lecture 000); others [P_s .. P_s+3].
            const double* g[4];
            if (hermite) {
                g[0] = &curve_.points[s * d];
                g[1] = &curve_.points[(s + 1) * d];
                g[2] = &curve_.tangents[s * d];
                g[3] = &curve_.tangents[(s + 1) * d];
            } else {
                for (int r = 0; r < 4; ++r) g[r] = &curve_.points[(s + r) * d];
            }
            std::vector<double> C(static_cast<std::size_t>(4 * d), 0.0);
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < d; ++k) {
                    double sum = 0;
                    for (int c = 0; c < 4; ++c) sum += M[4 * r + c] * g[c][k];
                    C[r * d + k] = sum;
                }
            segment_coefficients_.push_back(std::move(C));
        }
        domain_ = {0.0, static_cast<double>(segments)};
        break;
    }
    case CurveKind::Interpolation: {
        nodes_ = interpolation_nodes(curve_);
        // 2^node_shift_ brings the spread into [2, 4) exactly (a power of two), so the
        // scaled differences d_m keep the relative accuracy of u - u_m.
        int e = 0;
        std::frexp(nodes_.back() - nodes_.front(), &e);
        node_shift_ = 2 - e;
        node_weights_.resize(nodes_.size());
        for (int j = 0; j < K; ++j) {
            double product = 1;
            for (int m = 0; m < K; ++m)
                if (m != j) product *= std::ldexp(nodes_[j] - nodes_[m], node_shift_);
            node_weights_[j] = 1.0 / product;
        }
        domain_ = {nodes_.front(), nodes_.back()};
        break;
    }
    }
}

std::vector<double> CurveEvaluator::checked_params(const double* params, std::size_t n) const {
    std::vector<double> out(params, params + n);
    check_params(out.data(), n);
    return out;
}

void CurveEvaluator::check_params(double* out, std::size_t n, std::size_t index_offset) const {
    const double slack = kParameterSlack * std::max({1.0, std::abs(domain_.start), std::abs(domain_.end)});
    for (std::size_t j = 0; j < n; ++j) {
        const double u = out[j];
        if (u >= domain_.start && u <= domain_.end) continue;
        // (messages are built only on failure: this loop runs once per parameter)
        if (!std::isfinite(u))
            throw Error("non-finite-input",
                        "parameter " + std::to_string(j + index_offset) + " is " + num(u) + ", not a finite number");
        if (!(u >= domain_.start - slack && u <= domain_.end + slack))
            throw Error("parameter-out-of-range",
                        "parameter " + std::to_string(j + index_offset) + " is u = " + num(u) + ", outside the domain " +
                            range(domain_.start, domain_.end) + " of this " + curve_kind_name(curve_.kind) + " curve");
        out[j] = std::clamp(u, domain_.start, domain_.end);
    }
}

void CurveEvaluator::evaluate(const double* params, std::size_t n, int order, double* out) const {
    if (spline_) evaluate_spline(params, n, order, false, out);
    else if (!nodes_.empty()) evaluate_interpolation(params, n, order, false, out);
    else evaluate_polynomial(params, n, order, false, out);
}

void CurveEvaluator::evaluate_all(const double* params, std::size_t n, int max_order, double* out) const {
    if (spline_) evaluate_spline(params, n, max_order, true, out);
    else if (!nodes_.empty()) evaluate_interpolation(params, n, max_order, true, out);
    else evaluate_polynomial(params, n, max_order, true, out);
}

int weight_shift(const std::vector<double>& weights) {
    double largest = 0;
    for (double w : weights) largest = std::max(largest, w);
    if (!(largest > 0 && std::isfinite(largest))) return 0;
    int e = 0;
    std::frexp(largest, &e);
    return -e;
}

std::vector<double> to_homogeneous(const std::vector<double>& points, int dim, const std::vector<double>& weights) {
    if (weights.empty()) return points;
    const int shift = weight_shift(weights);
    const std::size_t K = weights.size();
    std::vector<double> h(K * (dim + 1));
    for (std::size_t i = 0; i < K; ++i) {
        const double w = std::ldexp(weights[i], shift);
        for (int k = 0; k < dim; ++k) h[i * (dim + 1) + k] = w * points[i * dim + k];
        h[i * (dim + 1) + dim] = w;
    }
    return h;
}

void from_homogeneous(const std::vector<double>& h, int dim, int shift, std::vector<double>& points,
                      std::vector<double>* weights) {
    const std::size_t K = h.size() / (dim + 1);
    points.resize(K * dim);
    if (weights) weights->resize(K);
    for (std::size_t i = 0; i < K; ++i) {
        const double w = h[i * (dim + 1) + dim];
        if (weights) (*weights)[i] = std::ldexp(w, -shift);
        for (int k = 0; k < dim; ++k) points[i * dim + k] = h[i * (dim + 1) + k] / w;
    }
}

std::vector<double> interpolation_nodes(const Curve& c) {
    if (!c.nodes.empty()) return c.nodes;
    const int n = control_point_count(c) - 1;
    std::vector<double> u;
    for (int i = 0; i <= n; ++i) u.push_back(static_cast<double>(i) / n);
    return u;
}

// The Lagrange product form, in the Taylor variable t of the scaled parameter: L_j(s + t) =
// w_j prod_(m != j) (d_m + t), truncated after t^o (o = the highest derivative needed). The
// products are built from a running prefix and stored suffixes, so there is no division
// and no cancellation at a node: there d_j = 0 exactly and only L_j survives. Cost per
// parameter: O(K) for points, O(K o^2) with derivatives.
void CurveEvaluator::evaluate_interpolation(const double* params, std::size_t n, int max_order, bool all,
                                            double* out) const {
    const int d = dim_;
    const int K = static_cast<int>(nodes_.size());
    const int o = std::min(max_order, K - 1); // derivatives above the degree vanish
    const int terms = o + 1;
    const int first_order = all ? 0 : max_order;
    const int orders = max_order - first_order + 1;
    std::vector<double> diff(static_cast<std::size_t>(K));
    std::vector<double> suffix(static_cast<std::size_t>((K + 1) * terms)); // prod_(i >= m) (d_i + t)
    std::vector<double> prefix(static_cast<std::size_t>(terms)), next(prefix.size()), basis(prefix.size());
    std::vector<double> taylor(static_cast<std::size_t>(terms * d));
    for (std::size_t j = 0; j < n; ++j) {
        const double u = params[j];
        int at_node = -1;
        for (int m = 0; m < K; ++m) {
            diff[m] = std::ldexp(u - nodes_[m], node_shift_);
            if (diff[m] == 0) at_node = m;
        }
        std::fill(suffix.begin() + static_cast<std::ptrdiff_t>(K) * terms, suffix.end(), 0.0);
        suffix[static_cast<std::size_t>(K) * terms] = 1;
        for (int m = K - 1; m >= 0; --m) {
            const double* s = &suffix[static_cast<std::size_t>(m + 1) * terms];
            double* r = &suffix[static_cast<std::size_t>(m) * terms];
            r[0] = diff[m] * s[0];
            for (int k = 1; k < terms; ++k) r[k] = diff[m] * s[k] + s[k - 1];
        }
        std::fill(prefix.begin(), prefix.end(), 0.0);
        prefix[0] = 1;
        std::fill(taylor.begin(), taylor.end(), 0.0);
        for (int m = 0; m < K; ++m) {
            const double* s = &suffix[static_cast<std::size_t>(m + 1) * terms];
            for (int k = 0; k < terms; ++k) {
                double v = 0;
                for (int i = 0; i <= k; ++i) v += prefix[i] * s[k - i];
                basis[k] = node_weights_[m] * v;
            }
            for (int k = 0; k < terms; ++k)
                for (int c = 0; c < d; ++c) taylor[k * d + c] += basis[k] * curve_.points[m * d + c];
            next[0] = diff[m] * prefix[0];
            for (int k = 1; k < terms; ++k) next[k] = diff[m] * prefix[k] + prefix[k - 1];
            std::swap(prefix, next);
        }
        double* dst = out + j * static_cast<std::size_t>(orders * d);
        for (int q = first_order; q <= max_order; ++q) {
            double factorial = 1;
            for (int i = 2; i <= q; ++i) factorial *= i;
            for (int c = 0; c < d; ++c) {
                double v = 0;
                if (q == 0 && at_node >= 0) v = curve_.points[at_node * d + c]; // the data, exactly
                else if (q <= o) v = std::ldexp(factorial * taylor[q * d + c], q * node_shift_);
                dst[(q - first_order) * d + c] = v;
            }
        }
    }
}

void CurveEvaluator::evaluate_polynomial(const double* params, std::size_t n, int max_order, bool all,
                                         double* out) const {
    const int d = dim_;
    const int deg = degree_;
    const int segments = static_cast<int>(segment_coefficients_.size());
    const int first_order = all ? 0 : max_order;
    const int orders = max_order - first_order + 1;
    for (std::size_t j = 0; j < n; ++j) {
        double u = params[j];
        int s = std::min(static_cast<int>(std::floor(u - domain_.start)), segments - 1);
        s = std::max(s, 0);
        u -= domain_.start + s;
        const double* C = segment_coefficients_[s].data(); // row r multiplies u^(deg - r)
        for (int o = first_order; o <= max_order; ++o) {
            double* dst = out + (static_cast<std::size_t>(j) * orders + (o - first_order)) * d;
            for (int k = 0; k < d; ++k) {
                // Horner on the o-th derivative: sum over e >= o of c_e e!/(e-o)! u^(e-o).
                double v = 0;
                for (int e = deg; e >= o; --e) {
                    double f = 1;
                    for (int q = 0; q < o; ++q) f *= (e - q);
                    v = v * u + f * C[(deg - e) * d + k];
                }
                dst[k] = v;
            }
        }
    }
}

namespace {

// Per span of a cubic: 6 reciprocals for the Cox-de Boor triangle, 3 for the derivative
// (CurveEvaluator::kCubicStride, the layout the constructor fills).
constexpr int kReciprocalsPerSpan = 9;

// The cubic Cox-de Boor triangle with the span's reciprocal knot differences (no division):
// the same arithmetic as basis_functions_fixed<3> with a/b replaced by a*(1/b). Split in
// two: the functions of degree 2 (which the first derivatives also need), then degree 3.
struct CubicLower {
    double left1, left2, left3, right1, right2, right3;
    double n20, n21, n22; // N_{span-2+r, 2}(u), r = 0..2
};

inline CubicLower cubic_degree2(int span, double u, const double* t, const double* inv) {
    CubicLower c;
    c.left1 = u - t[span]; c.left2 = u - t[span - 1]; c.left3 = u - t[span - 2];
    c.right1 = t[span + 1] - u; c.right2 = t[span + 2] - u; c.right3 = t[span + 3] - u;
    // j = 1
    double temp = inv[0];
    const double n10 = c.right1 * temp, n11 = c.left1 * temp;
    // j = 2
    temp = n10 * inv[1];
    c.n20 = c.right1 * temp;
    const double saved = c.left2 * temp;
    temp = n11 * inv[2];
    c.n21 = saved + c.right2 * temp;
    c.n22 = c.left1 * temp;
    return c;
}

// j = 3: N[0..3] = N_{span-3+r, 3}(u) from the degree-2 functions.
inline void cubic_degree3(const CubicLower& c, const double* inv, double* N) {
    double temp = c.n20 * inv[3];
    N[0] = c.right1 * temp;
    double saved = c.left3 * temp;
    temp = c.n21 * inv[4];
    N[1] = saved + c.right2 * temp;
    saved = c.left2 * temp;
    temp = c.n22 * inv[5];
    N[2] = saved + c.right3 * temp;
    N[3] = c.left1 * temp;
}

inline void cubic_basis(int span, double u, const double* t, const double* inv, double* N) {
    cubic_degree3(cubic_degree2(span, u, t, inv), inv, N);
}

// The same plus the first derivatives from the degree-2 functions n20, n21, n22.
inline void cubic_basis_d1(int span, double u, const double* t, const double* inv, double* N, double* dN) {
    const CubicLower c = cubic_degree2(span, u, t, inv);
    // N'_i,3 = 3 (N_i,2 / (t_i+3 - t_i) - N_i+1,2 / (t_i+4 - t_i+1))
    const double a1 = c.n20 * inv[6], a2 = c.n21 * inv[7], a3 = c.n22 * inv[8];
    dN[0] = -3 * a1;
    dN[1] = 3 * (a1 - a2);
    dN[2] = 3 * (a2 - a3);
    dN[3] = 3 * a3;
    cubic_degree3(c, inv, N);
}

// Keeps `span` on the span of u: params that increase are found by a short forward walk,
// anything else by binary search (so any order of params gives exact results).
inline int track_span(const double* t, int first, int last, int span, double u) {
    if (u >= t[span] && (u < t[span + 1] || span == last)) return span;
    if (u > t[span]) {
        for (int step = 0; step < 4 && span < last && u >= t[span + 1]; ++step) ++span;
        if (u >= t[span] && (u < t[span + 1] || span == last)) return span;
    }
    return find_span_in(t, first, last, u);
}

template <int P>
void spline_points_fixed(const double* t, const double* cw, int hd, bool rational, int d, int first, int last,
                         const double* params, std::size_t n, double* out) {
    int span = first;
    double N[P + 1];
    for (std::size_t j = 0; j < n; ++j) {
        const double u = params[j];
        span = track_span(t, first, last, span, u);
        basis_functions_fixed<P>(span, u, t, N);
        const double* c = cw + static_cast<std::size_t>(span - P) * hd;
        double acc[4] = {0, 0, 0, 0};
        for (int r = 0; r <= P; ++r)
            for (int k = 0; k < hd; ++k) acc[k] += N[r] * c[r * hd + k];
        double* dst = out + j * d;
        if (rational) {
            const double inv = 1.0 / acc[d];
            for (int k = 0; k < d; ++k) dst[k] = acc[k] * inv;
        } else {
            for (int k = 0; k < d; ++k) dst[k] = acc[k];
        }
    }
}

template <int P, int D>
void spline_points_fixed_dim(const double* t, const double* cw, const double* inverse_differences, int first,
                             int last, const double* params, std::size_t n, double* out) {
    static_assert(P == 3, "the reciprocal table exists for cubics");
    int span = first;
    double N[P + 1];
    for (std::size_t j = 0; j < n; ++j) {
        const double u = params[j];
        span = track_span(t, first, last, span, u);
        cubic_basis(span, u, t, inverse_differences + kReciprocalsPerSpan * span, N);
        const double* c = cw + static_cast<std::size_t>(span - P) * D;
        double acc[D];
        for (int k = 0; k < D; ++k) acc[k] = N[0] * c[k];
        for (int r = 1; r <= P; ++r)
            for (int k = 0; k < D; ++k) acc[k] += N[r] * c[r * D + k];
        double* dst = out + j * (D == 4 ? 3 : D);
        if constexpr (D == 4) {
            const double inv = 1.0 / acc[3];
            dst[0] = acc[0] * inv;
            dst[1] = acc[1] * inv;
            dst[2] = acc[2] * inv;
        } else {
            for (int k = 0; k < D; ++k) dst[k] = acc[k];
        }
    }
}

// Point and first derivative (the d1 benchmarks and every tangent plot): out holds either
// [P, P'] (all) or P' only, per parameter.
template <int P, int HD>
void spline_d1_fixed(const double* t, const double* cw, const double* inverse_differences, bool rational, int first,
                     int last, const double* params, std::size_t n, bool all, double* out) {
    static_assert(P == 3, "the reciprocal table exists for cubics");
    constexpr int D = HD; // when rational, the caller passes HD = dim + 1
    const int d = rational ? D - 1 : D;
    int span = first;
    double N[P + 1], dN[P + 1];
    for (std::size_t j = 0; j < n; ++j) {
        const double u = params[j];
        span = track_span(t, first, last, span, u);
        cubic_basis_d1(span, u, t, inverse_differences + kReciprocalsPerSpan * span, N, dN);
        const double* c = cw + static_cast<std::size_t>(span - P) * HD;
        double A[HD], dA[HD];
        for (int k = 0; k < HD; ++k) {
            A[k] = N[0] * c[k];
            dA[k] = dN[0] * c[k];
        }
        for (int r = 1; r <= P; ++r)
            for (int k = 0; k < HD; ++k) {
                A[k] += N[r] * c[r * HD + k];
                dA[k] += dN[r] * c[r * HD + k];
            }
        double* dst = out + j * (all ? 2 * d : d);
        double* ddst = all ? dst + d : dst;
        if (rational) {
            // C = A / w, C' = (A' - w' C) / w (The NURBS Book, eq. 4.8)
            const double inv = 1.0 / A[d];
            for (int k = 0; k < d; ++k) {
                const double point = A[k] * inv;
                if (all) dst[k] = point;
                ddst[k] = (dA[k] - dA[d] * point) * inv;
            }
        } else {
            for (int k = 0; k < d; ++k) {
                if (all) dst[k] = A[k];
                ddst[k] = dA[k];
            }
        }
    }
}

// The cubic Bezier curve in Bernstein form (lecture 001: (1-t)^3 P1 + 3t(1-t)^2 P2 +
// 3t^2(1-t) P3 + t^3 P4), 3D, no weights: the Bezier benchmark's path.
void bezier_cubic_points(const double* P, const double* params, std::size_t n, double* out) {
    for (std::size_t j = 0; j < n; ++j) {
        const double t = params[j];
        const double s = 1.0 - t;
        const double b0 = s * s * s, b1 = 3.0 * t * s * s, b2 = 3.0 * t * t * s, b3 = t * t * t;
        for (int k = 0; k < 3; ++k) out[3 * j + k] = b0 * P[k] + b1 * P[3 + k] + b2 * P[6 + k] + b3 * P[9 + k];
    }
}

double binomial(int n, int k) {
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

} // namespace

void CurveEvaluator::evaluate_spline(const double* params, std::size_t n, int max_order, bool all,
                                     double* out) const {
    const int d = dim_;
    const int p = degree_;
    const int hd = rational_ ? d + 1 : d;
    const double* t = knots_.data();
    const double* cw = homogeneous_.data();
    if (max_order == 0) {
        // The hot path of the benchmarks: points only.
        const double* inv = inverse_differences_.data();
        if (p == 3 && d == 3 && !rational_) {
            if (curve_.kind == CurveKind::Bezier) return bezier_cubic_points(cw, params, n, out);
            return spline_points_fixed_dim<3, 3>(t, cw, inv, first_span_, last_span_, params, n, out);
        }
        if (p == 3 && d == 3 && rational_) return spline_points_fixed_dim<3, 4>(t, cw, inv, first_span_, last_span_, params, n, out);
        if (p == 3 && d == 2 && !rational_) return spline_points_fixed_dim<3, 2>(t, cw, inv, first_span_, last_span_, params, n, out);
        if (p == 3) return spline_points_fixed<3>(t, cw, hd, rational_, d, first_span_, last_span_, params, n, out);
        if (p == 2) return spline_points_fixed<2>(t, cw, hd, rational_, d, first_span_, last_span_, params, n, out);
        if (p == 1) return spline_points_fixed<1>(t, cw, hd, rational_, d, first_span_, last_span_, params, n, out);
    }
    if (max_order == 1 && p == 3) {
        const double* inv = inverse_differences_.data();
        if (d == 3 && !rational_) return spline_d1_fixed<3, 3>(t, cw, inv, false, first_span_, last_span_, params, n, all, out);
        if (d == 3 && rational_) return spline_d1_fixed<3, 4>(t, cw, inv, true, first_span_, last_span_, params, n, all, out);
        if (d == 2 && !rational_) return spline_d1_fixed<3, 2>(t, cw, inv, false, first_span_, last_span_, params, n, all, out);
        if (d == 2 && rational_) return spline_d1_fixed<3, 3>(t, cw, inv, true, first_span_, last_span_, params, n, all, out);
    }
    const int first_order = all ? 0 : max_order;
    const int orders = max_order - first_order + 1;
    const int nd = std::min(max_order, p);
    std::vector<double> ders(static_cast<std::size_t>((nd + 1) * (p + 1)));
    std::vector<double> A(static_cast<std::size_t>((max_order + 1) * hd));
    std::vector<double> CK(static_cast<std::size_t>((max_order + 1) * d));
    int span = first_span_;
    for (std::size_t j = 0; j < n; ++j) {
        const double u = params[j];
        span = track_span(t, first_span_, last_span_, span, u);
        basis_function_derivatives(span, u, p, nd, t, ders.data());
        std::fill(A.begin(), A.end(), 0.0);
        const double* c = cw + static_cast<std::size_t>(span - p) * hd;
        for (int k = 0; k <= nd; ++k)
            for (int r = 0; r <= p; ++r) {
                const double b = ders[k * (p + 1) + r];
                for (int q = 0; q < hd; ++q) A[k * hd + q] += b * c[r * hd + q];
            }
        if (rational_) {
            // The NURBS Book A4.2: C^(k) = (A^(k) - sum_{i=1..k} binom(k,i) w^(i) C^(k-i)) / w.
            for (int k = 0; k <= max_order; ++k)
                for (int q = 0; q < d; ++q) {
                    double v = A[k * hd + q];
                    for (int i = 1; i <= k; ++i) v -= binomial(k, i) * A[i * hd + d] * CK[(k - i) * d + q];
                    CK[k * d + q] = v / A[d];
                }
        } else {
            for (int k = 0; k <= max_order; ++k)
                for (int q = 0; q < d; ++q) CK[k * d + q] = A[k * hd + q];
        }
        double* dst = out + static_cast<std::size_t>(j) * orders * d;
        for (int o = first_order; o <= max_order; ++o)
            for (int q = 0; q < d; ++q) dst[(o - first_order) * d + q] = CK[o * d + q];
    }
}

std::vector<double> evaluate_curve(const Curve& curve, const std::vector<double>& params, int order) {
    const CurveEvaluator ev(curve);
    require(order >= 0 && order <= kMaxDegree + 1, "invalid-argument",
            "the derivative order must be from 0 to " + std::to_string(kMaxDegree + 1));
    const auto u = ev.checked_params(params.data(), params.size());
    std::vector<double> out(u.size() * ev.dim());
    ev.evaluate(u.data(), u.size(), order, out.data());
    return out;
}

std::vector<double> evaluate_curve_all(const Curve& curve, const std::vector<double>& params, int max_order) {
    const CurveEvaluator ev(curve);
    require(max_order >= 0 && max_order <= kMaxDegree + 1, "invalid-argument",
            "the derivative order must be from 0 to " + std::to_string(kMaxDegree + 1));
    const auto u = ev.checked_params(params.data(), params.size());
    std::vector<double> out(u.size() * ev.dim() * (max_order + 1));
    ev.evaluate_all(u.data(), u.size(), max_order, out.data());
    return out;
}

BlendingValues blending_functions(const Curve& curve, const std::vector<double>& params, int order) {
    validate(curve);
    const int K = control_point_count(curve);
    BlendingValues r;
    r.count = curve.kind == CurveKind::Hermite ? 2 * K : K;
    // A blending function is the curve whose control items are all zero except item i = 1
    // (a scalar curve, dim = 1): exact for every family, rational ones included.
    Curve unit = curve;
    unit.dim = 1;
    unit.points.assign(static_cast<std::size_t>(K), 0.0);
    if (curve.kind == CurveKind::Hermite) unit.tangents.assign(static_cast<std::size_t>(K), 0.0);
    r.values.assign(params.size() * r.count, 0.0);
    std::vector<double> column(params.size());
    for (int i = 0; i < r.count; ++i) {
        if (i < K) unit.points[i] = 1.0;
        else unit.tangents[i - K] = 1.0;
        const CurveEvaluator ev(unit);
        const auto u = ev.checked_params(params.data(), params.size());
        ev.evaluate(u.data(), u.size(), order, column.data());
        for (std::size_t j = 0; j < params.size(); ++j) r.values[j * r.count + i] = column[j];
        if (i < K) unit.points[i] = 0.0;
        else unit.tangents[i - K] = 0.0;
    }
    return r;
}

} // namespace wingspline::curves
