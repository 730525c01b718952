// Exercise kind "subdivide": exact stencils of one subdivision step and the checks of a
// student's mask and counts; header: exercise_subdivide.h.
//
// The stencils are built here again, in fractions, from the ring and face walks of
// winged_edge.h (the rules as subdivision.cpp's header lists them), rather than read from
// subdivision_steps' doubles: a weight read back from a double would be a guess at the
// fraction, and the check must be exact.
#include "wingspline/mesh/exercise_subdivide.h"

#include "wingspline/error.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>

namespace wingspline::mesh {

// ------------------------------------------------------------------ fractions

namespace {

__extension__ typedef __int128 Wide; // products of two int64 before reduction

int64_t narrow(Wide x) {
    if (x > INT64_MAX || x < -INT64_MAX) throw Error("invalid-argument", "a fraction grew beyond 64 bits; use smaller numbers");
    return static_cast<int64_t>(x);
}

Fraction reduced(Wide num, Wide den) {
    if (den < 0) num = -num, den = -den;
    Wide a = num < 0 ? -num : num, b = den;
    while (b != 0) {
        const Wide t = a % b;
        a = b, b = t;
    }
    if (a > 1) num /= a, den /= a;
    Fraction f;
    f.num = narrow(num);
    f.den = narrow(den);
    return f;
}

} // namespace

Fraction::Fraction(int64_t n, int64_t d) {
    if (d == 0) throw Error("invalid-argument", "a fraction's denominator must not be 0");
    *this = reduced(n, d);
}

Fraction Fraction::operator+(const Fraction& o) const { return reduced(Wide(num) * o.den + Wide(o.num) * den, Wide(den) * o.den); }
Fraction Fraction::operator-(const Fraction& o) const { return reduced(Wide(num) * o.den - Wide(o.num) * den, Wide(den) * o.den); }
Fraction Fraction::operator*(const Fraction& o) const { return reduced(Wide(num) * o.num, Wide(den) * o.den); }
Fraction Fraction::operator/(const Fraction& o) const {
    if (o.num == 0) throw Error("invalid-argument", "division of a fraction by 0");
    return reduced(Wide(num) * o.den, Wide(den) * o.num);
}

std::string Fraction::text() const { return den == 1 ? std::to_string(num) : std::to_string(num) + "/" + std::to_string(den); }

const char* new_point_name(NewPoint p) {
    switch (p) {
        case NewPoint::Vertex: return "vertex";
        case NewPoint::Edge: return "edge";
        case NewPoint::Face: return "face";
    }
    return "";
}

NewPoint new_point_from_name(const std::string& name) {
    if (name == "vertex") return NewPoint::Vertex;
    if (name == "edge") return NewPoint::Edge;
    if (name == "face") return NewPoint::Face;
    throw Error("invalid-argument", "a new point is a 'vertex', 'edge' or 'face' point, not '" + name.substr(0, 40) + "'");
}

// cos(2 pi / n) is rational only for n = 1, 2, 3, 4, 6 (Niven's theorem).
Fraction loop_beta_exact(int32_t n) {
    Fraction cosine;
    switch (n) {
        case 1: cosine = Fraction(1); break;
        case 2: cosine = Fraction(-1); break;
        case 3: cosine = Fraction(-1, 2); break;
        case 4: cosine = Fraction(0); break;
        case 6: cosine = Fraction(1, 2); break;
        default:
            throw Error("no-exact-mask", "Loop's beta for valence " + std::to_string(n) +
                                             " is not a fraction (cos(2 pi / n) is irrational); ask about a vertex of valence 3, 4 or 6");
    }
    const Fraction c = Fraction(3, 8) + cosine * Fraction(1, 4);
    return (Fraction(5, 8) - c * c) / Fraction(n);
}

// ------------------------------------------------------------------ stencils

namespace {

// Terms merged by vertex, first met first; the role is the first one given.
struct StencilBuilder {
    SubdivideStencil s;
    void add(int32_t v, const Fraction& w, const std::string& role) {
        auto at = std::find(s.vertices.begin(), s.vertices.end(), v);
        if (at == s.vertices.end()) {
            s.vertices.push_back(v);
            s.weights.push_back(w);
            s.roles.push_back(role);
        } else {
            const std::size_t i = static_cast<std::size_t>(at - s.vertices.begin());
            s.weights[i] = s.weights[i] + w;
        }
    }
};

bool boundary_edge(const WingedEdgeMesh& m, int32_t e) { return m.edge(e).left == kNone || m.edge(e).right == kNone; }

std::vector<int32_t> boundary_neighbours_of(const WingedEdgeMesh& m, int32_t v) {
    std::vector<int32_t> out;
    for (int32_t e : m.edges_around_vertex(v))
        if (boundary_edge(m, e)) out.push_back(m.other_vertex(e, v));
    return out;
}

// The face point of f spread over its corners, each with `scale` of the face point.
void add_face_point(StencilBuilder& b, const WingedEdgeMesh& m, int32_t f, const Fraction& scale, const std::string& role) {
    const std::vector<int32_t> corners = m.vertices_of_face(f);
    const Fraction share = scale / Fraction(static_cast<int64_t>(corners.size()));
    for (int32_t c : corners) b.add(c, share, role);
}

void require_index(int32_t i, int32_t count, MeshTable table) {
    if (i < 0 || i >= count) throw Error("invalid-element", missing_element_message(table, i, count));
}

SubdivideStencil vertex_stencil(const WingedEdgeMesh& m, Scheme scheme, int32_t v) {
    require_index(v, m.vertex_count(), MeshTable::Vertex);
    const std::string self = vertex_label(v);
    if (m.vertex_edge(v) == kNone) throw Error("no-exact-mask", self + " is on no edge: its vertex point is " + self + " itself, no mask to ask about");
    const std::vector<int32_t> ring = m.vertices_around_vertex(v);
    const int64_t n = static_cast<int64_t>(ring.size());
    const std::vector<int32_t> along = boundary_neighbours_of(m, v);
    StencilBuilder b;
    if (!along.empty()) {
        b.s.rule = PointRule::VertexBoundary;
        b.add(v, Fraction(3, 4), "the old vertex itself");
        for (int32_t u : along) b.add(u, Fraction(1, 4) / Fraction(static_cast<int64_t>(along.size())), "a neighbour of " + self + " along the boundary");
        return b.s;
    }
    b.s.rule = PointRule::VertexInterior;
    if (scheme == Scheme::Loop) {
        const Fraction beta = loop_beta_exact(static_cast<int32_t>(n));
        b.add(v, Fraction(1) - Fraction(n) * beta, "the old vertex itself");
        for (int32_t u : ring) b.add(u, beta, "a neighbour of " + self);
        return b.s;
    }
    const Fraction nn(n * n);
    b.add(v, Fraction(n - 2, n), "the old vertex itself");
    for (int32_t u : ring) b.add(u, Fraction(1) / nn, "joined to " + self + " by an edge (and a corner of faces around it)");
    for (int32_t f : m.faces_around_vertex(v)) add_face_point(b, m, f, Fraction(1) / nn, "a corner of " + face_label(f) + ", a face around " + self);
    return b.s;
}

int32_t opposite_corner(const WingedEdgeMesh& m, int32_t e, int32_t f) {
    for (int32_t c : m.vertices_of_face(f))
        if (c != m.edge(e).start && c != m.edge(e).end) return c;
    return kNone;
}

SubdivideStencil edge_stencil(const WingedEdgeMesh& m, Scheme scheme, int32_t e) {
    require_index(e, m.edge_count(), MeshTable::Edge);
    const EdgeRecord& r = m.edge(e);
    const std::string end = "an end of " + edge_label(e);
    StencilBuilder b;
    if (boundary_edge(m, e)) {
        b.s.rule = PointRule::EdgeBoundary;
        b.add(r.start, Fraction(1, 2), end);
        b.add(r.end, Fraction(1, 2), end);
        return b.s;
    }
    b.s.rule = PointRule::EdgeInterior;
    if (scheme == Scheme::Loop) {
        b.add(r.start, Fraction(3, 8), end);
        b.add(r.end, Fraction(3, 8), end);
        for (int32_t f : {r.left, r.right})
            b.add(opposite_corner(m, e, f), Fraction(1, 8), "the corner of " + face_label(f) + " opposite " + edge_label(e));
        return b.s;
    }
    b.add(r.start, Fraction(1, 4), end + " (and a corner of both faces beside it)");
    b.add(r.end, Fraction(1, 4), end + " (and a corner of both faces beside it)");
    for (int32_t f : {r.left, r.right})
        add_face_point(b, m, f, Fraction(1, 4), "a corner of " + face_label(f) + ", a face beside " + edge_label(e));
    return b.s;
}

SubdivideStencil face_stencil(const WingedEdgeMesh& m, Scheme scheme, int32_t f) {
    if (scheme == Scheme::Loop) throw Error("no-exact-mask", "Loop's scheme makes no face points: ask about a vertex or an edge point");
    require_index(f, m.face_count(), MeshTable::Face);
    StencilBuilder b;
    b.s.rule = PointRule::FacePoint;
    add_face_point(b, m, f, Fraction(1), "a corner of " + face_label(f));
    return b.s;
}

} // namespace

SubdivideStencil exact_stencil(const WingedEdgeMesh& mesh, Scheme scheme, NewPoint point, int32_t element) {
    require_ok(check_subdivide(mesh, scheme, 1));
    switch (point) {
        case NewPoint::Vertex: return vertex_stencil(mesh, scheme, element);
        case NewPoint::Edge: return edge_stencil(mesh, scheme, element);
        case NewPoint::Face: return face_stencil(mesh, scheme, element);
    }
    throw Error("invalid-argument", "unknown new point");
}

// ------------------------------------------------------------------ the checks' words

namespace {

std::string capitalised(std::string s) {
    if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
    return s;
}

std::string scheme_words(Scheme s) { return s == Scheme::Loop ? "Loop's scheme" : "Catmull-Clark's scheme"; }

std::string point_words(NewPoint p, int32_t element) {
    switch (p) {
        case NewPoint::Vertex: return "the vertex point of " + vertex_label(element);
        case NewPoint::Edge: return "the edge point of " + edge_label(element);
        case NewPoint::Face: return "the face point of " + face_label(element);
    }
    return "";
}

std::string mask_words(PointRule rule, Scheme scheme) {
    switch (rule) {
        case PointRule::FacePoint: return "face mask of " + scheme_words(scheme);
        case PointRule::EdgeInterior: return "interior edge mask of " + scheme_words(scheme);
        case PointRule::EdgeBoundary: return "boundary edge mask (the cubic B-spline curve's edge rule)";
        case PointRule::VertexInterior: return "interior vertex mask of " + scheme_words(scheme);
        case PointRule::VertexBoundary: return "boundary vertex mask (the cubic B-spline curve's vertex rule)";
        default: return "mask";
    }
}

// The rule the weights follow, in words and without a value.
std::string weight_rule(PointRule rule, Scheme scheme) {
    const bool loop = scheme == Scheme::Loop;
    switch (rule) {
        case PointRule::FacePoint: return "a face point is the centroid of the face's corners";
        case PointRule::EdgeInterior:
            return loop ? "an interior Loop edge point weighs the edge's two ends alike, and more than the two corners opposite the edge"
                        : "a Catmull-Clark edge point averages the edge's two ends and the face points of the two faces beside it, "
                          "and each face point shares its weight among its face's corners";
        case PointRule::EdgeBoundary: return "on the boundary the edge point follows the curve rule, along the boundary only";
        case PointRule::VertexInterior:
            return loop ? "an interior Loop vertex point gives each neighbour beta, which depends on the vertex's valence n, and the vertex itself 1 - n beta"
                        : "a Catmull-Clark vertex point weighs the vertex by (n - 2)/n and each edge neighbour and each face point around it "
                          "by 1/n^2 (n the valence), and each face point shares its weight among its face's corners";
        case PointRule::VertexBoundary: return "on the boundary the vertex point follows the curve rule: the vertex and its two neighbours along the boundary";
        default: return "";
    }
}

std::string weight_hint(PointRule rule, Scheme scheme) {
    const bool loop = scheme == Scheme::Loop;
    switch (rule) {
        case PointRule::FacePoint: return "Every corner of the face counts the same.";
        case PointRule::EdgeInterior:
            return loop ? "Sort the four points into the edge's two ends and the two corners opposite it; the ends count more, and all four weights add up to 1."
                        : "Write each face point as the average of its corners first, then add up everything one old point receives.";
        case PointRule::EdgeBoundary: return "Only points on the boundary count, as in the curve rule.";
        case PointRule::VertexInterior:
            return loop ? "Count the edges at the vertex (its valence n), put n into the lecture's formula for beta, and give the vertex what is left so that the weights add up to 1."
                        : "Count the valence n, write each face point as the average of its corners, then add up what each old point receives; "
                          "a point joined by an edge is also a corner of two faces.";
        case PointRule::VertexBoundary: return "Only the vertex and its two neighbours along the boundary count; the vertex itself counts most.";
        default: return "";
    }
}

const char* kMaskHint = "An edge with a face on one side only lies on the boundary, and so do its two ends.";

bool same_type(PointRule rule, NewPoint p) {
    switch (p) {
        case NewPoint::Vertex: return rule == PointRule::VertexInterior || rule == PointRule::VertexBoundary;
        case NewPoint::Edge: return rule == PointRule::EdgeInterior || rule == PointRule::EdgeBoundary;
        case NewPoint::Face: return rule == PointRule::FacePoint;
    }
    return false;
}

std::string row_words(std::size_t r) { return "row " + std::to_string(r + 1); }

} // namespace

std::vector<SubdivideFinding> check_subdivide_mask(const WingedEdgeMesh& mesh, Scheme scheme, NewPoint point, int32_t element,
                                                   const SubdivideMaskAnswer& answer) {
    const SubdivideStencil s = exact_stencil(mesh, scheme, point, element);
    if (answer.vertices.size() != answer.weights.size())
        throw Error("invalid-answer", "the answer has " + std::to_string(answer.vertices.size()) + " old points but " +
                                          std::to_string(answer.weights.size()) + " weights; give one weight per point");
    if (answer.rule != kNone && (answer.rule < 0 || answer.rule >= kPointRuleCount))
        throw Error("invalid-answer", "the mask chosen (" + std::to_string(answer.rule) + ") is not one of the masks");
    const std::string where = point_words(point, element);
    std::vector<SubdivideFinding> out;
    const bool mask_right = answer.rule == static_cast<int32_t>(s.rule);
    const std::string mask_read = mask_right ? "the " + mask_words(s.rule, scheme) : "the mask that makes this point";
    const std::string hint = mask_right ? weight_hint(s.rule, scheme) : kMaskHint;
    if (answer.rule == kNone) {
        out.push_back({"no-mask", kNone, kNone, kNone, "Choose the mask that makes " + where + ".", kMaskHint});
    } else if (!mask_right) {
        std::string text = "The mask chosen is not the one that makes " + where + ": ";
        if (!same_type(static_cast<PointRule>(answer.rule), point))
            text += std::string("a ") + new_point_name(point) + " point is made by " +
                    (point == NewPoint::Face ? "the face mask" : point == NewPoint::Edge ? "an edge mask" : "a vertex mask") +
                    ". Re-read the masks of the step.";
        else
            text += "re-read when a point is made by a boundary mask rather than an interior one.";
        out.push_back({"wrong-mask", kNone, kNone, kNone, text, kMaskHint});
    }
    const int32_t V = mesh.vertex_count();
    std::vector<int32_t> first_row(static_cast<std::size_t>(V), kNone);
    for (std::size_t r = 0; r < answer.vertices.size(); ++r) {
        const int32_t v = answer.vertices[r];
        const int32_t row = static_cast<int32_t>(r);
        if (v < 0 || v >= V) {
            out.push_back({"not-a-vertex", row, kNone, kNone,
                           capitalised(row_words(r)) + " names " + (v < 0 ? std::string("no vertex") : vertex_label(v)) +
                               ", but the old mesh has vertices v1 to " + vertex_label(V - 1) + ".",
                           "Name the old points as the drawing labels them."});
            continue;
        }
        if (first_row[v] != kNone) {
            out.push_back({"repeated-point", row, v, kNone,
                           capitalised(row_words(static_cast<std::size_t>(first_row[v]))) + " and " + row_words(r) + " both name " +
                               vertex_label(v) + ": give each old point once, with its whole weight.",
                           "Add up what one old point receives before you write it down."});
            continue;
        }
        first_row[v] = row;
        const auto at = std::find(s.vertices.begin(), s.vertices.end(), v);
        if (at == s.vertices.end()) {
            if (answer.weights[r].num != 0)
                out.push_back({"not-in-stencil", row, v, kNone,
                               vertex_label(v) + " (" + row_words(r) + ") is not one of the old points " + where +
                                   " averages. Re-read which points " + mask_read + " uses.",
                               hint});
            continue;
        }
        const std::size_t i = static_cast<std::size_t>(at - s.vertices.begin());
        if (answer.weights[r] != s.weights[i]) {
            std::string text = "The weight of " + vertex_label(v) + " (" + row_words(r) + ") in " + where + " is not right";
            text += mask_right ? ": " + vertex_label(v) + " is " + s.roles[i] + ", and " + weight_rule(s.rule, scheme) + ". Re-read " + mask_read + "."
                               : ". Re-read " + mask_read + ".";
            out.push_back({"wrong-weight", row, v, kNone, text, hint});
        }
    }
    // Missing points by their numbers (v1 before v5), as the student reads the drawing.
    std::vector<std::size_t> order(s.vertices.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.vertices[a] < s.vertices[b]; });
    for (std::size_t i : order) {
        const int32_t v = s.vertices[i];
        if (first_row[v] != kNone) continue;
        std::string text = vertex_label(v) + " is missing: " + where + " also averages " + vertex_label(v);
        text += mask_right ? " (" + s.roles[i] + "). Re-read " + mask_read + "." : ". Re-read " + mask_read + ".";
        out.push_back({"missing-point", kNone, v, kNone, text, hint});
    }
    return out;
}

