// Exercise kinds 3 and 5 (joints): thousands of joints built from the definitions
// (lectures 000, 002, 004) with every statement of jointReasons() decided by the
// construction; the checker's verdict and 'why' must match it, every wrong class or tick is
// refused with its own field, and nothing changes when the drawing is scaled, turned or moved.
#include <catch2/catch.hpp>

#include "wingspline/curves/exercise.h"
#include "wingspline/error.h"

#include <glm/glm.hpp>
#include <glm/gtx/rotate_vector.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace wingspline::curves;
using glm::dvec2;

namespace {

constexpr double kJointTolerance = 1e-9; // relative, the API's default (docs/api-curves.md)
constexpr int kJoints = 3000;            // random joints in the property test
constexpr double kPi = 3.14159265358979323846;

// The statement ids in jointReasons() order.
const std::vector<std::string> kIds = {"meet", "equal-first", "same-direction", "equal-second", "equal-curvature"};

enum class Tangent { Equal, Proportional, Turned, ZeroB, BothZero };
enum class Second { Equal, AlongTangent, Across };

// A pair of cubic Bezier segments a, b and the truth of every statement, by construction.
// At a's end A1 = 3(a3 - a2), A2 = 6(a3 - 2 a2 + a1); b is built from B1, B2 at its start:
// b1 = b0 + B1/3, b2 = 2 b1 - b0 + B2/6. Every "not" has a margin of at least 1% of the
// compared size, far above the 1e-9 tolerance.
struct BuiltJoint {
    std::vector<dvec2> a, b;
    bool truths[5] = {};
};

dvec2 perp(dvec2 v) { return {-v.y, v.x}; }
double cross(dvec2 p, dvec2 q) { return p.x * q.y - p.y * q.x; }

BuiltJoint build_joint(bool meet, Tangent tangent, Second second, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0, 1), u11(-1, 1);
    auto point = [&] { return dvec2(u11(rng), u11(rng)); };
    auto sign = [&] { return u01(rng) < 0.5 ? -1.0 : 1.0; };
    BuiltJoint j;
    dvec2 A1, A2;
    for (;;) {
        j.a = {point(), point(), point(), point()};
        if (tangent == Tangent::BothZero) j.a[3] = j.a[2]; // A1 = 0 exactly
        A1 = 3.0 * (j.a[3] - j.a[2]);
        A2 = 6.0 * (j.a[3] - 2.0 * j.a[2] + j.a[1]);
        if (tangent == Tangent::BothZero) {
            if (glm::length(A2) >= 0.6) break;
            continue;
        }
        const double kappa = std::abs(cross(A1, A2)) / std::pow(glm::length(A1), 3);
        if (glm::length(A1) >= 0.6 && kappa >= 0.1 && kappa <= 10) break;
    }
    const dvec2 J = j.a[3];
    const dvec2 Na = tangent == Tangent::BothZero ? dvec2(0) : perp(A1) / glm::length(A1);
    double lambda = 1;
    if (tangent == Tangent::Proportional) lambda = u01(rng) < 0.5 ? 0.3 + 0.6 * u01(rng) : 1.2 + 1.8 * u01(rng);
    dvec2 B1 = lambda * A1;
    if (tangent == Tangent::Turned) B1 = (0.3 + u01(rng)) * glm::rotate(A1, sign() * (0.2 + (kPi - 0.4) * u01(rng)));
    if (tangent == Tangent::ZeroB || tangent == Tangent::BothZero) B1 = dvec2(0);
    dvec2 B2 = A2;
    if (second == Second::AlongTangent) B2 = lambda * lambda * A2 + sign() * (0.2 + 1.8 * u01(rng)) * A1;
    if (second == Second::Across) {
        if (tangent == Tangent::Equal || tangent == Tangent::Proportional) {
            // The curvature moves by c along N_a; c takes the sign that adds to (lambda^2 - 1) A2.N_a.
            const double drift = (lambda * lambda - 1) * glm::dot(A2, Na);
            const double c = (drift < 0 ? -1.0 : 1.0) * (0.05 + 0.45 * u01(rng));
            B2 = lambda * lambda * A2 + c * glm::dot(B1, B1) * Na;
        } else {
            B2 = A2 + (0.3 + u01(rng)) * glm::rotate(dvec2(1, 0), 2 * kPi * u01(rng));
        }
    }
    const dvec2 b0 = meet ? J : J + (0.05 + 0.45 * u01(rng)) * glm::rotate(dvec2(1, 0), 2 * kPi * u01(rng));
    const dvec2 b1 = b0 + B1 / 3.0;
    j.b = {b0, b1, 2.0 * b1 - b0 + B2 / 6.0, point()};
    const bool eq_tangent = tangent == Tangent::Equal || tangent == Tangent::BothZero;
    const bool same_direction = tangent == Tangent::Equal || tangent == Tangent::Proportional;
    const bool eq_second = second == Second::Equal;
    // Curvature vectors (lecture 004, kappa N = P''_perp / |P'|^2): equal for a joint built with
    // B2 = lambda^2 A2 + beta A1 (beta = 0 when lambda = 1 and B2 = A2); different otherwise.
    const bool eq_curvature = same_direction && (second == Second::AlongTangent || (second == Second::Equal && tangent == Tangent::Equal));
    const bool truths[5] = {meet, eq_tangent, same_direction, eq_second, eq_curvature};
    std::copy(truths, truths + 5, j.truths);
    return j;
}

