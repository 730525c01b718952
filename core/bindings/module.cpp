// Module-level bindings, in every module: version, memory use and the error codes. Mesh
// and curve bindings live in their own translation units next to this one and follow
// boundary.h.
#include "boundary.h"

#include <malloc.h>

#include "wingspline/error_codes.h"
#include "wingspline/version.h"

namespace wingspline::bindings {
namespace {

val core_version() { return val(std::string(wingspline::version())); }

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
    emscripten::function("memoryUsage", &wingspline::bindings::memory_usage);
    emscripten::function("errorCodes", &wingspline::bindings::error_codes);
}
