#pragma once
// The wasm boundary's conventions, shared by every binding translation unit.
//  * Every exported function returns a plain JS object: {ok:true, ...} or
//    {ok:false, code, message}. C++ exceptions never cross into JS (in Emscripten 3.1.6
//    an escaping exception leaks wasm stack on every throw; see docs/toolchain.md).
//  * Bulk numbers leave as typed arrays copied out of the heap (slice), never as views
//    that a later allocation could detach.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "wingspline/error.h"

#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace wingspline::bindings {

using emscripten::val;

inline val ok_object() {
    val r = val::object();
    r.set("ok", true);
    return r;
}

inline val error_object(const std::string& code, const std::string& message) {
    val r = val::object();
    r.set("ok", false);
    r.set("code", code);
    r.set("message", message);
    return r;
}

// Runs body() (which returns a val holding the success fields) and maps every failure to
// an error object. body must not let a non-std exception escape.
template <class Body> val guarded(Body&& body) {
    try {
        val r = body();
        r.set("ok", true);
        return r;
    } catch (const Error& e) {
        return error_object(e.code(), e.what());
    } catch (const std::bad_alloc&) {
        return error_object("out-of-memory", "the input is too large for the memory available to this page");
    } catch (const std::exception& e) {
        return error_object("internal-error", std::string("internal error: ") + e.what());
    }
}

// A copy of a C++ array as a JS typed array (Float64Array, Int32Array, ...).
template <class T> val to_typed_array(const std::vector<T>& v) {
    return val(emscripten::typed_memory_view(v.size(), v.data())).call<val>("slice");
}
template <class T> val to_typed_array(const T* data, std::size_t n) {
    return val(emscripten::typed_memory_view(n, data)).call<val>("slice");
}

// Numbers in: the JS layer has already checked that `array` is an array or typed array.
inline std::vector<double> to_doubles(const val& array) {
    return emscripten::convertJSArrayToNumberVector<double>(array);
}
inline std::vector<int32_t> to_ints(const val& array) {
    return emscripten::convertJSArrayToNumberVector<int32_t>(array);
}

} // namespace wingspline::bindings
