#pragma once
// Exercise kind "subdivide": one step of Loop's or Catmull-Clark's scheme asked by hand.
//  * Which mask makes a given new point (the vertex point of v, the edge point of e, the face
//    point of f; interior or boundary), and the point as exact fractions of named old
//    vertices. The stencil is the scheme's rule expanded onto the old vertices (a
//    Catmull-Clark face point inside an edge or vertex point is replaced by its corners), in
//    exact rational arithmetic, so "3/8" is right and 0.37499 is not.
//  * The counts V, E, F after one (or a few) steps.
// The rules are subdivision.h's (Loop 1987, Catmull and Clark 1978, boundaries by the cubic
// B-spline curve rules); the teaching path there (subdivision_steps) computes the same
// masks in floating point, and the tests hold the two together.
//
// Every finding names where the answer is wrong (the point, the old vertex, the row, the
// count) and the rule to re-read; none holds the right value. The values are only in
// exact_stencil() and subdivision_counts(), which give the worked answer.
#include "wingspline/mesh/subdivision.h"
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

// An exact fraction num/den, always in lowest terms with den > 0 (0 is 0/1).
struct Fraction {
    int64_t num = 0, den = 1;
    Fraction() = default;
    Fraction(int64_t n, int64_t d = 1); // throws Error("invalid-argument") when d == 0
    Fraction operator+(const Fraction& o) const;
    Fraction operator-(const Fraction& o) const;
    Fraction operator*(const Fraction& o) const;
    Fraction operator/(const Fraction& o) const;
    bool operator==(const Fraction& o) const { return num == o.num && den == o.den; }
    bool operator!=(const Fraction& o) const { return !(*this == o); }
    double value() const { return static_cast<double>(num) / static_cast<double>(den); }
    std::string text() const; // "3/8", "1", "0", "-1/8"
};

// Which new point: the vertex point of old vertex `element`, the edge point of old edge
// `element`, the face point of old face `element` (0-based; the drawing says v1, e1, F1).
enum class NewPoint : int32_t { Vertex = 0, Edge = 1, Face = 2 };
// "vertex", "edge", "face"; new_point_from_name throws Error("invalid-argument") otherwise.
const char* new_point_name(NewPoint p);
NewPoint new_point_from_name(const std::string& name);

struct SubdivideStencil {
    PointRule rule = PointRule::VertexIsolated; // the mask that applies
    std::vector<int32_t> vertices;              // old vertices, first met first
    std::vector<Fraction> weights;              // weights[i] of vertices[i]; they sum to exactly 1
    std::vector<std::string> roles;             // why vertices[i] is in it ("an end of e3")
};

// The stencil of one new point. Throws Error: what check_subdivide refuses
// ("not-a-triangle-mesh", "mesh-has-gaps", ...), "invalid-element" (no such vertex, edge or
// face), "no-exact-mask" (Loop has no face points; a vertex on no edge has no mask; Loop's
// beta for an interior vertex of valence n is a fraction only for n = 3, 4 and 6, where
// cos(2 pi / n) is one).
SubdivideStencil exact_stencil(const WingedEdgeMesh& mesh, Scheme scheme, NewPoint point, int32_t element);

// Loop's beta for valence n exactly: (1/n)(5/8 - (3/8 + cos(2 pi / n)/4)^2), for n in
// {1, 2, 3, 4, 6}; throws Error("no-exact-mask") for any other n.
Fraction loop_beta_exact(int32_t n);

// One thing wrong with an answer. code: "no-mask" (no mask chosen), "wrong-mask",
// "not-a-vertex" (a row names a vertex the mesh does not have), "repeated-point" (a vertex
// named on two rows; the later row), "not-in-stencil" (a non-zero weight on a vertex the
// mask does not use), "wrong-weight", "missing-point" (a vertex of the stencil on no row),
// "wrong-count". row: the answer's row (0-based), kNone for a missing point or a count;
// vertex: the old vertex it is about (kNone for the mask and counts); count: 0 V, 1 E, 2 F
// for wrong-count, else kNone. text: where and the rule, never the value; hint: a nudge,
// value-free too.
struct SubdivideFinding {
    std::string code;
    int32_t row = kNone;
    int32_t vertex = kNone;
    int32_t count = kNone;
    std::string text;
    std::string hint;
};

// The student's mask answer: the rule chosen (kNone: none chosen) and the rows, each an
// old vertex (any number: one that names no vertex is a finding) and its weight.
struct SubdivideMaskAnswer {
    int32_t rule = kNone; // a PointRule, or kNone
    std::vector<int32_t> vertices;
    std::vector<Fraction> weights;
};

// Checks a mask answer against exact_stencil (throws as it does; "invalid-answer" when
// the rows and weights differ in number or the rule is not a PointRule). Findings in order:
// the mask, then the rows, then the missing points (by vertex number).
std::vector<SubdivideFinding> check_subdivide_mask(const WingedEdgeMesh& mesh, Scheme scheme, NewPoint point,
                                                   int32_t element, const SubdivideMaskAnswer& answer);

// Checks V, E, F typed for the mesh after `steps` steps (kNone = left blank, a finding too).
// Throws what check_subdivide refuses (steps 1..4 here: "invalid-argument" otherwise).
std::vector<SubdivideFinding> check_subdivide_counts(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps,
                                                     int64_t vertices, int64_t edges, int64_t faces);

} // namespace wingspline::mesh
