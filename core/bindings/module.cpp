// Module-level bindings: version and the cubic basis matrices. Mesh and curve bindings live
// in their own translation units next to this one and follow boundary.h.
#include "boundary.h"
#include "rational.h"

#include <malloc.h>

#include "wingspline/curves/basis_matrix.h"
#include "wingspline/error_codes.h"
#include "wingspline/version.h"

namespace wingspline::bindings {
namespace {

val core_version() { return val(std::string(wingspline::version())); }

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

// {linearBytes: size of the wasm memory, heapInUse: bytes malloc has handed out}
val memory_usage() {
    return guarded([] {
        val r = val::object();
        r.set("linearBytes", static_cast<double>(__builtin_wasm_memory_size(0)) * 65536.0);
        r.set("heapInUse", static_cast<double>(mallinfo().uordblks));
        return r;
    });
}

// [{code, group, meaning}]: every error code the API can give (error_codes.h).
val error_codes() {
    return guarded([] {
        val list = val::array();
        const auto& all = wingspline::error_codes();
        for (std::size_t k = 0; k < all.size(); ++k) {
            val one = val::object();
            one.set("code", std::string(all[k].code));
            one.set("group", std::string(all[k].group));
            one.set("meaning", std::string(all[k].meaning));
            list.set(k, one);
        }
        val r = val::object();
        r.set("codes", list);
        return r;
    });
}
} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_module) {
    emscripten::function("version", &wingspline::bindings::core_version);
    emscripten::function("basisMatrix", &wingspline::bindings::basis_matrix);
    emscripten::function("hermiteFromConstraints", &wingspline::bindings::hermite_from_constraints);
    emscripten::function("memoryUsage", &wingspline::bindings::memory_usage);
    emscripten::function("errorCodes", &wingspline::bindings::error_codes);
}
