#include "wingspline/curves/patch.h"

#include "wingspline/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace wingspline::curves {

namespace {

// Row vectors [u^3 u^2 u 1] and their derivatives.
void powers(double u, int order, double out[4]) {
    if (order == 0) { out[0] = u * u * u; out[1] = u * u; out[2] = u; out[3] = 1; }
    else if (order == 1) { out[0] = 3 * u * u; out[1] = 2 * u; out[2] = 1; out[3] = 0; }
    else { out[0] = 6 * u; out[1] = 2; out[2] = 0; out[3] = 0; }
}

} // namespace

PatchSamples sample_patch(BasisKind kind, const std::vector<double>& P, int nu, int nv) {
    require(kind == BasisKind::Hermite || kind == BasisKind::Bezier, "unknown-basis",
            "patches are sampled in the hermite or bezier basis");
    require(P.size() == 48, "wrong-point-count",
            "a bicubic patch needs a 4 x 4 geometry matrix of 3D vectors (48 numbers), not " + std::to_string(P.size()));
    for (std::size_t i = 0; i < P.size(); ++i)
        require(std::isfinite(P[i]), "non-finite-input",
                "geometry entry (" + std::to_string(i / 12) + ", " + std::to_string((i / 3) % 4) + ") has a value that is not a finite number");
    require(nu >= 2 && nv >= 2 && nu <= 4096 && nv <= 4096, "invalid-argument",
            "the grid needs 2 to 4096 samples in each direction");
    const Mat4 M = basis_matrix(kind);
    const Mat4 MT = transpose(M);
    // A_k = M P_k M^T for every coordinate k: p(u,v)_k = U A_k V^T.
    double A[3][16];
    for (int k = 0; k < 3; ++k) {
        Mat4 Pk{};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) Pk[4 * i + j] = P[3 * (4 * i + j) + k];
        const Mat4 r = multiply(multiply(M, Pk), MT);
        for (int q = 0; q < 16; ++q) A[k][q] = r[q];
    }
    auto eval = [&](double u, double v, int ou, int ov, double out[3]) {
        double U[4], V[4];
        powers(u, ou, U);
        powers(v, ov, V);
        for (int k = 0; k < 3; ++k) {
            double s = 0;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) s += U[i] * A[k][4 * i + j] * V[j];
            out[k] = s;
        }
    };
    PatchSamples s;
    s.nu = nu;
    s.nv = nv;
    const std::size_t n = static_cast<std::size_t>(nu) * nv * 3;
    s.positions.resize(n);
    s.normals.resize(n);
    s.du.resize(n);
    s.dv.resize(n);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = static_cast<double>(i) / (nu - 1), v = static_cast<double>(j) / (nv - 1);
            const std::size_t at = 3 * (static_cast<std::size_t>(nv) * i + j);
            eval(u, v, 0, 0, &s.positions[at]);
            eval(u, v, 1, 0, &s.du[at]);
            eval(u, v, 0, 1, &s.dv[at]);
            const double* a = &s.du[at];
            const double* b = &s.dv[at];
            const double nx = a[1] * b[2] - a[2] * b[1], ny = a[2] * b[0] - a[0] * b[2], nz = a[0] * b[1] - a[1] * b[0];
            const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
            const double inv = len > 1e-300 ? 1 / len : 0;
            s.normals[at] = nx * inv;
            s.normals[at + 1] = ny * inv;
            s.normals[at + 2] = nz * inv;
        }
    s.twists.resize(12);
    const double corners[4][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
    for (int c = 0; c < 4; ++c) eval(corners[c][0], corners[c][1], 1, 1, &s.twists[3 * c]);
    return s;
}

} // namespace wingspline::curves
