// Curve bindings. Every function takes plain values (the JS layer in
// web/js/core/curves-api.js has already normalised and type-checked them: every curve spec
// arrives with all fields, arrays as Float64Array) and returns {ok:true, ...} or
// {ok:false, code, message} through guarded(); bulk results leave as copied typed arrays.
#include "boundary.h"
#include "curve_spec.h"
#include "rational.h"

#include "wingspline/curves/analysis.h"
#include "wingspline/curves/bezier.h"
#include "wingspline/curves/bspline_ops.h"
#include "wingspline/curves/conics.h"
#include "wingspline/curves/constraints.h"
#include "wingspline/curves/curve.h"
#include "wingspline/curves/derivation.h"
#include "wingspline/curves/guarantees.h"
#include "wingspline/curves/knot_vectors.h"
#include "wingspline/curves/linear_algebra.h"
#include "wingspline/curves/patch.h"
#include "wingspline/curves/segment.h"

#include <string>
#include <vector>

namespace wingspline::bindings {
namespace {

using namespace wingspline::curves;

val doubles_array(const std::vector<std::vector<double>>& rows) {
    val a = val::array();
    for (std::size_t i = 0; i < rows.size(); ++i) a.set(i, to_typed_array(rows[i]));
    return a;
}

val ints(const std::vector<int>& v) {
    std::vector<int32_t> w(v.begin(), v.end());
    return to_typed_array(w);
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

val curve_segment(const val& spec, int index, const std::string& form_name) {
    return guarded([&] {
        const MatrixForm form = parse_matrix_form(form_name);
        const SegmentMatrices s = segment_matrices(curve_from(spec), index);
        val r = val::object();
        r.set("segment", s.segment);
        r.set("segmentCount", s.segment_count);
        r.set("degree", s.degree);
        r.set("columns", s.columns);
        r.set("M", to_typed_array(s.M));
        r.set("rational", rational_value(s.M)); // M as the slide writes it, or null
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
        // M, G, C as the chosen lecture writes them (segment_in_form).
        const SegmentForm f = segment_in_form(s, form);
        val shown = val::object();
        shown.set("form", std::string(matrix_form_name(f.form)));
        shown.set("M", to_typed_array(f.M));
        shown.set("G", to_typed_array(f.G));
        shown.set("C", to_typed_array(f.C));
        shown.set("size", f.m_size);
        shown.set("geometryRows", f.g_rows);
        shown.set("geometryColumns", f.g_cols);
        shown.set("rational", rational_value(f.M));
        r.set("shown", shown);
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
        // As lecture 002 writes them, 1/8 [integers] at t = 1/2 (null if none).
        r.set("leftRational", rational_value(SL));
        r.set("rightRational", rational_value(SR));
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

// A curve back to JS: { kind, dim, points, degree, knots?, weights? } (plain values).
val curve_to_val(const Curve& c) {
    val r = val::object();
    r.set("kind", std::string(curve_kind_name(c.kind)));
    r.set("dim", c.dim);
    r.set("points", to_typed_array(c.points));
    r.set("degree", curve_degree(c));
    if (!c.knots.empty()) r.set("knots", to_typed_array(c.knots));
    if (!c.weights.empty()) r.set("weights", to_typed_array(c.weights));
    return r;
}

val bspline_de_boor(const val& spec, double u) {
    return guarded([&] {
        const DeBoorSteps s = de_boor(curve_from(spec), u);
        val r = val::object();
        r.set("span", s.span);
        r.set("degree", s.degree);
        r.set("firstIndex", s.first_index);
        r.set("levels", doubles_array(s.levels));
        r.set("levelWeights", doubles_array(s.level_weights));
        r.set("alphas", doubles_array(s.alphas));
        return r;
    });
}

val bspline_insert_knot(const val& spec, double u) {
    return guarded([&] {
        const KnotInsertion k = insert_knot(curve_from(spec), u);
        val r = val::object();
        r.set("curve", curve_to_val(k.curve));
        r.set("span", k.span);
        r.set("insertedIndex", k.inserted_index);
        r.set("recomputed", ints(k.recomputed));
        r.set("alphas", to_typed_array(k.alphas));
        r.set("newPoints", ints(k.new_points));
        return r;
    });
}

val bspline_to_bezier(const val& spec) {
    return guarded([&] {
        const auto segments = to_bezier_segments(curve_from(spec));
        val list = val::array();
        for (std::size_t i = 0; i < segments.size(); ++i) {
            val seg = val::object();
            seg.set("points", to_typed_array(segments[i].points));
            if (!segments[i].weights.empty()) seg.set("weights", to_typed_array(segments[i].weights));
            seg.set("start", segments[i].start);
            seg.set("end", segments[i].end);
            list.set(i, seg);
        }
        val r = val::object();
        r.set("segments", list);
        return r;
    });
}

val bspline_knot_multiplicities(const val& spec) {
    return guarded([&] {
        const auto knots = knot_multiplicities(curve_from(spec));
        std::vector<double> values;
        std::vector<int> mult, first, interior, continuity;
        for (const auto& k : knots) {
            values.push_back(k.value);
            mult.push_back(k.multiplicity);
            first.push_back(k.first_index);
            interior.push_back(k.interior ? 1 : 0);
            continuity.push_back(k.continuity);
        }
        val r = val::object();
        r.set("knots", to_typed_array(as_explicit_bspline(curve_from(spec)).knots));
        r.set("values", to_typed_array(values));
        r.set("multiplicities", ints(mult));
        r.set("firstIndices", ints(first));
        r.set("interior", ints(interior));
        r.set("continuity", ints(continuity));
        return r;
    });
}

// The maths out of the lessons: the segment holding a parameter, knot vector presets,
// and the continuity constraints of a piecewise curve while it is dragged.
val curve_segment_at(const val& spec, double t) {
    return guarded([&] {
        val r = val::object();
        r.set("segment", segment_at(curve_from(spec), t));
        return r;
    });
}


val knots_clamped(const val& knots, int degree) {
    return guarded([&] {
        val r = val::object();
        const auto t = to_doubles(knots);
        r.set("clamped", is_clamped(t, degree));
        r.set("bezier", is_bezier_in_disguise(t, degree));
        return r;
    });
}

// op: 'drag' (index, to), 'enforce' or 'append'.
val joint_constraint(const std::string& op, const val& points, int dim, const std::string& family, const std::string& mode,
                     int index, const val& to) {
    return guarded([&] {
        const std::vector<double> p = to_doubles(points);
        const BasisKind basis = parse_basis_kind(family);
        const JointConstraint m = parse_joint_constraint(mode);
        std::vector<double> out;
        if (op == "drag") out = drag_with_constraint(p, dim, basis, m, index, to_doubles(to));
        else if (op == "enforce") out = enforce_constraint(p, dim, basis, m);
        else if (op == "append") out = append_segment(p, dim, basis, m);
        else throw Error("invalid-argument", "the constraint operation must be drag, enforce or append");
        val r = val::object();
        r.set("points", to_typed_array(out));
        return r;
    });
}

val nurbs_preset(const std::string& shape, const val& a, const val& b, const val& c, int dim, const val& numbers) {
    return guarded([&] {
        const std::vector<double> n = to_doubles(numbers);
        auto number = [&](std::size_t i) { return i < n.size() ? n[i] : 0.0; };
        Curve curve;
        if (shape == "circle") curve = nurbs_circle(to_doubles(a), dim, number(0));
        else if (shape == "arc") curve = nurbs_arc(to_doubles(a), dim, number(0), number(1), number(2));
        else if (shape == "ellipse") curve = nurbs_ellipse(to_doubles(a), dim, number(0), number(1));
        else if (shape == "conic") curve = nurbs_conic(to_doubles(a), to_doubles(b), to_doubles(c), dim, number(0));
        else throw Error("invalid-argument", "unknown preset '" + shape.substr(0, 40) + "'");
        val r = val::object();
        r.set("curve", curve_to_val(curve));
        if (shape == "conic") r.set("conicType", std::string(conic_type(number(0))));
        return r;
    });
}

val curve_curvature(const val& spec, const val& params) {
    return guarded([&] {
        const CurvatureValues k = curvature(curve_from(spec), to_doubles(params));
        val r = val::object();
        r.set("curvature", to_typed_array(k.curvature));
        r.set("signedCurvature", to_typed_array(k.signed_curvature));
        r.set("speed", to_typed_array(k.speed));
        r.set("tangent", to_typed_array(k.tangent));
        r.set("singular", to_typed_array(k.singular));
        return r;
    });
}

val curve_arc_length(const val& spec, double a, double b) {
    return guarded([&] {
        val r = val::object();
        r.set("length", arc_length(curve_from(spec), a, b));
        return r;
    });
}

val curve_arc_length_params(const val& spec, int n) {
    return guarded([&] {
        const ArcLengthParams p = arc_length_params(curve_from(spec), n);
        val r = val::object();
        r.set("params", to_typed_array(p.params));
        r.set("lengths", to_typed_array(p.lengths));
        r.set("total", p.total);
        return r;
    });
}

// A rational matrix as { rows, cols, num, den } (numerators and denominators as
// Float64Arrays; every entry of these derivations is far below 2^53, so exact in a double).
val fraction_matrix(const std::vector<Rational>& m, int rows, int cols) {
    std::vector<double> num, den;
    for (const Rational& x : m) num.push_back(static_cast<double>(x.num())), den.push_back(static_cast<double>(x.den()));
    val r = val::object();
    r.set("rows", rows);
    r.set("cols", cols);
    r.set("num", to_typed_array(num));
    r.set("den", to_typed_array(den));
    return r;
}

val cubic_derivation(const std::string& family) {
    return guarded([&] {
        const Derivation d = derive_cubic(parse_basis_kind(family));
        val r = val::object();
        r.set("family", d.family);
        r.set("size", d.size);
        r.set("constraint", fraction_matrix(d.constraint, d.size, d.size));
        r.set("inverse", fraction_matrix(d.inverse, d.size, d.size));
        r.set("basis", fraction_matrix(d.basis, 4, 4));
        r.set("rhs", d.rhs.empty() ? val::null() : fraction_matrix(d.rhs, d.size, 1));
        r.set("substitution", d.substitution.empty() ? val::null() : fraction_matrix(d.substitution, 4, 4));
        val c = val::array();
        for (std::size_t i = 0; i < d.conditions.size(); ++i) c.set(i, d.conditions[i]);
        r.set("conditions", c);
        return r;
    });
}

val curve_joint_continuity(const val& a, const val& b, double tolerance) {
    return guarded([&] {
        const JointContinuity j = joint_continuity(curve_from(a), curve_from(b), tolerance);
        const JointEvidence& e = j.evidence;
        val ev = val::object();
        ev.set("tolerance", e.tolerance);
        ev.set("a", to_typed_array(e.a_derivatives));
        ev.set("b", to_typed_array(e.b_derivatives));
        ev.set("positionGap", e.position_gap);
        ev.set("size", e.size);
        ev.set("relativeGap", e.relative_gap);
        ev.set("d1Gap", e.d1_gap);
        ev.set("d2Gap", e.d2_gap);
        ev.set("ratio", e.ratio);
        ev.set("tangentAngle", e.tangent_angle);
        // A side whose P' is zero has no curvature: null, never 0.
        ev.set("curvatureA", e.zero_tangent_a ? val::null() : val(e.curvature_a));
        ev.set("curvatureB", e.zero_tangent_b ? val::null() : val(e.curvature_b));
        ev.set("zeroTangentA", e.zero_tangent_a);
        ev.set("zeroTangentB", e.zero_tangent_b);
        ev.set("curvatureVectorGap", e.curvature_vector_gap);
        ev.set("zeroTangent", e.zero_tangent);
        val notes = val::array();
        for (std::size_t i = 0; i < e.notes.size(); ++i) notes.set(i, e.notes[i]);
        ev.set("notes", notes);
        val r = val::object();
        r.set("parametric", j.parametric);
        r.set("geometric", j.geometric);
        r.set("evidence", ev);
        val wordings = val::array();
        for (std::size_t i = 0; i < j.wordings.size(); ++i) {
            const LectureWording& w = j.wordings[i];
            val o = val::object();
            o.set("id", w.id);
            o.set("source", w.source);
            o.set("wording", w.wording);
            o.set("geometric", w.geometric);
            o.set("reason", w.reason);
            wordings.set(i, o);
        }
        r.set("wordings", wordings);
        return r;
    });
}

// What a representation guarantees for every control polygon.
// {parametric, geometric, joints, interpolated: Int32Array of slots}.
val guarantees_value(const Guarantees& g) {
    val r = val::object();
    r.set("parametric", g.parametric);
    r.set("geometric", g.geometric);
    r.set("joints", g.joints);
    r.set("interpolated", to_typed_array(g.interpolated));
    return r;
}
// maps: Float64Array, segments * 4 * slots (maps[4*slots*s + slots*r + j]: weight of slot j
// in geometry row r of segment s); isPoint: Int32Array of slots flags (1 point, 0 vector).
val chain_guarantees_value(const std::string& basis, int slots, const val& maps, const val& is_point) {
    return guarded([&] {
        const std::vector<double> flat = to_doubles(maps);
        const std::vector<int32_t> flags = to_ints(is_point);
        require(slots >= 1 && slots <= 4096, "invalid-argument", "the construction needs 1 to 4096 slots, not " + std::to_string(slots));
        const std::size_t per = 4 * static_cast<std::size_t>(slots);
        require(!flat.empty() && flat.size() % per == 0, "invalid-argument",
                "maps holds " + std::to_string(flat.size()) + " numbers: give 4 x " + std::to_string(slots) + " per segment");
        std::vector<std::vector<double>> segs;
        for (std::size_t o = 0; o < flat.size(); o += per) segs.emplace_back(flat.begin() + o, flat.begin() + o + per);
        std::vector<bool> points(flags.begin(), flags.end());
        return guarantees_value(chain_guarantees(parse_basis_kind(basis), slots, segs, points));
    });
}
val bspline_guarantees_value(const val& knots, int degree, int count) {
    return guarded([&] { return guarantees_value(bspline_guarantees(to_doubles(knots), degree, count)); });
}

val patch_sample(const std::string& kind, const val& points, int nu, int nv) {
    return guarded([&] {
        const PatchSamples s = sample_patch(parse_basis_kind(kind), to_doubles(points), nu, nv);
        val r = val::object();
        r.set("nu", s.nu);
        r.set("nv", s.nv);
        r.set("positions", to_typed_array(s.positions));
        r.set("normals", to_typed_array(s.normals));
        r.set("du", to_typed_array(s.du));
        r.set("dv", to_typed_array(s.dv));
        r.set("twists", to_typed_array(s.twists));
        return r;
    });
}

// The Vandermonde system of lecture 000 for an interpolation curve: V, M = V^-1, C = M G.
val interpolation_system(const val& spec) {
    return guarded([&] {
        const Curve c = curve_from(spec);
        const SegmentMatrices s = segment_matrices(c, 0);
        const std::vector<double> u = interpolation_nodes(c);
        val r = val::object();
        r.set("nodes", to_typed_array(u));
        r.set("vandermonde", to_typed_array(vandermonde(u)));
        r.set("inverse", to_typed_array(s.M));
        r.set("coefficients", to_typed_array(s.C));
        return r;
    });
}

// The core's limits a lesson must respect (the lesson reads them, no copy).
val curve_limits() {
    return guarded([&] {
        val r = val::object();
        r.set("maxInterpolationPoints", kMaxInterpolationPoints);
        r.set("maxDegree", kMaxDegree);
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_curves) {
    using namespace wingspline::bindings;
    emscripten::function("curveBlending", &curve_blending);
    emscripten::function("curveSegment", &curve_segment);
    emscripten::function("bezierDeCasteljau", &bezier_de_casteljau);
    emscripten::function("bezierSubdivide", &bezier_subdivide);
    emscripten::function("bezierSubdivisionMatrices", &bezier_subdivision_matrix_pair);
    emscripten::function("bezierElevate", &bezier_elevate);
    emscripten::function("basisConvert", &basis_convert);
    emscripten::function("bsplineDeBoor", &bspline_de_boor);
    emscripten::function("bsplineInsertKnot", &bspline_insert_knot);
    emscripten::function("bsplineToBezier", &bspline_to_bezier);
    emscripten::function("bsplineKnotMultiplicities", &bspline_knot_multiplicities);
    emscripten::function("nurbsPreset", &nurbs_preset);
    emscripten::function("curveSegmentAt", &curve_segment_at);
    emscripten::function("knotsClamped", &knots_clamped);
    emscripten::function("jointConstraint", &joint_constraint);
    emscripten::function("curveCurvature", &curve_curvature);
    emscripten::function("curveArcLength", &curve_arc_length);
    emscripten::function("curveArcLengthParams", &curve_arc_length_params);
    emscripten::function("curveJointContinuity", &curve_joint_continuity);
    emscripten::function("cubicDerivation", &cubic_derivation);
    emscripten::function("patchSample", &patch_sample);
    emscripten::function("chainGuarantees", &chain_guarantees_value);
    emscripten::function("bsplineGuarantees", &bspline_guarantees_value);
    emscripten::function("interpolationSystem", &interpolation_system);
    emscripten::function("curveLimits", &curve_limits);
}
