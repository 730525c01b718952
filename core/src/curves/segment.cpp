#include "wingspline/curves/segment.h"

#include "wingspline/curves/bezier.h"
#include "wingspline/curves/bspline_basis.h"
#include "wingspline/curves/linear_algebra.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>

namespace wingspline::curves {

int segment_count(const Curve& c) {
    validate(c);
    const int K = control_point_count(c);
    switch (c.kind) {
    case CurveKind::Bezier:
    case CurveKind::Interpolation: return 1;
    case CurveKind::Hermite: return K - 1;
    case CurveKind::CatmullRom:
    case CurveKind::Cardinal: return K - 3;
    case CurveKind::BSpline:
    case CurveKind::Nurbs: {
        const int p = curve_degree(c);
        if (c.knots.empty()) return K - p;
        int count = 0;
        for (int l = p; l < K; ++l) count += c.knots[l] < c.knots[l + 1] ? 1 : 0;
        return count;
    }
    }
    return 1;
}

int segment_at(const Curve& c, double t) {
    const int count = segment_count(c); // validates
    const CurveEvaluator ev(c);
    const double u = ev.checked_params(&t, 1)[0];
    if (count <= 1) return 0;
    if (c.kind == CurveKind::BSpline || c.kind == CurveKind::Nurbs) {
        const int K = control_point_count(c);
        const int p = curve_degree(c);
        const std::vector<double> knots = c.knots.empty() ? uniform_knots(K, p) : c.knots;
        int index = -1;
        for (int l = p; l < K; ++l) {
            if (knots[l + 1] > knots[l]) {
                ++index;
                if (u < knots[l + 1]) return index;
            }
        }
        return std::max(0, index);
    }
    const Domain d = ev.domain();
    const double at = std::floor((u - d.start) / (d.end - d.start) * count);
    return static_cast<int>(std::min<double>(count - 1, std::max(0.0, at)));
}

namespace {

std::vector<double> from_mat4(const Mat4& m) { return std::vector<double>(m.begin(), m.end()); }

std::string indexed(const char* name, int i) { return std::string(name) + "_" + std::to_string(i); }

} // namespace

SegmentMatrices segment_matrices(const Curve& c, int segment) {
    const int count = segment_count(c);
    require(segment >= 0 && segment < count, "segment-out-of-range",
            "segment " + std::to_string(segment) + " does not exist; this " + curve_kind_name(c.kind) +
                " curve has segments 0 to " + std::to_string(count - 1));
    const int K = control_point_count(c);
    const int d = c.dim;
    SegmentMatrices s;
    s.segment = segment;
    s.segment_count = count;
    s.degree = curve_degree(c);
    s.columns = d;
    const int p = s.degree;
    auto take_points = [&](int first) {
        for (int r = 0; r <= p; ++r) {
            s.control_indices.push_back(first + r);
            s.labels.push_back(indexed("P", first + r));
            for (int k = 0; k < d; ++k) s.G.push_back(c.points[(first + r) * d + k]);
        }
    };
    switch (c.kind) {
    case CurveKind::Hermite: {
        s.basis = "hermite";
        s.M = from_mat4(basis_matrix(BasisKind::Hermite));
        const int k0 = segment;
        s.control_indices = {k0, k0 + 1, k0, k0 + 1};
        s.labels = {indexed("p", k0), indexed("p", k0 + 1), indexed("t", k0), indexed("t", k0 + 1)};
        for (int k = 0; k < d; ++k) s.G.push_back(c.points[k0 * d + k]);
        for (int k = 0; k < d; ++k) s.G.push_back(c.points[(k0 + 1) * d + k]);
        for (int k = 0; k < d; ++k) s.G.push_back(c.tangents[k0 * d + k]);
        for (int k = 0; k < d; ++k) s.G.push_back(c.tangents[(k0 + 1) * d + k]);
        s.start = segment;
        s.end = segment + 1;
        break;
    }
    case CurveKind::CatmullRom:
    case CurveKind::Cardinal:
        s.basis = curve_kind_name(c.kind);
        s.M = from_mat4(c.kind == CurveKind::CatmullRom ? basis_matrix(BasisKind::CatmullRom)
                                                         : cardinal_matrix(c.tension));
        take_points(segment);
        s.start = segment;
        s.end = segment + 1;
        break;
    case CurveKind::Bezier: {
        s.basis = "bezier";
        s.M = p == 3 ? from_mat4(basis_matrix(BasisKind::Bezier)) : bezier_power_matrix(p);
        take_points(0);
        if (!c.weights.empty()) {
            s.homogeneous = true;
            s.columns = d + 1;
            std::vector<double> h;
            for (int i = 0; i <= p; ++i) {
                for (int k = 0; k < d; ++k) h.push_back(c.weights[i] * c.points[i * d + k]);
                h.push_back(c.weights[i]);
            }
            s.G = h;
        }
        break;
    }
    case CurveKind::Interpolation: {
        s.basis = "interpolation";
        const std::vector<double> u = interpolation_nodes(c);
        // Lecture 000: (a_n ... a_0) = V^-1 (p_0 ... p_n), so M = V^-1 and C = M G. Column j
        // of V^-1 holds the power coefficients of the Lagrange polynomial L_j, expanded
        // factor by factor from prod_(m != j) (u - u_m) / (u_j - u_m): no elimination, so no
        // pivot test that depends on the offset or scale of the nodes.
        s.M = vandermonde_inverse(u);
        take_points(0);
        s.start = u.front();
        s.end = u.back();
        s.local_parameter = false;
        break;
    }
    case CurveKind::BSpline:
    case CurveKind::Nurbs: {
        s.basis = "bspline";
        const std::vector<double> t = c.knots.empty() ? uniform_knots(K, p) : c.knots;
        int l = p;
        for (int seen = -1; l < K; ++l)
            if (t[l] < t[l + 1] && ++seen == segment) break;
        s.start = t[l];
        s.end = t[l + 1];
        take_points(l - p);
        if (c.kind == CurveKind::BSpline && c.knots.empty() && p == 3) {
            s.M = from_mat4(basis_matrix(BasisKind::BSpline)); // lecture 003's (1/6)[...]
        } else {
            // Column r of M holds the power coefficients, in the local u, of the basis
            // function N_{l-p+r,p} on this span: its Taylor coefficients at the span start,
            // d^k N / dt^k (t_l) h^k / k! for u^k (h = t_{l+1} - t_l), exact up to rounding.
            const double h = s.end - s.start;
            std::vector<double> ders(static_cast<std::size_t>((p + 1) * (p + 1)));
            basis_function_derivatives(l, t[l], p, p, t.data(), ders.data());
            s.M.assign(static_cast<std::size_t>((p + 1) * (p + 1)), 0.0);
            double scale = 1; // h^k / k!
            for (int k = 0; k <= p; ++k) {
                for (int r = 0; r <= p; ++r) s.M[(p - k) * (p + 1) + r] = ders[k * (p + 1) + r] * scale;
                scale *= h / (k + 1);
            }
        }
        if (c.kind == CurveKind::Nurbs) {
            s.homogeneous = true;
            s.columns = d + 1;
            std::vector<double> h;
            for (int r = 0; r <= p; ++r) {
                const int i = l - p + r;
                const double w = c.weights.empty() ? 1.0 : c.weights[i];
                for (int k = 0; k < d; ++k) h.push_back(w * c.points[i * d + k]);
                h.push_back(w);
            }
            s.G = h;
        }
        break;
    }
    }
    s.C = multiply_n(s.M, s.G, p + 1, p + 1, s.columns);
    return s;
}

std::vector<double> convert_basis(const std::vector<double>& G, int dim, BasisKind from, BasisKind to) {
    require(dim >= 1 && dim <= 3, "invalid-dimension", "dim must be 2 or 3, not " + std::to_string(dim));
    require(G.size() == static_cast<std::size_t>(4 * dim), "wrong-point-count",
            "a cubic segment has 4 geometry rows (" + std::to_string(4 * dim) + " numbers), not " +
                std::to_string(G.size()) + " numbers");
    for (std::size_t i = 0; i < G.size(); ++i)
        require(std::isfinite(G[i]), "non-finite-input",
                "geometry row " + std::to_string(i / dim) + " has a value that is not a finite number");
    const Mat4 T = multiply(inverse(basis_matrix(to)), basis_matrix(from));
    return multiply_n(std::vector<double>(T.begin(), T.end()), G, 4, 4, dim);
}

SegmentForm segment_in_form(const SegmentMatrices& s, MatrixForm form) {
    const int n = s.degree + 1;
    const int rows = static_cast<int>(s.G.size()) / std::max(1, s.columns);
    SegmentForm f;
    f.form = form;
    f.m_size = n;
    f.M = matrix_in_form(s.M, n, n, form);
    f.C = matrix_in_form(s.C, rows, s.columns, form);
    // The geometry keeps its row order in 002's form (only the powers are reversed).
    f.G = form == MatrixForm::Transposed ? matrix_in_form(s.G, rows, s.columns, form) : s.G;
    f.g_rows = form == MatrixForm::Transposed ? s.columns : rows;
    f.g_cols = form == MatrixForm::Transposed ? rows : s.columns;
    return f;
}

} // namespace wingspline::curves
