#include "wingspline/mesh/view_geometry.h"

#include "wingspline/error.h"
#include "wingspline/mesh/planes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace wingspline::mesh {

BoundingBox bounding_box(const WingedEdgeMesh& mesh) {
    // Over the live vertices: a vertex removed by an edit keeps its row but is not drawn.
    BoundingBox box;
    const int32_t n = mesh.vertex_count();
    int32_t v0 = 0;
    while (v0 < n && mesh.is_deleted(Vertex(v0))) ++v0;
    if (v0 == n) return box;
    box.min = box.max = mesh.position(v0);
    for (int32_t v = v0 + 1; v < n; ++v) {
        if (mesh.is_deleted(Vertex(v))) continue;
        const glm::dvec3 p = mesh.position(v);
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return box;
}

glm::dvec3 vertex_normal(const WingedEdgeMesh& mesh, int32_t v) {
    require_ok(mesh.check_element(Vertex(v)));
    glm::dvec3 sum(0.0);
    for (int32_t f : mesh.faces_around_vertex(v)) {
        const std::vector<int32_t> c = mesh.vertices_of_face(f);
        const glm::dvec3 n = newell_vector(mesh.positions().data(), c.data(), static_cast<int32_t>(c.size()));
        sum += n;
    }
    // Divided by its largest component first, so a tiny sum does not underflow in length().
    const double big = std::max({std::abs(sum.x), std::abs(sum.y), std::abs(sum.z)});
    if (!(big > 0)) return glm::dvec3(0.0);
    const glm::dvec3 s = sum / big;
    return s / glm::length(s);
}

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The corners of face f in the order of the lecture's walk along the face.
void corners_of(const WingedEdgeMesh& mesh, int32_t f, std::vector<int32_t>& out) {
    out.clear();
    const EdgeRecord* edges = mesh.edges().data();
    const int32_t first = mesh.face_edges()[f];
    if (first == kNone) return;
    int32_t e = first;
    const std::size_t limit = mesh.edges().size();
    do {
        const EdgeRecord& r = edges[e];
        out.push_back(r.left == f ? r.start : r.end);
        e = mesh.next_in_face(e, f);
    } while (e != first && out.size() <= limit);
}

double segment_distance(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(ax + t * dx - px, ay + t * dy - py);
}

} // namespace

namespace {

// The view frame: n towards the viewer, (a, b) the view plane, a x b = n, so a face whose
// corners run counter-clockwise in (a, b) is turned towards the viewer.
struct ViewFrame {
    glm::dvec3 n, a, b;
};

ViewFrame view_frame(const glm::dvec3& towards) {
    if (!finite(towards)) throw Error("invalid-argument", "the view direction must have finite components");
    const double big = std::max({std::abs(towards.x), std::abs(towards.y), std::abs(towards.z)});
    if (!(big > 0)) throw Error("invalid-argument", "the view direction is (0, 0, 0): it must point from the mesh to the viewer");
    const glm::dvec3 n = glm::normalize(towards / big);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(helper, n));
    return {n, a, glm::cross(n, a)};
}

void check_pick(const glm::dvec3& point, double radius, int32_t max_near) {
    if (!finite(point)) throw Error("invalid-argument", "the picking point must have finite coordinates");
    if (!(radius >= 0) || !std::isfinite(radius))
        throw Error("invalid-argument", "the picking radius must be a finite number >= 0 (world units)");
    if (max_near < 0) throw Error("invalid-argument", "the number of nearby faces asked for must be >= 0");
}

