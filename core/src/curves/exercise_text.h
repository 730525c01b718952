#pragma once
// How the exercise checkers write numbers, vectors and indices in their worked lines and
// feedback: short numbers (6 significant digits, what a student writes down) and
// unicode sub/superscripts (B₁,₃, u³), so the lines read like the slides.
#include <cstdio>
#include <string>

namespace wingspline::curves::exercise_text {

inline std::string fmt(double x) {
    if (x == 0) x = 0; // no "-0"
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

// A number as an operand inside a sum or difference: negative ones in parentheses, so a
// line reads "3 · 0 + (-6) · 2", never "+ -6 · 2".
inline std::string operand(double x) { return x < 0 ? "(" + fmt(x) + ")" : fmt(x); }

inline std::string vec(const double* v, int d) {
    std::string s = "(";
    for (int k = 0; k < d; ++k) s += (k ? ", " : "") + fmt(v[k]);
    return s + ")";
}

namespace internal {
inline std::string digits(int n, const char* const* glyphs, const char* minus) {
    std::string s = n < 0 ? minus : "";
    const std::string plain = std::to_string(n < 0 ? -static_cast<long>(n) : n);
    for (char c : plain) s += glyphs[c - '0'];
    return s;
}
} // namespace internal

inline std::string sub(int n) {
    static const char* const g[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
    return internal::digits(n, g, "₋");
}
inline std::string sup(int n) {
    static const char* const g[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    return internal::digits(n, g, "⁻");
}

} // namespace wingspline::curves::exercise_text
