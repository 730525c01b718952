// The cubic basis matrices of lectures 001-003 and the Hermite matrix computed from its
// constraints. In the curves group: only the curve lessons read them, so the mesh lessons'
// modules do not carry them (docs/architecture.md, "Module size").
#include "boundary.h"
#include "rational.h"

#include "wingspline/curves/basis_matrix.h"

namespace wingspline::bindings {
namespace {

// basis_matrix(kind) -> {ok, matrix: Float64Array(16) row-major, rational: the slide's
// fraction and integers}
// form: 'descending' (000, 003), 'ascending' (002) or 'transposed' (001).
val basis_matrix(const std::string& kind, const std::string& form) {
    return guarded([&] {
        const auto m = curves::basis_matrix(curves::parse_basis_kind(kind), curves::parse_matrix_form(form));
        val r = val::object();
        r.set("matrix", to_typed_array(m.data(), m.size()));
        r.set("rational", rational_value(std::vector<double>(m.begin(), m.end())));
        return r;
    });
}

// hermite_from_constraints() -> the inverse of the lecture's constraint matrix, computed.
val hermite_from_constraints() {
    return guarded([] {
        const auto m = curves::inverse(curves::hermite_constraint_matrix());
        const auto c = curves::hermite_constraint_matrix();
        val r = val::object();
        r.set("constraints", to_typed_array(c.data(), c.size()));
        r.set("matrix", to_typed_array(m.data(), m.size()));
        return r;
    });
}
} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_basis) {
    emscripten::function("basisMatrix", &wingspline::bindings::basis_matrix);
    emscripten::function("hermiteFromConstraints", &wingspline::bindings::hermite_from_constraints);
}
