// Bindings of the lessons' measurements: the comparison measurements and
// the convex hull (core/include/wingspline/curves/comparison.h), the curve explorer's
// overlays (overlays.h). Same conventions as curves.cpp: plain values
// in (checked and normalised by web/js/core/curves-api.js), {ok, ...} or {ok:false, code,
// message} out through guarded().
#include "boundary.h"
#include "curve_spec.h"

#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/comparison.h"
#include "wingspline/curves/overlays.h"

#include <string>

namespace wingspline::bindings {
namespace {

using namespace wingspline::curves;

val convex_hull_value(const val& points) {
    return guarded([&] {
        const ConvexHull h = convex_hull(to_doubles(points));
        val r = val::object();
        r.set("indices", to_typed_array(h.indices));
        r.set("tolerance", h.tolerance);
        return r;
    });
}

val map_points_value(const val& points, int dim, bool perspective, double angle, double scale, double shear, double tx,
                     double ty, double px, double py, const std::string& what) {
    return guarded([&] {
        const MappedPoints m = map_points(to_doubles(points), dim, plane_map(perspective, angle, scale, shear, tx, ty, px, py), what);
        val r = val::object();
        r.set("points", to_typed_array(m.points));
        r.set("w", to_typed_array(m.w));
        return r;
    });
}

val max_distance_value(const val& a, const val& b, int dim) {
    return guarded([&] {
        const MaxDistance d = max_distance(to_doubles(a), to_doubles(b), dim);
        val r = val::object();
        r.set("distance", d.distance);
        r.set("index", d.index);
        return r;
    });
}

val blending_weight_check_value(const val& specs, int samples) {
    return guarded([&] {
        const BlendingWeightCheck b = blending_weight_check(curves_from(specs), samples);
        val r = val::object();
        r.set("tangentWeight", b.tangent_weight);
        r.set("weightsPoints", b.weights_points);
        r.set("minWeight", b.min_weight);
        r.set("minWeightAt", b.min_weight_at);
        r.set("sumError", b.sum_error);
        r.set("convexHull", b.convex_hull);
        r.set("tolerance", b.tolerance);
        return r;
    });
}

val point_curve_distances_value(const val& points, int dim, const val& specs, int samples) {
    return guarded([&] {
        const PointCurveDistances d = point_curve_distances(to_doubles(points), dim, curves_from(specs), samples);
        val r = val::object();
        r.set("distances", to_typed_array(d.distances));
        r.set("interpolated", to_typed_array(d.interpolated));
        r.set("farthest", d.farthest);
        r.set("nearestMissed", d.nearest_missed);
        r.set("tolerance", d.tolerance);
        return r;
    });
}

val split_check_value(const val& specs) {
    return guarded([&] {
        const SplitCheck s = split_check(curves_from(specs));
        val r = val::object();
        r.set("error", s.error);
        r.set("segments", s.segments);
        return r;
    });
}

val knot_refinement_check_value(const val& spec, int samples) {
    return guarded([&] {
        const KnotRefinementCheck k = knot_refinement_check(curve_from(spec), samples);
        val r = val::object();
        r.set("error", k.error);
        r.set("inserted", k.inserted);
        r.set("pointsBefore", k.points_before);
        r.set("pointsAfter", k.points_after);
        return r;
    });
}

val patch_corner_check_value(const std::string& kind, const val& net) {
    return guarded([&] {
        const PatchCornerCheck c = patch_corner_check(parse_basis_kind(kind), to_doubles(net));
        val r = val::object();
        val corners = val::array();
        for (int k = 0; k < 4; ++k) {
            val one = val::object();
            one.set("entry", c.entry[k]);
            one.set("distance", c.distance[k]);
            one.set("interpolated", c.interpolated[k]);
            corners.set(k, one);
        }
        r.set("corners", corners);
        r.set("tolerance", c.tolerance);
        return r;
    });
}

val patch_join_check_value(const std::string& kind, const val& a, const val& b, int samples) {
    return guarded([&] {
        const PatchJoinCheck j = patch_join_check(parse_basis_kind(kind), to_doubles(a), to_doubles(b), samples);
        val r = val::object();
        r.set("positionGap", j.position_gap);
        r.set("duGap", j.du_gap);
        r.set("c0", j.c0);
        r.set("c1", j.c1);
        r.set("tolerance", j.tolerance);
        return r;
    });
}

val catmull_rom_tangents_value(const val& points, int dim) {
    return guarded([&] {
        val r = val::object();
        r.set("tangents", to_typed_array(catmull_rom_tangents(to_doubles(points), dim)));
        return r;
    });
}

val convert_patch_basis_value(const std::string& from, const std::string& to, const val& net) {
    return guarded([&] {
        val r = val::object();
        r.set("points", to_typed_array(convert_patch_basis(to_doubles(net), parse_basis_kind(from), parse_basis_kind(to))));
        return r;
    });
}

val curvature_comb_value(const val& spec, const val& params) {
    return guarded([&] {
        const CurvatureComb c = curvature_comb(curve_from(spec), to_doubles(params));
        val r = val::object();
        r.set("teeth", to_typed_array(c.teeth));
        r.set("maxCurvature", c.max_curvature);
        r.set("singular", c.singular);
        return r;
    });
}

val homogeneous_lift_value(const val& points, int dim, const val& weights) {
    return guarded([&] {
        val r = val::object();
        r.set("points", to_typed_array(homogeneous_lift(to_doubles(points), dim, to_doubles(weights))));
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_comparison) {
    using namespace wingspline::bindings;
    emscripten::function("convexHull", &convex_hull_value);
    emscripten::function("mapPoints", &map_points_value);
    emscripten::function("maxDistance", &max_distance_value);
    emscripten::function("blendingWeightCheck", &blending_weight_check_value);
    emscripten::function("pointCurveDistances", &point_curve_distances_value);
    emscripten::function("splitCheck", &split_check_value);
    emscripten::function("knotRefinementCheck", &knot_refinement_check_value);
    emscripten::function("catmullRomTangents", &catmull_rom_tangents_value);
    emscripten::function("convertPatchBasis", &convert_patch_basis_value);
    emscripten::function("curvatureComb", &curvature_comb_value);
    emscripten::function("homogeneousLift", &homogeneous_lift_value);
    emscripten::function("patchCornerCheck", &patch_corner_check_value);
    emscripten::function("patchJoinCheck", &patch_join_check_value);
}