std::vector<SubdivideFinding> check_subdivide_counts(const WingedEdgeMesh& mesh, Scheme scheme, int32_t steps, int64_t vertices,
                                                     int64_t edges, int64_t faces) {
    if (steps < 1 || steps > 4) throw Error("invalid-argument", "a counts question asks about 1 to 4 steps, not " + std::to_string(steps));
    require_ok(check_subdivide(mesh, scheme, steps));
    const SubdivisionCounts c = subdivision_counts(mesh, scheme, steps);
    const bool loop = scheme == Scheme::Loop;
    const std::string after = "after " + std::string(steps == 1 ? "one" : std::to_string(steps)) + " " +
                              (loop ? "Loop" : "Catmull-Clark") + " step" + (steps == 1 ? "" : "s");
    const std::string each = steps == 1 ? "" : " (each step starts from the mesh the step before made)";
    const std::string hint = "Count V, E and F of the mesh drawn first; on a closed mesh V - E + F stays the same after a step.";
    const struct {
        const char* what;
        int64_t given, expected;
        std::string rule;
    } rows[3] = {
        {"vertices", vertices, c.vertices,
         loop ? "every old vertex gives a vertex point and every old edge an edge point"
              : "every old vertex gives a vertex point, every old edge an edge point and every old face a face point"},
        {"edges", edges, c.edges,
         loop ? "every old edge is split in two, and every triangle gains three edges inside it, joining its edge points"
              : "every old edge is split in two, and every face gains one edge from its face point to the edge point of each side"},
        {"faces", faces, c.faces,
         loop ? "every triangle is split into four" : "every face is split into one quad per corner"},
    };
    std::vector<SubdivideFinding> out;
    for (int32_t k = 0; k < 3; ++k) {
        const auto& row = rows[k];
        if (row.given == row.expected) continue;
        if (row.given == kNone)
            out.push_back({"wrong-count", kNone, kNone, k, "The number of " + std::string(row.what) + " " + after + " is missing.", hint});
        else
            out.push_back({"wrong-count", kNone, kNone, k,
                           "The number of " + std::string(row.what) + " " + after + " is not right: " + row.rule + each +
                               ". Re-read what one step makes.",
                           hint});
    }
    return out;
}

} // namespace wingspline::mesh