// The pick itself, over the edges `each_edge` hands out in increasing order (every live edge,
// or those a PickGrid found near the line; the answer is the same when those include every
// edge the half-line crosses or the radius reaches), a vertex's view-plane coordinates
// relative to the point from `at(v)`.
// `odd`: one entry per face, all 0 on entry; the faces it toggled are set back to 0 on return.
template <class EachEdge, class At>
PickResult pick_over(const WingedEdgeMesh& mesh, const glm::dvec3& n, EachEdge&& each_edge, At&& at, double radius, int32_t max_near,
                     std::vector<char>& odd) {
    // The line of sight passes through a face when the half-line from the point along +a
    // crosses the face's sides an odd number of times (the crossing-number test, half-open
    // in y so a corner on the half-line counts once); each side crossed toggles both faces of
    // the edge. A side within the radius makes both its faces near, at the side's distance.
    const auto is_odd = [&](int32_t f) { return odd[static_cast<std::size_t>(f)] != 0; };
    std::vector<int32_t> toggled;
    std::vector<std::pair<int32_t, double>> close; // (face, distance of one of its sides)
    each_edge([&](const EdgeRecord& r) {
        const auto [xs, ys] = at(r.start);
        const auto [xt, yt] = at(r.end);
        if ((ys > 0) != (yt > 0) && xs + (0 - ys) * (xt - xs) / (yt - ys) > 0) {
            for (const int32_t f : {r.left, r.right}) {
                if (f == kNone) continue;
                char& o = odd[static_cast<std::size_t>(f)];
                if (!o) toggled.push_back(f);
                o ^= 1;
            }
        }
        if (std::min(xs, xt) > radius || std::max(xs, xt) < -radius || std::min(ys, yt) > radius || std::max(ys, yt) < -radius)
            return;
        const double d = segment_distance(0, 0, xs, ys, xt, yt);
        if (d > radius) return;
        for (const int32_t f : {r.left, r.right})
            if (f != kNone) close.push_back({f, d});
    });
    // The faces passed through: the nearest to the viewer is the one seen. Its depth where
    // the line meets it: the fan triangle (0, i, i+1) containing the point, by barycentric
    // coordinates (for a non-planar face, the triangle nearest containing it).
    PickResult result;
    double best_depth = -std::numeric_limits<double>::infinity();
    std::vector<int32_t> c;
    for (const int32_t f : toggled) {
        if (!is_odd(f)) continue;
        corners_of(mesh, f, c);
        double depth = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 1; i + 1 < c.size(); ++i) {
            const auto [x0, y0] = at(c[0]);
            const auto [xi, yi] = at(c[i]);
            const auto [xj, yj] = at(c[i + 1]);
            const double x1 = xi - x0, y1 = yi - y0, x2 = xj - x0, y2 = yj - y0;
            const double det = x1 * y2 - x2 * y1;
            if (det == 0) continue;
            const double w1 = (-x0 * y2 + x2 * y0) / det, w2 = (x1 * -y0 + x0 * y1) / det;
            const double z0 = glm::dot(mesh.position(c[0]), n);
            const double z = z0 + w1 * (glm::dot(mesh.position(c[i]), n) - z0) + w2 * (glm::dot(mesh.position(c[i + 1]), n) - z0);
            const bool inside = w1 >= 0 && w2 >= 0 && w1 + w2 <= 1;
            if (inside || depth == -std::numeric_limits<double>::infinity()) depth = inside ? z : std::max(depth, z);
            if (inside) break;
        }
        if (depth > best_depth) best_depth = depth, result.face = f;
    }
    // Near: the seen face first, then faces turned towards the viewer by the distance of
    // their nearest side (a face passed through but behind the seen one is hidden by it).
    std::sort(close.begin(), close.end(), [](const auto& l, const auto& r) { return l.first < r.first || (l.first == r.first && l.second < r.second); });
    std::vector<PickNear> near;
    if (result.face >= 0) near.push_back({result.face, 0});
    for (std::size_t i = 0; i < close.size(); ++i) {
        if (i > 0 && close[i].first == close[i - 1].first) continue; // the nearest side of each face
        const int32_t f = close[i].first;
        if (f == result.face || is_odd(f) || mesh.is_deleted(Face(f))) continue;
        corners_of(mesh, f, c);
        double area2 = 0; // twice the signed area in the view plane
        for (std::size_t k = 0, j = c.size() - 1; k < c.size(); j = k++) {
            const auto [xj, yj] = at(c[j]);
            const auto [xk, yk] = at(c[k]);
            area2 += xj * yk - xk * yj;
        }
        if (area2 > 0) near.push_back({f, close[i].second});
    }
    std::stable_sort(near.begin() + (result.face >= 0 ? 1 : 0), near.end(),
                     [](const PickNear& l, const PickNear& r) { return l.distance < r.distance; });
    if (near.size() > static_cast<std::size_t>(max_near)) near.resize(static_cast<std::size_t>(max_near));
    result.near = std::move(near);
    for (const int32_t f : toggled) odd[static_cast<std::size_t>(f)] = 0;
    return result;
}

} // namespace

