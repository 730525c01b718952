#include "wingspline/curves/overlays.h"

#include "wingspline/curves/analysis.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace wingspline::curves {

CurvatureComb curvature_comb(const Curve& curve, const std::vector<double>& params) {
    require(curve.dim == 2, "invalid-dimension", "the curvature comb is drawn for plane curves (dim 2), not dim " + std::to_string(curve.dim));
    const CurvatureValues k = curvature(curve, params);
    const std::vector<double> p = evaluate_curve(curve, params);
    CurvatureComb comb;
    comb.teeth.resize(4 * params.size());
    for (std::size_t j = 0; j < params.size(); ++j) {
        const double kappa = k.signed_curvature[j];
        comb.teeth[4 * j] = p[2 * j];
        comb.teeth[4 * j + 1] = p[2 * j + 1];
        comb.teeth[4 * j + 2] = kappa * -k.tangent[2 * j + 1];
        comb.teeth[4 * j + 3] = kappa * k.tangent[2 * j];
        comb.max_curvature = std::max(comb.max_curvature, std::abs(kappa));
        comb.singular += k.singular[j] ? 1 : 0;
    }
    return comb;
}

std::vector<double> homogeneous_lift(const std::vector<double>& points, int dim, const std::vector<double>& weights) {
    require(dim == 2 || dim == 3, "invalid-dimension", "dim must be 2 or 3, not " + std::to_string(dim));
    require(points.size() % dim == 0, "invalid-points",
            "points has " + std::to_string(points.size()) + " numbers, which is not a multiple of dim = " + std::to_string(dim));
    const std::size_t n = points.size() / dim;
    require(weights.size() == n, "wrong-weight-count",
            "there are " + std::to_string(n) + " points but " + std::to_string(weights.size()) + " weights");
    std::vector<double> h;
    h.reserve(n * (dim + 1));
    for (std::size_t i = 0; i < n; ++i) {
        require(std::isfinite(weights[i]) && weights[i] > 0, "invalid-weight",
                "the weight of point " + std::to_string(i) + " must be a finite number > 0");
        for (int k = 0; k < dim; ++k) {
            require(std::isfinite(points[dim * i + k]), "non-finite-input",
                    "point " + std::to_string(i) + " has a value that is not a finite number");
            h.push_back(weights[i] * points[dim * i + k]);
        }
        h.push_back(weights[i]);
    }
    return h;
}

} // namespace wingspline::curves
