// Curve bindings (issue 5). Every function takes plain values (the JS layer in
// web/js/core/curves-api.js has already normalised and type-checked them: every curve spec
// arrives with all fields, arrays as Float64Array) and returns {ok:true, ...} or
// {ok:false, code, message} through guarded(); bulk results leave as copied typed arrays.
#include "boundary.h"

#include "wingspline/curves/bezier.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/segment.h"

#include <malloc.h>
#include <string>
#include <vector>

namespace wingspline::bindings {
namespace {

using namespace wingspline::curves;

Curve curve_from(const val& spec) {
    Curve c;
    c.kind = parse_curve_kind(spec["kind"].as<std::string>());
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

val doubles_array(const std::vector<std::vector<double>>& rows) {
    val a = val::array();
    for (std::size_t i = 0; i < rows.size(); ++i) a.set(i, to_typed_array(rows[i]));
    return a;
}

val ints(const std::vector<int>& v) {
    std::vector<int32_t> w(v.begin(), v.end());
    return to_typed_array(w);
}

// curveEvaluate(spec, params, order, all) -> {values}: all = false gives the derivative of
// `order` only (dim per param); all = true gives orders 0..order ((order+1)*dim per param).
val curve_evaluate(const val& spec, const val& params, int order, bool all) {
    return guarded([&] {
        const CurveEvaluator ev(curve_from(spec));
        require(order >= 0 && order <= kMaxDegree + 1, "invalid-argument",
                "the derivative order must be a whole number from 0 to " + std::to_string(kMaxDegree + 1));
        const std::vector<double> raw = to_doubles(params);
        const std::vector<double> u = ev.checked_params(raw.data(), raw.size());
        const std::size_t per = static_cast<std::size_t>(ev.dim()) * (all ? order + 1 : 1);
        std::vector<double> out(u.size() * per);
        if (all) ev.evaluate_all(u.data(), u.size(), order, out.data());
        else ev.evaluate(u.data(), u.size(), order, out.data());
        val r = val::object();
        r.set("values", to_typed_array(out));
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

val curve_blending(const val& spec, const val& params, int order) {
    return guarded([&] {
        require(order >= 0 && order <= kMaxDegree + 1, "invalid-argument",
                "the derivative order must be a whole number from 0 to " + std::to_string(kMaxDegree + 1));
        const BlendingValues b = blending_functions(curve_from(spec), to_doubles(params), order);
        val r = val::object();
        r.set("count", b.count);
        r.set("values", to_typed_array(b.values));
        return r;
    });
}

val curve_segment(const val& spec, int index) {
    return guarded([&] {
        const SegmentMatrices s = segment_matrices(curve_from(spec), index);
        val r = val::object();
        r.set("segment", s.segment);
        r.set("segmentCount", s.segment_count);
        r.set("degree", s.degree);
        r.set("columns", s.columns);
        r.set("M", to_typed_array(s.M));
        r.set("G", to_typed_array(s.G));
        r.set("C", to_typed_array(s.C));
        r.set("controlIndices", ints(s.control_indices));
        val labels = val::array();
        for (std::size_t i = 0; i < s.labels.size(); ++i) labels.set(i, s.labels[i]);
        r.set("labels", labels);
        r.set("start", s.start);
        r.set("end", s.end);
        r.set("localParameter", s.local_parameter);
        r.set("homogeneous", s.homogeneous);
        r.set("basis", s.basis);
        return r;
    });
}

val bezier_de_casteljau(const val& points, int dim, double t, const val& weights) {
    return guarded([&] {
        const DeCasteljauSteps s = de_casteljau(to_doubles(points), dim, t, to_doubles(weights));
        val r = val::object();
        r.set("degree", s.degree);
        r.set("levels", doubles_array(s.levels));
        r.set("levelWeights", doubles_array(s.level_weights));
        return r;
    });
}

val bezier_subdivide(const val& points, int dim, double t, const val& weights) {
    return guarded([&] {
        const BezierSplit s = subdivide_bezier(to_doubles(points), dim, t, to_doubles(weights));
        val r = val::object();
        r.set("left", to_typed_array(s.left));
        r.set("right", to_typed_array(s.right));
        r.set("leftWeights", to_typed_array(s.left_weights));
        r.set("rightWeights", to_typed_array(s.right_weights));
        return r;
    });
}

val bezier_subdivision_matrix_pair(int degree, double t) {
    return guarded([&] {
        std::vector<double> SL, SR;
        bezier_subdivision_matrices(degree, t, SL, SR);
        val r = val::object();
        r.set("left", to_typed_array(SL));
        r.set("right", to_typed_array(SR));
        return r;
    });
}

val bezier_elevate(const val& points, int dim, const val& weights) {
    return guarded([&] {
        const ElevatedBezier e = elevate_bezier(to_doubles(points), dim, to_doubles(weights));
        val r = val::object();
        r.set("points", to_typed_array(e.points));
        r.set("weights", to_typed_array(e.weights));
        return r;
    });
}

val basis_convert(const val& G, int dim, const std::string& from, const std::string& to) {
    return guarded([&] {
        const auto q = convert_basis(to_doubles(G), dim, parse_basis_kind(from), parse_basis_kind(to));
        val r = val::object();
        r.set("points", to_typed_array(q));
        return r;
    });
}

// Bytes of the wasm heap in use (dlmalloc's count): the leak tests watch it across
// thousands of failing calls.
double heap_bytes_in_use() { return static_cast<double>(mallinfo().uordblks); }

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_curves) {
    using namespace wingspline::bindings;
    emscripten::function("heapBytesInUse", &heap_bytes_in_use);
    emscripten::function("curveEvaluate", &curve_evaluate);
    emscripten::function("curveDomain", &curve_domain);
    emscripten::function("curveBlending", &curve_blending);
    emscripten::function("curveSegment", &curve_segment);
    emscripten::function("bezierDeCasteljau", &bezier_de_casteljau);
    emscripten::function("bezierSubdivide", &bezier_subdivide);
    emscripten::function("bezierSubdivisionMatrices", &bezier_subdivision_matrix_pair);
    emscripten::function("bezierElevate", &bezier_elevate);
    emscripten::function("basisConvert", &basis_convert);
}