PickResult pick_faces(const WingedEdgeMesh& mesh, const glm::dvec3& point, const glm::dvec3& towards, double radius,
                      int32_t max_near) {
    check_pick(point, radius, max_near);
    const ViewFrame frame = view_frame(towards);
    const double qx = glm::dot(point, frame.a), qy = glm::dot(point, frame.b);
    // Every vertex in the view frame once, relative to the point (a vertex is a corner of
    // about six faces).
    const int32_t V = mesh.vertex_count();
    std::vector<double> vx(static_cast<std::size_t>(V)), vy(static_cast<std::size_t>(V));
    for (int32_t v = 0; v < V; ++v) {
        const glm::dvec3 p = mesh.position(v);
        vx[static_cast<std::size_t>(v)] = glm::dot(p, frame.a) - qx, vy[static_cast<std::size_t>(v)] = glm::dot(p, frame.b) - qy;
    }
    const std::vector<EdgeRecord>& edges = mesh.edges();
    const auto every_edge = [&](auto&& visit) {
        for (int32_t e = 0; e < static_cast<int32_t>(edges.size()); ++e)
            if (!mesh.is_deleted(Edge(e))) visit(edges[static_cast<std::size_t>(e)]);
    };
    const auto at = [&](int32_t v) { return std::pair<double, double>{vx[static_cast<std::size_t>(v)], vy[static_cast<std::size_t>(v)]}; };
    std::vector<char> odd(static_cast<std::size_t>(mesh.face_count()), 0);
    return pick_over(mesh, frame.n, every_edge, at, radius, max_near, odd);
}

// ---------------------------------------------------------------- the pick grid

bool PickGrid::fits(const WingedEdgeMesh& mesh, const glm::dvec3& towards) const {
    return built_ && version_ == mesh.version() && towards_ == towards && vertices_ == mesh.vertex_count();
}