BuiltJoint random_joint(std::mt19937_64& rng) {
    struct Combo {
        Tangent t;
        Second s;
    };
    static const Combo combos[] = {
        {Tangent::Equal, Second::Equal},        {Tangent::Equal, Second::AlongTangent},        {Tangent::Equal, Second::Across},
        {Tangent::Proportional, Second::Equal}, {Tangent::Proportional, Second::AlongTangent}, {Tangent::Proportional, Second::Across},
        {Tangent::Turned, Second::Equal},       {Tangent::Turned, Second::Across},             {Tangent::ZeroB, Second::Equal},
        {Tangent::ZeroB, Second::Across},       {Tangent::BothZero, Second::Equal},            {Tangent::BothZero, Second::Across},
    };
    std::uniform_int_distribution<int> pick(0, static_cast<int>(std::size(combos)) - 1);
    const Combo c = combos[pick(rng)];
    return build_joint(rng() % 2 == 0, c.t, c.s, rng);
}

Curve bezier(const std::vector<dvec2>& p) {
    Curve c;
    c.kind = CurveKind::Bezier;
    c.dim = 2;
    for (const dvec2& q : p) c.points.insert(c.points.end(), {q.x, q.y});
    return c;
}

// The classes as the lectures define them from the statements (000: C^k needs every equality
// up to k; 004: G^1 = meet + same direction; G^2 = G^1 + same curvature vector).
int parametric_of(const bool* t) { return !t[0] ? -1 : !t[1] ? 0 : !t[3] ? 1 : 2; }
int geometric_of(const bool* t) { return !t[0] ? -1 : !t[2] ? 0 : !t[4] ? 1 : 2; }

std::vector<std::string> ids_of(const bool* t) {
    std::vector<std::string> ids;
    for (int i = 0; i < 5; ++i)
        if (t[i]) ids.push_back(kIds[i]);
    return ids;
}

JointCheck check(const BuiltJoint& j, JointAnswer answer) {
    return check_joint_answer(bezier(j.a), bezier(j.b), answer, kJointTolerance);
}

} // namespace

TEST_CASE("jointReasons: the five statements in a fixed order, in the lectures' notation", "[exercise][joint]") {
    const auto& reasons = joint_reasons();
    REQUIRE(reasons.size() == kIds.size());
    for (std::size_t i = 0; i < kIds.size(); ++i) CHECK(reasons[i].id == kIds[i]);
    CHECK(reasons[0].statement.find("P(1) = Q(0)") != std::string::npos);
    CHECK(reasons[1].statement.find("P'(1) = Q'(0)") != std::string::npos);
    CHECK(reasons[3].statement.find("P''(1) = Q''(0)") != std::string::npos);
}

TEST_CASE("jointClasses: C^-1..C^2 and G^-1..G^2, each naming the statements it needs", "[exercise][joint]") {
    const JointClasses& c = joint_classes();
    REQUIRE(c.parametric.size() == 4);
    REQUIRE(c.geometric.size() == 4);
    for (int k = -1; k <= 2; ++k) {
        CHECK(c.parametric[k + 1].k == k);
        CHECK(c.geometric[k + 1].k == k);
    }
    CHECK(c.parametric[0].label.find("C⁻¹") == 0);
    CHECK(c.parametric[3].label.find("or smoother") != std::string::npos);
    CHECK(c.parametric[3].requires_reasons == std::vector<std::string>{"meet", "equal-first", "equal-second"});
    CHECK(c.geometric[3].requires_reasons == std::vector<std::string>{"meet", "same-direction", "equal-curvature"});
}

