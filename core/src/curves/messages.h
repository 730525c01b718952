#pragma once
// Small helpers for the students' error messages of the curves core.
#include <cstdio>
#include <string>

namespace wingspline::curves::detail {

// A number as a student would write it: up to 12 significant digits, no trailing zeros.
inline std::string num(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.12g", x);
    return buf;
}

inline std::string range(double a, double b) { return "[" + num(a) + ", " + num(b) + "]"; }

} // namespace wingspline::curves::detail