void PickGrid::build(const WingedEdgeMesh& mesh, const glm::dvec3& towards) {
    const ViewFrame frame = view_frame(towards);
    built_ = false;
    n_ = frame.n, a_ = frame.a, b_ = frame.b;
    const int32_t V = mesh.vertex_count();
    pa_.assign(static_cast<std::size_t>(V), 0.0);
    pb_.assign(static_cast<std::size_t>(V), 0.0);
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
    for (int32_t v = 0; v < V; ++v) {
        const glm::dvec3 p = mesh.position(v);
        pa_[static_cast<std::size_t>(v)] = glm::dot(p, a_), pb_[static_cast<std::size_t>(v)] = glm::dot(p, b_);
        if (mesh.is_deleted(Vertex(v))) continue;
        xmin = std::min(xmin, pa_[static_cast<std::size_t>(v)]), xmax = std::max(xmax, pa_[static_cast<std::size_t>(v)]);
        ymin = std::min(ymin, pb_[static_cast<std::size_t>(v)]), ymax = std::max(ymax, pb_[static_cast<std::size_t>(v)]);
    }
    const std::vector<EdgeRecord>& edges = mesh.edges();
    const auto E = static_cast<int32_t>(edges.size());
    // About eight live edges per cell (a coarser grid builds faster: each edge is in one or two
    // cells; a pick then reads a few thousand edges at a million faces): square cells over the
    // mesh's extent in the view plane.
    int64_t live = 0;
    for (int32_t e = 0; e < E; ++e) live += !mesh.is_deleted(Edge(e));
    if (!(xmin <= xmax)) xmin = xmax = ymin = ymax = 0;
    const double w = std::max(xmax - xmin, 1e-300), hgt = std::max(ymax - ymin, 1e-300);
    const double cells = std::max<double>(1.0, static_cast<double>(live) / 8.0);
    h_ = std::max(std::sqrt(w * hgt / cells), std::max(w, hgt) / 4096.0);
    x0_ = xmin, y0_ = ymin;
    nx_ = std::clamp(static_cast<int32_t>(std::floor(w / h_)) + 1, 1, 4096);
    ny_ = std::clamp(static_cast<int32_t>(std::floor(hgt / h_)) + 1, 1, 4096);
    // Each live edge in every cell its box in the view plane covers (counting, then filling).
    cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    const auto range = [&](const EdgeRecord& r, int32_t& c0, int32_t& c1, int32_t& r0, int32_t& r1) {
        const double xs = pa_[static_cast<std::size_t>(r.start)], xt = pa_[static_cast<std::size_t>(r.end)];
        const double ys = pb_[static_cast<std::size_t>(r.start)], yt = pb_[static_cast<std::size_t>(r.end)];
        c0 = column(std::min(xs, xt)), c1 = column(std::max(xs, xt));
        r0 = row(std::min(ys, yt)), r1 = row(std::max(ys, yt));
    };
    for (int32_t e = 0; e < E; ++e) {
        if (mesh.is_deleted(Edge(e))) continue;
        int32_t c0, c1, r0, r1;
        range(edges[static_cast<std::size_t>(e)], c0, c1, r0, r1);
        for (int32_t y = r0; y <= r1; ++y)
            for (int32_t x = c0; x <= c1; ++x) ++cell_start_[static_cast<std::size_t>(y) * nx_ + x + 1];
    }
    for (std::size_t i = 1; i < cell_start_.size(); ++i) cell_start_[i] += cell_start_[i - 1];
    cell_edges_.assign(static_cast<std::size_t>(cell_start_.back()), 0);
    std::vector<int32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (int32_t e = 0; e < E; ++e) {
        if (mesh.is_deleted(Edge(e))) continue;
        int32_t c0, c1, r0, r1;
        range(edges[static_cast<std::size_t>(e)], c0, c1, r0, r1);
        for (int32_t y = r0; y <= r1; ++y)
            for (int32_t x = c0; x <= c1; ++x) cell_edges_[static_cast<std::size_t>(fill[static_cast<std::size_t>(y) * nx_ + x]++)] = e;
    }
    version_ = mesh.version();
    towards_ = towards;
    vertices_ = V;
    built_ = true;
}

int32_t PickGrid::column(double x) const {
    return std::clamp(static_cast<int32_t>(std::floor((x - x0_) / h_)), 0, nx_ - 1);
}

int32_t PickGrid::row(double y) const {
    return std::clamp(static_cast<int32_t>(std::floor((y - y0_) / h_)), 0, ny_ - 1);
}

