#include "wingspline/mesh/view_geometry.h"

#include "wingspline/error.h"
#include "wingspline/mesh/planes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
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

PickResult pick_faces(const WingedEdgeMesh& mesh, const glm::dvec3& point, const glm::dvec3& towards, double radius,
                      int32_t max_near) {
    if (!finite(point)) throw Error("invalid-argument", "the picking point must have finite coordinates");
    if (!finite(towards)) throw Error("invalid-argument", "the view direction must have finite components");
    const double big = std::max({std::abs(towards.x), std::abs(towards.y), std::abs(towards.z)});
    if (!(big > 0)) throw Error("invalid-argument", "the view direction is (0, 0, 0): it must point from the mesh to the viewer");
    if (!(radius >= 0) || !std::isfinite(radius))
        throw Error("invalid-argument", "the picking radius must be a finite number >= 0 (world units)");
    if (max_near < 0) throw Error("invalid-argument", "the number of nearby faces asked for must be >= 0");
    // The view frame: n towards the viewer, (a, b) the view plane, a x b = n, so a face whose
    // corners run counter-clockwise in (a, b) is turned towards the viewer.
    const glm::dvec3 n = glm::normalize(towards / big);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 b = glm::cross(n, a);
    const double qx = glm::dot(point, a), qy = glm::dot(point, b);
    // Every vertex in the view frame once, relative to the point (a vertex is a corner of
    // about six faces).
    const int32_t V = mesh.vertex_count();
    std::vector<double> vx(static_cast<std::size_t>(V)), vy(static_cast<std::size_t>(V));
    for (int32_t v = 0; v < V; ++v) {
        const glm::dvec3 p = mesh.position(v);
        vx[static_cast<std::size_t>(v)] = glm::dot(p, a) - qx, vy[static_cast<std::size_t>(v)] = glm::dot(p, b) - qy;
    }
    // One pass over the edges. The line of sight passes through a face when the half-line
    // from the point along +a crosses the face's sides an odd number of times (the
    // crossing-number test, half-open in y so a corner on the half-line counts once); each
    // side crossed toggles both faces of the edge. A side within the radius makes both its
    // faces near, at the side's distance.
    const int32_t F = mesh.face_count();
    std::vector<char> odd(static_cast<std::size_t>(F), 0);
    std::vector<int32_t> toggled;
    std::vector<std::pair<int32_t, double>> close; // (face, distance of one of its sides)
    const std::vector<EdgeRecord>& edges = mesh.edges();
    const int32_t E = static_cast<int32_t>(edges.size());
    for (int32_t e = 0; e < E; ++e) {
        if (mesh.is_deleted(Edge(e))) continue;
        const EdgeRecord& r = edges[static_cast<std::size_t>(e)];
        const double xs = vx[static_cast<std::size_t>(r.start)], ys = vy[static_cast<std::size_t>(r.start)];
        const double xt = vx[static_cast<std::size_t>(r.end)], yt = vy[static_cast<std::size_t>(r.end)];
        if ((ys > 0) != (yt > 0) && xs + (0 - ys) * (xt - xs) / (yt - ys) > 0) {
            for (const int32_t f : {r.left, r.right}) {
                if (f == kNone) continue;
                if (!odd[static_cast<std::size_t>(f)]) toggled.push_back(f);
                odd[static_cast<std::size_t>(f)] ^= 1;
            }
        }
        if (std::min(xs, xt) > radius || std::max(xs, xt) < -radius || std::min(ys, yt) > radius || std::max(ys, yt) < -radius)
            continue;
        const double d = segment_distance(0, 0, xs, ys, xt, yt);
        if (d > radius) continue;
        for (const int32_t f : {r.left, r.right})
            if (f != kNone) close.push_back({f, d});
    }
    // The faces passed through: the nearest to the viewer is the one seen. Its depth where
    // the line meets it: the fan triangle (0, i, i+1) containing the point, by barycentric
    // coordinates (for a non-planar face, the triangle nearest containing it).
    PickResult result;
    double best_depth = -std::numeric_limits<double>::infinity();
    std::vector<int32_t> c;
    for (const int32_t f : toggled) {
        if (!odd[static_cast<std::size_t>(f)]) continue;
        corners_of(mesh, f, c);
        double depth = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 1; i + 1 < c.size(); ++i) {
            const double x0 = vx[static_cast<std::size_t>(c[0])], y0 = vy[static_cast<std::size_t>(c[0])];
            const double x1 = vx[static_cast<std::size_t>(c[i])] - x0, y1 = vy[static_cast<std::size_t>(c[i])] - y0;
            const double x2 = vx[static_cast<std::size_t>(c[i + 1])] - x0, y2 = vy[static_cast<std::size_t>(c[i + 1])] - y0;
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
        if (f == result.face || odd[static_cast<std::size_t>(f)] || mesh.is_deleted(Face(f))) continue;
        corners_of(mesh, f, c);
        double area2 = 0; // twice the signed area in the view plane
        for (std::size_t k = 0, j = c.size() - 1; k < c.size(); j = k++)
            area2 += vx[static_cast<std::size_t>(c[j])] * vy[static_cast<std::size_t>(c[k])] - vx[static_cast<std::size_t>(c[k])] * vy[static_cast<std::size_t>(c[j])];
        if (area2 > 0) near.push_back({f, close[i].second});
    }
    std::stable_sort(near.begin() + (result.face >= 0 ? 1 : 0), near.end(),
                     [](const PickNear& l, const PickNear& r) { return l.distance < r.distance; });
    if (near.size() > static_cast<std::size_t>(max_near)) near.resize(static_cast<std::size_t>(max_near));
    result.near = std::move(near);
    return result;
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