TEST_CASE("a joint built to be G1 but not C1 (lecture 004's Q1-Q3) reads as the task's example", "[exercise][joint]") {
    // a ends with P'(1) = 3 (a3 - a2) = (3, 0); b starts with Q'(0) = 3 (b1 - b0) = (6, 0).
    const Curve a = bezier({{-3, 1}, {-2, 1}, {-1, 0}, {0, 0}});
    const Curve b = bezier({{0, 0}, {2, 0}, {3, 1}, {4, 3}});
    const JointCheck c = check_joint_answer(a, b, {1, 1, std::vector<std::string>{"meet", "same-direction"}}, kJointTolerance);
    CHECK(c.worked.parametric == 0);
    CHECK(c.worked.geometric == 1);
    REQUIRE(c.findings.size() == 1);
    CHECK(c.findings[0].field == "parametric");
    CHECK(c.findings[0].given == 1);
    CHECK(c.findings[0].expected == 0);
    INFO(c.findings[0].reason);
    CHECK(c.findings[0].reason.find("C¹ needs P'(1) = Q'(0)") != std::string::npos);
    const std::string line = c.worked.explanation[1];
    INFO(line);
    CHECK(line.find("P'(1) = (3, 0) and Q'(0) = (6, 0): the same direction, lengths 3 and 6") == 0);
    CHECK(line.find("so G¹ but not C¹") != std::string::npos);
}

TEST_CASE("property: thousands of constructed joints; verdict and 'why' follow the construction", "[exercise][joint][property]") {
    std::mt19937_64 rng(19031);
    int seen[4][4] = {};
    for (int n = 0; n < kJoints; ++n) {
        const BuiltJoint j = random_joint(rng);
        const int p = parametric_of(j.truths), g = geometric_of(j.truths);
        const std::vector<std::string> why = ids_of(j.truths);
        ++seen[p + 1][g + 1];
        INFO("joint " << n << ", expected C" << p << " G" << g);
        const JointCheck right = check(j, {p, g, why});
        REQUIRE(right.worked.parametric == p);
        REQUIRE(right.worked.geometric == g);
        REQUIRE(right.worked.why == why);
        REQUIRE(right.correct);
        REQUIRE(right.findings.empty());
        // Every wrong class is refused with its own field, and only that field.
        for (int k = -1; k <= 2; ++k) {
            if (k != p) {
                const JointCheck c = check(j, {k, g, why});
                REQUIRE(!c.correct);
                REQUIRE(c.findings.size() == 1);
                CHECK((c.findings[0].field == "parametric" && c.findings[0].given == k && c.findings[0].expected == p));
            }
            if (k != g) {
                const JointCheck c = check(j, {p, k, why});
                REQUIRE(c.findings.size() == 1);
                CHECK((c.findings[0].field == "geometric" && c.findings[0].given == k && c.findings[0].expected == g));
            }
        }
        // Every wrong tick (a false statement ticked, a true one left out) names that statement.
        for (int r = 0; r < 5; ++r) {
            bool flipped[5];
            std::copy(j.truths, j.truths + 5, flipped);
            flipped[r] = !flipped[r];
            const JointCheck c = check(j, {p, g, ids_of(flipped)});
            REQUIRE(c.findings.size() == 1);
            CHECK(c.findings[0].field == kIds[r]);
            CHECK(c.findings[0].is_reason);
            CHECK(c.findings[0].given == (flipped[r] ? 1 : 0));
        }
        // Kind 5: "make the joint exactly C^p" holds, every other class does not.
        for (int k = -1; k <= 2; ++k) {
            CHECK(check_joint_class(bezier(j.a), bezier(j.b), k, std::nullopt, kJointTolerance).holds == (k == p));
            CHECK(check_joint_class(bezier(j.a), bezier(j.b), std::nullopt, k, kJointTolerance).holds == (k == g));
        }
    }
    // The construction reaches every class the lectures name (C^-1 .. C^2 with G^-1 .. G^2,
    // including C^1 without G^1: both tangents zero, lecture 004's exception).
    for (auto [p, g] : {std::pair{-1, -1}, {0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}, {1, 0}, {2, 0}}) {
        INFO("C" << p << " G" << g);
        CHECK(seen[p + 1][g + 1] > 0);
    }
}