PickResult PickGrid::pick(const WingedEdgeMesh& mesh, const glm::dvec3& point, double radius, int32_t max_near) {
    check_pick(point, radius, max_near);
    if (!built_) throw Error("internal-error", "the pick grid is used before it was built");
    const double qx = glm::dot(point, a_), qy = glm::dot(point, b_);
    // The edges the answer can depend on: those whose box meets the half-line from the point
    // along +a (the crossings) or the square of side 2 radius about it (the near ones). The
    // cells are found with a margin: a coordinate's cell is computed from its absolute value,
    // the tests on values relative to the point.
    const double margin = 1e-9 * h_ * (nx_ + ny_);
    std::vector<int32_t> found;
    const auto take = [&](int32_t c0, int32_t c1, int32_t r0, int32_t r1) {
        for (int32_t y = r0; y <= r1; ++y)
            for (int32_t x = c0; x <= c1; ++x) {
                const std::size_t cell = static_cast<std::size_t>(y) * nx_ + x;
                found.insert(found.end(), cell_edges_.begin() + cell_start_[cell], cell_edges_.begin() + cell_start_[cell + 1]);
            }
    };
    const double gx1 = x0_ + h_ * nx_, gy1 = y0_ + h_ * ny_;
    if (qy + margin >= y0_ && qy - margin <= gy1 && qx - margin <= gx1) take(column(qx - margin), nx_ - 1, row(qy - margin), row(qy + margin));
    if (qx + radius + margin >= x0_ && qx - radius - margin <= gx1 && qy + radius + margin >= y0_ && qy - radius - margin <= gy1)
        take(column(qx - radius - margin), column(qx + radius + margin), row(qy - radius - margin), row(qy + radius + margin));
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    const std::vector<EdgeRecord>& edges = mesh.edges();
    const auto some_edges = [&](auto&& visit) {
        for (const int32_t e : found) visit(edges[static_cast<std::size_t>(e)]);
    };
    const auto at = [&](int32_t v) {
        return std::pair<double, double>{pa_[static_cast<std::size_t>(v)] - qx, pb_[static_cast<std::size_t>(v)] - qy};
    };
    odd_.resize(static_cast<std::size_t>(mesh.face_count()), 0); // all 0 between picks
    return pick_over(mesh, n_, some_edges, at, radius, max_near, odd_);
}

std::size_t PickGrid::bytes() const {
    return sizeof(double) * (pa_.capacity() + pb_.capacity()) + sizeof(int32_t) * (cell_start_.capacity() + cell_edges_.capacity()) + odd_.capacity();
}

