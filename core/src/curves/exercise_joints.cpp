// Exercise kinds 3 and 5 (joints): the statements that decide C^k and G^k, the classes a
// student picks from, the check of an answer and of a "make the joint ..." property.
#include "wingspline/curves/exercise.h"

#include "exercise_text.h"
#include "wingspline/error.h"

#include <algorithm>
#include <cmath>

namespace wingspline::curves {

using exercise_text::fmt;
using exercise_text::vec;

namespace {

constexpr double kDegreesPerRadian = 180 / 3.14159265358979323846;

// Short forms of every statement, holding and failing (same order as joint_reasons()).
struct ReasonForms {
    const char* holds;
    const char* fails;
};
const ReasonForms kForms[] = {
    {"P(1) = Q(0)", "P(1) ≠ Q(0)"},
    {"P'(1) = Q'(0)", "P'(1) ≠ Q'(0)"},
    {"P'(1) and Q'(0) point the same way", "P'(1) and Q'(0) do not point the same way"},
    {"P''(1) = Q''(0)", "P''(1) ≠ Q''(0)"},
    {"the curvature vectors κN are equal", "the curvature vectors κN differ"},
};
// What a student reads at feedback levels "check" and "hint" (no class, no truth, no evidence).
struct ValueFreeWords {
    const char* message;
    const char* hint;
};
const ValueFreeWords kParametricWords = {
    "The parametric class (Cᵏ) is not right. Re-read the definition (lecture 000): a joint is Cᵏ when the segments agree at it in "
    "position and in every derivative up to order k: P(1) = Q(0), then P'(1) = Q'(0), then P''(1) = Q''(0).",
    "Go up one order at a time and stop at the first equation that fails: the class is the order before it (no order holds: "
    "the segments do not meet)."};
const ValueFreeWords kGeometricWords = {
    "The geometric class (Gᵏ) is not right. Re-read the definition (lectures 002, 004): Gᵏ asks what Cᵏ asks, up to a change "
    "of parameter: the segments meet, then the tangents point the same way (their lengths may differ), then the curvature "
    "vectors κN agree (one osculating circle).",
    "A joint is at least as smooth geometrically as parametrically; compare the tangents' directions, not their lengths."};
// Per statement (joint_reasons() order): how to work it out.
const char* const kStatementHints[] = {
    "Evaluate the first segment at u = 1 and the second at u = 0: for Bézier segments, the last and the first control points.",
    "Compare the two tangent vectors themselves, length included: for cubic Bézier segments 3 (P₃ − P₂) and 3 (Q₁ − Q₀).",
    "Compare the directions only: is one tangent a positive multiple of the other?",
    "Compare the second derivatives: for cubic Bézier segments 6 (P₃ − 2 P₂ + P₁) and 6 (Q₂ − 2 Q₁ + Q₀).",
    "Compare how sharply and which way each segment bends at the joint: κ = |P' × P''| / |P'|³ and the side it turns to.",
};
// The evidence line (worked_joint's explanation) that speaks about each statement.
constexpr int kEvidenceLine[] = {0, 1, 1, 2, 3};

std::string class_name(char letter, int k) { return std::string(1, letter) + exercise_text::sup(k); }

int reason_index(const std::string& id) {
    const auto& rs = joint_reasons();
    for (std::size_t i = 0; i < rs.size(); ++i)
        if (rs[i].id == id) return static_cast<int>(i);
    return -1;
}

double norm_of(const double* v, int d) {
    double s = 0;
    for (int k = 0; k < d; ++k) s += v[k] * v[k];
    return std::sqrt(s);
}

void check_class(std::optional<int> k, const char* field) {
    require(!k || (*k >= -1 && *k <= 2), "invalid-argument",
            std::string(field) + " must be a class k from -1 to 2, not " + std::to_string(k.value_or(0)));
}

// The classes of one family (C or G) and the statements each requires.
const std::vector<JointClass>& family(char letter) {
    const JointClasses& c = joint_classes();
    return letter == 'C' ? c.parametric : c.geometric;
}

// The statement that decides class k + 1 over class k (the last one class k + 1 requires).
int deciding_reason(char letter, int k) { return reason_index(family(letter)[k + 2].requires_reasons.back()); }

// Why the joint is class `actual` and not `given` (letter C or G), with the evidence line.
std::string class_reason(char letter, int given, int actual, const JointWorked& w) {
    const std::string is = "the joint is " + class_name(letter, actual);
    if (given > actual) {
        const int r = deciding_reason(letter, actual);
        return is + ", not " + class_name(letter, given) + ": " + class_name(letter, actual + 1) + " needs " + kForms[r].holds +
               ", and " + kForms[r].fails + " here (" + w.explanation[kEvidenceLine[r]] + ")";
    }
    const int r = deciding_reason(letter, actual - 1);
    return is + ", more than " + class_name(letter, given) + ": " + kForms[r].holds + " holds too (" +
           w.explanation[kEvidenceLine[r]] + ")";
}

// What a student should change to turn class `actual` into class `target`.
std::string class_move(char letter, int target, int actual, const std::vector<bool>& truths) {
    if (actual > target) {
        const int r = deciding_reason(letter, target);
        return "the joint is " + class_name(letter, actual) + ": " + kForms[r].holds + "; move a point so that " + kForms[r].fails +
               (target >= 0 ? " while the joint stays " + class_name(letter, target) : std::string());
    }
    for (const std::string& id : family(letter)[target + 1].requires_reasons) {
        const int r = reason_index(id);
        if (!truths[r])
            return "the joint is only " + class_name(letter, actual) + ": " + kForms[r].fails + "; move a point so that " +
                   kForms[r].holds;
    }
    return "the joint is " + class_name(letter, actual);
}

} // namespace

const std::vector<JointReason>& joint_reasons() {
    // Lecture 000 (C^0..C^2: P_i(1) = P_i+1(0), P'_i(1) = P'_i+1(0), P''_i(1) = P''_i+1(0)),
    // lectures 002/004 (G^1: one tangent a positive multiple of the other) and the core's G^2
    // (lecture 004's osculating circle: the same curvature vector).
    static const std::vector<JointReason> reasons = {
        {"meet", "The segments meet: P(1) = Q(0)"},
        {"equal-first", "The first derivatives are equal: P'(1) = Q'(0)"},
        {"same-direction", "P'(1) and Q'(0) point the same way (both non-zero): Q'(0) = α P'(1) with α > 0"},
        {"equal-second", "The second derivatives are equal: P''(1) = Q''(0)"},
        {"equal-curvature", "The curvature vectors κN at P(1) and Q(0) are equal (both tangents non-zero): one osculating circle"},
    };
    return reasons;
}

std::vector<bool> joint_reason_truths(const JointEvidence& e) {
    return {e.meet, e.equal_first, e.same_direction, e.equal_second, e.equal_curvature};
}

const JointClasses& joint_classes() {
    static const JointClasses classes = {
        {
            {-1, "C⁻¹: not even C⁰ (the segments do not meet)", {}},
            {0, "C⁰: the segments meet", {"meet"}},
            {1, "C¹: C⁰ and P'(1) = Q'(0)", {"meet", "equal-first"}},
            {2, "C² (or smoother): C¹ and P''(1) = Q''(0)", {"meet", "equal-first", "equal-second"}},
        },
        {
            {-1, "G⁻¹: not even G⁰ (the segments do not meet)", {}},
            {0, "G⁰: the segments meet (the same as C⁰)", {"meet"}},
            {1, "G¹: G⁰ and the same tangent direction", {"meet", "same-direction"}},
            {2, "G² (or smoother): G¹ and the same curvature vector", {"meet", "same-direction", "equal-curvature"}},
        },
    };
    return classes;
}

JointWorked worked_joint(const JointContinuity& j, int d) {
    const JointEvidence& e = j.evidence;
    const double* A = e.a_derivatives.data();
    const double* B = e.b_derivatives.data();
    JointWorked w;
    w.parametric = j.parametric;
    w.geometric = j.geometric;
    const std::vector<bool> truths = joint_reason_truths(e);
    for (std::size_t i = 0; i < truths.size(); ++i)
        if (truths[i]) w.why.push_back(joint_reasons()[i].id);

    const std::string P0 = "P(1) = " + vec(A, d) + " and Q(0) = " + vec(B, d);
    w.explanation.push_back(e.meet ? P0 + ": the segments meet"
                                   : P0 + ": they do not meet; the gap is " + fmt(e.position_gap) + ", " + fmt(e.relative_gap) +
                                         " of the size of the two curves (" + fmt(e.size) + ")");
    const double la = norm_of(A + d, d), lb = norm_of(B + d, d);
    const std::string P1 = "P'(1) = " + vec(A + d, d) + " and Q'(0) = " + vec(B + d, d);
    std::string first;
    if (e.equal_first && e.same_direction) first = P1 + ": equal (the same direction and length " + fmt(la) + ")";
    else if (e.equal_first) first = P1 + ": equal, but the zero vector, so the tangent direction is undefined (C¹ without G¹)";
    else if (e.same_direction)
        first = P1 + ": the same direction, lengths " + fmt(la) + " and " + fmt(lb) + " (α = " + fmt(e.ratio) + "), so G¹ but not C¹";
    else if (e.zero_tangent)
        first = P1 + ": " + (e.zero_tangent_a ? "P'(1)" : "Q'(0)") + " is the zero vector, so the tangent direction is undefined";
    else {
        double dot = 0;
        for (int k = 0; k < d; ++k) dot += A[d + k] * B[d + k];
        const double angle = std::acos(std::clamp(dot / (la * lb), -1.0, 1.0)) * kDegreesPerRadian;
        first = P1 + ": different directions (" + fmt(angle) + " degrees apart), so neither C¹ nor G¹";
    }
    w.explanation.push_back(first);
    const std::string P2 = "P''(1) = " + vec(A + 2 * d, d) + " and Q''(0) = " + vec(B + 2 * d, d);
    w.explanation.push_back(e.equal_second ? P2 + ": equal" : P2 + ": they differ by " + fmt(e.d2_gap));
    if (e.zero_tangent) {
        w.explanation.push_back("the curvature vector is undefined where a tangent is the zero vector");
    } else {
        const std::string kappas = "κ = " + fmt(e.curvature_a) + " at P(1) and " + fmt(e.curvature_b) + " at Q(0)";
        w.explanation.push_back(e.equal_curvature ? kappas + ": the curvature vectors κN are equal"
                                                  : kappas + ": the curvature vectors κN differ");
    }
    w.explanation.push_back("so the joint is " + class_name('C', j.parametric) + " and " + class_name('G', j.geometric));
    return w;
}

JointCheck check_joint_answer(const Curve& a, const Curve& b, const JointAnswer& answer, double tolerance) {
    check_class(answer.parametric, "parametric");
    check_class(answer.geometric, "geometric");
    std::vector<bool> ticked(joint_reasons().size(), false);
    if (answer.why) {
        for (const std::string& id : *answer.why) {
            const int r = reason_index(id);
            require(r >= 0, "invalid-argument", "why names '" + id.substr(0, 40) + "', which is not a statement id (see jointReasons())");
            ticked[r] = true;
        }
    }
    const JointContinuity j = joint_continuity(a, b, tolerance);
    JointCheck c;
    c.worked = worked_joint(j, a.dim);
    const std::vector<bool> truths = joint_reason_truths(j.evidence);
    if (answer.parametric && *answer.parametric != j.parametric)
        c.findings.push_back({"parametric", false, *answer.parametric, j.parametric,
                              class_reason('C', *answer.parametric, j.parametric, c.worked), kParametricWords.message,
                              kParametricWords.hint});
    if (answer.geometric && *answer.geometric != j.geometric)
        c.findings.push_back({"geometric", false, *answer.geometric, j.geometric,
                              class_reason('G', *answer.geometric, j.geometric, c.worked), kGeometricWords.message,
                              kGeometricWords.hint});
    if (answer.why) {
        for (std::size_t r = 0; r < truths.size(); ++r) {
            if (ticked[r] == truths[r]) continue;
            const std::string& statement = joint_reasons()[r].statement;
            c.findings.push_back({joint_reasons()[r].id, true, ticked[r] ? 1 : 0, truths[r] ? 1 : 0,
                                  "\"" + statement + "\" is " + (truths[r] ? "true" : "false") + " here: " +
                                      c.worked.explanation[kEvidenceLine[r]],
                                  "The statement \"" + statement + "\" is not judged right. Re-read it and work out both sides at "
                                  "the joint from the drawing's points (P is the first segment at its end, Q the second at its start).",
                                  kStatementHints[r]});
        }
    }
    c.correct = c.findings.empty();
    return c;
}

PropertyCheck check_joint_class(const Curve& a, const Curve& b, std::optional<int> parametric, std::optional<int> geometric,
                                double tolerance) {
    require(parametric || geometric, "invalid-argument", "a joint-class property needs parametric or geometric (a class k from -1 to 2)");
    check_class(parametric, "parametric");
    check_class(geometric, "geometric");
    const JointContinuity j = joint_continuity(a, b, tolerance);
    const std::vector<bool> truths = joint_reason_truths(j.evidence);
    PropertyCheck r;
    r.parametric = j.parametric;
    r.geometric = j.geometric;
    for (std::size_t i = 0; i < truths.size(); ++i)
        if (truths[i]) r.why.push_back(joint_reasons()[i].id);
    const bool p_ok = !parametric || *parametric == j.parametric;
    const bool g_ok = !geometric || *geometric == j.geometric;
    r.holds = p_ok && g_ok;
    std::vector<std::string> parts;
    if (!p_ok) parts.push_back(class_move('C', *parametric, j.parametric, truths));
    if (!g_ok) parts.push_back(class_move('G', *geometric, j.geometric, truths));
    if (r.holds) {
        std::string asked;
        if (parametric) asked = class_name('C', *parametric);
        if (geometric) asked += (asked.empty() ? "" : " and ") + class_name('G', *geometric);
        r.reason = "the joint is exactly " + asked + ", as asked";
    } else {
        for (std::size_t i = 0; i < parts.size(); ++i) r.reason += (i ? "; and " : "") + parts[i];
    }
    return r;
}

} // namespace wingspline::curves
