// Curve sampling: points and derivatives of a curve, its domain, the knot vector presets and
// the subdivision of a control polygon (Chaikin, Lane-Riesenfeld). Linked into both the
// curves and the subdivision modules (CMakeLists.txt, WINGSPLINE_BINDINGS_sampling): the
// subdivision lesson draws a polygon's limit B-spline beside its meshes and loads only the
// subdivision module.
#include "boundary.h"
#include "curve_spec.h"

#include "wingspline/curves/curve.h"
#include "wingspline/curves/knot_vectors.h"
#include "wingspline/curves/segment.h"
#include "wingspline/curves/subdivision.h"

#include <string>
#include <vector>

namespace wingspline::bindings {
namespace {

using namespace wingspline::curves;

// curveEvaluate(spec, params, order, all) -> {values}: all = false gives the derivative of
// `order` only (dim per param); all = true gives orders 0..order ((order+1)*dim per param).
// Batches run in chunks of kChunk parameters: copy a chunk of params into wasm memory,
// check and evaluate it, copy its points straight into the JS result. The data stay in
// cache between the steps and the wasm heap never holds the whole batch (1e6 points would
// otherwise grow it by 40 MB).
constexpr std::size_t kChunk = 8192;

// out: undefined (a new Float64Array is returned) or a Float64Array of the right length
// that the JS layer checked; filling it avoids allocating a new array on every redraw. On
// an error the contents of a given `out` are unspecified (the error says which parameter).
val curve_evaluate(const val& spec, const val& params, int order, bool all, const val& out_array) {
    return guarded([&] {
        const CurveEvaluator ev(curve_from(spec));
        require(order >= 0 && order <= kMaxDegree + 1, "invalid-argument",
                "the derivative order must be a whole number from 0 to " + std::to_string(kMaxDegree + 1));
        const std::size_t n = params["length"].as<std::size_t>();
        const std::size_t per = static_cast<std::size_t>(ev.dim()) * (all ? order + 1 : 1);
        val result = out_array.isUndefined() ? val::global("Float64Array").new_(n * per) : out_array;
        std::vector<double> u(std::min(n, kChunk));
        std::vector<double> points(u.size() * per);
        for (std::size_t start = 0; start < n; start += kChunk) {
            const std::size_t m = std::min(kChunk, n - start);
            val(emscripten::typed_memory_view(m, u.data()))
                .call<void>("set", params.call<val>("subarray", start, start + m));
            ev.check_params(u.data(), m, start);
            if (all) ev.evaluate_all(u.data(), m, order, points.data());
            else ev.evaluate(u.data(), m, order, points.data());
            result.call<void>("set", val(emscripten::typed_memory_view(m * per, points.data())), start * per);
        }
        val r = val::object();
        r.set("values", result);
        return r;
    });
}

val curve_domain(const val& spec) {
    return guarded([&] {
        const Curve c = curve_from(spec);
        const CurveEvaluator ev(c);
        val r = val::object();
        r.set("start", ev.domain().start);
        r.set("end", ev.domain().end);
        r.set("degree", ev.degree());
        r.set("controlPointCount", control_point_count(c));
        r.set("segmentCount", segment_count(c));
        return r;
    });
}

// style: 'clamped' | 'uniform' (count, degree) or 'unclamped' (from knots, degree).
val knot_vector(const std::string& style, int count, int degree, const val& knots) {
    return guarded([&] {
        std::vector<double> t;
        if (style == "clamped") t = clamped_knots(count, degree);
        else if (style == "unclamped") t = unclamped_knots(to_doubles(knots), degree);
        else if (style == "uniform") {
            require(degree >= 1 && degree <= kMaxDegree && count >= degree + 1, "invalid-argument",
                    "a uniform B-spline needs a degree from 1 to " + std::to_string(kMaxDegree) + " and at least degree + 1 points");
            t = uniform_knots(count, degree);
        } else throw Error("invalid-argument", "the knot style must be clamped, uniform or unclamped");
        val r = val::object();
        r.set("knots", to_typed_array(t));
        return r;
    });
}

val curve_subdivide(const val& points, int32_t dim, const std::string& scheme, bool closed, int32_t steps) {
    return guarded([&] {
        val r = val::object();
        r.set("points", to_typed_array(subdivide_curve(to_doubles(points), dim,
                                                               curve_subdivision_from_name(scheme), closed, steps)));
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_curve_sampling) {
    using namespace wingspline::bindings;
    emscripten::function("curveEvaluate", &curve_evaluate);
    emscripten::function("curveDomain", &curve_domain);
    emscripten::function("knotVector", &knot_vector);
    emscripten::function("curveSubdivide", &curve_subdivide);
}
