#pragma once
// Every stable error code the API can give (Error::code(), the JS WingsplineError's .code),
// listed once with what it means. The package's declarations (WingsplineErrorCode in
// types/wingspline.d.ts) and docs/errors.md are compared with this list by a test, and so
// is every code the core and the JS API throw (tests/wasm/module/error-codes.test.mjs).
#include <string_view>
#include <vector>

namespace wingspline {

struct ErrorCodeInfo {
    const char* code;    // kebab-case, stable: what a program tests
    const char* group;   // where it comes from: "mesh files", "changing a mesh", ...
    const char* meaning; // one sentence: when it is given
};

const std::vector<ErrorCodeInfo>& error_codes();
bool is_error_code(std::string_view code);

} // namespace wingspline
