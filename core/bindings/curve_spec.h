#pragma once
// The curve spec as the JS layer sends it (web/js/core/curves-api.js normalizeCurve: every
// field present, arrays as Float64Array) read into a core Curve. Shared by the curve
// binding translation units.
#include "boundary.h"

#include "wingspline/curves/curve.h"

#include <string>
#include <vector>

namespace wingspline::bindings {

inline curves::Curve curve_from(const val& spec) {
    curves::Curve c;
    c.kind = curves::parse_curve_kind(spec["kind"].as<std::string>());
    c.dim = spec["dim"].as<int>();
    c.points = to_doubles(spec["points"]);
    c.degree = spec["degree"].as<int>();
    c.knots = to_doubles(spec["knots"]);
    c.weights = to_doubles(spec["weights"]);
    c.tangents = to_doubles(spec["tangents"]);
    c.nodes = to_doubles(spec["nodes"]);
    c.tension = spec["tension"].as<double>();
    return c;
}

// A JS array of normalised curve specs.
inline std::vector<curves::Curve> curves_from(const val& specs) {
    const std::size_t n = specs["length"].as<std::size_t>();
    std::vector<curves::Curve> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) out.push_back(curve_from(specs[i]));
    return out;
}

} // namespace wingspline::bindings
