// Exercise bindings of the kind "subdivide" (exercise_subdivide.h): the exact stencil of a
// new point, the checks of a student's mask and counts, and the counts for the worked
// answer. The mesh crosses as CSR (faceOffsets: F + 1 entries, faceVertices) with its vertex
// count, built by exercise_mesh (the core's own numbering, as the lesson's drawing labels
// it). Fractions cross as two Float64Arrays of whole numbers, numerators[i] / denominators[i]
// (|x| <= 2^53); a rule as its name (point_rule_name; "" = none chosen).
#include "boundary.h"

#include "wingspline/mesh/exercise_check.h"
#include "wingspline/mesh/exercise_subdivide.h"

#include <cmath>

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

constexpr double kLargestWhole = 9007199254740992.0; // 2^53: every whole double up to it is exact

WingedEdgeMesh subdivide_exercise_mesh(const val& face_offsets, const val& face_vertices, int32_t vertex_count) {
    return exercise_mesh(to_ints(face_offsets), to_ints(face_vertices), vertex_count);
}

int64_t whole(double x, const char* what, std::size_t i) {
    require(std::isfinite(x) && std::floor(x) == x && std::abs(x) <= kLargestWhole, "invalid-answer",
            std::string(what) + "[" + std::to_string(i) + "] must be a whole number of at most 2^53");
    return static_cast<int64_t>(x);
}

int32_t rule_from_name(const std::string& name) {
    if (name.empty()) return kNone;
    for (int32_t r = 0; r < kPointRuleCount; ++r)
        if (name == point_rule_name(r)) return r;
    throw Error("invalid-answer", "'" + name.substr(0, 40) + "' is not a mask (face-point, edge-interior, edge-boundary, vertex-interior, vertex-boundary)");
}

val findings_value(const std::vector<SubdivideFinding>& list) {
    val out = val::array();
    for (std::size_t i = 0; i < list.size(); ++i) {
        const SubdivideFinding& f = list[i];
        val o = val::object();
        o.set("code", f.code);
        o.set("row", f.row);
        o.set("vertex", f.vertex);
        o.set("count", f.count);
        o.set("text", f.text);
        o.set("hint", f.hint);
        out.set(i, o);
    }
    return out;
}

val stencil(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const std::string& scheme,
            const std::string& point, int32_t element) {
    return guarded([&] {
        const WingedEdgeMesh mesh = subdivide_exercise_mesh(face_offsets, face_vertices, vertex_count);
        const SubdivideStencil s = exact_stencil(mesh, scheme_from_name(scheme), new_point_from_name(point), element);
        std::vector<double> nums, dens;
        for (const Fraction& w : s.weights) nums.push_back(static_cast<double>(w.num)), dens.push_back(static_cast<double>(w.den));
        val roles = val::array();
        for (std::size_t i = 0; i < s.roles.size(); ++i) roles.set(i, s.roles[i]);
        val r = val::object();
        r.set("rule", std::string(point_rule_name(static_cast<int32_t>(s.rule))));
        r.set("vertices", to_typed_array(s.vertices));
        r.set("numerators", to_typed_array(nums));
        r.set("denominators", to_typed_array(dens));
        r.set("roles", roles);
        return r;
    });
}

val check_mask(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const std::string& scheme,
               const std::string& point, int32_t element, const std::string& rule, const val& vertices, const val& numerators,
               const val& denominators) {
    return guarded([&] {
        const WingedEdgeMesh mesh = subdivide_exercise_mesh(face_offsets, face_vertices, vertex_count);
        SubdivideMaskAnswer answer;
        answer.rule = rule_from_name(rule);
        answer.vertices = to_ints(vertices);
        const std::vector<double> nums = to_doubles(numerators), dens = to_doubles(denominators);
        require(nums.size() == dens.size(), "invalid-answer", "numerators and denominators must have one entry per row");
        for (std::size_t i = 0; i < nums.size(); ++i) {
            const int64_t d = whole(dens[i], "denominators", i);
            require(d != 0, "invalid-answer", "denominators[" + std::to_string(i) + "] must not be 0");
            answer.weights.emplace_back(whole(nums[i], "numerators", i), d);
        }
        val r = val::object();
        r.set("findings", findings_value(check_subdivide_mask(mesh, scheme_from_name(scheme), new_point_from_name(point), element, answer)));
        return r;
    });
}

val check_counts(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const std::string& scheme, int32_t steps,
                 double vertices, double edges, double faces) {
    return guarded([&] {
        const WingedEdgeMesh mesh = subdivide_exercise_mesh(face_offsets, face_vertices, vertex_count);
        const int64_t given[3] = {whole(vertices, "counts", 0), whole(edges, "counts", 1), whole(faces, "counts", 2)};
        val r = val::object();
        r.set("findings", findings_value(check_subdivide_counts(mesh, scheme_from_name(scheme), steps, given[0], given[1], given[2])));
        return r;
    });
}

val counts(const val& face_offsets, const val& face_vertices, int32_t vertex_count, const std::string& scheme, int32_t steps) {
    return guarded([&] {
        const WingedEdgeMesh mesh = subdivide_exercise_mesh(face_offsets, face_vertices, vertex_count);
        const Scheme s = scheme_from_name(scheme);
        require_ok(check_subdivide(mesh, s, steps));
        const SubdivisionCounts c = subdivision_counts(mesh, s, steps);
        val r = val::object();
        r.set("vertices", static_cast<double>(c.vertices));
        r.set("edges", static_cast<double>(c.edges));
        r.set("faces", static_cast<double>(c.faces));
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_exercise_subdivide) {
    emscripten::function("exerciseSubdivideStencil", &wingspline::bindings::stencil);
    emscripten::function("exerciseCheckSubdivideMask", &wingspline::bindings::check_mask);
    emscripten::function("exerciseCheckSubdivideCounts", &wingspline::bindings::check_counts);
    emscripten::function("exerciseSubdivisionCounts", &wingspline::bindings::counts);
}
