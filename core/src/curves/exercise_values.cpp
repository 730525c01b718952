// Exercise kind 4 (compute a value by hand): the value the core computes, what it is called
// in the lectures' notation, and the worked computation line by line. The expected value
// comes from the same routines the lessons draw with (blending_functions, evaluate_curve,
// segment_matrices, insert_knot); the worked lines recompute it the way the slides do.
#include "wingspline/curves/exercise.h"

#include "exercise_text.h"
#include "messages.h"
#include "wingspline/curves/bspline_ops.h"
#include "wingspline/curves/segment.h"
#include "wingspline/error.h"

#include <cmath>
#include <limits>

namespace wingspline::curves {

using exercise_text::fmt;
using exercise_text::operand;
using exercise_text::sub;
using exercise_text::sup;
using exercise_text::vec;

namespace {

const char* const kQuantities = "blend, point, mg, boehm or patch-point";

int need_index(const std::optional<int>& value, const char* field, int count, const std::string& what) {
    require(value.has_value(), "invalid-argument", std::string(field) + " is missing: give " + what);
    require(*value >= 0 && *value < count, "invalid-argument",
            std::string(field) + " is " + std::to_string(*value) + "; " + what + " runs from 0 to " + std::to_string(count - 1));
    return *value;
}

double need_number(const std::optional<double>& value, const char* field) {
    require(value.has_value(), "invalid-argument", std::string(field) + " is missing: give the parameter (a number)");
    require(std::isfinite(*value), "non-finite-input", std::string(field) + " is " + detail::num(*value) + ", not a finite number");
    return *value;
}

// The name of control item i as the slides write it: P_i, or p_i / t_i for Hermite curves.
std::string item_name(const Curve& c, int i) {
    const int K = control_point_count(c);
    if (c.kind == CurveKind::Hermite) return (i < K ? "p" : "t") + sub(i < K ? i : i - K);
    return "P" + sub(i);
}
const double* item_value(const Curve& c, int i) {
    const int K = control_point_count(c);
    return c.kind == CurveKind::Hermite && i >= K ? &c.tangents[(i - K) * c.dim] : &c.points[i * c.dim];
}

// [t^p .. t 1] as numbers.
std::vector<double> powers(double t, int p) {
    std::vector<double> T(p + 1, 1.0);
    for (int r = p - 1; r >= 0; --r) T[r] = T[r + 1] * t;
    return T;
}

std::string powers_name(int p) {
    std::string s = "[";
    for (int r = p; r >= 1; --r) s += "t" + (r > 1 ? sup(r) : std::string()) + " ";
    return s + "1]";
}

// Where u lies and its local parameter t (the matrix form of lectures 000, 003).
std::string locate(const SegmentMatrices& s, double u, double& t) {
    if (!s.local_parameter) {
        t = u;
        return "one polynomial over the whole domain: t = u = " + fmt(u);
    }
    t = (u - s.start) / (s.end - s.start);
    return "u = " + fmt(u) + " lies in segment " + std::to_string(s.segment) + ", [" + fmt(s.start) + ", " + fmt(s.end) +
           "]; t = (u − " + fmt(s.start) + ") / (" + fmt(s.end) + " − " + fmt(s.start) + ") = " + fmt(t);
}

// The G rows that hold control item i of a segment (Hermite: points in rows 0, 1, tangents in 2, 3).
std::vector<int> rows_of_item(const Curve& c, const SegmentMatrices& s, int i) {
    const int K = control_point_count(c);
    std::vector<int> rows;
    for (int r = 0; r < static_cast<int>(s.control_indices.size()); ++r) {
        if (c.kind == CurveKind::Hermite && ((i < K) != (r < 2))) continue;
        if (s.control_indices[r] == (c.kind == CurveKind::Hermite && i >= K ? i - K : i)) rows.push_back(r);
    }
    return rows;
}

void work_bernstein(const Curve& c, int i, double u, WorkedValue& w) {
    const int n = curve_degree(c);
    double binom = 1;
    for (int k = 1; k <= i; ++k) binom = binom * (n - i + k) / k;
    const double ui = std::pow(u, i), vi = std::pow(1 - u, n - i);
    w.working.push_back("B" + sub(i) + "," + sub(n) + "(u) = C(" + std::to_string(n) + ", " + std::to_string(i) + ") uⁱ (1 − u)ⁿ⁻ⁱ = " +
                        fmt(binom) + " u" + sup(i) + " (1 − u)" + sup(n - i) + " (lecture 001, Bernstein)");
    w.working.push_back("at u = " + fmt(u) + ": " + fmt(binom) + " · " + fmt(ui) + " · " + fmt(vi) + " = " + fmt(binom * ui * vi));
}

void work_matrix_blend(const Curve& c, int i, double u, WorkedValue& w) {
    const SegmentMatrices s = segment_matrices(c, segment_at(c, u));
    double t = 0;
    w.working.push_back(locate(s, u, t));
    const int n = s.degree + 1;
    const std::vector<int> rows = rows_of_item(c, s, i);
    if (rows.empty()) {
        w.working.push_back(item_name(c, i) + " is not in this segment's G, so its weight here is 0");
        return;
    }
    const std::vector<double> T = powers(t, s.degree);
    w.working.push_back("P(t) = " + powers_name(s.degree) + " M G (lectures 000, 003): the weight of a row of G is " +
                        powers_name(s.degree) + " times that column of M; " + powers_name(s.degree) + " = " + vec(T.data(), n));
    for (int r : rows) {
        std::vector<double> col(n);
        std::string terms;
        double sum = 0;
        for (int k = 0; k < n; ++k) {
            col[k] = s.M[k * n + r];
            sum += T[k] * col[k];
            terms += (k ? " + " : "") + operand(T[k]) + " · " + operand(col[k]);
        }
        w.working.push_back("row " + std::to_string(r) + " of G is " + item_name(c, i) + "; column " + std::to_string(r) +
                            " of M = " + vec(col.data(), n) + "; " + terms + " = " + fmt(sum));
    }
}

void work_rational_blend(const Curve& c, int i, double u, WorkedValue& w) {
    Curve plain = c;
    plain.weights.clear();
    if (plain.kind == CurveKind::Nurbs) plain.kind = CurveKind::BSpline;
    const BlendingValues N = blending_functions(plain, {u});
    const int p = curve_degree(c);
    double denominator = 0;
    std::string terms;
    for (int j = 0; j < N.count; ++j) {
        const double wj = c.weights.empty() ? 1.0 : c.weights[j];
        denominator += wj * N.values[j];
        if (N.values[j] != 0) terms += (terms.empty() ? "" : " + ") + fmt(wj) + " · " + fmt(N.values[j]);
    }
    const double wi = c.weights.empty() ? 1.0 : c.weights[i];
    w.working.push_back("R" + sub(i) + "," + sub(p) + "(u) = wᵢ Nᵢ,ₚ(u) / Σⱼ wⱼ Nⱼ,ₚ(u) (lecture 001, NURBS)");
    w.working.push_back("Σⱼ wⱼ Nⱼ,ₚ(" + fmt(u) + ") = " + terms + " = " + fmt(denominator));
    w.working.push_back("R" + sub(i) + "," + sub(p) + "(" + fmt(u) + ") = " + fmt(wi) + " · " + fmt(N.values[i]) + " / " +
                        fmt(denominator) + " = " + fmt(wi * N.values[i] / denominator));
}

WorkedValue blend(const Curve& c, const ValueAsk& ask) {
    const double u = need_number(ask.u, "ask.u");
    const BlendingValues b = blending_functions(c, {u});
    const int i = need_index(ask.i, "ask.i", b.count, "the blending function's index i (0-based)");
    WorkedValue w;
    w.expected = {b.values[i]};
    const int p = curve_degree(c);
    const bool rational = is_rational(c);
    if (c.kind == CurveKind::Bezier && !rational) {
        w.label = "B" + sub(i) + "," + sub(p) + "(" + fmt(u) + ")";
        work_bernstein(c, i, u, w);
    } else if (rational) {
        w.label = "R" + sub(i) + "," + sub(p) + "(" + fmt(u) + ")";
        work_rational_blend(c, i, u, w);
    } else {
        w.label = c.kind == CurveKind::BSpline ? "N" + sub(i) + "," + sub(p) + "(" + fmt(u) + ")"
                                                : "the weight of " + item_name(c, i) + " in P(" + fmt(u) + ")";
        work_matrix_blend(c, i, u, w);
    }
    return w;
}

WorkedValue point(const Curve& c, const ValueAsk& ask) {
    const double u = need_number(ask.u, "ask.u");
    const BlendingValues b = blending_functions(c, {u});
    WorkedValue w;
    w.expected = evaluate_curve(c, {u});
    w.label = "P(" + fmt(u) + ")";
    const int d = c.dim;
    w.working.push_back("P(u) = Σᵢ bᵢ(u) · (control item i): the blending functions at u times the points" +
                        std::string(c.kind == CurveKind::Hermite ? " and tangents" : ""));
    std::string terms;
    std::vector<double> sum(d, 0.0);
    for (int i = 0; i < b.count; ++i) {
        const double bi = b.values[i];
        if (bi == 0) continue;
        const double* q = item_value(c, i);
        for (int k = 0; k < d; ++k) sum[k] += bi * q[k];
        terms += (terms.empty() ? "" : " + ") + operand(bi) + " · " + item_name(c, i) + vec(q, d);
    }
    w.working.push_back("P(" + fmt(u) + ") = " + terms + " = " + vec(sum.data(), d));
    return w;
}

WorkedValue matrix_entry(const Curve& c, const ValueAsk& ask) {
    validate(c);
    const int segment = need_index(ask.segment, "ask.segment", segment_count(c), "the segment index");
    const SegmentMatrices s = segment_matrices(c, segment);
    const int n = s.degree + 1;
    const int row = need_index(ask.row, "ask.row", n, "the row of M G");
    const int col = need_index(ask.col, "ask.col", s.columns, "the column of M G (x, y" + std::string(s.columns > 2 ? ", ..." : "") + ")");
    WorkedValue w;
    w.expected = {s.C[s.columns * row + col]};
    // In the question's language: rows, columns and segments counted from 1, the coordinate
    // named, the segment's own parameter u as lecture 003 writes P(u) = [u³ u² u 1] M G.
    const char* axes[] = {"x", "y", "z", "w"};
    const std::string axis = col < 4 ? std::string(" (") + axes[s.homogeneous && col == s.columns - 1 ? 3 : col] + ")" : "";
    std::string powers = powers_name(s.degree);
    for (char& ch : powers)
        if (ch == 't') ch = 'u';
    w.label = "(M G)" + sub(row + 1) + "," + sub(col + 1) + ", row " + std::to_string(row + 1) + ", column " + std::to_string(col + 1) + axis +
              ", of segment " + std::to_string(segment + 1);
    w.working.push_back("P(u) = " + powers + " M G on the segment, its own u from 0 to 1 (lecture 003); row r of M G multiplies u^(" +
                        std::to_string(s.degree + 1) + " − r)" + (s.homogeneous ? "; G holds (w x, w y, .., w)" : ""));
    std::string terms, column;
    double sum = 0;
    for (int j = 0; j < n; ++j) {
        const double m = s.M[row * n + j], g = s.G[s.columns * j + col];
        sum += m * g;
        terms += (j ? " + " : "") + operand(m) + " · " + operand(g);
        column += (j ? ", " : "") + s.labels[j];
    }
    w.working.push_back("the rows of G are " + column + "; column " + std::to_string(col + 1) + " of G holds their" + axis +
                        " coordinates");
    w.working.push_back("(M G)" + sub(row + 1) + "," + sub(col + 1) + " = Σⱼ M" + sub(row + 1) + ",ⱼ Gⱼ," + sub(col + 1) + " = " + terms +
                        " = " + fmt(sum));
    return w;
}

WorkedValue boehm(const Curve& c, const ValueAsk& ask) {
    const double u = need_number(ask.u, "ask.u");
    const KnotInsertion ins = insert_knot(c, u);
    const Curve before = as_explicit_bspline(c);
    const int K = control_point_count(before);
    const int index = need_index(ask.index, "ask.index", K + 1, "the index of the new control point Q (0-based)");
    const int d = c.dim, p = curve_degree(before), k = ins.span;
    const std::vector<double>& t = before.knots;
    const bool rational = !before.weights.empty();
    WorkedValue w;
    w.expected.assign(ins.curve.points.begin() + index * d, ins.curve.points.begin() + (index + 1) * d);
    w.label = "Q" + sub(index) + " after inserting the knot u = " + fmt(u);
    w.working.push_back("u = " + fmt(u) + " lies in the knot span [u" + sub(k) + ", u" + sub(k + 1) + ") = [" + fmt(t[k]) + ", " +
                        fmt(t[k + 1]) + "), k = " + std::to_string(k) + ", p = " + std::to_string(p) + ": Qᵢ = Pᵢ for i ≤ k − p, Qᵢ = Pᵢ₋₁ for i ≥ k + 1, and between "
                        "Qᵢ = (1 − aᵢ) Pᵢ₋₁ + aᵢ Pᵢ with aᵢ = (u − uᵢ) / (uᵢ₊ₚ − uᵢ) (Boehm)");
    const std::string Q = "Q" + sub(index);
    if (index <= k - p) {
        w.working.push_back(Q + " = P" + sub(index) + " = " + vec(&before.points[index * d], d) + " (i ≤ k − p: unchanged)");
        return w;
    }
    if (index >= k + 1) {
        w.working.push_back(Q + " = P" + sub(index - 1) + " = " + vec(&before.points[(index - 1) * d], d) + " (i ≥ k + 1: shifted by one)");
        return w;
    }
    const double a = (u - t[index]) / (t[index + p] - t[index]);
    w.working.push_back("a" + sub(index) + " = (u − u" + sub(index) + ") / (u" + sub(index + p) + " − u" + sub(index) + ") = (" + fmt(u) +
                        " − " + operand(t[index]) + ") / (" + fmt(t[index + p]) + " − " + operand(t[index]) + ") = " + fmt(a));
    const double* P0 = &before.points[(index - 1) * d];
    const double* P1 = &before.points[index * d];
    std::vector<double> q(d);
    if (!rational) {
        for (int x = 0; x < d; ++x) q[x] = (1 - a) * P0[x] + a * P1[x];
        w.working.push_back(Q + " = (1 − a" + sub(index) + ") P" + sub(index - 1) + " + a" + sub(index) + " P" + sub(index) + " = " +
                            fmt(1 - a) + " · " + vec(P0, d) + " + " + fmt(a) + " · " + vec(P1, d) + " = " + vec(q.data(), d));
        return w;
    }
    const double w0 = before.weights[index - 1], w1 = before.weights[index];
    const double wq = (1 - a) * w0 + a * w1;
    for (int x = 0; x < d; ++x) q[x] = ((1 - a) * w0 * P0[x] + a * w1 * P1[x]) / wq;
    w.working.push_back("in homogeneous coordinates (w x, w y, .., w) (lecture 001, NURBS): weight of " + Q + " = " + fmt(1 - a) + " · " +
                        fmt(w0) + " + " + fmt(a) + " · " + fmt(w1) + " = " + fmt(wq));
    w.working.push_back(Q + " = (" + fmt(1 - a) + " · " + fmt(w0) + " · " + vec(P0, d) + " + " + fmt(a) + " · " + fmt(w1) + " · " +
                        vec(P1, d) + ") / " + fmt(wq) + " = " + vec(q.data(), d));
    return w;
}

WorkedValue patch_point(const ValueSubject& subject, const ValueAsk& ask) {
    const double u = need_number(ask.u, "ask.u"), v = need_number(ask.v, "ask.v");
    for (auto [x, name] : {std::pair{u, "ask.u"}, std::pair{v, "ask.v"}})
        require(x >= 0 && x <= 1, "parameter-out-of-range", std::string(name) + " = " + detail::num(x) + " is outside the patch's [0, 1]");
    const std::vector<double>& P = subject.patch_points;
    require(P.size() == 48, "wrong-point-count",
            "subject.patch.points must hold the 4 x 4 geometry matrix of 3D vectors (48 numbers), not " + std::to_string(P.size()));
    for (std::size_t i = 0; i < P.size(); ++i)
        require(std::isfinite(P[i]), "non-finite-input", "subject.patch.points[" + std::to_string(i) + "] is not a finite number");
    const Mat4 M = basis_matrix(subject.patch_kind);
    const std::vector<double> U = powers(u, 3), V = powers(v, 3);
    double a[4] = {0, 0, 0, 0}, b[4] = {0, 0, 0, 0};
    for (int j = 0; j < 4; ++j)
        for (int r = 0; r < 4; ++r) a[j] += U[r] * M[4 * r + j], b[j] += V[r] * M[4 * r + j];
    WorkedValue w;
    w.expected.assign(3, 0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 3; ++k) w.expected[k] += a[i] * b[j] * P[3 * (4 * i + j) + k];
    w.label = "p(" + fmt(u) + ", " + fmt(v) + ")";
    w.working.push_back("p(u, v) = [u³ u² u 1] M P Mᵀ [v³ v² v 1]ᵀ (lecture 002, " + std::string(basis_kind_name(subject.patch_kind)) + " patch)");
    w.working.push_back("[u³ u² u 1] M = " + vec(a, 4) + " at u = " + fmt(u));
    w.working.push_back("Mᵀ [v³ v² v 1]ᵀ = " + vec(b, 4) + " at v = " + fmt(v));
    w.working.push_back("p = Σᵢⱼ aᵢ bⱼ Pᵢⱼ = " + vec(w.expected.data(), 3));
    return w;
}

// What was asked, in the question's words (indices of rows, columns and segments from
// "first", the parameter u), the formula to re-read and a nudge: no value, no distance.
struct AskedWords {
    std::string what, rule, hint;
};

std::string first_words(int index0) {
    static const char* const kWords[] = {"first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth"};
    return index0 >= 0 && index0 < 10 ? kWords[index0] : "number " + std::to_string(index0 + 1);
}

AskedWords asked_words(const ValueSubject& subject, const ValueAsk& ask) {
    const std::string& q = ask.quantity;
    const std::string u = ask.u ? fmt(*ask.u) : "u";
    if (q == "patch-point")
        return {"p(u, v) at u = " + u + ", v = " + (ask.v ? fmt(*ask.v) : "v"),
                "p(u, v) = [u³ u² u 1] M P Mᵀ [v³ v² v 1]ᵀ (lecture 002): the row [u³ u² u 1] M weighs the rows of P, the column Mᵀ [v³ v² v 1]ᵀ its columns",
                "First work out the four numbers [u³ u² u 1] M, then the four Mᵀ [v³ v² v 1]ᵀ; each point Pᵢⱼ weighs their product."};
    const Curve& c = subject.curve;
    if (q == "mg") {
        const int row = ask.row.value_or(0), col = ask.col.value_or(0), segment = ask.segment.value_or(0);
        const std::string axis = col == 0 ? " (x)" : col == 1 ? " (y)" : col == 2 ? " (z)" : "";
        return {"the " + first_words(row) + " row, " + first_words(col) + " column" + axis + " of M G for the " + first_words(segment) + " segment",
                "P(u) = [u³ u² u 1] M G (lectures 000, 003); the entry in row r, column c of M G is row r of M times column c of G, "
                "term by term, and G's rows are the segment's points (and tangents) in order, column c holding their coordinate c",
                "Write out that row of M and that column of G side by side, multiply each pair and add; the first row multiplies u³."};
    }
    if (q == "boehm")
        return {"Q" + sub(ask.index.value_or(0)) + " after inserting the knot u = " + u,
                "find the knot span [uₖ, uₖ₊₁) that holds u; then Qᵢ = Pᵢ for i ≤ k − p, Qᵢ = Pᵢ₋₁ for i ≥ k + 1, and between them "
                "Qᵢ = (1 − aᵢ) Pᵢ₋₁ + aᵢ Pᵢ with aᵢ = (u − uᵢ) / (uᵢ₊ₚ − uᵢ) (Boehm)",
                "Find k first (the span of u in the knot vector), then decide whether this Q is kept, shifted or blended."};
    if (q == "point")
        return {"P(u) at u = " + u,
                std::string("P(u) = Σᵢ bᵢ(u) · (control item i): each blending function at u times its control point") +
                    (c.kind == CurveKind::Hermite ? " or tangent" : ""),
                "Work out every blending function at u first (for a Bézier or B-spline curve they add up to 1), then weigh the points and add."};
    // blend
    const int i = ask.i.value_or(0);
    const int p = curve_degree(c);
    if (is_rational(c))
        return {"R" + sub(i) + "," + sub(p) + "(u) at u = " + u, "Rᵢ,ₚ(u) = wᵢ Bᵢ,ₚ(u) / Σⱼ wⱼ Bⱼ,ₚ(u): the weighted basis function over the sum of them all (lecture 001, NURBS)",
                "Work out every basis function at u, weigh each by its wᵢ, then divide this one by their sum."};
    if (c.kind == CurveKind::Bezier)
        return {"B" + sub(i) + "," + sub(p) + "(u) at u = " + u, "Bᵢ,ₙ(u) = C(n, i) uⁱ (1 − u)ⁿ⁻ⁱ, the Bernstein polynomial (lecture 001)",
                "Check the binomial coefficient C(n, i) and each power of u and of 1 − u separately."};
    if (c.kind == CurveKind::BSpline)
        return {"N" + sub(i) + "," + sub(p) + "(u) at u = " + u,
                "Nᵢ,ₚ(u) by the Cox–de Boor recursion over the knots: Nᵢ,₀ is 1 on [uᵢ, uᵢ₊₁), and each degree blends two of the degree below",
                "Build the triangle of Nᵢ,ⱼ from degree 0 up, only over the knot spans around u."};
    return {"the weight of " + item_name(c, i) + " in P(u) at u = " + u,
            "the weight of a control item is its entry of the row [u³ u² u 1] M (the basis matrix form, lecture 003), with u the segment's own parameter",
            "Find the segment u lies in and its local parameter, then multiply the row of powers by the column of M that belongs to this item."};
}

std::string count_words(std::size_t n) {
    static const char* const kWords[] = {"no numbers", "one number", "two numbers", "three numbers", "four numbers", "five numbers"};
    return n < 6 ? kWords[n] : std::to_string(n) + " numbers";
}

// A wrong count of numbers, said plainly: "The answer is a single number; you typed two numbers."
std::string count_sentence(const ValueSubject& subject, const ValueAsk& ask, std::size_t wanted, std::size_t typed) {
    const std::string you = "you typed " + count_words(typed) + ".";
    if (wanted == 1) return "The answer is a single number; " + you;
    const std::string name = ask.quantity == "patch-point" ? "p(u, v)" : ask.quantity == "boehm" ? "Q" + sub(ask.index.value_or(0)) : "P(u)";
    (void)subject;
    const std::string coords = wanted == 2 ? "its x and y" : wanted == 3 ? "its x, y and z" : "its " + std::to_string(wanted) + " coordinates";
    return name + " is a point: type " + coords + " (" + you.substr(0, you.size() - 1) + ").";
}

} // namespace

WorkedValue worked_value(const ValueSubject& subject, const ValueAsk& ask) {
    const std::string& q = ask.quantity;
    const bool known = q == "blend" || q == "point" || q == "mg" || q == "boehm" || q == "patch-point";
    require(known, "unknown-quantity", "ask.quantity is '" + q.substr(0, 40) + "'; expected " + kQuantities);
    const bool wants_patch = q == "patch-point";
    require(subject.is_patch == wants_patch, "invalid-argument",
            wants_patch ? std::string("subject must be {patch: {kind, points}} for a patch point")
                        : "subject must be {curve} for the quantity '" + q + "'");
    if (wants_patch) return patch_point(subject, ask);
    const Curve& c = subject.curve;
    validate(c);
    if (q == "blend") return blend(c, ask);
    if (q == "point") return point(c, ask);
    if (q == "mg") return matrix_entry(c, ask);
    return boehm(c, ask);
}

ValueCheck check_value_answer(const ValueSubject& subject, const ValueAsk& ask, const std::vector<double>& given, double tolerance) {
    require(std::isfinite(tolerance) && tolerance >= 0, "invalid-argument",
            "tolerance must be a finite number >= 0 (absolute, in the units of the value), not " + detail::num(tolerance));
    ValueCheck c;
    c.worked = worked_value(subject, ask);
    const std::vector<double>& e = c.worked.expected;
    if (given.size() != e.size()) {
        c.code = "wrong-count";
        c.message = count_sentence(subject, ask, e.size(), given.size());
        c.hint = asked_words(subject, ask).hint;
        c.reason = c.message;
        c.distance = std::numeric_limits<double>::infinity();
        return c;
    }
    double s = 0;
    for (std::size_t k = 0; k < e.size(); ++k) {
        require(std::isfinite(given[k]), "non-finite-input", "given[" + std::to_string(k) + "] is not a finite number");
        s += (given[k] - e[k]) * (given[k] - e[k]);
    }
    c.distance = std::sqrt(s);
    c.correct = c.distance <= tolerance;
    if (!c.correct) {
        const std::string g = e.size() == 1 ? fmt(given[0]) : vec(given.data(), static_cast<int>(given.size()));
        const std::string x = e.size() == 1 ? fmt(e[0]) : vec(e.data(), static_cast<int>(e.size()));
        c.reason = g + " is " + fmt(c.distance) + " from " + c.worked.label + " = " + x + "; the tolerance is " + fmt(tolerance);
        const AskedWords a = asked_words(subject, ask);
        c.code = "not-within";
        c.message = "Your answer is not within the tolerance of " + a.what + ". Re-read: " + a.rule + ".";
        c.hint = a.hint;
    }
    return c;
}

} // namespace wingspline::curves
