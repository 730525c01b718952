#pragma once
// Exercises on curves that check themselves (kinds 3, 4 and 5):
//  3. classify a joint (C^k and G^k, lectures 000, 001, 002, 004) and say why, from a fixed
//     list of statements, exactly those that decide the core's verdict (joint_continuity);
//  4. compute a value by hand (a blending function, a point, an entry of M G, a point made by
//     Boehm's rule, a patch point) within a stated absolute tolerance, with the worked lines;
//  5. move points until a property holds (a joint of exactly one class; a curve through a point).
// Notation of the statements: P is the first segment (a) at its end, Q the second (b) at its
// start; P(1) and Q(0) as in lecture 000 (the domain end and start for any curve family).
#include "wingspline/curves/analysis.h"
#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/curve.h"

#include <optional>
#include <string>
#include <vector>

namespace wingspline::curves {

// ---- kind 3: joints
struct JointReason {
    std::string id;        // 'meet' | 'equal-first' | 'same-direction' | 'equal-second' | 'equal-curvature'
    std::string statement; // in the lectures' notation
};
const std::vector<JointReason>& joint_reasons();
// The truth of every statement of joint_reasons() for a joint, in that order.
std::vector<bool> joint_reason_truths(const JointEvidence& evidence);

struct JointClass {
    int k = 0;
    std::string label;
    std::vector<std::string> requires_reasons; // the statements that must all hold (ids)
};
struct JointClasses {
    std::vector<JointClass> parametric; // C^-1 .. C^2
    std::vector<JointClass> geometric;  // G^-1 .. G^2
};
// The verdict stops at 2 (the core checks derivatives up to order 2): the class with k = 2
// reads "C² (or smoother)" and a C^3 joint is classified C^2.
const JointClasses& joint_classes();

struct JointAnswer {
    std::optional<int> parametric, geometric;    // not given: not asked
    std::optional<std::vector<std::string>> why; // the ids ticked as true; not given: not asked
};
struct JointFinding {
    std::string field;  // 'parametric' | 'geometric' | a reason id
    bool is_reason = false;
    int given = 0, expected = 0; // classes: k; reasons: 1 ticked/true, 0 not
    std::string reason;
    // Value-free (feedback levels "check" and "hint"): which choice or statement is wrong and
    // the definition to re-read; never the class nor the truth, nor the measured evidence.
    std::string message;
    std::string hint;
};
struct JointWorked {
    int parametric = -1, geometric = -1;
    std::vector<std::string> why;          // the ids that hold
    std::vector<std::string> explanation;  // sentences with the measured evidence
};
struct JointCheck {
    bool correct = false;
    std::vector<JointFinding> findings;
    JointWorked worked;
};
// Refuses a class outside -1..2 and an unknown reason id ('invalid-argument', naming it).
JointCheck check_joint_answer(const Curve& a, const Curve& b, const JointAnswer& answer, double tolerance);
JointWorked worked_joint(const JointContinuity& joint, int dim);

// ---- kind 4: values
struct ValueSubject {
    bool is_patch = false;
    Curve curve;                     // when !is_patch
    BasisKind patch_kind = BasisKind::Bezier; // hermite or bezier (patch.h)
    std::vector<double> patch_points; // 48 numbers, patch.h's layout
};
struct ValueAsk {
    std::string quantity; // 'blend' | 'point' | 'mg' | 'boehm' | 'patch-point'
    // The fields the quantity needs (all indices 0-based); unset: absent.
    std::optional<int> i, segment, row, col, index;
    std::optional<double> u, v;
};
struct WorkedValue {
    std::vector<double> expected;
    std::string label;                // what is asked, e.g. "B₁,₃(0.5)"
    std::vector<std::string> working; // the computation line by line
};
// Throws 'unknown-quantity', or 'invalid-argument' naming the missing or invalid field.
WorkedValue worked_value(const ValueSubject& subject, const ValueAsk& ask);
struct ValueCheck {
    bool correct = false;
    double distance = 0; // Euclidean, in the quantity's units
    WorkedValue worked;
    std::string reason;  // why it is wrong (empty when right), with the value: the worked answer's words
    // "" when right; "not-within" (a value outside the tolerance) or "wrong-count" (as many
    // numbers as the value has are needed: given.size() differs).
    std::string code;
    // Value-free (feedback levels "check" and "hint"): what was asked in the question's words
    // (indices from first, the parameter u) and the formula to re-read; never the value, nor
    // the distance it is off by.
    std::string message;
    std::string hint;
};
// tolerance: absolute, in the quantity's units (>= 0); given: as many numbers as the value (a
// different count is a wrong answer, code "wrong-count", said in a plain sentence).
ValueCheck check_value_answer(const ValueSubject& subject, const ValueAsk& ask, const std::vector<double>& given,
                              double tolerance);

// ---- kind 5: properties
struct ClosestPoint {
    double u = 0;
    std::vector<double> point;
    double distance = 0;
};
// The point of the curve closest to x (dim numbers): dense samples over every segment, then
// Newton's method on (P(u) - x) . P'(u) = 0 from the best ones, the domain ends included.
ClosestPoint closest_point(const Curve& curve, const std::vector<double>& x);
// The size a passes-through tolerance is relative to: the largest distance between two
// control points (for Hermite curves: between two of its points), which is the bounding box
// diagonal when the extremes are opposite corners, and does not change when the drawing is
// turned (the bounding box does).
double control_polygon_diameter(const Curve& curve);

struct PropertyCheck {
    bool holds = false;
    std::string reason;
    // joint-class: the joint's verdict and statements
    int parametric = -1, geometric = -1;
    std::vector<std::string> why;
    // passes-through
    double distance = 0, relative_distance = 0, size = 0, u = 0;
    std::vector<double> closest;
};
PropertyCheck check_joint_class(const Curve& a, const Curve& b, std::optional<int> parametric,
                                std::optional<int> geometric, double tolerance);
// tolerance: relative to control_polygon_diameter, in (0, 1).
PropertyCheck check_passes_through(const Curve& curve, const std::vector<double>& point, double tolerance);

} // namespace wingspline::curves