TEST_CASE("property: the verdict and 'why' do not change when the drawing is scaled, turned or moved", "[exercise][joint][property]") {
    std::mt19937_64 rng(19032);
    std::uniform_real_distribution<double> u11(-1, 1);
    for (int n = 0; n < kJoints; ++n) {
        const BuiltJoint j = random_joint(rng);
        const double scale = std::pow(10.0, 8 * u11(rng)), angle = kPi * u11(rng);
        const dvec2 shift = 10 * scale * dvec2(u11(rng), u11(rng));
        auto moved = [&](const std::vector<dvec2>& pts) {
            std::vector<dvec2> out;
            for (const dvec2& q : pts) out.push_back(scale * glm::rotate(q, angle) + shift);
            return out;
        };
        const JointCheck c = check_joint_answer(bezier(moved(j.a)), bezier(moved(j.b)), {}, kJointTolerance);
        INFO("joint " << n << " at scale " << scale);
        REQUIRE(c.worked.parametric == parametric_of(j.truths));
        REQUIRE(c.worked.geometric == geometric_of(j.truths));
        REQUIRE(c.worked.why == ids_of(j.truths));
        CHECK(c.correct); // nothing asked, nothing wrong
    }
}

TEST_CASE("joint-class property: the reason says what the joint is and what to change", "[exercise][joint]") {
    // A C^2 joint of two cubic Bezier segments: a = (0,0),(1,1),(2,1),(3,0); b continues it
    // with b1 = 2 a3 - a2 and b2 = a1 + 4 (a3 - a2) (lecture 001's C^2 conditions).
    const Curve a = bezier({{0, 0}, {1, 1}, {2, 1}, {3, 0}});
    const Curve b = bezier({{3, 0}, {4, -1}, {5, -3}, {6, 0}});
    const PropertyCheck c = check_joint_class(a, b, 1, std::nullopt, kJointTolerance);
    CHECK(!c.holds);
    CHECK(c.parametric == 2);
    CHECK(c.reason.find("the joint is C²: P''(1) = Q''(0); move a point so that P''(1) ≠ Q''(0) while the joint stays C¹") == 0);
    const PropertyCheck g = check_joint_class(a, b, std::nullopt, 2, kJointTolerance);
    CHECK(g.holds);
    CHECK(g.reason == "the joint is exactly G², as asked");
    // b moved off the joint: the reason names the first missing statement.
    const Curve gap = bezier({{3, 1}, {4, 0}, {5, -2}, {6, 1}});
    const PropertyCheck m = check_joint_class(a, gap, 1, std::nullopt, kJointTolerance);
    CHECK(!m.holds);
    CHECK(m.reason.find("the joint is only C⁻¹: P(1) ≠ Q(0); move a point so that P(1) = Q(0)") == 0);
}

TEST_CASE("joint answers: a class outside -1..2, an unknown statement id and an empty property are refused", "[exercise][joint]") {
    const Curve a = bezier({{0, 0}, {1, 1}, {2, 1}, {3, 0}});
    const Curve b = bezier({{3, 0}, {4, -1}, {5, -3}, {6, 0}});
    auto code_of = [](auto&& f) {
        try {
            f();
        } catch (const wingspline::Error& e) {
            return e.code() + ": " + e.what();
        }
        return std::string("no error");
    };
    CHECK(code_of([&] { check_joint_answer(a, b, {3, std::nullopt, std::nullopt}, kJointTolerance); }).find("invalid-argument: parametric") == 0);
    CHECK(code_of([&] { check_joint_answer(a, b, {std::nullopt, -2, std::nullopt}, kJointTolerance); }).find("invalid-argument: geometric") == 0);
    CHECK(code_of([&] { check_joint_answer(a, b, {1, 1, std::vector<std::string>{"tangent"}}, kJointTolerance); })
              .find("invalid-argument: why names 'tangent'") == 0);
    CHECK(code_of([&] { check_joint_class(a, b, std::nullopt, std::nullopt, kJointTolerance); }).find("invalid-argument") == 0);
}
