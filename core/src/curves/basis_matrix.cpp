#include "wingspline/curves/basis_matrix.h"

#include "wingspline/error.h"

#include <glm/mat4x4.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <algorithm>
#include <cmath>

namespace wingspline::curves {

BasisKind parse_basis_kind(const std::string& name) {
    if (name == "hermite") return BasisKind::Hermite;
    if (name == "bezier") return BasisKind::Bezier;
    if (name == "bspline") return BasisKind::BSpline;
    if (name == "catmull-rom") return BasisKind::CatmullRom;
    throw Error("unknown-basis", "unknown basis '" + name +
                                     "'; expected hermite, bezier, bspline or catmull-rom");
}

const char* basis_kind_name(BasisKind kind) {
    switch (kind) {
    case BasisKind::Hermite: return "hermite";
    case BasisKind::Bezier: return "bezier";
    case BasisKind::BSpline: return "bspline";
    case BasisKind::CatmullRom: return "catmull-rom";
    }
    return "hermite";
}

Mat4 basis_matrix(BasisKind kind) {
    switch (kind) {
    case BasisKind::Hermite: // lecture 000: G = [p_k, p_k+1, t_k, t_k+1]
        return {2, -2, 1, 1,  -3, 3, -2, -1,  0, 0, 1, 0,  1, 0, 0, 0};
    case BasisKind::Bezier: // lecture 003: G = [P0 P1 P2 P3]
        return {-1, 3, -3, 1,  3, -6, 3, 0,  -3, 3, 0, 0,  1, 0, 0, 0};
    case BasisKind::BSpline: // lecture 003: (1/6) [-1 3 -3 1; 3 -6 3 0; -3 0 3 0; 1 4 1 0]
        return {-1.0 / 6, 3.0 / 6, -3.0 / 6, 1.0 / 6,   3.0 / 6, -6.0 / 6, 3.0 / 6, 0,
                -3.0 / 6, 0, 3.0 / 6, 0,                 1.0 / 6, 4.0 / 6, 1.0 / 6, 0};
    case BasisKind::CatmullRom: // lecture 003: (1/2) [-1 3 -3 1; 2 -5 4 -1; -1 0 1 0; 0 2 0 0]
        return {-0.5, 1.5, -1.5, 0.5,  1, -2.5, 2, -0.5,  -0.5, 0, 0.5, 0,  0, 1, 0, 0};
    }
    throw Error("unknown-basis", "unknown basis");
}

Mat4 cardinal_matrix(double tension) {
    const double s = (1.0 - tension) / 2.0;
    return {-s, 2 - s, s - 2, s,  2 * s, s - 3, 3 - 2 * s, -s,  -s, 0, s, 0,  0, 1, 0, 0};
}

Mat4 hermite_constraint_matrix() {
    return {0, 0, 0, 1,   // P(0)  = d
            1, 1, 1, 1,   // P(1)  = a + b + c + d
            0, 0, 1, 0,   // P'(0) = c
            3, 2, 1, 0};  // P'(1) = 3a + 2b + c
}

std::optional<RationalForm> rational_form(const std::vector<double>& values, int max_denominator) {
    for (double v : values)
        if (!std::isfinite(v) || std::abs(v) > 1e12) return std::nullopt;
    // The first d that works is the smallest: if d works, so does every multiple of d, and
    // the smallest common denominator leaves the integers without a common factor with d.
    for (int d = 1; d <= max_denominator; ++d) {
        RationalForm form;
        form.denominator = d;
        form.numerators.reserve(values.size());
        bool ok = true;
        for (double v : values) {
            const double scaled = v * d;
            const double whole = std::round(scaled);
            if (std::abs(scaled - whole) > kRationalTolerance * std::max(1.0, std::abs(scaled))) {
                ok = false;
                break;
            }
            form.numerators.push_back(static_cast<long long>(whole));
        }
        if (ok) return form;
    }
    return std::nullopt;
}

MatrixForm parse_matrix_form(const std::string& name) {
    if (name == "descending") return MatrixForm::Descending;
    if (name == "ascending") return MatrixForm::Ascending;
    if (name == "transposed") return MatrixForm::Transposed;
    throw Error("unknown-form", "unknown matrix form '" + name +
                                    "'; expected descending (lectures 000, 003), ascending (002) or transposed (001)");
}

const char* matrix_form_name(MatrixForm form) {
    switch (form) {
    case MatrixForm::Descending: return "descending";
    case MatrixForm::Ascending: return "ascending";
    case MatrixForm::Transposed: return "transposed";
    }
    return "descending";
}

std::vector<double> matrix_in_form(const std::vector<double>& values, int rows, int cols, MatrixForm form) {
    require(rows >= 0 && cols >= 0 && values.size() == static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols),
            "invalid-argument", "the matrix has " + std::to_string(values.size()) + " entries, not " +
                                    std::to_string(rows) + " x " + std::to_string(cols));
    std::vector<double> r(values.size());
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j) {
            const double v = values[static_cast<std::size_t>(cols * i + j)];
            if (form == MatrixForm::Ascending) r[static_cast<std::size_t>(cols * (rows - 1 - i) + j)] = v;
            else if (form == MatrixForm::Transposed) r[static_cast<std::size_t>(rows * j + i)] = v;
            else r[static_cast<std::size_t>(cols * i + j)] = v;
        }
    return r;
}

Mat4 basis_matrix(BasisKind kind, MatrixForm form) {
    const Mat4 m = basis_matrix(kind);
    const auto shown = matrix_in_form(std::vector<double>(m.begin(), m.end()), 4, 4, form);
    Mat4 r{};
    std::copy(shown.begin(), shown.end(), r.begin());
    return r;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a[4 * i + k] * b[4 * k + j];
            r[4 * i + j] = s;
        }
    return r;
}

Mat4 transpose(const Mat4& m) {
    Mat4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[4 * j + i] = m[4 * i + j];
    return r;
}

Mat4 inverse(const Mat4& m) {
    // GLM is column-major: glm_m[col][row].
    glm::dmat4 g;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) g[j][i] = m[4 * i + j];
    const double det = glm::determinant(g);
    double scale = 0;
    for (double v : m) scale = std::max(scale, std::abs(v));
    require(std::isfinite(det) && std::abs(det) > 1e-12 * std::pow(scale, 4), "singular-matrix",
            "the matrix is singular (determinant " + std::to_string(det) + "), so it has no inverse");
    const glm::dmat4 inv = glm::inverse(g);
    Mat4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[4 * i + j] = inv[j][i];
    return r;
}

} // namespace wingspline::curves
