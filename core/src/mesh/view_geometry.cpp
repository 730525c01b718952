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
    if (v < 0 || v >= mesh.vertex_count())
        throw Error("invalid-element", "vertex index " + std::to_string(v) + " is out of range: the mesh has vertices 0 to " +
                                           std::to_string(mesh.vertex_count() - 1));
    if (mesh.is_deleted(Vertex(v)))
        throw Error("deleted-element", vertex_label(v) + " was removed by an edit (its number stays a gap until the mesh is compacted)");
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
    PickResult result;
    double best_depth = -std::numeric_limits<double>::infinity();
    std::vector<int32_t> c;
    std::vector<double> x, y, z;
    const int32_t F = mesh.face_count();
    for (int32_t f = 0; f < F; ++f) {
        if (mesh.is_deleted(Face(f))) continue;
        corners_of(mesh, f, c);
        const std::size_t k = c.size();
        if (k < 3) continue;
        x.resize(k), y.resize(k), z.resize(k);
        double minx = std::numeric_limits<double>::infinity(), maxx = -minx, miny = minx, maxy = -minx;
        for (std::size_t i = 0; i < k; ++i) {
            const glm::dvec3 p = mesh.position(c[i]);
            x[i] = glm::dot(p, a) - qx, y[i] = glm::dot(p, b) - qy, z[i] = glm::dot(p, n);
            minx = std::min(minx, x[i]), maxx = std::max(maxx, x[i]);
            miny = std::min(miny, y[i]), maxy = std::max(maxy, y[i]);
        }
        if (minx > radius || maxx < -radius || miny > radius || maxy < -radius) continue;
        // Through a fan triangle (0, i, i+1)? Barycentric signs, either orientation; the
        // depth where the line meets it.
        bool hit = false;
        double depth = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 1; i + 1 < k && !hit; ++i) {
            const double d = (x[i] - x[0]) * (y[i + 1] - y[0]) - (x[i + 1] - x[0]) * (y[i] - y[0]);
            if (d == 0) continue;
            const double w1 = ((0 - x[0]) * (y[i + 1] - y[0]) - (x[i + 1] - x[0]) * (0 - y[0])) / d;
            const double w2 = ((x[i] - x[0]) * (0 - y[0]) - (0 - x[0]) * (y[i] - y[0])) / d;
            if (w1 >= 0 && w2 >= 0 && w1 + w2 <= 1) {
                hit = true;
                depth = z[0] + w1 * (z[i] - z[0]) + w2 * (z[i + 1] - z[0]);
            }
        }
        double area2 = 0; // twice the signed area in the view plane
        for (std::size_t i = 0, j = k - 1; i < k; j = i++) area2 += x[j] * y[i] - x[i] * y[j];
        if (hit && depth > best_depth) best_depth = depth, result.face = f;
        double distance = 0;
        if (!hit) {
            distance = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0, j = k - 1; i < k; j = i++)
                distance = std::min(distance, segment_distance(0, 0, x[j], y[j], x[i], y[i]));
        }
        if (distance <= radius && (area2 > 0 || hit)) result.near.push_back({f, distance});
    }
    // Faces hit but behind the nearest one are hidden by it: only the nearest stays at 0.
    std::vector<PickNear> near;
    if (result.face >= 0) near.push_back({result.face, 0});
    for (const PickNear& p : result.near)
        if (p.face != result.face && (p.distance > 0 || result.face < 0)) near.push_back(p);
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
    int64_t fan = 0;
    for (int32_t f = 0; f < F; ++f)
        if (!mesh.is_deleted(Face(f)) && mesh.face_edges()[f] != kNone) {
            corners_of(mesh, f, c);
            fan += std::max<int64_t>(0, static_cast<int64_t>(c.size()) - 2);
        }
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
        if (ratio > 0.8 && ratio < 1.1) break;
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
    return out;
}

} // namespace wingspline::mesh
