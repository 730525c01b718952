#pragma once
// Errors are data at the boundary: every failure in the core is an Error with a stable,
// kebab-case code (what a program tests) and a message a student understands (what a
// person reads). The binding layer turns it into {ok:false, code, message}; the JS layer
// into an Error object with .code. Nothing in the core aborts or returns a silent NaN.
#include <stdexcept>
#include <string>

namespace wingspline {

class Error : public std::runtime_error {
public:
    Error(std::string code, const std::string& message)
        : std::runtime_error(message), code_(std::move(code)) {}
    const std::string& code() const noexcept { return code_; }

private:
    std::string code_;
};

// Throws Error(code, message) unless the condition holds. The const char* overload keeps
// a check inside a loop free: no std::string is built unless the check fails (building
// one per call made copying a 100k-face mesh into wasm 5x slower).
inline void require(bool condition, const char* code, const char* message) {
    if (!condition) throw Error(code, message);
}
inline void require(bool condition, const char* code, const std::string& message) {
    if (!condition) throw Error(code, message);
}

} // namespace wingspline