DisplayProxy display_proxy(const WingedEdgeMesh& mesh, int32_t target_triangles) {
    if (target_triangles < 1) throw Error("invalid-argument", "the proxy needs a target of at least 1 triangle");
    const int32_t F = mesh.face_count();
    const int32_t V = mesh.vertex_count();
    std::vector<int32_t> c;
    // Fan triangles = corners - 2 per face; the corners are the edge sides that have a face.
    int64_t fan = 0;
    const int32_t E = static_cast<int32_t>(mesh.edges().size());
    for (int32_t e = 0; e < E; ++e) {
        if (mesh.is_deleted(Edge(e))) continue;
        const EdgeRecord& r = mesh.edges()[static_cast<std::size_t>(e)];
        fan += (r.left != kNone) + (r.right != kNone);
    }
    for (int32_t f = 0; f < F; ++f)
        if (!mesh.is_deleted(Face(f)) && mesh.face_edges()[f] != kNone) fan -= 2;
    DisplayProxy out;
    // Each face's fan triangles through a vertex map (identity for the mesh itself).
    auto triangles_through = [&](const std::vector<int32_t>& map) {
        for (int32_t f = 0; f < F; ++f) {
            if (mesh.is_deleted(Face(f)) || mesh.face_edges()[f] == kNone) continue;
            corners_of(mesh, f, c);
            for (std::size_t i = 1; i + 1 < c.size(); ++i) {
                const int32_t p = map.empty() ? c[0] : map[c[0]];
                const int32_t q = map.empty() ? c[i] : map[c[i]];
                const int32_t r = map.empty() ? c[i + 1] : map[c[i + 1]];
                if (p == q || q == r || r == p) continue;
                out.triangles.insert(out.triangles.end(), {p, q, r});
            }
        }
    };
    if (fan <= target_triangles) {
        out.positions.reserve(3 * static_cast<std::size_t>(V));
        for (int32_t v = 0; v < V; ++v) out.positions.insert(out.positions.end(), {mesh.position(v).x, mesh.position(v).y, mesh.position(v).z});
        triangles_through({});
        return out;
    }
    const BoundingBox box = bounding_box(mesh);
    const glm::dvec3 size = box.max - box.min;
    const double extent = std::max({size.x, size.y, size.z});
    // A closed surface keeps about two triangles per occupied cell: aim at target / 2 cells.
    // First guess from the box's surface, then refined by the cells really occupied
    // (occupied cells of a surface grow as 1 / cell^2).
    const double wanted = std::max(1.0, target_triangles / 2.0);
    const double surface = 2 * (size.x * size.y + size.y * size.z + size.z * size.x);
    double cell = surface > 0 ? std::sqrt(surface / wanted) : extent / wanted;
    if (!(cell > 0)) cell = 1;
    constexpr int64_t kMaxCells = int64_t(1) << 24; // a dense grid of at most 16M cells (64 MB)
    std::vector<int32_t> grid;
    std::vector<int32_t> map(static_cast<std::size_t>(V), -1);
    int64_t nx = 1, ny = 1, nz = 1;
    int32_t occupied = 0;
    auto assign = [&](double s) {
        nx = static_cast<int64_t>(size.x / s) + 1, ny = static_cast<int64_t>(size.y / s) + 1, nz = static_cast<int64_t>(size.z / s) + 1;
        grid.assign(static_cast<std::size_t>(nx * ny * nz), -1);
        occupied = 0;
        for (int32_t v = 0; v < V; ++v) {
            if (mesh.is_deleted(Vertex(v))) continue;
            const glm::dvec3 d = (mesh.position(v) - box.min) / s;
            const int64_t ix = std::min<int64_t>(nx - 1, static_cast<int64_t>(d.x));
            const int64_t iy = std::min<int64_t>(ny - 1, static_cast<int64_t>(d.y));
            const int64_t iz = std::min<int64_t>(nz - 1, static_cast<int64_t>(d.z));
            int32_t& slot = grid[static_cast<std::size_t>((ix * ny + iy) * nz + iz)];
            if (slot < 0) slot = occupied++;
            map[static_cast<std::size_t>(v)] = slot;
        }
    };
    for (int round = 0; round < 4; ++round) {
        while ((static_cast<int64_t>(size.x / cell) + 1) * (static_cast<int64_t>(size.y / cell) + 1) *
                   (static_cast<int64_t>(size.z / cell) + 1) > kMaxCells)
            cell *= 1.25;
        assign(cell);
        const double ratio = occupied / wanted;
        if ((ratio > 0.8 && ratio < 1.1) || round == 3) break; // the cell assigned is the one kept
        cell *= std::sqrt(ratio);
    }
    out.cell = cell;
    std::vector<double> sum(3 * static_cast<std::size_t>(occupied), 0.0);
    std::vector<int32_t> count(static_cast<std::size_t>(occupied), 0);
    for (int32_t v = 0; v < V; ++v) {
        const int32_t m = map[static_cast<std::size_t>(v)];
        if (m < 0) continue;
        const glm::dvec3 p = mesh.position(v);
        sum[3 * m] += p.x, sum[3 * m + 1] += p.y, sum[3 * m + 2] += p.z;
        ++count[static_cast<std::size_t>(m)];
    }
    out.positions.resize(3 * static_cast<std::size_t>(occupied));
    for (int32_t m = 0; m < occupied; ++m)
        for (int i = 0; i < 3; ++i) out.positions[3 * m + i] = sum[3 * m + i] / std::max(1, count[static_cast<std::size_t>(m)]);
    triangles_through(map);
    // A mesh thinner than a cell (a long strip) can collapse to almost nothing: then the
    // mesh itself is the truer picture (at most target triangles were asked for, but an
    // empty proxy would draw nothing while the view moves).
    if (out.triangles.size() / 3 < static_cast<std::size_t>(target_triangles) / 8) {
        out = DisplayProxy{};
        out.positions.reserve(3 * static_cast<std::size_t>(V));
        for (int32_t v = 0; v < V; ++v) out.positions.insert(out.positions.end(), {mesh.position(v).x, mesh.position(v).y, mesh.position(v).z});
        triangles_through({});
    }
    return out;
}

} // namespace wingspline::mesh
