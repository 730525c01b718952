#include "wingspline/curves/constraints.h"

#include "wingspline/error.h"

#include <algorithm>
#include <cmath>

namespace wingspline::curves {

namespace {

// A view of the flat entries as vectors of `dim` numbers.
struct Entries {
    std::vector<double> v;
    int dim;
    std::vector<double> get(int i) const { return {v.begin() + dim * i, v.begin() + dim * (i + 1)}; }
    void set(int i, const std::vector<double>& x) { std::copy(x.begin(), x.end(), v.begin() + dim * i); }
    int count() const { return static_cast<int>(v.size()) / dim; }
};

using Vec = std::vector<double>;
Vec combine(double a, const Vec& x, double b, const Vec& y) {
    Vec out(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) out[k] = a * x[k] + b * y[k];
    return out;
}
Vec add(const Vec& x, const Vec& y) { return combine(1, x, 1, y); }
Vec sub(const Vec& x, const Vec& y) { return combine(1, x, -1, y); }
Vec scale(const Vec& x, double s) { return combine(s, x, 0, x); }
double norm(const Vec& x) {
    double s = 0;
    for (double c : x) s += c * c;
    return std::sqrt(s);
}
int level_of(JointConstraint m) {
    switch (m) {
    case JointConstraint::Free: return -1;
    case JointConstraint::C0: return 0;
    case JointConstraint::G1: return 1; // with the G1 rule below
    case JointConstraint::C1: return 2;
    case JointConstraint::C2: return 3;
    }
    return -1;
}

// d scaled to length `keep` when d has a direction (see kDegenerateLeg); false otherwise.
bool direction_with_length(const Vec& d, double keep, double size, Vec& out) {
    const double n = norm(d);
    if (!(n > kDegenerateLeg * std::max({size, n, keep}))) return false;
    out = scale(d, keep / n);
    return true;
}

void check(const std::vector<double>& points, int dim, BasisKind family, bool piecewise_only) {
    require(dim == 2 || dim == 3, "invalid-dimension", "dim must be 2 or 3, not " + std::to_string(dim));
    require(points.size() % static_cast<std::size_t>(dim) == 0, "invalid-points",
            "the number of coordinates (" + std::to_string(points.size()) + ") is not a multiple of dim " + std::to_string(dim));
    for (std::size_t j = 0; j < points.size(); ++j)
        require(std::isfinite(points[j]), "non-finite-input",
                "control entry " + std::to_string(j / dim) + " component " + std::to_string(j % dim) + " is not a finite number");
    const bool piecewise = family == BasisKind::Bezier || family == BasisKind::Hermite;
    if (piecewise_only)
        require(piecewise, "unsupported-curve-kind",
                std::string("constraints move the separate segments of a Bezier or Hermite curve; ") + basis_kind_name(family) +
                    " segments share their control points, so their joints are continuous by construction");
    const std::size_t n = points.size() / dim;
    if (piecewise)
        require(n >= 4 && n % 4 == 0, "wrong-point-count",
                "a piecewise " + std::string(basis_kind_name(family)) + " curve has 4 entries per segment, not " + std::to_string(n) + " entries");
    else
        require(n >= 4, "too-few-points", "a curve of windows of four needs at least 4 points, not " + std::to_string(n));
}

// Makes joint j satisfy `mode`, changing only the side that is not the master.
void enforce_joint(Entries& e, BasisKind family, int j, JointConstraint mode, bool left_master) {
    const int level = level_of(mode);
    if (level < 0) return;
    const int l = 4 * (j - 1);
    const int r = 4 * j;
    if (family == BasisKind::Bezier) {
        if (left_master) e.set(r, e.get(l + 3)); else e.set(l + 3, e.get(r));
        const Vec J = e.get(r);
        if (mode == JointConstraint::G1) {
            Vec moved;
            if (left_master) {
                const Vec d = sub(J, e.get(l + 2));
                if (direction_with_length(d, norm(sub(e.get(r + 1), J)), norm(J), moved)) e.set(r + 1, add(J, moved));
            } else {
                const Vec d = sub(e.get(r + 1), J);
                if (direction_with_length(d, norm(sub(J, e.get(l + 2))), norm(J), moved)) e.set(l + 2, sub(J, moved));
            }
        } else if (level >= 2) {
            // C1: J - L2 = R1 - J
            if (left_master) e.set(r + 1, sub(scale(J, 2), e.get(l + 2)));
            else e.set(l + 2, sub(scale(J, 2), e.get(r + 1)));
        }
        if (level >= 3) {
            // C2: R2 = L1 - 4 L2 + 4 L3 (and L1 = R2 - 4 R1 + 4 R0)
            if (left_master) e.set(r + 2, add(sub(e.get(l + 1), scale(e.get(l + 2), 4)), scale(J, 4)));
            else e.set(l + 1, add(sub(e.get(r + 2), scale(e.get(r + 1), 4)), scale(J, 4)));
        }
        return;
    }
    // Hermite: [p0, p1, t0, t1] per segment; the joint is L.p1 = R.p0, tangents L.t1 and R.t0.
    if (left_master) e.set(r, e.get(l + 1)); else e.set(l + 1, e.get(r));
    if (mode == JointConstraint::G1) {
        Vec moved;
        if (left_master) {
            if (direction_with_length(e.get(l + 3), norm(e.get(r + 2)), 0, moved)) e.set(r + 2, moved);
        } else {
            if (direction_with_length(e.get(r + 2), norm(e.get(l + 3)), 0, moved)) e.set(l + 3, moved);
        }
    } else if (level >= 2) {
        if (left_master) e.set(r + 2, e.get(l + 3)); else e.set(l + 3, e.get(r + 2));
    }
    if (level >= 3) {
        const Vec p0 = e.get(l), p1 = e.get(l + 1), t0 = e.get(l + 2), t1 = e.get(l + 3);
        const Vec q0 = e.get(r), q1 = e.get(r + 1), s0 = e.get(r + 2), s1 = e.get(r + 3);
        if (left_master) {
            // 6p0 - 6p1 + 2t0 + 4t1 = -6q0 + 6q1 - 4s0 - 2s1, solved for s1
            const Vec a = add(add(scale(sub(p0, p1), 6), scale(t0, 2)), scale(t1, 4));
            e.set(r + 3, scale(sub(sub(scale(sub(q1, q0), 6), scale(s0, 4)), a), 0.5));
        } else {
            // ... solved for t0
            const Vec a = sub(sub(scale(sub(q1, q0), 6), scale(s0, 4)), scale(s1, 2));
            e.set(l + 2, scale(sub(sub(a, scale(sub(p0, p1), 6)), scale(t1, 4)), 0.5));
        }
    }
}

} // namespace

JointConstraint parse_joint_constraint(const std::string& name) {
    if (name == "free") return JointConstraint::Free;
    if (name == "C0") return JointConstraint::C0;
    if (name == "G1") return JointConstraint::G1;
    if (name == "C1") return JointConstraint::C1;
    if (name == "C2") return JointConstraint::C2;
    throw Error("invalid-argument", "the constraint must be free, C0, G1, C1 or C2, not '" + name.substr(0, 20) + "'");
}

std::vector<double> drag_with_constraint(const std::vector<double>& points, int dim, BasisKind family,
                                         JointConstraint mode, int index, const std::vector<double>& to) {
    check(points, dim, family, true);
    Entries e{points, dim};
    const int n = e.count();
    require(index >= 0 && index < n, "invalid-argument",
            "entry " + std::to_string(index) + " does not exist; this curve has entries 0 to " + std::to_string(n - 1));
    require(to.size() == static_cast<std::size_t>(dim), "invalid-points",
            "the new position needs " + std::to_string(dim) + " numbers, not " + std::to_string(to.size()));
    for (double c : to) require(std::isfinite(c), "non-finite-input", "the new position is not a finite point");
    const int segments = n / 4;
    const int s = index / 4;
    const int k = index % 4;
    const Vec delta = sub(to, e.get(index));
    e.set(index, to);
    if (mode == JointConstraint::Free) return e.v;
    const bool bezier = family == BasisKind::Bezier;
    const bool is_start = k == 0;
    const bool is_end = bezier ? k == 3 : k == 1;
    // Moving a joint end point carries its Bezier neighbours along, so the joint keeps its shape.
    if (bezier && is_end) {
        e.set(4 * s + 2, add(e.get(4 * s + 2), delta));
        if (s + 1 < segments) e.set(4 * (s + 1) + 1, add(e.get(4 * (s + 1) + 1), delta));
    }
    if (bezier && is_start) {
        e.set(4 * s + 1, add(e.get(4 * s + 1), delta));
        if (s > 0) e.set(4 * (s - 1) + 2, add(e.get(4 * (s - 1) + 2), delta));
    }
    if (is_end && s + 1 < segments) e.set(4 * (s + 1), e.get(index));
    if (is_start && s > 0) e.set(4 * (s - 1) + (bezier ? 3 : 1), e.get(index));
    for (int j = s + 1; j < segments; ++j) enforce_joint(e, family, j, mode, true);
    for (int j = s; j >= 1; --j) enforce_joint(e, family, j, mode, false);
    return e.v;
}

std::vector<double> enforce_constraint(const std::vector<double>& points, int dim, BasisKind family, JointConstraint mode) {
    check(points, dim, family, true);
    Entries e{points, dim};
    for (int j = 1; j < e.count() / 4; ++j) enforce_joint(e, family, j, mode, true);
    return e.v;
}

std::vector<double> append_segment(const std::vector<double>& points, int dim, BasisKind family, JointConstraint mode) {
    check(points, dim, family, false);
    Entries e{points, dim};
    const int n = e.count();
    std::vector<Vec> more;
    if (family == BasisKind::Bezier) {
        const Vec L0 = e.get(n - 4), L1 = e.get(n - 3), L2 = e.get(n - 2), L3 = e.get(n - 1);
        const Vec d = sub(L3, L0);
        more = {L3, add(L1, d), add(L2, d), add(L3, d)};
    } else if (family == BasisKind::Hermite) {
        const Vec p0 = e.get(n - 4), p1 = e.get(n - 3), t0 = e.get(n - 2), t1 = e.get(n - 1);
        more = {p1, add(p1, sub(p1, p0)), t1, t0};
    } else {
        more = {add(e.get(n - 1), scale(sub(e.get(n - 1), e.get(n - 3)), 0.5))};
    }
    for (const Vec& x : more) e.v.insert(e.v.end(), x.begin(), x.end());
    if (family != BasisKind::Bezier && family != BasisKind::Hermite) return e.v;
    return enforce_constraint(e.v, dim, family, mode);
}

} // namespace wingspline::curves
